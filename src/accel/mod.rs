//! Acceleration structures: axis-aligned boxes and the SAH bounding volume hierarchy.
//!
//! In: one bounding box per primitive. Out: a [`Bvh`] that finds the nearest hit of a ray by
//! calling back into the caller's primitive test, visiting only primitives whose boxes the ray
//! crosses. Holds: the hierarchy knows nothing about shapes; unbounded primitives stay with the
//! caller. [`counters`] keeps the statistics of rays and intersection tests.

mod aabb;
mod bvh;
pub mod counters;

pub use aabb::Aabb;
pub use bvh::{Bvh, MAX_DEPTH};
