//! One render run: every frame of the animation (or the one image), from settings to files.
//!
//! Per frame: the scene is evaluated with that frame's clock, built, rendered (region,
//! anti-aliasing, alpha), encoded in the output format and written atomically (or to
//! standard output). A progress line per frame and a summary at the end; statistics as
//! POV-Ray's `+GS` or `--stats json`.

use super::animation::{frame_file_name, Animation, FrameClock};
use super::povray_options::Settings;
use super::{evaluate, print_diagnostics, RenderArgs};
use super::{EXIT_INTERRUPTED, EXIT_SCENE_ERROR, EXIT_USAGE};
use durer::eval::{AnimationValues, EvalOptions};
use durer::render::antialias::{Antialias, Method};
use durer::render::output::{self, FileFormat, OutputOptions};
use durer::render::{Region, RenderOptions};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Where images go.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Destination {
    /// Files named from this base (the name without the format's extension).
    Files { base: String },
    /// One path taken as it is: a device, a FIFO or a symbolic link (written through).
    Exact(PathBuf),
    /// Standard output.
    Stdout,
    /// No file (`-F`, `Output_to_File=off`).
    Nowhere,
}

/// The output format and where frames go.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct OutputPlan {
    pub(super) destination: Destination,
    pub(super) options: OutputOptions,
}

/// The format and the base name, by POV-Ray's rules: with a type given (`+F`), a name
/// ending in that type's extension loses it and any other name keeps its extension (the
/// type's is appended: `+FT +Oout.png` writes `out.png.tga`, as `povray` does); without
/// one, durer takes the format from the name's extension (PNG when it names none).
pub(super) fn output_plan(
    settings: &Settings,
    scene: &Path,
    povray_mode: bool,
) -> Result<OutputPlan, String> {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "image".into());
    let mut format = settings.file_type.unwrap_or(FileFormat::Png);
    let destination = match settings.output.as_deref() {
        _ if !settings.output_to_file => Destination::Nowhere,
        Some("-") => Destination::Stdout,
        None => {
            // POV-Ray writes to the current folder, durer's own `render` next to the scene.
            let base = if povray_mode {
                PathBuf::from(&stem)
            } else {
                scene.with_file_name(&stem)
            };
            Destination::Files {
                base: base.to_string_lossy().into_owned(),
            }
        }
        Some(name) if names_special_file(Path::new(name)) => {
            if settings.file_type.is_none() {
                if let Some(named) = FileFormat::from_extension(Path::new(name)) {
                    format = named;
                }
            }
            Destination::Exact(PathBuf::from(name))
        }
        Some(name) if name.ends_with('/') || Path::new(name).is_dir() => Destination::Files {
            base: Path::new(name).join(&stem).to_string_lossy().into_owned(),
        },
        Some(name) => {
            let base = match settings.file_type {
                Some(given) => name
                    .strip_suffix(&format!(".{}", given.extension()))
                    .unwrap_or(name)
                    .to_string(),
                None => match FileFormat::from_extension(Path::new(name)) {
                    Some(named) => {
                        format = named;
                        let path = Path::new(name);
                        path.with_extension("").to_string_lossy().into_owned()
                    }
                    None => name.to_string(),
                },
            };
            Destination::Files { base }
        }
    };
    let bits = match format {
        FileFormat::Png | FileFormat::Ppm => settings.bits_per_colour.unwrap_or(8),
        _ => 8,
    };
    let jpeg_quality = match settings.compression {
        None | Some(0) | Some(1) => 85,
        Some(q) => q.clamp(2, 100) as u8,
    };
    Ok(OutputPlan {
        destination,
        options: OutputOptions {
            format,
            bits,
            alpha: settings.alpha,
            jpeg_quality,
            file_gamma: settings.file_gamma,
        },
    })
}

/// Whether `path` is something other than a regular file or folder (a device such as
/// `/dev/stdout`, a FIFO) or a symbolic link: it is written as named, no extension added.
fn names_special_file(path: &Path) -> bool {
    std::fs::symlink_metadata(path)
        .is_ok_and(|m| m.file_type().is_symlink() || (!m.file_type().is_file() && !m.is_dir()))
}

/// A region bound in pixels from 0: `value` is a pixel number from 1, or below 1 (1 for an
/// end) a fraction of `size` (measured: `+SC0.25 +EC0.5` of 10 columns renders 2..=4).
fn region_bounds(start: Option<f64>, end: Option<f64>, size: u32) -> (u32, u32) {
    let size_f = f64::from(size);
    let first = match start {
        None => 0.0,
        Some(v) if v < 1.0 => (v * size_f).floor(),
        Some(v) => v.floor() - 1.0,
    };
    let last = match end {
        None => size_f,
        Some(v) if v <= 1.0 => (v * size_f).floor(),
        Some(v) => v.floor(),
    };
    (
        first.clamp(0.0, size_f) as u32,
        last.clamp(0.0, size_f) as u32,
    )
}

/// The region the settings ask for, `None` for the whole image.
pub(super) fn region(settings: &Settings) -> Result<Option<Region>, String> {
    if settings.start_column.is_none()
        && settings.end_column.is_none()
        && settings.start_row.is_none()
        && settings.end_row.is_none()
    {
        return Ok(None);
    }
    let (left, right) = region_bounds(settings.start_column, settings.end_column, settings.width);
    let (top, bottom) = region_bounds(settings.start_row, settings.end_row, settings.height);
    if left >= right || top >= bottom {
        return Err(format!(
            "the render region is empty: columns {} to {}, rows {} to {} of {}x{}",
            left + 1,
            right,
            top + 1,
            bottom,
            settings.width,
            settings.height
        ));
    }
    Ok(Some(Region {
        left,
        top,
        right,
        bottom,
    }))
}

/// Set by Ctrl-C.
static STOP: AtomicBool = AtomicBool::new(false);

/// Installs the Ctrl-C handler: the first press stops the render (rows not begun are
/// skipped, nothing is written); if the process has not ended two seconds later, or on a
/// second press, it exits with 130 at once (output files are only ever renamed into place,
/// so no image is half written).
fn install_interrupt_handler() {
    let _ = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(EXIT_INTERRUPTED);
        }
        durer::render::interrupt();
        std::thread::spawn(|| {
            std::thread::sleep(Duration::from_secs(2));
            eprintln!("durer: interrupted");
            std::process::exit(EXIT_INTERRUPTED);
        });
    });
}

/// The render options the settings give (size, anti-aliasing, region, alpha, quality).
pub(super) fn render_options(settings: &Settings, region: Option<Region>) -> RenderOptions {
    let antialias = settings.antialias.then_some(Antialias {
        threshold: settings.antialias_threshold,
        method: if settings.sampling_method == 2 {
            Method::Recursive
        } else {
            Method::NonRecursive
        },
        depth: settings.antialias_depth,
        jitter: if settings.jitter {
            settings.jitter_amount
        } else {
            0.0
        },
    });
    RenderOptions {
        width: settings.width,
        height: settings.height,
        antialias,
        region,
        alpha: settings.alpha,
        quality: durer::render::quality::Quality(settings.quality),
    }
}

/// What a run needs before its first frame: the scene, where images go, the frames and
/// the region (settings' warnings printed; a usage error printed and its exit code).
pub(super) struct RunPlan {
    pub(super) scene_path: PathBuf,
    pub(super) plan: OutputPlan,
    pub(super) animation: Animation,
    pub(super) region: Option<Region>,
}

pub(super) fn plan_run(settings: &Settings, povray_mode: bool) -> Result<RunPlan, i32> {
    for warning in &settings.warnings {
        if settings.streams.warning {
            eprintln!("durer: warning: {warning}");
        }
    }
    let Some(scene_path) = settings.input.clone() else {
        eprintln!(
            "durer: no scene given: name a .pov file, or give +Iscene.pov or \
             Input_File_Name in an INI file (durer --help)"
        );
        return Err(EXIT_USAGE);
    };
    let usage = |message: String| {
        eprintln!("durer: {message}");
        EXIT_USAGE
    };
    let plan = output_plan(settings, &scene_path, povray_mode).map_err(usage)?;
    let animation = Animation::plan(settings).map_err(usage)?;
    let region = region(settings).map_err(usage)?;
    Ok(RunPlan {
        scene_path,
        plan,
        animation,
        region,
    })
}

/// The render threads. Deep CSG (up to the `nesting` limit) is built and traced
/// recursively on them: they get room (reserved, used only as deep as a scene goes).
pub(super) fn render_pool(settings: &Settings) -> Result<rayon::ThreadPool, i32> {
    let mut pool = rayon::ThreadPoolBuilder::new().stack_size(durer::limits::RENDER_STACK_BYTES);
    if let Some(threads) = settings.threads {
        pool = pool.num_threads(threads.max(1));
    }
    pool.build().map_err(|error| {
        eprintln!("durer: cannot start render threads: {error}");
        EXIT_SCENE_ERROR
    })
}

/// Runs the render the settings describe; returns the exit code.
pub fn run(settings: Settings, args: &RenderArgs, povray_mode: bool) -> i32 {
    let RunPlan {
        scene_path,
        plan,
        animation,
        region,
    } = match plan_run(&settings, povray_mode) {
        Ok(run) => run,
        Err(code) => return code,
    };
    if animation.animated && plan.destination == Destination::Stdout && animation.frames.len() > 1 {
        eprintln!("durer: an animation of several frames cannot be written to standard output");
        return EXIT_USAGE;
    }
    let pool = match render_pool(&settings) {
        Ok(pool) => pool,
        Err(code) => return code,
    };
    install_interrupt_handler();
    let mut render_options = render_options(&settings, region);
    let tile = match args.tile {
        None => None,
        Some(_) if region.is_some() => {
            eprintln!("durer: --tile cannot be combined with a render region (+SR/+ER/+SC/+EC)");
            return EXIT_USAGE;
        }
        Some(spec) => match super::farm::TileJob::new(
            spec,
            &render_options,
            &plan.options,
            &tile_identity(&settings, &scene_path, &render_options, &plan.options),
            |name| std::env::var(name).ok(),
        ) {
            Ok(job) => {
                render_options.region = Some(job.region);
                Some(job)
            }
            Err(message) => {
                eprintln!("durer: {message}");
                return EXIT_USAGE;
            }
        },
    };
    let mut summary = super::stats::Summary::default();
    let start = Instant::now();
    let frame_count = animation.frames.len();
    for (index, frame) in animation.frames.iter().enumerate() {
        let frame_tile = tile.as_ref().map(|t| t.for_frame(frame));
        let file = match &plan.destination {
            Destination::Files { base } if tile.is_some() => {
                Some(PathBuf::from(super::farm::tile_file_name(
                    base,
                    settings.output.is_none(),
                    animation.animated.then_some(frame.frame_number),
                    animation.digits,
                    tile.as_ref().map_or((0, 1), |t| (t.index, t.count)),
                )))
            }
            Destination::Files { base } => Some(PathBuf::from(frame_file_name(
                base,
                animation.animated.then_some(frame.frame_number),
                animation.digits,
                plan.options.format.extension(),
            ))),
            Destination::Exact(path) => Some(path.clone()),
            _ => None,
        };
        let outcome = render_frame(
            &settings,
            &scene_path,
            frame,
            &render_options,
            &plan,
            file.as_deref(),
            &pool,
            &mut summary,
            args.format,
            frame_tile.as_ref(),
        );
        match outcome {
            FrameOutcome::Done(time) => {
                if settings.streams.render {
                    let name = file
                        .as_ref()
                        .map_or_else(|| "(no file)".to_string(), |f| f.display().to_string());
                    if animation.animated {
                        eprintln!(
                            "frame {} ({} of {frame_count}, clock {}): {name}, {}x{} in {:.3} s",
                            frame.frame_number,
                            index + 1,
                            trimmed(frame.clock),
                            settings.width,
                            settings.height,
                            time.as_secs_f64()
                        );
                    } else if plan.destination != Destination::Stdout {
                        eprintln!(
                            "{name}: {}x{} in {:.3} s (parse {:.3} s, render {:.3} s)",
                            settings.width,
                            settings.height,
                            time.as_secs_f64(),
                            summary.last_parse.as_secs_f64(),
                            summary.last_render.as_secs_f64()
                        );
                    }
                }
            }
            FrameOutcome::Failed(code) => return code,
            FrameOutcome::Interrupted => {
                let place = if animation.animated {
                    format!(
                        " at frame {} ({} of {frame_count})",
                        frame.frame_number,
                        index + 1
                    )
                } else {
                    String::new()
                };
                eprintln!("durer: interrupted{place}; no image was written for it");
                return EXIT_INTERRUPTED;
            }
        }
    }
    if animation.animated && settings.streams.render {
        eprintln!(
            "{} frames in {:.3} s",
            frame_count,
            start.elapsed().as_secs_f64()
        );
    }
    summary.total = start.elapsed();
    summary.frames = frame_count;
    // POV-Ray prints statistics unless -GS; durer's own `render` only with --stats.
    let text_stats = match args.stats.as_deref() {
        Some("text") => true,
        Some(_) => false,
        None => povray_mode && settings.streams.statistics,
    };
    if text_stats {
        eprint!("{}", summary.text());
    }
    if let Some(path) = &settings.statistics_file {
        if let Err(error) = output::write_atomic(path, summary.text().as_bytes()) {
            eprintln!(
                "durer: cannot write statistics to {}: {error}",
                path.display()
            );
        }
    }
    if args.stats.as_deref() == Some("json") {
        let json = summary.json();
        if plan.destination == Destination::Stdout {
            eprintln!("{json}");
        } else {
            println!("{json}");
        }
    }
    0
}

/// A clock value for messages: at most 6 decimals, trailing zeros dropped.
fn trimmed(value: f64) -> String {
    let text = format!("{value:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

/// What makes two renders the same render, for the fingerprint tiles carry: the scene
/// file's bytes and path, the size, anti-aliasing, alpha and quality, the output options,
/// declared constants, include header and language version. (Files the scene includes
/// are not hashed, nor where they are found: keep them the same on every worker.)
fn tile_identity(
    settings: &Settings,
    scene_path: &Path,
    render_options: &RenderOptions,
    output_options: &OutputOptions,
) -> Vec<u8> {
    let mut identity = std::fs::read(scene_path).unwrap_or_default();
    identity.extend_from_slice(
        format!(
            "|{:?}|{render_options:?}|{output_options:?}|{:?}|{:?}|{:?}",
            scene_path.file_name(),
            settings.declares,
            settings.include_header,
            settings.version
        )
        .as_bytes(),
    );
    identity
}

enum FrameOutcome {
    Done(Duration),
    Failed(i32),
    Interrupted,
}

/// The evaluation options of one frame (`file` is the image written, whose folder the
/// scene may write into).
pub(super) fn eval_options(
    settings: &Settings,
    frame: &FrameClock,
    file: Option<&Path>,
) -> EvalOptions {
    EvalOptions {
        include_paths: settings.library_paths.clone(),
        image_width: settings.width,
        image_height: settings.height,
        clock: frame.clock,
        animation: AnimationValues {
            clock_delta: frame.clock_delta,
            clock_on: frame.clock_on,
            frame_number: frame.frame_number as f64,
            initial_frame: frame.initial_frame as f64,
            final_frame: frame.final_frame as f64,
            initial_clock: frame.initial_clock,
            final_clock: frame.final_clock,
        },
        defines: settings.declares.clone(),
        include_header: settings.include_header.clone(),
        initial_version: settings.version,
        print_debug: settings.streams.debug,
        output_folder: file.and_then(Path::parent).map(Path::to_path_buf),
        search_installed_povray: true,
        file_policy: settings.file_policy.clone(),
        limits: settings.limits,
        ..EvalOptions::default()
    }
}

#[allow(clippy::too_many_arguments)]
fn render_frame(
    settings: &Settings,
    scene_path: &Path,
    frame: &FrameClock,
    render_options: &RenderOptions,
    plan: &OutputPlan,
    file: Option<&Path>,
    pool: &rayon::ThreadPool,
    summary: &mut super::stats::Summary,
    format: super::diagnostic_format::Format,
    tile: Option<&super::farm::TileJob>,
) -> FrameOutcome {
    let start = Instant::now();
    let options = eval_options(settings, frame, file);
    let evaluated = evaluate(scene_path, options);
    let warnings = settings.streams.warning && settings.warning_level > 0;
    let image_to_stdout = settings.output.as_deref() == Some("-");
    let failed = print_diagnostics(&evaluated, warnings, format, image_to_stdout);
    let Some(mut scene) = evaluated.scene.filter(|_| !failed) else {
        return FrameOutcome::Failed(EXIT_SCENE_ERROR);
    };
    let parse_time = start.elapsed();
    let show_progress = settings.streams.render && std::io::stderr().is_terminal();
    let bar = show_progress.then(|| {
        let bar = indicatif::ProgressBar::new(u64::from(render_options.height));
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} rendering [{bar:40}] {pos}/{len} rows {eta}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let render_start = Instant::now();
    super::stats::reset(pool);
    let objects = std::mem::take(&mut scene.objects);
    let object_count = objects.len();
    let (image, build_time) = pool.install(|| {
        let build_start = Instant::now();
        let world = durer::geometry::World::build_from_objects(objects);
        let build_time = build_start.elapsed();
        let image = durer::render::render_image(&scene, &world, render_options, &|rows| {
            if let Some(bar) = &bar {
                bar.inc(u64::from(rows));
            }
        });
        (image, build_time)
    });
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let render_time = render_start.elapsed();
    summary.threads = pool.current_num_threads();
    summary.add_frame(
        super::stats::collect(pool),
        object_count,
        scene.lights.len(),
        parse_time,
        build_time,
        render_time.saturating_sub(build_time),
    );
    let Some(image) = image else {
        return FrameOutcome::Interrupted;
    };
    if durer::render::interrupted() {
        return FrameOutcome::Interrupted;
    }
    let write_start = Instant::now();
    if plan.destination != Destination::Nowhere {
        let encoded = match tile {
            Some(tile) => tile.encode(&image, &plan.options),
            None => output::encode(&image, &plan.options),
        };
        let bytes = match encoded {
            Ok(bytes) => bytes,
            Err(error) => {
                eprintln!("durer: cannot encode the image: {error}");
                return FrameOutcome::Failed(EXIT_SCENE_ERROR);
            }
        };
        let written = match file {
            Some(path) => {
                output::write_atomic(path, &bytes).map_err(|e| (path.display().to_string(), e))
            }
            None => {
                let mut stdout = std::io::stdout().lock();
                stdout
                    .write_all(&bytes)
                    .and_then(|()| stdout.flush())
                    .map_err(|e| ("standard output".to_string(), e))
            }
        };
        if let Err((name, error)) = written {
            eprintln!("durer: cannot write {name}: {error}");
            return FrameOutcome::Failed(EXIT_SCENE_ERROR);
        }
    }
    summary.write += write_start.elapsed();
    FrameOutcome::Done(start.elapsed())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan_for(output: Option<&str>, file_type: Option<FileFormat>) -> OutputPlan {
        let mut settings = Settings::povray_defaults();
        settings.output = output.map(str::to_string);
        settings.file_type = file_type;
        output_plan(&settings, Path::new("dir/scene.pov"), true).unwrap()
    }

    fn base(plan: &OutputPlan) -> String {
        match &plan.destination {
            Destination::Files { base } => base.clone(),
            other => format!("{other:?}"),
        }
    }

    // The names povray 3.7 wrote for each case.
    #[test]
    fn output_names_as_povray() {
        assert_eq!(base(&plan_for(None, None)), "scene");
        assert_eq!(base(&plan_for(Some("out"), None)), "out");
        let plan = plan_for(Some("out.tga"), Some(FileFormat::Png));
        assert_eq!(base(&plan), "out.tga", "povray writes out.tga.png");
        let plan = plan_for(Some("out.png"), Some(FileFormat::Tga));
        assert_eq!(base(&plan), "out.png");
        assert_eq!(plan.options.format.extension(), "tga");
        let plan = plan_for(Some("a.b.png"), Some(FileFormat::Png));
        assert_eq!(base(&plan), "a.b");
        // Without +F, durer takes the format from the extension.
        let plan = plan_for(Some("out.exr"), None);
        assert_eq!(base(&plan), "out");
        assert_eq!(plan.options.format, FileFormat::Exr);
        assert_eq!(plan_for(Some("-"), None).destination, Destination::Stdout);
    }

    #[test]
    fn regions_in_pixels_and_fractions() {
        // +SC2 +EC5 of 8 columns: 1-based 2..=5.
        assert_eq!(region_bounds(Some(2.0), Some(5.0), 8), (1, 5));
        // +SC0.25 +EC0.5 of 10 columns: 0-based 2..=4.
        assert_eq!(region_bounds(Some(0.25), Some(0.5), 10), (2, 5));
        assert_eq!(region_bounds(None, Some(1.0), 10), (0, 10));
        assert_eq!(region_bounds(Some(0.5), None, 10), (5, 10));
    }
}
