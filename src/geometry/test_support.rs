//! Helpers shared by the geometry tests: a seeded random generator, scene builders and a ray
//! walker collecting every hit along a ray.
//!
//! In: seeds, shapes, objects. Out: scenes, random shapes and rays, hit sequences.
//! Holds: everything is deterministic for a given seed.

use super::{Ray, SurfaceHit, World};
use crate::{
    math::{Colour, Transform},
    scene::{CsgOperation, Object, Scene, Shape},
    texture::{Pigment, Texture},
};
use glam::DVec3;
use std::sync::Arc;

/// A small xorshift generator: deterministic, good enough for tests.
pub struct Random(u64);

impl Random {
    /// A generator from a seed (zero is replaced).
    pub fn new(seed: u64) -> Random {
        Random(seed.max(1))
    }

    /// A uniform number in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A uniform number in [low, high).
    pub fn range(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }

    /// A point in the cube [-scale, scale]³.
    pub fn vector(&mut self, scale: f64) -> DVec3 {
        DVec3::new(
            self.range(-scale, scale),
            self.range(-scale, scale),
            self.range(-scale, scale),
        )
    }

    /// A random unit vector.
    pub fn unit_vector(&mut self) -> DVec3 {
        loop {
            let candidate = self.vector(1.0);
            let length = candidate.length();
            if length > 0.1 && length <= 1.0 {
                return candidate / length;
            }
        }
    }

    /// A random index below `count`.
    pub fn index(&mut self, count: usize) -> usize {
        ((self.next() * count as f64) as usize).min(count.saturating_sub(1))
    }

    /// A ray from a random point in [-scale, scale]³ in a random direction.
    pub fn ray(&mut self, scale: f64) -> Ray {
        Ray::new(self.vector(scale), self.unit_vector())
    }

    /// A random scale, rotation and translation.
    pub fn transform(&mut self) -> Transform {
        let scale = DVec3::new(
            self.range(0.5, 1.5),
            self.range(0.5, 1.5),
            self.range(0.5, 1.5),
        );
        Transform::scaling(scale)
            .unwrap_or(Transform::IDENTITY)
            .then(&Transform::rotation_degrees(self.vector(180.0)))
            .then(&Transform::translation(self.vector(0.5)))
    }
}

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

/// Checks, along 500 seeded random rays, that every pair of crossings `intersect` finds
/// flips the `inside` test: the point midway between two crossings is on the other side from
/// the point just before the first one. Crossings closer than `min_gap` are skipped; origins
/// lie in the cube [-origin_scale, origin_scale]³.
pub fn assert_crossings_flip_inside(
    seed: u64,
    origin_scale: f64,
    min_gap: f64,
    before: f64,
    intersect: impl Fn(DVec3, DVec3, &mut super::roots::Roots),
    inside: impl Fn(DVec3) -> bool,
) {
    let mut state = seed;
    let mut random = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for _ in 0..500 {
        let origin = DVec3::new(random(), random(), random()) * origin_scale;
        let direction = DVec3::new(random(), random(), random());
        let mut roots = super::roots::Roots::new();
        intersect(origin, direction, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        for pair in found.windows(2) {
            if pair[1] - pair[0] < min_gap {
                continue;
            }
            let middle = origin + direction * (0.5 * (pair[0] + pair[1]));
            let just_before = origin + direction * (pair[0] - before);
            assert_ne!(
                inside(middle),
                inside(just_before),
                "crossings {pair:?} from {origin}"
            );
        }
    }
}
