//! POV-Ray's solid noise and turbulence: the functions every noise-based pattern, the
//! `turbulence` modifier, turbulence warps, `vturbulence` and `f_noise3d` are built on.
//!
//! In: points in pattern space. Out: values as POV-Ray 3.7 computes them. Holds: pure
//! functions of their arguments (no global state, no allocation), safe to call from any thread.
//!
//! NOTE: this file currently holds the agreed API only; the bodies are placeholders until the
//! noise work lands.

use glam::DVec3;

/// True once these functions reproduce POV-Ray's noise exactly; reference scenes marked
/// `// needs-exact-noise` are skipped until then.
pub const EXACT: bool = false;

/// POV-Ray's `noise_generator` choice (global_settings or per pattern; default 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum NoiseGenerator {
    /// 1: the original noise of POV-Ray 3.1 and earlier.
    Original,
    /// 2: the original noise with its range corrected (POV-Ray 3.7's default).
    #[default]
    RangeCorrected,
    /// 3: Perlin's improved noise.
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
    /// Number of noise layers added (1 to 10).
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

/// POV-Ray's scalar solid noise at `point`, in [0, 1] (the `bozo` pattern's raw value).
pub fn noise(point: DVec3, generator: NoiseGenerator) -> f64 {
    let _ = (point, generator);
    0.5
}

/// POV-Ray's vector noise at `point` (each component roughly in [-1, 1]).
pub fn vector_noise(point: DVec3, generator: NoiseGenerator) -> DVec3 {
    let _ = (point, generator);
    DVec3::ZERO
}

/// POV-Ray's scalar turbulence: noise summed over octaves (used by agate, granite-like
/// patterns and `function { pattern {..} }` values).
pub fn turbulence(point: DVec3, shape: &TurbulenceShape, generator: NoiseGenerator) -> f64 {
    let _ = (point, shape, generator);
    0.5
}

/// POV-Ray's vector turbulence: the displacement the `turbulence` modifier and
/// `vturbulence(lambda, omega, octaves, point)` use (before scaling by the turbulence amount).
pub fn vector_turbulence(
    point: DVec3,
    shape: &TurbulenceShape,
    generator: NoiseGenerator,
) -> DVec3 {
    let _ = (point, shape, generator);
    DVec3::ZERO
}
