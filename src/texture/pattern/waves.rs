//! The wave sources of the `ripples` and `waves` patterns: centres on the unit sphere, each
//! with its own frequency (used by `waves` only); ten unless `global_settings {
//! number_of_waves N }` asks for another count.
//!
//! In: the count. Out: the shared, immutable table of that many sources (the default ten
//! built once per process; other counts once per `number_of_waves`). Holds: nothing
//! mutable, safe to read from any thread.
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
//! generator). `number_of_waves N` (measured with N = 1, 3, 12, 25, 40) uses the first N
//! sources of the same two sequences; values and normals average over them. It takes
//! effect at render time (povray's own parse-time function calls still see ten).

use std::sync::{Arc, OnceLock};

use glam::DVec3;

use crate::noise::{vector_noise, NoiseGenerator};

/// How many wave sources `ripples` and `waves` use by default (`number_of_waves`).
pub const DEFAULT_WAVE_COUNT: usize = 10;

/// The most wave sources durer builds (a larger `number_of_waves` is limited to this: each
/// evaluation of the patterns visits every source).
pub const MAX_WAVE_COUNT: usize = 65_536;

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

/// The wave sources a `ripples` or `waves` pattern uses (cheap to clone: shared).
#[derive(Clone, Debug, PartialEq)]
pub struct WaveSources(Arc<[WaveSource]>);

impl WaveSources {
    /// The first `count` sources, `count` limited to 1..=[`MAX_WAVE_COUNT`].
    pub fn new(count: usize) -> WaveSources {
        if count == DEFAULT_WAVE_COUNT {
            return WaveSources::default();
        }
        WaveSources(build_sources(count.clamp(1, MAX_WAVE_COUNT)).into())
    }

    /// The sources, never empty.
    pub fn as_slice(&self) -> &[WaveSource] {
        &self.0
    }
}

impl Default for WaveSources {
    /// The default ten sources (shared).
    fn default() -> WaveSources {
        default_sources().clone()
    }
}

fn build_sources(count: usize) -> Vec<WaveSource> {
    let mut state = FREQUENCY_SEED;
    (0..count)
        .map(|index| {
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
        .collect()
}

/// The wave sources of one scene: every `ripples` and `waves` pattern of the scene shares
/// this handle, and the count the scene's last `number_of_waves` asks for is fixed in it
/// when parsing ends, so that it applies to every pattern wherever `global_settings`
/// stands (measured). Until then (function calls while parsing) the default ten are used,
/// as povray does.
#[derive(Clone, Debug, Default)]
pub struct SceneWaveSources(Arc<OnceLock<WaveSources>>);

impl SceneWaveSources {
    /// Fixes the scene's sources; later calls change nothing.
    pub fn fix(&self, sources: WaveSources) {
        let _ = self.0.set(sources);
    }

    /// The sources the patterns use now (never empty).
    pub fn as_slice(&self) -> &[WaveSource] {
        match self.0.get() {
            Some(sources) => sources.as_slice(),
            None => default_sources().as_slice(),
        }
    }
}

/// The default ten sources, built once per process.
fn default_sources() -> &'static WaveSources {
    static DEFAULT: OnceLock<WaveSources> = OnceLock::new();
    DEFAULT.get_or_init(|| WaveSources(build_sources(DEFAULT_WAVE_COUNT).into()))
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
        let sources = WaveSources::default();
        for (source, expected) in sources.as_slice().iter().zip(measured) {
            assert!((source.frequency - expected).abs() < 1e-12);
        }
    }

    #[test]
    fn centres_are_unit_vectors() {
        for count in [1, 10, 40] {
            let sources = WaveSources::new(count);
            assert_eq!(sources.as_slice().len(), count);
            for source in sources.as_slice() {
                assert!((source.centre.length() - 1.0).abs() < 1e-12);
            }
        }
        // More sources extend the same sequences.
        assert_eq!(
            WaveSources::new(12).as_slice()[..10],
            WaveSources::default().as_slice()[..]
        );
        assert_eq!(WaveSources::new(0).as_slice().len(), 1);
    }

    #[test]
    fn scene_sources_are_the_default_until_fixed_once() {
        let scene = SceneWaveSources::default();
        let shared = scene.clone();
        assert_eq!(shared.as_slice().len(), DEFAULT_WAVE_COUNT);
        scene.fix(WaveSources::new(3));
        scene.fix(WaveSources::new(5));
        assert_eq!(shared.as_slice().len(), 3);
    }
}
