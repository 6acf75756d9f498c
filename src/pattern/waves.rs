//! The wave sources of the `ripples` and `waves` patterns: ten centres on the unit sphere,
//! each with its own frequency (used by `waves` only).
//!
//! In: nothing (the sources are fixed). Out: the table, built once on first use. Holds: one
//! process-wide immutable table, safe to read from any thread.
//!
//! Measured black-box against POV-Ray 3.7 (`scripts/probe-waves.py`; values of
//! `function { pattern { ripples } }` and `waves` at random points fit to ~1e-16):
//! - centre `i` is POV-Ray's vector noise at `<i, 0, 0>`, normalised (povray's own
//!   `vturbulence(2, 0.5, 1, <i, 0, 0>)` gives the same directions);
//! - frequency `i` is `nᵢ / 32767 + 0.01`, where `nᵢ = (s >> 16) & 0x7FFF` and `s` steps
//!   through the LCG `s = s·1812433253 + 12345 (mod 2³²)` from the seed `−560851967`
//!   (one step before each draw).
//!
//! Both are independent of `noise_generator` (the vector noise is the same for every
//! generator).

use std::sync::OnceLock;

use glam::DVec3;

use crate::noise::{vector_noise, NoiseGenerator};

/// How many wave sources `ripples` and `waves` use (POV-Ray's fixed count).
pub const WAVE_COUNT: usize = 10;

/// The LCG state before the first frequency draw (`−560851967` as an unsigned 32-bit value).
const FREQUENCY_SEED: u32 = (-560_851_967_i32) as u32;

/// One wave source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveSource {
    /// Where the waves start (a unit vector).
    pub centre: DVec3,
    /// The frequency factor of this source's waves in the `waves` pattern, in [0.01, 1.01].
    pub frequency: f64,
}

/// The ten wave sources (built on first use, then shared).
pub fn wave_sources() -> &'static [WaveSource; WAVE_COUNT] {
    static SOURCES: OnceLock<[WaveSource; WAVE_COUNT]> = OnceLock::new();
    SOURCES.get_or_init(build_sources)
}

fn build_sources() -> [WaveSource; WAVE_COUNT] {
    let mut state = FREQUENCY_SEED;
    std::array::from_fn(|index| {
        let direction = vector_noise(
            DVec3::new(index as f64, 0.0, 0.0),
            NoiseGenerator::default(),
        );
        state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
        let draw = (state >> 16) & 0x7FFF;
        WaveSource {
            centre: direction.try_normalize().unwrap_or(DVec3::X),
            frequency: f64::from(draw) / 32767.0 + 0.01,
        }
    })
}

/// The distance from `point` to a wave centre, as POV-Ray uses it: a point exactly at the
/// centre counts as distance 1.
pub fn distance_to_centre(point: DVec3, source: &WaveSource) -> f64 {
    let distance = point.distance(source.centre);
    if distance == 0.0 {
        1.0
    } else {
        distance
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frequencies_match_the_measured_ones() {
        // Fitted from povray's `waves` values (least squares, residual 5e-16).
        let measured = [
            0.919_115_878_780_564,
            0.960_041_199_987_88,
            0.433_169_652_394_216,
            0.709_301_126_133_064,
            0.689_189_428_388_38,
            0.991_444_746_238_684,
            0.782_972_808_008_128,
            0.400_667_439_802_276,
            0.229_672_231_208_248,
            0.168_513_138_218_344,
        ];
        for (source, expected) in wave_sources().iter().zip(measured) {
            assert!((source.frequency - expected).abs() < 1e-12);
        }
    }

    #[test]
    fn centres_are_unit_vectors() {
        for source in wave_sources() {
            assert!((source.centre.length() - 1.0).abs() < 1e-12);
        }
    }
}
