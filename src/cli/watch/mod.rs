//! `durer watch SCENE [render options] [--serve [ADDR]]`: renders, then renders again
//! whenever the scene or a file it read (includes, images, fonts, data files) changes.
//!
//! Each round: evaluate (an error prints its diagnostic and keeps the last good image),
//! build, a quick preview (a quarter of the size each way, no anti-aliasing), then the
//! full image, written atomically to the output file. A watcher thread polls the files'
//! size and modification time every [`POLL`]; a change abandons the render in progress
//! (through the renderer's interrupt flag) and starts the next round. With `--serve` the
//! same state is published to a page on localhost ([`server`]).
//!
//! Polling rather than OS notifications (the `notify` crate): a round watches a handful
//! of files, editors save by writing a new file and renaming it over the old (which
//! drops inotify watches on the file), and polling behaves the same on network folders.

mod server;

use super::animation::frame_file_name;
use super::povray_options::Settings;
use super::render_job::{
    eval_options, plan_run, render_options, render_pool, Destination, RunPlan,
};
use super::{evaluate, print_diagnostics, EXIT_USAGE};
use durer::diag::Severity;
use durer::render::output::{self, FileFormat, OutputOptions, RenderedImage};
use durer::render::RenderOptions;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime};

/// How often the watched files are looked at.
const POLL: Duration = Duration::from_millis(100);

/// Set by Ctrl-C: leave the loop.
static QUIT: AtomicBool = AtomicBool::new(false);

/// What `--serve` gives: where to listen.
pub struct ServeOption {
    pub address: String,
}

/// Takes `--serve [ADDR]` out of `words` (ADDR: `HOST:PORT`, `:PORT` or `PORT`; default
/// `127.0.0.1:8181`).
pub fn take_serve_option(words: &mut Vec<String>) -> Option<ServeOption> {
    let at = words.iter().position(|w| w == "--serve")?;
    words.remove(at);
    let next = words.get(at).cloned();
    let address = match next {
        Some(word) if looks_like_address(&word) => {
            words.remove(at);
            if let Some(port) = word.strip_prefix(':') {
                format!("127.0.0.1:{port}")
            } else if word.parse::<u16>().is_ok() {
                format!("127.0.0.1:{word}")
            } else {
                word
            }
        }
        _ => "127.0.0.1:8181".to_string(),
    };
    Some(ServeOption { address })
}

fn looks_like_address(word: &str) -> bool {
    word.parse::<u16>().is_ok()
        || (word.contains(':') && !word.starts_with('-') && !word.starts_with('+'))
}

/// The (length, modification time) of each file; `None` for one that is gone.
type Stamps = Vec<Option<(u64, SystemTime)>>;

fn stamps(files: &[PathBuf]) -> Stamps {
    files
        .iter()
        .map(|f| {
            std::fs::metadata(f)
                .ok()
                .map(|m| (m.len(), m.modified().unwrap_or(SystemTime::UNIX_EPOCH)))
        })
        .collect()
}

/// The files of the current round and their stamps; the watcher thread compares.
struct Watched {
    files: Vec<PathBuf>,
    stamps: Stamps,
    changed: bool,
}

/// Runs the watch loop; returns the exit code (0 after Ctrl-C).
pub fn run(settings: Settings, serve: Option<ServeOption>) -> i32 {
    let RunPlan {
        scene_path,
        plan,
        animation,
        region,
    } = match plan_run(&settings, false) {
        Ok(run) => run,
        Err(code) => return code,
    };
    let frame = animation.frames[0];
    let file = match &plan.destination {
        Destination::Files { base } => Some(PathBuf::from(frame_file_name(
            base,
            None,
            0,
            plan.options.format.extension(),
        ))),
        Destination::Exact(path) => Some(path.clone()),
        Destination::Stdout => {
            eprintln!("durer: watch writes a file: give -o FILE, not -o -");
            return EXIT_USAGE;
        }
        Destination::Nowhere => None,
    };
    let full = render_options(&settings, region);
    let live = Arc::new(server::Live::default());
    if let Some(serve) = &serve {
        match server::start(&serve.address, live.clone()) {
            Ok(address) => eprintln!("durer: live preview on http://{address}/"),
            Err(message) => {
                eprintln!("durer: cannot serve on {}: {message}", serve.address);
                return EXIT_USAGE;
            }
        }
    }
    let pool = match render_pool(&settings) {
        Ok(pool) => pool,
        Err(code) => return code,
    };
    let _ = ctrlc::set_handler(|| {
        QUIT.store(true, Ordering::SeqCst);
        durer::render::interrupt();
    });
    let watched = Arc::new(Mutex::new(Watched {
        files: vec![scene_path.clone()],
        stamps: stamps(std::slice::from_ref(&scene_path)),
        changed: false,
    }));
    start_watcher(watched.clone());
    eprintln!("durer: watching {} (Ctrl-C to stop)", scene_path.display());
    let round = Round {
        settings: &settings,
        scene_path: &scene_path,
        frame: &frame,
        file: file.as_deref(),
        output: &plan.options,
        full: &full,
        pool: &pool,
        live: &live,
    };
    let mut saved = SystemTime::now();
    while !QUIT.load(Ordering::SeqCst) {
        let files = round.run(saved);
        {
            let mut watched = watched.lock().unwrap_or_else(|e| e.into_inner());
            // Stamps taken before evaluation would miss a save during it: the flag set by
            // the watcher covers that; the new set is compared from now on.
            if !watched.changed {
                watched.stamps = stamps(&files);
                watched.files = files;
            }
        }
        // Wait for a change (or Ctrl-C).
        loop {
            if QUIT.load(Ordering::SeqCst) {
                break;
            }
            let mut watched = watched.lock().unwrap_or_else(|e| e.into_inner());
            if watched.changed {
                watched.changed = false;
                watched.stamps = stamps(&watched.files);
                // The save: the newest modification time of the files (not when the
                // poll saw it), so the times printed are from the save.
                saved = watched
                    .stamps
                    .iter()
                    .flatten()
                    .map(|(_, time)| *time)
                    .max()
                    .unwrap_or_else(SystemTime::now);
                break;
            }
            drop(watched);
            std::thread::sleep(POLL);
        }
        durer::render::clear_interrupt();
    }
    eprintln!("durer: stopped watching");
    0
}

/// Polls the watched files; on a change marks it and abandons the render in progress.
fn start_watcher(watched: Arc<Mutex<Watched>>) {
    std::thread::spawn(move || loop {
        std::thread::sleep(POLL);
        let mut watched = watched.lock().unwrap_or_else(|e| e.into_inner());
        if watched.changed {
            continue;
        }
        let now = stamps(&watched.files);
        if now != watched.stamps {
            watched.stamps = now;
            watched.changed = true;
            durer::render::interrupt();
        }
    });
}

/// What every round shares.
struct Round<'a> {
    settings: &'a Settings,
    scene_path: &'a Path,
    frame: &'a super::animation::FrameClock,
    file: Option<&'a Path>,
    output: &'a OutputOptions,
    full: &'a RenderOptions,
    pool: &'a rayon::ThreadPool,
    live: &'a server::Live,
}

impl Round<'_> {
    /// Evaluates and renders once (preview, then full); returns the files the scene read.
    /// `saved` is when the change was saved (for the times printed).
    fn run(&self, saved: SystemTime) -> Vec<PathBuf> {
        durer::render::clear_interrupt();
        self.live.set_status("evaluating");
        let start = Instant::now();
        let options = eval_options(self.settings, self.frame, self.file);
        let evaluated = evaluate(self.scene_path, options);
        let mut files = evaluated.files_read.clone();
        if !files.iter().any(|f| f == self.scene_path) {
            files.insert(0, self.scene_path.to_path_buf());
        }
        let warnings = self.settings.streams.warning && self.settings.warning_level > 0;
        let failed = print_diagnostics(
            &evaluated,
            warnings,
            super::diagnostic_format::Format::Human,
            true,
        );
        self.live
            .set_diagnostics(diagnostics_json(&evaluated, warnings));
        let Some(mut scene) = evaluated.scene.filter(|_| !failed) else {
            eprintln!("durer: the scene has errors; the last good image is kept");
            self.live
                .set_status("the scene has errors; the last good image is kept");
            return files;
        };
        let parse = start.elapsed();
        let objects = std::mem::take(&mut scene.objects);
        let object_count = objects.len();
        let build_start = Instant::now();
        let world = self
            .pool
            .install(|| durer::geometry::World::build_from_objects(objects));
        let build = build_start.elapsed();
        let preview = RenderOptions {
            width: self.full.width.div_ceil(4).max(1),
            height: self.full.height.div_ceil(4).max(1),
            antialias: None,
            region: None,
            ..*self.full
        };
        let passes = [("preview", preview), ("full", *self.full)];
        for (pass, (name, render)) in passes.into_iter().enumerate() {
            self.live.set_status(&format!("rendering the {name} image"));
            let render_start = Instant::now();
            super::stats::reset(self.pool);
            let image = self
                .pool
                .install(|| durer::render::render_image(&scene, &world, &render, &|_| {}));
            let Some(image) = image.filter(|_| !durer::render::interrupted()) else {
                eprintln!("durer: a file changed; the render was abandoned");
                return files;
            };
            let render_time = render_start.elapsed();
            let mut summary = super::stats::Summary {
                frames: 1,
                threads: self.pool.current_num_threads(),
                ..Default::default()
            };
            summary.add_frame(
                super::stats::collect(self.pool),
                object_count,
                scene.lights.len(),
                parse,
                build,
                render_time,
            );
            summary.total = start.elapsed();
            let shown = if pass == 0 {
                scaled_up(&image, self.full.width, self.full.height)
            } else {
                image
            };
            if let Err(message) = self.publish(&shown, name, &summary) {
                eprintln!("durer: {message}");
                self.live.set_status(&message);
                return files;
            }
            let since_save = SystemTime::now()
                .duration_since(saved)
                .unwrap_or_default()
                .as_secs_f64();
            eprintln!(
                "durer: {name} {}x{} in {:.3} s ({since_save:.3} s after the change)",
                render.width,
                render.height,
                render_time.as_secs_f64(),
            );
        }
        self.live.set_status("done");
        files
    }

    /// Writes the image file (when there is one) and gives the page its PNG.
    fn publish(
        &self,
        image: &RenderedImage,
        pass: &str,
        summary: &super::stats::Summary,
    ) -> Result<(), String> {
        if let Some(path) = self.file {
            let bytes = output::encode(image, self.output).map_err(|e| e.to_string())?;
            output::write_atomic(path, &bytes)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        let png = if self.output.format == FileFormat::Png && self.output.bits == 8 {
            output::encode(image, self.output)
        } else {
            output::encode(image, &OutputOptions::png())
        }
        .map_err(|e| e.to_string())?;
        let stats: Value = serde_json::from_str(&summary.json()).unwrap_or(Value::Null);
        self.live.set_image(
            png,
            json!({ "width": image.width, "height": image.height, "pass": pass }),
            stats,
        );
        Ok(())
    }
}

/// A preview scaled to the full size (nearest pixel), so viewers keep their zoom.
fn scaled_up(image: &RenderedImage, width: u32, height: u32) -> RenderedImage {
    let mut pixels = Vec::with_capacity(width as usize * height as usize);
    for row in 0..height {
        let y = (u64::from(row) * u64::from(image.height) / u64::from(height)) as usize;
        for column in 0..width {
            let x = (u64::from(column) * u64::from(image.width) / u64::from(width)) as usize;
            pixels.push(image.pixels[y * image.width as usize + x]);
        }
    }
    RenderedImage {
        width,
        height,
        pixels,
        encoding: image.encoding,
    }
}

/// The diagnostics for the page: the `--format json` object of each, plus the plain
/// text report with its source lines.
fn diagnostics_json(evaluated: &durer::eval::Evaluated, warnings: bool) -> Value {
    Value::Array(
        evaluated
            .diagnostics
            .iter()
            .filter(|d| warnings || d.severity == Severity::Error)
            .map(|d| {
                let mut object = super::diagnostic_format::json_object(d, &evaluated.sources);
                object["text"] = json!(durer::report::render_plain(d, &evaluated.sources));
                object
            })
            .collect(),
    )
}
