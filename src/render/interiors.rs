//! The objects a ray is inside: the stack of interiors camera rays and photons carry, so
//! that entering and leaving a surface, the indices of refraction on both sides and the
//! media around a ray are decided by what the ray went through, not by the side of the
//! surface it meets.
//!
//! In: materials entered and left, the [`World`] for a ray's starting point. Out:
//! [`InteriorStack`]. Holds: a fixed array, no allocation.

use super::optics::sanitise_ior;
use crate::geometry::World;
use glam::DVec3;

/// How many nested objects a ray remembers; deeper nesting forgets the outermost.
const INTERIOR_STACK_DEPTH: usize = 16;

/// The objects (by material) a ray is inside, innermost last, with their indices of refraction.
#[derive(Clone, Copy, Debug)]
pub struct InteriorStack {
    entries: [(u32, f64); INTERIOR_STACK_DEPTH],
    len: usize,
    /// For a ray of one dispersion band: the exponent applied to `dispersion`.
    pub(super) band: Option<f64>,
    /// The ray started inside a non-hollow object it does not know about (the camera is
    /// inside one): no fog or media anywhere along it.
    pub(super) in_solid: bool,
    /// Radiosity bounces behind the ray (0 for camera rays and their continuations).
    pub(super) radiosity_depth: u32,
    /// The ray descends from a mirror reflection: the background it meets counts as
    /// opaque for the alpha channel (POV-Ray: reflections of the background are not
    /// transparent).
    pub(super) reflected: bool,
}

impl InteriorStack {
    /// A ray in empty space (index of refraction 1).
    pub const OUTSIDE: InteriorStack = InteriorStack {
        entries: [(0, 1.0); INTERIOR_STACK_DEPTH],
        len: 0,
        band: None,
        in_solid: false,
        radiosity_depth: 0,
        reflected: false,
    };

    /// The same stack for a mirror-reflected ray.
    pub(super) fn reflected(self) -> InteriorStack {
        InteriorStack {
            reflected: true,
            ..self
        }
    }

    /// The same stack for a ray `depth` radiosity bounces behind.
    pub(super) fn at_radiosity_depth(self, depth: u32) -> InteriorStack {
        InteriorStack {
            radiosity_depth: depth,
            ..self
        }
    }

    /// Index of refraction of the innermost medium.
    pub(super) fn ior(&self) -> f64 {
        match self.len {
            0 => 1.0,
            n => self.entries[n - 1].1,
        }
    }

    /// The materials of the objects the ray is in, innermost first.
    pub(super) fn materials_innermost_first(&self) -> impl Iterator<Item = u32> + '_ {
        self.entries[..self.len].iter().rev().map(|entry| entry.0)
    }

    /// The materials of the objects the ray is in, in the order it entered them.
    pub(super) fn materials_outermost_first(&self) -> impl Iterator<Item = u32> + '_ {
        self.entries[..self.len].iter().map(|entry| entry.0)
    }

    /// Whether the ray is inside an object with this material.
    pub(super) fn contains(&self, material: u32) -> bool {
        self.entries[..self.len]
            .iter()
            .any(|entry| entry.0 == material)
    }

    /// The stack after entering an object with this material and index.
    pub(super) fn entered(&self, material: u32, ior: f64) -> InteriorStack {
        let mut stack = *self;
        if stack.len == INTERIOR_STACK_DEPTH {
            stack.entries.copy_within(1.., 0);
            stack.len -= 1;
        }
        stack.entries[stack.len] = (material, ior);
        stack.len += 1;
        stack
    }

    /// The stack after leaving an object with this material (unchanged when the ray was not
    /// known to be inside it, e.g. a camera inside an object).
    pub(super) fn left(&self, material: u32) -> InteriorStack {
        let mut stack = *self;
        if let Some(at) = stack.entries[..stack.len]
            .iter()
            .rposition(|entry| entry.0 == material)
        {
            stack.entries.copy_within(at + 1..stack.len, at);
            stack.len -= 1;
        }
        stack
    }
}

/// The stack of a ray starting at `point`: inside every object around it, outermost first
/// (measured: a camera inside a hollow sphere of media sees the media from its first step).
pub(super) fn interiors_around(world: &World, point: DVec3) -> InteriorStack {
    let start = InteriorStack {
        in_solid: world.inside_solid(point),
        ..InteriorStack::OUTSIDE
    };
    world
        .materials_around(point)
        .into_iter()
        .fold(start, |stack, id| {
            let ior = world
                .materials
                .get(id as usize)
                .map_or(1.0, |material| sanitise_ior(material.interior.ior));
            stack.entered(id, ior)
        })
}
