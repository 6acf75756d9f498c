//! Noise generator 3 ("Perlin noise" in POV-Ray's manual), as measured from POV-Ray 3.7.
//!
//! In: a point in pattern space. Out: the noise value in [0, 1]. Holds: the measured tables in
//! `perlin_tables.rs`; no allocation.
//!
//! What the probes showed (`scripts/probe-noise.py --perlin-tables` measures and writes the
//! tables): gradient noise on a lattice whose cells start `LATTICE_SHIFT` below the integers,
//! the cubic ease curve 3t² − 2t³ for the weights, unit gradients repeating every 2048 cells
//! on each axis, and the value `0.4925 + 0.795 · Σ weight · gradient · (point − corner)`
//! clamped to [0, 1]. The gradient of corner (x, y, z) is
//! `GRADIENTS[(Y_STAGE[(X_STAGE[x] + y) mod 2048] + z) mod 2048]`: the three stages were read
//! off gradients measured along lattice lines in z, y and x. Gradients and shift are measured
//! values themselves, so results match POV-Ray to about 1.2e-8 (worst seen on 1200 random
//! probes), not to the last bit; POV-Ray's own values also carry about 1e-10 of rounding noise
//! from a large internal coordinate offset (its cell fractions step by 2⁻²⁹).

use super::perlin_tables::{GRADIENTS, LATTICE_SHIFT, X_STAGE, Y_STAGE};
use glam::DVec3;

/// Cells after which the gradients repeat, on every axis.
const PERIOD: i64 = 2048;

/// Generator 3's output mapping: `OFFSET + SCALE · gradient noise`.
const SCALE: f64 = 0.795;
const OFFSET: f64 = 0.4925;

/// The cubic ease curve 3t² − 2t³.
fn smooth(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// The lattice cell (reduced modulo the period) and the fraction inside it of one coordinate.
/// Non-finite or astronomically large coordinates land in cell 0 (their value is meaningless
/// in POV-Ray too) rather than overflowing.
fn cell(coordinate: f64) -> (i64, f64) {
    let shifted = coordinate + LATTICE_SHIFT;
    let floor = shifted.floor();
    if !floor.is_finite() || floor.abs() > 1e15 {
        return (0, 0.0);
    }
    ((floor as i64).rem_euclid(PERIOD), shifted - floor)
}

/// The gradient at lattice corner (x, y, z), each already reduced modulo the period.
fn gradient(x: i64, y: i64, z: i64) -> DVec3 {
    let row = (i64::from(X_STAGE[x as usize]) + y) % PERIOD;
    let index = (i64::from(Y_STAGE[row as usize]) + z) % PERIOD;
    DVec3::from_array(GRADIENTS[index as usize])
}

/// Generator 3's noise at `point`, in [0, 1].
pub(super) fn noise(point: DVec3) -> f64 {
    let (ix, fx) = cell(point.x);
    let (iy, fy) = cell(point.y);
    let (iz, fz) = cell(point.z);
    let eased = DVec3::new(smooth(fx), smooth(fy), smooth(fz));
    let fraction = DVec3::new(fx, fy, fz);
    let mut sum = 0.0;
    for corner in 0..8 {
        let offset = DVec3::new(
            (corner & 1) as f64,
            ((corner >> 1) & 1) as f64,
            ((corner >> 2) & 1) as f64,
        );
        // Trilinear weight of this corner: the eased fraction toward it on each axis.
        let toward = DVec3::ONE - offset + eased * (2.0 * offset - DVec3::ONE);
        let weight = toward.x * toward.y * toward.z;
        let g = gradient(
            (ix + (corner & 1)) % PERIOD,
            (iy + ((corner >> 1) & 1)) % PERIOD,
            (iz + ((corner >> 2) & 1)) % PERIOD,
        );
        sum += weight * g.dot(fraction - offset);
    }
    super::clamp_unit(OFFSET + SCALE * sum)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_points_give_the_offset() {
        // At a lattice point every corner term vanishes.
        let corner = DVec3::new(3.0, -2.0, 7.0) - DVec3::splat(LATTICE_SHIFT);
        assert!((noise(corner) - OFFSET).abs() < 1e-12);
    }

    #[test]
    fn gradients_are_unit_vectors() {
        for g in GRADIENTS.iter() {
            assert!((DVec3::from_array(*g).length() - 1.0).abs() < 1e-6);
        }
    }

    #[test]
    fn far_points_do_not_panic() {
        for coordinate in [1e300, -1e300, f64::INFINITY, f64::NAN, 3e9, -3e9] {
            let _ = noise(DVec3::splat(coordinate));
        }
    }
}
