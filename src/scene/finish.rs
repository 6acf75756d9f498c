//! Surface finishes and object interiors as POV-Ray defines them.
//!
//! In: nothing (data definitions). Out: [`Finish`], [`Interior`]. Holds: defaults are
//! POV-Ray 3.7's.

use glam::DVec3;

/// POV-Ray's `finish` with its defaults.
#[derive(Clone, Debug)]
pub struct Finish {
    /// Ambient light reflected (colour; default 0.1 grey).
    pub ambient: DVec3,
    /// Light emitted independently of `ambient_light` (default black).
    pub emission: DVec3,
    /// Diffuse reflection (default 0.6).
    pub diffuse: f64,
    /// Diffuse falloff exponent (default 1).
    pub brilliance: f64,
    /// Phong highlight amount (default 0).
    pub phong: f64,
    /// Phong exponent (default 40).
    pub phong_size: f64,
    /// Blinn specular highlight amount (default 0).
    pub specular: f64,
    /// Specular roughness (default 0.05).
    pub roughness: f64,
    /// Tints highlights with the surface colour, 0 to 1 (default 0).
    pub metallic: f64,
    /// Mirror reflection colour (default black).
    pub reflection: DVec3,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: DVec3::ZERO,
        }
    }
}

/// What is inside an object.
#[derive(Clone, Debug)]
pub struct Interior {
    /// Index of refraction (default 1: no bending).
    pub ior: f64,
}

impl Default for Interior {
    fn default() -> Self {
        Interior { ior: 1.0 }
    }
}
