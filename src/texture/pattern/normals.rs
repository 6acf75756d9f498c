//! Dedicated normal perturbations of the patterns POV-Ray gives one (bumps, dents,
//! wrinkles, ripples, waves, quilted), and the quilted pattern's value.
//!
//! In: a pattern-space point after warps and turbulence. Out: the vector added to the
//! surface normal for a bump size of 1. Holds: pure, allocation-free.
//!
//! The quilted value and normal are measured against POV-Ray 3.7 (the normal as the vector
//! that, times the bump size, is added to the unflipped surface normal before normalising).
//! bumps, dents and wrinkles are measured too (renders of `normal { PATTERN }` on a plane
//! match povray pixel for pixel; reference scene `normal_noise_patterns`). ripples and
//! waves are measured (`scripts/probe-waves.py`: 16-bit linear renders of a plane lit from
//! five directions match to 8e-6; reference scene `normal_waves`).

use std::f64::consts::PI;

use glam::DVec3;

use super::wave::Wave;
use super::waves::{distance_to_centre, WaveSource};
use crate::noise::{noise, vector_noise, NoiseGenerator};

/// `bumps`: the vector noise at the point.
pub fn bumps(point: DVec3, generator: NoiseGenerator) -> DVec3 {
    vector_noise(point, generator)
}

/// `dents`: the vector noise scaled by the cube of the noise.
pub fn dents(point: DVec3, generator: NoiseGenerator) -> DVec3 {
    let depth = noise(point, generator);
    vector_noise(point, generator) * (depth * depth * depth)
}

/// `wrinkles`: ten octaves of the vector noise with every component made positive, each
/// half the weight and twice the frequency of the one before (measured: renders of
/// `normal { wrinkles }` on a plane match povray to 1/255).
pub fn wrinkles(point: DVec3, generator: NoiseGenerator) -> DVec3 {
    let mut sum = DVec3::ZERO;
    let mut weight = 1.0;
    let mut scale = 1.0;
    for _ in 0..10 {
        sum += vector_noise(point * scale, generator).abs() * weight;
        weight *= 0.5;
        scale *= 2.0;
    }
    sum
}

/// `ripples`: the unit directions from the wave centres to the point, each weighted by
/// `sin(2π·(d·frequency + phase))` at its distance `d` (measured).
pub fn ripples(point: DVec3, wave: &Wave, sources: &[WaveSource]) -> DVec3 {
    radial_waves(point, sources, |distance, _| {
        (2.0 * PI * (distance * wave.frequency + wave.phase)).sin()
    })
}

/// `waves`: like ripples with every source's own frequency `fᵢ`: weights
/// `sin(2π·(d·fᵢ·frequency + phase)) / fᵢ` (measured).
pub fn waves(point: DVec3, wave: &Wave, sources: &[WaveSource]) -> DVec3 {
    radial_waves(point, sources, |distance, source_frequency| {
        (2.0 * PI * (distance * source_frequency * wave.frequency + wave.phase)).sin()
            / source_frequency
    })
}

/// The mean over the wave sources of the unit direction from the centre to the point times
/// `weight(distance, source frequency)`. A point at a centre gets nothing from that source.
fn radial_waves(point: DVec3, sources: &[WaveSource], weight: impl Fn(f64, f64) -> f64) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for source in sources {
        let offset = point - source.centre;
        let distance = distance_to_centre(point, source);
        sum += offset * (weight(distance, source.frequency) / distance);
    }
    sum / sources.len() as f64
}

/// The cubic Bézier from 0 to 1 with control values `control0` and `control1`.
fn quilt_curve(t: f64, control0: f64, control1: f64) -> f64 {
    let s = 1.0 - t;
    t * t * t + 3.0 * t * t * s * control1 + 3.0 * t * s * s * control0
}

/// `2/√3`: 1 over the distance from a unit cube's centre to its corners.
const QUILTED_SCALE: f64 = 1.154_700_538_379_251_7;

/// The quilted vector: the offset `v` of the point from the centre of its unit cube, scaled
/// by `curve(|v|) · 2/√3`.
fn quilted_vector(point: DVec3, control0: f64, control1: f64) -> DVec3 {
    let offset = point - point.floor() - DVec3::splat(0.5);
    offset * (quilt_curve(offset.length(), control0, control1) * QUILTED_SCALE)
}

/// `quilted` as a pigment: the mean of the absolute components of the quilted vector
/// (measured against POV-Ray 3.7).
pub fn quilted_value(point: DVec3, control0: f64, control1: f64) -> f64 {
    quilted_vector(point, control0, control1)
        .abs()
        .element_sum()
        / 3.0
}

/// `quilted` as a normal: the quilted vector, tilting the normal away from each cube's
/// centre (measured against POV-Ray 3.7: normals recovered from renders of a perturbed
/// plane lit from three directions, seen from both sides, bump sizes 1 and 5).
pub fn quilted(point: DVec3, control0: f64, control1: f64) -> DVec3 {
    quilted_vector(point, control0, control1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quilted_values_match_povray() {
        // POV-Ray's `quilted` with several controls at (-1.3, 0.4, 0.2) and along lines.
        let p = DVec3::new(-1.3, 0.4, 0.2);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-5;
        assert!(close(quilted_value(p, 1.0, 1.0), 0.17433));
        assert!(close(quilted_value(p, 0.0, 0.0), 0.01210));
        assert!(close(quilted_value(p, 0.3, 0.7), 0.08505));
        assert!(close(
            quilted_value(DVec3::new(0.1, 0.5, 0.5), 1.0, 0.0),
            0.076364
        ));
        assert!(close(
            quilted_value(DVec3::new(0.25, 0.5, 0.5), 0.0, 1.0),
            0.015035
        ));
        assert!(close(quilted_value(DVec3::splat(0.45), 0.0, 0.0), 0.000037));
    }

    #[test]
    fn quilted_normal_matches_povray() {
        // Normals recovered from POV-Ray renders of `normal { quilted 5 control0 0
        // control1 0 }` on the plane z = 0.25, lit from three directions, seen from -z and
        // from +z: the facing normal plus 5 times the perturbation, normalised.
        let close = |a: DVec3, b: DVec3| (a - b).abs().max_element() < 2e-3;
        let seen =
            |facing: DVec3, point: DVec3| (facing + 5.0 * quilted(point, 0.0, 0.0)).normalize();
        let from_front = seen(-DVec3::Z, DVec3::new(0.953125, 0.484375, 0.25));
        assert!(close(from_front, DVec3::new(0.2895, -0.0100, -0.9571)));
        let from_behind = seen(DVec3::Z, DVec3::new(0.984375, 0.484375, 0.25));
        assert!(close(from_behind, DVec3::new(0.5094, -0.0164, 0.8604)));
    }

    #[test]
    fn perturbations_are_finite() {
        let wave = Wave::new(crate::texture::pattern::WaveShape::Ramp);
        let generator = NoiseGenerator::default();
        let p = DVec3::new(0.3, -2.0, 5.5);
        let sources = crate::texture::pattern::waves::WaveSources::default();
        let sources = sources.as_slice();
        assert!(ripples(p, &wave, sources).is_finite());
        assert!(waves(p, &wave, sources).is_finite());
        // A point at a wave centre gets nothing from that source.
        let centre = sources[0].centre;
        assert!(ripples(centre, &wave, sources).is_finite());
        assert!(waves(centre, &wave, sources).is_finite());
        assert!(quilted(p, 1.0, 1.0).is_finite());
        assert!(wrinkles(p, generator).is_finite());
    }
}
