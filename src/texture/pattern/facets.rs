//! The `facets` normal pattern: flat facets on the crackle cell structure.
//!
//! In: a pattern-space point, the unit surface normal facing the viewer in pattern space and
//! the `coords` and `size` settings. Out: the new surface normal (unnormalised), which
//! replaces the facing one. Holds: pure, allocation-free; the cells are crackle's
//! (`noise::crackle_feature_point`), searched in the 27 unit cubes around a point.
//!
//! Measured against POV-Ray 3.7 (normals recovered from 16-bit linear renders of a plane
//! lit from five directions; then renders of planes and spheres, scaled, rotated and
//! translated, with the pattern transformed too, match povray pixel for pixel:
//! `scripts/probe-facets.py`):
//! - `coords C` (C non-zero): the point divided by `size` (default 0.1, at least 1e-6)
//!   falls in a crackle cell; the normal is tilted by `C` times the vector noise at the
//!   cell's feature point, with the component along the normal removed, so every cell is
//!   one flat facet.
//! - without `coords`: the facing normal divided by `size` falls in a crackle cell, and the
//!   normal becomes the direction of that cell's feature point: normals are snapped to a
//!   jittered grid of directions, so the facets depend on the surface's curvature only.
//! - the bump amount written after `facets` has no effect in either form, and the pattern's
//!   transformations carry the normal into pattern space and back like any normal (no bump
//!   scaling).

use glam::DVec3;

use crate::noise::{crackle_feature_point, vector_noise, NoiseGenerator};

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

/// The smallest cell scale: a smaller (or negative) `size` gives cells this small.
const MIN_SIZE: f64 = 1e-6;

/// `facets`: the new (unnormalised) normal at `point` replacing the facing unit normal
/// `normal`; `coords` 0 means not given. A `size` below [`MIN_SIZE`] (or NaN) counts as
/// that (measured: tiny and negative sizes match povray to 5/255 on 0.02% of pixels).
pub fn facets_normal(point: DVec3, normal: DVec3, coords: f64, size: f64) -> DVec3 {
    let size = size.max(MIN_SIZE);
    if coords != 0.0 {
        let site = nearest_feature_point(point / size);
        let tilt = vector_noise(site, NoiseGenerator::default());
        normal + (tilt - normal * tilt.dot(normal)) * coords
    } else {
        nearest_feature_point(normal / size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FACING: DVec3 = DVec3::NEG_Z;

    #[test]
    fn coords_normal_matches_povray() {
        // Normals recovered from 16-bit linear POV-Ray renders of `normal { facets coords C }`
        // on the plane z = 0 seen from -z, at the pixel centre (-1.975, 1.475).
        let point = DVec3::new(-1.975, 1.475, 0.0);
        let close = |a: DVec3, b: DVec3| (a - b).abs().max_element() < 1e-3;
        let half = facets_normal(point, FACING, 0.5, 0.1).normalize();
        assert!(close(half, DVec3::new(-0.20802, -0.08564, -0.97437)));
        let whole = facets_normal(point, FACING, 1.0, 0.1).normalize();
        assert!(close(whole, DVec3::new(-0.38764, -0.15958, -0.90789)));
    }

    #[test]
    fn coords_facets_are_flat_and_only_tilt() {
        let point = DVec3::new(0.31, -0.42, 0.05);
        let tilted = facets_normal(point, FACING, 0.8, 0.1);
        // The tilt is tangential: the component along the normal stays 1.
        assert!((tilted.dot(FACING) - 1.0).abs() < 1e-12);
        // Every point of a cell gets the same normal.
        let nearby = point + DVec3::new(1e-4, -1e-4, 0.0);
        assert_eq!(facets_normal(nearby, FACING, 0.8, 0.1), tilted);
    }

    #[test]
    fn size_form_snaps_the_normal() {
        let normal = DVec3::new(0.3, -0.5, 0.8).normalize();
        let snapped = facets_normal(DVec3::ZERO, normal, 0.0, 0.05);
        // The point does not matter, and the snapped normal stays near the original.
        assert_eq!(facets_normal(DVec3::splat(7.0), normal, 0.0, 0.05), snapped);
        assert!(snapped.normalize().dot(normal) > 0.9);
        // Close normals share a facet.
        let close_normal = (normal + DVec3::splat(1e-5)).normalize();
        assert_eq!(facets_normal(DVec3::ZERO, close_normal, 0.0, 0.05), snapped);
    }

    #[test]
    fn tiny_negative_and_nan_sizes_give_the_smallest_cells() {
        let point = DVec3::new(0.25, 0.5, -0.125);
        let smallest = facets_normal(point, FACING, 0.5, MIN_SIZE);
        for size in [0.0, -1.0, f64::NAN] {
            assert_eq!(facets_normal(point, FACING, 0.5, size), smallest);
        }
        assert!(smallest.is_finite());
    }
}
