//! Bad input never panics: every prefix-cut and byte-mangled version of the reference scenes
//! evaluates to a scene or to diagnostics.

use crate::{scratch, tests_folder};

/// Evaluates a scene text; returns false when evaluation panicked.
fn evaluates_without_panic(dir: &std::path::Path, name: &str, text: &str) -> bool {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write scene");
    let outcome = std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || {
            let evaluated = durer::eval::evaluate_file(&path, &durer::eval::EvalOptions::default());
            if let Some(scene) = &evaluated.scene {
                let _ = durer::geometry::World::build(scene);
            }
        })
        .expect("spawn")
        .join();
    outcome.is_ok()
}

#[test]
fn truncated_and_mangled_scenes_do_not_panic() {
    let dir = scratch("robustness");
    let mut panics = Vec::new();
    let mut scenes: Vec<_> = std::fs::read_dir(tests_folder().join("reference"))
        .expect("reference folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    scenes.sort();
    for scene in scenes.iter().take(10) {
        let text = std::fs::read_to_string(scene).expect("read scene");
        let cuts = (1..12).map(|k| text.len() * k / 12);
        for cut in cuts {
            let cut = (0..=cut)
                .rev()
                .find(|&i| text.is_char_boundary(i))
                .unwrap_or(0);
            if !evaluates_without_panic(&dir, "cut.pov", &text[..cut]) {
                panics.push(format!("{} cut at {cut}", scene.display()));
            }
        }
        // Replace each kind of delimiter with another to make plausible nonsense.
        for (from, to) in [("{", "("), ("}", ">"), (",", "<"), ("<", "{"), ("1", "-")] {
            if !evaluates_without_panic(&dir, "mangled.pov", &text.replacen(from, to, 3)) {
                panics.push(format!("{} with {from:?} -> {to:?}", scene.display()));
            }
        }
    }
    assert!(
        panics.is_empty(),
        "evaluation panicked for:\n{}",
        panics.join("\n")
    );
}
