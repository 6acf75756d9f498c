//! durer as a drop-in for `povray`: its switches and .ini files, animation, output formats,
//! alpha, render regions, statistics, exit codes. Every expected value written here that
//! comes from POV-Ray was printed or written by `povray` 3.7 for the same command.

use crate::reference_images::compare;
use crate::{scratch, tests_folder};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The durer binary, with no default INI file (POVINI names an empty one) so the tests do
/// not depend on the machine's povray.ini.
fn durer(folder: &Path) -> Command {
    let empty = folder.join("empty-povray.ini");
    std::fs::write(&empty, "").unwrap();
    let mut command = Command::new(env!("CARGO_BIN_EXE_durer"));
    command.current_dir(folder).env("POVINI", empty);
    command
}

fn run(folder: &Path, args: &[&str]) -> Output {
    durer(folder).args(args).output().expect("run durer")
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn fixture(name: &str) -> PathBuf {
    tests_folder().join("cli").join(name)
}

/// A scratch folder holding a copy of a fixture scene.
fn folder_with(name: &str, scene: &str) -> PathBuf {
    let folder = scratch(name);
    std::fs::copy(fixture(scene), folder.join(scene)).unwrap();
    folder
}

const SMALL_SCENE: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n\
    sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }\n\
    plane { y, -1 pigment { checker rgb 1, rgb 0.2 } }\n";

#[test]
fn povray_command_line_uses_povray_defaults_and_prints_statistics() {
    let folder = scratch("povray-defaults");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    let output = run(&folder, &["+Iscene.pov", "-D", "+V", "+Q9"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let image = image::open(folder.join("scene.png")).unwrap();
    assert_eq!(
        (image.width(), image.height()),
        (160, 120),
        "povray's 160x120"
    );
    let text = stderr(&output);
    assert!(text.contains("Render statistics"), "{text}");
    assert!(text.contains("Camera rays:"), "{text}");
    // -GS turns them off; a bare scene name is the input file.
    let output = run(&folder, &["scene.pov", "-GS", "+W20", "+H10"]);
    assert_eq!(output.status.code(), Some(0));
    assert!(!stderr(&output).contains("Render statistics"));
    let image = image::open(folder.join("scene.png")).unwrap();
    assert_eq!((image.width(), image.height()), (20, 10));
}

#[test]
fn ini_files_sections_comments_and_later_wins() {
    let folder = scratch("ini-sections");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    std::fs::write(
        folder.join("res.ini"),
        "; resolution\nInput_File_Name=scene.pov ; the scene\n+W30 +H20 ; unlabelled\n\
         [Low]\nWidth=16\nHeight = 12\nOutput_File_Name='low.png'\n[Really High]\n\
         Width=64\nHeight=48\nOutput_File_Name=high.png\n",
    )
    .unwrap();
    let size = |name: &str| {
        let image = image::open(folder.join(name)).unwrap();
        (image.width(), image.height())
    };
    assert!(run(&folder, &["res.ini", "-GS"]).status.success());
    assert_eq!(size("scene.png"), (30, 20));
    // A section replaces the unlabelled part (so the input file comes from the command
    // line here); labels ignore case; later options win.
    let output = run(&folder, &["res[low]", "+H9", "-GS", "+Iscene.pov"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(size("low.png"), (16, 9));
    let output = run(
        &folder,
        &["+H9", "res.ini[really high]", "-GS", "+Iscene.pov"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(size("high.png"), (64, 48));
    // durer's own flags win over POV-Ray options, in `render` too.
    let output = run(
        &folder,
        &[
            "render",
            "scene.pov",
            "res.ini[Low]",
            "--width",
            "8",
            "-o",
            "flag.png",
            "-q",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(size("flag.png"), (8, 12));
    let output = run(&folder, &["res.ini[Huge]"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("no section [Huge]"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn unknown_options_are_usage_errors_naming_the_nearest() {
    let folder = scratch("unknown-options");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    let output = run(&folder, &["+Iscene.pov", "+WX3"]);
    assert_eq!(output.status.code(), Some(2));
    let text = stderr(&output);
    assert!(text.contains("unknown switch `+WX3`"), "{text}");
    assert!(text.contains("did you mean `+W"), "{text}");
    assert!(text.contains("POV-Ray would ignore it"), "{text}");
    std::fs::write(
        folder.join("bad.ini"),
        "Input_File_Name=scene.pov\nWidht=30\n",
    )
    .unwrap();
    let output = run(&folder, &["bad.ini"]);
    assert_eq!(output.status.code(), Some(2));
    let text = stderr(&output);
    assert!(text.contains("bad.ini:2: unknown option `Widht`"), "{text}");
    assert!(text.contains("did you mean `Width`?"), "{text}");
    let output = run(&folder, &["+Iscene.pov", "+W0"]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    let output = run(&folder, &["+Iscene.pov", "Declare=V=<1,2,3>"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("--define"), "{}", stderr(&output));
}

/// The `#debug` lines of clock.pov under `options`, and the image files written.
fn clock_lines(name: &str, options: &[&str]) -> (Vec<String>, Vec<String>) {
    let folder = folder_with(name, "clock.pov");
    let mut args = vec!["+Iclock.pov", "+W8", "+H6", "-GS"];
    args.extend_from_slice(options);
    let output = run(&folder, &args);
    assert!(output.status.success(), "{}", stderr(&output));
    let lines = stderr(&output)
        .lines()
        .filter(|l| l.starts_with("clock="))
        .map(str::to_string)
        .collect();
    let mut files: Vec<String> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    files.sort();
    (lines, files)
}

#[test]
fn animation_clock_values_and_frame_names_match_povray() {
    let (lines, files) = clock_lines("anim-plain", &["+KFF3"]);
    assert_eq!(
        lines,
        [
            "clock=0.000000 delta=0.500000 on=1 frame=1 if=1 ff=3 ic=0.0000 fc=1.0000",
            "clock=0.500000 delta=0.500000 on=1 frame=2 if=1 ff=3 ic=0.0000 fc=1.0000",
            "clock=1.000000 delta=0.500000 on=1 frame=3 if=1 ff=3 ic=0.0000 fc=1.0000",
        ]
    );
    assert_eq!(files, ["clock1.png", "clock2.png", "clock3.png"]);
    let (lines, files) = clock_lines("anim-cyclic", &["+KFF12", "+KC", "+SF3", "+EF5"]);
    assert_eq!(
        lines,
        [
            "clock=0.166667 delta=0.083333 on=1 frame=3 if=1 ff=13 ic=0.0000 fc=1.0000",
            "clock=0.250000 delta=0.083333 on=1 frame=4 if=1 ff=13 ic=0.0000 fc=1.0000",
            "clock=0.333333 delta=0.083333 on=1 frame=5 if=1 ff=13 ic=0.0000 fc=1.0000",
        ]
    );
    assert_eq!(files, ["clock03.png", "clock04.png", "clock05.png"]);
    let (lines, files) = clock_lines("anim-clocks", &["+KFI5", "+KFF10", "+SF0.5", "+EF0.7"]);
    assert_eq!(
        lines,
        [
            "clock=0.000000 delta=0.200000 on=1 frame=5 if=5 ff=10 ic=0.0000 fc=1.0000",
            "clock=0.200000 delta=0.200000 on=1 frame=6 if=5 ff=10 ic=0.0000 fc=1.0000",
            "clock=0.400000 delta=0.200000 on=1 frame=7 if=5 ff=10 ic=0.0000 fc=1.0000",
        ]
    );
    assert_eq!(files, ["clock05.png", "clock06.png", "clock07.png"]);
    let (lines, files) = clock_lines("anim-step", &["+KFF10", "+STP3", "+KI2", "+KF4"]);
    assert_eq!(lines.len(), 4);
    assert!(lines[1].starts_with("clock=2.666667 delta=0.222222 on=1 frame=4"));
    assert_eq!(
        files,
        ["clock01.png", "clock04.png", "clock07.png", "clock10.png"]
    );
    // A still image: +K sets the clock (and clock_on), the rest stays 0.
    let (lines, files) = clock_lines("anim-still", &["+K0.25"]);
    assert_eq!(
        lines,
        ["clock=0.250000 delta=0.000000 on=1 frame=0 if=0 ff=0 ic=0.0000 fc=0.0000"]
    );
    assert_eq!(files, ["clock.png"]);
    // durer's own spellings.
    let folder = folder_with("anim-durer", "clock.pov");
    let output = run(
        &folder,
        &[
            "render",
            "clock.pov",
            "--frames",
            "1..24",
            "--frame",
            "7",
            "--width",
            "8",
            "--height",
            "6",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(folder.join("clock07.png").is_file());
    assert!(
        stderr(&output).contains("frame 7 (1 of 1, clock 0.26087)"),
        "{}",
        stderr(&output)
    );
    assert!(
        stderr(&output).contains("1 frames in"),
        "{}",
        stderr(&output)
    );
}

/// Reads a PNG with its exact samples (16-bit kept).
fn decode(path: &Path) -> image::DynamicImage {
    image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn every_output_format_decodes_back() {
    let folder = folder_with("formats", "flat.pov");
    let render = |switches: &[&str], name: &str| {
        let mut args = vec!["+Iflat.pov", "+W8", "+H6", "-GS"];
        args.extend_from_slice(switches);
        let out = format!("+O{name}");
        args.push(&out);
        let output = run(&folder, &args);
        assert!(output.status.success(), "{name}: {}", stderr(&output));
        folder.join(name)
    };
    // 8-bit: sRGB of the clipped value (0.5 -> 188, 0.25 -> 137, 2.0 -> 255).
    let png = decode(&render(&[], "flat.png")).to_rgb8();
    assert_eq!(png.get_pixel(0, 0).0, [188, 137, 255]);
    // 16 bits and alpha: the same curve at 65535; the background is transparent.
    let wide = decode(&render(&["+FN16", "+UA"], "wide.png"));
    let wide = wide.as_rgba16().expect("a 16-bit RGBA PNG");
    let expected = |v: f64| ((1.055 * v.powf(1.0 / 2.4) - 0.055) * 65535.0 + 0.5).floor() as u16;
    assert_eq!(
        wide.get_pixel(0, 0).0,
        [expected(0.5), expected(0.25), 65535, 65535]
    );
    assert_eq!(wide.get_pixel(7, 0).0[3], 0);
    // Targa (plain and run-length), BMP, PPM (16-bit), JPEG.
    let tga = render(&["+FT", "+UA"], "flat.tga");
    assert_eq!(
        std::fs::read(&tga).unwrap()[2],
        2,
        "uncompressed true-colour"
    );
    let tga = decode(&tga).to_rgba8();
    assert_eq!(tga.get_pixel(0, 0).0, [188, 137, 255, 255]);
    assert_eq!(tga.get_pixel(7, 0).0[3], 0);
    let rle = render(&["+FC"], "rle.tga");
    assert_eq!(
        std::fs::read(&rle).unwrap()[2],
        10,
        "run-length true-colour"
    );
    assert_eq!(decode(&rle).to_rgb8().get_pixel(0, 0).0, [188, 137, 255]);
    assert_eq!(
        decode(&render(&["+FB"], "flat.bmp"))
            .to_rgb8()
            .get_pixel(0, 0)
            .0,
        [188, 137, 255]
    );
    let ppm = decode(&render(&["+FP16"], "flat.ppm"));
    assert_eq!(
        ppm.as_rgb16().expect("16-bit PPM").get_pixel(0, 0).0[0],
        expected(0.5)
    );
    let jpeg = decode(&render(&[], "flat.jpg")).to_rgb8();
    let [r, g, b] = jpeg.get_pixel(1, 1).0;
    assert!(
        r.abs_diff(188) < 8 && g.abs_diff(137) < 8 && b > 240,
        "{r} {g} {b}"
    );
    // OpenEXR and Radiance: linear light, not clamped (2.0 stays 2.0).
    let exr = decode(&render(&["+UA"], "flat.exr")).to_rgba32f();
    let [r, g, b, a] = exr.get_pixel(0, 0).0;
    assert_eq!((r, g, b, a), (0.5, 0.25, 2.0, 1.0));
    assert_eq!(exr.get_pixel(7, 0).0, [0.0; 4], "associated alpha");
    let hdr = decode(&render(&["+FH"], "flat.hdr")).to_rgb32f();
    let [r, g, b] = hdr.get_pixel(0, 0).0;
    assert!((r - 0.5).abs() < 0.01 && (g - 0.25).abs() < 0.01 && (b - 2.0).abs() < 0.02);
    // The extension chooses the format when +F does not; +F keeps POV-Ray's naming.
    render(&["+FT"], "named.png");
    assert!(
        folder.join("named.png.tga").is_file(),
        "povray writes named.png.tga"
    );
    // Standard output.
    let output = run(&folder, &["+Iflat.pov", "+W8", "+H6", "-GS", "+O-"]);
    assert!(output.status.success());
    let piped = image::load_from_memory(&output.stdout).unwrap().to_rgb8();
    assert_eq!(piped.get_pixel(0, 0).0, [188, 137, 255]);
}

#[test]
fn alpha_channel_matches_povray() {
    let folder = folder_with("alpha", "alpha.pov");
    // povray 3.7's pixels (x = 0, 2, 4, 6 on rows 1 and 5) for each background.
    let cases: [(&str, [[[u8; 4]; 4]; 2]); 2] = [
        (
            "Declare=T=1",
            [
                [
                    [255, 0, 0, 255],
                    [0, 255, 0, 191],
                    [0, 234, 0, 233],
                    [0, 0, 0, 0],
                ],
                [
                    [255, 0, 0, 255],
                    [0, 255, 0, 191],
                    [0, 234, 0, 233],
                    [97, 117, 255, 239],
                ],
            ],
        ),
        (
            "Declare=T=0.5",
            [
                [
                    [255, 0, 0, 255],
                    [47, 243, 68, 223],
                    [0, 234, 0, 244],
                    [124, 149, 170, 128],
                ],
                [
                    [255, 0, 0, 255],
                    [47, 243, 68, 223],
                    [0, 234, 0, 244],
                    [98, 118, 255, 247],
                ],
            ],
        ),
    ];
    for (declare, rows) in cases {
        let output = run(
            &folder,
            &[
                "+Ialpha.pov",
                "+W8",
                "+H6",
                "+UA",
                "-GS",
                declare,
                "+Oalpha.png",
            ],
        );
        assert!(output.status.success(), "{}", stderr(&output));
        let image = decode(&folder.join("alpha.png")).to_rgba8();
        for (row, expected) in [1, 5].into_iter().zip(rows) {
            for (column, pixel) in [0, 2, 4, 6].into_iter().zip(expected) {
                assert_eq!(
                    image.get_pixel(column, row).0,
                    pixel,
                    "{declare}: pixel {column},{row}"
                );
            }
        }
    }
}

#[test]
fn region_pixels_equal_the_whole_render() {
    let folder = scratch("regions");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    for aa in [
        vec!["-A"],
        vec!["+A0.1", "+AM1"],
        vec!["+A0.1", "+AM2", "+R3"],
    ] {
        let mut whole = vec!["+Iscene.pov", "+W40", "+H30", "-GS", "+Owhole.png"];
        whole.extend(aa.iter().copied());
        assert!(run(&folder, &whole).status.success());
        let mut part = vec![
            "+Iscene.pov",
            "+W40",
            "+H30",
            "-GS",
            "+Opart.png",
            "+SC11",
            "+EC30",
            "+SR0.3",
            "+ER0.8",
        ];
        part.extend(aa.iter().copied());
        let output = run(&folder, &part);
        assert!(output.status.success(), "{}", stderr(&output));
        let whole = decode(&folder.join("whole.png")).to_rgb8();
        let part = decode(&folder.join("part.png")).to_rgb8();
        assert_eq!(
            part.dimensions(),
            (40, 30),
            "a full-size image, as povray writes"
        );
        for y in 0..30 {
            for x in 0..40 {
                // Columns 11..=30 (from 1), rows 9..24 (0.3 and 0.8 of 30, from 0).
                let inside = (10..30).contains(&x) && (9..24).contains(&y);
                let expected = if inside {
                    whole.get_pixel(x, y).0
                } else {
                    [0, 0, 0]
                };
                assert_eq!(part.get_pixel(x, y).0, expected, "{aa:?}: pixel {x},{y}");
            }
        }
    }
}

#[test]
fn statistics_as_json() {
    let folder = scratch("stats-json");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    let output = run(
        &folder,
        &[
            "render",
            "scene.pov",
            "--width",
            "20",
            "--height",
            "10",
            "--stats",
            "json",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let json = String::from_utf8_lossy(&output.stdout);
    for key in [
        "\"frames\": 1",
        "\"objects\": 2",
        "\"lights\": 1",
        "\"camera\": 200",
        "\"shadow\": ",
        "\"intersection_tests\": ",
        "\"render\": ",
        "\"peak_memory_bytes\": ",
    ] {
        assert!(json.contains(key), "{key} in {json}");
    }
    let shadow: u64 = json
        .split("\"shadow\": ")
        .nth(1)
        .and_then(|rest| rest.split(',').next())
        .and_then(|n| n.trim().parse().ok())
        .unwrap();
    assert!(
        shadow > 0 && shadow <= 200,
        "one light: at most one shadow ray per hit"
    );
}

#[test]
fn statistics_give_rates_per_thread_and_radiosity_samples_by_bounce() {
    let folder = scratch("stats-radiosity");
    std::fs::write(
        folder.join("scene.pov"),
        "global_settings { radiosity { count 20 recursion_limit 2 } }\n\
         camera { location <0, 1, -3> look_at <0, 0.5, 0> }\n\
         light_source { <2, 4, -3> rgb 1 }\n\
         plane { y, 0 pigment { rgb 1 } }\n\
         box { <-1, 0, 0>, <1, 2, 0.2> pigment { rgb <1, 0.2, 0.2> } }\n",
    )
    .unwrap();
    let output = run(
        &folder,
        &[
            "render",
            "scene.pov",
            "--width",
            "32",
            "--height",
            "24",
            "--threads",
            "2",
            "--stats",
            "json",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let json = String::from_utf8_lossy(&output.stdout);
    let number_after = |text: &str, key: &str| -> f64 {
        text.split(&format!("\"{key}\": "))
            .nth(1)
            .and_then(|rest| rest.split([',', '}']).next())
            .and_then(|n| n.trim().parse().ok())
            .unwrap_or_else(|| panic!("{key} in {text}"))
    };
    assert_eq!(number_after(&json, "threads"), 2.0);
    let samples = json.split("\"radiosity_samples\": ").nth(1).unwrap();
    assert!(number_after(samples, "first_bounce") > 0.0, "{json}");
    assert!(number_after(samples, "second_bounce") > 0.0, "{json}");
    assert_eq!(
        number_after(samples, "deeper"),
        0.0,
        "recursion_limit 2: {json}"
    );
    // The rate is the count over the render time and the threads.
    let rates = json
        .split("\"rays_per_second_per_thread\": ")
        .nth(1)
        .unwrap();
    let seconds = json.split("\"seconds\": ").nth(1).unwrap();
    let expected = number_after(&json, "camera") / number_after(seconds, "render") / 2.0;
    let rate = number_after(rates, "camera");
    assert!(
        (rate - expected).abs() <= 1.0 + expected * 1e-3,
        "{rate} vs {expected}: {json}"
    );
}

#[test]
fn defines_take_any_value() {
    let folder = scratch("defines");
    std::fs::write(
        folder.join("scene.pov"),
        "#if (Size != 2 | Colour.x != 1 | Name != \"text\" | Count != 3) #error \"wrong\" #end\n\
         camera { location -3*z look_at 0 } sphere { 0, Size pigment { Colour } }\n",
    )
    .unwrap();
    let output = run(
        &folder,
        &[
            "render",
            "scene.pov",
            "--width",
            "8",
            "--height",
            "6",
            "--quiet",
            "--define",
            "Size=2",
            "--define",
            "Colour=<1, 0, 0>",
            "--define",
            "Name=\"text\"",
            "Declare=Count=3",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let output = run(&folder, &["render", "scene.pov", "--define", "Size=(1+"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("<command line>"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn ctrl_c_stops_the_render_and_keeps_the_previous_image() {
    let folder = scratch("interrupt");
    std::fs::write(folder.join("scene.pov"), SMALL_SCENE).unwrap();
    std::fs::write(folder.join("scene.png"), b"previous image").unwrap();
    let mut child = durer(&folder)
        .args(["+Iscene.pov", "+W3000", "+H3000", "+A0", "+R5", "-GS"])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let signalled = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    if !signalled.is_ok_and(|s| s.success()) {
        let _ = child.kill();
        let _ = child.wait();
        eprintln!("skipped: `kill` could not send SIGINT");
        return;
    }
    let started = std::time::Instant::now();
    let output = child.wait_with_output().unwrap();
    assert!(started.elapsed().as_secs() < 10, "stops promptly");
    assert_eq!(output.status.code(), Some(130), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("interrupted"),
        "{}",
        stderr(&output)
    );
    assert_eq!(
        std::fs::read(folder.join("scene.png")).unwrap(),
        b"previous image"
    );
}

/// The frames of POV-Ray's example animations listed in tests/animation/NAME/frames.txt,
/// rendered by `durer NAME.ini` as `povray NAME.ini` rendered the references
/// (scripts/render-animation-references.sh): same file names, images matching.
#[test]
fn example_animations_match_povray_frames() {
    let root = tests_folder().join("animation");
    let mut checked = 0;
    for entry in std::fs::read_dir(&root).unwrap() {
        let scene_folder = entry.unwrap().path();
        let Some(name) = scene_folder
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
        else {
            continue;
        };
        let Ok(frames) = std::fs::read_to_string(scene_folder.join("frames.txt")) else {
            continue;
        };
        let out = scratch(&format!("animation-{name}"));
        for frame in frames.split_whitespace() {
            let output = durer(&scene_folder)
                .args([
                    format!("{name}.ini"),
                    "+W80".into(),
                    "+H60".into(),
                    format!("+SF{frame}"),
                    format!("+EF{frame}"),
                    "-J".into(),
                    "-GS".into(),
                    format!("+O{}/", out.display()),
                ])
                .output()
                .unwrap();
            assert!(
                output.status.success(),
                "{name} {frame}: {}",
                stderr(&output)
            );
            let reference_name = std::fs::read_dir(scene_folder.join("reference"))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .find(|n| {
                    n.trim_end_matches(".png")
                        .ends_with(&format!("{frame:0>2}"))
                })
                .unwrap_or_else(|| panic!("{name}: no reference for frame {frame}"));
            let ours = out.join(&reference_name);
            assert!(ours.is_file(), "{name}: durer must write {reference_name}");
            let reference = decode(&scene_folder.join("reference").join(&reference_name));
            let comparison = compare(&reference.to_rgb8(), &decode(&ours).to_rgb8()).unwrap();
            assert!(
                comparison.fraction_over <= 0.02,
                "{name} frame {frame}: {:.2}% of pixels off",
                comparison.fraction_over * 100.0
            );
            checked += 1;
        }
    }
    assert!(checked >= 6, "two animations at three clock values each");
}
