//! Integration tests: language cases, diagnostics and the command line.

mod architecture;
mod cli;
mod diagnostics;
mod diagnostics_wording;
mod expand;
mod farm;
mod fuzz_mutation;
mod hostile;
mod includes;
mod language;
mod lsp;
mod povray_cli;
mod reference_images;
mod robustness;
mod watch;

use std::path::{Path, PathBuf};

/// The repository's `tests/` folder.
pub fn tests_folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests")
}

/// Evaluates a scene file on a thread with a large stack, as the CLI does.
pub fn evaluate(path: &Path) -> durer::eval::Evaluated {
    evaluate_with(path, durer::eval::EvalOptions::default())
}

/// Evaluates a scene file with the given options on a thread with a large stack.
pub fn evaluate_with(path: &Path, options: durer::eval::EvalOptions) -> durer::eval::Evaluated {
    let path = path.to_path_buf();
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || durer::eval::evaluate_file(&path, &options))
        .expect("spawn evaluator")
        .join()
        .expect("evaluator thread")
}

/// A fresh scratch folder for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("durer-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create scratch folder");
    dir
}
