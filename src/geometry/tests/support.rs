//! World-level helpers shared by the geometry tests: scene builders, marked textures that tell
//! objects apart, random shapes and CSG trees, a ray walker collecting every hit along a ray,
//! and the small fixtures (two overlapping spheres, a slab) several subjects use.
//!
//! In: seeds, shapes, objects. Out: scenes, random shapes and CSG trees, hit sequences.
//! Holds: everything is deterministic for a given seed.

use crate::geometry::test_support::Random;
use crate::geometry::{Ray, SurfaceHit, World};
use crate::{
    math::Colour,
    scene::{CsgOperation, Object, Scene, Shape},
    texture::{Pigment, Texture},
};
use glam::DVec3;
use std::sync::Arc;

/// A scene holding just `objects`.
pub fn scene_of(objects: Vec<Object>) -> Scene {
    Scene {
        camera: Default::default(),
        lights: Vec::new(),
        objects,
        background: Colour::BLACK,
        atmosphere: Default::default(),
        settings: Default::default(),
    }
}

/// A solid-colour texture whose red channel tells objects apart.
pub fn marked_texture(mark: f64) -> Arc<Texture> {
    Arc::new(Texture {
        pigment: Pigment::Solid(Colour::rgb(mark, 0.0, 0.0)),
        ..Texture::default()
    })
}

/// The red channel of a hit's solid pigment, identifying the object that was hit.
pub fn mark_of(world: &World, hit: &SurfaceHit) -> f64 {
    match world.materials[hit.material as usize].texture.pigment {
        Pigment::Solid(colour) => colour.red,
        _ => f64::NAN,
    }
}

/// An object with a marked texture.
pub fn marked(shape: Shape, mark: f64) -> Object {
    let mut object = Object::new(shape);
    object.texture = Some(marked_texture(mark));
    object
}

/// A CSG object from an operation and children.
pub fn csg(operation: CsgOperation, children: Vec<Object>) -> Object {
    Object::new(Shape::Csg {
        operation,
        children,
    })
}

/// Every hit along `ray` from distance zero, in order, by repeated nearest-hit queries.
pub fn all_hits(world: &World, ray: &Ray) -> Vec<SurfaceHit> {
    let mut hits = Vec::new();
    let mut from = 0.0;
    while let Some(hit) = world.first_hit(ray, from, f64::INFINITY) {
        from = hit.distance;
        hits.push(hit);
        if hits.len() > 64 {
            break;
        }
    }
    hits
}

/// A random non-CSG shape of any kind, roughly within the unit cube.
pub fn random_shape(random: &mut Random) -> Shape {
    match random.index(10) {
        0 => Shape::Sphere {
            centre: random.vector(0.5),
            radius: random.range(0.2, 1.0),
        },
        1 => Shape::Box {
            corner1: random.vector(1.0),
            corner2: random.vector(1.0),
        },
        2 => Shape::Cylinder {
            base: random.vector(1.0),
            cap: random.vector(1.0),
            radius: random.range(0.1, 0.6),
            open: random.next() < 0.3,
        },
        3 => Shape::Cone {
            base: random.vector(1.0),
            base_radius: random.range(0.0, 0.7),
            cap: random.vector(1.0),
            cap_radius: random.range(0.0, 0.7),
            open: random.next() < 0.3,
        },
        4 => Shape::Torus {
            major: random.range(0.3, 0.8),
            minor: random.range(0.05, 0.3),
        },
        5 => Shape::Disc {
            centre: random.vector(0.5),
            normal: random.unit_vector(),
            radius: random.range(0.3, 1.0),
            hole_radius: random.range(0.0, 0.2),
        },
        6 => Shape::Triangle {
            corners: Box::new([random.vector(1.0), random.vector(1.0), random.vector(1.0)]),
        },
        7 => Shape::Plane {
            normal: random.unit_vector(),
            distance: random.range(-0.5, 0.5),
        },
        8 => Shape::Quadric {
            coefficients: Box::new([
                random.range(0.5, 2.0),
                random.range(-1.0, 2.0),
                random.range(0.5, 2.0),
                random.range(-0.5, 0.5),
                random.range(-0.5, 0.5),
                random.range(-0.5, 0.5),
                random.range(-0.3, 0.3),
                random.range(-0.3, 0.3),
                random.range(-0.3, 0.3),
                -random.range(0.3, 1.0),
            ]),
        },
        _ => Shape::Sphere {
            centre: random.vector(1.0),
            radius: random.range(0.05, 0.3),
        },
    }
}

/// A random CSG tree up to `depth` levels deep, with random transforms and inversions.
pub fn random_csg(random: &mut Random, depth: usize) -> Object {
    let count = 2 + random.index(2);
    let children = (0..count)
        .map(|_| {
            let mut child = if depth > 0 && random.next() < 0.3 {
                random_csg(random, depth - 1)
            } else {
                marked(random_shape(random), random.next())
            };
            child.set_transform(random.transform());
            child.inverse = random.next() < 0.15;
            child
        })
        .collect();
    let operation = [
        CsgOperation::Union,
        CsgOperation::Intersection,
        CsgOperation::Difference,
        CsgOperation::Merge,
    ][random.index(4)];
    csg(operation, children)
}

/// Sphere A: centre (-0.5, 0, 0), radius 1; crossed by the x axis at x = -1.5 and 0.5.
pub fn sphere_a() -> Object {
    marked(
        Shape::Sphere {
            centre: DVec3::new(-0.5, 0.0, 0.0),
            radius: 1.0,
        },
        0.25,
    )
}

/// Sphere B: centre (0.5, 0, 0), radius 1; crossed by the x axis at x = -0.5 and 1.5.
pub fn sphere_b() -> Object {
    marked(
        Shape::Sphere {
            centre: DVec3::new(0.5, 0.0, 0.0),
            radius: 1.0,
        },
        0.75,
    )
}

/// The ray along +x from x = -5 used by the truth tables: A at 3.5 and 5.5, B at 4.5 and 6.5.
pub fn along_x() -> Ray {
    Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X)
}

pub fn distances(objects: Vec<Object>, ray: Ray) -> Vec<f64> {
    let world = World::build(&scene_of(objects));
    all_hits(&world, &ray)
        .iter()
        .map(|hit| (hit.distance * 1e9).round() / 1e9)
        .collect()
}

pub fn slab(low: f64, high: f64) -> Object {
    Object::new(Shape::Box {
        corner1: DVec3::new(low, -5.0, -5.0),
        corner2: DVec3::new(high, 5.0, 5.0),
    })
}
