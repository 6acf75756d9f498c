//! Syntax errors in plain words.
//!
//! In: the text pest failed on and where it stopped. Out: one diagnostic saying what is
//! wrong as a person would: an unclosed bracket, a directive written the wrong way
//! (`src/syntax/headers.rs`), an operator POV-Ray does not have, or else what was expected
//! there. Holds: no list of grammar rules reaches the message.

use super::tokens::{next_token, Token, TokenKind};
use super::{balance, headers, keywords, parse_step_budget, Rule};
use super::{PARSE_STEPS_PER_BYTE, PARSE_STEP_LIMIT};
use crate::diag::{suggest_name, Diagnostic, FileId, Span};
use std::sync::atomic::Ordering;

/// Turns a pest error into a diagnostic, preferring an unclosed bracket or directive when
/// the text has one (pest would report where the file ended instead).
pub(super) fn syntax_diagnostic(
    text: &str,
    file: FileId,
    error: pest::error::Error<Rule>,
) -> Diagnostic {
    let unbalanced = balance::unbalanced(text, file, error_offset(&error));
    if let pest::error::ErrorVariant::CustomError { .. } = error.variant {
        // The parser gave up (its step or stack limit): say so, and show the bracket or
        // directive left open, which is the usual cause.
        let d = pest_diagnostic(text, file, error);
        return match unbalanced {
            Some(open) => d.with_secondary(open.span, format!("{}: {}", open.message, open.label)),
            None => d,
        };
    }
    match unbalanced {
        Some(d) => d.with_code("syntax"),
        None => pest_diagnostic(text, file, error),
    }
}

/// Where pest stopped.
fn error_offset(error: &pest::error::Error<Rule>) -> usize {
    match error.location {
        pest::error::InputLocation::Pos(p) => p,
        pest::error::InputLocation::Span((s, _)) => s,
    }
}

/// Turns a pest error into a diagnostic at the place pest stopped.
pub(super) fn pest_diagnostic(
    text: &str,
    file: FileId,
    error: pest::error::Error<Rule>,
) -> Diagnostic {
    let offset = error_offset(&error).min(text.len());
    let found = token_at(text, offset);
    let span = Span::new(
        file,
        offset,
        offset + found.len().max(1).min(text.len() - offset),
    );
    let positives = match &error.variant {
        pest::error::ErrorVariant::ParsingError { positives, .. } => positives.as_slice(),
        pest::error::ErrorVariant::CustomError { message } => {
            return limit_reached(text, span, message).with_code("syntax")
        }
    };
    if let Some(d) = headers::directive_problem(text, file, offset)
        .or_else(|| unclosed_vector(text, file, offset))
        .or_else(|| misplaced_symbol(text, file, offset))
    {
        return d.with_code("syntax");
    }
    let found_text = if found.is_empty() {
        "end of file".to_string()
    } else {
        format!("`{found}`")
    };
    let mut d = match describe_expected(positives) {
        Some(expected) => {
            Diagnostic::error(span, format!("expected {expected}, found {found_text}"))
                .with_label(format!("expected {expected} here"))
        }
        None if found.is_empty() => Diagnostic::error(span, "unexpected end of file")
            .with_label("the file ends here")
            .with_help("something is missing before the end of the file"),
        None => Diagnostic::error(span, format!("unexpected {found_text}"))
            .with_label(format!("`{found}` cannot stand here")),
    };
    let is_word = found
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    // A word the user typed that is itself a keyword is no typo of another one.
    if is_word && !keywords::ALL.contains(&found) {
        if let Some(k) = suggest_name(found, keywords::ALL.iter().copied()) {
            d = d.with_help(format!("did you mean `{k}`?"));
        }
    }
    d.with_code("syntax")
}

/// The parser gave up: its step or stack limit was reached.
fn limit_reached(text: &str, span: Span, message: &str) -> Diagnostic {
    if !message.contains("limit reached") {
        return Diagnostic::error(span, message.to_string());
    }
    let budget = parse_step_budget(text.len());
    let what = if message.contains("stack") {
        "ran out of stack: the text nests too deeply".to_string()
    } else {
        format!(
            "gave up after {budget} steps: the text makes the grammar try too many \
             readings (often an unclosed `<`, `(` or `[`)"
        )
    };
    Diagnostic::error(span, format!("the parser {what}"))
        .with_label("the parser stopped here")
        .with_help(format!(
            "this is the `parse-steps` limit ({} plus {PARSE_STEPS_PER_BYTE} per byte); \
             check the brackets before this point, or raise it with --limit parse-steps=N",
            PARSE_STEP_LIMIT.load(Ordering::Relaxed)
        ))
}

/// The word or symbol starting at `offset`.
fn token_at(text: &str, offset: usize) -> &str {
    let rest = text.get(offset..).unwrap_or("");
    let word_len = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    if word_len > 0 {
        &rest[..word_len]
    } else {
        rest.char_indices().nth(1).map_or(rest, |(i, _)| &rest[..i])
    }
}

/// What the parser wanted, when one plain name says it; `None` when it wanted one of
/// several unrelated things (the message then says what it found instead).
fn describe_expected(rules: &[Rule]) -> Option<&'static str> {
    let mut names: Vec<&str> = rules.iter().filter_map(|r| rule_name(*r)).collect();
    names.sort_unstable();
    names.dedup();
    const VALUES: [&str; 6] = [
        "an expression",
        "a number",
        "a vector",
        "an identifier",
        "a string",
        "a block",
    ];
    match names.as_slice() {
        [] => None,
        [one] => Some(one),
        many if many.iter().all(|n| VALUES.contains(n)) => Some("a value"),
        _ => None,
    }
}

/// Human names for grammar rules in error messages (`None`: no plain name).
fn rule_name(rule: Rule) -> Option<&'static str> {
    Some(match rule {
        Rule::expr
        | Rule::full_expr
        | Rule::postfix_expr
        | Rule::relational_expr
        | Rule::logical_expr => "an expression",
        Rule::number => "a number",
        Rule::string => "a string",
        Rule::ident | Rule::target => "an identifier",
        Rule::block | Rule::block_head => "a block",
        Rule::end => "`#end`",
        Rule::vector => "a vector",
        Rule::map_entry => "a map entry",
        Rule::parameters | Rule::parameter => "a parameter",
        _ => return None,
    })
}

/// The tokens that start before `offset`, and the one at or after it.
pub(super) fn tokens_around(text: &str, offset: usize) -> (Vec<Token>, Option<Token>) {
    let mut before = Vec::new();
    let mut position = 0;
    while let Some(token) = next_token(text, position) {
        if token.end > offset {
            // A token pest stopped inside (`#ifdef` stopped at `ifdef`) counts as found.
            return (before, Some(token));
        }
        position = token.end;
        before.push(token);
    }
    (before, None)
}

/// Words that are values, though reserved (`clock < 1`).
const VALUE_WORDS: &[&str] = &[
    "clock", "pi", "tau", "true", "false", "yes", "no", "on", "off", "x", "y", "z", "t", "u", "v",
];

/// Whether `token` ends an operand, so that a `<` after it compares.
fn ends_operand(text: &str, token: &Token) -> bool {
    let word = token.text(text);
    match token.kind {
        TokenKind::Number | TokenKind::String => true,
        TokenKind::Word => !keywords::ALL.contains(&word) || VALUE_WORDS.contains(&word),
        TokenKind::Punctuation => matches!(word, ")" | "]" | ">"),
        TokenKind::Directive => false,
    }
}

/// Whether `token` (`None`: the end of the text) ends what a vector could hold.
fn ends_values(text: &str, token: Option<&Token>) -> bool {
    token.is_none_or(|t| {
        t.kind == TokenKind::Directive || matches!(t.text(text), "}" | ")" | "]" | ";" | "{")
    })
}

/// A `<` still open where the parser stopped at something no vector holds: "unclosed `<`".
fn unclosed_vector(text: &str, file: FileId, offset: usize) -> Option<Diagnostic> {
    let (before, found) = tokens_around(text, offset);
    if !ends_values(text, found.as_ref()) {
        return None;
    }
    let mut stack: Vec<(u8, usize)> = Vec::new();
    let mut previous: Option<&Token> = None;
    for token in &before {
        let symbol = token.text(text);
        if token.kind == TokenKind::Punctuation {
            match symbol {
                "{" | "(" | "[" => stack.push((symbol.as_bytes()[0], token.start)),
                "}" | ")" | "]" => {
                    let opener = match symbol {
                        "}" => b'{',
                        ")" => b'(',
                        _ => b'[',
                    };
                    while stack.last().is_some_and(|(k, _)| *k == b'<') {
                        stack.pop();
                    }
                    if stack.last().is_some_and(|(k, _)| *k == opener) {
                        stack.pop();
                    }
                }
                "<" => {
                    // After a value a `<` compares (`A < B`), after a vector's `>` it starts
                    // the next vector (`<0, 0, 0> <1, 0, 0>`).
                    let after_value =
                        previous.is_some_and(|p| p.text(text) != ">" && ends_operand(text, p));
                    let compares = text[token.end..].starts_with('=') || after_value;
                    if !compares {
                        stack.push((b'<', token.start));
                    }
                }
                ">" if stack.last().is_some_and(|(k, _)| *k == b'<') => {
                    stack.pop();
                }
                _ => {}
            }
        }
        previous = Some(token);
    }
    let &(kind, start) = stack.last()?;
    if kind != b'<' {
        return None;
    }
    let stop = found.map(|t| t.start);
    Some(balance::unclosed(
        text,
        file,
        (b'<', start, start + 1),
        stop,
    ))
}

/// An operator POV-Ray does not have (`^`, `%`, `==`, `&&`), a `>` that closes nothing, a
/// comparison outside parentheses, `\\` for a comment or a misspelt directive.
fn misplaced_symbol(text: &str, file: FileId, offset: usize) -> Option<Diagnostic> {
    let (before, found) = tokens_around(text, offset);
    if let Some(d) = unknown_directive(text, file, &before, found.as_ref()) {
        return Some(d);
    }
    let found = found?;
    let symbol = found.text(text);
    let previous = before.last();
    let next = next_token(text, found.end);
    let span = Span::new(file, found.start, found.end);
    let doubled = |what: &str| {
        previous.filter(|p| p.end == found.start && p.text(text) == what && symbol == what)
    };
    if symbol == "\\" {
        if text[found.end..].starts_with('\\') {
            return Some(
                Diagnostic::error(
                    Span::new(file, found.start, found.end + 1),
                    "`\\\\` does not start a comment",
                )
                .with_label("POV-Ray reads a stray `\\` here")
                .with_help("comments start with `//` (or are written `/* ... */`)"),
            );
        }
        return Some(
            Diagnostic::error(span, "unexpected `\\`")
                .with_label("`\\` is only allowed inside strings"),
        );
    }
    if symbol == "^" || symbol == "%" {
        let (function, what) = if symbol == "^" {
            ("pow", "powers")
        } else {
            ("mod", "the remainder")
        };
        let simple = |t: Option<&Token>| {
            t.filter(|t| matches!(t.kind, TokenKind::Number | TokenKind::Word))
                .map(|t| t.text(text))
        };
        let example = match (simple(previous), simple(next.as_ref())) {
            (Some(a), Some(b)) => format!("`{function}({a}, {b})`"),
            _ => format!("`{function}(A, B)`"),
        };
        return Some(
            Diagnostic::error(span, format!("POV-Ray has no `{symbol}` operator"))
                .with_label("not an operator")
                .with_help(format!("write {what} with `{function}`: {example}")),
        );
    }
    for (pair, single, meaning) in [("=", "=", "compares"), ("&", "&", "and"), ("|", "|", "or")] {
        if let Some(first) = doubled(pair) {
            let help = match meaning {
                "compares" => "POV-Ray compares with a single `=`, inside parentheses: `(A = 1)`",
                "and" => "POV-Ray's *and* is a single `&`: `(A > 0 & A < 2)`",
                _ => "POV-Ray's *or* is a single `|`: `(A < 0 | A > 2)`",
            };
            return Some(
                Diagnostic::error(
                    Span::new(file, first.start, found.end),
                    format!("`{pair}{single}` is not an operator in POV-Ray"),
                )
                .with_label(format!("write a single `{single}`"))
                .with_help(help),
            );
        }
    }
    // `>=`, `<=`, `!=`: the operator and what follows it.
    let (symbol, next, span) = match next {
        Some(n)
            if ["<", ">", "!"].contains(&symbol) && n.start == found.end && n.text(text) == "=" =>
        {
            let operator = &text[found.start..n.end];
            (
                operator,
                next_token(text, n.end),
                Span::new(file, found.start, n.end),
            )
        }
        _ => (symbol, next, span),
    };
    if symbol == ">" {
        if previous.is_some_and(|p| p.text(text) == ">") {
            return Some(
                Diagnostic::error(span, "an extra `>`")
                    .with_label("this `>` closes no `<`")
                    .with_help("remove it: the vector before it is already closed"),
            );
        }
        if next.as_ref().is_none_or(|n| !starts_operand(text, n)) {
            return Some(
                Diagnostic::error(span, "a `>` without its `<`")
                    .with_label("no `<` opens a vector before this `>`")
                    .with_help("a vector is written `<1, 2, 3>`"),
            );
        }
    }
    let compares = ["<", ">", "=", "&", "|", "?", "<=", ">=", "!="].contains(&symbol)
        && previous.is_some_and(|p| ends_operand(text, p))
        && next.as_ref().is_some_and(|n| starts_operand(text, n));
    if compares {
        let what = match symbol {
            "&" | "|" => "logical operators",
            "?" => "the conditional `? :`",
            _ => "comparisons",
        };
        let simple = |t: Option<&Token>| {
            t.filter(|t| matches!(t.kind, TokenKind::Number | TokenKind::Word))
                .map(|t| t.text(text))
        };
        let example = match (simple(previous), simple(next.as_ref())) {
            (Some(a), Some(b)) if symbol != "?" => format!("({a} {symbol} {b})"),
            _ => format!("(A {symbol} B)"),
        };
        return Some(
            Diagnostic::error(span, format!("`{symbol}` outside parentheses"))
                .with_label(format!("{what} are only allowed inside parentheses"))
                .with_help(format!(
                    "as in POV-Ray, write `{example}`: comparisons, `&`, `|` and `? :` \
                     need parentheses around them"
                )),
        );
    }
    None
}

/// Whether `token` can start an operand (`A > 1`, not `3> }`).
fn starts_operand(text: &str, token: &Token) -> bool {
    match token.kind {
        TokenKind::Number | TokenKind::String => true,
        TokenKind::Word => ends_operand(text, token),
        TokenKind::Punctuation => matches!(token.text(text), "(" | "<" | "-" | "+" | "!"),
        TokenKind::Directive => false,
    }
}

/// `#delcare R = 1;`: a `#` and a misspelt directive word shortly before where the parser
/// stopped (POV-Ray skips a `#` that starts no directive, so the word reads as a name).
fn unknown_directive(
    text: &str,
    file: FileId,
    before: &[Token],
    found: Option<&Token>,
) -> Option<Diagnostic> {
    let recent = before.iter().rev().take(6).chain(found);
    for token in recent {
        if token.kind != TokenKind::Word {
            continue;
        }
        let before = text[..token.start].trim_end_matches([' ', '\t']);
        let hash = match before.strip_suffix('#') {
            Some(rest) => rest.len(),
            // The text a macro produced has lost the `#`: a line `locl R = 1;`.
            None if before.is_empty() || before.ends_with(['\n', '\r']) => {
                let declares = next_token(text, token.end)
                    .filter(|t| t.kind == TokenKind::Word)
                    .and_then(|t| next_token(text, t.end))
                    .is_some_and(|t| t.text(text) == "=");
                if !declares {
                    continue;
                }
                token.start
            }
            None => continue,
        };
        let word = token.text(text);
        let Some(directive) = suggest_name(word, super::tokens::DIRECTIVE_WORDS.iter().copied())
        else {
            continue;
        };
        return Some(
            Diagnostic::error(
                Span::new(file, hash, token.end),
                format!("unknown directive `#{word}`"),
            )
            .with_label("not a directive")
            .with_help(format!("did you mean `#{directive}`?")),
        );
    }
    None
}

#[cfg(test)]
mod tests {
    use crate::diag::Diagnostic;

    fn error(text: &str) -> Diagnostic {
        *super::super::parse(text, 0).expect_err(text)
    }

    /// The message, and the label of the second span if there is one.
    fn said(text: &str) -> (String, Option<String>) {
        let d = error(text);
        (d.message, d.labels.first().map(|(_, label)| label.clone()))
    }

    #[test]
    fn unclosed_brackets_are_named_with_where_their_closer_was_due() {
        let cases = [
            (
                "#declare A = max(1, 2;\n",
                "unclosed `(`",
                "expected `)` before this `;`",
            ),
            (
                "#declare A = B[1 + 2;\n",
                "unclosed `[`",
                "expected `]` before this `;`",
            ),
            (
                "sphere { 0, 1 scale <1, 2, 3 }\n",
                "unclosed `<`",
                "expected `>` before this `}`",
            ),
            (
                "sphere { 0, (1 + 2 }\n",
                "unclosed `(`",
                "expected `)` before this `}`",
            ),
            (
                "#if (1\n  box { 0, 1 }\n#end\n",
                "unclosed `(`",
                "expected `)` before this `box`",
            ),
            (
                "#declare S = concat(\"a\", \"b\"\n",
                "unclosed `(`",
                "expected `)` after this",
            ),
        ];
        for (text, message, label) in cases {
            assert_eq!(said(text), (message.into(), Some(label.into())), "{text}");
        }
    }

    #[test]
    fn a_stray_brace_names_the_block_that_misses_its_opening_one() {
        assert_eq!(
            said("sphere 0, 1 }"),
            (
                "unexpected `}`".into(),
                Some("no `{` after this `sphere`".into())
            )
        );
        assert_eq!(said("sphere { 0, 1 } }"), ("unexpected `}`".into(), None));
    }

    #[test]
    fn operators_pov_ray_lacks_are_named() {
        let cases = [
            ("#declare A = 2 ^ 3;", "POV-Ray has no `^` operator"),
            ("#declare A = 7 % 3;", "POV-Ray has no `%` operator"),
            ("#if (A || B) #end", "`||` is not an operator in POV-Ray"),
            ("#declare A = (1 + 2));", "unmatched `)`"),
            ("sphere { 0, 1] }", "unmatched `]`"),
            ("box { <0, 0, 0>, <1, 1, 1>> }", "an extra `>`"),
            ("box { 0, 1 scale 2, 2, 2> }", "a `>` without its `<`"),
            ("#declare C = A = B;", "`=` outside parentheses"),
            ("#declare C = A >= 1;", "`>=` outside parentheses"),
        ];
        for (text, message) in cases {
            assert_eq!(error(text).message, message, "{text}");
        }
    }

    #[test]
    fn malformed_directive_heads_are_named() {
        let cases = [
            (
                "#ifndef B\n#declare B = 1;\n#end\n",
                "`#ifndef` needs parentheses around the name",
            ),
            ("#for (I, 1, 2, 3, 4)\n#end\n", "`#for` has too many values"),
            ("#for I, 1, 2\n#end\n", "`#for` needs parentheses"),
            (
                "#switch (1)\n#declare A = 1;\n#case (1)\n#end\n",
                "`#switch` must start with `#case` or `#range`",
            ),
            (
                "#macro M(A, B = 2)\n#end\n",
                "macro parameters cannot have default values",
            ),
            ("#local = 2;\n", "`#local` needs a name"),
            (
                "#declare V.y = 2;\n",
                "a vector component cannot be assigned",
            ),
            ("#declare ball-size = 2;\n", "a name cannot contain `-`"),
            ("#decalre R = 1;\n", "unknown directive `#decalre`"),
        ];
        for (text, message) in cases {
            assert_eq!(error(text).message, message, "{text}");
        }
    }

    #[test]
    fn other_errors_say_what_was_found_in_plain_words() {
        for text in [
            "sphere { 0, 1 } }",
            "#declare A = ;",
            "box { 0, 1 } ,, {",
            "#version",
        ] {
            let d = error(text);
            for phrase in [
                "something else",
                "block or",
                "directive, block",
                "or an expression",
            ] {
                assert!(!d.message.contains(phrase), "{text}: {}", d.message);
            }
        }
    }
}
