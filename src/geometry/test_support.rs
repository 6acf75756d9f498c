//! Test helpers for any shape's own unit tests and for the tests in [`tests`](super::tests):
//! a seeded random generator and the check that crossings flip a shape's inside test.
//!
//! In: seeds, a shape's intersect and inside functions. Out: random numbers, points, rays and
//! transforms; a panic when two crossings do not bound a change of side.
//! Holds: everything is deterministic for a given seed. It sits beside the shape files, not
//! in `tests/`, because the shapes' unit tests use it and `tests/` uses the shapes: keeping
//! it here keeps geometry's file graph free of circles.

use super::Ray;
use crate::math::Transform;
use glam::DVec3;

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
