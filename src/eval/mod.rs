//! Evaluation: the AST of a scene file to a [`Scene`].
//!
//! In: a scene file path and options. Out: the [`Scene`] plus warnings, or the diagnostic
//! that stopped evaluation. Holds: each file is parsed once (includes are cached); macro
//! bodies are evaluated from their AST at each call; every limit ends in a diagnostic.
//!
//! Two parts, each owning its state: [`language`] (the language runtime: values, scopes,
//! sources, item streams and directives, macros, expressions, built-ins, data files, the
//! call trace — state in `language::Runtime`) and [`assembly`] (the blocks that become
//! scene data, and the scene being built — state in `assembly::SceneAssembly`). The
//! runtime never imports assembly; it reaches it only through [`Evaluator::eval_block`].

mod assembly;
mod language;

pub use language::standard_names;
pub use language::value::{Array, Value, Vector};

use crate::diag::{Diagnostic, SourceMap};
use crate::scene::Scene;
use crate::syntax::ast::Item;
use assembly::SceneAssembly;
use language::stream::Stream;
use language::Runtime;
use std::path::{Path, PathBuf};
use std::rc::Rc;

pub use crate::limits::Limits;

/// What the evaluator needs to know from outside the scene file.
#[derive(Clone, Debug)]
pub struct EvalOptions {
    /// Folders searched by `#include` after the scene's own folder.
    pub include_paths: Vec<PathBuf>,
    /// Value of `image_width`.
    pub image_width: u32,
    /// Value of `image_height`.
    pub image_height: u32,
    /// Value of `clock`.
    pub clock: f64,
    /// The other animation identifiers (`clock_delta`, `frame_number` ...).
    pub animation: AnimationValues,
    /// Identifiers declared before the scene is read (`Declare=`, `--define`): name and
    /// the text of an SDL expression, evaluated in order.
    pub defines: Vec<(String, String)>,
    /// A file included before the scene (`Include_Header`, `+HI`).
    pub include_header: Option<PathBuf>,
    /// The language version in force at the start (`+MV`), as an initial `#version`.
    pub initial_version: Option<f64>,
    /// Print `#debug` messages (POV-Ray's debug stream, `-GD` turns it off).
    pub print_debug: bool,
    /// Folder of the output image: scenes may read and write data files there.
    pub output_folder: Option<PathBuf>,
    /// Search POV-Ray's installed include folder (before durer's own standard library).
    pub search_installed_povray: bool,
    /// Which files the scene may read and write, before the scene's folder, the output
    /// folder and the include folders are added (see [`crate::file_policy`]).
    pub file_policy: crate::file_policy::FilePolicy,
    /// Nesting, loop, array, string and object limits (see [`crate::limits`]).
    pub limits: Limits,
    /// Text standing for the scene file (an editor's unsaved buffer); `None` reads the file.
    pub main_text: Option<std::sync::Arc<str>>,
    /// Stop with a `time-budget` error once this instant has passed (the language server's
    /// budget); `None` runs to the end.
    pub deadline: Option<std::time::Instant>,
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions {
            include_paths: Vec::new(),
            image_width: 320,
            image_height: 240,
            clock: 0.0,
            animation: AnimationValues::default(),
            defines: Vec::new(),
            include_header: None,
            initial_version: None,
            print_debug: true,
            output_folder: None,
            search_installed_povray: true,
            file_policy: crate::file_policy::FilePolicy::default(),
            limits: Limits::default(),
            main_text: None,
            deadline: None,
        }
    }
}

/// The animation identifiers besides `clock`, as POV-Ray's animation loop sets them (all
/// 0 for a still image).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AnimationValues {
    pub clock_delta: f64,
    pub clock_on: bool,
    pub frame_number: f64,
    pub initial_frame: f64,
    pub final_frame: f64,
    pub initial_clock: f64,
    pub final_clock: f64,
}

/// The outcome of evaluating a scene file.
#[derive(Debug)]
pub struct Evaluated {
    /// The scene, or `None` when an error stopped evaluation.
    pub scene: Option<Scene>,
    /// Errors and warnings, in the order found.
    pub diagnostics: Vec<Diagnostic>,
    /// The text of every file read, for showing diagnostics.
    pub sources: SourceMap,
    /// Every file the scene read (scene, includes, data files, images, fonts), each once:
    /// what `durer watch` watches.
    pub files_read: Vec<PathBuf>,
}

/// Error type used throughout evaluation.
pub(crate) type EvalResult<T> = Result<T, Box<Diagnostic>>;

/// Reads, parses and evaluates a scene file.
pub fn evaluate_file(path: &Path, options: &EvalOptions) -> Evaluated {
    crate::syntax::set_parse_step_limit(options.limits.parse_steps);
    let mut evaluator = Evaluator::new(options.clone());
    let result = evaluator.run_main(path);
    let mut diagnostics = evaluator.runtime.take_warnings();
    let scene = match result {
        Ok(()) => {
            let (version, declared) = evaluator.runtime.version();
            Some(evaluator.scene.finish(version, declared))
        }
        Err(d) => {
            diagnostics.push(*d);
            None
        }
    };
    let files_read = evaluator.runtime.files_read();
    Evaluated {
        scene,
        diagnostics,
        sources: evaluator.runtime.into_sources(),
        files_read,
    }
}

/// The evaluator: the language runtime and the scene it assembles. Block readers across
/// `language/` and `assembly/` are `impl Evaluator` blocks; each reaches the state it needs
/// through one of the two parts.
pub(crate) struct Evaluator {
    /// Values, scopes, sources, macros, data files and the call trace.
    pub(crate) runtime: Runtime,
    /// Camera, lights, objects, atmosphere and settings added so far.
    pub(crate) scene: SceneAssembly,
}

impl Evaluator {
    /// A fresh evaluator for one scene file.
    pub(crate) fn new(options: EvalOptions) -> Evaluator {
        Evaluator {
            runtime: Runtime::new(options),
            scene: SceneAssembly::new(),
        }
    }

    fn run_main(&mut self, path: &Path) -> EvalResult<()> {
        self.runtime.set_main_file(path);
        if let Some(version) = self.runtime.options().initial_version {
            self.runtime.set_version(version);
        }
        self.run_prelude()?;
        let items = self.runtime.load_file(path, None)?;
        let mut stream = Stream::new(items);
        while let Some(item) = self.next_item(&mut stream)? {
            self.scene_item(item)?;
        }
        Ok(())
    }

    /// The command line's `Declare`s / `--define`s and `Include_Header`, run as a small
    /// file named `<command line>` before the scene (so its messages point into it).
    fn run_prelude(&mut self) -> EvalResult<()> {
        let options = self.runtime.options();
        if options.defines.is_empty() && options.include_header.is_none() {
            return Ok(());
        }
        let mut text = String::new();
        for (name, value) in &options.defines {
            text.push_str(&format!("#declare {name} = {value};\n"));
        }
        if let Some(header) = &options.include_header {
            let name = header.to_string_lossy().replace('\\', "/").replace('"', "");
            text.push_str(&format!("#include \"{name}\"\n"));
        }
        let items = self.runtime.parse_virtual_file("<command line>", &text)?;
        let mut stream = Stream::new(items);
        while let Some(item) = self.next_item(&mut stream)? {
            self.scene_item(item)?;
        }
        Ok(())
    }

    /// Handles one item at the top level of the scene.
    fn scene_item(&mut self, item: Item) -> EvalResult<()> {
        let span = item.span();
        let value = match &item {
            Item::Block(block) => self.eval_block(block)?,
            Item::Expr(expr) => self.eval_expr(expr)?,
            Item::Keyword(word, span) => {
                return Err(self
                    .runtime
                    .error(
                        *span,
                        format!("`{word}` cannot stand at the top level of a scene"),
                    )
                    .with_label("expected an object, camera, light or directive")
                    .into())
            }
            Item::Comma(_) => return Ok(()),
            Item::MapEntry(..) | Item::Directive(_) => {
                return Err(self
                    .runtime
                    .error(span, "expected an object, camera, light or directive")
                    .into())
            }
        };
        match value {
            Value::Object(object) => self.scene.add_object(object),
            Value::Camera(camera) => self.scene.set_camera(Rc::unwrap_or_clone(camera)),
            Value::Light(light) => self.scene.add_light(Rc::unwrap_or_clone(light)),
            Value::Atmospheric(effect) => self.scene.add_atmospheric_effect(&effect),
            Value::Media(media) => self.scene.add_media(Rc::unwrap_or_clone(media)),
            Value::Colour(colour) if matches!(item, Item::Block(_)) => {
                self.scene.set_background(colour)
            }
            Value::Nothing => {} // settings blocks and left-out features
            other => {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!(
                            "expected an object, camera or light, found {}",
                            other.type_name()
                        ),
                    )
                    .with_label("this value does nothing here")
                    .into())
            }
        }
        Ok(())
    }
}
