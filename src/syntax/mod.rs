//! Syntax: source text to spanned AST.
//!
//! In: the text of one file. Out: its top-level [`ast::Item`]s, or one diagnostic for the
//! first syntax error. Holds: every node carries a [`Span`]; no pest types escape.

pub mod ast;
mod balance;
mod explain;
mod grammar;
mod headers;
pub mod keywords;
mod lower;
pub mod mapping;
pub mod symbol;
pub mod tokens;

pub use grammar::{Rule, SdlParser};

use crate::diag::{Diagnostic, FileId, Span};
use explain::{pest_diagnostic, syntax_diagnostic};
use mapping::OffsetMap;
use pest::Parser;
use std::rc::Rc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Parses one file's text into its top-level items. A file whose directives cut across
/// braces (`#if (C) union { #else merge { #end ... }`) has no tree shape: it becomes one
/// [`ast::DirectiveKind::TextRun`] item, run token by token as POV-Ray reads it.
pub fn parse(text: &str, file: FileId) -> Result<Rc<[ast::Item]>, Box<Diagnostic>> {
    if let Some(error) = unterminated(text, file) {
        return Err(Box::new(error));
    }
    match guarded_parse(Rule::file, text) {
        Ok(mut pairs) => {
            let file_pair = pairs.next().expect("file rule");
            let items = file_pair.into_inner().next().expect("items");
            Ok(lower::Lowerer::new(file).items(items))
        }
        Err(_) if braces_cross_directives(text) => {
            let span = Span {
                file,
                start: 0,
                end: u32::try_from(text.len()).unwrap_or(u32::MAX),
            };
            let run = ast::DirectiveKind::TextRun {
                text: Rc::from(text),
                span,
            };
            let directive = ast::Directive {
                kind: run,
                without_hash: false,
                span,
            };
            Ok(Rc::from([ast::Item::Directive(Rc::new(directive))]))
        }
        Err(error) => Err(Box::new(syntax_diagnostic(text, file, error))),
    }
}

/// Fewest parser steps allowed for any file; see [`set_parse_step_limit`].
static PARSE_STEP_LIMIT: AtomicUsize = AtomicUsize::new(50_000_000);
/// The highest step budget set so far (pest's budget is one process-wide number; it only
/// ever grows, so parses on other threads are never cut short by a smaller one).
static PARSE_STEPS_IN_FORCE: AtomicUsize = AtomicUsize::new(0);
/// Parser steps allowed per byte of text beyond the fixed budget (a large mesh file
/// takes about 30 per byte).
const PARSE_STEPS_PER_BYTE: usize = 400;

/// Sets the parser's step budget for a file: `steps` plus [`PARSE_STEPS_PER_BYTE`] per
/// byte. Bounds the time of text that makes the grammar backtrack (the `parse-steps` limit).
pub fn set_parse_step_limit(steps: u64) {
    PARSE_STEP_LIMIT.store(
        usize::try_from(steps).unwrap_or(usize::MAX),
        Ordering::Relaxed,
    );
}

/// The budget for a file of `length` bytes.
pub(super) fn parse_step_budget(length: usize) -> usize {
    PARSE_STEP_LIMIT
        .load(Ordering::Relaxed)
        .saturating_add(length.saturating_mul(PARSE_STEPS_PER_BYTE))
}

/// Runs the pest parser with the step budget in force.
fn guarded_parse(
    rule: Rule,
    text: &str,
) -> Result<pest::iterators::Pairs<'_, Rule>, pest::error::Error<Rule>> {
    let budget = parse_step_budget(text.len());
    let in_force = PARSE_STEPS_IN_FORCE
        .fetch_max(budget, Ordering::Relaxed)
        .max(budget);
    pest::set_call_limit(std::num::NonZeroUsize::new(in_force));
    SdlParser::parse(rule, text)
}

/// A block comment without its `*/` or more `#if`/`#while`/`#macro`... than `#end`s: found
/// by a linear scan before parsing, because the grammar would backtrack over such text in
/// time exponential in the number of open constructs (measured: 20 nested `/*` took 3 s,
/// 20 unterminated `#macro`s 16 s). Such a file never parses, so nothing valid is refused.
pub fn unterminated(text: &str, file: FileId) -> Option<Diagnostic> {
    let bytes = text.as_bytes();
    let mut openers: Vec<(usize, usize)> = Vec::new();
    // The start of the last string that ran over a line break.
    let mut multiline_string: Option<usize> = None;
    // The first `#word` that looks like a misspelt `#end`.
    let mut misspelt_end: Option<(usize, usize)> = None;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                let opened = i;
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if i >= bytes.len() {
                    // A quote left open earlier is closed by the next string's opening
                    // quote: that string then runs over lines, and its start is the mistake.
                    if let Some(earlier) = multiline_string {
                        return Some(
                            Diagnostic::error(
                                Span::new(file, earlier, earlier + 1),
                                "this string runs over several lines: is its closing `\"` missing?",
                            )
                            .with_label("the string starting here ends only at a later quote")
                            .with_help("then the last `\"` of the file opens a string that is never closed; add the missing `\"` where this string ends"),
                        );
                    }
                    let lines = text[opened..].lines().count();
                    let runs = if lines > 1 {
                        format!("this string runs over {lines} lines to the end of the file")
                    } else {
                        "this string runs to the end of the file".to_string()
                    };
                    return Some(
                        Diagnostic::error(
                            Span::new(file, opened, opened + 1),
                            "unterminated string",
                        )
                        .with_label(runs)
                        .with_help("add the closing `\"` where the string ends"),
                    );
                }
                if text[opened..i].contains('\n') {
                    multiline_string = Some(opened);
                }
                i += 1;
            }
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                while i < bytes.len() && bytes[i] != b'\n' && bytes[i] != b'\r' {
                    i += 1;
                }
            }
            b'/' if bytes.get(i + 1) == Some(&b'*') => {
                let opened = i;
                let closed;
                (i, closed) = skip_block_comment(bytes, i);
                if !closed {
                    return Some(
                        Diagnostic::error(Span::new(file, opened, opened + 2), "no `*/` closes this comment")
                            .with_label("this comment runs to the end of the file")
                            .with_help("add `*/` where the comment ends (comments nest: each `/*` needs its own `*/`)"),
                    );
                }
            }
            b'#' => {
                let (word, end) = directive_word(text, i);
                match word {
                    "if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro" => {
                        openers.push((i, end))
                    }
                    "end" => {
                        openers.pop();
                    }
                    // `#ned`: a misspelt `#end` (POV-Ray skips the `#`, so it ends nothing).
                    word if !word.is_empty()
                        && !tokens::DIRECTIVE_WORDS.contains(&word)
                        && crate::diag::suggest_name(word, ["end"]).is_some() =>
                    {
                        misspelt_end.get_or_insert((i, end));
                    }
                    _ => {}
                }
                i = end;
            }
            _ => i += 1,
        }
    }
    let (start, end) = *openers.last()?;
    let word = text[start + 1..end].trim();
    let d = Diagnostic::error(
        Span::new(file, start, end),
        format!("unterminated `#{word}`"),
    )
    .with_label(format!("this `#{word}` has no matching `#end`"));
    Some(match misspelt_end.filter(|(at, _)| *at > start) {
        Some((at, to)) => {
            let typo = text[at + 1..to].trim();
            d.with_secondary(
                Span::new(file, at, to),
                format!("`#{typo}` is not a directive"),
            )
            .with_help(format!("did you mean `#end` instead of `#{typo}`?"))
        }
        None => d.with_help("add `#end` where the directive's body ends"),
    })
}

/// The word after the `#` at byte `hash` of `text` (blanks after the `#` allowed) and the
/// byte just past it.
pub(crate) fn directive_word(text: &str, hash: usize) -> (&str, usize) {
    let rest = &text[hash + 1..];
    let trimmed = rest.trim_start_matches([' ', '\t']);
    let skip = rest.len() - trimmed.len();
    let word_len = trimmed
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(trimmed.len());
    (&trimmed[..word_len], hash + 1 + skip + word_len)
}

/// Skips the (nesting) `/* */` comment opening at `start`: the offset after it and whether
/// it was closed before the end of the text.
pub(super) fn skip_block_comment(bytes: &[u8], start: usize) -> (usize, bool) {
    let mut depth = 0usize;
    let mut i = start;
    while i < bytes.len() {
        if bytes[i] == b'/' && bytes.get(i + 1) == Some(&b'*') {
            depth += 1;
            i += 2;
        } else if bytes[i] == b'*' && bytes.get(i + 1) == Some(&b'/') {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return (i, true);
            }
        } else {
            i += 1;
        }
    }
    (i, false)
}

/// Whether braces opened under a conditional or loop directive close under another branch
/// or after its `#end`, or a block's `{` follows an `#end` that chose its keyword (outside
/// macro bodies, which are handled on their own). A file
/// with unbalanced directives answers `false`, so its syntax error is reported as usual.
pub fn braces_cross_directives(text: &str) -> bool {
    // For each open directive: its word and the brace depth where it opened. Branches are
    // alternatives: each starts from the depth where the directive opened.
    let mut open: Vec<(&str, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut crossed = false;
    let mut position = 0;
    while let Some(token) = tokens::next_token(text, position) {
        position = token.end;
        let in_macro = open.iter().any(|(word, _)| *word == "macro");
        match (token.kind, token.text(text)) {
            (tokens::TokenKind::Punctuation, "{") => depth += 1,
            (tokens::TokenKind::Punctuation, "}") => depth = depth.saturating_sub(1),
            (tokens::TokenKind::Directive, _) => match token.directive_word(text) {
                word @ ("if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro") => {
                    open.push((word, depth))
                }
                "else" | "elseif" | "case" | "range" => match open.last() {
                    Some(&(_, opened)) => {
                        crossed |= !in_macro && opened != depth;
                        depth = opened;
                    }
                    None => return false,
                },
                "end" => match open.pop() {
                    Some((_, opened)) => {
                        crossed |= !in_macro && opened != depth;
                        // A block whose keyword a branch chose: `#if (V) material #else
                        // texture #end { .. }` (LDView's output).
                        let next = tokens::next_token(text, position).map(|t| t.text(text));
                        crossed |= !in_macro && next == Some("{");
                    }
                    None => return false,
                },
                _ => {}
            },
            _ => {}
        }
    }
    crossed && open.is_empty()
}

/// Parses generated text (a text macro's expansion) into items; spans, including a syntax
/// error's, point to where `map` says each piece came from.
pub fn parse_generated(text: &str, map: &OffsetMap) -> Result<Rc<[ast::Item]>, Box<Diagnostic>> {
    match guarded_parse(Rule::file, text) {
        Ok(mut pairs) => {
            let file_pair = pairs.next().expect("file rule");
            let items = file_pair.into_inner().next().expect("items");
            Ok(lower::Lowerer::mapped(map).items(items))
        }
        Err(error) => {
            let mut d = syntax_diagnostic(text, 0, error);
            d.span = map.span(d.span.start as usize, d.span.end as usize);
            Err(Box::new(d))
        }
    }
}

/// A piece of SDL parsed from the start of some text, with the length it took.
pub enum Prefix {
    /// A directive other than the conditionals and loops (`#local`, `#write`, ...).
    Directive(Rc<ast::Directive>),
    /// An expression.
    Expr(ast::Expr),
    /// An `#ifdef` target.
    Target(ast::Target),
    /// A call `Name(arguments)`.
    Call(Rc<ast::Call>),
}

/// Parses the longest start of `text` that `rule` matches (a directive rule, `expr`,
/// `full_expr`, `paren`, `ifdef_target` or `call`); `map` leads offsets of `text` back to the source.
pub fn parse_prefix(
    rule: Rule,
    text: &str,
    map: &OffsetMap,
) -> Result<(Prefix, usize), Box<Diagnostic>> {
    match guarded_parse(rule, text) {
        Ok(mut pairs) => {
            let pair = pairs.next().expect("matched rule");
            let length = pair.as_span().end();
            let lowerer = lower::Lowerer::mapped(map);
            let piece = match rule {
                Rule::expr => Prefix::Expr(lowerer.expr(pair)),
                Rule::full_expr => Prefix::Expr(lowerer.full_expression(pair)),
                Rule::paren => Prefix::Expr(
                    lowerer.full_expression(pair.into_inner().next().expect("parenthesised")),
                ),
                Rule::ifdef_target => Prefix::Target(lowerer.ifdef_target(pair)),
                Rule::call => Prefix::Call(Rc::new(lowerer.macro_call(pair))),
                _ => Prefix::Directive(Rc::new(lowerer.directive_item(pair))),
            };
            Ok((piece, length))
        }
        Err(error) => {
            let mut d = pest_diagnostic(text, 0, error);
            d.span = map.span(d.span.start as usize, d.span.end as usize);
            Err(Box::new(d))
        }
    }
}

#[cfg(test)]
mod crossing_tests {
    use super::braces_cross_directives;

    #[test]
    fn braces_cut_across_branches_are_found() {
        assert!(braces_cross_directives(
            "#if (A) merge { #else union { #end sphere { 0, 1 } }"
        ));
        assert!(braces_cross_directives(
            "#switch (K) #case (1) box { 0, 1 #break #else sphere { 0, 1 #end pigment { rgb 1 } }"
        ));
        assert!(braces_cross_directives(
            "sphere { 0, 1 #if (A) pigment { rgb 1 } } #else } #end"
        ));
        assert!(braces_cross_directives(
            "sphere { 0, 1 #if (V) material #else texture #end { T } }"
        ));
    }

    #[test]
    fn balanced_files_and_macro_bodies_are_not_crossings() {
        assert!(!braces_cross_directives(
            "#if (A) sphere { 0, 1 } #else box { 0, 1 } #end"
        ));
        // A macro body that cuts across braces is a text macro of its own.
        assert!(!braces_cross_directives(
            "#macro M() #if (F) mesh2 { #else union { #end } #end"
        ));
        // Unbalanced directives: the syntax error is reported as usual.
        assert!(!braces_cross_directives("#if (A) union { #else merge { "));
        assert!(!braces_cross_directives("} #end"));
        // Braces in strings and comments do not count.
        assert!(!braces_cross_directives(
            "#if (A) #debug \"{\" // {\n #else /* { */ #end"
        ));
    }
}
