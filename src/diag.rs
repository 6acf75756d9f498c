//! Diagnostics: errors and warnings with source spans, labels, hints and a call trace.
//!
//! Every stage reports problems as [`Diagnostic`] values; only the CLI turns them into
//! miette reports. [`SourceMap`] owns the text of every file read, indexed by [`FileId`].

use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Index of a source file in the [`SourceMap`].
pub type FileId = u32;

/// A byte range in one source file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Hash)]
pub struct Span {
    /// The file the range lies in.
    pub file: FileId,
    /// Byte offset of the first character.
    pub start: u32,
    /// Byte offset just past the last character.
    pub end: u32,
}

impl Span {
    /// A span covering `start..end` of `file`.
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        Span {
            file,
            start: start as u32,
            end: end as u32,
        }
    }

    /// The smallest span covering both `self` and `other` (same file assumed).
    pub fn join(self, other: Span) -> Span {
        if self.file != other.file {
            return self;
        }
        Span {
            file: self.file,
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }
}

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// The scene cannot be rendered.
    Error,
    /// Worth knowing; the render goes on.
    Warning,
}

/// One step of the call trace: "in macro `Flake`, called here".
#[derive(Clone, Debug, PartialEq)]
pub struct TraceEntry {
    /// What was entered, e.g. "macro `Flake`" or "file `colors.inc`".
    pub what: String,
    /// Where it was entered from.
    pub span: Span,
}

/// A problem found in a scene, with everything needed to show it well.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// The main location.
    pub span: Span,
    /// One-line message, lowercase, e.g. "expected `{`, found `}`".
    pub message: String,
    /// Label on the main span (may be empty).
    pub label: String,
    /// Further labelled locations.
    pub labels: Vec<(Span, String)>,
    /// Advice, e.g. "did you mean `pigment`?".
    pub help: Option<String>,
    /// Macro calls and includes that led here, innermost first.
    pub trace: Vec<TraceEntry>,
    /// A stable machine-readable kind (`syntax`, `file-not-found`, `eval`, `warning`, ...),
    /// for `--format json|sarif`; see docs/diagnostics.md.
    pub code: &'static str,
}

impl Diagnostic {
    /// An error at `span` with `message`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            span,
            message: message.into(),
            label: String::new(),
            labels: Vec::new(),
            help: None,
            trace: Vec::new(),
            code: "eval",
        }
    }

    /// A warning at `span` with `message`.
    pub fn warning(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            code: "warning",
            ..Diagnostic::error(span, message)
        }
    }

    /// Sets the label shown under the main span.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = label.into();
        self
    }

    /// Adds a secondary labelled span.
    pub fn with_secondary(mut self, span: Span, label: impl Into<String>) -> Diagnostic {
        self.labels.push((span, label.into()));
        self
    }

    /// Sets the machine-readable kind.
    pub fn with_code(mut self, code: &'static str) -> Diagnostic {
        self.code = code;
        self
    }

    /// Sets the help text.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }
}

/// Result of a stage that reports diagnostics.
pub type SourceResult<T> = Result<T, Box<Diagnostic>>;

/// One source file's name and text.
#[derive(Debug)]
pub struct SourceFile {
    /// The path as opened.
    pub path: PathBuf,
    /// The full text.
    pub text: Arc<str>,
}

/// All source files read during a run, so spans can be shown with their text.
#[derive(Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// The paths of the files, in the order added.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().map(|f| f.path.as_path())
    }

    /// Adds a file and returns its id.
    pub fn add(&mut self, path: &Path, text: Arc<str>) -> FileId {
        self.files.push(SourceFile {
            path: path.to_path_buf(),
            text,
        });
        (self.files.len() - 1) as FileId
    }

    /// The file with this id.
    pub fn file(&self, id: FileId) -> Option<&SourceFile> {
        self.files.get(id as usize)
    }

    /// 1-based line and column of a byte offset in a file.
    pub fn line_column(&self, id: FileId, offset: u32) -> (usize, usize) {
        let Some(file) = self.file(id) else {
            return (0, 0);
        };
        let offset = (offset as usize).min(file.text.len());
        let before = &file.text[..floor_char_boundary(&file.text, offset)];
        let line = before.matches('\n').count() + 1;
        let column = before
            .rfind('\n')
            .map_or(before.len(), |n| before.len() - n - 1)
            + 1;
        (line, column)
    }

    /// "file:line:col" for a span.
    pub fn describe(&self, span: Span) -> String {
        let (line, column) = self.line_column(span.file, span.start);
        let name = self
            .file(span.file)
            .map(|f| f.path.display().to_string())
            .unwrap_or_default();
        format!("{name}:{line}:{column}")
    }
}

fn floor_char_boundary(text: &str, mut offset: usize) -> usize {
    while offset > 0 && !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

/// Names longer than this get no did-you-mean.
const MAX_SUGGESTED_LENGTH: usize = 64;

/// The candidate closest to `name` by edit distance, if close enough to be a likely typo.
///
/// ```
/// use durer::diag::did_you_mean;
/// assert_eq!(did_you_mean("pigmnet", ["pigment", "finish"]), Some("pigment"));
/// assert_eq!(did_you_mean("zzz", ["pigment", "finish"]), None);
/// ```
pub fn did_you_mean<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let length = name.chars().count();
    // No name that long is a typo of a known one; the distance would cost length² each.
    if length > MAX_SUGGESTED_LENGTH {
        return None;
    }
    let limit = (length / 3).max(1);
    let lowered = name.to_lowercase();
    let mut best: Option<(usize, &str)> = None;
    for candidate in candidates {
        // The distance is at least the difference in length.
        if candidate == name || candidate.chars().count().abs_diff(length) > limit {
            continue;
        }
        let distance = edit_distance(&lowered, &candidate.to_lowercase());
        if distance <= limit
            && best.is_none_or(|(d, c)| distance < d || (distance == d && candidate < c))
        {
            best = Some((distance, candidate));
        }
    }
    best.map(|(_, c)| c)
}

/// [`did_you_mean`] for names in a scene: a one- or two-letter candidate is offered only
/// for the same word in another case (`X` for `x`, not `if` for `I`), and a capitalised
/// name, which scenes use for their own identifiers, only gets a lower-case keyword that
/// starts with the same letter (`Sin` gets `sin`, `Undefined` does not get `defined`).
///
/// ```
/// use durer::diag::suggest_name;
/// assert_eq!(suggest_name("I", ["if", "x"]), None);
/// assert_eq!(suggest_name("Undefined", ["defined"]), None);
/// assert_eq!(suggest_name("Sphere", ["sphere"]), Some("sphere"));
/// ```
pub fn suggest_name<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let first = name.chars().next()?;
    let fits = |candidate: &&str| {
        if candidate.chars().count() <= 2 {
            return candidate.eq_ignore_ascii_case(name);
        }
        let other = candidate.chars().next().unwrap_or(' ');
        !(first.is_uppercase() && other.is_lowercase())
            || other.to_lowercase().eq(first.to_lowercase())
    };
    did_you_mean(name, candidates.into_iter().filter(fits))
}

/// Levenshtein distance with adjacent transpositions counted as one edit.
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut rows = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in rows.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in rows[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut d = (rows[i - 1][j] + 1)
                .min(rows[i][j - 1] + 1)
                .min(rows[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(rows[i - 2][j - 2] + 1);
            }
            rows[i][j] = d;
        }
    }
    rows[a.len()][b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_keyword() {
        let words = ["pigment", "finish", "normal"];
        assert_eq!(did_you_mean("pigmnet", words), Some("pigment"));
        assert_eq!(did_you_mean("zzz", words), None);
    }

    #[test]
    fn line_and_column_are_one_based() {
        let mut map = SourceMap::new();
        let id = map.add(Path::new("a.pov"), Arc::from("ab\ncd"));
        assert_eq!(map.line_column(id, 0), (1, 1));
        assert_eq!(map.line_column(id, 4), (2, 2));
    }
}
