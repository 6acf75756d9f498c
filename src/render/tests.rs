//! Render-level known-answer tests: small scenes whose centre pixel POV-Ray 3.7 was seen to
//! produce (3×3 renders with `povray +W3 +H3 -GA`), and determinism across thread counts.

use super::*;
use crate::{
    math::{Colour, Transform},
    scene::{Camera, GlobalSettings, Interior, LightSource, Object, Shape},
    texture::{
        finish::Finish,
        pattern::{Pattern, PatternKind},
        Pigment, PigmentMap, Texture,
    },
};
use glam::DVec3;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Arc;

/// Settings of a scene starting `#version 3.7; global_settings { assumed_gamma 1.0 }`.
fn version_37() -> GlobalSettings {
    GlobalSettings {
        assumed_gamma: Some(1.0),
        language_version: 3.7,
        version_declared: true,
        ..GlobalSettings::default()
    }
}

/// POV-Ray's default camera moved to `<0, 0, -5>`, looking along +z.
fn camera() -> Camera {
    Camera {
        location: DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    }
}

fn scene(objects: Vec<Object>, lights: Vec<LightSource>, settings: GlobalSettings) -> Scene {
    Scene {
        camera: camera(),
        lights,
        objects,
        background: Colour::BLACK,
        atmosphere: Default::default(),
        settings,
    }
}

fn finish(ambient: f64, diffuse: f64) -> Finish {
    Finish {
        ambient: DVec3::splat(ambient),
        diffuse,
        ..Finish::default()
    }
}

/// An object with a texture and, optionally, an index of refraction.
fn textured(shape: Shape, pigment: Pigment, finish: Finish, ior: Option<f64>) -> Object {
    let mut object = Object::new(shape);
    object.texture = Some(Arc::new(Texture {
        pigment,
        finish: Arc::new(finish),
        ..Texture::default()
    }));
    object.interior = ior.map(|ior| {
        Box::new(Interior {
            ior,
            ..Interior::default()
        })
    });
    object
}

fn plane(normal: DVec3, distance: f64) -> Shape {
    Shape::Plane { normal, distance }
}

fn point_light(position: DVec3) -> LightSource {
    LightSource::point(position, DVec3::ONE)
}

/// The centre pixel of a 3×3 render (its ray runs exactly along the camera direction).
fn centre_pixel(scene: &Scene) -> [u8; 3] {
    let world = World::build(scene);
    let options = RenderOptions {
        width: 3,
        height: 3,
        antialias: None,
        region: None,
        alpha: false,
        quality: Default::default(),
    };
    render(scene, &world, &options, &|_| {})
        .pixel(1, 1)
        .unwrap()
}

fn ambient_plane(settings: GlobalSettings) -> Scene {
    let wall = textured(
        plane(DVec3::Z, 0.0),
        Pigment::Solid(Colour::grey(0.5)),
        finish(1.0, 0.0),
        None,
    );
    scene(vec![wall], vec![], settings)
}

#[test]
fn ambient_surface_after_gamma() {
    assert_eq!(centre_pixel(&ambient_plane(version_37())), [188; 3]);
    assert_eq!(
        centre_pixel(&ambient_plane(GlobalSettings::default())),
        [128; 3]
    );
    let gamma_22 = GlobalSettings {
        assumed_gamma: Some(2.2),
        ..version_37()
    };
    assert_eq!(centre_pixel(&ambient_plane(gamma_22)), [128; 3]);
}

#[test]
fn diffuse_with_light_along_the_normal() {
    let wall = textured(
        plane(DVec3::Z, 0.0),
        Pigment::Solid(Colour::rgb(1.0, 0.5, 0.25)),
        finish(0.0, 0.6),
        None,
    );
    let lit = scene(
        vec![wall],
        vec![point_light(camera().location)],
        version_37(),
    );
    // Linear 0.6, 0.3, 0.15 after sRGB encoding.
    assert_eq!(centre_pixel(&lit), [203, 149, 108]);
}

#[test]
fn reflection_of_the_background() {
    let mirror = textured(
        plane(DVec3::Z, 0.0),
        Pigment::Solid(Colour::BLACK),
        Finish {
            reflection: DVec3::splat(0.5),
            ..finish(0.0, 0.0)
        },
        None,
    );
    let mut reflecting = scene(vec![mirror], vec![], version_37());
    reflecting.background = Colour::rgb(0.2, 0.4, 0.6);
    // Half of the background: linear 0.1, 0.2, 0.3.
    assert_eq!(centre_pixel(&reflecting), [89, 124, 149]);
}

#[test]
fn snell_at_a_flat_interface() {
    // A wall at z = 2 whose grey level is (x + 2) / 4 (gradient x, scale 4, translate -2x),
    // seen through the surface of a glass half-space tilted about the y axis.
    let ramp = Pigment::Pattern {
        pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
        map: PigmentMap::Colours(vec![(0.0, Colour::BLACK), (1.0, Colour::WHITE)]),
        transform: Transform::scaling(DVec3::splat(4.0))
            .unwrap()
            .then(&Transform::translation(DVec3::new(-2.0, 0.0, 0.0))),
    };
    let wall = textured(plane(DVec3::Z, 2.0), ramp, finish(1.0, 0.0), None);
    let normal = DVec3::new(0.3, 0.0, -1.0);
    let glass = textured(
        plane(normal, 0.0),
        Pigment::Solid(Colour::rgbft(1.0, 1.0, 1.0, 1.0, 0.0)),
        finish(0.0, 0.0),
        Some(1.5),
    );
    // No #version: the byte is round(255 · value).
    let through = scene(vec![wall, glass], vec![], GlobalSettings::default());
    let pixel = centre_pixel(&through);
    assert_eq!(pixel, [115; 3]);

    // The same value from Snell's law by hand: sin(out) = sin(in) / 1.5. The ray enters at
    // the origin and turns towards the inward normal (towards -x) by in - out.
    let unit = normal.normalize();
    let incidence = (-unit.z).acos();
    let refracted = (incidence.sin() / 1.5).asin();
    let deviation = incidence - refracted;
    let x_at_wall = -2.0 * deviation.tan();
    let expected = ((x_at_wall + 2.0) / 4.0 * 255.0).round() as u8;
    assert_eq!(pixel[0], expected);
}

#[test]
fn total_internal_reflection_replaces_reflection() {
    // The camera sits inside glass; its ray meets the surface at 56 degrees and is totally
    // reflected onto a sphere of colour <0.2, 0.1, 0.05>.
    let normal = DVec3::new(1.5, 0.0, 1.0).normalize();
    let glass = textured(
        plane(normal, -2.0 * normal.z),
        Pigment::Solid(Colour::rgbft(0.2, 0.3, 0.4, 0.3, 0.0)),
        Finish {
            reflection: DVec3::splat(0.5),
            ..finish(1.0, 0.0)
        },
        Some(1.5),
    );
    let ball = textured(
        Shape::Sphere {
            centre: DVec3::new(-9.23, 0.0, 1.85),
            radius: 3.0,
        },
        Pigment::Solid(Colour::rgb(0.2, 0.1, 0.05)),
        finish(1.0, 0.0),
        None,
    );
    let mut inside = scene(vec![glass, ball], vec![], version_37());
    inside.background = Colour::rgb(0.1, 0.2, 0.4);
    // 0.7 · pigment + 1 · sphere colour (the finish's reflection 0.5 is not added).
    assert_eq!(centre_pixel(&inside), [158, 151, 155]);
}

#[test]
fn exhausted_trace_level_adds_black() {
    let mirror = |distance: f64, colour: Colour| {
        textured(
            plane(DVec3::Z, distance),
            Pigment::Solid(colour),
            Finish {
                reflection: DVec3::splat(0.5),
                ..finish(0.5, 0.0)
            },
            None,
        )
    };
    let settings = GlobalSettings {
        max_trace_level: 2,
        adc_bailout: 0.0,
        ..version_37()
    };
    let mut facing = scene(
        vec![
            mirror(0.0, Colour::rgb(1.0, 0.0, 0.0)),
            mirror(-20.0, Colour::rgb(0.0, 1.0, 0.0)),
        ],
        vec![],
        settings,
    );
    facing.background = Colour::rgb(0.0, 0.0, 1.0);
    // Red 0.5 + 0.5 · green 0.5; the third bounce is not traced and the blue background
    // never shows.
    assert_eq!(centre_pixel(&facing), [188, 137, 0]);
}

#[test]
fn filtered_light_through_transparent_disc() {
    let wall = textured(
        plane(DVec3::Z, 0.0),
        Pigment::Solid(Colour::WHITE),
        finish(0.0, 1.0),
        None,
    );
    let disc = textured(
        Shape::Disc {
            centre: DVec3::new(0.0, 0.0, -2.0),
            normal: DVec3::Z,
            radius: 0.1,
            hole_radius: 0.0,
        },
        Pigment::Solid(Colour::rgbft(0.8, 0.5, 0.2, 0.5, 0.3)),
        finish(0.0, 0.0),
        None,
    );
    let lit = scene(
        vec![wall, disc],
        vec![point_light(camera().location)],
        version_37(),
    );
    // The disc passes 0.7, 0.55, 0.4 twice: once in the shadow ray, once in the view ray.
    assert_eq!(centre_pixel(&lit), [186, 149, 111]);
}

/// A scene using every feature: patterns, highlights, shadows, glass, mirrors, spotlight.
fn busy_scene() -> Scene {
    let floor = textured(
        plane(DVec3::Y, -1.0),
        Pigment::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map: PigmentMap::Blocks(vec![
                Pigment::Solid(Colour::WHITE),
                Pigment::Solid(Colour::rgb(0.1, 0.2, 0.1)),
            ]),
            transform: Transform::scaling(DVec3::splat(0.5)).unwrap(),
        },
        Finish {
            reflection: DVec3::splat(0.2),
            ..finish(0.1, 0.7)
        },
        None,
    );
    let ball = |centre: DVec3, pigment: Colour, ior: Option<f64>, finish: Finish| {
        let shape = Shape::Sphere {
            centre,
            radius: 0.8,
        };
        textured(shape, Pigment::Solid(pigment), finish, ior)
    };
    let shiny = Finish {
        phong: 0.8,
        specular: 0.4,
        metallic: 0.5,
        ..Finish::default()
    };
    let mut spot = point_light(DVec3::new(3.0, 5.0, -2.0));
    spot.spotlight = Some(crate::scene::Spotlight {
        point_at: DVec3::ZERO,
        radius: 15.0,
        falloff: 30.0,
        tightness: 5.0,
        cylinder: false,
    });
    let mut busy = scene(
        vec![
            floor,
            ball(
                DVec3::new(-1.5, 0.0, 0.0),
                Colour::rgb(0.9, 0.3, 0.1),
                None,
                shiny,
            ),
            ball(
                DVec3::new(0.0, 0.0, -1.0),
                Colour::rgbft(0.9, 0.9, 1.0, 0.8, 0.1),
                Some(1.5),
                Finish {
                    reflection: DVec3::splat(0.1),
                    ..finish(0.0, 0.1)
                },
            ),
            ball(DVec3::new(1.5, 0.0, 0.5), Colour::grey(0.3), None, {
                Finish {
                    reflection: DVec3::new(0.8, 0.7, 0.6),
                    ..finish(0.0, 0.3)
                }
            }),
        ],
        vec![point_light(DVec3::new(-4.0, 6.0, -5.0)), spot],
        version_37(),
    );
    busy.background = Colour::rgb(0.3, 0.4, 0.6);
    busy.camera.location = DVec3::new(0.0, 1.0, -6.0);
    busy
}

/// `scene` rendered at `width` x `height` without anti-aliasing on a pool of `threads`.
fn render_on_threads(scene: &Scene, width: u32, height: u32, threads: usize) -> Image {
    let world = World::build(scene);
    let options = RenderOptions::new(width, height);
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| render(scene, &world, &options, &|_| {}))
}

#[test]
fn same_image_with_one_and_four_threads() {
    let busy = busy_scene();
    let single = render_on_threads(&busy, 48, 36, 1);
    let four = render_on_threads(&busy, 48, 36, 4);
    assert_eq!(single, four);
    // The scene is not trivially black.
    assert!(
        single
            .pixels
            .iter()
            .filter(|p| p.iter().any(|&c| c > 40))
            .count()
            > 500
    );
}

#[test]
fn radiosity_final_pass_is_the_same_with_one_and_three_threads() {
    let mut busy = busy_scene();
    // A coarse pretrace and a low error bound: the final pass gathers and stores most samples.
    busy.settings.radiosity = Some(crate::scene::RadiositySettings {
        count: 12,
        direction_pool: 12,
        error_bound: 0.3,
        pretrace_start: 0.25,
        pretrace_end: 0.25,
        ..Default::default()
    });
    assert_eq!(
        render_on_threads(&busy, 40, 30, 1),
        render_on_threads(&busy, 40, 30, 3)
    );
}

#[test]
fn radiosity_pretrace_with_deep_bounces_is_the_same_with_one_two_and_seven_threads() {
    let mut busy = busy_scene();
    // A fine pretrace, three bounces and a windowed direction pool: the pretrace's batches
    // of parallel rays gather most samples, deeper ones included.
    busy.settings.radiosity = Some(crate::scene::RadiositySettings {
        count: 40,
        direction_pool: 400,
        recursion_limit: 3,
        error_bound: 0.4,
        pretrace_start: 0.2,
        pretrace_end: 0.05,
        ..Default::default()
    });
    let single = render_on_threads(&busy, 40, 30, 1);
    assert_eq!(single, render_on_threads(&busy, 40, 30, 2));
    assert_eq!(single, render_on_threads(&busy, 40, 30, 7));
}

#[test]
fn progress_counts_every_row() {
    let busy = busy_scene();
    let world = World::build(&busy);
    let rows = AtomicU32::new(0);
    let options = RenderOptions {
        width: 8,
        height: 7,
        antialias: None,
        region: None,
        alpha: false,
        quality: Default::default(),
    };
    let image = render(&busy, &world, &options, &|n| {
        rows.fetch_add(n, Ordering::Relaxed);
    });
    assert_eq!(rows.load(Ordering::Relaxed), 7);
    assert_eq!(image.pixels.len(), 56);
}

#[test]
fn hostile_values_do_not_panic() {
    let mut broken = busy_scene();
    broken.camera.direction = DVec3::splat(f64::NAN);
    broken.lights[0].position = DVec3::splat(f64::INFINITY);
    broken.lights[1].colour = DVec3::splat(f64::NAN);
    broken.settings.max_trace_level = u32::MAX;
    broken.settings.adc_bailout = f64::NAN;
    broken.settings.assumed_gamma = Some(-1.0);
    let world = World::build(&broken);
    let image = render(
        &broken,
        &world,
        &RenderOptions {
            width: 4,
            height: 3,
            antialias: None,
            region: None,
            alpha: false,
            quality: Default::default(),
        },
        &|_| {},
    );
    assert_eq!(image.pixels.len(), 12);
    let empty = render(
        &broken,
        &world,
        &RenderOptions {
            width: 0,
            height: 3,
            antialias: None,
            region: None,
            alpha: false,
            quality: Default::default(),
        },
        &|_| {},
    );
    assert!(empty.pixels.is_empty());

    let mut odd_finish = busy_scene();
    odd_finish.camera.location = DVec3::new(0.0, 0.0, -1.0);
    for object in &mut odd_finish.objects {
        object.texture = Some(Arc::new(Texture {
            pigment: Pigment::Solid(Colour::rgbft(f64::NAN, 2.0, -1.0, 0.5, f64::INFINITY)),
            finish: Arc::new(Finish {
                roughness: 0.0,
                phong: 1.0,
                specular: 1.0,
                phong_size: f64::NAN,
                brilliance: -3.0,
                ..Finish::default()
            }),
            ..Texture::default()
        }));
        object.interior = Some(Box::new(Interior {
            ior: 0.0,
            ..Interior::default()
        }));
    }
    let world = World::build(&odd_finish);
    let image = render(
        &odd_finish,
        &world,
        &RenderOptions {
            width: 5,
            height: 4,
            antialias: None,
            region: None,
            alpha: false,
            quality: Default::default(),
        },
        &|_| {},
    );
    assert_eq!(image.pixels.len(), 20);
}
