//! Leaf mathematics shared by every layer: colours and affine transformations.
//!
//! In: nothing. Out: [`Colour`] (five channels: red, green, blue, filter, transmit) and
//! [`Transform`] (an affine map with its inverse). Holds: plain values; this module
//! imports nothing from the crate.

mod colour;
mod transform;

pub use colour::Colour;
pub use transform::Transform;
