//! Command-line interface: `durer render` and `durer check`.
//!
//! Exit codes: 0 success, 1 scene error, 2 usage error (clap's own code for bad flags).

use clap::{Args, Parser, Subcommand};
use durer::diag::Severity;
use durer::eval::{evaluate_file, EvalOptions, Evaluated};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Stack size of the thread that evaluates scenes: deep macro recursion needs room.
const EVALUATION_STACK_BYTES: usize = 1 << 30;

#[derive(Parser)]
#[command(
    name = "durer",
    version,
    about = "Render POV-Ray 3.7 scenes with a recursive ray tracer"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene to a PNG image.
    Render(RenderArgs),
    /// Parse and evaluate a scene without rendering; print diagnostics and a summary.
    Check(SceneArgs),
}

#[derive(Args)]
struct SceneArgs {
    /// The scene file (.pov).
    scene: PathBuf,
    /// Add a folder to the #include search path (repeatable).
    #[arg(short = 'L', long = "library", value_name = "DIR")]
    include_paths: Vec<PathBuf>,
    /// Image width seen by the scene as `image_width`.
    #[arg(long, default_value_t = 320)]
    width: u32,
    /// Image height seen by the scene as `image_height`.
    #[arg(long, default_value_t = 240)]
    height: u32,
}

#[derive(Args)]
struct RenderArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// Output PNG (default: the scene's path with `.png`).
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Number of render threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
    #[command(flatten)]
    antialias: AntialiasArgs,
}

/// Anti-aliasing options, as POV-Ray's `+A`, `+AM`, `+R` and `+J`.
#[derive(Args)]
struct AntialiasArgs {
    /// Turn anti-aliasing on: supersample pixels differing from a neighbour by more than
    /// THRESHOLD (0 to 3; without a value 0.3, as POV-Ray's +A).
    #[arg(long, value_name = "THRESHOLD", value_parser = parse_threshold,
          num_args = 0..=1, default_missing_value = "0.3")]
    antialias: Option<f64>,
    /// Supersampling method: 1 non-recursive grid, 2 recursive (POV-Ray's +AM).
    #[arg(long, value_name = "1|2", value_parser = clap::value_parser!(u32).range(1..=2),
          requires = "antialias")]
    aa_method: Option<u32>,
    /// Grid size (method 1) or recursion depth (method 2), 1 to 9 (POV-Ray's +R; default 3).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=9),
          requires = "antialias")]
    aa_depth: Option<u32>,
    /// Jitter of the supersamples, 0 (off) to 1 (POV-Ray's +J; default 1).
    #[arg(long, value_name = "AMOUNT", value_parser = parse_jitter, requires = "antialias")]
    jitter: Option<f64>,
}

impl AntialiasArgs {
    /// The anti-aliasing asked for; the method, depth and jitter alone do not turn it on.
    fn options(&self) -> Option<durer::render::antialias::Antialias> {
        use durer::render::antialias::{Antialias, Method};
        let threshold = self.antialias?;
        let defaults = Antialias::default();
        Some(Antialias {
            threshold,
            method: match self.aa_method {
                Some(2) => Method::Recursive,
                _ => Method::NonRecursive,
            },
            depth: self.aa_depth.unwrap_or(defaults.depth),
            jitter: self.jitter.unwrap_or(defaults.jitter),
        })
    }
}

/// A float from `text` within `range`, or a message naming the range.
fn parse_float_in(text: &str, range: std::ops::RangeInclusive<f64>) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(value) if range.contains(&value) => Ok(value),
        _ => Err(format!(
            "expected a number from {} to {}",
            range.start(),
            range.end()
        )),
    }
}

/// `--antialias`: a threshold from 0 to 3.
fn parse_threshold(text: &str) -> Result<f64, String> {
    parse_float_in(text, 0.0..=3.0)
}

/// `--jitter`: an amount from 0 to 1.
fn parse_jitter(text: &str) -> Result<f64, String> {
    parse_float_in(text, 0.0..=1.0)
}

/// Runs the command line and returns the process exit code.
pub fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => {
            let _ = error.print();
            return if error.use_stderr() { 2 } else { 0 };
        }
    };
    match cli.command {
        Command::Render(args) => render(args),
        Command::Check(args) => check(args),
    }
}

fn eval_options(args: &SceneArgs, output: Option<&Path>) -> EvalOptions {
    EvalOptions {
        include_paths: args.include_paths.clone(),
        image_width: args.width,
        image_height: args.height,
        clock: 0.0,
        output_folder: output.and_then(Path::parent).map(Path::to_path_buf),
        search_installed_povray: true,
    }
}

/// Evaluates on a thread with a large stack, so deep recursion cannot overflow.
fn evaluate(path: &Path, options: EvalOptions) -> Evaluated {
    let path = path.to_path_buf();
    let worker = std::thread::Builder::new()
        .stack_size(EVALUATION_STACK_BYTES)
        .spawn(move || evaluate_file(&path, &options));
    match worker.map(|handle| handle.join()) {
        Ok(Ok(evaluated)) => evaluated,
        _ => {
            eprintln!("durer: internal error while evaluating the scene");
            std::process::exit(1);
        }
    }
}

fn print_diagnostics(evaluated: &Evaluated, quiet: bool) -> bool {
    let mut failed = false;
    let colour = std::io::stderr().is_terminal();
    for diagnostic in &evaluated.diagnostics {
        if diagnostic.severity == Severity::Error {
            failed = true;
        } else if quiet {
            continue;
        }
        let report = durer::report::to_report(diagnostic, &evaluated.sources);
        if colour {
            eprintln!("{:?}", miette::Report::new(report));
        } else {
            eprint!(
                "{}",
                durer::report::render_plain(diagnostic, &evaluated.sources)
            );
        }
    }
    failed
}

fn check(args: SceneArgs) -> i32 {
    let start = Instant::now();
    let evaluated = evaluate(&args.scene, eval_options(&args, None));
    let failed = print_diagnostics(&evaluated, false);
    let Some(mut scene) = evaluated.scene.filter(|_| !failed) else {
        return 1;
    };
    let object_count = scene.objects.len();
    let world = durer::geometry::World::build_from_objects(std::mem::take(&mut scene.objects));
    println!(
        "{}: ok, {} objects ({} primitives), {} lights, {:.3} s",
        args.scene.display(),
        object_count,
        world.object_count(),
        scene.lights.len(),
        start.elapsed().as_secs_f64()
    );
    0
}

fn render(args: RenderArgs) -> i32 {
    let start = Instant::now();
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| args.scene.scene.with_extension("png"));
    let evaluated = evaluate(&args.scene.scene, eval_options(&args.scene, Some(&output)));
    let failed = print_diagnostics(&evaluated, args.quiet);
    let Some(mut scene) = evaluated.scene.filter(|_| !failed) else {
        return 1;
    };
    let parse_time = start.elapsed();

    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(threads) = args.threads {
        pool = pool.num_threads(threads.max(1));
    }
    let pool = match pool.build() {
        Ok(pool) => pool,
        Err(error) => {
            eprintln!("durer: cannot start render threads: {error}");
            return 1;
        }
    };
    let render_start = Instant::now();
    let options = durer::render::RenderOptions {
        width: args.scene.width.max(1),
        height: args.scene.height.max(1),
        antialias: args.antialias.options(),
    };
    let show_progress = !args.quiet && std::io::stderr().is_terminal();
    let bar = show_progress.then(|| {
        let bar = indicatif::ProgressBar::new(u64::from(options.height));
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} rendering [{bar:40}] {pos}/{len} rows {eta}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let image = pool.install(|| {
        let objects = std::mem::take(&mut scene.objects);
        let world = durer::geometry::World::build_from_objects(objects);
        durer::render::render(&scene, &world, &options, &|rows| {
            if let Some(bar) = &bar {
                bar.inc(u64::from(rows));
            }
        })
    });
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    if let Err(error) = durer::render::write_png_atomic(&output, &image) {
        eprintln!("durer: cannot write {}: {error}", output.display());
        return 1;
    }
    if !args.quiet {
        eprintln!(
            "{}: {}x{} in {:.3} s (parse {:.3} s, render {:.3} s)",
            output.display(),
            options.width,
            options.height,
            start.elapsed().as_secs_f64(),
            parse_time.as_secs_f64(),
            render_start.elapsed().as_secs_f64()
        );
    }
    0
}
