//! Assertion-style language cases: each `tests/language/*.pov` must evaluate without error
//! (the cases use `#error` when a check fails).

use crate::{evaluate, tests_folder};
use durer::diag::Severity;

#[test]
fn language_cases_pass() {
    let mut failures = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir(tests_folder().join("language"))
        .expect("tests/language exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    paths.sort();
    assert!(
        paths.len() >= 3,
        "expected language cases, found {}",
        paths.len()
    );
    for path in paths {
        let evaluated = evaluate(&path);
        for d in evaluated
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
        {
            failures.push(durer::report::render_plain(d, &evaluated.sources));
        }
    }
    assert!(
        failures.is_empty(),
        "language cases failed:\n{}",
        failures.join("\n")
    );
}
