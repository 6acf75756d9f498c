//! Diagnostics: each broken scene in `tests/diagnostics/` declares, in comments, the diagnostic
//! it must report, and one runner checks them all (see `tests/diagnostics/README.md`).
//!
//! The annotations, each on a line of its own:
//!
//! - `// error: LINE:COLUMN TEXT`: the first error is at LINE:COLUMN (1-based) and its rendered
//!   plain report (`durer::report::render_plain`) contains TEXT. At most one per file.
//! - `// error-text: TEXT`: a further piece of text that error's report contains.
//! - `// warning: LINE:COLUMN TEXT`: a warning at LINE:COLUMN whose message contains TEXT.
//!   When a file declares warnings, the warnings it reports must be exactly those, in order.
//! - `// warning-text: TEXT`: a further piece of text the message of the warning above contains.
//!
//! A file without `// error:` must evaluate to a scene with no error. A `.pov` file without any
//! `// error:` or `// warning:` line is a failure, so that a fixture cannot silently check
//! nothing; files a fixture reads (images, density files, includes) must not end in `.pov`.

use crate::{evaluate, tests_folder};
use durer::diag::{Diagnostic, Severity};
use durer::eval::Evaluated;
use std::path::Path;

/// An expected diagnostic: where it starts and the texts it must contain.
#[derive(Debug, Clone, PartialEq)]
struct Expected {
    line: usize,
    column: usize,
    needles: Vec<String>,
}

/// What a fixture declares in its annotations.
#[derive(Debug, Clone, PartialEq, Default)]
struct Expectations {
    /// The first error, or `None` when the scene must evaluate without error.
    error: Option<Expected>,
    /// Every warning, in order; not checked when empty and an error is declared.
    warnings: Vec<Expected>,
}

/// Parses the annotations of the fixture `name` (used in error messages) from its `text`.
fn parse_annotations(name: &str, text: &str) -> Result<Expectations, String> {
    let mut expectations = Expectations::default();
    let mut error_texts = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let at = format!("{name}:{}", index + 1);
        let Some(comment) = line.trim_start().strip_prefix("//") else {
            continue;
        };
        let comment = comment.trim_start();
        let Some((key, rest)) = comment.split_once(':') else {
            continue;
        };
        let rest = rest.trim();
        match key {
            "error" => {
                if expectations.error.is_some() {
                    return Err(format!("{at}: a second `// error:` line (one per file)"));
                }
                expectations.error = Some(parse_expected(&at, rest)?);
            }
            "error-text" => error_texts.push(needle(&at, key, rest)?),
            "warning" => expectations.warnings.push(parse_expected(&at, rest)?),
            "warning-text" => {
                let text = needle(&at, key, rest)?;
                match expectations.warnings.last_mut() {
                    Some(warning) => warning.needles.push(text),
                    None => {
                        return Err(format!("{at}: `// warning-text:` before any `// warning:`"))
                    }
                }
            }
            _ if !key.contains(char::is_whitespace)
                && (key.starts_with("error") || key.starts_with("warning")) =>
            {
                return Err(format!(
                    "{at}: unknown annotation `// {key}:` (expected error, error-text, \
                     warning or warning-text)"
                ));
            }
            _ => {}
        }
    }
    match &mut expectations.error {
        Some(error) => error.needles.extend(error_texts),
        None if !error_texts.is_empty() => {
            return Err(format!(
                "{name}: `// error-text:` without a `// error:` line"
            ));
        }
        None if expectations.warnings.is_empty() => {
            return Err(format!(
                "{name}: no `// error:` or `// warning:` annotation, so it checks nothing"
            ));
        }
        None => {}
    }
    Ok(expectations)
}

/// Parses `LINE:COLUMN TEXT`.
fn parse_expected(at: &str, rest: &str) -> Result<Expected, String> {
    let malformed =
        || format!("{at}: expected `LINE:COLUMN TEXT` after the annotation, found `{rest}`");
    let (location, text) = rest.split_once(char::is_whitespace).ok_or_else(malformed)?;
    let (line, column) = location.split_once(':').ok_or_else(malformed)?;
    let line: usize = line.parse().map_err(|_| malformed())?;
    let column: usize = column.parse().map_err(|_| malformed())?;
    if line == 0 || column == 0 {
        return Err(format!(
            "{at}: lines and columns count from 1, found `{location}`"
        ));
    }
    Ok(Expected {
        line,
        column,
        needles: vec![needle(at, "location", text)?],
    })
}

fn needle(at: &str, key: &str, text: &str) -> Result<String, String> {
    let text = text.trim();
    if text.is_empty() {
        Err(format!("{at}: `{key}` annotation without text"))
    } else {
        Ok(text.to_string())
    }
}

/// The report with the lines that show annotations left out: miette shows source lines around
/// the error, and an annotation shown there would otherwise match its own needle.
fn without_annotations(report: &str) -> String {
    report
        .lines()
        .filter(|line| {
            ![
                "// error:",
                "// error-text:",
                "// warning:",
                "// warning-text:",
            ]
            .iter()
            .any(|marker| line.contains(marker))
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn position(evaluated: &Evaluated, diagnostic: &Diagnostic) -> (usize, usize) {
    evaluated
        .sources
        .line_column(diagnostic.span.file, diagnostic.span.start)
}

/// What is wrong with the outcome of evaluating a fixture, one line per problem (none: it passed).
fn problems(expectations: &Expectations, evaluated: &Evaluated) -> Vec<String> {
    let mut problems = Vec::new();
    let first_error = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error);
    match (&expectations.error, first_error) {
        (Some(expected), None) => problems.push(format!(
            "expected an error at {}:{}, found no error",
            expected.line, expected.column
        )),
        (Some(expected), Some(error)) => {
            let (line, column) = position(evaluated, error);
            let report = durer::report::render_plain(error, &evaluated.sources);
            let searched = without_annotations(&report);
            let mut wrong = Vec::new();
            if (line, column) != (expected.line, expected.column) {
                wrong.push(format!(
                    "expected the error at {}:{}, found it at {line}:{column}",
                    expected.line, expected.column
                ));
            }
            for needle in &expected.needles {
                if !searched.contains(needle.as_str()) {
                    wrong.push(format!("missing {needle:?} in the report"));
                }
            }
            if !wrong.is_empty() {
                problems.extend(wrong);
                problems.push(format!("the report:\n{report}"));
            }
        }
        (None, Some(error)) => {
            let (line, column) = position(evaluated, error);
            problems.push(format!(
                "expected no error, found one at {line}:{column}:\n{}",
                durer::report::render_plain(error, &evaluated.sources)
            ));
        }
        (None, None) => {
            if evaluated.scene.is_none() {
                problems.push("expected a scene, found none".to_string());
            }
        }
    }
    if !expectations.warnings.is_empty() {
        let warnings: Vec<((usize, usize), &str)> = evaluated
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Warning)
            .map(|d| (position(evaluated, d), d.message.as_str()))
            .collect();
        let matches = |expected: &Expected, &((line, column), message): &((usize, usize), &str)| {
            (line, column) == (expected.line, expected.column)
                && expected
                    .needles
                    .iter()
                    .all(|n| message.contains(n.as_str()))
        };
        let all_match = warnings.len() == expectations.warnings.len()
            && expectations
                .warnings
                .iter()
                .zip(&warnings)
                .all(|(expected, found)| matches(expected, found));
        if !all_match {
            let mut text = String::from("expected the warnings:");
            for expected in &expectations.warnings {
                text.push_str(&format!(
                    "\n  {}:{} {:?}",
                    expected.line, expected.column, expected.needles
                ));
            }
            text.push_str("\nfound the warnings:");
            for ((line, column), message) in &warnings {
                text.push_str(&format!("\n  {line}:{column} {message}"));
            }
            problems.push(text);
        }
    }
    problems
}

/// Evaluates every `tests/diagnostics/*.pov` (sorted) and checks it reports what it declares;
/// all failures are listed together.
#[test]
fn every_diagnostic_fixture_reports_what_it_declares() {
    let folder = tests_folder().join("diagnostics");
    let mut fixtures: Vec<_> = std::fs::read_dir(&folder)
        .expect("read tests/diagnostics")
        .map(|entry| entry.expect("read a folder entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "pov"))
        .collect();
    fixtures.sort();
    assert!(!fixtures.is_empty(), "no fixtures in {}", folder.display());
    let mut failures = Vec::new();
    for path in &fixtures {
        let name = file_name(path);
        let text = std::fs::read_to_string(path).expect("read a fixture");
        let expectations = match parse_annotations(&name, &text) {
            Ok(expectations) => expectations,
            Err(message) => {
                failures.push(format!("--- {name}\n{message}"));
                continue;
            }
        };
        let problems = problems(&expectations, &evaluate(path));
        if !problems.is_empty() {
            failures.push(format!("--- {name}\n{}", problems.join("\n")));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} diagnostic fixtures failed:\n\n{}",
        failures.len(),
        fixtures.len(),
        failures.join("\n\n")
    );
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Kept as a Rust test: the scene writes a file, so it runs in a scratch folder instead of
/// `tests/diagnostics/`, where `#fopen .. write` would create `out.bin` in the source tree.
#[test]
fn binary_write_of_a_string_names_the_type() {
    let dir = crate::scratch("binary-write-string");
    let scene = dir.join("binary_write.pov");
    std::fs::write(
        &scene,
        "#fopen Out \"out.bin\" write\n#write (Out, uint8 65, uint16be \"text\")\n",
    )
    .expect("write scene");
    let evaluated = evaluate(&scene);
    let error = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error)
        .expect("an error");
    let (line, column) = evaluated
        .sources
        .line_column(error.span.file, error.span.start);
    let text = durer::report::render_plain(error, &evaluated.sources);
    assert_eq!((line, column), (2, 33), "{text}");
    assert!(
        text.contains("binary `#write` needs a float or a vector, found a string"),
        "{text}"
    );
}

#[test]
fn an_error_annotation_gives_location_and_texts() {
    let text = "// error: 3:14 undefined identifier `Raduis`\n\
                // error-text: did you mean `Radius`?\n\
                // an ordinary comment: not an annotation\n\
                \n\
                sphere { 0, Raduis }\n";
    let expectations = parse_annotations("scene.pov", text).expect("parses");
    assert_eq!(
        expectations,
        Expectations {
            error: Some(Expected {
                line: 3,
                column: 14,
                needles: vec![
                    "undefined identifier `Raduis`".to_string(),
                    "did you mean `Radius`?".to_string()
                ],
            }),
            warnings: Vec::new(),
        }
    );
}

#[test]
fn warning_texts_belong_to_the_warning_above() {
    let text = "// warning: 2:10 lemon\n// warning-text: too small\n// warning: 5:1 other\n";
    let expectations = parse_annotations("scene.pov", text).expect("parses");
    assert_eq!(expectations.error, None);
    assert_eq!(
        expectations.warnings,
        vec![
            Expected {
                line: 2,
                column: 10,
                needles: vec!["lemon".to_string(), "too small".to_string()],
            },
            Expected {
                line: 5,
                column: 1,
                needles: vec!["other".to_string()],
            },
        ]
    );
}

#[test]
fn malformed_annotations_are_errors_naming_the_file_and_line() {
    let cases = [
        (
            "// error: 3 undefined identifier\n",
            "bad.pov:1: expected `LINE:COLUMN TEXT`",
        ),
        (
            "// error: 3:x text\n",
            "bad.pov:1: expected `LINE:COLUMN TEXT`",
        ),
        ("// error: 3:14\n", "bad.pov:1: expected `LINE:COLUMN TEXT`"),
        (
            "// error: 0:14 text\n",
            "bad.pov:1: lines and columns count from 1",
        ),
        (
            "\n// error: 1:1 a\n// error: 2:2 b\n",
            "bad.pov:3: a second `// error:`",
        ),
        (
            "// warning-text: text\n",
            "bad.pov:1: `// warning-text:` before any",
        ),
        (
            "// errors: 1:1 text\n",
            "bad.pov:1: unknown annotation `// errors:`",
        ),
        (
            "// error: 1:1 text\n// error-text:   \n",
            "bad.pov:2: `error-text` annotation without text",
        ),
        (
            "// error-text: text\n",
            "bad.pov: `// error-text:` without a `// error:` line",
        ),
    ];
    for (text, expected) in cases {
        let error = parse_annotations("bad.pov", text).expect_err(text);
        assert!(error.starts_with(expected), "{text:?}: {error}");
    }
}

#[test]
fn a_fixture_without_annotations_checks_nothing_and_is_refused() {
    let error = parse_annotations("plain.pov", "// just a comment\nsphere { 0, 1 }\n")
        .expect_err("no annotation");
    assert!(error.contains("plain.pov"), "{error}");
    assert!(error.contains("checks nothing"), "{error}");
}

#[test]
fn annotations_shown_in_a_report_do_not_match_themselves() {
    let report = "scene.pov:3:1: unclosed `{`\n 2 │ // error-text: this `{` is never closed\n 3 │ sphere {\n";
    let searched = without_annotations(report);
    assert!(!searched.contains("never closed"), "{searched}");
    assert!(searched.contains("unclosed `{`"), "{searched}");
}

/// `text { internal N }` names the POV-Ray font file it stands for when that file is not on
/// the search path (POV-Ray's installed include folder left out here on purpose).
#[test]
fn a_missing_internal_font_names_its_file() {
    let dir = crate::scratch("internal-font");
    let path = dir.join("internal.pov");
    std::fs::write(&path, "text { internal 3 \"abc\" 0.1, 0 }\n").expect("write scene");
    let options = durer::eval::EvalOptions {
        search_installed_povray: false,
        ..durer::eval::EvalOptions::default()
    };
    let evaluated = crate::evaluate_with(&path, options);
    let error = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error)
        .expect("the font is not found");
    let report = durer::report::render_plain(error, &evaluated.sources);
    assert!(
        report.contains("font file `crystal.ttf` not found"),
        "{report}"
    );
    assert!(report.contains("POV-Ray's `crystal.ttf`"), "{report}");
    assert_eq!(error.span.start, 16, "at the font number");
}
