//! POV-Ray's solid noise and turbulence: the functions every noise-based pattern, the
//! `turbulence` modifier, turbulence warps, `vturbulence` and `f_noise3d` are built on.
//!
//! In: points in pattern space. Out: values as POV-Ray 3.7 computes them (measured against
//! povray with `scripts/probe-noise.py`; the known-answer tests hold those measurements).
//! Holds: pure functions of their arguments over constant tables (no global state, no
//! allocation), safe to call from any thread. Also the per-cube random numbers of the `cells`
//! and `crackle` patterns (`cells.rs`), and the handle through which patterns follow the
//! scene's global `noise_generator` (`scene.rs`, the one shared state, written only while
//! parsing).

mod cells;
mod lattice;
mod perlin;
mod perlin_tables;
mod scene;

pub use cells::{cells_value, crackle_feature_point, cube_random_value, cube_random_vector};
pub use scene::SceneNoiseGenerator;

use glam::DVec3;

/// POV-Ray's `noise_generator` choice (global_settings or per pattern; default 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum NoiseGenerator {
    /// 1: the original noise of POV-Ray 3.1 and earlier.
    Original,
    /// 2: the original noise with its range corrected (POV-Ray 3.7's default).
    #[default]
    RangeCorrected,
    /// 3: POV-Ray's "Perlin noise": gradient noise with its own measured tables.
    Perlin,
}

impl NoiseGenerator {
    /// The generator for a `noise_generator` number (1, 2 or 3); `None` for other numbers.
    pub fn from_number(number: i64) -> Option<NoiseGenerator> {
        match number {
            1 => Some(NoiseGenerator::Original),
            2 => Some(NoiseGenerator::RangeCorrected),
            3 => Some(NoiseGenerator::Perlin),
            _ => None,
        }
    }
}

/// `turbulence`'s shape parameters with POV-Ray's defaults (octaves 6, omega 0.5, lambda 2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurbulenceShape {
    /// Number of noise layers added (1 to 10; other counts are clamped into that range).
    pub octaves: u32,
    /// Amplitude factor from one layer to the next.
    pub omega: f64,
    /// Frequency factor from one layer to the next.
    pub lambda: f64,
}

impl Default for TurbulenceShape {
    fn default() -> Self {
        TurbulenceShape {
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        }
    }
}

/// Fewest and most octaves POV-Ray sums (it clamps the count into this range).
const OCTAVE_RANGE: (u32, u32) = (1, 10);

/// Generator 2's range correction, measured: `(sum + SHIFT) · SCALE`, then clamped to [0, 1].
const RANGE_CORRECTION_SHIFT: f64 = 1.05242;
const RANGE_CORRECTION_SCALE: f64 = 0.48985582;

/// Clamps to [0, 1]; NaN (from coordinates beyond the lattice's 32-bit range) becomes 0, as
/// POV-Ray's output does.
fn clamp_unit(value: f64) -> f64 {
    if value >= 1.0 {
        1.0
    } else if value > 0.0 {
        value
    } else {
        0.0
    }
}

/// POV-Ray's scalar solid noise at `point`, in [0, 1] (the `bozo` pattern's raw value and
/// `f_noise_generator`'s result).
pub fn noise(point: DVec3, generator: NoiseGenerator) -> f64 {
    match generator {
        NoiseGenerator::Original => clamp_unit(lattice::scalar_sum(point) + 0.5),
        NoiseGenerator::RangeCorrected => clamp_unit(
            (lattice::scalar_sum(point) + RANGE_CORRECTION_SHIFT) * RANGE_CORRECTION_SCALE,
        ),
        NoiseGenerator::Perlin => perlin::noise(point),
    }
}

/// POV-Ray's vector noise at `point` (each component roughly in [-1, 1]). POV-Ray uses the
/// same lattice vector noise whatever the generator (measured: the turbulence warp and
/// `vturbulence` do not change with `noise_generator`), so `generator` is accepted for
/// symmetry with [`noise`] and does not change the result.
pub fn vector_noise(point: DVec3, generator: NoiseGenerator) -> DVec3 {
    let _ = generator;
    lattice::vector_sum(point)
}

/// The per-octave noise scalar turbulence sums: generator 1's noise as it is; for generators
/// 2 and 3 the noise stretched to `2·noise − 0.5` (measured through `marble`'s turbulence).
fn octave_noise(point: DVec3, generator: NoiseGenerator) -> f64 {
    let value = noise(point, generator);
    match generator {
        NoiseGenerator::Original => value,
        NoiseGenerator::RangeCorrected | NoiseGenerator::Perlin => 2.0 * value - 0.5,
    }
}

/// The octave count, frequency factor and amplitude factor POV-Ray really uses: the count
/// clamped to 1..=10, omega and lambda rounded to single precision (as POV-Ray stores them).
fn octave_parameters(shape: &TurbulenceShape) -> (u32, f64, f64) {
    let octaves = shape.octaves.clamp(OCTAVE_RANGE.0, OCTAVE_RANGE.1);
    (
        octaves,
        f64::from(shape.lambda as f32),
        f64::from(shape.omega as f32),
    )
}

/// POV-Ray's scalar turbulence: `Σ omegaⁱ · octave_noise(point · lambdaⁱ)` over the octaves,
/// where the octave noise is [`noise`] for generator 1 and `2·noise − 0.5` for generators 2
/// and 3, and the first octave's term alone is clamped to [0, 1] (all measured). Measured
/// through `marble`, whose value with `turbulence <a, b, c>` is its ramp at `x + a · this`
/// (only the x amount counts); the other "classic turbulence" patterns are expected to use it
/// the same way.
pub fn turbulence(point: DVec3, shape: &TurbulenceShape, generator: NoiseGenerator) -> f64 {
    let (octaves, lambda, omega) = octave_parameters(shape);
    let mut sum = clamp_unit(octave_noise(point, generator));
    let (mut frequency, mut amplitude) = (lambda, omega);
    for _ in 1..octaves {
        sum += amplitude * octave_noise(point * frequency, generator);
        frequency *= lambda;
        amplitude *= omega;
    }
    sum
}

/// POV-Ray's vector turbulence: `Σ omegaⁱ · vector_noise(point · lambdaⁱ)` over the octaves —
/// the displacement the `turbulence` modifier and `vturbulence(lambda, omega, octaves, point)`
/// use (before scaling by the turbulence amount).
pub fn vector_turbulence(
    point: DVec3,
    shape: &TurbulenceShape,
    generator: NoiseGenerator,
) -> DVec3 {
    let (octaves, lambda, omega) = octave_parameters(shape);
    let (mut frequency, mut amplitude, mut sum) = (1.0, 1.0, DVec3::ZERO);
    for _ in 0..octaves {
        sum += amplitude * vector_noise(point * frequency, generator);
        frequency *= lambda;
        amplitude *= omega;
    }
    sum
}

#[cfg(test)]
mod tests;
