//! `#fopen`, `#read`, `#write`, `#fclose`: data files next to the scene or the output image.
//!
//! Files are opened only where the file policy allows (`crate::file_policy`: by default
//! the scene's folder and the output image's folder); any other path is refused with a
//! diagnostic. At the end of a file being read, its handle
//! identifier is undefined, so `#while (defined(Handle))` loops end, as in POV-Ray.

use super::c_format::general_format;
use super::value::{Value, Vector};
use crate::diag::Span;
use crate::eval::{EvalResult, Evaluator};
use crate::file_policy::Access;
use crate::syntax::ast::{Expr, Target, WriteValue};
use crate::syntax::symbol::Symbol;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// An open data file.
pub(crate) enum DataFile {
    /// Being read: the whole text and the read position.
    Reading { text: String, position: usize },
    /// Being written.
    Writing(std::io::BufWriter<std::fs::File>),
}

impl Evaluator {
    /// `#fopen Handle "name" read|write|append`.
    pub(crate) fn file_open(
        &mut self,
        handle: &Symbol,
        path: &Expr,
        mode: &str,
        span: Span,
    ) -> EvalResult<()> {
        let name = self.eval_string(path)?;
        let access = if mode == "read" {
            Access::Read
        } else {
            Access::Write
        };
        let resolved = self.allowed_data_path(&name, access, path.span())?;
        let file = match mode {
            "read" => match self.runtime.read_file_bytes(&resolved) {
                Ok(bytes) => DataFile::Reading {
                    text: String::from_utf8_lossy(&bytes).into_owned(),
                    position: 0,
                },
                Err(e) => {
                    return Err(self
                        .runtime
                        .error(
                            path.span(),
                            format!("cannot open `{}` for reading: {e}", resolved.display()),
                        )
                        .into())
                }
            },
            "write" | "append" => {
                let opened = std::fs::OpenOptions::new()
                    .create(true)
                    .write(true)
                    .append(mode == "append")
                    .truncate(mode == "write")
                    .open(&resolved);
                match opened {
                    Ok(f) => {
                        self.runtime.forget_parsed(&resolved);
                        DataFile::Writing(std::io::BufWriter::new(f))
                    }
                    Err(e) => {
                        return Err(self
                            .runtime
                            .error(
                                path.span(),
                                format!("cannot open `{}` for writing: {e}", resolved.display()),
                            )
                            .into())
                    }
                }
            }
            other => {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!("expected `read`, `write` or `append`, found `{other}`"),
                    )
                    .into())
            }
        };
        self.runtime.files.push(Some(file));
        let index = self.runtime.files.len() - 1;
        self.assign_local(handle, Value::File(index));
        Ok(())
    }

    /// Resolves a data file name (relative to the scene's folder) and checks it against the
    /// file policy; the resolved path (links followed) is the one to open.
    fn allowed_data_path(&self, name: &str, access: Access, span: Span) -> EvalResult<PathBuf> {
        let path = Path::new(name);
        let joined = if path.is_absolute() {
            path.to_path_buf()
        } else {
            self.runtime.scene_folder.join(path)
        };
        self.runtime.check_access(&joined, access, span)
    }

    fn file_index(&self, handle: Symbol, span: Span) -> EvalResult<usize> {
        match self.runtime.lookup(handle) {
            Some(Value::File(index)) if matches!(self.runtime.files.get(*index), Some(Some(_))) => {
                Ok(*index)
            }
            _ => Err(self
                .runtime
                .error(span, format!("`{handle}` is not an open file"))
                .with_help("open it first with #fopen")
                .into()),
        }
    }

    /// `#fclose Handle`; like POV-Ray, closing a handle that is not open (for example one
    /// already undefined at the end of a read) does nothing.
    pub(crate) fn file_close(&mut self, handle: &Symbol, span: Span) -> EvalResult<()> {
        let Ok(index) = self.file_index(*handle, span) else {
            return Ok(());
        };
        if let Some(DataFile::Writing(mut writer)) = self.runtime.files[index].take() {
            if let Err(e) = writer.flush() {
                return Err(self
                    .runtime
                    .error(span, format!("cannot finish writing: {e}"))
                    .into());
            }
        }
        self.undefine(*handle);
        Ok(())
    }

    /// `#write (Handle, values..)`: strings as they are, floats and vectors as POV-Ray writes them;
    /// a value after `uint8`, `sint16be` and the like as binary integers, one per component.
    pub(crate) fn file_write(
        &mut self,
        handle: &Symbol,
        values: &[WriteValue],
        span: Span,
    ) -> EvalResult<()> {
        let index = self.file_index(*handle, span)?;
        let mut bytes = Vec::new();
        for WriteValue { binary, value } in values {
            let evaluated = self.eval_expr(value)?;
            if let Some(integer) = binary {
                let components = match &evaluated {
                    Value::Float(f) => std::slice::from_ref(f),
                    Value::Vector(v) => &v.components[..v.len as usize],
                    other => {
                        return Err(self
                            .runtime
                            .error(
                                value.span(),
                                format!(
                                    "binary `#write` needs a float or a vector, found {}",
                                    other.type_name()
                                ),
                            )
                            .into())
                    }
                };
                for component in components {
                    integer.encode(*component, &mut bytes);
                }
                continue;
            }
            match evaluated {
                Value::String(s) => bytes.extend_from_slice(s.as_bytes()),
                Value::Float(f) => bytes.extend_from_slice(format_number(f).as_bytes()),
                Value::Vector(v) => {
                    let parts: Vec<String> = v.components[..v.len as usize]
                        .iter()
                        .map(|c| format_number(*c))
                        .collect();
                    // POV-Ray follows a written vector with a space.
                    bytes.extend_from_slice(format!("<{}> ", parts.join(",")).as_bytes());
                }
                Value::Colour(c) => {
                    let parts: Vec<String> =
                        c.to_array().iter().map(|c| format_number(*c)).collect();
                    bytes.extend_from_slice(format!("rgbft <{}>", parts.join(",")).as_bytes());
                }
                other => {
                    return Err(self
                        .runtime
                        .error(
                            value.span(),
                            format!("cannot write {} to a file", other.type_name()),
                        )
                        .into())
                }
            }
        }
        match &mut self.runtime.files[index] {
            Some(DataFile::Writing(writer)) => writer.write_all(&bytes).map_err(|e| {
                self.runtime
                    .error(span, format!("cannot write: {e}"))
                    .into()
            }),
            _ => Err(self
                .runtime
                .error(span, format!("`{handle}` was opened for reading"))
                .into()),
        }
    }

    /// `#read (Handle, targets..)`: comma-separated floats, vectors and strings.
    pub(crate) fn file_read(
        &mut self,
        handle: &Symbol,
        targets: &[Target],
        span: Span,
    ) -> EvalResult<()> {
        let index = self.file_index(*handle, span)?;
        for target in targets {
            let next = match &mut self.runtime.files[index] {
                Some(DataFile::Reading { text, position }) => next_datum(text, position),
                _ => {
                    return Err(self
                        .runtime
                        .error(span, format!("`{handle}` was opened for writing"))
                        .into())
                }
            };
            match next {
                Ok(Some(value)) => self.assign(true, target, value)?,
                Ok(None) => {
                    // End of file: the handle becomes undefined, as in POV-Ray.
                    self.runtime.files[index] = None;
                    self.undefine(*handle);
                    return Ok(());
                }
                Err(message) => {
                    return Err(self
                        .runtime
                        .error(span, format!("cannot read `{handle}`: {message}"))
                        .into())
                }
            }
        }
        let at_end = match &mut self.runtime.files[index] {
            Some(DataFile::Reading { text, position }) => {
                skip_separators(text, position);
                *position >= text.len()
            }
            _ => false,
        };
        if at_end {
            self.runtime.files[index] = None;
            self.undefine(*handle);
        }
        Ok(())
    }

    /// Removes the innermost version of an identifier (`#undef`).
    pub(crate) fn undefine(&mut self, name: Symbol) {
        if let Some(index) = self.runtime.scopes.innermost_holder(name) {
            self.runtime.scopes.remove(index, name);
        }
    }
}

fn skip_separators(text: &str, position: &mut usize) {
    let bytes = text.as_bytes();
    while *position < bytes.len()
        && (bytes[*position].is_ascii_whitespace() || bytes[*position] == b',')
    {
        *position += 1;
    }
}

/// Reads the next float, vector or string; `Ok(None)` at the end of the text.
fn next_datum(text: &str, position: &mut usize) -> Result<Option<Value>, String> {
    skip_separators(text, position);
    let rest = &text[*position..];
    if rest.is_empty() {
        return Ok(None);
    }
    if let Some(stripped) = rest.strip_prefix('"') {
        let end = stripped.find('"').ok_or("unterminated string")?;
        *position += end + 2;
        return Ok(Some(Value::String(Rc::from(&stripped[..end]))));
    }
    if let Some(stripped) = rest.strip_prefix('<') {
        let end = stripped.find('>').ok_or("unterminated vector")?;
        let mut components = Vec::new();
        for part in stripped[..end].split(',') {
            components.push(
                part.trim()
                    .parse::<f64>()
                    .map_err(|_| format!("bad vector component `{}`", part.trim()))?,
            );
        }
        if !(2..=5).contains(&components.len()) {
            return Err(format!(
                "a vector has 2 to 5 components, found {}",
                components.len()
            ));
        }
        *position += end + 2;
        return Ok(Some(Value::Vector(Vector::from_slice(&components))));
    }
    let end = rest
        .find(|c: char| c == ',' || c.is_ascii_whitespace())
        .unwrap_or(rest.len());
    let word = &rest[..end];
    let value = word
        .parse::<f64>()
        .map_err(|_| format!("expected a number, found `{word}`"))?;
    *position += end;
    Ok(Some(Value::Float(value)))
}

/// Floats as POV-Ray writes them: C's `%g`, six significant digits without trailing zeros,
/// switching to an exponent below 1e-4 and from 1e6 on (`1e-05`, `1.23457e+06`).
fn format_number(value: f64) -> String {
    general_format(value, 6)
}

#[cfg(test)]
mod tests {
    use super::format_number;

    /// What povray 3.7 writes for these floats with `#write`.
    #[test]
    fn numbers_are_written_like_povray() {
        let cases = [
            (0.000123456789, "0.000123457"),
            (123456.789, "123457"),
            (1e10, "1e+10"),
            (1.5, "1.5"),
            (0.0, "0"),
            (-0.0, "-0"),
            (-2.25e-7, "-2.25e-07"),
            (1.0 / 3.0, "0.333333"),
            (1e-5, "1e-05"),
            (999999.5, "1e+06"),
            (1234567.0, "1.23457e+06"),
            (0.1 + 0.2, "0.3"),
            (-1e300, "-1e+300"),
            (100.0, "100"),
        ];
        for (value, written) in cases {
            assert_eq!(format_number(value), written, "{value}");
        }
    }
}
