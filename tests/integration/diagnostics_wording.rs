//! Diagnostics read as a person would write them: no message, label or help lists grammar
//! rules ("expected `,`, a block or something else"). Checked on every diagnostic fixture and
//! fuzz-found file, and on the syntax errors of many broken variants of the fixtures (each
//! with one bracket, operator or separator removed or doubled), so that the wording holds for
//! files never seen.

use crate::{evaluate, tests_folder};
use durer::diag::Diagnostic;
use std::path::PathBuf;

/// Phrases that only a list of grammar rules produces.
const RULE_LIST_PHRASES: &[&str] = &[
    "something else",
    "a directive, block or value",
    "a block or an expression",
    "a block or ",
    "`,`, a block",
    "or an expression",
    "or a keyword",
    "arguments or",
];

/// The first rule-list phrase in any text of `d`.
fn rule_list_phrase(d: &Diagnostic) -> Option<&'static str> {
    let texts = std::iter::once(d.message.as_str())
        .chain(std::iter::once(d.label.as_str()))
        .chain(d.help.as_deref())
        .chain(d.labels.iter().map(|(_, label)| label.as_str()));
    let all: Vec<&str> = texts.collect();
    RULE_LIST_PHRASES
        .iter()
        .copied()
        .find(|phrase| all.iter().any(|text| text.contains(phrase)))
}

fn pov_files(folder: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(tests_folder().join(folder))
        .expect("read a test folder")
        .map(|entry| entry.expect("a folder entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "pov"))
        .collect();
    files.sort();
    files
}

#[test]
fn no_fixture_message_lists_grammar_rules() {
    let mut failures = Vec::new();
    for folder in ["diagnostics", "fuzz_found"] {
        for path in pov_files(folder) {
            let evaluated = evaluate(&path);
            for d in &evaluated.diagnostics {
                if let Some(phrase) = rule_list_phrase(d) {
                    failures.push(format!(
                        "{}: {:?} (contains {phrase:?})",
                        path.display(),
                        d.message
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn no_syntax_error_of_a_broken_variant_lists_grammar_rules() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for path in pov_files("diagnostics") {
        let text = std::fs::read_to_string(&path).expect("read a fixture");
        for (at, c) in text.char_indices() {
            if !"(){}[]<>,;=\"+-*/".contains(c) {
                continue;
            }
            let end = at + c.len_utf8();
            let removed = format!("{}{}", &text[..at], &text[end..]);
            let doubled = format!("{}{c}{}", &text[..end], &text[end..]);
            for variant in [removed, doubled] {
                if let Err(d) = durer::syntax::parse(&variant, 0) {
                    checked += 1;
                    if let Some(phrase) = rule_list_phrase(&d) {
                        failures.push(format!(
                            "{} with `{c}` at byte {at} changed: {:?} (contains {phrase:?})",
                            path.display(),
                            d.message
                        ));
                    }
                }
            }
        }
    }
    assert!(checked > 1000, "only {checked} broken variants");
    assert!(
        failures.is_empty(),
        "{} messages list rules:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
