//! Flat shapes with more data than a triangle: the smooth triangle and the polygon.
//!
//! In: corners with vertex normals; closed outlines in one plane. Out: intersections (one per
//! line at most), interpolated or plane normals, bounds.
//! Holds: neither shape has an inside (like POV-Ray, `inverse` leaves them unchanged); a
//! degenerate input (collinear corners, outlines with no area, non-finite values) gives `None`.

use super::flat::Triangle;
use super::roots::Roots;
use super::uv::barycentric;
use crate::accel::Aabb;
use glam::{DAffine3, DVec2, DVec3};

/// A triangle whose normal is interpolated between normals given at its corners.
#[derive(Clone, Copy, Debug)]
pub struct SmoothTriangle {
    triangle: Triangle,
    normals: [DVec3; 3],
}

impl SmoothTriangle {
    /// A smooth triangle; zero vertex normals fall back to the flat normal.
    pub fn new(corners: [DVec3; 3], normals: [DVec3; 3]) -> Option<SmoothTriangle> {
        let triangle = Triangle::new(corners)?;
        let flat = triangle.normal().normalize();
        let normals = normals.map(|n| n.try_normalize().unwrap_or(flat));
        Some(SmoothTriangle { triangle, normals })
    }

    /// The same triangle after `map` (normals mapped by the inverse transpose).
    pub fn transformed(&self, map: &DAffine3) -> Option<SmoothTriangle> {
        let normal_map = map.matrix3.inverse().transpose();
        let corners = self
            .triangle
            .corners()
            .map(|corner| map.transform_point3(corner));
        SmoothTriangle::new(corners, self.normals.map(|n| normal_map * n))
    }

    /// The three corners.
    pub fn corners(&self) -> [DVec3; 3] {
        self.triangle.corners()
    }

    /// Pushes the crossing of the line with the triangle.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        self.triangle.intersect(origin, direction, roots);
    }

    /// The normal interpolated at `point` from the corner normals (barycentric weights).
    pub fn normal(&self, point: DVec3) -> DVec3 {
        self.normal_at_weights(barycentric(self.corners(), point))
    }

    /// The normal interpolated at the point with barycentric `weights`.
    pub fn normal_at_weights(&self, weights: [f64; 3]) -> DVec3 {
        interpolated_normal(self.normals, weights, self.triangle.normal())
    }

    /// Bounding box of the corners.
    pub fn bounds(&self) -> Aabb {
        self.triangle.bounds()
    }
}

/// The normal of a triangle at the point with barycentric `weights` (see
/// [`barycentric`]), interpolated from the unit corner `normals` with the weights clamped
/// onto the triangle; `flat` where that gives no direction.
pub fn interpolated_normal(normals: [DVec3; 3], weights: [f64; 3], flat: DVec3) -> DVec3 {
    let u = weights[1].clamp(0.0, 1.0);
    let v = weights[2].clamp(0.0, 1.0 - u);
    let normal = normals[0] * (1.0 - u - v) + normals[1] * u + normals[2] * v;
    if normal.length_squared() > 0.0 {
        normal
    } else {
        flat
    }
}

/// Closed outlines in one plane; a point of the plane is on the polygon when a line from it
/// crosses the outlines an odd number of times.
#[derive(Clone, Debug)]
pub struct Polygon {
    /// A point of the plane.
    origin: DVec3,
    /// Unit normal of the plane.
    normal: DVec3,
    /// In-plane axes for the 2-D test.
    axis_u: DVec3,
    axis_v: DVec3,
    /// Edges as 2-D (start, end) pairs in the plane's axes.
    edges: Vec<(DVec2, DVec2)>,
    /// Bounds of the points.
    bounds: Aabb,
}

impl Polygon {
    /// A polygon from its outlines; `None` when the points do not span a plane or are not
    /// finite. Points off the plane of the first outline are projected onto it.
    pub fn new(outlines: &[Vec<DVec3>]) -> Option<Polygon> {
        let points: Vec<DVec3> = outlines.iter().flatten().copied().collect();
        if points.len() < 3 || points.iter().any(|p| !p.is_finite()) {
            return None;
        }
        // Newell's method gives the plane normal of the first outline robustly.
        let first = outlines.iter().find(|o| o.len() >= 3)?;
        let mut normal = DVec3::ZERO;
        for (index, &current) in first.iter().enumerate() {
            let next = first[(index + 1) % first.len()];
            normal += (current - next).cross(current + next);
        }
        let normal = normal.try_normalize()?;
        let origin = first[0];
        let axis_u = (first[1] - first[0])
            .try_normalize()
            .unwrap_or_else(|| normal.any_orthonormal_vector());
        let axis_u = (axis_u - normal * axis_u.dot(normal)).try_normalize()?;
        let axis_v = normal.cross(axis_u);
        let flat = |p: DVec3| DVec2::new((p - origin).dot(axis_u), (p - origin).dot(axis_v));
        let mut edges = Vec::with_capacity(points.len());
        for outline in outlines {
            for (index, &start) in outline.iter().enumerate() {
                let end = outline[(index + 1) % outline.len()];
                edges.push((flat(start), flat(end)));
            }
        }
        Some(Polygon {
            origin,
            normal,
            axis_u,
            axis_v,
            edges,
            bounds: Aabb::from_points(points),
        })
    }

    /// True when the in-plane point lies on the polygon (even-odd rule).
    fn covers(&self, point: DVec2) -> bool {
        let mut inside = false;
        for &(start, end) in &self.edges {
            if (start.y > point.y) != (end.y > point.y) {
                let crossing_x =
                    start.x + (point.y - start.y) / (end.y - start.y) * (end.x - start.x);
                if point.x < crossing_x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Pushes the crossing of the line with the polygon.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let approach = direction.dot(self.normal);
        if approach == 0.0 {
            return;
        }
        let distance = (self.origin - origin).dot(self.normal) / approach;
        let offset = origin + direction * distance - self.origin;
        if self.covers(DVec2::new(offset.dot(self.axis_u), offset.dot(self.axis_v))) {
            roots.push(distance, 0);
        }
    }

    /// The plane's unit normal (the side where the first outline runs anticlockwise).
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// Bounding box of the points.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hits(polygon: &Polygon, x: f64, y: f64) -> bool {
        let mut roots = Roots::new();
        polygon.intersect(DVec3::new(x, y, -5.0), DVec3::Z, &mut roots);
        roots.iter().count() == 1
    }

    #[test]
    fn polygon_with_hole_uses_even_odd_rule() {
        let square = |r: f64| {
            vec![
                DVec3::new(-r, -r, 0.0),
                DVec3::new(r, -r, 0.0),
                DVec3::new(r, r, 0.0),
                DVec3::new(-r, r, 0.0),
            ]
        };
        let polygon = Polygon::new(&[square(2.0), square(1.0)]).unwrap();
        assert!(hits(&polygon, 1.5, 0.0));
        assert!(!hits(&polygon, 0.0, 0.0));
        assert!(!hits(&polygon, 3.0, 0.0));
        assert!(polygon.normal().abs().abs_diff_eq(DVec3::Z, 1e-12));
        let mut roots = Roots::new();
        polygon.intersect(DVec3::new(1.5, 0.0, -5.0), DVec3::Z, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 10.0).map(|h| h.0), Some(5.0));
    }

    #[test]
    fn degenerate_polygons_are_rejected() {
        let line = vec![DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        assert!(Polygon::new(&[line]).is_none());
        assert!(Polygon::new(&[]).is_none());
        let nan = vec![DVec3::ZERO, DVec3::X, DVec3::splat(f64::NAN)];
        assert!(Polygon::new(&[nan]).is_none());
    }

    #[test]
    fn smooth_triangle_interpolates_normals() {
        let corners = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let normals = [DVec3::Z, DVec3::X + DVec3::Z, DVec3::Y + DVec3::Z];
        let triangle = SmoothTriangle::new(corners, normals).unwrap();
        let at_corner = triangle.normal(DVec3::ZERO).normalize();
        assert!(at_corner.abs_diff_eq(DVec3::Z, 1e-12));
        let at_second = triangle.normal(DVec3::X).normalize();
        assert!(at_second.abs_diff_eq((DVec3::X + DVec3::Z).normalize(), 1e-12));
        let moved = triangle
            .transformed(&DAffine3::from_scale(DVec3::new(2.0, 1.0, 1.0)))
            .unwrap();
        let n = moved.normal(DVec3::new(2.0, 0.0, 0.0)).normalize();
        assert!(n.abs_diff_eq(DVec3::new(0.5, 0.0, 1.0).normalize(), 1e-12));
        assert!(SmoothTriangle::new([DVec3::ZERO; 3], normals).is_none());
    }
}
