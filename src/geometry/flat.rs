//! Flat shapes: plane, disc and triangle, in local space, and the frame of POV-Ray's
//! bounding boxes around discs, cylinders and cones (the axis-aligned box is in
//! [`cuboid`](super::cuboid); smooth triangles and polygons in [`polygon`](super::polygon)).
//!
//! In: shape parameters as written in the scene; rays as local origin plus (not necessarily
//! unit) direction. Out: intersections tagged with a surface part, inside tests, outward
//! normals, bounds. Holds: constructors return `None` for degenerate input (zero normal,
//! collinear triangle corners, non-finite numbers), which the caller turns into an empty shape.

use super::roots::Roots;
use crate::accel::Aabb;
use glam::{DAffine3, DVec3};

/// How far outside a plane a point may be and still count as inside it.
pub const INSIDE_TOLERANCE: f64 = 1e-10;

/// The plane `dot(point, normal) = distance` (unit normal); inside is the side opposite the
/// normal.
#[derive(Clone, Copy, Debug)]
pub struct Plane {
    normal: DVec3,
    distance: f64,
}

impl Plane {
    /// The plane as POV-Ray reads `plane { normal, distance }`: the normal is normalised and
    /// the plane lies `distance` along it; `None` for a zero or non-finite normal.
    pub fn new(normal: DVec3, distance: f64) -> Option<Plane> {
        let unit = normal.try_normalize()?;
        distance.is_finite().then_some(Plane {
            normal: unit,
            distance,
        })
    }

    /// The same plane after mapping space through an invertible affine `map`.
    pub fn transformed(&self, map: &DAffine3) -> Option<Plane> {
        let on_plane = map.transform_point3(self.normal * self.distance);
        let normal = (map.matrix3.inverse().transpose() * self.normal).try_normalize()?;
        Plane::new(normal, normal.dot(on_plane))
    }

    /// Pushes the crossing of the line with the plane.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let rate = self.normal.dot(direction);
        if rate != 0.0 {
            roots.push((self.distance - self.normal.dot(origin)) / rate, 0);
        }
    }

    /// True when `point` is on the inner side or within [`INSIDE_TOLERANCE`] of the plane
    /// (POV-Ray counts points on a plane as inside).
    pub fn inside(&self, point: DVec3) -> bool {
        self.normal.dot(point) - self.distance < INSIDE_TOLERANCE
    }

    /// The outward unit normal.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// How far the plane lies along its normal from the origin.
    pub fn distance(&self) -> f64 {
        self.distance
    }
}

/// A flat ring: points of a plane between the hole radius and the outer radius of a centre.
#[derive(Clone, Copy, Debug)]
pub struct Disc {
    centre: DVec3,
    normal: DVec3,
    radius_squared: f64,
    hole_radius_squared: f64,
}

impl Disc {
    /// A disc; `None` for a zero normal, zero radius or non-finite input.
    pub fn new(centre: DVec3, normal: DVec3, radius: f64, hole_radius: f64) -> Option<Disc> {
        let normal = normal.try_normalize()?;
        let radius_squared = radius * radius;
        let hole_radius_squared = hole_radius * hole_radius;
        (centre.is_finite()
            && radius_squared > 0.0
            && radius_squared.is_finite()
            && hole_radius_squared.is_finite()
            && hole_radius_squared < radius_squared)
            .then_some(Disc {
                centre,
                normal,
                radius_squared,
                hole_radius_squared,
            })
    }

    /// Pushes the crossing of the line with the ring.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let rate = self.normal.dot(direction);
        if rate == 0.0 {
            return;
        }
        let distance = self.normal.dot(self.centre - origin) / rate;
        let offset = (origin + direction * distance - self.centre).length_squared();
        if offset <= self.radius_squared && offset >= self.hole_radius_squared {
            roots.push(distance, 0);
        }
    }

    /// POV-Ray's disc inside: strictly on the inner side of the disc's plane, whatever the
    /// radius.
    pub fn inside(&self, point: DVec3) -> bool {
        self.normal.dot(point - self.centre) < 0.0
    }

    /// The outward unit normal.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// Corners of POV-Ray's bounding box of the disc: the square of half-width `radius` in the
    /// disc's plane, oriented like [`pov_frame`].
    pub fn pov_box_corners(&self) -> [DVec3; 8] {
        pov_box_corners(self.centre, self.normal, self.radius_squared.sqrt(), 0.0)
    }

    /// Bounding box of the ring.
    pub fn bounds(&self) -> Aabb {
        let reach = disc_reach(self.normal, self.radius_squared.sqrt());
        Aabb::from_corners(self.centre - reach, self.centre + reach)
    }
}

/// Half the size, along each axis, of the bounds of a disc of `radius` across unit `normal`.
pub fn disc_reach(normal: DVec3, radius: f64) -> DVec3 {
    let across = DVec3::ONE - normal * normal;
    DVec3::new(
        across.x.max(0.0).sqrt(),
        across.y.max(0.0).sqrt(),
        across.z.max(0.0).sqrt(),
    ) * radius
}

/// Two unit vectors across the unit `axis`: the images of x and y under the smallest rotation
/// taking the z axis to `axis`, which is how POV-Ray orients the boxes around discs, cylinders
/// and cones.
pub fn pov_frame(axis: DVec3) -> (DVec3, DVec3) {
    if 1.0 + axis.z <= 1e-12 {
        return (DVec3::X, -DVec3::Y);
    }
    let k = 1.0 / (1.0 + axis.z);
    (
        DVec3::new(1.0 - axis.x * axis.x * k, -axis.x * axis.y * k, -axis.x),
        DVec3::new(-axis.x * axis.y * k, 1.0 - axis.y * axis.y * k, -axis.y),
    )
}

/// Corners of the box reaching `half_width` across the unit `axis` (oriented by
/// [`pov_frame`]) and from `start` to `start + length * axis` along it.
pub fn pov_box_corners(start: DVec3, axis: DVec3, half_width: f64, length: f64) -> [DVec3; 8] {
    let (across, across_too) = pov_frame(axis);
    std::array::from_fn(|index| {
        let a = if index & 1 == 0 {
            -half_width
        } else {
            half_width
        };
        let b = if index & 2 == 0 {
            -half_width
        } else {
            half_width
        };
        let c = if index & 4 == 0 { 0.0 } else { length };
        start + across * a + across_too * b + axis * c
    })
}

/// A triangle, stored as one corner and the two edges leaving it.
#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    corner: DVec3,
    edge_one: DVec3,
    edge_two: DVec3,
}

impl Triangle {
    /// A triangle; `None` when the corners are collinear or not finite.
    pub fn new(corners: [DVec3; 3]) -> Option<Triangle> {
        let [a, b, c] = corners;
        let triangle = Triangle {
            corner: a,
            edge_one: b - a,
            edge_two: c - a,
        };
        let area = triangle.edge_one.cross(triangle.edge_two).length_squared();
        (area > 0.0 && area.is_finite() && a.is_finite()).then_some(triangle)
    }

    /// The same triangle with its corners mapped by `map`.
    pub fn transformed(&self, map: &DAffine3) -> Option<Triangle> {
        Triangle::new(self.corners().map(|corner| map.transform_point3(corner)))
    }

    /// The three corners.
    pub fn corners(&self) -> [DVec3; 3] {
        [
            self.corner,
            self.corner + self.edge_one,
            self.corner + self.edge_two,
        ]
    }

    /// Pushes the crossing of the line with the triangle (edges included).
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        if let Some(distance) =
            triangle_crossing(self.corner, self.edge_one, self.edge_two, origin, direction)
        {
            roots.push(distance, 0);
        }
    }

    /// A triangle has no inside.
    pub fn inside(&self, _point: DVec3) -> bool {
        false
    }

    /// The normal (not normalised): POV-Ray's, `(c − a) × (b − a)` for corners a, b, c
    /// (measured: `interior_texture` shows on the side `(b − a) × (c − a)` points to).
    pub fn normal(&self) -> DVec3 {
        self.edge_two.cross(self.edge_one)
    }

    /// Bounding box of the corners.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points(self.corners())
    }
}

/// The ray parameter where the line `origin + t direction` crosses the triangle with one
/// corner at `corner` and edges `edge_one`, `edge_two` leaving it (edges included), or `None`.
#[inline]
pub fn triangle_crossing(
    corner: DVec3,
    edge_one: DVec3,
    edge_two: DVec3,
    origin: DVec3,
    direction: DVec3,
) -> Option<f64> {
    let across_two = direction.cross(edge_two);
    let determinant = edge_one.dot(across_two);
    if determinant == 0.0 {
        return None;
    }
    let inverse_determinant = 1.0 / determinant;
    let offset = origin - corner;
    let first = offset.dot(across_two) * inverse_determinant;
    if !(0.0..=1.0).contains(&first) {
        return None;
    }
    let across_one = offset.cross(edge_one);
    let second = direction.dot(across_one) * inverse_determinant;
    if second < 0.0 || first + second > 1.0 {
        return None;
    }
    Some(edge_two.dot(across_one) * inverse_determinant)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_follows_pov_ray_definition() {
        // plane { <0, 2, 0>, 1 } is the plane y = 1 with +y outside.
        let plane = Plane::new(DVec3::new(0.0, 2.0, 0.0), 1.0).unwrap();
        let mut roots = Roots::new();
        plane.intersect(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 100.0), Some((4.0, 0)));
        assert!(plane.inside(DVec3::ZERO));
        assert!(!plane.inside(DVec3::Y * 2.0));
        let moved = plane
            .transformed(&DAffine3::from_translation(DVec3::Y))
            .unwrap();
        assert!((moved.distance - 2.0).abs() < 1e-12);
        assert!(Plane::new(DVec3::ZERO, 1.0).is_none());
    }

    #[test]
    fn disc_hole_and_rim() {
        let disc = Disc::new(DVec3::ZERO, DVec3::Y, 2.0, 1.0).unwrap();
        for (x, hit) in [(0.5, false), (1.5, true), (2.5, false)] {
            let mut roots = Roots::new();
            disc.intersect(DVec3::new(x, 3.0, 0.0), -DVec3::Y, &mut roots);
            assert_eq!(roots.iter().count() == 1, hit, "x = {x}");
        }
        assert!(disc.inside(DVec3::new(10.0, -1.0, 0.0)));
    }

    #[test]
    fn triangle_hits_inside_only() {
        let triangle = Triangle::new([DVec3::ZERO, DVec3::X, DVec3::Y]).unwrap();
        let mut roots = Roots::new();
        triangle.intersect(DVec3::new(0.2, 0.2, -1.0), DVec3::Z * 2.0, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 10.0), Some((0.5, 0)));
        let mut roots = Roots::new();
        triangle.intersect(DVec3::new(0.6, 0.6, -1.0), DVec3::Z, &mut roots);
        assert!(roots.iter().next().is_none());
        assert!(Triangle::new([DVec3::ZERO, DVec3::X, DVec3::X * 2.0]).is_none());
    }
}
