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
fn vturbulence_with_too_few_arguments_names_the_count() {
    check(
        "vturbulence_arity",
        2,
        18,
        &["`vturbulence` takes 4 arguments, found 3", "called here"],
    );
}

#[test]
fn pattern_modifier_of_another_pattern_names_its_pattern() {
    check(
        "pattern_modifier_elsewhere",
        2,
        45,
        &["`mortar` only applies to brick"],
    );
}

#[test]
fn repeat_warp_along_two_axes_is_refused() {
    check(
        "warp_repeat_two_axes",
        3,
        10,
        &["the `repeat` direction must lie along one axis"],
    );
}

#[test]
fn noise_generator_out_of_range_is_refused() {
    check(
        "bad_noise_generator",
        2,
        45,
        &["the noise generator must be 0, 1, 2 or 3"],
    );
}

#[test]
fn unknown_cylinder_camera_type_is_named() {
    check(
        "camera_cylinder_type",
        2,
        12,
        &["unknown cylinder camera type 5", "expected 1, 2, 3 or 4"],
    );
}

#[test]
fn zero_blur_samples_are_refused() {
    check(
        "camera_blur_samples",
        1,
        56,
        &["0 is not a number of samples", "at least 1"],
    );
}

#[test]
fn confidence_must_be_a_probability() {
    check(
        "camera_confidence",
        1,
        47,
        &["confidence 1.5 is not a probability"],
    );
}

#[test]
fn unknown_fog_type_is_named() {
    check(
        "fog_type",
        3,
        12,
        &[
            "unknown fog_type 3",
            "expected 1 (constant) or 2 (ground fog)",
        ],
    );
}

#[test]
fn missing_image_file_lists_the_folders_searched() {
    check(
        "missing_image",
        2,
        40,
        &[
            "cannot find image file `no_such_image.png`",
            "searched:",
            "diagnostics",
        ],
    );
}

#[test]
fn map_entry_without_a_key_is_an_error() {
    check(
        "bad_map_entry",
        2,
        60,
        &[
            "a `pigment_map` entry starts with its key, a float",
            "expected a float key",
        ],
    );
}

#[test]
fn map_entry_with_only_a_key_is_an_error() {
    check(
        "empty_map_entry",
        2,
        28,
        &["this `texture_map` entry has a key but nothing after it"],
    );
}

#[test]
fn missing_height_field_image_lists_the_folders_searched() {
    check(
        "missing_height_field",
        1,
        20,
        &[
            "cannot find height field image `no_such_height.png`",
            "searched: ",
        ],
    );
}

#[test]
fn unimplemented_internal_function_is_refused_where_called() {
    check(
        "unimplemented_internal",
        2,
        14,
        &[
            "`f_comma`: POV-Ray's internal function 9 is not implemented in durer",
            "called here",
            "every function of functions.inc except f_comma (9)",
        ],
    );
}

#[test]
fn agate_does_not_take_another_patterns_setting() {
    check(
        "agate_with_quilted_setting",
        2,
        30,
        &["`control1` only applies to quilted"],
    );
}

#[test]
fn a_spline_without_points_is_reported_at_the_block() {
    check(
        "empty_spline",
        2,
        18,
        &["a spline needs at least one point", "this spline has none"],
    );
}

#[test]
fn a_spline_call_with_a_bad_kind_points_at_the_argument() {
    check("spline_kind", 3, 21, &["expected a spline kind"]);
}

#[test]
fn inside_on_a_float_points_at_the_argument() {
    check(
        "inside_not_object",
        3,
        22,
        &["expected an object, found a float"],
    );
}

#[test]
fn inside_on_a_triangle_says_it_has_no_inside() {
    check(
        "inside_not_solid",
        3,
        22,
        &["`inside` needs a solid object", "contains a triangle"],
    );
}

#[test]
fn a_datetime_format_with_a_time_zone_points_at_the_format() {
    check(
        "datetime_format",
        2,
        32,
        &["`%Z` cannot be used", "in this datetime"],
    );
}

#[test]
fn an_undefined_macro_argument_is_refused() {
    check(
        "undefined_macro_argument",
        3,
        7,
        &["cannot pass undefined identifier `Nothing` to a macro"],
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

/// Area light modifiers on a light without `area_light`: `jitter` is ignored silently and
/// `circular` with a warning at the keyword, as povray does.
#[test]
fn area_light_modifiers_without_an_area_light_are_ignored() {
    let path = tests_folder()
        .join("diagnostics")
        .join("area_modifier_alone.pov");
    let evaluated = evaluate(&path);
    assert_eq!(
        evaluated.diagnostics.len(),
        1,
        "expected one warning, got {:?}",
        evaluated.diagnostics
    );
    let warning = &evaluated.diagnostics[0];
    assert_eq!(warning.severity, Severity::Warning);
    assert_eq!(
        warning.message,
        "`circular` only affects an area light; it is ignored"
    );
    let position = evaluated
        .sources
        .line_column(warning.span.file, warning.span.start);
    assert_eq!(position, (2, 10));
}

#[test]
fn palette_entry_outside_the_palette_is_refused() {
    check(
        "palette_index_range",
        2,
        60,
        &[
            "palette index 300 is outside 0 to 255",
            "no such palette entry",
        ],
    );
}

#[test]
fn material_map_without_textures_is_an_error() {
    check(
        "material_map_empty",
        2,
        24,
        &["lists no textures", "expected `texture { .. }` entries"],
    );
}

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
fn pigment_function_member_must_exist() {
    check(
        "pigment_function_wrong_member",
        2,
        25,
        &[
            "`P` returns a colour, which has no member `.w`",
            ".gray .hf",
        ],
    );
}

#[test]
fn pigment_function_inside_a_function_needs_a_member() {
    check(
        "pigment_function_without_member",
        2,
        29,
        &[
            "`P` returns a colour; pick one of its components",
            "add a member, e.g. `P(..).red`",
        ],
    );
}

#[test]
fn pattern_function_has_no_members() {
    check(
        "pattern_function_member",
        2,
        25,
        &["`Q` returns a float, which has no member `.red`"],
    );
}

#[test]
fn transform_function_called_with_wrong_arity() {
    check(
        "transform_function_arity",
        2,
        25,
        &[
            "function `T` takes 3 arguments, found 2",
            "the function is declared here",
        ],
    );
}

#[test]
fn spline_called_inside_a_function_is_refused() {
    check(
        "spline_called_in_function",
        2,
        25,
        &[
            "the spline `S` cannot be called inside a function",
            "function { spline { S } }",
        ],
    );
}

#[test]
fn pattern_written_after_a_modifier_is_refused() {
    check(
        "pattern_after_modifier",
        2,
        21,
        &[
            "the pattern `checker` must come first in its block",
            "this comes before it",
        ],
    );
}

#[test]
fn pigment_functions_nested_too_deeply_are_refused() {
    check(
        "functions_nested_too_deeply",
        3,
        48,
        &[
            "functions call each other too deeply",
            "more than 64 nested calls",
        ],
    );
}

#[test]
fn spline_identifier_as_a_function_body_is_refused() {
    check(
        "spline_identifier_as_function",
        2,
        25,
        &[
            "a function cannot be the spline `S` itself",
            "write `function { spline { S } }`",
        ],
    );
}

#[test]
fn mesh2_texture_index_out_of_range_names_the_list_size() {
    check(
        "mesh2_texture_index",
        4,
        21,
        &[
            "texture index out of range",
            "the texture_list has 1 textures",
        ],
    );
}

#[test]
fn mesh2_uv_vectors_without_uv_indices_need_one_per_vertex() {
    check(
        "mesh2_missing_uv_indices",
        1,
        1,
        &[
            "missing `uv_indices` in mesh2",
            "2 uv vectors for 3 vertices",
        ],
    );
}

#[test]
fn slope_with_zero_direction_is_refused() {
    check(
        "slope_zero_direction",
        2,
        25,
        &["the `slope` direction must not be zero"],
    );
}

#[test]
fn object_pattern_needs_an_object() {
    check(
        "object_pattern_not_object",
        3,
        34,
        &[
            "expected an object, found",
            "the `object` pattern needs an object",
        ],
    );
}

#[test]
fn broken_density_file_is_refused() {
    check(
        "bad_density_file",
        2,
        42,
        &[
            "cannot read density file \"broken.df3\"",
            "do not fit 2 x 2 x 2 voxels",
        ],
    );
}

#[test]
fn mesh_camera_smooth_needs_distribution_3() {
    check(
        "mesh_camera_smooth_distribution",
        2,
        39,
        &["`smooth` needs mesh camera distribution 3"],
    );
}

#[test]
fn uv_mesh_camera_shoots_one_ray_per_pixel() {
    check(
        "mesh_camera_uv_single_ray",
        2,
        24,
        &["2 rays per pixel", "exactly 1 ray per pixel"],
    );
}

#[test]
fn mesh_camera_needs_a_mesh_per_ray() {
    check(
        "mesh_camera_too_few_meshes",
        2,
        24,
        &["distribution 0 needs a mesh for each of the 2 rays per pixel, found 1 meshes"],
    );
}

/// `number_of_waves` below 1 is a warning at the value (povray's rule: 1 is used).
#[test]
fn number_of_waves_below_one_warns_at_the_value() {
    let path = tests_folder()
        .join("diagnostics")
        .join("number_of_waves_zero.pov");
    let evaluated = evaluate(&path);
    let warning = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Warning && d.message.contains("number_of_waves"))
        .unwrap_or_else(|| panic!("expected a warning, got {:?}", evaluated.diagnostics));
    assert!(warning
        .message
        .contains("must be greater than 0; 1 is used"));
    let position = evaluated
        .sources
        .line_column(warning.span.file, warning.span.start);
    assert_eq!(position, (2, 35));
}

#[test]
fn global_lights_outside_a_light_group_is_refused() {
    check(
        "global_lights_outside_light_group",
        2,
        25,
        &["`global_lights` is not allowed inside `union`"],
    );
}

#[test]
fn tiling_number_out_of_range_is_refused() {
    check(
        "tiling_out_of_range",
        2,
        31,
        &["the tiling number must be between 1 and 27", "this is 28"],
    );
}

#[test]
fn quaternion_julia_fractal_refuses_other_functions() {
    check(
        "julia_quaternion_function",
        2,
        45,
        &[
            "quaternion julia fractals take only `sqr` or `cube`",
            "needs `hypercomplex`",
        ],
    );
}

#[test]
fn julia_slice_needs_a_fourth_component() {
    check(
        "julia_slice_without_w",
        2,
        34,
        &["the slice normal needs a non-zero fourth component"],
    );
}

#[test]
fn media_scattering_type_out_of_range_points_at_the_type() {
    check(
        "media_bad_scattering_type",
        3,
        35,
        &["scattering type must be 1 to 5", "Henyey-Greenstein"],
    );
}

#[test]
fn errors_in_text_macro_output_point_into_the_body() {
    check(
        "text_macro_error",
        3,
        17,
        &[
            "undefined identifier `Radius`",
            "in macro `Wall`, called at",
            "text_macro_error.pov:6:10",
        ],
    );
}

/// A text macro whose output leaves a brace open is reported at that brace in the body.

#[test]
fn unbalanced_text_macro_output_points_at_the_open_brace() {
    check(
        "text_macro_unbalanced",
        2,
        20,
        &[
            "in the text this macro produced: unclosed `{`",
            "in macro `Open`, called at",
            "text_macro_unbalanced.pov:5:10",
        ],
    );
}

/// An error in a macro called from a text macro's loop shows both calls.

#[test]
fn errors_in_calls_from_text_macros_show_the_call_trace() {
    check(
        "text_macro_call",
        2,
        14,
        &[
            "cannot combine a float and a string",
            "in macro `Bad`, called at",
            "text_macro_call.pov:7:5",
            "in macro `Rows`, called at",
            "text_macro_call.pov:11:10",
        ],
    );
}

#[test]
fn pavement_pattern_out_of_range_names_the_count() {
    check(
        "pavement_pattern_out_of_range",
        2,
        77,
        &["`pattern` of this pavement must be between 1 and 2"],
    );
}

#[test]
fn radiosity_count_out_of_range_is_refused() {
    check(
        "radiosity_count_out_of_range",
        2,
        37,
        &[
            "radiosity value 0 is out of range",
            "expected a whole number from 1 to",
        ],
    );
}

#[test]
fn radiosity_pretrace_size_out_of_range_is_refused() {
    check(
        "radiosity_pretrace_out_of_range",
        2,
        44,
        &[
            "pretrace block size 1.5 is out of range",
            "above 0 and at most 1",
        ],
    );
}

#[test]
fn interior_texture_outside_an_object_is_an_error() {
    check(
        "interior_texture_alone",
        3,
        19,
        &[
            "`interior_texture` belongs in an object or a `material`",
            "not a value of its own",
        ],
    );
}

/// A `pot` height field must be a GIF (Fractint continuous potential).
#[test]
fn pot_height_field_that_is_not_a_gif_is_refused_at_the_file_name() {
    check(
        "pot_not_a_gif",
        1,
        20,
        &["cannot read height field image \"images/palette8.png\": cannot decode"],
    );
}

#[test]
fn radiosity_importance_out_of_range_is_refused() {
    check(
        "radiosity_importance_out_of_range",
        2,
        56,
        &[
            "radiosity importance 1.5 is out of range",
            "above 0 and at most 1",
        ],
    );
}

#[test]
fn facets_outside_a_normal_is_an_error() {
    check(
        "facets_in_pigment",
        2,
        35,
        &[
            "`facets` can only be used in a `normal`",
            "not allowed in a `pigment`",
            "normal { facets .. }",
        ],
    );
    check(
        "facets_in_texture",
        2,
        25,
        &[
            "`facets` can only be used in a `normal`",
            "not allowed in a `texture`",
        ],
    );
}

#[test]
fn directive_after_a_macro_argument_is_refused() {
    check(
        "directive_after_macro_argument",
        2,
        58,
        &[
            "directive after a macro argument",
            "POV-Ray ends the argument list here",
        ],
    );
}

#[test]
fn photons_block_without_density_is_refused() {
    check(
        "photons_without_density",
        2,
        19,
        &["needs `spacing` or `count`", "no photon density given"],
    );
}

#[test]
fn photon_spacing_must_be_positive() {
    check(
        "photons_negative_spacing",
        2,
        37,
        &["the photon spacing -0.1 must be positive"],
    );
}

#[test]
fn photon_target_multiplier_must_be_positive() {
    check(
        "photons_target_multiplier",
        2,
        32,
        &["photon spacing multiplier 0 must be positive"],
    );
}

/// A lemon's inner radius too small for the arc's centre to reach the axis is a warning at the
/// lemon (povray 3.7.1 warns and raises it likewise), not an error.
#[test]
fn lemon_inner_radius_too_small_warns_and_is_raised() {
    let path = tests_folder()
        .join("diagnostics")
        .join("lemon_inner_radius_too_small.pov");
    let evaluated = evaluate(&path);
    assert!(
        evaluated
            .diagnostics
            .iter()
            .all(|d| d.severity != Severity::Error),
        "{:?}",
        evaluated.diagnostics
    );
    let warning = evaluated
        .diagnostics
        .iter()
        .find(|d| d.severity == Severity::Warning && d.message.contains("lemon"))
        .unwrap_or_else(|| panic!("expected a warning, got {:?}", evaluated.diagnostics));
    assert!(
        warning.message.contains("0.2 is too small"),
        "{}",
        warning.message
    );
    assert!(
        warning.message.contains("using 0.335"),
        "{}",
        warning.message
    );
    let position = evaluated
        .sources
        .line_column(warning.span.file, warning.span.start);
    assert_eq!(position, (2, 10));
}

#[test]
fn unsupported_photon_options_are_warned_at_their_keyword() {
    let path = tests_folder()
        .join("diagnostics")
        .join("photons_unsupported_options.pov");
    let evaluated = evaluate(&path);
    assert!(evaluated.scene.is_some());
    let warnings: Vec<(usize, usize, String)> = evaluated
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Warning)
        .map(|d| {
            let (line, column) = evaluated.sources.line_column(d.span.file, d.span.start);
            (line, column, d.message.clone())
        })
        .collect();
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert_eq!((warnings[0].0, warnings[0].1), (2, 43));
    assert!(warnings[0].2.contains("area light photons"));
    assert_eq!((warnings[1].0, warnings[1].1), (3, 76));
    assert!(warnings[1].2.contains("`split_union off`"));
}

#[test]
fn comparison_outside_parentheses_asks_for_parentheses() {
    check(
        "comparison_outside_parentheses",
        2,
        21,
        &[
            "found `>`",
            "only allowed inside parentheses, as in POV-Ray: write `(A > B)`",
        ],
    );
}

#[test]
fn sor_heights_that_do_not_increase_point_at_the_point() {
    check(
        "sor_heights_not_increasing",
        3,
        44,
        &[
            "a sor's heights must increase: -0.5 follows -0.5",
            "last but one",
        ],
    );
}

#[test]
fn sor_negative_radius_points_at_the_point() {
    check(
        "sor_negative_radius",
        2,
        59,
        &["a sor's radius must not be negative, found -0.4"],
    );
}

#[test]
fn sor_with_too_few_points_is_an_error() {
    check(
        "sor_too_few_points",
        2,
        1,
        &["a sor needs 4 to 10000000 points, found 3"],
    );
}

#[test]
fn truncated_tga_is_reported_at_the_file_name() {
    check(
        "truncated_tga",
        2,
        40,
        &[
            "cannot read image \"truncated.tga\"",
            "the file ends before its last pixel",
            "unreadable image",
        ],
    );
}

#[test]
fn bad_ppm_header_is_reported_at_the_file_name() {
    check(
        "bad_ppm_header",
        2,
        42,
        &["cannot read image \"bad_header.ppm\"", "preamble"],
    );
}

#[test]
fn bad_hdr_resolution_is_reported_at_the_file_name() {
    check(
        "bad_hdr",
        2,
        20,
        &[
            "cannot read height field image \"bad.hdr\"",
            "the resolution line `-Y four +X 4` is not `-Y height +X width`",
        ],
    );
}

#[test]
fn sor_end_point_level_with_the_third_point_is_an_error() {
    check(
        "sor_end_point_level",
        2,
        10,
        &[
            "a sor's point may not lie at the height of the point two places from it (1)",
            "divide by a zero height difference",
        ],
    );
}

#[test]
fn directive_after_a_structured_macro_call_argument_is_refused() {
    check(
        "macro_directive_after_argument",
        2,
        24,
        &[
            "directive after a macro argument",
            "POV-Ray ends the argument list here",
            "a directive may follow `(` or a comma",
        ],
    );
}

#[test]
fn directive_leaving_two_macro_arguments_points_at_the_second_value() {
    check(
        "macro_directive_leaves_value",
        2,
        37,
        &[
            "a directive standing as a macro argument left two values",
            "separate arguments with commas outside the directive",
        ],
    );
}

#[test]
fn directive_leaving_a_value_before_an_argument_is_refused() {
    check(
        "macro_directive_value_before_argument",
        2,
        44,
        &[
            "a directive among a call's arguments left a value where POV-Ray reads none",
            "left by this directive",
        ],
    );
}
