//! The `facets` normal pattern: flat facets on the crackle cell structure.
//!
//! In: a pattern-space point, the unit surface normal facing the viewer in pattern space and
//! the `coords` and `size` settings. Out: the vector to add to that normal (before
//! normalising). Holds: pure, allocation-free; the cells are crackle's (`noise::cells`).
//!
//! Measured against POV-Ray 3.7 (normals recovered from 16-bit linear renders of a plane
//! lit from five directions, `scripts/probe-facets.py`):
//! - `coords C`: the point divided by `size` (default 0.1) falls in a crackle cell; the
//!   normal is tilted by `C` times the vector noise at the cell's feature point, with its
//!   component along the normal removed, so every cell is one flat facet. The bump amount
//!   written after `facets` has no effect.

use glam::DVec3;

use crate::noise::{crackle_feature_point, vector_noise, NoiseGenerator};

/// `size` when none is given (measured: the cells of `facets coords C` are a tenth of
/// crackle's).
const DEFAULT_SIZE: f64 = 0.1;

/// The nearest crackle feature point to `point` (searched in the 27 unit cubes around it).
fn nearest_feature_point(point: DVec3) -> DVec3 {
    let limit = 1e15;
    let home = point
        .floor()
        .clamp(DVec3::splat(-limit), DVec3::splat(limit));
    let home = [home.x as i64, home.y as i64, home.z as i64];
    let mut nearest = DVec3::ZERO;
    let mut nearest_distance = f64::INFINITY;
    for dx in -1..=1 {
        for dy in -1..=1 {
            for dz in -1..=1 {
                let site = crackle_feature_point([home[0] + dx, home[1] + dy, home[2] + dz]);
                let distance = point.distance_squared(site);
                if distance < nearest_distance {
                    nearest_distance = distance;
                    nearest = site;
                }
            }
        }
    }
    nearest
}

/// The cell scale: `size`, or its default when not given (zero or less).
fn cell_size(size: f64) -> f64 {
    if size > 0.0 {
        size
    } else {
        DEFAULT_SIZE
    }
}

/// `facets`: the vector added to the facing unit normal `normal` at `point`.
pub fn facets(point: DVec3, normal: DVec3, coords: f64, size: f64) -> DVec3 {
    let site = nearest_feature_point(point / cell_size(size));
    let tilt = vector_noise(site, NoiseGenerator::default());
    let tangential = tilt - normal * tilt.dot(normal);
    tangential * (2.0 * coords)
}
