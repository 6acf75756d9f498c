//! What the language server knows of a text without evaluating it: the declarations,
//! macros, includes and objects found by durer's SDL tokenizer. It works on broken text
//! too (a file being typed rarely parses), which is why it reads tokens, not the AST.

use durer::eval::standard_names;
use durer::syntax::tokens::{next_token, Token, TokenKind};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// What a name is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SymbolKind {
    Declare,
    Local,
    Macro { parameters: Vec<String> },
    Object,
}

/// A declaration, macro or object in one text.
#[derive(Clone, Debug)]
pub struct Symbol {
    pub name: String,
    pub kind: SymbolKind,
    /// Byte range of the name.
    pub name_range: (usize, usize),
    /// Byte range of the whole declaration (a macro to its `#end`, an object to its `}`).
    pub range: (usize, usize),
    /// The value as written (`#declare R = 2;` gives `2`), or a macro's parameter list.
    pub detail: String,
}

/// An `#include "name"` in one text.
#[derive(Clone, Debug)]
pub struct Include {
    pub name: String,
}

/// Everything found in one text.
#[derive(Clone, Debug, Default)]
pub struct Outline {
    pub symbols: Vec<Symbol>,
    pub includes: Vec<Include>,
}

/// Words that start an object block at file level (for document symbols).
pub const OBJECT_WORDS: &[&str] = &[
    "sphere",
    "box",
    "cylinder",
    "cone",
    "plane",
    "torus",
    "disc",
    "mesh",
    "mesh2",
    "union",
    "difference",
    "intersection",
    "merge",
    "object",
    "blob",
    "lathe",
    "sor",
    "prism",
    "text",
    "height_field",
    "isosurface",
    "parametric",
    "superellipsoid",
    "julia_fractal",
    "polygon",
    "triangle",
    "smooth_triangle",
    "bicubic_patch",
    "sphere_sweep",
    "ovus",
    "lemon",
    "quadric",
    "quartic",
    "poly",
    "cubic",
    "polynomial",
    "light_source",
    "camera",
    "light_group",
    "background",
    "sky_sphere",
    "fog",
    "rainbow",
    "global_settings",
    "media",
];

fn tokens(text: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        if token.end <= position {
            break;
        }
        position = token.end;
        out.push(token);
    }
    out
}

/// Index of the token closing the `{` at `open` (or the last token).
fn matching_brace(text: &str, tokens: &[Token], open: usize) -> usize {
    let mut depth = 0usize;
    for (index, token) in tokens.iter().enumerate().skip(open) {
        if token.kind == TokenKind::Punctuation {
            match token.text(text) {
                "{" => depth += 1,
                "}" => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return index;
                    }
                }
                _ => {}
            }
        }
    }
    tokens.len().saturating_sub(1)
}

/// Index of the `#end` closing the directive at `open` (or the last token).
fn matching_end(text: &str, tokens: &[Token], open: usize) -> usize {
    let mut depth = 0usize;
    for (index, token) in tokens.iter().enumerate().skip(open) {
        if token.kind == TokenKind::Directive {
            match token.directive_word(text) {
                "if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro" => depth += 1,
                "end" => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return index;
                    }
                }
                _ => {}
            }
        }
    }
    tokens.len().saturating_sub(1)
}

/// Reads the declarations, macros, includes and file-level objects of `text`.
pub fn outline(text: &str) -> Outline {
    let tokens = tokens(text);
    let mut out = Outline::default();
    let mut depth = 0usize;
    let mut index = 0;
    while index < tokens.len() {
        let token = tokens[index];
        match token.kind {
            TokenKind::Punctuation => match token.text(text) {
                "{" => depth += 1,
                "}" => depth = depth.saturating_sub(1),
                _ => {}
            },
            TokenKind::Directive => {
                let word = token.directive_word(text);
                let name = tokens.get(index + 1).filter(|t| t.kind == TokenKind::Word);
                match (word, name) {
                    ("declare" | "local", Some(name)) => {
                        let kind = if word == "declare" {
                            SymbolKind::Declare
                        } else {
                            SymbolKind::Local
                        };
                        // The value runs from `=` to `;` or the next directive.
                        let mut end = index + 2;
                        let mut detail = String::new();
                        if tokens.get(end).is_some_and(|t| t.text(text) == "=") {
                            let value_start = end + 1;
                            end = value_start;
                            let mut braces = 0usize;
                            while let Some(t) = tokens.get(end) {
                                let piece = t.text(text);
                                if t.kind == TokenKind::Directive || (braces == 0 && piece == ";") {
                                    break;
                                }
                                if piece == "{" {
                                    braces += 1;
                                } else if piece == "}" {
                                    if braces == 0 {
                                        break;
                                    }
                                    braces -= 1;
                                    if braces == 0 {
                                        end += 1;
                                        break;
                                    }
                                }
                                end += 1;
                            }
                            if let (Some(first), Some(last)) = (
                                tokens.get(value_start),
                                tokens.get(end.saturating_sub(1).max(value_start)),
                            ) {
                                detail = short(&text[first.start..last.end.max(first.start)]);
                            }
                        }
                        let last = tokens
                            .get(end.min(tokens.len() - 1))
                            .map_or(name.end, |t| t.end);
                        out.symbols.push(Symbol {
                            name: name.text(text).to_string(),
                            kind,
                            name_range: (name.start, name.end),
                            range: (token.start, last.max(name.end)),
                            detail,
                        });
                    }
                    ("macro", Some(name)) => {
                        let mut parameters = Vec::new();
                        let mut cursor = index + 2;
                        if tokens.get(cursor).is_some_and(|t| t.text(text) == "(") {
                            cursor += 1;
                            while let Some(t) = tokens.get(cursor) {
                                match t.kind {
                                    TokenKind::Word if t.text(text) != "optional" => {
                                        parameters.push(t.text(text).to_string())
                                    }
                                    TokenKind::Punctuation if t.text(text) == ")" => break,
                                    TokenKind::Directive => break,
                                    _ => {}
                                }
                                cursor += 1;
                            }
                        }
                        let end = matching_end(text, &tokens, index);
                        out.symbols.push(Symbol {
                            name: name.text(text).to_string(),
                            detail: format!("({})", parameters.join(", ")),
                            kind: SymbolKind::Macro { parameters },
                            name_range: (name.start, name.end),
                            range: (token.start, tokens[end].end),
                        });
                        // What a macro body makes is not part of the file's outline.
                        index = end + 1;
                        continue;
                    }
                    ("include", _) => {
                        if let Some(string) = tokens
                            .get(index + 1)
                            .filter(|t| t.kind == TokenKind::String)
                        {
                            let quoted = string.text(text);
                            out.includes.push(Include {
                                name: quoted.trim_matches('"').to_string(),
                            });
                        }
                    }
                    _ => {}
                }
            }
            TokenKind::Word if depth == 0 => {
                let word = token.text(text);
                let opens = tokens.get(index + 1).is_some_and(|t| t.text(text) == "{");
                let after_equals = index > 0 && tokens[index - 1].text(text) == "=";
                if opens && !after_equals && OBJECT_WORDS.contains(&word) {
                    let end = matching_brace(text, &tokens, index + 1);
                    out.symbols.push(Symbol {
                        name: word.to_string(),
                        kind: SymbolKind::Object,
                        name_range: (token.start, token.end),
                        range: (token.start, tokens[end].end),
                        detail: String::new(),
                    });
                    depth += 1;
                    index += 2;
                    continue;
                }
            }
            _ => {}
        }
        index += 1;
    }
    out
}

/// A value's text shortened to one line of at most 80 characters.
fn short(text: &str) -> String {
    let flat: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    if flat.chars().count() > 80 {
        let cut: String = flat.chars().take(77).collect();
        format!("{cut}...")
    } else {
        flat
    }
}

/// Where an included file's text comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Source {
    /// A file on disk.
    Disk(PathBuf),
    /// One of durer's embedded standard include files.
    Embedded(&'static str),
}

/// An include file found and read.
#[derive(Clone, Debug)]
pub struct IncludedFile {
    pub name: String,
    pub source: Source,
    pub text: String,
}

/// Finds an include file as the evaluator does: the scene's folder, the `-L` folders,
/// POV-Ray's installed include folder, then the embedded copies; `.inc` is tried for a name
/// without an extension.
pub fn find_include(name: &str, folder: &Path, library: &[PathBuf]) -> Option<IncludedFile> {
    let mut names = vec![name.to_string()];
    if Path::new(name).extension().is_none() {
        names.push(format!("{name}.inc"));
    }
    for candidate in &names {
        let mut folders = vec![folder.to_path_buf()];
        folders.extend(library.iter().cloned());
        folders.push(PathBuf::from("/usr/share/povray-3.7/include"));
        for f in folders {
            let path = f.join(candidate);
            if path.is_file() {
                if let Ok(text) = std::fs::read_to_string(&path) {
                    return Some(IncludedFile {
                        name: candidate.clone(),
                        source: Source::Disk(path),
                        text,
                    });
                }
            }
        }
        if let Some(text) = standard_names::embedded_include(candidate) {
            let name = standard_names::embedded_include_names()
                .find(|n| n == candidate)
                .unwrap_or("");
            return Some(IncludedFile {
                name: candidate.clone(),
                source: Source::Embedded(name),
                text: text.to_string(),
            });
        }
    }
    None
}

/// The files `text` includes, and the files they include (each once, at most 200).
pub fn included_files(text: &str, folder: &Path, library: &[PathBuf]) -> Vec<IncludedFile> {
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    let mut queue: Vec<String> = outline(text).includes.into_iter().map(|i| i.name).collect();
    queue.reverse();
    while let Some(name) = queue.pop() {
        if out.len() >= 200 || !seen.insert(name.clone()) {
            continue;
        }
        if let Some(file) = find_include(&name, folder, library) {
            let mut nested: Vec<String> = outline(&file.text)
                .includes
                .into_iter()
                .map(|i| i.name)
                .collect();
            nested.reverse();
            out.push(file);
            queue.extend(nested);
        }
    }
    out
}

/// The token (word, string, ...) containing byte `offset`, or ending at it.
pub fn token_at(text: &str, offset: usize) -> Option<Token> {
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        if token.end <= position || token.start > offset {
            return None;
        }
        if token.start <= offset && offset <= token.end {
            // Punctuation ending at the cursor gives way to the word starting there.
            let next = next_token(text, token.end).filter(|n| n.start == offset);
            if token.kind == TokenKind::Punctuation && token.end == offset && next.is_some() {
                return next;
            }
            return Some(token);
        }
        position = token.end;
    }
    None
}

/// The brace depth at `offset` and whether a `#` (and maybe a partial word) comes just
/// before it.
pub fn context_at(text: &str, offset: usize) -> (usize, bool) {
    let offset = offset.min(text.len());
    let mut depth = 0usize;
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        if token.end <= position || token.start >= offset {
            break;
        }
        if token.kind == TokenKind::Punctuation {
            match token.text(text) {
                "{" => depth += 1,
                "}" => depth = depth.saturating_sub(1),
                _ => {}
            }
        }
        position = token.end;
    }
    let before = text.get(..offset).unwrap_or("");
    let trimmed = before.trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_');
    let directive = trimmed.trim_end_matches([' ', '\t']).ends_with('#');
    (depth, directive)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_declarations_macros_includes_and_objects() {
        let text = "#include \"colors.inc\"\n#declare R = 2 * 3;\n#macro M(A, optional B)\n sphere { 0, A }\n#end\nsphere { 0, R pigment { Red } }\n#local T = texture { pigment { rgb 1 } }\n";
        let o = outline(text);
        assert_eq!(o.includes[0].name, "colors.inc");
        let names: Vec<&str> = o.symbols.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["R", "M", "sphere", "T"]);
        assert_eq!(o.symbols[0].detail, "2 * 3");
        assert_eq!(
            o.symbols[1].kind,
            SymbolKind::Macro {
                parameters: vec!["A".into(), "B".into()]
            }
        );
        assert_eq!(o.symbols[3].detail, "texture { pigment { rgb 1 } }");
    }

    #[test]
    fn broken_text_still_has_an_outline() {
        let o = outline("#declare A = <1, 2\n#macro Open(X)\n sphere { 0, \"unclosed\n");
        assert_eq!(o.symbols.len(), 2);
    }

    #[test]
    fn context_knows_directives_and_depth() {
        assert_eq!(context_at("sphere { #dec", 13), (1, true));
        assert_eq!(context_at("sphere { 0, 1 } cam", 19), (0, false));
    }
}
