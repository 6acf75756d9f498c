//! Scene data of the `lemon` shape.
//!
//! In: nothing (data definitions). Out: [`Lemon`]. Holds: values as written in the scene.

use glam::DVec3;

/// `lemon { base, base_radius, cap, cap_radius, inner_radius [open] }`: the circle arc of
/// radius `inner_radius` from the base rim to the cap rim, bulging outwards, turned around
/// the axis from `base` to `cap`.
#[derive(Clone, Debug, PartialEq)]
pub struct Lemon {
    /// Centre of the base rim.
    pub base: DVec3,
    /// Radius of the base rim (zero for a point).
    pub base_radius: f64,
    /// Centre of the cap rim.
    pub cap: DVec3,
    /// Radius of the cap rim (zero for a point).
    pub cap_radius: f64,
    /// Radius of the arc turned around the axis.
    pub inner_radius: f64,
    /// Without the flat ends (`open`).
    pub open: bool,
}
