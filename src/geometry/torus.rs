//! The torus.
//!
//! In: major and minor radius (torus in the XZ plane around Y); rays as local origin plus
//! direction. Out: up to four intersections, inside test, outward normal, bounds.
//! Holds: the crossings are the real roots of a quartic found by
//! [`real_roots_between`], so a crossing is never lost to cancellation in a closed-form
//! solution; only tangent touches whose minimum does not reach zero in floating point are
//! missed.

use super::roots::{real_roots_between, Roots, MAX_DEGREE};
use super::round::Sphere;
use crate::accel::Aabb;
use glam::DVec3;

/// A torus around the Y axis: a circle of radius `minor` swept along a circle of radius
/// `major` in the XZ plane.
#[derive(Clone, Copy, Debug)]
pub struct Torus {
    major: f64,
    minor: f64,
}

/// What a `torus { major, minor }` becomes.
#[derive(Clone, Copy, Debug)]
pub enum TorusShape {
    /// A proper torus.
    Torus(Torus),
    /// A zero major radius leaves a sphere of the minor radius.
    Sphere(Sphere),
}

impl Torus {
    /// The torus for the given radii; `None` for a zero minor radius or non-finite radii.
    pub fn from_radii(major: f64, minor: f64) -> Option<TorusShape> {
        let major = major.abs();
        let minor = minor.abs();
        if !(minor > 0.0 && minor.is_finite() && major.is_finite()) {
            return None;
        }
        if major == 0.0 {
            return Sphere::new(DVec3::ZERO, minor).map(TorusShape::Sphere);
        }
        Some(TorusShape::Torus(Torus { major, minor }))
    }

    /// The radius of the circle the tube's centre follows.
    pub fn major(&self) -> f64 {
        self.major
    }

    /// Pushes every crossing of the line `origin + t direction` with the torus.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let speed = direction.length();
        if !(speed > 0.0 && speed.is_finite()) {
            return;
        }
        // Work with a unit direction in a space scaled so the bounding sphere has radius 1,
        // measuring from the line's point closest to the centre: all coefficients are then
        // of order one.
        let scale = self.major + self.minor;
        let unit_direction = direction / speed;
        let start = origin / scale;
        let closest_offset = -start.dot(unit_direction);
        let closest = start + unit_direction * closest_offset;
        let closest_squared = closest.length_squared();
        if closest_squared.is_nan() || closest_squared > 1.0 {
            return;
        }
        let half_chord = (1.0 - closest_squared).sqrt() * (1.0 + 1e-9) + 1e-12;
        let major = self.major / scale;
        let minor = self.minor / scale;
        let major_squared = major * major;
        let offset = closest_squared + major_squared - minor * minor;
        let across_xz = unit_direction.x * unit_direction.x + unit_direction.z * unit_direction.z;
        let along_xz = closest.x * unit_direction.x + closest.z * unit_direction.z;
        let closest_xz = closest.x * closest.x + closest.z * closest.z;
        let coefficients = [
            1.0,
            0.0,
            2.0 * offset - 4.0 * major_squared * across_xz,
            -8.0 * major_squared * along_xz,
            offset * offset - 4.0 * major_squared * closest_xz,
        ];
        let mut found = [0.0; MAX_DEGREE];
        let count = real_roots_between(&coefficients, -half_chord, half_chord, &mut found);
        for &root in &found[..count] {
            roots.push((closest_offset + root) * scale / speed, 0);
        }
    }

    /// True when `point` is strictly inside the tube.
    pub fn inside(&self, point: DVec3) -> bool {
        let radial = (point.x * point.x + point.z * point.z).sqrt() - self.major;
        radial * radial + point.y * point.y < self.minor * self.minor
    }

    /// Outward normal (not normalised): away from the nearest point of the centre circle.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        let radial = DVec3::new(point.x, 0.0, point.z);
        let radial_length = radial.length();
        if radial_length > 0.0 {
            point - radial * (self.major / radial_length)
        } else {
            DVec3::new(0.0, point.y.signum(), 0.0)
        }
    }

    /// Bounding box.
    pub fn bounds(&self) -> Aabb {
        let reach = self.major + self.minor;
        Aabb::from_corners(
            DVec3::new(-reach, -self.minor, -reach),
            DVec3::new(reach, self.minor, reach),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn torus_known_hits() {
        let TorusShape::Torus(torus) = Torus::from_radii(2.0, 0.5).unwrap() else {
            panic!("expected a torus");
        };
        let mut roots = Roots::new();
        torus.intersect(DVec3::new(-5.0, 0.0, 0.0), DVec3::X, &mut roots);
        let mut hits: Vec<f64> = roots.iter().map(|(distance, _)| distance).collect();
        hits.sort_by(f64::total_cmp);
        let expected = [2.5, 3.5, 6.5, 7.5];
        assert_eq!(hits.len(), 4);
        for (hit, want) in hits.iter().zip(expected) {
            assert!((hit - want).abs() < 1e-9, "{hits:?}");
        }
        let normal = torus.normal(DVec3::new(-2.5, 0.0, 0.0));
        assert!((normal.normalize() - -DVec3::X).length() < 1e-12);
        // Straight down through the tube at x = 2: hits at y = ±0.5.
        let mut roots = Roots::new();
        torus.intersect(DVec3::new(2.0, 5.0, 0.0), -DVec3::Y * 2.0, &mut roots);
        let mut hits: Vec<f64> = roots.iter().map(|(distance, _)| distance).collect();
        hits.sort_by(f64::total_cmp);
        assert_eq!(hits.len(), 2);
        assert!((hits[0] - 2.25).abs() < 1e-9 && (hits[1] - 2.75).abs() < 1e-9);
        assert!(torus.inside(DVec3::new(0.0, 0.1, 2.2)));
        assert!(!torus.inside(DVec3::ZERO));
    }
}
