//! Diagnostics: each error case reports the right place, message and help.

use crate::{evaluate, tests_folder};
use durer::diag::Severity;

/// Evaluates `tests/diagnostics/NAME.pov` and returns (line, column, rendered report).
fn first_error(name: &str) -> (usize, usize, String) {
    let path = tests_folder()
        .join("diagnostics")
        .join(format!("{name}.pov"));
    let evaluated = evaluate(&path);
    let error = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error)
        .unwrap_or_else(|| panic!("{name}: expected an error"));
    let (line, column) = evaluated
        .sources
        .line_column(error.span.file, error.span.start);
    (
        line,
        column,
        durer::report::render_plain(error, &evaluated.sources),
    )
}

fn check(name: &str, line: usize, column: usize, needles: &[&str]) {
    let (l, c, text) = first_error(name);
    assert_eq!((l, c), (line, column), "{name}: wrong location\n{text}");
    for needle in needles {
        assert!(
            text.contains(needle),
            "{name}: missing {needle:?} in\n{text}"
        );
    }
}

#[test]
fn unclosed_brace_points_at_the_open_brace() {
    check(
        "unclosed_brace",
        1,
        8,
        &["unclosed `{`", "this `{` is never closed"],
    );
}

#[test]
fn undefined_identifier_suggests_a_declared_name() {
    check(
        "undefined_identifier",
        2,
        13,
        &["undefined identifier `Raduis`", "did you mean `Radius`?"],
    );
}

#[test]
fn misspelt_block_keyword_suggests_the_keyword() {
    check(
        "misspelt_keyword",
        2,
        3,
        &["unknown block keyword `pigmnet`", "did you mean `pigment`?"],
    );
}

#[test]
fn misspelt_modifier_suggests_the_keyword() {
    check(
        "misspelt_modifier",
        1,
        15,
        &["`tranlate`", "did you mean `translate`?"],
    );
}

#[test]
fn wrong_argument_count_names_the_parameters() {
    check(
        "macro_arguments",
        2,
        14,
        &[
            "macro `Add` takes 2 arguments, found 1",
            "parameters: (A, B)",
        ],
    );
}

#[test]
fn array_index_out_of_range_shows_index_and_size() {
    check(
        "array_index",
        2,
        14,
        &["array index [5] out of range", "size is [3]"],
    );
}

#[test]
fn type_mismatch_names_both_types() {
    check(
        "type_mismatch",
        1,
        14,
        &["cannot combine a vector and a string"],
    );
}

#[test]
fn runaway_recursion_is_an_error_not_a_crash() {
    check(
        "runaway_recursion",
        2,
        3,
        &["nesting deeper than", "in macro `Deep`", "times)"],
    );
}

#[test]
fn unterminated_while_points_at_its_opening() {
    check(
        "unterminated_while",
        1,
        1,
        &["unterminated `#while`", "has no matching `#end`"],
    );
}

#[test]
fn missing_include_lists_the_folders_searched() {
    check(
        "missing_include",
        1,
        1,
        &["cannot find include file `no_such_file.inc`", "searched:"],
    );
}

#[test]
fn errors_inside_macros_show_the_call_trace() {
    let needles = [
        "in macro `Inner`, called at",
        "macro_trace.pov:6:3",
        "in macro `Outer`, called at",
        "macro_trace.pov:8:14",
    ];
    check("macro_trace", 2, 14, &needles);
}

#[test]
fn files_outside_the_scene_folder_are_refused() {
    check(
        "file_outside",
        1,
        10,
        &[
            "`/etc/passwd` is outside the folders scenes may read and write",
            "data files must be in",
        ],
    );
}

#[test]
fn area_light_sizes_must_be_positive() {
    check(
        "area_light_size",
        2,
        36,
        &["an area light needs 1 to 257 lights per axis", "this is 0"],
    );
}

#[test]
fn area_light_modifiers_need_an_area_light() {
    check(
        "area_modifier_alone",
        2,
        3,
        &["`jitter` needs an `area_light` before it"],
    );
}
