//! POV-Ray 3.7's standard include files load without error.
//!
//! Needs the include files of the Debian package `povray-includes` (`.ci/run` installs it);
//! set `DURER_POVRAY_INCLUDE` to use another folder. Without them the test says so and passes.

use crate::{evaluate_with, scratch};
use durer::diag::Severity;
use std::path::PathBuf;

fn povray_include_folder() -> Option<PathBuf> {
    let folder = std::env::var_os("DURER_POVRAY_INCLUDE")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/share/povray-3.7/include"));
    folder.join("colors.inc").is_file().then_some(folder)
}

#[test]
fn every_standard_include_file_loads() {
    let Some(folder) = povray_include_folder() else {
        eprintln!(
            "POV-Ray's include files are not installed; skipping (apt-get install povray-includes)"
        );
        return;
    };
    let dir = scratch("includes");
    let mut names: Vec<String> = std::fs::read_dir(&folder)
        .expect("include folder")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".inc"))
        .collect();
    names.sort();
    assert!(
        names.len() >= 30,
        "expected POV-Ray's include files, found {}",
        names.len()
    );
    let mut failures = Vec::new();
    for name in &names {
        // Several files expect colors.inc and shapes.inc to be included first, as in POV-Ray.
        let scene = dir.join(format!("{name}.pov"));
        let text = format!(
            "#version 3.7;\n#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"{name}\"\n"
        );
        std::fs::write(&scene, text).expect("write scene");
        let options = durer::eval::EvalOptions {
            include_paths: vec![folder.clone()],
            ..Default::default()
        };
        let evaluated = evaluate_with(&scene, options);
        for d in evaluated
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
        {
            failures.push(format!(
                "{name}: {}",
                durer::report::render_plain(d, &evaluated.sources)
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "include files failed to load:\n{}",
        failures.join("\n")
    );
}
