//! Scene data of the `parametric` shape.
//!
//! In: nothing (data definitions). Out: [`Parametric`]. Holds: every value is final, with
//! POV-Ray's defaults filled in.

use super::Container;
use crate::texture::function::Function;
use glam::DVec2;
use std::sync::Arc;

/// `parametric { function { x(u,v) } function { y(u,v) } function { z(u,v) } <u1, v1>,
/// <u2, v2> .. }`: the surface of the points the three functions give over a uv rectangle.
#[derive(Clone, Debug)]
pub struct Parametric {
    /// The functions of `u, v` (read as `x, y`) giving the point's x, y and z.
    pub functions: [Arc<Function>; 3],
    /// One corner of the uv rectangle.
    pub uv_corner1: DVec2,
    /// The opposite corner.
    pub uv_corner2: DVec2,
    /// Where the surface is kept (default `box { -1, 1 }`).
    pub container: Container,
    /// Bound of the functions' partial derivatives the search relies on (default 1.1).
    pub max_gradient: f64,
    /// Size of the smallest piece the search looks at (default 0.001).
    pub accuracy: f64,
}
