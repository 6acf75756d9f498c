//! Atmospheric effects: fog layers, the sky sphere and rainbows.
//!
//! In: nothing (data definition). Out: [`Atmosphere`] and its parts. Holds: values are final
//! (defaults filled in, transformations folded in); angles in degrees.

use crate::noise::TurbulenceShape;
use crate::{
    math::{Colour, Transform},
    texture::Pigment,
};
use glam::DVec3;

/// Everything between the camera and the objects, and what lies beyond them.
#[derive(Clone, Debug, Default)]
pub struct Atmosphere {
    /// Fog layers, in scene order.
    pub fogs: Vec<Fog>,
    /// The sky seen by rays that hit nothing (replaces `background` there).
    pub sky_sphere: Option<SkySphere>,
    /// Rainbows, in scene order.
    pub rainbows: Vec<Rainbow>,
    /// Atmospheric `media { }` blocks, filling all space outside non-hollow objects.
    pub media: Vec<super::Media>,
}

impl Atmosphere {
    /// True when the atmosphere changes nothing along rays.
    pub fn is_clear(&self) -> bool {
        self.fogs.is_empty() && self.rainbows.is_empty()
    }
}

/// How a fog's density varies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FogKind {
    /// `fog_type 1`: the same density everywhere.
    Constant,
    /// `fog_type 2`: full density up to `offset` along `up`, then
    /// `1 / (1 + (h - offset) / altitude)²` above.
    Ground {
        /// `fog_offset`: the height below which the fog is dense.
        offset: f64,
        /// `fog_alt`: how fast the fog thins above `offset`.
        altitude: f64,
    },
}

/// One `fog { }` layer.
#[derive(Clone, Debug)]
pub struct Fog {
    /// Constant or ground fog.
    pub kind: FogKind,
    /// `distance`: the depth at which 36.8% of the fog colour is mixed in.
    pub distance: f64,
    /// Fog colour; its filter and transmit say how much of the scene shows through at least.
    pub colour: Colour,
    /// The direction heights are measured along (transformed, not normalised).
    pub up: DVec3,
    /// Turbulence stirring the fog's density, if any (looked up in world space: measured,
    /// POV-Ray's fog transformations turn `up` but do not move the turbulence).
    pub turbulence: Option<FogTurbulence>,
}

/// A fog's `turbulence` with its parameters.
#[derive(Clone, Copy, Debug)]
pub struct FogTurbulence {
    /// The turbulence amount per axis.
    pub amount: DVec3,
    /// `turb_depth`: scales the turbulence value before it thins the fog.
    pub depth: f64,
    /// Octaves, omega and lambda.
    pub shape: TurbulenceShape,
}

/// `sky_sphere { }`: pigments looked up in the ray's direction.
#[derive(Clone, Debug)]
pub struct SkySphere {
    /// Pigment layers, bottom first.
    pub pigments: Vec<Pigment>,
    /// Multiplies the sky's colour (default white).
    pub emission: DVec3,
    /// Maps sky space into world space (only its rotation and scaling matter).
    pub transform: Transform,
}

/// `rainbow { }`: a fog-like coloured arc around a direction.
#[derive(Clone, Debug)]
pub struct Rainbow {
    /// Direction of the light making the rainbow.
    pub direction: DVec3,
    /// Angle from `direction` to the middle of the bow.
    pub angle: f64,
    /// Angular width of the bow.
    pub width: f64,
    /// Fog distance of the bow.
    pub distance: f64,
    /// Colours from the inner (0) to the outer (1) edge.
    pub colour_map: Vec<(f64, Colour)>,
    /// Random offset added to the colour map index.
    pub jitter: f64,
    /// Where the arc's zero angle is (its part across `direction`).
    pub up: DVec3,
    /// Size of the arc.
    pub arc_angle: f64,
    /// Size of the part of the arc at full strength.
    pub falloff_angle: f64,
}
