//! What is inside an object: refraction, fading, dispersion and media.
//!
//! In: nothing (a data definition). Out: [`Interior`]. Holds: defaults are POV-Ray 3.7's.

use glam::DVec3;

/// What is inside an object.
#[derive(Clone, Debug)]
pub struct Interior {
    /// Index of refraction (default 1: no bending).
    pub ior: f64,
    /// `dispersion`: the index of refraction of violet light over that of red (default 1).
    pub dispersion: f64,
    /// `dispersion_samples`: wavelengths traced for dispersion (default 7).
    pub dispersion_samples: u32,
    /// `fade_distance`: distance at which light inside has faded halfway towards
    /// `fade_colour` (0: no fading).
    pub fade_distance: f64,
    /// `fade_power` (default 0: no fading).
    pub fade_power: f64,
    /// `fade_color`: colour light fades to inside (default black).
    pub fade_colour: DVec3,
    /// `caustics`: fake caustics, brightening shadow rays that cross the surface nearly
    /// along its normal (0 is off).
    pub caustics: f64,
    /// `media { }` blocks inside the object; their effects add.
    pub media: Vec<super::Media>,
}

impl Default for Interior {
    fn default() -> Self {
        Interior {
            ior: 1.0,
            dispersion: 1.0,
            dispersion_samples: 7,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_colour: DVec3::ZERO,
            caustics: 0.0,
            media: Vec::new(),
        }
    }
}
