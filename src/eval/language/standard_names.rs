//! Which standard include file declares a name: durer's embedded copies of POV-Ray's
//! include files, scanned once for `#declare`, `#local` at file level and `#macro`.
//!
//! In: an identifier. Out: the first embedded include file (in [`EMBEDDED_INCLUDES`] order,
//! so `colors.inc` before the files that include it) that declares it. Used by the
//! "undefined identifier" message and by the language server.

use super::EMBEDDED_INCLUDES;
use crate::syntax::tokens::{next_token, TokenKind};
use std::collections::HashMap;
use std::sync::OnceLock;

/// A name declared by a standard include file: the file, the byte range of the name and
/// whether it is a macro.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StandardName {
    /// The include file's name, such as `colors.inc`.
    pub file: &'static str,
    /// Byte range of the name in the file's text.
    pub start: usize,
    /// End of that range.
    pub end: usize,
    /// Declared by `#macro` rather than `#declare`.
    pub is_macro: bool,
    /// The file a scene includes to get the name: `file`, or for an `X_old.inc` the
    /// standard file that includes it (`Cone_Y` is declared in `shapes_old.inc`, which
    /// `shapes.inc` includes).
    pub include: &'static str,
}

/// The file a scene includes for the names of `file`: `file` itself, except for a part of
/// a standard file named after it, such as an `X_old.inc` (POV-Ray moved old declarations
/// there) or `stones1.inc`, whose includer (`shapes.inc`, `stones.inc`) is the file to
/// include. Aggregates like `stdinc.inc` are never suggested.
fn include_for(file: &'static str) -> &'static str {
    let stem = file.trim_end_matches(".inc");
    for (includer, text) in EMBEDDED_INCLUDES {
        // Only a file named as a part of its includer: `stones1.inc` of `stones.inc`,
        // `shapes_old.inc` of `shapes.inc` (not `colors.inc` of `stdinc.inc`).
        let includer_stem = includer.trim_end_matches(".inc");
        if includer_stem == stem || !stem.starts_with(includer_stem) {
            continue;
        }
        let mut position = 0;
        let mut after_include = false;
        while let Some(token) = next_token(text, position) {
            position = token.end;
            if token.kind == TokenKind::Directive {
                after_include = token.directive_word(text) == "include";
                continue;
            }
            if after_include && token.text(text).trim_matches('"') == file {
                return includer;
            }
            after_include = false;
        }
    }
    file
}

fn index() -> &'static HashMap<&'static str, StandardName> {
    static INDEX: OnceLock<HashMap<&'static str, StandardName>> = OnceLock::new();
    INDEX.get_or_init(|| {
        let mut names = HashMap::new();
        for (file, text) in EMBEDDED_INCLUDES {
            let include = include_for(file);
            let mut position = 0;
            let mut pending: Option<bool> = None;
            while let Some(token) = next_token(text, position) {
                position = token.end;
                match token.kind {
                    TokenKind::Directive => {
                        pending = match token.directive_word(text) {
                            "declare" | "local" => Some(false),
                            "macro" => Some(true),
                            _ => None,
                        };
                    }
                    TokenKind::Word => {
                        if let Some(is_macro) = pending.take() {
                            names.entry(token.text(text)).or_insert(StandardName {
                                file,
                                start: token.start,
                                end: token.end,
                                is_macro,
                                include,
                            });
                        }
                    }
                    _ => pending = None,
                }
            }
        }
        names
    })
}

/// The standard include file that declares `name`, if any.
pub fn standard_name(name: &str) -> Option<StandardName> {
    index().get(name).copied()
}

/// Every name the standard include files declare.
pub fn standard_names() -> impl Iterator<Item = (&'static str, StandardName)> {
    index().iter().map(|(name, place)| (*name, *place))
}

/// The text of an embedded standard include file.
pub fn embedded_include(name: &str) -> Option<&'static str> {
    EMBEDDED_INCLUDES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

/// The names of the embedded standard include files.
pub fn embedded_include_names() -> impl Iterator<Item = &'static str> {
    EMBEDDED_INCLUDES.iter().map(|(name, _)| *name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_and_macros_are_found_in_their_files() {
        assert_eq!(standard_name("White").map(|n| n.file), Some("colors.inc"));
        assert_eq!(
            standard_name("T_Stone1").map(|n| n.file),
            Some("stones1.inc")
        );
        let cone = standard_name("Cone_Y");
        assert!(
            cone.is_some_and(|n| n.file == "shapes_old.inc" && n.include == "shapes.inc"),
            "{cone:?}"
        );
        assert!(standard_name("no_such_name_anywhere").is_none());
    }
}
