//! `durer expand SCENE [-o FLAT.pov] [render options]`: the evaluated scene as flat SDL.
//!
//! The scene is evaluated exactly as `render` would (same options: `--define`, `--clock`,
//! `--frame`, `+K..`, `-L`, `.ini` files), then written by [`durer::expand`]. Without
//! `-o` the text goes to standard output; an animation writes one numbered file per frame
//! (`-o flat.pov` gives `flat01.pov`, `flat02.pov`, ...). Files are written atomically.
//! Exit codes as `render`: 1 for a scene error or something flat SDL cannot say.

use super::animation::{frame_file_name, Animation};
use super::povray_options::Settings;
use super::render_job::eval_options;
use super::{evaluate, print_diagnostics, EXIT_SCENE_ERROR, EXIT_USAGE};
use durer::expand::{expand_scene, ExpandOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Runs `durer expand` with the settings `render` would use.
pub(super) fn run(settings: Settings, format: super::diagnostic_format::Format) -> i32 {
    let Some(scene_path) = settings.input.clone() else {
        eprintln!("durer: no scene given: name a .pov file (durer expand --help)");
        return EXIT_USAGE;
    };
    let animation = match Animation::plan(&settings) {
        Ok(animation) => animation,
        Err(message) => {
            eprintln!("durer: {message}");
            return EXIT_USAGE;
        }
    };
    let output = settings.output.clone().filter(|o| o != "-");
    let several = animation.animated && animation.frames.len() > 1;
    if several && output.is_none() {
        eprintln!(
            "durer: an animation of several frames needs -o FILE.pov (one numbered file a frame)"
        );
        return EXIT_USAGE;
    }
    for frame in &animation.frames {
        let file = output.as_ref().map(|output| {
            if animation.animated {
                let base = output.strip_suffix(".pov").unwrap_or(output);
                PathBuf::from(frame_file_name(
                    base,
                    Some(frame.frame_number),
                    animation.digits,
                    "pov",
                ))
            } else {
                PathBuf::from(output)
            }
        });
        let options = eval_options(&settings, frame, file.as_deref());
        let evaluated = evaluate(&scene_path, options);
        let warnings = settings.streams.warning && settings.warning_level > 0;
        // Machine-format diagnostics go to standard error when the flat scene takes the output.
        let failed = print_diagnostics(&evaluated, warnings, format, output.is_none());
        let Some(scene) = evaluated.scene.filter(|_| !failed) else {
            return EXIT_SCENE_ERROR;
        };
        let base = file
            .as_deref()
            .and_then(Path::parent)
            .map(|p| {
                if p.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    p
                }
            })
            .and_then(|p| std::fs::canonicalize(p).ok());
        let text = match expand_scene(&scene, &ExpandOptions { base }) {
            Ok(text) => text,
            Err(unsupported) => {
                eprintln!("durer: {}: {unsupported}", scene_path.display());
                return EXIT_SCENE_ERROR;
            }
        };
        let written = match &file {
            Some(path) => durer::render::output::write_atomic(path, text.as_bytes())
                .map_err(|e| format!("cannot write {}: {e}", path.display())),
            None => std::io::stdout()
                .lock()
                .write_all(text.as_bytes())
                .map_err(|e| format!("cannot write to standard output: {e}")),
        };
        if let Err(message) = written {
            eprintln!("durer: {message}");
            return EXIT_SCENE_ERROR;
        }
        if let Some(path) = &file {
            if settings.streams.render {
                eprintln!("{}: {} bytes", path.display(), text.len());
            }
        }
    }
    0
}
