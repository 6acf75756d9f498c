//! The axis-aligned box (`box { corner1, corner2 }`), in local space.
//!
//! In: two opposite corners as written in the scene; rays as local origin plus (not
//! necessarily unit) direction. Out: the entry and exit crossings tagged with the face hit,
//! inside test (faces count as inside), outward face normals, bounds. Holds: the constructor
//! returns `None` for non-finite corners, which the caller turns into an empty shape.

use super::roots::Roots;
use crate::accel::Aabb;
use glam::{DAffine3, DVec3};

/// An axis-aligned box between two corners.
#[derive(Clone, Copy, Debug)]
pub struct Cuboid {
    min: DVec3,
    max: DVec3,
}

impl Cuboid {
    /// A box from two opposite corners in any order; `None` when a coordinate is not a
    /// number. An infinite coordinate makes a box that runs on forever that way (POV-Ray
    /// renders `box { <0, 0, 1>, <1, 1, 5/0> }`, whose corner is at infinity).
    pub fn new(corner1: DVec3, corner2: DVec3) -> Option<Cuboid> {
        (!corner1.is_nan() && !corner2.is_nan()).then_some(Cuboid {
            min: corner1.min(corner2),
            max: corner1.max(corner2),
        })
    }

    /// The same box after a map that only scales and translates each axis (diagonal matrix).
    pub fn scaled_and_moved(&self, map: &DAffine3) -> Option<Cuboid> {
        // Axis by axis, so that an infinite corner meets no zero off the diagonal.
        let scale = DVec3::new(
            map.matrix3.x_axis.x,
            map.matrix3.y_axis.y,
            map.matrix3.z_axis.z,
        );
        Cuboid::new(
            self.min * scale + map.translation,
            self.max * scale + map.translation,
        )
    }

    /// Whether every corner coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// Pushes where the line enters and leaves the box.
    ///
    /// The part tag is `2 * axis` for the face at the smaller coordinate and `2 * axis + 1`
    /// for the face at the larger one.
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let mut entry = f64::NEG_INFINITY;
        let mut exit = f64::INFINITY;
        let mut entry_part = 0;
        let mut exit_part = 0;
        for axis in 0..3 {
            let step = direction[axis];
            let start = origin[axis];
            if step == 0.0 {
                if start < self.min[axis] || start > self.max[axis] {
                    return;
                }
                continue;
            }
            let to_min = (self.min[axis] - start) / step;
            let to_max = (self.max[axis] - start) / step;
            let axis_tag = 2 * axis as u8;
            // By direction, not by distance: a flat box (both faces at one distance) is then
            // entered through the face the ray meets from outside.
            let (near, far, near_part, far_part) = if step > 0.0 {
                (to_min, to_max, axis_tag, axis_tag + 1)
            } else {
                (to_max, to_min, axis_tag + 1, axis_tag)
            };
            if near > entry {
                entry = near;
                entry_part = near_part;
            }
            if far < exit {
                exit = far;
                exit_part = far_part;
            }
        }
        if entry <= exit {
            roots.push(entry, entry_part);
            roots.push(exit, exit_part);
        }
    }

    /// True when `point` is inside or on the box (POV-Ray counts the faces as inside).
    pub fn inside(&self, point: DVec3) -> bool {
        point.cmpge(self.min).all() && point.cmple(self.max).all()
    }

    /// Outward unit normal of the face with tag `part`.
    pub fn normal(&self, part: u8) -> DVec3 {
        let mut normal = DVec3::ZERO;
        normal[(part / 2).min(2) as usize] = if part.is_multiple_of(2) { -1.0 } else { 1.0 };
        normal
    }

    /// The box itself.
    pub fn bounds(&self) -> Aabb {
        Aabb {
            min: self.min,
            max: self.max,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_faces() {
        let cuboid = Cuboid::new(DVec3::ONE, -DVec3::ONE).unwrap();
        let mut roots = Roots::new();
        cuboid.intersect(DVec3::new(0.5, 0.5, -5.0), DVec3::Z, &mut roots);
        let hits: Vec<_> = roots.iter().collect();
        assert_eq!(hits, vec![(4.0, 4), (6.0, 5)]);
        assert_eq!(cuboid.normal(4), -DVec3::Z);
        assert_eq!(cuboid.normal(5), DVec3::Z);
        let mut roots = Roots::new();
        cuboid.intersect(DVec3::new(2.0, 0.0, -5.0), DVec3::Z, &mut roots);
        assert!(roots.iter().next().is_none());
    }
}
