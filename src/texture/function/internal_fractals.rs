//! The noise fractals of functions.inc: `f_hetero_mf`, `f_ridged_mf` and `f_ridge`, built from
//! durer's solid noise so they match povray's.
//!
//! In: the point and the fractal's parameters. Out: the field value; the octave sums were
//! recovered from values povray 3.7 prints with `#debug` next to `f_noise_generator` at the
//! octaves' points. Holds: pure functions, no allocation.
//!
//! povray caches each fractal's octave weights between calls and, measured, does not always
//! refresh them when only `H` changes; durer always uses the weights of the call's own
//! parameters, which is what a scene with one set of parameters per fractal gets in povray.

use crate::noise::{noise, NoiseGenerator};
use glam::DVec3;

/// The most octaves summed; more only adds noise finer than a double can resolve.
const MAX_OCTAVES: f64 = 64.0;

/// The parameters shared by the two multifractals.
#[derive(Clone, Copy, Debug)]
pub struct Multifractal {
    /// `H`: octave `i` is weighted by `lacunarity^(-H i)`.
    pub dimension: f64,
    /// The frequency factor from one octave to the next.
    pub lacunarity: f64,
    /// The number of octaves (the hetero fractal adds a fraction of the last).
    pub octaves: f64,
    /// The base altitude added to each octave's noise.
    pub offset: f64,
    /// `f_hetero_mf`'s `T` or `f_ridged_mf`'s gain.
    pub control: f64,
    /// The noise generator number.
    pub generator: f64,
}

/// The noise generator a function parameter selects: povray keeps the two low bits of the
/// truncated number, and 0 means generator 1 (measured: -1 is 3, 4 is 1, 2.7 is 2).
pub fn generator_parameter(value: f64) -> NoiseGenerator {
    let bits = (value as i64) & 3;
    NoiseGenerator::from_number(bits.max(1)).unwrap_or_default()
}

/// Signed noise in [-1, 1] with the generator a function parameter selects.
fn signed_noise(point: DVec3, generator: f64) -> f64 {
    2.0 * noise(point, generator_parameter(generator)) - 1.0
}

/// `f_hetero_mf`: each octave's `noise + offset`, weighted, scaled by the sum so far raised to
/// the whole part of `T` (povray multiplies it in once per whole unit of T); a fractional last
/// octave is scaled by the sum so far once, whatever `T` (measured).
pub fn hetero_multifractal(point: DVec3, fractal: Multifractal) -> f64 {
    let octaves = fractal.octaves.min(MAX_OCTAVES);
    let heterogeneity = fractal.control.floor().clamp(0.0, MAX_OCTAVES) as i32;
    let octave_term = |frequency: f64| {
        (signed_noise(point * frequency, fractal.generator) + fractal.offset)
            * frequency.powf(-fractal.dimension)
    };
    let mut value = signed_noise(point, fractal.generator) + fractal.offset;
    let mut frequency = fractal.lacunarity;
    let mut octave = 1.0;
    while octave < octaves {
        value += octave_term(frequency) * value.powi(heterogeneity);
        frequency *= fractal.lacunarity;
        octave += 1.0;
    }
    let remainder = octaves - octaves.floor();
    if remainder > 0.0 {
        value += remainder * octave_term(frequency) * value;
    }
    value
}

/// `f_ridged_mf`: Musgrave's ridged multifractal, `(offset - |noise|)²` per octave, each octave
/// weighted by the previous one times the gain (clamped to [0, 1]).
pub fn ridged_multifractal(point: DVec3, fractal: Multifractal) -> f64 {
    let octaves = fractal.octaves.min(MAX_OCTAVES);
    let ridge = |frequency: f64| {
        let signal = fractal.offset - signed_noise(point * frequency, fractal.generator).abs();
        signal * signal
    };
    let mut signal = ridge(1.0);
    let mut value = signal;
    let mut frequency = fractal.lacunarity;
    let mut octave = 1.0;
    while octave < octaves {
        let weight = (signal * fractal.control).clamp(0.0, 1.0);
        signal = ridge(frequency) * weight;
        value += signal * frequency.powf(-fractal.dimension);
        frequency *= fractal.lacunarity;
        octave += 1.0;
    }
    value
}

/// `f_ridge(x,y,z, lambda, octaves, omega, offset, ridge, generator)`: the weighted mean of
/// the octaves' ridged noise `|1 - noise / ridge|` (plain noise when `ridge` is 0), octave `i`
/// at frequency `lambda^i` weighted `omega^i` (the last by its fraction), then shifted by
/// `offset` and scaled by the larger of `offset` and `1 - offset`.
pub fn ridge(point: DVec3, parameters: [f64; 6]) -> f64 {
    let [lambda, octaves, omega, offset, ridge, generator] = parameters;
    let octaves = octaves.clamp(1.0, MAX_OCTAVES);
    let generator = generator_parameter(generator);
    let (mut total, mut weights) = (0.0, 0.0);
    let (mut frequency, mut amplitude, mut octave) = (1.0, 1.0, 0.0);
    while octave < octaves {
        let value = noise(point * frequency, generator);
        let ridged = if ridge == 0.0 {
            value
        } else {
            (1.0 - value / ridge).abs()
        };
        let weight = amplitude * (octaves - octave).min(1.0);
        total += weight * ridged;
        weights += weight;
        frequency *= lambda;
        amplitude *= omega;
        octave += 1.0;
    }
    (total / weights - offset) / offset.max(1.0 - offset)
}
