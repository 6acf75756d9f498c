//! Directives written the wrong way: `#for (I = 0; I < 3; I++)`, `#ifdef A`,
//! `#macro Ball R`, `#declare P.x = 5`, `#switch` without `#case`, ...
//!
//! In: the text pest failed on and where it stopped. Out: a diagnostic for the directive
//! whose head is malformed, when the parser stopped inside it or shortly after (before the
//! second directive that follows the mistake); `None` otherwise. Holds: only the heads of
//! directives are checked, by their tokens; a well-formed head is never reported.

use super::tokens::{next_token, Token, TokenKind};
use crate::diag::{Diagnostic, FileId, Span};

/// The first malformed directive head around `offset`, where the parser stopped.
pub(super) fn directive_problem(text: &str, file: FileId, offset: usize) -> Option<Diagnostic> {
    let mut tokens = Vec::new();
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        position = token.end;
        tokens.push(token);
    }
    for (index, token) in tokens.iter().enumerate() {
        if token.kind != TokenKind::Directive || token.start > offset {
            continue;
        }
        let head = Head {
            text,
            file,
            tokens: &tokens,
            at: index,
        };
        let Some((violation, d)) = head.check() else {
            continue;
        };
        // The parser's stop must lie before the second directive after the mistake.
        let window_end = tokens
            .iter()
            .filter(|t| t.kind == TokenKind::Directive && t.start > violation)
            .nth(1)
            .map_or(text.len() + 1, |t| t.start);
        if offset < window_end {
            return Some(d);
        }
    }
    None
}

/// A directive's head: the directive token at `at` and the tokens after it.
struct Head<'a> {
    text: &'a str,
    file: FileId,
    tokens: &'a [Token],
    at: usize,
}

impl Head<'_> {
    /// The `n`th token after the directive (0: the one right after it).
    fn after(&self, n: usize) -> Option<&Token> {
        self.tokens.get(self.at + 1 + n)
    }

    /// The text of the `n`th token after the directive ("" past the end).
    fn word(&self, n: usize) -> &str {
        self.after(n).map_or("", |t| t.text(self.text))
    }

    fn span(&self, token: &Token) -> Span {
        Span::new(self.file, token.start, token.end)
    }

    /// Where the head goes wrong and the diagnostic for it.
    fn check(&self) -> Option<(usize, Diagnostic)> {
        let directive = &self.tokens[self.at];
        let word = directive.directive_word(self.text);
        match word {
            "ifdef" | "ifndef" => self.needs_parentheses(word, "the name"),
            "while" => self.needs_parentheses(word, "its condition"),
            "for" => self.for_head(),
            "macro" => self.macro_head(),
            "declare" | "local" => self.declare_head(word),
            "switch" => self.switch_head(),
            _ => None,
        }
    }

    /// `#ifdef A` / `#while I < 3`: the `(` is missing.
    fn needs_parentheses(&self, word: &str, what: &str) -> Option<(usize, Diagnostic)> {
        let first = self.after(0)?;
        if first.text(self.text) == "(" || first.kind == TokenKind::Directive {
            return None;
        }
        // The rest of the line, as the user meant it.
        let rest = &self.text[first.start..];
        let line = rest.lines().next().unwrap_or("").trim();
        let line = line.split("//").next().unwrap_or("").trim();
        let d = Diagnostic::error(
            self.span(first),
            format!("`#{word}` needs parentheses around {what}"),
        )
        .with_label("`(` expected before this")
        .with_help(format!("write `#{word} ({line})`"));
        Some((first.start, d))
    }

    /// `#for (I, Start, End [, Step])`.
    fn for_head(&self) -> Option<(usize, Diagnostic)> {
        const SHAPE: &str = "`#for (Identifier, Start, End [, Step])`";
        let open = self.after(0)?;
        if open.text(self.text) != "(" {
            let d = Diagnostic::error(self.span(open), "`#for` needs parentheses")
                .with_label("`(` expected before this")
                .with_help(format!("POV-Ray's loop is written {SHAPE}"));
            return Some((open.start, d));
        }
        let name = self.word(1).to_string();
        let second = self.after(2)?;
        if second.text(self.text) == "=" || second.text(self.text) == ";" {
            let d = Diagnostic::error(self.span(second), "`#for` is not written as in C")
                .with_label("`,` expected here")
                .with_help(format!(
                    "POV-Ray's loop is written {SHAPE}: `#for ({name}, 0, 2)` counts {name} \
                     from 0 to 2"
                ));
            return Some((second.start, d));
        }
        // Count the values: commas at the parenthesis' own depth, up to its `)`.
        let mut depth = 0usize;
        let mut commas = 0;
        for token in &self.tokens[self.at + 2..] {
            match token.text(self.text) {
                "(" | "[" => depth += 1,
                ")" | "]" if depth > 0 => depth -= 1,
                "," if depth == 0 => commas += 1,
                ")" if depth == 0 => {
                    let message = match commas {
                        0 | 1 => "`#for` needs a start and an end value",
                        2 | 3 => return None,
                        _ => "`#for` has too many values",
                    };
                    let d = Diagnostic::error(self.span(token), message)
                        .with_label("the loop's values end here")
                        .with_help(format!("POV-Ray's loop is written {SHAPE}"));
                    return Some((token.start, d));
                }
                _ if token.kind == TokenKind::Directive => return None,
                _ => {}
            }
        }
        None
    }

    /// `#macro Name(Parameters)`: parentheses, and no default values.
    fn macro_head(&self) -> Option<(usize, Diagnostic)> {
        let name = self.after(0).filter(|t| t.kind == TokenKind::Word)?;
        let name = name.text(self.text);
        let open = self.after(1)?;
        if open.text(self.text) != "(" {
            let mut parameters = Vec::new();
            let line_end = self.text[open.start..]
                .find('\n')
                .map_or(self.text.len(), |n| open.start + n);
            for token in &self.tokens[self.at + 2..] {
                if token.start >= line_end || token.kind != TokenKind::Word {
                    break;
                }
                parameters.push(token.text(self.text));
            }
            let d = Diagnostic::error(self.span(open), "macro parameters go in parentheses")
                .with_label("`(` expected before this")
                .with_help(format!("write `#macro {name}({})`", parameters.join(", ")));
            return Some((open.start, d));
        }
        for token in &self.tokens[self.at + 3..] {
            match token.text(self.text) {
                ")" => return None,
                "=" => {
                    let d = Diagnostic::error(
                        self.span(token),
                        "macro parameters cannot have default values",
                    )
                    .with_label("no `=` in a parameter list")
                    .with_help(format!(
                        "POV-Ray has no default values: write `#macro {name}(R)` and pass the \
                         value in every call"
                    ));
                    return Some((token.start, d));
                }
                _ => {}
            }
        }
        None
    }

    /// `#declare Name = Value`: a name (maybe indexed), then one `=`.
    fn declare_head(&self, word: &str) -> Option<(usize, Diagnostic)> {
        let name = self.after(0)?;
        let name_text = name.text(self.text);
        if name_text == "=" {
            let d = Diagnostic::error(self.span(name), format!("`#{word}` needs a name"))
                .with_label("the name is missing before this `=`")
                .with_help(format!("write `#{word} Name = Value;`"));
            return Some((name.start, d));
        }
        if name.kind != TokenKind::Word || name_text == "deprecated" {
            return None;
        }
        // Skip the indices of an array element: `#declare A[1][2] = ...`.
        let mut n = 1;
        while self.word(n) == "[" {
            let mut depth = 0usize;
            loop {
                match self.word(n) {
                    "[" => depth += 1,
                    "]" => depth -= 1,
                    "" => return None,
                    _ => {}
                }
                n += 1;
                if depth == 0 {
                    break;
                }
            }
        }
        let after = self.after(n)?;
        let next = self.after(n + 1);
        let adjacent = |a: &Token, b: Option<&Token>| b.is_some_and(|b| b.start == a.end);
        let d = match after.text(self.text) {
            "=" if next.is_some_and(|t| t.text(self.text) == "=") && adjacent(after, next) => {
                let end = next.map_or(after.end, |t| t.end);
                Diagnostic::error(
                    Span::new(self.file, after.start, end),
                    format!("`#{word}` takes a single `=`"),
                )
                .with_label("`==` is not an operator in POV-Ray")
                .with_help(format!(
                    "write `#{word} {name_text} = Value;` (comparisons are written `(A = B)`)"
                ))
            }
            "." => Diagnostic::error(self.span(after), "a vector component cannot be assigned")
                .with_label("`=` expected here")
                .with_help(format!(
                    "declare the whole vector again, as in `#{word} {name_text} = <5, \
                     {name_text}.y, {name_text}.z>;`"
                )),
            "-" if next.is_some_and(|t| t.kind == TokenKind::Word) && adjacent(after, next) => {
                let joined = format!("{name_text}_{}", next.map_or("", |t| t.text(self.text)));
                Diagnostic::error(self.span(after), "a name cannot contain `-`")
                    .with_label("`=` expected here")
                    .with_help(format!(
                        "names are letters, digits and `_`: write `{joined}`"
                    ))
            }
            _ => return None,
        };
        Some((after.start, d))
    }

    /// `#switch (Value)` must go on with `#case`, `#range`, `#else` or `#end`.
    fn switch_head(&self) -> Option<(usize, Diagnostic)> {
        let mut n = 0;
        if self.word(0) == "(" {
            let mut depth = 0usize;
            loop {
                match self.word(n) {
                    "(" => depth += 1,
                    ")" => depth -= 1,
                    "" => return None,
                    _ => {}
                }
                n += 1;
                if depth == 0 {
                    break;
                }
            }
        } else {
            n = 1;
        }
        let next = self.after(n)?;
        let is_branch = next.kind == TokenKind::Directive
            && matches!(
                next.directive_word(self.text),
                "case" | "range" | "else" | "end"
            );
        if is_branch {
            return None;
        }
        let switch = &self.tokens[self.at];
        let d = Diagnostic::error(
            self.span(next),
            "`#switch` must start with `#case` or `#range`",
        )
        .with_label("this comes before any `#case`")
        .with_secondary(self.span(switch), "this `#switch`")
        .with_help("put `#case (Value)` or `#range (Low, High)` before the content of each branch");
        Some((next.start, d))
    }
}
