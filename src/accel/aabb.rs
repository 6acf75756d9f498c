//! Axis-aligned bounding boxes and the ray–box slab test.
//!
//! In: corner points, affine maps, rays given as origin plus inverse direction.
//! Out: boxes, unions and intersections of boxes, ray entry distances.
//! Holds: an empty box has `min > max` on some axis and is never hit by a ray.

use glam::{DAffine3, DVec3};

/// An axis-aligned box given by its smallest and largest corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: DVec3,
    /// The corner with the largest coordinates.
    pub max: DVec3,
}

impl Aabb {
    /// The empty box: contains nothing, and is the identity of [`Aabb::union`].
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    /// The box spanned by two corners given in any order.
    pub fn from_corners(a: DVec3, b: DVec3) -> Aabb {
        Aabb {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// The smallest box holding every point of `points`.
    pub fn from_points(points: impl IntoIterator<Item = DVec3>) -> Aabb {
        points
            .into_iter()
            .fold(Aabb::EMPTY, |bounds, point| bounds.grown_to(point))
    }

    /// True when the box contains no point at all.
    pub fn is_empty(&self) -> bool {
        !(self.min.x <= self.max.x && self.min.y <= self.max.y && self.min.z <= self.max.z)
    }

    /// True when every coordinate of both corners is a finite number.
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// This box enlarged just enough to hold `point`.
    pub fn grown_to(&self, point: DVec3) -> Aabb {
        Aabb {
            min: self.min.min(point),
            max: self.max.max(point),
        }
    }

    /// The smallest box holding both boxes.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The overlap of both boxes (possibly empty).
    pub fn intersection(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(other.min),
            max: self.max.min(other.max),
        }
    }

    /// The midpoint of the box.
    pub fn centre(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// The full size along each axis.
    pub fn extent(&self) -> DVec3 {
        self.max - self.min
    }

    /// The area of the box's surface; zero for an empty box.
    pub fn surface_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let size = self.extent();
        2.0 * (size.x * size.y + size.y * size.z + size.z * size.x)
    }

    /// True when `point` lies inside or on the box.
    pub fn contains(&self, point: DVec3) -> bool {
        point.cmpge(self.min).all() && point.cmple(self.max).all()
    }

    /// The box grown on every side by `relative` times its largest size plus `absolute`.
    pub fn padded(&self, relative: f64, absolute: f64) -> Aabb {
        if self.is_empty() {
            return *self;
        }
        let size = self.extent();
        let margin = DVec3::splat(size.max_element() * relative + absolute)
            + self.min.abs().max(self.max.abs()) * relative;
        Aabb {
            min: self.min - margin,
            max: self.max + margin,
        }
    }

    /// The bounds of this box after mapping it through `map` (all eight corners mapped).
    pub fn transformed(&self, map: &DAffine3) -> Aabb {
        if self.is_empty() {
            return *self;
        }
        let corners = (0..8).map(|index| {
            DVec3::new(
                if index & 1 == 0 {
                    self.min.x
                } else {
                    self.max.x
                },
                if index & 2 == 0 {
                    self.min.y
                } else {
                    self.max.y
                },
                if index & 4 == 0 {
                    self.min.z
                } else {
                    self.max.z
                },
            )
        });
        Aabb::from_points(corners.map(|corner| map.transform_point3(corner)))
    }

    /// The ray parameter where the ray enters the box, when its span within the box overlaps
    /// `[min_distance, max_distance]`.
    ///
    /// `inverse_direction` is the componentwise reciprocal of the ray direction (infinite for a
    /// zero component). The returned value is clamped to `min_distance`.
    #[inline]
    pub fn ray_entry(
        &self,
        origin: DVec3,
        inverse_direction: DVec3,
        min_distance: f64,
        max_distance: f64,
    ) -> Option<f64> {
        let to_min = (self.min - origin) * inverse_direction;
        let to_max = (self.max - origin) * inverse_direction;
        let mut entry = min_distance;
        let mut exit = max_distance;
        for axis in 0..3 {
            let (a, b) = (to_min[axis], to_max[axis]);
            // A NaN (0 * infinity: a ray parallel to the axis lying in a face plane) fails
            // both comparisons, leaving the axis unlimited.
            if a <= b {
                entry = entry.max(a);
                exit = exit.min(b);
            } else if b < a {
                entry = entry.max(b);
                exit = exit.min(a);
            }
        }
        if entry <= exit {
            Some(entry)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ray_entry_hits_and_misses() {
        let unit = Aabb::from_corners(DVec3::splat(1.0), DVec3::splat(-1.0));
        let inverse = DVec3::ONE / DVec3::new(0.0, 0.0, 1.0);
        let origin = DVec3::new(0.0, 0.0, -5.0);
        assert_eq!(unit.ray_entry(origin, inverse, 0.0, 100.0), Some(4.0));
        assert_eq!(unit.ray_entry(origin, inverse, 0.0, 3.0), None);
        let beside = DVec3::new(2.0, 0.0, -5.0);
        assert_eq!(unit.ray_entry(beside, inverse, 0.0, 100.0), None);
        // A ray lying in a face plane still counts as touching.
        let on_face = DVec3::new(1.0, 0.0, -5.0);
        assert!(unit.ray_entry(on_face, inverse, 0.0, 100.0).is_some());
        assert!(Aabb::EMPTY.is_empty());
        assert_eq!(Aabb::EMPTY.surface_area(), 0.0);
    }

    #[test]
    fn transformed_box_holds_rotated_corners() {
        let unit = Aabb::from_corners(DVec3::ZERO, DVec3::ONE);
        let map = DAffine3::from_rotation_z(std::f64::consts::FRAC_PI_4);
        let bounds = unit.transformed(&map);
        for corner in [DVec3::ZERO, DVec3::ONE, DVec3::X, DVec3::Y] {
            assert!(bounds
                .padded(1e-12, 1e-12)
                .contains(map.transform_point3(corner)));
        }
    }
}
