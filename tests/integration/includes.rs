//! POV-Ray 3.7's standard include files load without error.
//!
//! Needs the include files of the Debian package `povray-includes` (`.ci/run` installs it);
//! set `DURER_POVRAY_INCLUDE` to use another folder. Without them the test says so and passes.

use crate::{evaluate_with, scratch};
use durer::diag::Severity;
use std::path::PathBuf;

fn povray_include_folder() -> Option<PathBuf> {
    let folder = std::env::var_os("DURER_POVRAY_INCLUDE")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/share/povray-3.7/include"));
    folder.join("colors.inc").is_file().then_some(folder)
}

#[test]
fn every_standard_include_file_loads() {
    let Some(folder) = povray_include_folder() else {
        eprintln!(
            "POV-Ray's include files are not installed; skipping (apt-get install povray-includes)"
        );
        return;
    };
    let dir = scratch("includes");
    let mut names: Vec<String> = std::fs::read_dir(&folder)
        .expect("include folder")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".inc"))
        .collect();
    names.sort();
    assert!(
        names.len() >= 30,
        "expected POV-Ray's include files, found {}",
        names.len()
    );
    let mut failures = Vec::new();
    for name in &names {
        // Several files expect colors.inc and shapes.inc to be included first, as in POV-Ray.
        let scene = dir.join(format!("{name}.pov"));
        let text = format!(
            "#version 3.7;\n#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"{name}\"\n"
        );
        std::fs::write(&scene, text).expect("write scene");
        let options = durer::eval::EvalOptions {
            include_paths: vec![folder.clone()],
            ..Default::default()
        };
        let evaluated = evaluate_with(&scene, options);
        for d in evaluated
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
        {
            failures.push(format!(
                "{name}: {}",
                durer::report::render_plain(d, &evaluated.sources)
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "include files failed to load:\n{}",
        failures.join("\n")
    );
}

/// Names declared by durer's embedded colors.inc.
fn embedded_colour_names() -> Vec<String> {
    let text = include_str!("../../src/eval/language/stdlib/colors.inc");
    text.lines()
        .filter_map(|l| l.strip_prefix("#declare "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|n| *n != "Colors_Inc_Temp")
        .map(str::to_string)
        .collect()
}

/// Evaluates the scene at `path` (with or without POV-Ray's installed include folder) and
/// fails the test, naming `context`, if it reports any error.
fn evaluate_cleanly(path: &std::path::Path, installed: bool, context: &str) {
    // The fonts are named by their path in POV-Ray's folder even when it is not searched.
    let options = durer::eval::EvalOptions {
        search_installed_povray: installed,
        file_policy: durer::file_policy::FilePolicy::unrestricted(),
        ..Default::default()
    };
    let evaluated = evaluate_with(path, options);
    let errors: Vec<String> = evaluated
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .map(|d| durer::report::render_plain(d, &evaluated.sources))
        .collect();
    assert!(errors.is_empty(), "{context}: {}", errors.join("\n"));
}

/// Writes `text` to `path`, evaluates it (embedded include files only unless `installed`)
/// and renders it at `width` x `height`: the image, or the messages of its errors.
fn render_scene(
    path: &std::path::Path,
    text: &str,
    installed: bool,
    (width, height): (u32, u32),
) -> Result<durer::render::Image, Vec<String>> {
    std::fs::write(path, text).expect("write scene");
    // The fonts are named by their path in POV-Ray's folder even when it is not searched.
    let options = durer::eval::EvalOptions {
        search_installed_povray: installed,
        file_policy: durer::file_policy::FilePolicy::unrestricted(),
        ..Default::default()
    };
    let evaluated = evaluate_with(path, options);
    let errors: Vec<String> = evaluated
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .map(|d| d.message.clone())
        .collect();
    match evaluated.scene {
        Some(mut scene) if errors.is_empty() => {
            let world =
                durer::geometry::World::build_from_objects(std::mem::take(&mut scene.objects));
            let options = durer::render::RenderOptions {
                width,
                height,
                antialias: None,
                region: None,
                alpha: false,
                quality: Default::default(),
            };
            Ok(durer::render::render(&scene, &world, &options, &|_| {}))
        }
        _ => Err(errors),
    }
}

/// Evaluates a scene that includes colors.inc and writes every colour's components to a file.
fn dump_colours(dir: &std::path::Path, installed: bool) -> String {
    let mut scene = String::from("#include \"colors.inc\"\n#fopen Out \"colours.txt\" write\n");
    for name in embedded_colour_names() {
        scene.push_str(&format!(
            "#write (Out, \"{name} \", {name}.red, \" \", {name}.green, \" \", {name}.blue, \" \", {name}.filter, \" \", {name}.transmit, \"\\n\")\n"
        ));
    }
    scene.push_str("#fclose Out\n");
    let path = dir.join("colours.pov");
    std::fs::write(&path, scene).expect("write scene");
    evaluate_cleanly(&path, installed, "colors.inc");
    std::fs::read_to_string(dir.join("colours.txt")).expect("colours written")
}

#[test]
fn embedded_colours_work_without_povray() {
    let dir = scratch("embedded-colours");
    let dump = dump_colours(&dir, false);
    assert!(dump.lines().count() >= 100, "expected the colour table");
    assert!(dump.contains("Red 1 0 0 0 0"), "{dump}");
    assert!(dump.contains("Clear 1 1 1 1 0"), "{dump}");
}

#[test]
fn embedded_colours_have_povray_values() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let ours = dump_colours(&scratch("colours-ours"), false);
    let theirs = dump_colours(&scratch("colours-theirs"), true);
    for (a, b) in ours.lines().zip(theirs.lines()) {
        let parse = |l: &str| -> Vec<f64> {
            l.split_whitespace()
                .skip(1)
                .map(|v| v.parse().unwrap())
                .collect()
        };
        let (x, y) = (parse(a), parse(b));
        let same = x.iter().zip(&y).all(|(p, q)| (p - q).abs() < 1e-6);
        assert!(same, "embedded `{a}` differs from POV-Ray's `{b}`");
    }
    assert_eq!(ours.lines().count(), theirs.lines().count());
}

/// durer's embedded include files other than colors.inc (which has its own tests), with
/// their text.
const EMBEDDED_FILES: &[(&str, &str)] = &[
    (
        "consts.inc",
        include_str!("../../src/eval/language/stdlib/consts.inc"),
    ),
    (
        "finish.inc",
        include_str!("../../src/eval/language/stdlib/finish.inc"),
    ),
    (
        "glass.inc",
        include_str!("../../src/eval/language/stdlib/glass.inc"),
    ),
    (
        "glass_old.inc",
        include_str!("../../src/eval/language/stdlib/glass_old.inc"),
    ),
    (
        "golds.inc",
        include_str!("../../src/eval/language/stdlib/golds.inc"),
    ),
    (
        "metals.inc",
        include_str!("../../src/eval/language/stdlib/metals.inc"),
    ),
    (
        "skies.inc",
        include_str!("../../src/eval/language/stdlib/skies.inc"),
    ),
    (
        "textures.inc",
        include_str!("../../src/eval/language/stdlib/textures.inc"),
    ),
    (
        "woodmaps.inc",
        include_str!("../../src/eval/language/stdlib/woodmaps.inc"),
    ),
    (
        "woods.inc",
        include_str!("../../src/eval/language/stdlib/woods.inc"),
    ),
    (
        "stones1.inc",
        include_str!("../../src/eval/language/stdlib/stones1.inc"),
    ),
    (
        "stones2.inc",
        include_str!("../../src/eval/language/stdlib/stones2.inc"),
    ),
    (
        "ior.inc",
        include_str!("../../src/eval/language/stdlib/ior.inc"),
    ),
    (
        "stdinc.inc",
        include_str!("../../src/eval/language/stdlib/stdinc.inc"),
    ),
    (
        "stdcam.inc",
        include_str!("../../src/eval/language/stdlib/stdcam.inc"),
    ),
    (
        "stoneold.inc",
        include_str!("../../src/eval/language/stdlib/stoneold.inc"),
    ),
    (
        "stars.inc",
        include_str!("../../src/eval/language/stdlib/stars.inc"),
    ),
    (
        "rad_def.inc",
        include_str!("../../src/eval/language/stdlib/rad_def.inc"),
    ),
    (
        "logo.inc",
        include_str!("../../src/eval/language/stdlib/logo.inc"),
    ),
];

/// What a declared identifier holds, by the keyword starting its value; `None` for
/// numbers (floats, vectors and colours).
const APPEARANCE_KINDS: &[&str] = &[
    "finish",
    "texture",
    "pigment",
    "interior",
    "material",
    "sky_sphere",
    "sphere",
    "union",
    "color_map",
    "merge",
];

/// (name, kind) for each identifier an embedded file declares; the kind is one of
/// [`APPEARANCE_KINDS`], or `None` for numbers. A `deprecated [once] "message"` marker
/// before the name is skipped.
fn declared_names(text: &str) -> Vec<(String, Option<&'static str>)> {
    let mut names: Vec<(String, Option<&'static str>)> = Vec::new();
    for line in text.lines() {
        let Some(rest) = line.strip_prefix("#declare ") else {
            continue;
        };
        let Some((name, value)) = rest.split_once('=') else {
            continue;
        };
        let name = name.trim();
        let name = match name.strip_prefix("deprecated") {
            Some(marked) => marked.rsplit('"').next().unwrap_or(marked).trim(),
            None => name,
        };
        let name = name.to_string();
        if name.ends_with("_Temp") || names.iter().any(|(n, _)| *n == name) {
            continue;
        }
        let value = value.trim_start();
        // Functions (ior.inc's FnPovDispersion) are checked through the values using them.
        if value.starts_with("function") {
            continue;
        }
        let kind = APPEARANCE_KINDS
            .iter()
            .copied()
            .find(|word| value.starts_with(word));
        names.push((name, kind));
    }
    names
}

/// Evaluates a scene including `file` and writes one line per declared identifier: its five
/// components for numbers, `defined` for the rest.
fn dump_include(
    file: &str,
    names: &[(String, Option<&'static str>)],
    dir: &std::path::Path,
    installed: bool,
) -> String {
    // Some of POV-Ray's files (skies.inc) expect colors.inc to be included first; durer's
    // stand alone.
    let colours = if installed {
        "#include \"colors.inc\"\n"
    } else {
        ""
    };
    let mut scene = format!("{colours}#include \"{file}\"\n#fopen Out \"dump.txt\" write\n");
    for (name, kind) in names {
        if kind.is_none() {
            scene.push_str(&format!(
                "#write (Out, \"{name} \", vstr(5, <0,0,0,0,0> + ({name}), \" \", 0, 9), \"\\n\")\n"
            ));
        } else {
            scene.push_str(&format!(
                "#ifdef ({name}) #write (Out, \"{name} defined\\n\") #end\n"
            ));
        }
    }
    scene.push_str("#fclose Out\n");
    let path = dir.join("dump.pov");
    std::fs::write(&path, scene).expect("write scene");
    evaluate_cleanly(&path, installed, file);
    std::fs::read_to_string(dir.join("dump.txt")).expect("dump written")
}

#[test]
fn embedded_include_files_load_without_povray() {
    for (file, text) in EMBEDDED_FILES {
        let names = declared_names(text);
        let dir = scratch(&format!("embedded-{file}"));
        let dump = dump_include(file, &names, &dir, false);
        assert_eq!(dump.lines().count(), names.len(), "{file}:\n{dump}");
    }
}

#[test]
fn embedded_include_files_match_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    for (file, text) in EMBEDDED_FILES {
        let names = declared_names(text);
        let ours = dump_include(file, &names, &scratch(&format!("ours-{file}")), false);
        let theirs = dump_include(file, &names, &scratch(&format!("theirs-{file}")), true);
        assert_eq!(ours.lines().count(), theirs.lines().count(), "{file}");
        for (a, b) in ours.lines().zip(theirs.lines()) {
            let parse = |l: &str| -> Vec<f64> {
                l.split_whitespace()
                    .skip(1)
                    .filter_map(|v| v.parse().ok())
                    .collect()
            };
            let (x, y) = (parse(a), parse(b));
            let same = x.len() == y.len() && x.iter().zip(&y).all(|(p, q)| (p - q).abs() < 1e-6);
            assert!(same, "{file}: embedded `{a}` differs from POV-Ray's `{b}`");
        }
    }
}

/// The statements of a tiny scene showing the declared identifier `name` of `kind`: a ball
/// with it (or under it, for a sky sphere) in front of a chequered floor and wall.
fn showcase(name: &str, kind: &str) -> String {
    let ball = "sphere { <0, 1, 0>, 1";
    let subject = match kind {
        "finish" => format!("{ball} pigment {{ rgb <0.8, 0.5, 0.3> }} finish {{ {name} }} }}"),
        "texture" => format!("{ball} texture {{ {name} }} }}"),
        "pigment" => format!("{ball} pigment {{ {name} }} }}"),
        "interior" => format!(
            "{ball} pigment {{ rgbf <0.9, 0.95, 1, 0.9> }} interior {{ {name} fade_color rgb <0.2, 0.6, 0.3> }} }}"
        ),
        "material" => format!("{ball} material {{ {name} }} }}"),
        "sky_sphere" => format!("sky_sphere {{ {name} }} {ball} pigment {{ rgb 0.5 }} }}"),
        "color_map" => {
            format!("{ball} pigment {{ gradient y color_map {{ {name} }} scale 0.5 }} }}")
        }
        _ => format!("object {{ {name} }}"),
    };
    format!(
        "camera {{ location <0, 1.5, -4> look_at <0, 1.8, 0> angle 80 }}\n\
         light_source {{ <-5, 8, -6>, rgb 1 }}\n\
         plane {{ y, 0 pigment {{ checker rgb 0.2 rgb 0.9 }} }}\n\
         plane {{ z, 3 pigment {{ checker rgb <0.1, 0.2, 0.6> rgb 0.9 }} }}\n\
         {subject}\n"
    )
}

/// Renders a small image of every finish, texture, interior, material, pigment, sky sphere
/// and object `file` declares, each in its own scene.
fn render_showcases(file: &str, installed: bool) -> Vec<(String, durer::render::Image)> {
    let text = EMBEDDED_FILES
        .iter()
        .find(|(f, _)| *f == file)
        .map(|(_, t)| *t)
        .expect("embedded file");
    let dir = scratch(&format!("showcase-{file}-{installed}"));
    let mut images = Vec::new();
    for (name, kind) in declared_names(text) {
        let Some(kind) = kind else { continue };
        let path = dir.join(format!("{name}.pov"));
        let colours = if installed {
            "#include \"colors.inc\"\n"
        } else {
            ""
        };
        let scene = format!(
            "#version 3.7;\n{colours}#include \"{file}\"\n{}",
            showcase(&name, kind)
        );
        let image = render_scene(&path, &scene, installed, (24, 18))
            .unwrap_or_else(|e| panic!("{file}: {name} does not evaluate: {}", e.join("\n")));
        images.push((name, image));
    }
    images
}

/// Finishes, textures, interiors, sky spheres and objects cannot be compared by value, so
/// each is rendered in a small scene with the embedded file and with POV-Ray's: the images
/// must be the same.
#[test]
fn embedded_appearances_render_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    for (file, _) in EMBEDDED_FILES {
        let ours = render_showcases(file, false);
        let theirs = render_showcases(file, true);
        assert_eq!(ours.len(), theirs.len(), "{file}");
        for ((name, a), (_, b)) in ours.iter().zip(&theirs) {
            assert!(a == b, "{file}: {name} renders differently from POV-Ray's");
        }
    }
}

/// Calls of the pattern macros of textures.inc, each with the turn that brings the
/// macro's plane to face the camera.
const TEXTURE_MACRO_CALLS: &[(&str, &str)] = &[
    ("Tiles_Ptrn()", ""),
    ("Tiles_Ptrn()", "scale <0.7, 0.4, 1> rotate 30*z"),
    ("Hex_Tiles_Ptrn()", "rotate -90*x"),
    ("Hex_Tiles_Ptrn()", "rotate -90*x scale 0.6"),
    ("Star_Ptrn(1, 5, 2)", ""),
    ("Star_Ptrn(1.4, 7, 3)", ""),
    ("Star_Ptrn(1.5, 6, 1)", "rotate 10*z"),
    ("Irregular_Bricks_Ptrn(0.1, 1, 0.5, 0.5)", "scale 0.5"),
    ("Irregular_Bricks_Ptrn(0.05, 2, 0.8, 0.2)", "scale 0.4"),
];

/// What durer makes of a flat, self-lit panel coloured by the pattern `call`: its image,
/// or the messages of its errors when durer cannot evaluate it.
fn render_texture_macro(
    call: &str,
    turn: &str,
    dir: &std::path::Path,
    installed: bool,
) -> Result<durer::render::Image, Vec<String>> {
    let path = dir.join("macro.pov");
    let scene = format!(
        "#version 3.7;\n#include \"textures.inc\"\n\
         camera {{ orthographic location <0, 0, -10> look_at 0 right 6*x up 4.5*y }}\n\
         box {{ <-4, -3, 0>, <4, 3, 1>\n\
           pigment {{ {call} color_map {{ [0 rgb <0.2, 0.1, 0>] [0.5 rgb <0.9, 0.5, 0.2>] [1 rgb 1] }} {turn} }}\n\
           finish {{ ambient 1 diffuse 0 }}\n\
         }}\n"
    );
    render_scene(&path, &scene, installed, (40, 30))
}

/// The pattern macros of durer's textures.inc give what POV-Ray's give: the same image, or
/// (where durer lacks a feature a macro needs) the same errors.
#[test]
fn embedded_texture_macros_match_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let ours_dir = scratch("texture-macros-ours");
    let theirs_dir = scratch("texture-macros-theirs");
    for (call, turn) in TEXTURE_MACRO_CALLS {
        let ours = render_texture_macro(call, turn, &ours_dir, false);
        let theirs = render_texture_macro(call, turn, &theirs_dir, true);
        match (&ours, &theirs) {
            (Ok(a), Ok(b)) => assert!(a == b, "{call} renders differently from POV-Ray's"),
            (Err(a), Err(b)) => assert_eq!(a, b, "{call} fails differently from POV-Ray's"),
            _ => panic!(
                "{call}: embedded gives {:?}, POV-Ray's {:?}",
                ours.as_ref().err(),
                theirs.as_ref().err()
            ),
        }
    }
}

/// Like POV-Ray's, durer's include files read their declarations as version 3.5 and then set the including file's version again, which
/// counts as the scene declaring one (gamma handling depends on that): a scene without
/// `#version` renders the same with either file.
#[test]
fn embedded_files_set_the_version_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let files = EMBEDDED_FILES.iter().chain(EMBEDDED_LIBRARIES);
    for file in files.map(|(file, _)| *file).chain(["colors.inc"]) {
        let render = |installed: bool| {
            let dir = scratch(&format!("version-{file}-{installed}"));
            let path = dir.join("scene.pov");
            let scene = format!(
                "#include \"{file}\"\n\
                 camera {{ location <0, 0, -3> look_at 0 }}\n\
                 light_source {{ <2, 4, -5>, rgb 1 }}\n\
                 sphere {{ 0, 1 pigment {{ rgb <0.5, 0.3, 0.2> }} }}\n"
            );
            render_scene(&path, &scene, installed, (16, 12)).ok()
        };
        // Some of POV-Ray's files (skies.inc, stones1.inc) do not load on their own: they
        // need colors.inc first. durer's do.
        let ours = render(false).unwrap_or_else(|| panic!("{file}: the scene does not evaluate"));
        if let Some(theirs) = render(true) {
            assert!(
                ours == theirs,
                "{file}: a scene without #version renders differently"
            );
        }
    }
}

/// durer's stones.inc only includes its two halves: without POV-Ray's files, the textures of
/// both (first and last of each family) are declared after including it.
#[test]
fn embedded_stones_inc_loads_both_halves() {
    let dir = scratch("embedded-stones");
    let names = [
        "T_Grnt0",
        "T_Grnt29",
        "T_Grnt0a",
        "T_Grnt24a",
        "T_Crack1",
        "T_Crack4",
        "T_Stone1",
        "T_Stone24",
        "T_Stone25",
        "T_Stone44",
        "g4",
    ];
    let mut scene = String::from("#include \"stones.inc\"\n#fopen Out \"found.txt\" write\n");
    for name in names {
        scene.push_str(&format!(
            "#ifdef ({name}) #write (Out, \"{name}\\n\") #end\n"
        ));
    }
    scene.push_str("#fclose Out\n");
    let path = dir.join("stones.pov");
    std::fs::write(&path, scene).expect("write scene");
    evaluate_cleanly(&path, false, "stones.inc");
    let found = std::fs::read_to_string(dir.join("found.txt")).expect("names written");
    assert_eq!(found.lines().collect::<Vec<_>>(), names);
}

/// durer's embedded libraries of functions and macros. Each has a probe scene
/// `tests/stdlib/NAME.pov` that calls what the file declares and writes the results to
/// `probe.txt`, and POV-Ray's answers in `tests/stdlib/NAME.txt` (scripts/probe-stdlib.sh).
const EMBEDDED_LIBRARIES: &[(&str, &str)] = &[
    (
        "functions.inc",
        include_str!("../../src/eval/language/stdlib/functions.inc"),
    ),
    (
        "math.inc",
        include_str!("../../src/eval/language/stdlib/math.inc"),
    ),
    (
        "transforms.inc",
        include_str!("../../src/eval/language/stdlib/transforms.inc"),
    ),
    (
        "strings.inc",
        include_str!("../../src/eval/language/stdlib/strings.inc"),
    ),
    (
        "rand.inc",
        include_str!("../../src/eval/language/stdlib/rand.inc"),
    ),
    (
        "arrays.inc",
        include_str!("../../src/eval/language/stdlib/arrays.inc"),
    ),
    (
        "debug.inc",
        include_str!("../../src/eval/language/stdlib/debug.inc"),
    ),
    (
        "sunpos.inc",
        include_str!("../../src/eval/language/stdlib/sunpos.inc"),
    ),
    (
        "screen.inc",
        include_str!("../../src/eval/language/stdlib/screen.inc"),
    ),
];

/// Whether two lines of probe output agree: the same words, numbers equal to a millionth of
/// their size (POV-Ray keeps colours and 5D vectors in single precision).
fn probe_lines_agree(ours: &str, theirs: &str) -> bool {
    let (a, b): (Vec<&str>, Vec<&str>) = (
        ours.split_whitespace().collect(),
        theirs.split_whitespace().collect(),
    );
    a.len() == b.len()
        && a.iter()
            .zip(&b)
            .all(|(p, q)| match (p.parse::<f64>(), q.parse::<f64>()) {
                (Ok(x), Ok(y)) => (x - y).abs() <= 1e-6 * y.abs().max(1.0),
                _ => p == q,
            })
}

/// Runs the probe scene of `file` with durer's embedded include files only and returns what
/// it wrote.
fn run_library_probe(file: &str) -> String {
    let name = file.trim_end_matches(".inc");
    let probe = crate::tests_folder()
        .join("stdlib")
        .join(format!("{name}.pov"));
    let dir = scratch(&format!("library-{name}"));
    let scene = dir.join(format!("{name}.pov"));
    std::fs::copy(&probe, &scene).expect("copy probe scene");
    evaluate_cleanly(&scene, false, file);
    std::fs::read_to_string(dir.join("probe.txt")).expect("probe written")
}

/// Every function and macro of the embedded libraries gives POV-Ray's results: the probe
/// scenes' output with durer's files equals POV-Ray's output with its own, line by line.
#[test]
fn embedded_libraries_give_povray_results() {
    for (file, _) in EMBEDDED_LIBRARIES {
        let ours = run_library_probe(file);
        let expected = crate::tests_folder()
            .join("stdlib")
            .join(format!("{}.txt", file.trim_end_matches(".inc")));
        let theirs = std::fs::read_to_string(&expected).expect("POV-Ray's probe output");
        for (a, b) in ours.lines().zip(theirs.lines()) {
            assert!(
                probe_lines_agree(a, b),
                "{file}: durer wrote `{a}`, POV-Ray `{b}`"
            );
        }
        assert_eq!(ours.lines().count(), theirs.lines().count(), "{file}");
    }
}

/// The names a standard include file's text declares with `#declare` or `#macro`, besides
/// its include guard.
fn library_names(text: &str) -> std::collections::BTreeSet<String> {
    text.lines()
        .map(str::trim_start)
        .filter_map(|l| {
            l.strip_prefix("#declare")
                .or_else(|| l.strip_prefix("#macro"))
        })
        .filter_map(|rest| {
            let name: String = rest
                .trim_start()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            (!name.is_empty() && !name.to_ascii_uppercase().ends_with("_INC_TEMP")).then_some(name)
        })
        .collect()
}

/// The embedded libraries declare exactly the functions, macros and variables of POV-Ray's
/// files of the same names.
#[test]
fn embedded_libraries_declare_povray_names() {
    let Some(folder) = povray_include_folder() else {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    };
    for (file, text) in EMBEDDED_LIBRARIES {
        let bytes = std::fs::read(folder.join(file)).expect("POV-Ray's file");
        let theirs = library_names(&String::from_utf8_lossy(&bytes));
        let ours = library_names(text);
        let missing: Vec<_> = theirs.difference(&ours).collect();
        let extra: Vec<_> = ours.difference(&theirs).collect();
        assert!(
            missing.is_empty() && extra.is_empty(),
            "{file}: missing {missing:?}, not in POV-Ray's {extra:?}"
        );
    }
}

/// arrays.inc's ARRAYS_WriteDF3 writes the density files POV-Ray writes: the three sizes as
/// big-endian 16-bit numbers, then each value scaled to 8 or 16 bits, rounded, x fastest.
#[test]
fn embedded_arrays_write_povray_density_files() {
    let dir = scratch("library-df3");
    let scene = dir.join("df3.pov");
    std::fs::write(
        &scene,
        "#include \"arrays.inc\"\n\
         #declare Grid = array[2][3] {{0, 0.5, 1}, {0.25, 0.75, 0.1}}\n\
         ARRAYS_WriteDF3(Grid, \"grid8.df3\", 8)\n\
         ARRAYS_WriteDF3(Grid, \"grid16.df3\", 16)\n",
    )
    .expect("write scene");
    evaluate_cleanly(&scene, false, "arrays.inc");
    // The bytes povray 3.7 writes for the same scene.
    let eight = [0, 2, 0, 3, 0, 1, 0x00, 0x40, 0x80, 0xbf, 0xff, 0x1a];
    let sixteen = [
        0, 2, 0, 3, 0, 1, 0x00, 0x00, 0x40, 0x00, 0x80, 0x00, 0xbf, 0xff, 0xff, 0xff, 0x19, 0x9a,
    ];
    assert_eq!(
        std::fs::read(dir.join("grid8.df3")).expect("8-bit file"),
        eight
    );
    assert_eq!(
        std::fs::read(dir.join("grid16.df3")).expect("16-bit file"),
        sixteen
    );
}

/// durer's embedded shape files, with their text. They have their own tests: POV-Ray's
/// shapes2.inc and shapesq.inc use shapes of shapes_old.inc without including it, and
/// shapes.inc is mostly macros.
const SHAPE_FILES: &[(&str, &str)] = &[
    (
        "shapes_old.inc",
        include_str!("../../src/eval/language/stdlib/shapes_old.inc"),
    ),
    (
        "shapes.inc",
        include_str!("../../src/eval/language/stdlib/shapes.inc"),
    ),
    (
        "shapes2.inc",
        include_str!("../../src/eval/language/stdlib/shapes2.inc"),
    ),
    (
        "shapesq.inc",
        include_str!("../../src/eval/language/stdlib/shapesq.inc"),
    ),
    (
        "chars.inc",
        include_str!("../../src/eval/language/stdlib/chars.inc"),
    ),
    (
        "shapes3.inc",
        include_str!("../../src/eval/language/stdlib/shapes3.inc"),
    ),
];

/// The identifiers a shape file declares (`#declare Name = ...` at the start of a line),
/// without its include guard, each with whether it holds a number.
fn declared_shapes(text: &str) -> Vec<(String, bool)> {
    text.lines()
        .filter_map(|l| l.strip_prefix("#declare "))
        .filter_map(|l| l.split_once('='))
        .map(|(name, value)| {
            let value = value.trim_start();
            let number = value.starts_with(|c: char| c.is_ascii_digit() || c == '-');
            (name.trim().to_string(), number)
        })
        .filter(|(name, _)| !name.ends_with("_Temp"))
        .collect()
}

/// The lines opening a scene that uses `file`: `#version`, then durer's embedded file alone,
/// or POV-Ray's after its shapes.inc (which its shapes2.inc and shapesq.inc need, as scenes know).
fn shape_includes(file: &str, installed: bool) -> String {
    if installed {
        format!("#version 3.7;\n#include \"shapes.inc\"\n#include \"{file}\"\n")
    } else {
        format!("#version 3.7;\n#include \"{file}\"\n")
    }
}

/// Evaluates and renders a small lit scene: `includes` (with `#version` if any), then `body`. Embedded include files
/// only unless `installed`.
fn render_shape_scene(
    dir: &std::path::Path,
    name: &str,
    includes: &str,
    body: &str,
    installed: bool,
) -> durer::render::Image {
    let path = dir.join(format!("{name}.pov"));
    let scene = format!(
        "{includes}\
         camera {{ location <3, 4, -9> look_at <0, 0.3, 0> angle 40 }}\n\
         light_source {{ <-5, 8, -6>, rgb 1 }}\n\
         light_source {{ <6, 3, -3>, rgb 0.5 }}\n\
         background {{ rgb <0.2, 0.3, 0.5> }}\n\
         {body}\n"
    );
    render_scene(&path, &scene, installed, (40, 30))
        .unwrap_or_else(|e| panic!("{name} does not evaluate:\n{}", e.join("\n")))
}

/// Asserts that `written` (a mesh written to a file and read back) renders like `direct`:
/// at most 2% of pixels with a channel more than 24/255 apart.
fn assert_renders_alike(direct: &durer::render::Image, written: &durer::render::Image, what: &str) {
    let differing = direct
        .pixels
        .iter()
        .zip(&written.pixels)
        .filter(|(p, q)| (0..3).any(|c| p[c].abs_diff(q[c]) > 24))
        .count();
    assert!(
        differing * 50 <= direct.pixels.len(),
        "{what} renders unlike the one made directly"
    );
}

/// The statement showing a declared shape, tinted so that its shading shows.
fn shape_showcase(name: &str) -> String {
    format!("object {{ {name} pigment {{ rgb <1, 0.6, 0.3> }} }}")
}

#[test]
fn embedded_shape_files_load_without_povray() {
    for (file, text) in SHAPE_FILES {
        let dir = scratch(&format!("embedded-shapes-{file}"));
        for (name, number) in declared_shapes(text) {
            let body = if number {
                format!("#if ({name} < 1) #error \"{name}\" #end")
            } else {
                shape_showcase(&name)
            };
            render_shape_scene(&dir, &name, &shape_includes(file, false), &body, false);
        }
    }
}

/// Every shape the files declare renders the same with durer's file and with POV-Ray's.
#[test]
fn embedded_shapes_render_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    for (file, text) in SHAPE_FILES {
        let ours = scratch(&format!("shapes-ours-{file}"));
        let theirs = scratch(&format!("shapes-theirs-{file}"));
        for (name, number) in declared_shapes(text) {
            let body = if number {
                format!("sphere {{ <{name}, 0, 0>, 0.5 pigment {{ rgb 1 }} }}")
            } else {
                shape_showcase(&name)
            };
            let a = render_shape_scene(&ours, &name, &shape_includes(file, false), &body, false);
            let b = render_shape_scene(&theirs, &name, &shape_includes(file, true), &body, true);
            assert!(a == b, "{file}: {name} renders differently from POV-Ray's");
        }
    }
}

/// Calls of shapes.inc's object macros, each with a few argument sets (the Round_, Wire_
/// and Circle_ ones also with arguments that make them warn); `FONT` stands for a font
/// file.
const SHAPE_MACRO_CALLS: &[&str] = &[
    "Center_Object(box { 0, <1, 2, 0.5> }, x + z)",
    "Align_Object(sphere { 0, 0.5 }, -y, <1, 0, 0>)",
    "Wedge(60)",
    "Wedge(180)",
    "Wedge(250)",
    "Wedge(-20)",
    "Spheroid(<0.5, 0.5, 0>, <1, 0.5, 0.7>)",
    "Spheroid(<0, 1, 0>, 0.8)",
    "Supertorus(1, 0.3, 0.5, 1.5, 0.001, 10)",
    "Supertorus(1.2, 0.4, 1, 1, 0.001, 0.5)",
    "Supercone(<0, -1.5, 0>, 1, 2, <0, 1.5, 0>, 1, 0.5)",
    "Supercone(<0, 0, 1>, 0.5, 1, <0, 0, -1>, 1, 0.5)",
    "Supercone(<1, 0, 0>, 0.5, 1, <-1, 1, 0.5>, 0.2, 0.7)",
    "Connect_Spheres(<-1, 0, 0>, 1, <1, 1, 0>, 0.5)",
    "Wire_Box_Union(<-1, 0, -1>, <1, 1, 1>, 0.1)",
    "Wire_Box_Merge(<1, 1, 1>, <-1, 0.1, -1>, 0.1)",
    "Wire_Box(<-1, 0, 0>, <1, 1, 0>, 0.1, false)",
    "Round_Box_Union(<-1, 0, -1>, <1, 1, 1>, 0.2)",
    "Round_Box_Merge(<-1, 0, -1>, <1, 0.2, 1>, 0.2)",
    "Round_Cylinder_Union(<-1, 0, 0>, <1, 1, 0.5>, 0.6, 0.1)",
    "Round_Cylinder_Merge(<-1, 0, 0>, <1, 1, 0.5>, 0.1, 0.3)",
    "Round_Cone_Union(<-1, 0, 0>, 0.8, <1, 1, 0.5>, 0.3, 0.1)",
    "Round_Cone_Merge(<-1, 0, 0>, 0.3, <1, 1, 0.5>, 0.8, 0.1)",
    "Round_Cone(<-1, 0, 0>, 0.3, <1, 1, 0.5>, 0.8, 0.5, true)",
    "Round_Cone2_Union(<-1, 0, 0>, 0.8, <1, 1, 0.5>, 0.3)",
    "Round_Cone2_Merge(<-1, 0, 0>, 0.3, <1, 1, 0.5>, 0.6)",
    "Round_Cone3_Union(<-1, 0, 0>, 0.8, <1, 1, 0.5>, 0.3)",
    "Round_Cone3_Merge(<-1, 0, 0>, 0.3, <1, 1, 0.5>, 0.6)",
    "union { Quad(<-1, 0, 0>, <1, 0, 0>, <1, 1, 0.5>, <-1, 1, 0>) }",
    "union { Smooth_Quad(<-1, 0, 0>, <0, 0, -1>, <1, 0, 0>, <0.3, 0, -1>, <1, 1, 0.5>, <0, 0.5, -1>, <-1, 1, 0>, <-0.3, 0, -1>) }",
    "Bevelled_Text(FONT, \"Hi!\", 5, 35, 0.1, 0.4, 0, false)",
    "Bevelled_Text(FONT, \"Ab\", 8, 20, 0.05, 0.3, 0.02, true)",
    "Circle_Text(FONT, \"Hello world\", 0.4, 0, 0.1, 1.5, false, Align_Center, 90)",
    "Circle_Text(FONT, \"Hello\", 0.4, 0.05, 0.1, 1.2, true, Align_Left, 45)",
    "Circle_Text(FONT, \"Hello\", 0.4, 0.05, 0.1, 1.2, false, Align_Right, 0)",
    "Circle_Text_Valigned(FONT, \"Ring text\", 0.4, 0, 0.1, 1.5, true, Align_Right, 200, -90)",
    "Circle_Text_Valigned(FONT, \"Ring\", 0.4, 0, 0.1, 1.5, false, Align_Center, 90, 90)",
];

/// Each object macro of shapes.inc makes an object rendering the same with durer's file
/// and with POV-Ray's.
#[test]
fn embedded_shape_macros_render_like_povray() {
    let Some(folder) = povray_include_folder() else {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    };
    let font = format!("\"{}\"", folder.join("timrom.ttf").display());
    let ours = scratch("shape-macros-ours");
    let theirs = scratch("shape-macros-theirs");
    for (index, call) in SHAPE_MACRO_CALLS.iter().enumerate() {
        let body = format!(
            "object {{ {} pigment {{ rgb <1, 0.6, 0.3> }} }}",
            call.replace("FONT", &font)
        );
        let name = format!("call{index}");
        let includes = "#version 3.7;\n#include \"shapes.inc\"\n";
        let a = render_shape_scene(&ours, &name, includes, &body, false);
        let b = render_shape_scene(&theirs, &name, includes, &body, true);
        assert!(
            a == b,
            "{call} renders differently from POV-Ray's shapes.inc"
        );
    }
}

/// shapes.inc's query macros (Isect, IsectN, Extents, Text_Space, Text_Width) give the same
/// values with durer's file as with POV-Ray's, hits and misses alike.
#[test]
fn embedded_shape_queries_match_povray() {
    let Some(folder) = povray_include_folder() else {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    };
    let font = folder.join("timrom.ttf");
    let scene = format!(
        "#include \"shapes.inc\"\n\
         #fopen Out \"queries.txt\" write\n\
         #declare Ball = sphere {{ 0, 1 }}\n\
         #declare Tilted = box {{ -1, 1 rotate 30 * y }}\n\
         #declare P = <9, 9, 9>;\n\
         #declare N = <9, 9, 9>;\n\
         #write (Out, Isect(<0, 0, -5>, z, Ball, P), \" \", P, \"\\n\")\n\
         #write (Out, Isect(<0, 3, -5>, z, Ball, P), \" \", P, \"\\n\")\n\
         #write (Out, IsectN(<0.3, 0.2, -5>, z, Tilted, P, N), \" \", P, \" \", N, \"\\n\")\n\
         #write (Out, IsectN(<0.3, 5, -5>, z, Tilted, P, N), \" \", P, \" \", N, \"\\n\")\n\
         #declare Low = 0;\n\
         #declare High = 0;\n\
         Extents(cone {{ 0, 1, y, 0.5 rotate 20 * z }}, Low, High)\n\
         #write (Out, vstr(3, Low, \" \", 0, 9), \" \", vstr(3, High, \" \", 0, 9), \"\\n\")\n\
         #declare Font = \"{}\";\n\
         #write (Out, str(Text_Space(Font, \"Hello there\", 1.5, 0.1), 0, 12), \"\\n\")\n\
         #write (Out, str(Text_Space(Font, \" \", 1, 0), 0, 12), \"\\n\")\n\
         #write (Out, str(Text_Width(Font, \"Hello there\", 1.5, 0.1), 0, 12), \"\\n\")\n\
         #write (Out, str(Text_Width(Font, \"W\", 2, 0), 0, 12), \"\\n\")\n\
         #fclose Out\n",
        font.display()
    );
    let run = |installed: bool| {
        let dir = scratch(&format!("shape-queries-{installed}"));
        let path = dir.join("queries.pov");
        std::fs::write(&path, &scene).expect("write scene");
        evaluate_cleanly(&path, installed, "shapes.inc queries");
        std::fs::read_to_string(dir.join("queries.txt")).expect("queries written")
    };
    let ours = run(false);
    assert_eq!(ours.lines().count(), 9, "{ours}");
    assert_eq!(ours, run(true));
}

/// Renders tests/stdlib/NAME.pov with durer's embedded files only (or, when `installed`,
/// with POV-Ray's installed files, if there are any) and requires it to match
/// tests/stdlib/NAME.png, POV-Ray's render (at most 2% of pixels over 24/255).
fn stdlib_scene_renders_like_povray(name: &str, installed: bool) {
    if installed && povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping {name} with them");
        return;
    }
    let path = crate::tests_folder().join(format!("stdlib/{name}.pov"));
    // The fonts are named by their path in POV-Ray's folder even when it is not searched.
    let options = durer::eval::EvalOptions {
        search_installed_povray: installed,
        file_policy: durer::file_policy::FilePolicy::unrestricted(),
        ..Default::default()
    };
    let evaluated = evaluate_with(&path, options);
    let Some(mut scene) = evaluated.scene else {
        panic!("{name}.pov does not evaluate");
    };
    let world = durer::geometry::World::build_from_objects(std::mem::take(&mut scene.objects));
    let reference = image::open(path.with_extension("png"))
        .unwrap_or_else(|e| panic!("{name}.png: {e}"))
        .to_rgb8();
    let options = durer::render::RenderOptions {
        width: reference.width(),
        height: reference.height(),
        antialias: None,
        region: None,
        alpha: false,
        quality: Default::default(),
    };
    let ours = durer::render::render(&scene, &world, &options, &|_| {});
    let over = reference
        .enumerate_pixels()
        .filter(|(column, row, pixel)| {
            let mine = ours.pixel(*column, *row).expect("same size");
            (0..3).any(|c| mine[c].abs_diff(pixel[c]) > 24)
        })
        .count();
    let total = (reference.width() * reference.height()) as usize;
    assert!(
        over * 50 <= total,
        "{over} of {total} pixels differ from POV-Ray's render"
    );
}

/// The HF_ macros render tests/stdlib/shapes_hf.pov like POV-Ray did, from durer's
/// shapes.inc and from POV-Ray's (whose HF macros interleave `#write` argument lists and
/// braces with directives: durer runs them token by token), and the meshes they write to
/// files render like the ones they make directly.
#[test]
fn embedded_height_field_macros_render_like_povray() {
    stdlib_scene_renders_like_povray("shapes_hf", false);
    stdlib_scene_renders_like_povray("shapes_hf", true);

    let dir = scratch("hf-files");
    let ripple = "#declare Ripple = function (x, y, z) { sin(x * 5) * 0.1 + z * z * 0.2 }\n";
    let calls = [
        "HF_Square(Ripple, 0, 0, <8, 6>, 1, FILE, <-2, 0, -1>, <0, 0.5, 1>)",
        "HF_Sphere(Ripple, 1, 0, 10, 1, FILE, <0.8, 1, 0>, 0.7, 0.3)",
        "HF_Cylinder(Ripple, 0, 0, <8, 5>, 0, FILE, <1, -1, 0>, <1.4, 0, 0.3>, 0.5, 0.5)",
        "HF_Torus(Ripple, 1, 0, 12, 1, FILE, 0.8, 0.2, 0.5)",
    ];
    let sources = [false, true]
        .into_iter()
        .filter(|installed| !installed || povray_include_folder().is_some());
    for (index, (call, installed)) in sources
        .flat_map(|installed| calls.iter().map(move |call| (call, installed)))
        .enumerate()
    {
        let includes = format!("#version 3.7;\n#include \"shapes.inc\"\n{ripple}");
        let direct = format!(
            "object {{ {} pigment {{ rgb <1, 0.6, 0.3> }} }}",
            call.replace("FILE", "\"\"")
        );
        let file = format!("mesh{index}.inc");
        let written = format!(
            "{}\nobject {{ #include \"{file}\" pigment {{ rgb <1, 0.6, 0.3> }} }}",
            call.replace("FILE", &format!("\"{file}\""))
        );
        let a = render_shape_scene(
            &dir,
            &format!("direct{index}"),
            &includes,
            &direct,
            installed,
        );
        let b = render_shape_scene(
            &dir,
            &format!("written{index}"),
            &includes,
            &written,
            installed,
        );
        assert_renders_alike(&a, &b, &format!("{call}: the written mesh"));
    }
}

/// Bad arguments to shapes.inc's macros stop with an error that says what is wrong, and
/// the error's trace leads back to the call in the scene.
#[test]
fn embedded_shape_macros_report_bad_arguments() {
    let cases = [
        (
            "Circle_Text(\"timrom.ttf\", \"\", 0.4, 0, 0.1, 1.5, false, Align_Center, 90)",
            "Circle_Text: the text is empty",
        ),
        (
            "Round_Cone2_Union(<0, 0, 0>, 1, <0.1, 0, 0>, 0.3)",
            "Round_Cone2: one sphere lies inside the other",
        ),
        (
            "Connect_Spheres(<0, 0, 0>, 1, <0.1, 0, 0>, 0.3)",
            "Connect_Spheres: one sphere lies inside the other",
        ),
        (
            "HF_Square(function { x }, 0, 0, <5, 1>, 0, \"\", <-1, 0, -1>, <1, 1, 1>)",
            "Res must be at least 2",
        ),
    ];
    let dir = scratch("shape-macro-errors");
    for (index, (call, message)) in cases.iter().enumerate() {
        let path = dir.join(format!("bad{index}.pov"));
        std::fs::write(
            &path,
            format!("#include \"shapes.inc\"\n\nobject {{ {call} }}\n"),
        )
        .expect("write scene");
        let options = durer::eval::EvalOptions {
            search_installed_povray: false,
            ..Default::default()
        };
        let evaluated = evaluate_with(&path, options);
        let error = evaluated
            .diagnostics
            .iter()
            .find(|d| d.severity == Severity::Error)
            .unwrap_or_else(|| panic!("{call}: expected an error"));
        let text = durer::report::render_plain(error, &evaluated.sources);
        assert!(error.message.contains(message), "{call}:\n{text}");
        let call_site = error.trace.last().expect("a macro trace").span;
        let (line, column) = evaluated
            .sources
            .line_column(call_site.file, call_site.start);
        assert_eq!((line, column), (3, 10), "{call}:\n{text}");
    }
}

/// Like POV-Ray's files, durer's read their declarations as version 3.5 and then restore the
/// including file's version, which counts as the scene's `#version`: a scene without one
/// renders the same with either file.
#[test]
fn embedded_shape_files_set_the_version_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let includes = "#include \"shapes.inc\"\n#include \"shapes2.inc\"\n#include \"shapesq.inc\"\n";
    let body =
        "object { Round_Box_Union(<-1, 0, -1>, <1, 1, 1>, 0.2) pigment { rgb <1, 0.6, 0.3> } }";
    let ours = render_shape_scene(
        &scratch("unversioned-ours"),
        "unversioned",
        includes,
        body,
        false,
    );
    let theirs = render_shape_scene(
        &scratch("unversioned-theirs"),
        "unversioned",
        includes,
        body,
        true,
    );
    assert!(
        ours == theirs,
        "a scene without #version renders differently"
    );
}

/// durer's stdinc.inc alone brings in colors, shapes, transforms, consts, functions, math
/// and rand.inc: something of each is there after including it without POV-Ray's files.
#[test]
fn embedded_stdinc_includes_the_everyday_files() {
    let dir = scratch("embedded-stdinc");
    let scene = dir.join("stdinc.pov");
    std::fs::write(
        &scene,
        "#include \"stdinc.inc\"\n\
         #fopen Out \"found.txt\" write\n\
         #declare Sheared = transform { Shear_Trans(x, y, z) }\n\
         #ifdef (f_algbr_cyl1) #write (Out, \"functions \") #end\n\
         #write (Out, vstr(3, <Red.red, xy.y, sind(90)>, \" \", 0, 3), \" \", Align_Left, \" \", seed(RdmA) > 0, \"\\n\")\n\
         #fclose Out\n",
    )
    .expect("write scene");
    evaluate_cleanly(&scene, false, "stdinc.inc");
    let found = std::fs::read_to_string(dir.join("found.txt")).expect("found written");
    assert_eq!(found.trim(), "functions 1.000 1.000 1.000 1 1");
}

/// durer's stdcam.inc and stage1.inc set up the same camera, light and floor or wall as
/// POV-Ray's (whose stdcam.inc needs colors.inc first): a sphere in front of them renders
/// pixel for pixel the same.
#[test]
fn embedded_stages_render_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let render = |file: &str, installed: bool| {
        let dir = scratch(&format!("stage-{file}-{installed}"));
        let path = dir.join("scene.pov");
        let colours = if installed {
            "#include \"colors.inc\"\n"
        } else {
            ""
        };
        let scene = format!(
            "#version 3.7;\n{colours}#include \"{file}\"\n\
             sphere {{ <-0.5, 0.6, 0>, 0.6 pigment {{ rgb <0.3, 0.6, 0.9> }} }}\n"
        );
        render_scene(&path, &scene, installed, (32, 24))
            .unwrap_or_else(|e| panic!("{file} does not evaluate: {}", e.join("\n")))
    };
    for file in ["stdcam.inc", "stage1.inc"] {
        assert!(
            render(file, false) == render(file, true),
            "{file} renders differently"
        );
    }
}

/// debug.inc's Warning and Error macros raise a warning and an error with the given message
/// when their condition holds.
#[test]
fn embedded_debug_macros_warn_and_stop() {
    let dir = scratch("embedded-debug");
    let scene = dir.join("debug.pov");
    std::fs::write(
        &scene,
        "#include \"debug.inc\"\n\
         Warning(1 < 2, \"careful\")\n\
         Error(yes, \"stopped here\")\n",
    )
    .expect("write scene");
    let options = durer::eval::EvalOptions {
        search_installed_povray: false,
        ..Default::default()
    };
    let evaluated = evaluate_with(&scene, options);
    let find = |severity: Severity, text: &str| {
        evaluated
            .diagnostics
            .iter()
            .any(|d| d.severity == severity && d.message.contains(text))
    };
    assert!(
        find(Severity::Warning, "careful"),
        "{:?}",
        evaluated.diagnostics
    );
    assert!(
        find(Severity::Error, "stopped here"),
        "{:?}",
        evaluated.diagnostics
    );
}

/// Calls of shapes3.inc's object macros that durer can also run from POV-Ray's file, each
/// with a few argument sets, some of them out of range (which the macros correct).
const SHAPES3_MACRO_CALLS: &[&str] = &[
    "Pyramid_N(5, 1, 0.5, 1.5)",
    "Pyramid_N_AB(6, <-1, 0, 0>, 1, <1, 1, 0.5>, 0.3)",
    "Column_N(8, 1, 2)",
    "Column_N_AB(5, <0, 0, 0>, <1, 1.5, 0>, 0.5)",
    "Egg_Shape(1, 2)",
    "Facetted_Sphere(4, 8)",
    "Facetted_Egg_Shape(3, 7, 1, 1.5)",
    "Facetted_Egg(5, 12)",
    "Ring_Sphere(1.2, 1, 0.05, 0, 3, 6)",
    "Round_Pyramid_N_out(5, <0, 0, 0>, 1, <0, 1.5, 0>, 0.4, 0.1, 1, 0)",
    "Round_Pyramid_N_out(4, <0, 0, 0>, 0.4, <0.5, 1.5, 0>, 1, 0.08, 0, 1)",
    "Round_Pyramid_N_out(3, <0, 0, 0>, 1, <0, 1.5, 0>, 0.1, 0.1, 1, 1)",
    "Round_Pyramid_N_in(6, <0, 0, 0>, 1, <0, 1, 0>, 0.6, 0.1, 1, 0)",
    "Rounded_Tube(1, 0.6, 0.1, 1.5, 0)",
    "Rounded_Tube(0.5, 1, 0.5, 1, 1)",
    "Rounded_Tube_AB(<-1, 0, 0>, <1, 1, 0>, 0.8, 0.5, 0.1, 0)",
    "Round_Conic_Torus(1.5, 0.8, 0.4, 0.1, 0)",
    "Round_Conic_Torus(1.5, 0.4, 0.8, 0.1, 1)",
    "Round_Conic_Torus(-1, 0.5, 0.5, 0, 0)",
    "Round_Conic_Prism(1.5, 0.8, 0.4, 1.2, 0.1, 0)",
    "Round_Conic_Prism(1.5, 0.4, 0.8, 1, 0.1, 1)",
    "Round_Conic_Prism(1, 0.5, 0.3, 1, 0, 0)",
    "Half_Hollowed_Rounded_Cylinder1(3, 0.8, 0.1, 1, 0)",
    "Half_Hollowed_Rounded_Cylinder1(1, 0.8, 0.1, 0.5, 1)",
    "Half_Hollowed_Rounded_Cylinder1(3, 0.1, 0.8, 0, 0)",
    "Half_Hollowed_Rounded_Cylinder2(3, 0.8, 0.3, 0.1, 1, 0)",
    "Half_Hollowed_Rounded_Cylinder2(2, 0.8, 1.5, 0.1, 0.5, 1)",
];

/// Each of those makes an object rendering the same with durer's shapes3.inc and with
/// POV-Ray's, and durer's file declares exactly POV-Ray's macros and objects.
#[test]
fn embedded_shapes3_macros_render_like_povray() {
    let Some(folder) = povray_include_folder() else {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    };
    let ours = scratch("shapes3-macros-ours");
    let theirs = scratch("shapes3-macros-theirs");
    let includes = "#version 3.7;\n#include \"shapes3.inc\"\n";
    for (index, call) in SHAPES3_MACRO_CALLS.iter().enumerate() {
        let body = format!("object {{ {call} pigment {{ rgb <1, 0.6, 0.3> }} }}");
        let name = format!("call{index}");
        let a = render_shape_scene(&ours, &name, includes, &body, false);
        let b = render_shape_scene(&theirs, &name, includes, &body, true);
        assert!(
            a == b,
            "{call} renders differently from POV-Ray's shapes3.inc"
        );
    }
    let bytes = std::fs::read(folder.join("shapes3.inc")).expect("POV-Ray's file");
    let text = SHAPE_FILES
        .iter()
        .find(|(file, _)| *file == "shapes3.inc")
        .map(|(_, text)| *text)
        .expect("embedded shapes3.inc");
    assert_eq!(
        library_names(text),
        library_names(&String::from_utf8_lossy(&bytes))
    );
}

/// The shapes3.inc macros whose POV-Ray text opens and closes braces under separate
/// `#if`s render tests/stdlib/shapes3.pov like POV-Ray did, with durer's file and with
/// POV-Ray's (run token by token).
#[test]
fn embedded_shapes3_segments_and_tubes_render_like_povray() {
    stdlib_scene_renders_like_povray("shapes3", false);
    stdlib_scene_renders_like_povray("shapes3", true);
}

/// Calls of makegrass.inc's MakeBlade (inside a mesh) and MakePrairie, plain and smooth,
/// folded and flat.
const MAKEGRASS_CALLS: &[&str] = &[
    "mesh { MakeBlade(false, <0, 0, 0>, 100, 20, 3, 0.3, 0.03, 0.15, <0, 1, 0>, <0, 0, 1>, 1, false, false) }",
    "mesh { MakeBlade(true, <0.2, 0, 0>, 30, 8, 3, 0.4, 0.05, 0.2, <0, 1, 0.3>, <0, -1, 2>, 3, true, false) }",
    "mesh { MakeBlade(true, <0, 0, 0>, 0, 5, 2.5, 0.5, 0.1, 0.3, <0.2, 1, 0>, <1, 0, 1>, 2, false, false) }",
    "mesh { MakeBlade(false, <0, 0, 0>, 60, 6, 2.5, 0.5, 0.1, 0.3, <0, 1, 0>, <0, 0, 1>, 1, true, false) }",
    "MakePrairie(1, 2, 1, 3, box { <-0.4, 0, -0.4>, <0.4, 0.3, 0.4> }, 779, 1, 1, false)",
    "MakePrairie(0.8, 3, 0.5, 2, cone { 0, 0.4, y, 0 }, 12, 0.5, 0.2, false)",
];

/// MakeBlade and MakePrairie make objects rendering the same with durer's makegrass.inc
/// and with POV-Ray's.
#[test]
fn embedded_makegrass_blades_render_like_povray() {
    if povray_include_folder().is_none() {
        eprintln!("POV-Ray's include files are not installed; skipping");
        return;
    }
    let ours = scratch("makegrass-ours");
    let theirs = scratch("makegrass-theirs");
    let includes = "#version 3.7;\n#include \"makegrass.inc\"\n";
    for (index, call) in MAKEGRASS_CALLS.iter().enumerate() {
        let body = format!("object {{ {call} pigment {{ rgb <1, 0.6, 0.3> }} }}");
        let name = format!("call{index}");
        let a = render_shape_scene(&ours, &name, includes, &body, false);
        let b = render_shape_scene(&theirs, &name, includes, &body, true);
        assert!(
            a == b,
            "{call} renders differently from POV-Ray's makegrass.inc"
        );
    }
}

/// MakeGrassPatch writes the mesh files POV-Ray wrote for tests/stdlib/makegrass.pov (same
/// random blades, numbers equal to the printed precision), and without a file it makes the
/// mesh it would have written: with durer's makegrass.inc and with POV-Ray's (a text macro:
/// its `mesh {` and `}` are under separate `#if`s, its blades' `#write`s run in order).
#[test]
fn embedded_makegrass_patches_match_povray() {
    makegrass_patches_match_povray(false);
    if povray_include_folder().is_some() {
        makegrass_patches_match_povray(true);
    }
}

/// The checks of [`embedded_makegrass_patches_match_povray`] with durer's makegrass.inc, or
/// POV-Ray's when `installed`.
fn makegrass_patches_match_povray(installed: bool) {
    let folder = crate::tests_folder().join("stdlib");
    let probe = scratch(&format!("makegrass-probe-{installed}"));
    let scene = probe.join("makegrass.pov");
    std::fs::copy(folder.join("makegrass.pov"), &scene).expect("copy probe scene");
    evaluate_cleanly(&scene, installed, "makegrass.inc");
    let words = |text: &str| -> Vec<String> {
        text.lines()
            .map(|line| line.replace([',', '<', '>', '{', '}'], " "))
            .collect()
    };
    for (file, recorded) in [
        ("probe.txt", "makegrass.txt"),
        ("smooth.txt", "makegrass_smooth.txt"),
    ] {
        let written = std::fs::read_to_string(probe.join(file)).expect("patch written");
        let theirs = std::fs::read_to_string(folder.join(recorded)).expect("POV-Ray's mesh");
        let (a, b) = (words(&written), words(&theirs));
        assert_eq!(a.len(), b.len(), "{recorded}");
        for (p, q) in a.iter().zip(&b) {
            assert!(
                probe_lines_agree(p, q),
                "{recorded}: durer wrote `{p}`, POV-Ray `{q}`"
            );
        }
    }

    let dir = scratch(&format!("makegrass-patch-{installed}"));
    let includes = "#version 3.7;\n#include \"makegrass.inc\"\n";
    let call = "MakeGrassPatch(2, 4, 60, 5, 1.5, 0.1, 0.03, true, <0, 1, 0.3>, <0, -1, 2>, 3, 459, 1, 360, 3, 0.5, true, FILE, NAME)";
    let direct = format!(
        "object {{ {} pigment {{ rgb <1, 0.6, 0.3> }} }}",
        call.replace("FILE", "false").replace("NAME", "\"\"")
    );
    let written = format!(
        "{}\nobject {{ #include \"patch.inc\" pigment {{ rgb <1, 0.6, 0.3> }} }}",
        call.replace("FILE", "true")
            .replace("NAME", "\"patch.inc\"")
    );
    let a = render_shape_scene(&dir, "direct", includes, &direct, installed);
    let b = render_shape_scene(&dir, "written", includes, &written, installed);
    assert_renders_alike(&a, &b, "the written patch");
}

/// meshmaker.inc's macros render tests/stdlib/meshmaker.pov like POV-Ray did (POV-Ray's
/// text: BuildWriteMesh2 interleaves `#write` argument lists and `mesh2 {` with directives),
/// and a mesh written to a file renders, read back, like the one made directly.
#[test]
fn meshmaker_macros_render_like_povray() {
    stdlib_scene_renders_like_povray("meshmaker", true);
    if povray_include_folder().is_none() {
        return;
    }
    let dir = scratch("meshmaker-files");
    let includes = "#version 3.7;\n#include \"meshmaker.inc\"\n\
        #declare Wave = function(u, v) { sin(u * 3) * 0.3 + v * v * 0.1 }\n";
    let call = "TwoVarSurf(Wave, <-1, 1>, <-1, 1>, 12, 10, FILE)";
    let direct = format!(
        "object {{ {} pigment {{ rgb <1, 0.6, 0.3> }} }}",
        call.replace("FILE", "\"\"")
    );
    let written = format!(
        "object {{ {} pigment {{ rgb <1, 0.6, 0.3> }} }}",
        call.replace("FILE", "\"surface.inc\"")
    );
    let a = render_shape_scene(&dir, "direct", includes, &direct, true);
    // The first run writes surface.inc, the second reads it back.
    let b = render_shape_scene(&dir, "written", includes, &written, true);
    let c = render_shape_scene(&dir, "read", includes, &written, true);
    assert!(
        dir.join("surface.inc").is_file(),
        "TwoVarSurf wrote no file"
    );
    assert!(
        a == b && b == c,
        "the written surface renders unlike the direct one"
    );
}

/// durer's own meshmaker.inc: renders tests/stdlib/meshmaker.pov like POV-Ray did, and its
/// macros write the same mesh files, byte for byte, as POV-Ray's meshmaker.inc (run by
/// durer) in all four formats. The sweeps are checked against POV-Ray's extents instead
/// (POV-Ray reads its file's `vlength(Waist(su).x)` in its own way).
#[test]
fn embedded_meshmaker_matches_povrays() {
    stdlib_scene_renders_like_povray("meshmaker", false);
    let sweeps = "#version 3.7;\n#include \"meshmaker.inc\"\n\
        #declare Track = spline { cubic_spline -1, <0,0,-1> 0, <0,0,0> 1, <1,1,1> 2, <2,1,2> 3, <3,0,3> }\n\
        #declare Shape = spline { linear_spline 0, <1,0> 0.25, <0,1> 0.5, <-1,0> 0.75, <0,-1> 1, <1,0> }\n\
        #declare Waist = spline { linear_spline 0, <0.3,0> 1, <0.1,0> }\n\
        #macro Near(A, B) #if (vlength(A - B) > 1e-5) #error \"extent differs\" #end #end\n\
        #declare I = SweepSpline1(Track, Shape, Waist, 6, 8, \"\")\n\
        Near(min_extent(I), <-0.268221, -0.273743, -0.134379>)\n\
        Near(max_extent(I), <0.910341, 0.993507, 0.932988>)\n\
        #declare J = SweepSpline2(Track, Shape, Waist, 6, 8, \"\")\n\
        Near(min_extent(J), <-0.268221, -0.273743, -0.134379>)\n\
        Near(max_extent(J), <0.918600, 0.991418, 0.922374>)\n";
    let dir = scratch("meshmaker-sweeps");
    if let Err(errors) = render_scene(&dir.join("sweeps.pov"), sweeps, false, (4, 3)) {
        panic!("the sweeps differ from POV-Ray's:\n{}", errors.join("\n"));
    }
    if povray_include_folder().is_none() {
        return;
    }
    let writer = "#version 3.7;\n#include \"meshmaker.inc\"\n\
        #declare Wave = function(u, v) { sin(u * 3) * 0.3 + v * v * 0.1 }\n\
        #declare Profile = spline { cubic_spline -0.25, <0.2, -0.2, 0> 0, <0.5, 0, 0> 0.5, <1, 1, 0> 1, <0.3, 2, 0> 1.25, <0.2, 2.5, 0> }\n\
        #declare A = TwoVarSurf(Wave, <-1, 1>, <-1, 1>, 4, 3, \"surf.inc\")\n\
        #declare B = Lathe(Profile, 4, 360, 5, \"lathe.obj\")\n\
        #declare C = Lathe(Profile, 3, 180, 4, \"lathe.pcm\")\n\
        #declare D = TwoVarSurf(Wave, <-1, 1>, <-1, 1>, 4, 4, \"surf.arr\")\n\
        #declare E = Coons(spline { linear_spline 0, <0,0,0> 1, <1,0,0> }, spline { linear_spline 0, <1,0,0> 1, <1,0.3,1> }, \
            spline { linear_spline 0, <1,0.3,1> 1, <0,0,1> }, spline { linear_spline 0, <0,0,1> 1, <0,0,0> }, 3, 3, \"coons.inc\")\n\
        #declare Points = array[5] { <0, 0, 0>, <1, 0.5, 0>, <2, 0, 1>, <3, 0.5, 0>, <4, 1, 1> }\n\
        #declare F = Prism(BuildSpline(Points, \"C\"), 4, 1, 2, \"prism.inc\")\n\
        #declare Shapes = array[4] {\n\
          spline { linear_spline 0, <-1, 0, 0> 1, <0, 0, 1> 2, <1, 0, 0> 3, <0, 0, -1> 4, <-1, 0, 0> },\n\
          spline { linear_spline 0, <-0.5, 2, 0> 1, <0, 2, 0.5> 2, <0.5, 2, 0> 3, <0, 2, -0.5> 4, <-0.5, 2, 0> },\n\
          spline { linear_spline 0, <-1, 1, 0> 1, <0, 1, 1.5> 2, <1, 1, 0> 3, <0, 1, -1> 4, <-1, 1, 0> },\n\
          spline { linear_spline 0, <-1, 3, 0> 1, <0, 3, 1> 2, <1, 3, 0> 3, <0, 3, -1> 4, <-1, 3, 0> } }\n\
        #declare G = MSM(Shapes, 4, \"c\", 3, \"msm.inc\")\n\
        #declare H = Parametric(function(u, v) { cos(u) * (1 + 0.3 * cos(v)) }, function(u, v) { 0.3 * sin(v) }, \
            function(u, v) { sin(u) * (1 + 0.3 * cos(v)) }, <FromU(0), 0>, <ToU(2 * pi), 2 * pi>, 4, 3, \"param.inc\")\n";
    let files = [
        "surf.inc",
        "lathe.obj",
        "lathe.pcm",
        "surf.arr",
        "coons.inc",
        "prism.inc",
        "msm.inc",
        "param.inc",
    ];
    let ours = scratch("meshmaker-ours");
    let theirs = scratch("meshmaker-povray");
    for (dir, installed) in [(&ours, false), (&theirs, true)] {
        if let Err(errors) = render_scene(&dir.join("write.pov"), writer, installed, (4, 3)) {
            panic!("the mesh writer fails:\n{}", errors.join("\n"));
        }
    }
    for file in files {
        let read = |dir: &PathBuf| {
            std::fs::read_to_string(dir.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
        };
        assert!(
            read(&ours) == read(&theirs),
            "{file} differs from POV-Ray's"
        );
    }
}
