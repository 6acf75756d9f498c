//! Render quality (`+Q0` … `+Q11`): what each level leaves out, as `povray` 3.7 renders
//! it (measured on probe scenes at each level).
//!
//! - 0, 1: pigment colours only: no light sources, no ambient scaling, no highlights, every
//!   surface opaque;
//! - 2, 3: ambient and diffuse light and highlights, no shadows;
//! - 4: shadows, area lights as point lights;
//! - 5: area lights;
//! - 6, 7: transparency and refraction, photons;
//! - 8: mirror reflection;
//! - 9 to 11 (9 is the default): media, radiosity and subsurface light transport.
//!
//! Not reproduced: below 6 POV-Ray shows a pigment's `quick_color` instead of the pigment,
//! which durer reads and ignores (such pigments keep their patterns, as pigments without a
//! `quick_color` do in POV-Ray).

use crate::scene::Scene;

/// The quality level POV-Ray renders at by default.
pub const DEFAULT_QUALITY: u32 = 9;

/// A quality level and what it computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quality(pub u32);

impl Default for Quality {
    fn default() -> Quality {
        Quality(DEFAULT_QUALITY)
    }
}

impl Quality {
    /// Surfaces show their pigment's colour and nothing else.
    pub fn colours_only(self) -> bool {
        self.0 <= 1
    }
    /// Shadow rays are traced.
    pub fn shadows(self) -> bool {
        self.0 >= 4
    }
    /// Area lights are arrays (else a point light at their centre).
    pub fn area_lights(self) -> bool {
        self.0 >= 5
    }
    /// Light passes through transparent surfaces (and photons are shot).
    pub fn transparency(self) -> bool {
        self.0 >= 6
    }
    /// Mirror reflection is traced.
    pub fn reflection(self) -> bool {
        self.0 >= 8
    }
    /// Media, radiosity and subsurface light transport are computed.
    pub fn media_and_global_light(self) -> bool {
        self.0 >= 9
    }

    /// The scene with what this level leaves out removed, or `None` when nothing is.
    pub fn reduced(self, scene: &Scene) -> Option<Scene> {
        if self.media_and_global_light() {
            return None;
        }
        let mut reduced = scene.clone();
        for light in &mut reduced.lights {
            if !self.shadows() {
                light.shadowless = true;
            }
            if !self.area_lights() {
                light.area = None;
            }
        }
        if !self.transparency() {
            reduced.settings.photons = None;
        }
        reduced.settings.radiosity = None;
        reduced.settings.subsurface = None;
        reduced.atmosphere.media.clear();
        Some(reduced)
    }
}
