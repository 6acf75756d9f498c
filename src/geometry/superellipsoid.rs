//! The superellipsoid `(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1` inside the unit cube.
//!
//! In: the exponents `e` (east-west) and `n` (north-south). Out: crossings of a line (the
//! line inside the cube is split where x, y or z is zero and where |x| = |y|, each piece is
//! sampled for sign changes and each change is bisected), inside test (the function is
//! negative inside), gradient normals, bounds. Holds: a tangent touch that never changes
//! the sign is missed; nothing allocates.

use super::roots::Roots;
use crate::accel::Aabb;
use glam::DVec3;

/// Samples per piece of the line when looking for sign changes.
const SAMPLES: usize = 12;
/// Bisection steps per root.
const BISECTIONS: usize = 60;

/// A superellipsoid in the unit cube.
#[derive(Clone, Copy, Debug)]
pub struct Superellipsoid {
    /// 2 / e: the exponent of |x| and |y|.
    horizontal: f64,
    /// e / n: the exponent of the horizontal sum.
    blend: f64,
    /// 2 / n: the exponent of |z|.
    vertical: f64,
}

impl Superellipsoid {
    /// A superellipsoid; `None` unless both exponents are positive and finite.
    pub fn new(east_west: f64, north_south: f64) -> Option<Superellipsoid> {
        let usable = |v: f64| v > 0.0 && v.is_finite();
        (usable(east_west) && usable(north_south)).then(|| Superellipsoid {
            horizontal: 2.0 / east_west,
            blend: east_west / north_south,
            vertical: 2.0 / north_south,
        })
    }

    /// The implicit function: negative inside, zero on the surface.
    pub fn value(&self, p: DVec3) -> f64 {
        let horizontal = p.x.abs().powf(self.horizontal) + p.y.abs().powf(self.horizontal);
        horizontal.powf(self.blend) + p.z.abs().powf(self.vertical) - 1.0
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        // The part of the line inside the cube [-1, 1]³.
        let mut entry = f64::NEG_INFINITY;
        let mut exit = f64::INFINITY;
        for axis in 0..3 {
            if direction[axis] == 0.0 {
                if origin[axis].abs() > 1.0 {
                    return;
                }
                continue;
            }
            let first = (-1.0 - origin[axis]) / direction[axis];
            let second = (1.0 - origin[axis]) / direction[axis];
            entry = entry.max(first.min(second));
            exit = exit.min(first.max(second));
        }
        if !(entry.is_finite() && exit.is_finite()) || entry >= exit {
            return;
        }
        let mut breaks = [0.0; 8];
        let mut count = 0;
        breaks[count] = entry;
        count += 1;
        let mut add = |t: f64| {
            if t > entry && t < exit && t.is_finite() {
                breaks[count] = t;
                count += 1;
            }
        };
        for axis in 0..3 {
            if direction[axis] != 0.0 {
                add(-origin[axis] / direction[axis]);
            }
        }
        if direction.x != direction.y {
            add((origin.y - origin.x) / (direction.x - direction.y));
        }
        if direction.x != -direction.y {
            add(-(origin.x + origin.y) / (direction.x + direction.y));
        }
        breaks[count] = exit;
        count += 1;
        let pieces = &mut breaks[..count];
        pieces.sort_by(f64::total_cmp);
        let at = |t: f64| self.value(origin + direction * t);
        for window in pieces.windows(2) {
            let (start, end) = (window[0], window[1]);
            let step = (end - start) / SAMPLES as f64;
            let mut previous_t = start;
            let mut previous = at(start);
            for sample in 1..=SAMPLES {
                let t = if sample == SAMPLES {
                    end
                } else {
                    start + step * sample as f64
                };
                let value = at(t);
                if (previous < 0.0) != (value < 0.0) {
                    let (mut low, mut high) = (previous_t, t);
                    let low_negative = previous < 0.0;
                    for _ in 0..BISECTIONS {
                        let middle = 0.5 * (low + high);
                        if (at(middle) < 0.0) == low_negative {
                            low = middle;
                        } else {
                            high = middle;
                        }
                    }
                    roots.push(0.5 * (low + high), 0);
                }
                previous_t = t;
                previous = value;
            }
        }
    }

    /// True when the function is negative at `point`.
    pub fn inside(&self, point: DVec3) -> bool {
        self.value(point) < 0.0
    }

    /// The gradient at `point` (outwards).
    pub fn normal(&self, point: DVec3) -> DVec3 {
        let power_slope = |v: f64, exponent: f64| {
            let magnitude = v.abs().max(1e-300);
            exponent * magnitude.powf(exponent - 1.0) * v.signum()
        };
        let horizontal = point.x.abs().powf(self.horizontal) + point.y.abs().powf(self.horizontal);
        let outer = if horizontal > 0.0 {
            self.blend * horizontal.powf(self.blend - 1.0)
        } else {
            0.0
        };
        let gradient = DVec3::new(
            outer * power_slope(point.x, self.horizontal),
            outer * power_slope(point.y, self.horizontal),
            power_slope(point.z, self.vertical),
        );
        if gradient.is_finite() && gradient != DVec3::ZERO {
            gradient
        } else {
            point
        }
    }

    /// The unit cube.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points([DVec3::splat(-1.0), DVec3::splat(1.0)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_superellipsoid_is_a_sphere() {
        let shape = Superellipsoid::new(1.0, 1.0).unwrap();
        let mut roots = Roots::new();
        shape.intersect(DVec3::new(-5.0, 0.1, 0.2), DVec3::X, &mut roots);
        let expected = (1.0f64 - 0.01 - 0.04).sqrt();
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 2);
        assert!((found[0] - (5.0 - expected)).abs() < 1e-9);
        assert!((found[1] - (5.0 + expected)).abs() < 1e-9);
        let n = shape.normal(DVec3::new(0.0, 0.0, 1.0)).normalize();
        assert!(n.abs_diff_eq(DVec3::Z, 1e-9));
        assert!(Superellipsoid::new(0.0, 1.0).is_none());
        assert!(Superellipsoid::new(1.0, f64::NAN).is_none());
    }

    #[test]
    fn boxy_superellipsoid_crossings_agree_with_inside_test() {
        let shape = Superellipsoid::new(0.25, 0.5).unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            11,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| shape.intersect(origin, direction, roots),
            |point| shape.inside(point),
        );
    }
}
