//! Scene data of the shapes defined by functions, grids and sweeps: `isosurface`,
//! `height_field` and `sphere_sweep`.
//!
//! In: nothing (data definitions). Out: [`Isosurface`], [`HeightField`], [`SphereSweep`].
//! Holds: every value is final, with POV-Ray's defaults filled in.

use crate::texture::function::Function;
use glam::DVec3;
use std::sync::Arc;

/// `isosurface { function { .. } contained_by { .. } .. }`.
#[derive(Clone, Debug)]
pub struct Isosurface {
    /// The function of `x, y, z`; the surface is where it equals `threshold`, the inside
    /// where it is lower.
    pub function: Arc<Function>,
    /// The region searched for the surface (default `box { -1, 1 }`).
    pub container: Container,
    /// The surface's function value (default 0).
    pub threshold: f64,
    /// Length of the ray interval at which root search stops (default 0.001).
    pub accuracy: f64,
    /// Bound of the function's rate of change the root search relies on (default 1.1).
    pub max_gradient: f64,
    /// Without the container's surface where it cuts the inside (`open`).
    pub open: bool,
    /// Most surface crossings reported along one ray (`max_trace`, default 1;
    /// `all_intersections` means as many as durer keeps).
    pub max_trace: usize,
}

/// An isosurface's `contained_by` shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    /// `box { corner1, corner2 }`.
    Box { corner1: DVec3, corner2: DVec3 },
    /// `sphere { centre, radius }`.
    Sphere { centre: DVec3, radius: f64 },
}

/// `height_field { .. }`: heights over the unit square in x and z.
#[derive(Clone, Debug)]
pub struct HeightField {
    /// Number of grid points along x (image columns).
    pub columns: usize,
    /// Number of grid points along z (image rows).
    pub rows: usize,
    /// Heights in [0, 1], row by row; row 0 is at z = 0 (the image's bottom row).
    pub heights: Vec<f64>,
    /// Normals interpolated across each triangle (`smooth`).
    pub smooth: bool,
    /// Parts at or below this height are left out (`water_level`, default 0).
    pub water_level: f64,
    /// What the heights were made from (for writing the scene back), when known.
    pub source: Option<HeightFieldSource>,
}

/// The file or function a height field's grid was sampled from.
#[derive(Clone, Debug)]
pub enum HeightFieldSource {
    /// An image file (format keyword as given, `sys` when none).
    Image {
        path: std::path::PathBuf,
        format: crate::raster::RasterFormat,
    },
    /// `function W, H { .. }`.
    Function {
        function: std::sync::Arc<crate::texture::function::Function>,
        columns: usize,
        rows: usize,
    },
}

/// `sphere_sweep { .. }`: a sphere of varying radius moved along a spline.
#[derive(Clone, Debug)]
pub struct SphereSweep {
    /// The spline kind.
    pub spline: SweepSpline,
    /// Control spheres as (centre, radius).
    pub spheres: Vec<(DVec3, f64)>,
    /// `tolerance` (default 1e-6).
    pub tolerance: f64,
}

/// The spline of a `sphere_sweep`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepSpline {
    /// Straight segments between the spheres.
    Linear,
    /// A uniform cubic B-spline (passes near, not through, the control spheres).
    BSpline,
    /// A Catmull-Rom spline through the control spheres (the first and last are guides).
    Cubic,
}
