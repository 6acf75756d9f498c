//! Entry points for fuzzers: one scene text through the pipeline, with small limits.
//!
//! In: the bytes of a scene file (any bytes: invalid UTF-8 is read lossily) and
//! [`Limits`]. Out: an [`Outcome`] saying how far the scene got. Holds: nothing here
//! panics on its own; a panic, stack overflow or hang inside the pipeline is what a fuzzer
//! looks for (the targets in `fuzz/` and the mutation test in
//! `tests/integration/fuzz_mutation.rs`, see `docs/fuzzing.md`).
//!
//! Each stage runs as the command line runs it: evaluation on a thread with the CLI's
//! large stack, rendering on a one-thread rayon pool with the CLI's render stacks, and every
//! diagnostic is drawn by the report printer (whose formatting is under test too). The
//! scene is written to a file in a private folder first, so `#include`, `#fopen` and
//! images resolve next to it as they do for a real scene file. The time budget is the
//! caller's: the fuzzer's own timeout (AFL `-t`) or the mutation test's per-case timeout.

use crate::diag::{Severity, SourceMap};
use crate::eval::{evaluate_file, EvalOptions, Evaluated};
use crate::geometry::World;
use crate::limits::{EVALUATION_STACK_BYTES, RENDER_STACK_BYTES};
use crate::render::RenderOptions;
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

/// How small the run is kept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Image width, as `image_width` and for the render.
    pub width: u32,
    /// Image height, as `image_height` and for the render.
    pub height: u32,
    /// Longest input, in bytes, taken at all (longer input is cut there).
    pub max_input_bytes: usize,
}

impl Default for Limits {
    /// A 16 x 12 image and inputs up to 256 KiB.
    fn default() -> Self {
        Limits {
            width: 16,
            height: 12,
            max_input_bytes: 256 << 10,
        }
    }
}

/// How far a scene got.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The text did not parse (only [`parse`] tells this apart from [`Outcome::EvalError`]).
    SyntaxError,
    /// Evaluation stopped with an error diagnostic (a syntax error included).
    EvalError,
    /// The scene was evaluated (and built, for [`render`]).
    Evaluated,
    /// The scene was rendered.
    Rendered,
}

/// The input as text, cut at `limits.max_input_bytes` (on a character boundary).
fn text_of(bytes: &[u8], limits: &Limits) -> String {
    let cut = &bytes[..bytes.len().min(limits.max_input_bytes)];
    let mut text = String::from_utf8_lossy(cut).into_owned();
    while text.len() > limits.max_input_bytes {
        text.pop();
    }
    text
}

/// Parses the text only (no evaluation); a syntax error is drawn by the report printer.
pub fn parse(bytes: &[u8], limits: &Limits) -> Outcome {
    let text: Arc<str> = Arc::from(text_of(bytes, limits));
    let mut sources = SourceMap::new();
    let file = sources.add(Path::new("fuzz.pov"), text.clone());
    match crate::syntax::parse(&text, file) {
        Ok(items) => {
            drop(items);
            Outcome::Evaluated
        }
        Err(diagnostic) => {
            let drawn = crate::report::render_plain(&diagnostic, &sources);
            std::hint::black_box(drawn);
            Outcome::SyntaxError
        }
    }
}

/// Parses and evaluates the text; every diagnostic is drawn by the report printer.
pub fn evaluate(bytes: &[u8], limits: &Limits) -> Outcome {
    let (outcome, _) = evaluate_keeping(bytes, limits);
    outcome
}

/// Parses, evaluates, builds and renders the text at the size in `limits`.
pub fn render(bytes: &[u8], limits: &Limits) -> Outcome {
    let (outcome, evaluated) = evaluate_keeping(bytes, limits);
    let Some(mut scene) = evaluated.and_then(|e| e.scene) else {
        return outcome;
    };
    if outcome != Outcome::Evaluated {
        return outcome;
    }
    let options = RenderOptions::new(limits.width, limits.height);
    render_pool().install(|| {
        let world = World::build_from_objects(std::mem::take(&mut scene.objects));
        let image = crate::render::render_image(&scene, &world, &options, &|_| {});
        std::hint::black_box(image);
    });
    Outcome::Rendered
}

/// The one-thread pool renders run on (with the command line's render stacks).
fn render_pool() -> &'static rayon::ThreadPool {
    static POOL: OnceLock<rayon::ThreadPool> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .stack_size(RENDER_STACK_BYTES)
            .build()
            .expect("a one-thread pool")
    })
}

/// The private folder the scene file is written to (one per process).
fn scene_path() -> PathBuf {
    static FOLDER: OnceLock<PathBuf> = OnceLock::new();
    let folder = FOLDER.get_or_init(|| {
        let folder = std::env::temp_dir().join(format!("durer-fuzz-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&folder);
        folder
    });
    folder.join("fuzz.pov")
}

/// Evaluates the text on a large-stack thread; the outcome and what evaluation gave
/// (`None` when the scene file could not be written).
fn evaluate_keeping(bytes: &[u8], limits: &Limits) -> (Outcome, Option<Evaluated>) {
    let text = text_of(bytes, limits);
    let path = scene_path();
    if std::fs::write(&path, text.as_bytes()).is_err() {
        return (Outcome::EvalError, None);
    }
    let options = EvalOptions {
        image_width: limits.width,
        image_height: limits.height,
        print_debug: false,
        ..EvalOptions::default()
    };
    let worker = std::thread::Builder::new()
        .stack_size(EVALUATION_STACK_BYTES)
        .spawn(move || evaluate_file(&path, &options));
    let evaluated = match worker.map(|handle| handle.join()) {
        Ok(Ok(evaluated)) => evaluated,
        // The evaluator panicked: let the fuzzer see the panic.
        Ok(Err(panic)) => std::panic::resume_unwind(panic),
        Err(_) => return (Outcome::EvalError, None),
    };
    let mut failed = false;
    for diagnostic in &evaluated.diagnostics {
        failed |= diagnostic.severity == Severity::Error;
        let drawn = crate::report::render_plain(diagnostic, &evaluated.sources);
        std::hint::black_box(drawn);
    }
    let outcome = if failed {
        Outcome::EvalError
    } else {
        Outcome::Evaluated
    };
    (outcome, Some(evaluated))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_stage_reports_how_far_a_scene_got() {
        let limits = Limits::default();
        let scene = b"camera { location <0,0,-3> look_at 0 }\n\
                      light_source { <1,2,-3> rgb 1 }\n\
                      sphere { 0, 1 pigment { rgb <1,0,0> } }\n";
        assert_eq!(parse(scene, &limits), Outcome::Evaluated);
        assert_eq!(evaluate(scene, &limits), Outcome::Evaluated);
        assert_eq!(render(scene, &limits), Outcome::Rendered);
        assert_eq!(parse(b"sphere { 0, 1", &limits), Outcome::SyntaxError);
        assert_eq!(render(b"sphere { 0, 1", &limits), Outcome::EvalError);
        assert_eq!(
            render(b"#declare A = 1 / <1,2>;\n#error \"x\"\n", &limits),
            Outcome::EvalError
        );
        assert_eq!(parse(&[0xff, 0xfe, 0x00], &limits), Outcome::SyntaxError);
        assert_eq!(render(&[0xff, 0xfe, 0x00], &limits), Outcome::EvalError);
    }

    #[test]
    fn long_input_is_cut_on_a_character_boundary() {
        let limits = Limits {
            max_input_bytes: 5,
            ..Limits::default()
        };
        assert_eq!(text_of("abcdéf".as_bytes(), &limits), "abcd");
    }
}
