//! durer: a POV-Ray 3.7 scene description language interpreter and recursive ray tracer.
//!
//! The pipeline runs one way: `syntax` (pest grammar to spanned AST) → `eval` (AST to
//! [`scene::Scene`]) → `geometry` + `accel` (render objects and BVH) → `render` (image).

pub mod accel;
pub mod diag;
pub mod eval;
pub mod expand;
pub mod file_policy;
pub mod fuzzing;
pub mod geometry;
pub mod hash;
pub mod limits;
pub mod math;
pub mod noise;
pub mod raster;
pub mod render;
pub mod report;
pub mod scene;
pub mod syntax;
pub mod texture;
