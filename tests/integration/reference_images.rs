//! Reference-image tests: durer must render like POV-Ray 3.7.
//!
//! Every `tests/reference/NAME.pov` with a `NAME.png` next to it (rendered by POV-Ray with
//! `scripts/render-references.sh`) is rendered by the durer binary at the reference's size,
//! and the two images are compared. A scene passes when at most 2% of its pixels differ by
//! more than 24/255 in any channel; a line `// tolerance: 0.05` in the scene raises that
//! fraction for scenes with inherent speckle. A line `// povray-options: +A0.3 +AM2 +R3 -J`
//! gives the anti-aliasing POV-Ray rendered the reference with; durer renders with the
//! same options. The test needs no POV-Ray installed.
//!
//! Failing renders, the reference and a diff image (red: pixel over the threshold) are
//! written to `target/reference-failures/`. Set `DURER_REFERENCE_FILTER=sphere` to run only
//! scenes whose name contains `sphere`, and `DURER_REFERENCE_KEEP=DIR` to keep every durer
//! render in `DIR` (to check that a change leaves every image byte-identical).

use std::fmt::Write as _;
use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use image::{Rgb, RgbImage};

/// A pixel is over when a channel differs by more than this (0..255).
const PIXEL_THRESHOLD: u8 = 24;
/// Fraction of pixels allowed over the threshold unless the scene says otherwise.
const DEFAULT_TOLERANCE: f64 = 0.02;
/// Side of the square blocks whose means the "close" measure compares.
const BLOCK_SIZE: u32 = 4;
/// Mean absolute block difference (0..255) at or under which an image is "close".
const CLOSE_BLOCK_DIFF: f64 = 6.0;
/// A render taking longer than this is killed and counted as a failure.
const RENDER_TIMEOUT: Duration = Duration::from_secs(300);

/// The metric for one pair of equally sized images.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Comparison {
    /// Fraction of pixels with a channel differing by more than `PIXEL_THRESHOLD`.
    pub(crate) fraction_over: f64,
    /// Mean absolute difference of 4x4-block channel means, in 0..255.
    block_diff: f64,
    /// Largest channel difference.
    max_diff: u8,
}

impl Comparison {
    fn matches(&self, tolerance: f64) -> bool {
        self.fraction_over <= tolerance
    }

    fn is_close(&self) -> bool {
        self.block_diff <= CLOSE_BLOCK_DIFF
    }
}

/// Compares two images; `None` when their sizes differ.
pub(crate) fn compare(a: &RgbImage, b: &RgbImage) -> Option<Comparison> {
    if a.dimensions() != b.dimensions() {
        return None;
    }
    let (width, height) = a.dimensions();

    // Per-pixel threshold and maximum.
    let mut over = 0usize;
    let mut max_diff = 0u8;
    for (pa, pb) in a.pixels().zip(b.pixels()) {
        let worst = (0..3).map(|c| pa[c].abs_diff(pb[c])).max().unwrap_or(0);
        max_diff = max_diff.max(worst);
        if worst > PIXEL_THRESHOLD {
            over += 1;
        }
    }

    // Per-channel block means; blocks on the right and bottom edges may be partial.
    let mut block_total = 0.0;
    let mut block_count = 0usize;
    for by in (0..height).step_by(BLOCK_SIZE as usize) {
        for bx in (0..width).step_by(BLOCK_SIZE as usize) {
            let mut sums = [0.0f64; 6];
            let mut pixels = 0.0;
            for y in by..(by + BLOCK_SIZE).min(height) {
                for x in bx..(bx + BLOCK_SIZE).min(width) {
                    let (pa, pb) = (a.get_pixel(x, y), b.get_pixel(x, y));
                    for c in 0..3 {
                        sums[c] += f64::from(pa[c]);
                        sums[c + 3] += f64::from(pb[c]);
                    }
                    pixels += 1.0;
                }
            }
            for c in 0..3 {
                block_total += (sums[c] - sums[c + 3]).abs() / pixels;
                block_count += 1;
            }
        }
    }

    let pixel_count = (width as usize) * (height as usize);
    Some(Comparison {
        fraction_over: if pixel_count == 0 {
            0.0
        } else {
            over as f64 / pixel_count as f64
        },
        block_diff: if block_count == 0 {
            0.0
        } else {
            block_total / block_count as f64
        },
        max_diff,
    })
}

/// The first file named by a `// needs: FILE` line of the scene that POV-Ray's include
/// folder (`DURER_POVRAY_INCLUDE` or /usr/share/povray-3.7/include) does not have. Such
/// scenes use files we do not redistribute, such as POV-Ray's fonts.
fn missing_povray_file(scene: &Path) -> Option<String> {
    let folder = std::env::var_os("DURER_POVRAY_INCLUDE")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/share/povray-3.7/include"));
    let source = fs::read_to_string(scene).ok()?;
    source
        .lines()
        .filter_map(|line| line.trim().strip_prefix("// needs:"))
        .map(|file| file.trim().to_string())
        .find(|file| !folder.join(file).is_file())
}

/// The scene's `// tolerance: F` override, if any; `Err` when the line is malformed.
fn tolerance_override(source: &str) -> Result<Option<f64>, String> {
    for line in source.lines() {
        let Some(comment) = line.trim_start().strip_prefix("//") else {
            continue;
        };
        let Some(rest) = comment.trim_start().strip_prefix("tolerance:") else {
            continue;
        };
        let value = rest.split_whitespace().next().unwrap_or("");
        return match value.parse::<f64>() {
            Ok(fraction) if (0.0..=1.0).contains(&fraction) => Ok(Some(fraction)),
            _ => Err(format!("bad tolerance comment `{}`", line.trim())),
        };
    }
    Ok(None)
}

/// durer's command-line options for the scene's `// povray-options:` line (none without
/// one): POV-Ray's own switches, which `durer render` takes as they are.
fn durer_options(source: &str) -> Result<Vec<String>, String> {
    let Some(line) = source
        .lines()
        .find_map(|line| line.trim().strip_prefix("// povray-options:"))
    else {
        return Ok(Vec::new());
    };
    let words: Vec<String> = line.split_whitespace().map(str::to_string).collect();
    match words
        .iter()
        .find(|w| !w.starts_with('+') && !w.starts_with('-'))
    {
        Some(word) => Err(format!("`{word}` in povray-options is not a switch")),
        None => Ok(words),
    }
}

/// The reference, darkened, with pixels over the threshold in red.
fn diff_image(reference: &RgbImage, render: &RgbImage) -> RgbImage {
    RgbImage::from_fn(reference.width(), reference.height(), |x, y| {
        let (pa, pb) = (reference.get_pixel(x, y), render.get_pixel(x, y));
        let worst = (0..3).map(|c| pa[c].abs_diff(pb[c])).max().unwrap_or(0);
        if worst > PIXEL_THRESHOLD {
            Rgb([255, 0, 0])
        } else {
            let grey = (u16::from(pa[0]) + u16::from(pa[1]) + u16::from(pa[2])) / 9;
            Rgb([grey as u8; 3])
        }
    })
}

/// One scene that did not pass.
struct Failure {
    name: String,
    tolerance: f64,
    comparison: Option<Comparison>,
    note: String,
}

/// Runs durer with a timeout; returns the first line of stderr on failure.
fn run_durer(
    scene: &Path,
    output: &Path,
    width: u32,
    height: u32,
    options: &[String],
) -> Result<(), String> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_durer"))
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(output)
        .args([
            "--width",
            &width.to_string(),
            "--height",
            &height.to_string(),
            "--quiet",
        ])
        .args(options)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|error| format!("cannot run durer: {error}"))?;
    // Drain stderr on its own thread so a chatty durer cannot block on a full pipe.
    let mut pipe = child.stderr.take().expect("stderr is piped");
    let stderr_reader = std::thread::spawn(move || {
        let mut text = String::new();
        let _ = pipe.read_to_string(&mut text);
        text
    });
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed() > RENDER_TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                let _ = stderr_reader.join();
                return Err(format!("timed out after {} s", RENDER_TIMEOUT.as_secs()));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(error) => return Err(format!("waiting for durer: {error}")),
        }
    };
    let stderr = stderr_reader.join().unwrap_or_default();
    if status.success() {
        return Ok(());
    }
    let first = stderr
        .lines()
        .map(str::trim)
        .find(|line| !line.is_empty())
        .unwrap_or("");
    Err(format!("durer {status}: {first}"))
}

/// Renders and compares one scene; its comparison when it matches.
fn check_scene(
    scene: &Path,
    reference_png: &Path,
    scratch: &Path,
    failures_dir: &Path,
) -> Result<Comparison, Failure> {
    let name = scene
        .file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned();
    let fail = |tolerance, comparison, note: String| Failure {
        name: name.clone(),
        tolerance,
        comparison,
        note,
    };
    let source = fs::read_to_string(scene).map_err(|error| {
        fail(
            DEFAULT_TOLERANCE,
            None,
            format!("cannot read scene: {error}"),
        )
    })?;
    let tolerance = tolerance_override(&source)
        .map_err(|note| fail(DEFAULT_TOLERANCE, None, note))?
        .unwrap_or(DEFAULT_TOLERANCE);
    let options = durer_options(&source).map_err(|note| fail(tolerance, None, note))?;
    let reference = image::open(reference_png)
        .map_err(|error| fail(tolerance, None, format!("cannot read reference: {error}")))?
        .to_rgb8();

    let output = scratch.join(format!("{name}.png"));
    run_durer(
        scene,
        &output,
        reference.width(),
        reference.height(),
        &options,
    )
    .map_err(|note| fail(tolerance, None, note))?;
    let render = image::open(&output)
        .map_err(|error| {
            fail(
                tolerance,
                None,
                format!("cannot read durer's image: {error}"),
            )
        })?
        .to_rgb8();
    if let Some(keep) = std::env::var_os("DURER_REFERENCE_KEEP") {
        // Best effort, like the failure images: a debugging aid.
        let _ = fs::create_dir_all(&keep);
        let _ = fs::copy(&output, Path::new(&keep).join(format!("{name}.png")));
    }

    let save_failure = |diff: Option<RgbImage>| {
        // Best effort: a debugging aid must not hide the real failure.
        let _ = fs::create_dir_all(failures_dir);
        let _ = render.save(failures_dir.join(format!("{name}.durer.png")));
        let _ = reference.save(failures_dir.join(format!("{name}.povray.png")));
        if let Some(diff) = diff {
            let _ = diff.save(failures_dir.join(format!("{name}.diff.png")));
        }
    };
    let Some(comparison) = compare(&reference, &render) else {
        save_failure(None);
        let note = format!(
            "size {}x{}, expected {}x{}",
            render.width(),
            render.height(),
            reference.width(),
            reference.height()
        );
        return Err(fail(tolerance, None, note));
    };
    if comparison.matches(tolerance) {
        return Ok(comparison);
    }
    save_failure(Some(diff_image(&reference, &render)));
    let note = if comparison.is_close() { "close" } else { "" };
    Err(fail(tolerance, Some(comparison), note.to_string()))
}

/// The `.pov` files in `dir` that have a `.png` next to them, sorted by name.
fn reference_scenes(dir: &Path) -> Vec<(PathBuf, PathBuf)> {
    let mut scenes: Vec<_> = fs::read_dir(dir)
        .expect("tests/reference exists")
        .filter_map(|entry| entry.ok().map(|entry| entry.path()))
        .filter(|path| path.extension().is_some_and(|ext| ext == "pov"))
        .map(|path| {
            let png = path.with_extension("png");
            (path, png)
        })
        .filter(|(_, png)| png.is_file())
        .collect();
    scenes.sort();
    scenes
}

fn failure_table(failures: &[Failure], total: usize, failures_dir: &Path) -> String {
    let mut table = format!(
        "{} of {total} reference scenes do not match POV-Ray\n\n\
         {:<24} {:>10} {:>8} {:>10} {:>8}  note\n",
        failures.len(),
        "scene",
        "over 24",
        "allowed",
        "block diff",
        "max diff"
    );
    for failure in failures {
        let (over, block, max) = match failure.comparison {
            Some(c) => (
                format!("{:.2}%", 100.0 * c.fraction_over),
                format!("{:.2}", c.block_diff),
                c.max_diff.to_string(),
            ),
            None => ("-".into(), "-".into(), "-".into()),
        };
        let _ = writeln!(
            table,
            "{:<24} {:>10} {:>7.2}% {:>10} {:>8}  {}",
            failure.name,
            over,
            100.0 * failure.tolerance,
            block,
            max,
            failure.note
        );
    }
    let _ = write!(
        table,
        "\nrenders and diff images: {}",
        failures_dir.display()
    );
    table
}

/// The scene's opening comment (after its `Tests:` or `NAME:` label, without the
/// `povray-options`, `tolerance` and `needs` lines) up to its first full stop, on one line.
fn scene_purpose(source: &str) -> String {
    let comment: Vec<&str> = source
        .lines()
        .map_while(|line| line.trim().strip_prefix("//"))
        .map(str::trim)
        .filter(|line| {
            !["povray-options:", "tolerance:", "needs:"]
                .iter()
                .any(|setting| line.starts_with(setting))
        })
        .collect();
    let text = comment.join(" ");
    let text = match text.split_once(": ") {
        Some((label, rest)) if !label.contains(' ') => rest,
        _ => text.as_str(),
    }
    .trim();
    let end = text.find(". ").map_or(text.len(), |stop| stop + 1);
    text[..end].replace('|', "\\|")
}

/// A markdown table of every scene's measured difference from POV-Ray.
fn results_table(outcomes: &[(&Path, Result<Comparison, Failure>)]) -> String {
    let mut table = String::from(
        "| scene | tests | pixels over 24/255 | block diff | max diff | result |\n\
         |---|---|---|---|---|---|\n",
    );
    for (scene, outcome) in outcomes {
        let name = scene.file_stem().unwrap_or_default().to_string_lossy();
        let purpose = fs::read_to_string(scene)
            .map(|source| scene_purpose(&source))
            .unwrap_or_default();
        let (comparison, result) = match outcome {
            Ok(comparison) => (Some(*comparison), "match".to_string()),
            Err(failure) => (failure.comparison, format!("FAIL {}", failure.note)),
        };
        let (over, block, max) = comparison.map_or(("-".into(), "-".into(), "-".into()), |c| {
            (
                format!("{:.2}%", 100.0 * c.fraction_over),
                format!("{:.2}", c.block_diff),
                c.max_diff.to_string(),
            )
        });
        let _ = writeln!(
            table,
            "| `{name}` | {purpose} | {over} | {block} | {max} | {} |",
            result.trim()
        );
    }
    table
}

#[test]
fn reference_images_match_povray() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let failures_dir = root.join("target").join("reference-failures");
    let _ = fs::remove_dir_all(&failures_dir);
    let filter = std::env::var("DURER_REFERENCE_FILTER").unwrap_or_default();
    let scenes: Vec<_> = reference_scenes(&root.join("tests").join("reference"))
        .into_iter()
        .filter(|(scene, _)| {
            let name = scene.file_stem().unwrap_or_default().to_string_lossy();
            name.contains(filter.as_str())
        })
        .filter(|(scene, _)| match missing_povray_file(scene) {
            Some(file) => {
                println!("skipping {}: needs POV-Ray's {file}", scene.display());
                false
            }
            None => true,
        })
        .collect();
    assert!(!scenes.is_empty(), "no reference scenes selected");

    let nanos = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let scratch =
        std::env::temp_dir().join(format!("durer-reference-{}-{nanos}", std::process::id()));
    fs::create_dir_all(&scratch).expect("create a scratch directory");

    let outcomes: Vec<(&Path, Result<Comparison, Failure>)> = scenes
        .iter()
        .map(|(scene, png)| {
            let outcome = check_scene(scene, png, &scratch, &failures_dir);
            (scene.as_path(), outcome)
        })
        .collect();
    let _ = fs::remove_dir_all(&scratch);
    if let Some(report) = std::env::var_os("DURER_REFERENCE_REPORT") {
        fs::write(&report, results_table(&outcomes)).expect("write the reference report");
    }
    let failures: Vec<Failure> = outcomes
        .into_iter()
        .filter_map(|(_, outcome)| outcome.err())
        .collect();

    println!(
        "{} of {} reference scenes match",
        scenes.len() - failures.len(),
        scenes.len()
    );
    if !failures.is_empty() {
        panic!("{}", failure_table(&failures, scenes.len(), &failures_dir));
    }
}

/// A test image with a distinct colour in every column and row.
fn pattern(width: u32, height: u32, shift: u32) -> RgbImage {
    RgbImage::from_fn(width, height, |x, y| {
        let x = x + shift;
        Rgb([
            (x * 37 % 256) as u8,
            (y * 53 % 256) as u8,
            ((x / 4 + y / 4) & 1) as u8 * 255,
        ])
    })
}

#[test]
fn identical_images_match() {
    let image = pattern(40, 30, 0);
    let comparison = compare(&image, &image).expect("same size");
    assert_eq!(
        comparison,
        Comparison {
            fraction_over: 0.0,
            block_diff: 0.0,
            max_diff: 0
        }
    );
    assert!(comparison.matches(DEFAULT_TOLERANCE));
}

#[test]
fn shifted_image_does_not_match() {
    let comparison = compare(&pattern(40, 30, 0), &pattern(40, 30, 1)).expect("same size");
    assert!(comparison.fraction_over > 0.5, "{comparison:?}");
    assert!(!comparison.matches(DEFAULT_TOLERANCE));
    assert!(!comparison.is_close());
}

#[test]
fn threshold_is_strictly_greater_than_24() {
    let base = RgbImage::from_pixel(8, 8, Rgb([100, 100, 100]));
    let at = RgbImage::from_pixel(8, 8, Rgb([124, 100, 100]));
    let over = RgbImage::from_pixel(8, 8, Rgb([100, 100, 125]));
    assert_eq!(compare(&base, &at).unwrap().fraction_over, 0.0);
    let comparison = compare(&base, &over).unwrap();
    assert_eq!(comparison.fraction_over, 1.0);
    assert_eq!(comparison.max_diff, 25);
    assert!((comparison.block_diff - 25.0 / 3.0).abs() < 1e-9);
}

#[test]
fn sparse_speckle_is_close_but_not_a_match() {
    // One pixel in every 4x4 block is off by 64 in red.
    let base = RgbImage::from_pixel(16, 16, Rgb([50, 50, 50]));
    let speckled = RgbImage::from_fn(16, 16, |x, y| {
        if x % 4 == 0 && y % 4 == 0 {
            Rgb([114, 50, 50])
        } else {
            Rgb([50, 50, 50])
        }
    });
    let comparison = compare(&base, &speckled).unwrap();
    assert!((comparison.fraction_over - 1.0 / 16.0).abs() < 1e-9);
    assert!((comparison.block_diff - 64.0 / 16.0 / 3.0).abs() < 1e-9);
    assert!(!comparison.matches(DEFAULT_TOLERANCE));
    assert!(comparison.matches(0.1));
    assert!(comparison.is_close());
}

#[test]
fn partial_edge_blocks_are_averaged_over_their_pixels() {
    // 5x5: the right column and bottom row form partial blocks.
    let base = RgbImage::from_pixel(5, 5, Rgb([0, 0, 0]));
    let bright_edge = RgbImage::from_fn(5, 5, |x, _| {
        if x == 4 {
            Rgb([30, 30, 30])
        } else {
            Rgb([0, 0, 0])
        }
    });
    let comparison = compare(&base, &bright_edge).unwrap();
    // Blocks: (0,0) 4x4 and (0,4) 4x1 unchanged; (4,0) 1x4 and (4,4) 1x1 differ by 30.
    assert!(
        (comparison.block_diff - 15.0).abs() < 1e-9,
        "{comparison:?}"
    );
    assert!((comparison.fraction_over - 5.0 / 25.0).abs() < 1e-9);
}

#[test]
fn different_sizes_do_not_compare() {
    assert!(compare(&pattern(8, 8, 0), &pattern(8, 6, 0)).is_none());
}

#[test]
fn tolerance_comment_is_read() {
    let scene = "// Tests: speckle\n// tolerance: 0.05 (glass edges speckle)\n#version 3.7;\n";
    assert_eq!(tolerance_override(scene), Ok(Some(0.05)));
    assert_eq!(
        tolerance_override("#version 3.7;\nsphere { 0, 1 }\n"),
        Ok(None)
    );
    assert!(tolerance_override("// tolerance: lots\n").is_err());
    assert!(tolerance_override("// tolerance: 2\n").is_err());
}

#[test]
fn povray_options_are_passed_to_durer_as_they_are() {
    let scene = "// povray-options: +A0.1 +AM2 +R4 -J\nsphere { 0, 1 }\n";
    assert_eq!(
        durer_options(scene).unwrap(),
        ["+A0.1", "+AM2", "+R4", "-J"]
    );
    assert!(durer_options("sphere { 0, 1 }\n").unwrap().is_empty());
    assert!(durer_options("// povray-options: +A0.3 scene.ini\n").is_err());
}

#[test]
fn scene_purpose_is_the_first_sentence_of_the_tests_comment() {
    let scene = "// Tests: a sphere | a box. More words\n// and more.\n#version 3.7;\n";
    assert_eq!(scene_purpose(scene), "a sphere \\| a box.");
    let scene =
        "// aa_method1: one line\n// povray-options: +A0.3\n// tolerance: 0.05\n#version 3.7;\n";
    assert_eq!(scene_purpose(scene), "one line");
    assert_eq!(scene_purpose("// Tests: a: b\n"), "a: b");
    assert_eq!(scene_purpose("#version 3.7;\n"), "");
}
