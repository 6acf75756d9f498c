//! Bracket and directive balance: the first `{`, `(`, `[` or directive opener never closed,
//! a closer that closes nothing, or a branch directive (`#else`, `#case`) outside the
//! directive it belongs to.
//!
//! In: the text of a file that failed to parse, and where the parser stopped. Out: a
//! diagnostic naming the bracket or directive, or `None`. Holds: a problem with `(` or `[`
//! is only reported when the parser stopped after the bracket, so an unrelated earlier
//! syntax error is not hidden by it.

use super::skip_block_comment;
use super::tokens::{next_token, TokenKind};
use crate::diag::{Diagnostic, FileId, Span};

/// An open bracket or directive: its kind (`{`, `(`, `[` or `#`) and byte range.
type Open = (u8, usize, usize);

/// The closer of an opening bracket.
fn closer(opener: u8) -> u8 {
    match opener {
        b'(' => b')',
        b'[' => b']',
        b'<' => b'>',
        _ => b'}',
    }
}

/// Finds the first `{`, `(`, `[` or directive opener that is never closed (or a stray
/// closer); `failed_at` is where the parser stopped.
pub(super) fn unbalanced(text: &str, file: FileId, failed_at: usize) -> Option<Diagnostic> {
    let bytes = text.as_bytes();
    let mut stack: Vec<Open> = Vec::new();
    // Starts of the open `#if`s (and `#switch`es) whose `#else` was seen.
    let mut else_seen: Vec<usize> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        match c {
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if bytes.get(i + 1) == Some(&b'*') => {
                i = skip_block_comment(bytes, i).0;
                continue;
            }
            b'{' | b'(' | b'[' => stack.push((c, i, i + 1)),
            b'}' | b')' | b']' => {
                // A `(` or `[` left open where another closer comes: unclosed, when the
                // parser stopped there too; otherwise it is dropped and the closer read again.
                while let Some(&(open, start, end)) = stack.last() {
                    if closer(open) == c || !matches!(open, b'(' | b'[') {
                        break;
                    }
                    if failed_at >= end {
                        let due = Some(i.min(failed_at));
                        return Some(unclosed(text, file, (open, start, end), due));
                    }
                    stack.pop();
                }
                match stack.last() {
                    Some(&(open, _, _)) if closer(open) == c => {
                        stack.pop();
                    }
                    _ if c == b'}' => return Some(stray_brace(text, file, i)),
                    _ if failed_at >= i => {
                        let symbol = c as char;
                        let opener = if c == b')' { '(' } else { '[' };
                        return Some(
                            Diagnostic::error(
                                Span::new(file, i, i + 1),
                                format!("unmatched `{symbol}`"),
                            )
                            .with_label(format!("this `{symbol}` closes nothing"))
                            .with_help(format!("remove it, or add the `{opener}` it should close")),
                        );
                    }
                    _ => {}
                }
            }
            b'#' => {
                let (word, end) = super::directive_word(text, i);
                match word {
                    "if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro" => {
                        stack.push((b'#', i, end))
                    }
                    "else" | "elseif" | "case" | "range" => {
                        if let Some(orphan) =
                            misplaced_branch(text, file, &stack, &mut else_seen, word, i, end)
                        {
                            return Some(orphan);
                        }
                    }
                    "end" => {
                        // An `#end` inside an open brace belongs to a directive cut across braces;
                        // only report a structure problem when nothing is open at all.
                        if let Some(pos) = stack.iter().rposition(|(k, _, _)| *k == b'#') {
                            // A `(` or `[` still open at the `#end` is never closed.
                            if let Some(&open) = stack[pos..]
                                .iter()
                                .rev()
                                .find(|(k, _, e)| matches!(k, b'(' | b'[') && failed_at >= *e)
                            {
                                let due = closing_expected(text, open.2).unwrap_or(i);
                                return Some(unclosed(text, file, open, Some(due.min(failed_at))));
                            }
                            stack.truncate(pos);
                        } else {
                            return Some(
                                Diagnostic::error(
                                    Span::new(file, i, end),
                                    "`#end` without an opening directive",
                                )
                                .with_label("nothing to end here"),
                            );
                        }
                    }
                    _ => {}
                }
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    while let Some(&(kind, start, end)) = stack.last() {
        let span = Span::new(file, start, end);
        return Some(match kind {
            b'{' => Diagnostic::error(span, "unclosed `{`")
                .with_label("this `{` is never closed")
                .with_help("add the matching `}`"),
            b'(' | b'[' => {
                if failed_at < end {
                    stack.pop();
                    continue;
                }
                // Where the closer was due: where the parser stopped, if that is sooner.
                let stop = match closing_expected(text, end) {
                    Some(stop) => Some(stop.min(failed_at)),
                    None => (failed_at < text.len()).then_some(failed_at),
                };
                unclosed(text, file, (kind, start, end), stop)
            }
            _ => {
                let word = text[start + 1..end].trim();
                Diagnostic::error(span, format!("unterminated `#{word}`"))
                    .with_label(format!("this `#{word}` has no matching `#end`"))
                    .with_help("add `#end` where the directive's body ends")
            }
        });
    }
    None
}

/// Keywords that are always followed by `{` (objects, lights, the camera, appearance blocks).
const BLOCK_WORDS: &[&str] = &[
    "background",
    "bicubic_patch",
    "blob",
    "box",
    "camera",
    "cone",
    "cylinder",
    "difference",
    "disc",
    "finish",
    "fog",
    "global_settings",
    "height_field",
    "interior",
    "intersection",
    "isosurface",
    "julia_fractal",
    "lathe",
    "light_source",
    "material",
    "media",
    "merge",
    "mesh",
    "mesh2",
    "normal",
    "object",
    "ovus",
    "parametric",
    "pigment",
    "plane",
    "polygon",
    "prism",
    "rainbow",
    "sky_sphere",
    "smooth_triangle",
    "sor",
    "sphere",
    "sphere_sweep",
    "superellipsoid",
    "text",
    "texture",
    "torus",
    "triangle",
    "union",
];

/// "unexpected `}`" at `at`; when the text before it starts with a keyword that no `{`
/// follows (`sphere 0, 1 }`), that keyword is labelled as missing its `{`.
fn stray_brace(text: &str, file: FileId, at: usize) -> Diagnostic {
    let d = Diagnostic::error(Span::new(file, at, at + 1), "unexpected `}`")
        .with_label("this `}` closes nothing");
    // The tokens since the last `}`, `;` or directive before the stray `}`.
    let mut run: Vec<super::tokens::Token> = Vec::new();
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        if token.start >= at {
            break;
        }
        position = token.end;
        if token.kind == TokenKind::Directive || matches!(token.text(text), "}" | ";") {
            run.clear();
        } else {
            run.push(token);
        }
    }
    let head = run
        .first()
        .filter(|t| t.kind == TokenKind::Word && BLOCK_WORDS.contains(&t.text(text)));
    match (head, run.get(1)) {
        (Some(head), Some(next)) if next.text(text) != "{" => {
            let word = head.text(text);
            d.with_secondary(
                Span::new(file, head.start, head.end),
                format!("no `{{` after this `{word}`"),
            )
            .with_help(format!("a block is written `{word} {{ ... }}`"))
        }
        _ => d,
    }
}

/// Where the closer of the bracket ending at `after` was due: the first `;`, `{`, directive
/// or unmatched closer at the bracket's own depth, or `None` at the end of the text.
pub(super) fn closing_expected(text: &str, after: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut position = after;
    while let Some(token) = next_token(text, position) {
        position = token.end;
        if token.kind == TokenKind::Directive {
            return Some(token.start);
        }
        match token.text(text) {
            "(" | "[" => depth += 1,
            ")" | "]" | "}" if depth == 0 => return Some(token.start),
            ")" | "]" => depth -= 1,
            ";" | "{" if depth == 0 => return Some(token.start),
            _ => {}
        }
    }
    None
}

/// "unclosed `(`": the opener labelled, and a second label where its closer was due
/// (`stop`, or after the last token when the text ended first).
pub(super) fn unclosed(text: &str, file: FileId, open: Open, stop: Option<usize>) -> Diagnostic {
    let (kind, start, end) = open;
    let (symbol, close) = (kind as char, closer(kind) as char);
    let due = match stop {
        Some(at) => {
            let found = next_token(text, at).map_or(at + 1, |t| t.end);
            let shown = &text[at..found];
            (
                Span::new(file, at, found),
                format!("expected `{close}` before this `{shown}`"),
            )
        }
        None => {
            let mut last = None;
            let mut position = end;
            while let Some(token) = next_token(text, position) {
                position = token.end;
                last = Some(token);
            }
            match last {
                Some(t) => (
                    Span::new(file, t.start, t.end),
                    format!("expected `{close}` after this"),
                ),
                None => (
                    Span::new(file, start, end),
                    format!("expected `{close}` after this"),
                ),
            }
        }
    };
    let mut d = Diagnostic::error(Span::new(file, start, end), format!("unclosed `{symbol}`"))
        .with_label(format!("this `{symbol}` is never closed"))
        .with_help(format!("add the matching `{close}`"));
    if due.0.start as usize != start {
        d = d.with_secondary(due.0, due.1);
    }
    d
}

/// A branch directive (`#else`, `#elseif`, `#case`, `#range` at `start..end`) with no
/// directive open that it could belong to, or an `#elseif` after its `#if`'s `#else`.
fn misplaced_branch(
    text: &str,
    file: FileId,
    stack: &[(u8, usize, usize)],
    else_seen: &mut Vec<usize>,
    word: &str,
    start: usize,
    end: usize,
) -> Option<Diagnostic> {
    let open = |kinds: &[&str]| {
        stack.iter().rev().find(|(kind, s, e)| {
            *kind == b'#' && kinds.contains(&text[s + 1..*e].trim_start_matches([' ', '\t']))
        })
    };
    let span = Span::new(file, start, end);
    match word {
        "case" | "range" => open(&["switch"]).is_none().then(|| {
            Diagnostic::error(span, format!("`#{word}` outside a `#switch`"))
                .with_label("no `#switch` is open here")
                .with_help(format!(
                    "`#{word}` starts a branch of `#switch (Value) ... #end`"
                ))
        }),
        _ => match open(&["if", "ifdef", "ifndef", "switch"]) {
            None => Some(
                Diagnostic::error(span, format!("`#{word}` without an `#if`"))
                    .with_label("no `#if` is open here")
                    .with_help(format!(
                        "`#{word}` belongs between `#if (Condition)` and its `#end`"
                    )),
            ),
            Some(&(_, if_start, if_end)) => {
                let seen = else_seen.contains(&if_start);
                if word == "else" && !seen {
                    else_seen.push(if_start);
                }
                (word == "elseif" && seen).then(|| {
                    Diagnostic::error(span, "`#elseif` after `#else`")
                        .with_label("this `#elseif` comes after the `#else` of its `#if`")
                        .with_secondary(Span::new(file, if_start, if_end), "this `#if`")
                        .with_help("put every `#elseif` before the `#else`")
                })
            }
        },
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn branches_inside_their_directives_are_not_orphans() {
        let text = "#if (1) #declare A = 1; #elseif (2) #else #end\n\
                    #switch (2) #case (1) #break #range (2, 3) #if (1) #else #end #else #end\n\
                    #macro M() #ifdef (A) #else #end #end\n";
        assert!(super::unbalanced(text, 0, usize::MAX).is_none());
        let orphan = |t: &str| super::unbalanced(t, 0, usize::MAX).map(|d| d.message);
        assert_eq!(
            orphan("#if (1) #end #else"),
            Some("`#else` without an `#if`".into())
        );
        assert_eq!(
            orphan("#if (1) #else #elseif (1) #end"),
            Some("`#elseif` after `#else`".into())
        );
        assert_eq!(
            orphan("#if (1) #range (1, 2) #end"),
            Some("`#range` outside a `#switch`".into())
        );
        // An inner `#if`'s `#else` does not count for the outer one.
        assert!(
            super::unbalanced("#if (1) #if (2) #else #end #elseif (3) #end", 0, usize::MAX)
                .is_none()
        );
    }
}
