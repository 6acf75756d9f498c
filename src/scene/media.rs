//! Participating media: particles that absorb, emit and scatter light inside objects or in
//! the whole scene.
//!
//! In: nothing (data definition). Out: [`Media`] and its parts. Holds: values are final
//! (defaults filled in, counts clamped to usable ranges); density pigments are in the space
//! of whatever holds the media (world space once the scene is built).

use crate::{math::Transform, texture::Pigment};
use glam::DVec3;

/// One `media { }` block.
#[derive(Clone, Debug)]
pub struct Media {
    /// `method`: 1 and 2 are legacy methods, 3 (the default) samples adaptively.
    pub method: u32,
    /// `intervals` (default 1).
    pub intervals: u32,
    /// `samples min, max` (default 10, 10: measured, where the manual says 1, 1).
    pub samples: (u32, u32),
    /// `confidence` (default 0.9).
    pub confidence: f64,
    /// `variance` (default 1/128).
    pub variance: f64,
    /// `ratio` (default 0.9).
    pub ratio: f64,
    /// `jitter` (default 0).
    pub jitter: f64,
    /// `aa_threshold` (default 0.1): sample differences above it are subdivided.
    pub aa_threshold: f64,
    /// `aa_level` (default 3): how deep method 3 subdivides.
    pub aa_level: u32,
    /// `absorption`: light taken out per unit length.
    pub absorption: DVec3,
    /// `emission`: light given off per unit length.
    pub emission: DVec3,
    /// `scattering { }`, if any.
    pub scattering: Option<Scattering>,
    /// `density { }` blocks; their values multiply (none: density 1 everywhere).
    pub densities: Vec<Pigment>,
}

impl Default for Media {
    fn default() -> Self {
        Media {
            method: 3,
            intervals: 1,
            samples: (10, 10),
            confidence: 0.9,
            variance: 1.0 / 128.0,
            ratio: 0.9,
            jitter: 0.0,
            aa_threshold: 0.1,
            aa_level: 3,
            absorption: DVec3::ZERO,
            emission: DVec3::ZERO,
            scattering: None,
            densities: Vec::new(),
        }
    }
}

impl Media {
    /// Composes `t` into the densities written so far (as POV-Ray does: later densities
    /// are not moved).
    pub fn transform(&mut self, t: &Transform) {
        for density in &mut self.densities {
            density.transform(t);
        }
    }

    /// True when the media takes light out of rays (absorption or scattering extinction).
    pub fn extinguishes(&self) -> bool {
        self.absorption != DVec3::ZERO
            || self
                .scattering
                .as_ref()
                .is_some_and(|s| s.extinction != 0.0 && s.colour != DVec3::ZERO)
    }
}

/// `scattering { type, colour [eccentricity e] [extinction x] }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scattering {
    /// The phase function.
    pub kind: ScatteringKind,
    /// How much light is scattered per unit length.
    pub colour: DVec3,
    /// `extinction` (default 1): how much of the scattering also dims the ray.
    pub extinction: f64,
}

/// POV-Ray's scattering phase functions (types 1 to 5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ScatteringKind {
    /// Type 1: the same in every direction.
    Isotropic,
    /// Type 2: Mie scattering by haze.
    MieHazy,
    /// Type 3: Mie scattering in a murky atmosphere (more forward).
    MieMurky,
    /// Type 4: Rayleigh scattering by molecules.
    Rayleigh,
    /// Type 5: Henyey-Greenstein with this `eccentricity`.
    HenyeyGreenstein(f64),
}
