//! Noise generator 3 — not reproduced yet: until it is, it falls back to generator 1's
//! lattice noise.

use glam::DVec3;

/// Generator 3's noise at `point`, in [0, 1] (for now generator 1's noise).
pub(super) fn noise(point: DVec3) -> f64 {
    super::noise(point, super::NoiseGenerator::Original)
}
