//! Round solids: sphere, cylinder and cone, in the object's local space.
//!
//! In: shape parameters as written in the scene; rays as local origin plus (not necessarily
//! unit) direction. Out: intersections tagged with a surface part, inside tests, outward
//! normals, bounds. Holds: constructors return `None` for degenerate input (zero or non-finite
//! radius, zero-length axis), which the caller turns into an empty shape.

use super::flat::{disc_reach, pov_box_corners};
use super::roots::{solve_quadratic, Roots};
use crate::accel::Aabb;
use glam::{DMat3, DVec3};

/// Surface part tag of a cylinder or cone side.
const SIDE: u8 = 0;
/// Surface part tag of the cap at the base end.
const BASE_CAP: u8 = 1;
/// Surface part tag of the cap at the far end.
const END_CAP: u8 = 2;

/// Relative margin by which a point must lie inside a cylinder or cone to count as inside.
const INSIDE_TOLERANCE: f64 = 1e-10;

/// A sphere given by its centre and radius.
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    centre: DVec3,
    radius: f64,
}

impl Sphere {
    /// A sphere; `None` when the radius is zero or not finite, or the centre is not finite.
    pub fn new(centre: DVec3, radius: f64) -> Option<Sphere> {
        let radius = radius.abs();
        (radius > 0.0 && radius.is_finite() && centre.is_finite())
            .then_some(Sphere { centre, radius })
    }

    /// The centre.
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Pushes both crossings of the line `origin + t direction`.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let offset = origin - self.centre;
        let a = direction.length_squared();
        let half_b = offset.dot(direction);
        let c = offset.length_squared() - self.radius * self.radius;
        if let Some((near, far)) = solve_quadratic(a, half_b, c) {
            roots.push(near, SIDE);
            roots.push(far, SIDE);
        }
    }

    /// True when `point` is strictly inside.
    pub fn inside(&self, point: DVec3) -> bool {
        (point - self.centre).length_squared() < self.radius * self.radius
    }

    /// Outward normal (not normalised) at a surface point.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        point - self.centre
    }

    /// Bounding box.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_corners(self.centre - self.radius, self.centre + self.radius)
    }
}

/// An orthonormal frame along an axis: rows map local offsets to (across, across, along).
#[derive(Clone, Copy, Debug)]
struct AxisFrame {
    /// The axis start point.
    origin: DVec3,
    /// Rows: two unit vectors across the axis, then the unit axis.
    frame_from_local: DMat3,
    /// Distance from the start to the end of the axis.
    length: f64,
}

impl AxisFrame {
    /// The frame from `start` towards `end`; `None` for a zero-length or non-finite axis.
    fn new(start: DVec3, end: DVec3) -> Option<AxisFrame> {
        let axis = end - start;
        let length = axis.length();
        if !(length > 0.0 && length.is_finite() && start.is_finite()) {
            return None;
        }
        let along = axis / length;
        let across = along.any_orthonormal_vector();
        let across_too = along.cross(across);
        Some(AxisFrame {
            origin: start,
            frame_from_local: DMat3::from_cols(across, across_too, along).transpose(),
            length,
        })
    }

    /// A local point in frame coordinates.
    fn point(&self, point: DVec3) -> DVec3 {
        self.frame_from_local * (point - self.origin)
    }

    /// A local direction in frame coordinates.
    fn vector(&self, vector: DVec3) -> DVec3 {
        self.frame_from_local * vector
    }

    /// A frame-coordinate direction back in local coordinates.
    fn vector_to_local(&self, vector: DVec3) -> DVec3 {
        self.frame_from_local.transpose() * vector
    }

    /// The unit axis direction.
    fn along(&self) -> DVec3 {
        self.frame_from_local.row(2)
    }

    /// Bounds of a disc of `radius` centred at `centre` across the axis.
    fn disc_bounds(&self, centre: DVec3, radius: f64) -> Aabb {
        let reach = disc_reach(self.along(), radius);
        Aabb::from_corners(centre - reach, centre + reach)
    }
}

/// A cylinder (or, with different radii, a cone frustum) along an axis, capped unless open.
///
/// In frame coordinates the side is x² + y² = (base_radius + slope z)² for 0 ≤ z ≤ length.
#[derive(Clone, Copy, Debug)]
pub struct Cone {
    frame: AxisFrame,
    base_radius: f64,
    end_radius: f64,
    /// Change of radius per unit of length along the axis.
    slope: f64,
    open: bool,
}

impl Cone {
    /// A cylinder; `None` when degenerate.
    pub fn cylinder(base: DVec3, cap: DVec3, radius: f64, open: bool) -> Option<Cone> {
        Cone::new(base, radius, cap, radius, open)
    }

    /// A cone frustum; `None` when degenerate (zero-length axis, both radii zero, non-finite).
    pub fn new(
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        open: bool,
    ) -> Option<Cone> {
        let frame = AxisFrame::new(base, cap)?;
        let base_radius = base_radius.abs();
        let end_radius = cap_radius.abs();
        if !(base_radius.is_finite() && end_radius.is_finite())
            || (base_radius == 0.0 && end_radius == 0.0)
        {
            return None;
        }
        let slope = (end_radius - base_radius) / frame.length;
        Some(Cone {
            frame,
            base_radius,
            end_radius,
            slope,
            open,
        })
    }

    /// Radius of the side at height `z` along the axis.
    #[inline]
    fn radius_at(&self, z: f64) -> f64 {
        self.base_radius + self.slope * z
    }

    /// Pushes every crossing of the line with the side and (unless open) the caps.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let start = self.frame.point(origin);
        let step = self.frame.vector(direction);
        let length = self.frame.length;
        let radius_start = self.radius_at(start.z);
        let radius_step = self.slope * step.z;
        let a = step.x * step.x + step.y * step.y - radius_step * radius_step;
        let half_b = start.x * step.x + start.y * step.y - radius_start * radius_step;
        let c = start.x * start.x + start.y * start.y - radius_start * radius_start;
        if let Some((near, far)) = solve_quadratic(a, half_b, c) {
            for distance in if near == far {
                [near, f64::NAN]
            } else {
                [near, far]
            } {
                let z = start.z + distance * step.z;
                if (0.0..=length).contains(&z) {
                    roots.push(distance, SIDE);
                }
            }
        }
        if self.open || step.z == 0.0 {
            return;
        }
        for (part, height, radius) in [
            (BASE_CAP, 0.0, self.base_radius),
            (END_CAP, length, self.end_radius),
        ] {
            let distance = (height - start.z) / step.z;
            let x = start.x + distance * step.x;
            let y = start.y + distance * step.y;
            if x * x + y * y <= radius * radius {
                roots.push(distance, part);
            }
        }
    }

    /// True when `point` is inside the solid (open ones included) by more than a relative
    /// [`INSIDE_TOLERANCE`]: POV-Ray counts the surface of cylinders and cones as outside.
    pub fn inside(&self, point: DVec3) -> bool {
        let local = self.frame.point(point);
        let radius = self.radius_at(local.z);
        let length = self.frame.length;
        local.z > length * INSIDE_TOLERANCE
            && local.z < length * (1.0 - INSIDE_TOLERANCE)
            && local.x * local.x + local.y * local.y < radius * radius * (1.0 - INSIDE_TOLERANCE)
    }

    /// Outward normal (not normalised) at a surface point on surface part `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        match part {
            BASE_CAP => -self.frame.along(),
            END_CAP => self.frame.along(),
            _ => {
                let local = self.frame.point(point);
                let radial = DVec3::new(local.x, local.y, 0.0);
                let radial_length = radial.length();
                if radial_length > 0.0 {
                    // The side's slope tilts the normal against the direction of growth.
                    let tilt = -self.slope;
                    self.frame
                        .vector_to_local(radial / radial_length + DVec3::Z * tilt)
                } else {
                    // The apex of a pointed cone: point along the axis away from the body.
                    self.frame.along() * -self.slope.signum()
                }
            }
        }
    }

    /// Corners of POV-Ray's bounding box: the larger radius across the axis, oriented like
    /// [`pov_frame`](super::flat::pov_frame), from base to cap along it.
    pub fn pov_box_corners(&self) -> [DVec3; 8] {
        let half_width = self.base_radius.max(self.end_radius);
        pov_box_corners(
            self.frame.origin,
            self.frame.along(),
            half_width,
            self.frame.length,
        )
    }

    /// Bounding box of the two end discs.
    pub fn bounds(&self) -> Aabb {
        let end = self.frame.origin + self.frame.along() * self.frame.length;
        self.frame
            .disc_bounds(self.frame.origin, self.base_radius)
            .union(&self.frame.disc_bounds(end, self.end_radius))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_known_hit() {
        let sphere = Sphere::new(DVec3::ZERO, 1.0).unwrap();
        let mut roots = Roots::new();
        sphere.intersect(DVec3::new(0.0, 0.0, -5.0), DVec3::Z, &mut roots);
        assert_eq!(roots.nearest_within(0.0, f64::INFINITY), Some((4.0, SIDE)));
        assert_eq!(
            sphere.normal(DVec3::new(0.0, 0.0, -1.0)),
            DVec3::new(0.0, 0.0, -1.0)
        );
        assert!(Sphere::new(DVec3::ZERO, 0.0).is_none());
        assert!(Sphere::new(DVec3::ZERO, f64::NAN).is_none());
    }

    #[test]
    fn cylinder_caps_and_side() {
        let cylinder = Cone::cylinder(DVec3::ZERO, DVec3::Y * 2.0, 1.0, false).unwrap();
        let mut roots = Roots::new();
        cylinder.intersect(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 100.0).map(|hit| hit.0), Some(3.0));
        let (distance, part) = roots.nearest_within(0.0, 100.0).unwrap();
        assert_eq!(
            cylinder.normal(DVec3::new(0.0, 5.0 - distance, 0.0), part),
            DVec3::Y
        );
        let mut roots = Roots::new();
        cylinder.intersect(DVec3::new(-5.0, 1.0, 0.0), DVec3::X, &mut roots);
        let (distance, part) = roots.nearest_within(0.0, 100.0).unwrap();
        assert!((distance - 4.0).abs() < 1e-12);
        let normal = cylinder
            .normal(DVec3::new(-1.0, 1.0, 0.0), part)
            .normalize();
        assert!((normal - -DVec3::X).length() < 1e-12);
        let open = Cone::cylinder(DVec3::ZERO, DVec3::Y * 2.0, 1.0, true).unwrap();
        let mut roots = Roots::new();
        open.intersect(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert!(roots.iter().next().is_none());
        assert!(Cone::cylinder(DVec3::ONE, DVec3::ONE, 1.0, false).is_none());
    }

    #[test]
    fn cone_side_normal_tilts() {
        // Unit cone from radius 1 at y = 0 to a point at y = 1: the side normal is (1, 1)/√2.
        let cone = Cone::new(DVec3::ZERO, 1.0, DVec3::Y, 0.0, false).unwrap();
        let normal = cone.normal(DVec3::new(0.5, 0.5, 0.0), SIDE).normalize();
        let expected = DVec3::new(1.0, 1.0, 0.0).normalize();
        assert!((normal - expected).length() < 1e-12);
        let mut roots = Roots::new();
        cone.intersect(DVec3::new(-5.0, 0.5, 0.0), DVec3::X, &mut roots);
        let (distance, _) = roots.nearest_within(0.0, 100.0).unwrap();
        assert!((distance - 4.5).abs() < 1e-12);
    }
}
