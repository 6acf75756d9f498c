//! The real binary: exit codes, output files, determinism.

use crate::{scratch, tests_folder};
use std::process::Command;

fn durer() -> Command {
    Command::new(env!("CARGO_BIN_EXE_durer"))
}

const SMALL_SCENE: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n\
    sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }\n\
    plane { y, -1 pigment { checker rgb 1, rgb 0.2 } }\n";

fn path(p: &std::path::Path) -> &str {
    p.to_str().expect("utf-8 path")
}

#[test]
fn render_writes_a_png_and_exits_zero() {
    let dir = scratch("render");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    let status = durer()
        .args([
            "render",
            path(&scene),
            "--width",
            "32",
            "--height",
            "24",
            "--quiet",
        ])
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    let image = image::open(dir.join("scene.png")).expect("default output next to the scene");
    assert_eq!((image.width(), image.height()), (32, 24));
}

#[test]
fn scene_error_exits_one_and_keeps_the_old_image() {
    let dir = scratch("error");
    let scene = dir.join("bad.pov");
    std::fs::write(&scene, "sphere { 0, 1 pigmnet { rgb 1 } }\n").unwrap();
    let output = dir.join("out.png");
    std::fs::write(&output, b"previous image").unwrap();
    let result = durer()
        .args(["render", path(&scene), "-o", path(&output)])
        .output()
        .unwrap();
    assert_eq!(result.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("bad.pov:1:15"), "{stderr}");
    assert!(stderr.contains("did you mean `pigment`?"), "{stderr}");
    assert_eq!(std::fs::read(&output).unwrap(), b"previous image");
}

#[test]
fn usage_error_exits_two() {
    let result = durer().args(["render", "--no-such-flag"]).output().unwrap();
    assert_eq!(result.status.code(), Some(2));
}

#[test]
fn missing_scene_file_exits_one() {
    let result = durer()
        .args(["check", "/no/such/scene.pov"])
        .output()
        .unwrap();
    assert_eq!(result.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&result.stderr).contains("cannot read"));
}

#[test]
fn check_prints_a_summary() {
    let scene = tests_folder().join("language").join("objects.pov");
    let result = durer().args(["check", path(&scene)]).output().unwrap();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(0), "{stderr}");
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(
        stdout.contains("16 objects") && stdout.contains("lights"),
        "{stdout}"
    );
}

#[test]
fn output_is_identical_for_any_thread_count() {
    let dir = scratch("threads");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    let mut images = Vec::new();
    for threads in ["1", "4"] {
        let out = dir.join(format!("t{threads}.png"));
        let status = durer()
            .args([
                "render",
                path(&scene),
                "-o",
                path(&out),
                "--width",
                "64",
                "--height",
                "48",
            ])
            .args(["--threads", threads, "--quiet"])
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(0));
        images.push(std::fs::read(out).unwrap());
    }
    assert_eq!(images[0], images[1]);
}

#[test]
fn radiosity_renders_are_identical_on_one_two_and_seven_threads() {
    // Three bounces, a pretrace whose gathers run in parallel batches and a final pass that
    // stores samples: the written PNG files must be the same bytes on any thread count.
    let scene = tests_folder().join("reference/radiosity_deep_reuse.pov");
    let dir = scratch("radiosity-threads");
    let mut images = Vec::new();
    for threads in ["1", "2", "7"] {
        let out = dir.join(format!("t{threads}.png"));
        let status = durer()
            .args(["render", path(&scene), "-o", path(&out)])
            .args([
                "--width",
                "48",
                "--height",
                "36",
                "--threads",
                threads,
                "--quiet",
            ])
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(0));
        images.push(std::fs::read(out).unwrap());
    }
    assert_eq!(images[0], images[1], "1 and 2 threads differ");
    assert_eq!(images[0], images[2], "1 and 7 threads differ");
}

#[test]
fn antialiasing_options_render_deterministically() {
    let dir = scratch("antialias");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    let render = |name: &str, extra: &[&str], threads: &str| {
        let output = dir.join(name);
        let status = durer()
            .args(["render", path(&scene), "-o", path(&output)])
            .args([
                "--width",
                "32",
                "--height",
                "24",
                "--quiet",
                "--threads",
                threads,
            ])
            .args(extra)
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(0), "{extra:?}");
        std::fs::read(output).unwrap()
    };
    let plain = render("plain.png", &[], "1");
    let method1 = render("aa1.png", &["--antialias", "0.1", "--jitter", "1"], "1");
    let method1_again = render("aa1b.png", &["--antialias", "0.1", "--jitter", "1"], "3");
    assert_ne!(plain, method1);
    assert_eq!(method1, method1_again, "jittered renders depend on threads");
    let method2 = [
        "--antialias",
        "0.1",
        "--aa-method",
        "2",
        "--aa-depth",
        "2",
        "--jitter",
        "0",
    ];
    assert_ne!(render("aa2.png", &method2, "2"), method1);
}

#[test]
fn bad_antialiasing_values_are_usage_errors() {
    let dir = scratch("antialias-bad");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    for (flag, value, message) in [
        ("--antialias", "3.5", "expected a number from 0 to 3"),
        ("--antialias", "lots", "expected a number from 0 to 3"),
        ("--aa-method", "3", "3 is not in 1..=2"),
        ("--aa-depth", "0", "0 is not in 1..=9"),
        ("--aa-depth", "10", "10 is not in 1..=9"),
        ("--jitter", "2", "expected a number from 0 to 1"),
    ] {
        let result = durer()
            .args(["render", path(&scene), flag, value])
            .output()
            .unwrap();
        assert_eq!(result.status.code(), Some(2), "{flag} {value}");
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(stderr.contains(message), "{flag} {value}: {stderr}");
    }
}

#[test]
fn huge_images_zero_sizes_and_too_many_threads_are_usage_errors() {
    let dir = scratch("limits");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    let run = |args: &[&str]| {
        let mut all = vec!["render", path(&scene)];
        all.extend_from_slice(args);
        durer().args(all).output().unwrap()
    };
    let huge = run(&["--width", "60000", "--height", "60000"]);
    assert_eq!(huge.status.code(), Some(2));
    let text = String::from_utf8_lossy(&huge.stderr);
    assert!(text.contains("--limit pixels=3600000000"), "{text}");
    assert_eq!(run(&["--width", "0"]).status.code(), Some(2));
    assert_eq!(run(&["+W0"]).status.code(), Some(2));
    assert_eq!(run(&["--threads", "100000"]).status.code(), Some(2));
    assert_eq!(run(&["+WT100000"]).status.code(), Some(2));
    // Raising the limit lets a large image through the check (here cut short by -F).
    let raised = run(&[
        "--width",
        "8000",
        "--height",
        "6000",
        "--max-pixels",
        "48000000",
        "+SR1",
        "+ER1",
        "-F",
        "--quiet",
    ]);
    assert_eq!(
        raised.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&raised.stderr)
    );
}

#[test]
fn output_to_a_device_is_written_through_not_replaced() {
    let dir = scratch("device");
    let scene = dir.join("scene.pov");
    std::fs::write(&scene, SMALL_SCENE).unwrap();
    let status = durer()
        .args([
            "render",
            path(&scene),
            "--width",
            "8",
            "--height",
            "6",
            "-o",
            "/dev/null",
            "-q",
        ])
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    assert!(!std::fs::metadata("/dev/null").unwrap().is_file());
    if std::path::Path::new("/dev/full").exists() {
        let full = durer()
            .args([
                "render",
                path(&scene),
                "--width",
                "8",
                "--height",
                "6",
                "-o",
                "/dev/full",
            ])
            .output()
            .unwrap();
        assert_eq!(full.status.code(), Some(1));
        assert!(String::from_utf8_lossy(&full.stderr).contains("cannot write /dev/full"));
        assert!(!std::fs::metadata("/dev/full").unwrap().is_file());
    }
}
