//! Light sources as POV-Ray defines them.
//!
//! In: nothing (data definitions). Out: [`LightSource`], [`Spotlight`]. Holds: positions
//! and directions in world space.

use glam::DVec3;

/// A light source.
#[derive(Clone, Debug)]
pub struct LightSource {
    /// Position of the light.
    pub position: DVec3,
    /// Colour (intensity) of the light.
    pub colour: DVec3,
    /// A `shadowless` light is never blocked by objects.
    pub shadowless: bool,
    /// Spotlight cone, when the light is a spotlight.
    pub spotlight: Option<Spotlight>,
    /// `fade_distance`; 0 means no fading.
    pub fade_distance: f64,
    /// `fade_power`; 0 means no fading.
    pub fade_power: f64,
}

/// The cone of a `spotlight`.
#[derive(Clone, Copy, Debug)]
pub struct Spotlight {
    /// The point the spotlight aims at.
    pub point_at: DVec3,
    /// Half-angle in degrees of the fully lit cone (default 30).
    pub radius: f64,
    /// Half-angle in degrees where the light reaches zero (default 45).
    pub falloff: f64,
    /// Exponent sharpening the edge of the cone.
    pub tightness: f64,
}
