//! Hostile input (issue 16): every case a careless user or an attacker found ends in a clear
//! diagnostic and a non-zero exit, in bounded time and memory; the limits are named and can
//! be raised; the file policy holds for every way a scene touches a file; special files
//! given as `-o` are written through. One test per item, named after it.

use crate::scratch;
use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn durer() -> Command {
    Command::new(env!("CARGO_BIN_EXE_durer"))
}

fn path(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

/// Runs durer with `args` and returns its output and how long it took.
fn run(args: &[&str]) -> (Output, Duration) {
    let start = Instant::now();
    let output = durer().args(args).output().expect("run durer");
    (output, start.elapsed())
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Writes `text` as `name` in a fresh folder and runs `durer check` on it with `extra`.
fn check(folder: &str, text: &str, extra: &[&str]) -> (Output, Duration) {
    let dir = scratch(folder);
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, text).unwrap();
    let mut args = vec!["check", path(&scene)];
    args.extend_from_slice(extra);
    run(&args)
}

/// Asserts a scene error (exit 1, no panic) whose report contains every text.
fn assert_scene_error(output: &Output, texts: &[&str]) {
    let text = stderr(output);
    assert_eq!(output.status.code(), Some(1), "{text}");
    assert!(!text.contains("panicked"), "{text}");
    for expected in texts {
        assert!(text.contains(expected), "missing {expected:?} in:\n{text}");
    }
}

#[test]
fn report_printer_survives_columns_past_65535() {
    let scene = format!(
        "#declare A = 1;{}#declare B = Missing;\n",
        " ".repeat(70_000)
    );
    let (output, _) = check("long-line", &scene, &[]);
    assert_scene_error(
        &output,
        &["scene.pov:1:70029", "undefined identifier `Missing`"],
    );
}

#[test]
fn deep_csg_checks_and_renders_up_to_the_nesting_limit_then_stops() {
    // 19,990 nested intersections: the block nesting limit is 20,000.
    let depth = 19_990;
    let scene = format!(
        "camera {{ location -5*z look_at 0 }}\nlight_source {{ <1, 2, -3> 1 }}\n{}sphere {{ 0, 1 \
         pigment {{ rgb 1 }} }}{}\n",
        "intersection { sphere { 0, 3 } ".repeat(depth),
        "}".repeat(depth)
    );
    let dir = scratch("deep-csg");
    let file = dir.join("deep.pov");
    std::fs::write(&file, &scene).unwrap();
    let (output, _) = run(&["check", path(&file)]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    // One render thread: the rayon thread, not the evaluator, must have the room.
    let image = dir.join("deep.png");
    let (output, _) = run(&[
        "render",
        path(&file),
        "--width",
        "8",
        "--height",
        "6",
        "--threads",
        "1",
        "-o",
        path(&image),
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let too_deep = format!(
        "{}sphere {{ 0, 1 }}{}\n",
        "union { ".repeat(20_001),
        "}".repeat(20_001)
    );
    let (output, _) = check("too-deep-csg", &too_deep, &[]);
    assert_scene_error(
        &output,
        &["nesting deeper than 20000 levels", "--limit nesting="],
    );
}

#[test]
fn object_copy_loop_stops_at_the_objects_limit() {
    // Each copy of O copies its whole tree: quadratic growth with no nesting at all.
    let scene = "#declare O = sphere { 0, 1 }\n#declare I = 0;\n#while (I < 100000)\n\
                 #declare O = union { object { O } }\n#declare I = I + 1;\n#end\nobject { O }\n";
    let (output, took) = check("copy-loop", scene, &[]);
    assert_scene_error(&output, &["more than 5000000 objects", "--limit objects="]);
    assert!(took < Duration::from_secs(30), "took {took:?}");
    // Raised limit: the tree then grows past the nesting limit instead.
    let (output, _) = check(
        "copy-loop-raised",
        scene,
        &["--limit", "objects=1000000000", "--limit", "nesting=2000"],
    );
    assert_scene_error(&output, &["nests more than 2000 levels deep"]);
}

#[test]
fn endless_object_loop_stops_at_the_objects_limit() {
    let scene = "#declare I = 0;\n#while (1)\nsphere { <I, 0, 0>, 1 }\n#declare I = I + 1;\n#end\n";
    let (output, _) = check("object-loop", scene, &["--limit", "objects=20000"]);
    assert_scene_error(&output, &["more than 20000 objects", "objects=200000"]);
}

#[test]
fn endless_while_stops_at_the_iterations_limit() {
    let scene = "#declare I = 0;\n#while (1)\n#declare I = I + 1;\n#end\n";
    let (output, _) = check("while-loop", scene, &["--limit", "iterations=50000"]);
    assert_scene_error(&output, &["loop ran 50000 times", "--limit iterations="]);
}

#[test]
fn endless_mesh_loops_stop_at_the_geometry_memory_limit() {
    // Triangles of a mesh and vectors of a mesh2 made by loops that never end: one object
    // each, so only the geometry limit stops them.
    let mesh = "mesh {\n#declare I = 0;\n#while (1)\ntriangle { <I,0,0>, <I,1,0>, <I,0,1> }\n\
                #declare I = I + 1;\n#end\n}\n";
    let (output, took) = check("mesh-loop", mesh, &["--limit", "geometry-memory=1e6"]);
    assert_scene_error(
        &output,
        &[
            "meshes need more than 1000000 bytes",
            "--limit geometry-memory=",
        ],
    );
    assert!(took < Duration::from_secs(30), "took {took:?}");
    let mesh2 = "mesh2 { vertex_vectors { 10000000,\n#declare I = 0;\n#while (1)\n<I,0,0>,\n\
                 #declare I = I + 1;\n#end\n} }\n";
    let (output, _) = check("mesh2-loop", mesh2, &["--limit", "geometry-memory=1e6"]);
    assert_scene_error(&output, &["meshes need more than 1000000 bytes"]);
}

#[test]
fn endless_loops_leaving_values_stop_at_the_iterations_limit_in_bounded_memory() {
    // Each pass leaves a value that is kept (an array element, a map entry): the default
    // iterations limit must stop them before memory runs out.
    for (name, scene) in [
        (
            "array-loop",
            "#declare A = array { #for (I, 0, 1e400) 5, #end }\n",
        ),
        (
            "map-loop",
            "#declare C = color_map { #for (I, 0, 1e400) [0.5 rgb 1] #end }\n",
        ),
    ] {
        let (output, took) = check(name, scene, &[]);
        assert_scene_error(&output, &["loop ran 10000000 times", "--limit iterations="]);
        assert!(took < Duration::from_secs(60), "{name} took {took:?}");
    }
}

#[test]
fn growing_string_stops_at_the_string_size_limit() {
    let scene = "#declare S = \"x\";\n#while (1)\n#declare S = concat(S, S);\n#end\n";
    let (output, _) = check("string-growth", scene, &[]);
    assert_scene_error(
        &output,
        &["string longer than 16777216 bytes", "string-size"],
    );
}

#[test]
fn deep_macro_recursion_and_deep_expressions_work_then_stop() {
    let recursion = |n: u32| {
        format!(
            "#macro R(N) #if (N > 0) union {{ R(N - 1) }} #else sphere {{ 0, 1 }} #end #end\n\
             R({n})\n"
        )
    };
    let (output, _) = check("macro-recursion", &recursion(9_000), &[]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let (output, _) = check("macro-recursion-deep", &recursion(30_000), &[]);
    assert_scene_error(&output, &["nesting deeper than", "--limit nesting="]);
    let depth = 20_000;
    let expression = format!(
        "#declare A = {}1{};\n#declare B = {}1;\nsphere {{ 0, A + B }}\n",
        "(".repeat(depth),
        ")".repeat(depth),
        "-".repeat(depth)
    );
    let (output, _) = check("deep-expression", &expression, &[]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
}

#[test]
fn unterminated_comments_macros_and_map_vectors_fail_fast() {
    // Each of these doubled the parser's time per level: 20 took seconds to minutes.
    let cases = [
        (
            format!("sphere {{ 0, 1 }}\n{}\n", "/* ".repeat(40)),
            "no `*/` closes this comment",
        ),
        (
            (0..40)
                .map(|i| format!("#macro M{i}()\n sphere {{ 0, 1 }}\n"))
                .collect::<String>(),
            "unterminated `#macro`",
        ),
        (
            format!(
                "sphere {{ 0, 1 pigment {{ color_map {{ {}{} }} }} }}\n",
                "[0 <1 ".repeat(40),
                "]".repeat(40)
            ),
            "scene.pov:1:",
        ),
    ];
    for (scene, expected) in cases {
        let (output, took) = check("unterminated", &scene, &[]);
        assert_scene_error(&output, &[expected]);
        assert!(took < Duration::from_secs(5), "{expected}: took {took:?}");
    }
}

#[test]
fn backtracking_parser_stops_at_the_parse_steps_limit() {
    // Nested unclosed calls with comparisons still make the grammar backtrack; the step
    // budget bounds it with a diagnostic naming the limit.
    let scene = format!("#declare A = {};\n", "f(0 <1 ".repeat(14));
    let (output, took) = check("parse-steps", &scene, &["--limit", "parse-steps=2000000"]);
    assert_scene_error(&output, &["the parser gave up", "--limit parse-steps="]);
    assert!(took < Duration::from_secs(10), "took {took:?}");
}

#[test]
fn huge_image_zero_width_and_too_many_threads_are_refused() {
    let dir = scratch("image-limits");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, "sphere { 0, 1 }\n").unwrap();
    let out = dir.join("out.png");
    let cases: [(&[&str], &str); 5] = [
        (&["--width", "60000", "--height", "60000"], "`pixels` limit"),
        (&["--width", "0"], "0 is not in 1..=65535"),
        (&["+W0"], "expected a whole number from 1 to 65535"),
        (
            &["--threads", "100000", "--width", "8", "--height", "8"],
            "`threads` limit",
        ),
        (&["+WT100000"], "from 1 to 512"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["render", path(&scene), "-o", path(&out)];
        args.extend_from_slice(extra);
        let (output, took) = run(&args);
        let text = stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{extra:?}: {text}");
        assert!(text.contains(expected), "{extra:?}: {text}");
        assert!(took < Duration::from_secs(5), "{extra:?}: took {took:?}");
    }
    assert!(!out.exists());
    // The limit can be lowered and raised: 16 x 16 is refused under 100 pixels.
    let (output, _) = run(&[
        "render",
        path(&scene),
        "-o",
        path(&out),
        "--width",
        "16",
        "--height",
        "16",
        "--limit",
        "pixels=100",
    ]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("--limit pixels=256"),
        "{}",
        stderr(&output)
    );
    let (output, _) = run(&[
        "render",
        path(&scene),
        "-o",
        path(&out),
        "--width",
        "16",
        "--height",
        "16",
        "--limit",
        "pixels=256",
        "--quiet",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let (output, _) = run(&["render", "--limit", "colours=3", path(&scene)]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("the limits are nesting"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn include_outside_the_file_policy_is_refused_without_reading_it() {
    let dir = scratch("policy-include");
    // The scene reads its project (two folders up: `a`) but not beside it.
    std::fs::create_dir_all(dir.join("a/b/scene")).unwrap();
    std::fs::create_dir_all(dir.join("private")).unwrap();
    std::fs::write(dir.join("private/secret.inc"), "SECRET-FIRST-LINE\n").unwrap();
    std::fs::write(dir.join("a/shared.inc"), "#declare Shared = 1;\n").unwrap();
    let scene = dir.join("a/b/scene/scene.pov");
    std::fs::write(
        &scene,
        "#include \"../../shared.inc\"\nsphere { 0, Shared }\n",
    )
    .unwrap();
    let (output, _) = run(&["check", path(&scene)]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    for name in [
        path(&dir.join("private/secret.inc")).to_string(),
        "../../../private/secret.inc".to_string(),
    ] {
        std::fs::write(&scene, format!("#include \"{name}\"\nsphere {{ 0, 1 }}\n")).unwrap();
        let (output, _) = run(&["check", path(&scene)]);
        assert_scene_error(&output, &["the file policy does not allow scenes to read"]);
        assert!(!stderr(&output).contains("SECRET"), "{}", stderr(&output));
        // Widened: the same scene reads it (and fails on its text, which is no SDL).
        let (output, _) = run(&[
            "check",
            path(&scene),
            "--allow-read",
            path(&dir.join("private")),
        ]);
        assert!(stderr(&output).contains("SECRET"), "{}", stderr(&output));
    }
}

#[cfg(unix)]
#[test]
fn fopen_through_a_symbolic_link_is_refused() {
    let dir = scratch("policy-symlink");
    // The scene is deep enough that `elsewhere` is outside its project (two folders up).
    std::fs::create_dir_all(dir.join("a/b/scene")).unwrap();
    std::fs::create_dir_all(dir.join("elsewhere")).unwrap();
    std::fs::write(dir.join("elsewhere/data.txt"), "\"x\"\n").unwrap();
    std::os::unix::fs::symlink(
        dir.join("elsewhere/data.txt"),
        dir.join("a/b/scene/link.txt"),
    )
    .unwrap();
    std::os::unix::fs::symlink(dir.join("elsewhere"), dir.join("a/b/scene/out")).unwrap();
    let scene = dir.join("a/b/scene/scene.pov");
    std::fs::write(&scene, "#fopen F \"link.txt\" read\n#read (F, S)\n").unwrap();
    let (output, _) = run(&["check", path(&scene)]);
    assert_scene_error(
        &output,
        &["does not allow scenes to read", "elsewhere/data.txt"],
    );
    std::fs::write(
        &scene,
        "#fopen F \"out/new.txt\" write\n#write (F, \"x\")\n",
    )
    .unwrap();
    let (output, _) = run(&["check", path(&scene)]);
    assert_scene_error(&output, &["does not allow scenes to write"]);
    assert!(!dir.join("elsewhere/new.txt").exists());
    // A povray.conf can permit the folder.
    let conf = dir.join("povray.conf");
    let conf_text = format!(
        "[File I/O Security]\nrestricted\n[Permitted Paths]\nread+write* = \"{}\"\n",
        path(&dir.join("elsewhere"))
    );
    std::fs::write(&conf, conf_text).unwrap();
    let (output, _) = run(&["check", path(&scene), "--file-policy", path(&conf)]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(dir.join("elsewhere/new.txt").exists());
}

#[test]
fn file_exists_outside_the_file_policy_answers_false() {
    let scene = "#if (file_exists(\"/etc/passwd\")) #error \"probed\" #end\nsphere { 0, 1 }\n";
    let (output, _) = check("policy-file-exists", scene, &[]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("answers false"),
        "{}",
        stderr(&output)
    );
    let (output, _) = check(
        "policy-file-exists-allowed",
        scene,
        &["--allow-read", "/etc"],
    );
    assert_scene_error(&output, &["probed"]);
}

#[cfg(unix)]
#[test]
fn output_to_a_device_or_fifo_is_written_through() {
    use std::os::unix::fs::FileTypeExt;
    let dir = scratch("special-output");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, "sphere { 0, 1 pigment { rgb 1 } }\n").unwrap();
    let size = ["--width", "8", "--height", "8", "--quiet"];
    if Path::new("/dev/full").exists() {
        let mut args = vec!["render", path(&scene), "-o", "/dev/full"];
        args.extend_from_slice(&size);
        let (output, _) = run(&args);
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        assert!(
            stderr(&output).contains("No space left"),
            "{}",
            stderr(&output)
        );
        let kind = std::fs::metadata("/dev/full").unwrap().file_type();
        assert!(kind.is_char_device(), "/dev/full was replaced");
    }
    // A FIFO: made with mkfifo(1), read by a thread.
    let fifo = dir.join("pipe");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        println!("skipped: mkfifo is not available");
        return;
    }
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let mut args = vec!["render", path(&scene), "-o", path(&fifo), "+FN"];
    args.extend_from_slice(&size);
    let (output, _) = run(&args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let bytes = reader.join().unwrap();
    assert!(bytes.starts_with(b"\x89PNG"), "read {} bytes", bytes.len());
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    // A symbolic link: the file it names gets the image, the link stays.
    let target = dir.join("target.png");
    let link = dir.join("link.png");
    std::fs::write(&target, b"old").unwrap();
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let mut args = vec!["render", path(&scene), "-o", path(&link)];
    args.extend_from_slice(&size);
    let (output, _) = run(&args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read(&target).unwrap().starts_with(b"\x89PNG"));
}
