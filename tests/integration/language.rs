//! Assertion-style language cases: each `tests/language/*.pov` must evaluate without error
//! (the cases use `#error` when a check fails).

use crate::{evaluate, tests_folder};
use durer::diag::Severity;

#[test]
fn language_cases_pass() {
    let mut failures = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir(tests_folder().join("language"))
        .expect("tests/language exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "pov"))
        .collect();
    paths.sort();
    assert!(
        paths.len() >= 3,
        "expected language cases, found {}",
        paths.len()
    );
    for path in paths {
        let evaluated = evaluate(&path);
        for d in evaluated
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
        {
            failures.push(durer::report::render_plain(d, &evaluated.sources));
        }
    }
    assert!(
        failures.is_empty(),
        "language cases failed:\n{}",
        failures.join("\n")
    );
}

/// Lights keep `media_interaction` and `media_attenuation`, and lights written inside a
/// declared union join the scene once per placed copy, moved with it.
#[test]
fn lights_keep_media_flags_and_follow_their_csg() {
    let dir = crate::scratch("lights");
    let path = dir.join("lights.pov");
    std::fs::write(
        &path,
        "light_source { <1, 2, 3> rgb 1 media_interaction off media_attenuation on }\n\
         #declare Lamp = union { light_source { <1, 0, 0> rgb 1 } sphere { 0, 1 } }\n\
         object { Lamp translate <0, 5, 0> }\n\
         object { Lamp rotate 90*z }\n",
    )
    .expect("write scene");
    let evaluated = evaluate(&path);
    let scene = evaluated.scene.expect("the scene evaluates");
    assert_eq!(scene.lights.len(), 3);
    assert!(!scene.lights[0].media_interaction);
    assert!(scene.lights[0].media_attenuation);
    assert!(scene.lights[1].media_interaction && !scene.lights[1].media_attenuation);
    let moved = scene.lights[1].position;
    assert!((moved - glam::DVec3::new(1.0, 5.0, 0.0)).length() < 1e-12);
    let turned = scene.lights[2].position;
    assert!((turned - glam::DVec3::new(0.0, 1.0, 0.0)).length() < 1e-12);
}

/// Settings that POV-Ray clamps silently rather than refusing: photons `autostop` 2 shoots as
/// 1 does and -1 as 0 (measured by the photon counts povray prints: 2040 and 755).
#[test]
fn photon_autostop_is_clamped_as_povray_does() {
    let dir = crate::scratch("autostop");
    for (given, clamped) in [(2.0, 1.0), (-1.0, 0.0), (0.4, 0.4)] {
        let path = dir.join("autostop.pov");
        std::fs::write(
            &path,
            format!("global_settings {{ photons {{ count 1000 autostop {given} }} }}\n"),
        )
        .expect("write scene");
        let evaluated = evaluate(&path);
        let scene = evaluated.scene.expect("the scene evaluates");
        let photons = scene.settings.photons.expect("photons are on");
        assert_eq!(photons.autostop, clamped, "autostop {given}");
        assert!(evaluated.diagnostics.is_empty(), "povray does not warn");
    }
}
