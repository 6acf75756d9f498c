//! Command-line interface: `durer render`, `durer check`, and POV-Ray's own command line
//! (`durer +Iscene.pov +W640 +H480`, `durer scene.ini[Section]`).
//!
//! `render` takes durer's flags and POV-Ray's `+`/`-` switches and `.ini` files mixed
//! ([`povray_options`]); durer's flags win over POV-Ray options. A command line that does
//! not start with a subcommand is read as POV-Ray reads its own: POV-Ray's defaults (160 x
//! 120), its default INI file (`$POVINI`, `./povray.ini`, `~/.povray/3.7/povray.ini`,
//! `/etc/povray/3.7/povray.ini`), then the words in order.
//!
//! Exit codes: 0 success, 1 scene error (or a file that cannot be written), 2 usage error,
//! 130 interrupted (Ctrl-C: the render stops, the previous image is left as it was).

mod animation;
mod diagnostic_format;
mod expand;
mod farm;
mod lsp;
mod povray_options;
mod render_job;
mod stats;
mod watch;

use clap::{Args, Parser, Subcommand};
use durer::diag::Severity;
use durer::eval::{evaluate_file, EvalOptions, Evaluated};
use povray_options::{OptionReader, Origin, Settings};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

use durer::limits::{EVALUATION_STACK_BYTES, RENDER_STACK_BYTES};

/// Exit code of a scene error.
pub const EXIT_SCENE_ERROR: i32 = 1;
/// Exit code of a usage error.
pub const EXIT_USAGE: i32 = 2;
/// Exit code after Ctrl-C (128 + SIGINT, as shells report it).
pub const EXIT_INTERRUPTED: i32 = 130;

const AFTER_HELP: &str = "\
POV-Ray's command line works too: `durer +Iscene.pov +W640 +H480 +A0.3 +FN16 +UA`,
`durer scene.ini[Section] +KFF24`, and such switches and .ini files may follow `durer render`.
Exit codes: 0 success, 1 scene error or unwritable output, 2 usage error, 130 interrupted
(Ctrl-C stops the render and leaves the previous image intact).";

#[derive(Parser)]
#[command(
    name = "durer",
    version,
    about = "Render POV-Ray 3.7 scenes with a recursive ray tracer",
    after_help = AFTER_HELP
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene (or an animation) to image files.
    Render(RenderArgs),
    /// Parse and evaluate a scene without rendering; print diagnostics and a summary.
    Check(SceneArgs),
    /// Write the evaluated scene as flat POV-Ray SDL (no macros, loops, includes or
    /// identifiers); takes render's options; `-o FLAT.pov` (default: standard output).
    Expand(RenderArgs),
    /// Render, then render again whenever the scene or a file it read changes (a quick
    /// preview first, then the full image); takes render's options, and `--serve [ADDR]`
    /// for a live preview page (default 127.0.0.1:8181).
    Watch(RenderArgs),
    /// Run a Language Server Protocol server on standard input and output (for editors).
    Lsp,
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
    /// Declare an identifier before the scene is read: NAME=EXPR, any SDL value
    /// (`--define Size=2`, `--define 'Colour=<1,0,0>'`, `--define 'Name="text"'`).
    #[arg(long = "define", value_name = "NAME=EXPR")]
    defines: Vec<String>,
    /// How diagnostics are printed: `human`, `json` (one object per line on standard
    /// output) or `sarif` (a SARIF 2.1.0 log on standard output).
    #[arg(long, value_enum, default_value = "human")]
    format: diagnostic_format::Format,
    #[command(flatten)]
    safety: SafetyArgs,
}

/// Limits and the file policy (docs/limits.md).
#[derive(Args)]
struct SafetyArgs {
    /// Set a limit: NAME=VALUE (repeatable; `--limit help` lists the limits and their
    /// defaults).
    #[arg(long = "limit", value_name = "NAME=VALUE")]
    limits: Vec<String>,
    /// Let the scene read files in DIR and its subfolders (repeatable).
    #[arg(long = "allow-read", value_name = "DIR")]
    allow_read: Vec<PathBuf>,
    /// Let the scene read and write files in DIR and its subfolders (repeatable).
    #[arg(long = "allow-write", value_name = "DIR")]
    allow_write: Vec<PathBuf>,
    /// Read the file policy from a povray.conf (POV-Ray for Unix's I/O restrictions: its
    /// security level replaces durer's `restricted` and its folders are added).
    #[arg(long = "file-policy", value_name = "FILE")]
    file_policy: Option<PathBuf>,
}

/// The limits and file policy the safety flags give; `Ok(None)` after `--limit help`.
fn safety_settings(
    args: &SafetyArgs,
) -> Result<Option<(durer::limits::Limits, durer::file_policy::FilePolicy)>, String> {
    use durer::file_policy::{FilePolicy, Reach};
    let mut limits = durer::limits::Limits::default();
    for assignment in &args.limits {
        if assignment == "help" {
            print!("{}", durer::limits::table());
            return Ok(None);
        }
        limits.set(assignment).map_err(|e| e.to_string())?;
    }
    let mut policy = FilePolicy::default();
    if let Some(conf) = &args.file_policy {
        let text = std::fs::read_to_string(conf)
            .map_err(|e| format!("--file-policy {}: {e}", conf.display()))?;
        let current = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("/"));
        let home = std::env::var_os("HOME").map(PathBuf::from);
        policy.read_conf(
            &text,
            &conf.display().to_string(),
            &current,
            Path::new("/usr/share/povray-3.7"),
            home.as_deref(),
        )?;
    }
    for folder in &args.allow_read {
        policy.allow(folder, false, Reach::Tree, "--allow-read");
    }
    for folder in &args.allow_write {
        policy.allow(folder, true, Reach::Tree, "--allow-write");
    }
    Ok(Some((limits, policy)))
}

#[derive(Args)]
#[command(after_help = AFTER_HELP)]
struct RenderArgs {
    /// The scene file (.pov); or give it with +I or Input_File_Name in an .ini file.
    scene: Option<PathBuf>,
    /// Add a folder to the #include search path (repeatable).
    #[arg(short = 'L', long = "library", value_name = "DIR")]
    include_paths: Vec<PathBuf>,
    /// Image width in pixels (default 320).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65535))]
    width: Option<u32>,
    /// Image height in pixels (default 240).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65535))]
    height: Option<u32>,
    /// Declare an identifier before the scene is read: NAME=EXPR, any SDL value.
    #[arg(long = "define", value_name = "NAME=EXPR")]
    defines: Vec<String>,
    /// How diagnostics are printed: `human`, `json` (one object per line) or `sarif` (a
    /// SARIF 2.1.0 log), on standard output unless the image goes there (`-o -`).
    #[arg(long, value_enum, default_value = "human")]
    format: diagnostic_format::Format,
    /// Output file (default: the scene's path with the format's extension); its extension
    /// chooses the format unless +F does (png, tga, bmp, ppm, jpg, exr, hdr); `-` writes
    /// the image to standard output.
    #[arg(short, long, value_name = "FILE")]
    output: Option<String>,
    /// Number of render threads, 1 to the `threads` limit, 512 (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    threads: Option<u32>,
    /// Print nothing but errors.
    #[arg(short, long)]
    quiet: bool,
    /// Largest image, in pixels, durer agrees to render (default 40,000,000: about
    /// 100 bytes of memory per pixel); raise it for larger images (= --limit pixels=N).
    #[arg(long, value_name = "N")]
    max_pixels: Option<u64>,
    /// Render the animation frames A to B (POV-Ray's +KFI A +KFF B).
    #[arg(long, value_name = "A..B", value_parser = parse_frame_range)]
    frames: Option<(i64, i64)>,
    /// Render only frame N of the animation (POV-Ray's +SF N +EF N).
    #[arg(long, value_name = "N")]
    frame: Option<i64>,
    /// The value of `clock` for a single frame (POV-Ray's +K).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    clock: Option<f64>,
    /// Render only tile I of an even split into N tiles (0 <= I < N), written as a `.tile`
    /// file for `durer merge`; `auto/N` takes I from SLURM_ARRAY_TASK_ID,
    /// JOB_COMPLETION_INDEX or PARALLEL_SEQ (minus 1), first found wins (docs/farm.md).
    #[arg(long, value_name = "I/N", value_parser = farm::parse_tile)]
    tile: Option<farm::TileSpec>,
    /// Print render statistics at the end: `text` (as POV-Ray's +GS) or `json` (on
    /// standard output, for scripts).
    #[arg(long, value_name = "text|json", num_args = 0..=1, default_missing_value = "text",
          value_parser = ["text", "json"])]
    stats: Option<String>,
    #[command(flatten)]
    antialias: AntialiasArgs,
    #[command(flatten)]
    safety: SafetyArgs,
    /// POV-Ray switches and .ini files (collected from the command line).
    #[arg(skip)]
    povray_words: Vec<String>,
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

/// `--frames A..B`.
fn parse_frame_range(text: &str) -> Result<(i64, i64), String> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| "expected A..B, such as 1..24".to_string())?;
    let a: i64 = a.trim().parse().map_err(|_| "A must be a whole number")?;
    let b: i64 = b.trim().parse().map_err(|_| "B must be a whole number")?;
    if b < a || a < 0 {
        return Err("expected 0 <= A <= B".into());
    }
    Ok((a, b))
}

/// Durer's flags that take a value in the next word.
const VALUE_FLAGS: &[&str] = &[
    "-o",
    "--output",
    "-L",
    "--library",
    "--width",
    "--height",
    "--threads",
    "--define",
    "--frames",
    "--tile",
    "--frame",
    "--clock",
    "--aa-method",
    "--aa-depth",
    "--jitter",
    "--limit",
    "--allow-read",
    "--allow-write",
    "--file-policy",
    "--max-pixels",
    "--format",
];

/// Whether `word` is a POV-Ray switch rather than one of durer's flags: it starts with `+`,
/// or with a single `-` followed by a letter, and is not `-o`, `-L`, `-q`, `-h` (durer's
/// short flags, whose POV-Ray namesakes mean the same or are written in upper case).
fn is_povray_switch(word: &str) -> bool {
    if word.starts_with('+') && word.len() > 1 {
        return true;
    }
    let Some(rest) = word.strip_prefix('-') else {
        return false;
    };
    if rest.starts_with('-') || rest.is_empty() {
        return false;
    }
    !(rest.starts_with('o') || rest.starts_with('L') || rest == "q" || rest == "h")
}

/// Splits `render`'s words into durer's flags (for clap) and POV-Ray's words, keeping each
/// list's order.
fn split_words(words: &[String], povray_mode: bool) -> (Vec<String>, Vec<String>) {
    let mut durer = Vec::new();
    let mut povray = Vec::new();
    let mut index = 0;
    while index < words.len() {
        let word = &words[index];
        index += 1;
        if VALUE_FLAGS.contains(&word.as_str()) {
            durer.push(word.clone());
            if let Some(value) = words.get(index) {
                durer.push(value.clone());
                index += 1;
            }
        } else if word == "--antialias" || word == "--stats" {
            durer.push(word.clone());
            let takes = |next: &str| {
                if word == "--stats" {
                    next == "text" || next == "json"
                } else {
                    next.parse::<f64>().is_ok()
                }
            };
            if let Some(value) = words.get(index).filter(|next| takes(next)) {
                durer.push(value.clone());
                index += 1;
            }
        } else if is_povray_switch(word)
            || povray_options::looks_like_ini(word)
            || povray_options::looks_like_key(word)
        {
            povray.push(word.clone());
        } else if povray_mode && !word.starts_with('-') && !looks_like_scene(word) {
            // POV-Ray reads a bare word as an INI file (`povray myopts` reads myopts.ini).
            povray.push(word.clone());
        } else {
            durer.push(word.clone());
        }
    }
    (durer, povray)
}

/// A word naming a scene file rather than an INI file.
fn looks_like_scene(word: &str) -> bool {
    let lower = word.to_ascii_lowercase();
    lower.ends_with(".pov") || lower.ends_with(".inc") || lower.ends_with(".mcr")
}

/// Runs the command line and returns the process exit code.
pub fn run() -> i32 {
    // The global pool (scene checks, the language's `trace`) builds deep CSG too.
    let _ = rayon::ThreadPoolBuilder::new()
        .stack_size(RENDER_STACK_BYTES)
        .build_global();
    let words: Vec<String> = std::env::args_os()
        .skip(1)
        .map(|w| w.to_string_lossy().into_owned())
        .collect();
    match words.first().map(String::as_str) {
        Some("render") => render_command(&words[1..], false),
        Some("expand") => match parse_render_args(&words[1..], false) {
            Ok((settings, args)) => expand::run(settings, args.format),
            Err(code) => code,
        },
        Some("merge") => farm::merge_command(&words[1..]),
        Some("watch") => {
            let mut words = words[1..].to_vec();
            let serve = watch::take_serve_option(&mut words);
            match parse_render_args(&words, false) {
                Ok((settings, _)) => watch::run(settings, serve),
                Err(code) => code,
            }
        }
        // `-V` alone is the version (POV-Ray's `-V`, verbose off, needs a scene with it).
        Some("-V") if words.len() == 1 => {
            println!("durer {}", env!("CARGO_PKG_VERSION"));
            0
        }
        Some("lsp") if words.len() == 1 => lsp::run(),
        Some("check") | Some("help") | Some("--help") | Some("-h") | Some("--version") | None => {
            match Cli::try_parse() {
                Ok(Cli {
                    command: Command::Check(args),
                }) => check(args),
                Ok(Cli {
                    command: Command::Render(_) | Command::Expand(_) | Command::Watch(_),
                }) => render_command(&words[1..], false),
                Ok(Cli {
                    command: Command::Lsp,
                }) => lsp::run(),
                Err(error) => {
                    let _ = error.print();
                    if error.use_stderr() {
                        EXIT_USAGE
                    } else {
                        0
                    }
                }
            }
        }
        Some(_) => render_command(&words, true),
    }
}

/// `durer render ...` (or POV-Ray's command line when `povray_mode`).
fn render_command(words: &[String], povray_mode: bool) -> i32 {
    match parse_render_args(words, povray_mode) {
        Ok((settings, args)) => render_job::run(settings, &args, povray_mode),
        Err(code) => code,
    }
}

/// `render`'s words read into settings and the parsed flags.
fn parse_render_args(words: &[String], povray_mode: bool) -> Result<(Settings, RenderArgs), i32> {
    let (durer_words, povray_words) = split_words(words, povray_mode);
    #[derive(Parser)]
    #[command(name = "durer render", after_help = AFTER_HELP)]
    struct RenderCli {
        #[command(flatten)]
        args: RenderArgs,
    }
    let mut args = match RenderCli::try_parse_from(
        std::iter::once("durer render".to_string()).chain(durer_words),
    ) {
        Ok(cli) => cli.args,
        Err(error) => {
            let _ = error.print();
            return Err(if error.use_stderr() { EXIT_USAGE } else { 0 });
        }
    };
    args.povray_words = povray_words;
    if args.safety.limits.iter().any(|l| l == "help") {
        print!("{}", durer::limits::table());
        return Err(0);
    }
    match settings_for(&args, povray_mode) {
        Ok(settings) => Ok((settings, args)),
        Err(message) => {
            eprintln!("durer: {message}");
            Err(EXIT_USAGE)
        }
    }
}

/// The settings of a render: defaults, default INI (POV-Ray mode), POV-Ray words in order,
/// then durer's flags.
fn settings_for(args: &RenderArgs, povray_mode: bool) -> Result<Settings, String> {
    let mut defaults = Settings::povray_defaults();
    if !povray_mode {
        defaults.width = 320;
        defaults.height = 240;
    }
    let mut reader = OptionReader::new(defaults);
    if povray_mode {
        if let Some(ini) = povray_options::default_ini() {
            let origin = Origin {
                place: "default INI".into(),
            };
            reader
                .ini(&ini.to_string_lossy(), &origin)
                .map_err(|e| e.to_string())?;
        }
    }
    let origin = Origin {
        place: "command line".into(),
    };
    for word in &args.povray_words {
        let result = if word.starts_with('+') || word.starts_with('-') {
            reader.switch(word, &origin)
        } else if let Some((key, value)) = word
            .split_once('=')
            .filter(|_| povray_options::looks_like_key(word))
        {
            // POV-Ray takes INI options on its command line too (`Declare=Size=2`).
            reader.key(key, value, &origin)
        } else {
            reader.ini(word, &origin)
        };
        result.map_err(|e| e.to_string())?;
    }
    let mut settings = reader.settings;
    if let Some(scene) = &args.scene {
        settings.input = Some(scene.clone());
    }
    settings
        .library_paths
        .extend(args.include_paths.iter().cloned());
    if let Some(width) = args.width {
        settings.width = width;
    }
    if let Some(height) = args.height {
        settings.height = height;
    }
    for define in &args.defines {
        settings.declares.push(parse_define(define)?);
    }
    if let Some(output) = &args.output {
        settings.output = Some(output.clone());
    }
    if let Some(threads) = args.threads {
        settings.threads = Some(threads as usize);
    }
    if let Some((limits, policy)) = safety_settings(&args.safety)? {
        settings.limits = limits;
        settings.file_policy = policy;
    }
    if let Some(pixels) = args.max_pixels {
        settings.limits.pixels = pixels;
    }
    let pixels = u64::from(settings.width) * u64::from(settings.height);
    if pixels > settings.limits.pixels {
        return Err(format!(
            "an image of {}x{} is {pixels} pixels, more than the `pixels` limit of {} (about \
             100 bytes of memory each); give --limit pixels={pixels} to render it anyway",
            settings.width, settings.height, settings.limits.pixels
        ));
    }
    if let Some(threads) = settings.threads {
        if threads as u64 > settings.limits.threads {
            return Err(format!(
                "{threads} render threads are more than the `threads` limit of {}; give \
                 --limit threads={threads} to use them anyway",
                settings.limits.threads
            ));
        }
    }
    if args.quiet {
        settings.streams.render = false;
        settings.streams.warning = false;
        settings.streams.statistics = false;
        settings.streams.debug = false;
    }
    if let Some(threshold) = args.antialias.antialias {
        settings.antialias = true;
        settings.antialias_threshold = threshold;
        if let Some(method) = args.antialias.aa_method {
            settings.sampling_method = method;
        }
        if let Some(depth) = args.antialias.aa_depth {
            settings.antialias_depth = depth;
        }
        if let Some(jitter) = args.antialias.jitter {
            settings.jitter = jitter > 0.0;
            settings.jitter_amount = jitter;
        }
    }
    if let Some((first, last)) = args.frames {
        settings.initial_frame = Some(first);
        settings.final_frame = Some(last);
    }
    if let Some(frame) = args.frame {
        if settings.final_frame.is_none() {
            return Err("--frame N needs an animation: give --frames A..B or +KFF".into());
        }
        settings.subset_start = Some(frame as f64);
        settings.subset_end = Some(frame as f64);
    }
    if let Some(clock) = args.clock {
        settings.clock = Some(clock);
    }
    Ok(settings)
}

/// `--define NAME=EXPR`.
fn parse_define(text: &str) -> Result<(String, String), String> {
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| format!("--define `{text}`: expected NAME=EXPR"))?;
    let name = name.trim();
    let valid = name
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid || value.trim().is_empty() {
        return Err(format!(
            "--define `{text}`: expected NAME=EXPR with an identifier and a value"
        ));
    }
    Ok((name.to_string(), value.trim().to_string()))
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
            std::process::exit(EXIT_SCENE_ERROR);
        }
    }
}

/// Prints the diagnostics (warnings only when `warnings`) in `format`, machine formats on
/// standard output unless `to_stderr`; true when one is an error.
fn print_diagnostics(
    evaluated: &Evaluated,
    warnings: bool,
    format: diagnostic_format::Format,
    to_stderr: bool,
) -> bool {
    let failed = evaluated
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error);
    let shown: Vec<&durer::diag::Diagnostic> = evaluated
        .diagnostics
        .iter()
        .filter(|d| warnings || d.severity == Severity::Error)
        .collect();
    if format != diagnostic_format::Format::Human {
        let text = diagnostic_format::machine_text(format, &shown, &evaluated.sources);
        if to_stderr {
            eprint!("{text}");
        } else {
            print!("{text}");
        }
        return failed;
    }
    let colour = std::io::stderr().is_terminal();
    for diagnostic in shown {
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
    let mut defines = Vec::new();
    for define in &args.defines {
        match parse_define(define) {
            Ok(define) => defines.push(define),
            Err(message) => {
                eprintln!("durer: {message}");
                return EXIT_USAGE;
            }
        }
    }
    let (limits, file_policy) = match safety_settings(&args.safety) {
        Ok(Some(safety)) => safety,
        Ok(None) => return 0,
        Err(message) => {
            eprintln!("durer: {message}");
            return EXIT_USAGE;
        }
    };
    let options = EvalOptions {
        include_paths: args.include_paths.clone(),
        image_width: args.width,
        image_height: args.height,
        defines,
        limits,
        file_policy,
        ..EvalOptions::default()
    };
    let evaluated = evaluate(&args.scene, options);
    let failed = print_diagnostics(&evaluated, true, args.format, false);
    let Some(mut scene) = evaluated.scene.filter(|_| !failed) else {
        return EXIT_SCENE_ERROR;
    };
    let object_count = scene.objects.len();
    let objects = std::mem::take(&mut scene.objects);
    // Built (and dropped) on a thread with a large stack: deep CSG recurses.
    let primitives = std::thread::Builder::new()
        .stack_size(EVALUATION_STACK_BYTES)
        .spawn(move || durer::geometry::World::build_from_objects(objects).object_count())
        .map(|handle| handle.join());
    let Ok(Ok(primitives)) = primitives else {
        eprintln!("durer: internal error while building the scene's geometry");
        return EXIT_SCENE_ERROR;
    };
    let summary = format!(
        "{}: ok, {} objects ({} primitives), {} lights, {:.3} s",
        args.scene.display(),
        object_count,
        primitives,
        scene.lights.len(),
        start.elapsed().as_secs_f64()
    );
    // Machine formats keep standard output for the diagnostics alone.
    if args.format == diagnostic_format::Format::Human {
        println!("{summary}");
    } else {
        eprintln!("{summary}");
    }
    0
}
