//! The scene's `global_settings { noise_generator }` as the patterns see it.
//!
//! In: the generator each `global_settings { noise_generator N }` sets while the scene is
//! parsed. Out: the generator in force when a pattern (or irid's turbulence) without its own
//! is evaluated. Holds: one handle shared by every such pattern of the scene; reads are one
//! atomic load, no allocation; after parsing nothing writes, so renders are deterministic.
//!
//! Rule measured in POV-Ray 3.7: a pattern without its own `noise_generator` follows the
//! scene's last `global_settings { noise_generator }`, wherever it stands (before or after
//! the pattern; a later `global_settings` without `noise_generator` changes nothing). While
//! the scene is still being parsed (functions called from the scene), the setting in force
//! at that moment applies.

use super::NoiseGenerator;
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::Arc;

/// A shared handle on a scene's global noise generator; without a scene (the default) it is
/// POV-Ray's default generator.
#[derive(Clone, Debug, Default)]
pub struct SceneNoiseGenerator(Option<Arc<AtomicU8>>);

impl SceneNoiseGenerator {
    /// A fresh handle for a scene being parsed, holding the default generator.
    pub fn for_scene() -> SceneNoiseGenerator {
        SceneNoiseGenerator(Some(Arc::new(AtomicU8::new(number_of(
            NoiseGenerator::default(),
        )))))
    }

    /// Sets the scene's generator (every holder of this handle sees it from now on).
    pub fn set(&self, generator: NoiseGenerator) {
        if let Some(shared) = &self.0 {
            shared.store(number_of(generator), Ordering::Relaxed);
        }
    }

    /// The scene's generator now.
    pub fn get(&self) -> NoiseGenerator {
        match &self.0 {
            Some(shared) => NoiseGenerator::from_number(i64::from(shared.load(Ordering::Relaxed)))
                .unwrap_or_default(),
            None => NoiseGenerator::default(),
        }
    }
}

/// The `noise_generator` number of `generator` (1, 2 or 3).
fn number_of(generator: NoiseGenerator) -> u8 {
    match generator {
        NoiseGenerator::Original => 1,
        NoiseGenerator::RangeCorrected => 2,
        NoiseGenerator::Perlin => 3,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_holder_sees_the_last_setting() {
        let scene = SceneNoiseGenerator::for_scene();
        let pattern_handle = scene.clone();
        assert_eq!(pattern_handle.get(), NoiseGenerator::RangeCorrected);
        scene.set(NoiseGenerator::Perlin);
        scene.set(NoiseGenerator::Original);
        assert_eq!(pattern_handle.get(), NoiseGenerator::Original);
        let detached = SceneNoiseGenerator::default();
        detached.set(NoiseGenerator::Perlin);
        assert_eq!(detached.get(), NoiseGenerator::RangeCorrected);
    }
}
