//! The lathe: a 2-D curve of cubic segments in the (radius, height) plane turned around the
//! Y axis.
//!
//! In: segments as cubic Béziers of (r, y) points. Out: every crossing of a line (a degree-6
//! polynomial per segment, or a cubic then a quadratic for lines across the axis), inside
//! test (odd number of curve crossings of a line from the point outwards in the (r, y)
//! plane), outward normals, bounds. Holds: at most [`MAX_ROOTS`] crossings are reported, the
//! nearest ahead first when there are more; the part tag carries the segment number when it
//! fits; nothing allocates per ray.

use super::extrusion::Segment;
use super::roots::{real_roots_between, Roots, CROSSING_BUFFER, MAX_DEGREE};
use crate::accel::Aabb;
use glam::{DVec2, DVec3};

/// Part tag for crossings whose segment number does not fit in a tag.
const UNKNOWN_SEGMENT: u8 = u8::MAX;

/// Multiplies two polynomials given lowest power first.
fn multiply(first: &[f64; 4], second: &[f64; 4]) -> [f64; 7] {
    let mut product = [0.0; 7];
    for (i, a) in first.iter().enumerate() {
        for (j, b) in second.iter().enumerate() {
            product[i + j] += a * b;
        }
    }
    product
}

/// A surface of revolution around Y.
#[derive(Clone, Debug)]
pub struct Lathe {
    segments: Vec<Segment>,
    radius: f64,
    low: f64,
    high: f64,
}

impl Lathe {
    /// A lathe from (r, y) Bézier segments; `None` without segments or with non-finite points.
    pub fn new(segments: &[[DVec2; 4]]) -> Option<Lathe> {
        if segments.is_empty() || !segments.iter().flatten().all(|p| p.is_finite()) {
            return None;
        }
        let points = segments.iter().flatten();
        let radius = points.clone().fold(0.0f64, |m, p| m.max(p.x.abs()));
        let low = points.clone().fold(f64::INFINITY, |m, p| m.min(p.y));
        let high = points.fold(f64::NEG_INFINITY, |m, p| m.max(p.y));
        Some(Lathe {
            segments: segments.iter().copied().map(Segment::from_points).collect(),
            radius,
            low,
            high,
        })
    }

    /// True when (r, y) is enclosed by the curve (odd crossings towards larger r).
    fn covers(&self, point: DVec2) -> bool {
        let mut inside = false;
        for segment in &self.segments {
            let (found, count) = segment.crossings_with_line(DVec2::Y, point.y);
            for &t in &found[..count] {
                if segment.at(t).x > point.x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// POV-Ray's uv at the surface `point` of segment `part`: u the angle around Y from +x
    /// towards +z, v the curve parameter (segment number plus the position along it) over
    /// the number of segments (measured).
    pub fn uv(&self, point: DVec3, part: u8) -> DVec2 {
        let u = super::uv::sphere_uv(DVec3::new(point.x, 0.0, point.z)).x;
        let radius = DVec2::new(point.x, point.z).length();
        let count = self.segments.len();
        let candidates = match self.segments.get(usize::from(part)) {
            Some(_) if part != UNKNOWN_SEGMENT => usize::from(part)..usize::from(part) + 1,
            _ => 0..count,
        };
        // The parameter whose curve point lies closest to the point's (radius, height).
        let mut best = (f64::INFINITY, 0.0);
        for index in candidates {
            let segment = &self.segments[index];
            let (found, found_count) = segment.crossings_with_line(DVec2::Y, point.y);
            for &t in &found[..found_count] {
                let miss = (segment.at(t).x - radius).abs();
                if miss < best.0 {
                    best = (miss, (index as f64 + t.clamp(0.0, 1.0)) / count as f64);
                }
            }
        }
        DVec2::new(u, best.1)
    }

    /// Pushes the crossings of the line `origin + s direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let mut crossings = [(0.0, 0u8); CROSSING_BUFFER];
        let mut count = 0;
        for (index, segment) in self.segments.iter().enumerate() {
            if !line_may_meet(segment, origin, direction) {
                continue;
            }
            let part = if index < UNKNOWN_SEGMENT as usize {
                index as u8
            } else {
                UNKNOWN_SEGMENT
            };
            let mut record = |s: f64| {
                if s.is_finite() && count < CROSSING_BUFFER {
                    crossings[count] = (s, part);
                    count += 1;
                }
            };
            let r = [segment.start.x, segment.c.x, segment.b.x, segment.a.x];
            let y = [segment.start.y, segment.c.y, segment.b.y, segment.a.y];
            if direction.y != 0.0 {
                // s = (y(t) - oy) / dy; then x(s)² + z(s)² - r(t)² = 0 is of degree 6 in t.
                let along = |o: f64, d: f64| -> [f64; 4] {
                    let k = d / direction.y;
                    [o + k * (y[0] - origin.y), k * y[1], k * y[2], k * y[3]]
                };
                let x = along(origin.x, direction.x);
                let z = along(origin.z, direction.z);
                let (xx, zz, rr) = (multiply(&x, &x), multiply(&z, &z), multiply(&r, &r));
                let mut coefficients = [0.0; MAX_DEGREE];
                for power in 0..7 {
                    coefficients[6 - power] = xx[power] + zz[power] - rr[power];
                }
                // Leading terms that are rounding noise (straight segments) are dropped.
                let largest = coefficients.iter().fold(0.0f64, |m, c| m.max(c.abs()));
                for value in coefficients.iter_mut().take(5) {
                    if value.abs() > 1e-14 * largest {
                        break;
                    }
                    *value = 0.0;
                }
                let mut found = [0.0; MAX_DEGREE];
                let roots_found = real_roots_between(&coefficients[..7], 0.0, 1.0, &mut found);
                for &t in &found[..roots_found] {
                    if t < 1.0 {
                        let height = ((y[3] * t + y[2]) * t + y[1]) * t + y[0];
                        record((height - origin.y) / direction.y);
                    }
                }
            } else {
                let cubic = [y[3], y[2], y[1], y[0] - origin.y];
                let mut found = [0.0; MAX_DEGREE];
                let roots_found = real_roots_between(&cubic, 0.0, 1.0, &mut found);
                for &t in &found[..roots_found] {
                    if t >= 1.0 {
                        continue;
                    }
                    let radius = ((r[3] * t + r[2]) * t + r[1]) * t + r[0];
                    let a = direction.x * direction.x + direction.z * direction.z;
                    let half_b = origin.x * direction.x + origin.z * direction.z;
                    let c = origin.x * origin.x + origin.z * origin.z - radius * radius;
                    if let Some((near, far)) = super::roots::solve_quadratic(a, half_b, c) {
                        record(near);
                        if far != near {
                            record(far);
                        }
                    }
                }
            }
        }
        roots.push_nearest(&mut crossings[..count]);
    }

    /// True when `point` is inside the solid of revolution.
    pub fn inside(&self, point: DVec3) -> bool {
        let radial = DVec2::new(point.x, point.z).length();
        point.y >= self.low && point.y <= self.high && self.covers(DVec2::new(radial, point.y))
    }

    /// Outward normal at the surface `point` of segment `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        let radial = DVec2::new(point.x, point.z).length();
        let flat = DVec2::new(radial, point.y);
        let candidates: &[Segment] = match self.segments.get(usize::from(part)) {
            Some(segment) if part != UNKNOWN_SEGMENT => std::slice::from_ref(segment),
            _ => &self.segments,
        };
        // The parameter on the segment at the point's height nearest to its radius.
        let mut best: Option<(Segment, f64, f64)> = None;
        for segment in candidates {
            let (found, count) = segment.crossings_with_line(DVec2::Y, point.y);
            let ends = [0.0, 1.0];
            for &t in found[..count].iter().chain(ends.iter()) {
                let distance = segment.at(t).distance_squared(flat);
                if best.is_none_or(|(_, _, nearest)| distance < nearest) {
                    best = Some((*segment, t, distance));
                }
            }
        }
        let Some((segment, t, _)) = best else {
            return DVec3::Y;
        };
        let tangent = segment.tangent(t);
        let mut normal = DVec2::new(tangent.y, -tangent.x);
        let length = normal.length();
        if length == 0.0 || !length.is_finite() {
            return DVec3::Y;
        }
        normal /= length;
        let step = 1e-6 * self.radius.max(self.high - self.low).max(1e-9);
        if self.covers(flat + normal * step) {
            normal = -normal;
        }
        let outward = if radial > 0.0 {
            DVec2::new(point.x, point.z) / radial
        } else {
            DVec2::X
        };
        DVec3::new(outward.x * normal.x, normal.y, outward.y * normal.x)
    }

    /// Bounds of the solid.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points([
            DVec3::new(-self.radius, self.low, -self.radius),
            DVec3::new(self.radius, self.high, self.radius),
        ])
    }
}

/// False when the line `origin + s direction` surely misses the surface the segment sweeps:
/// while inside the segment's height range it stays farther from the Y axis than any radius
/// of the segment, or nearer than all of them (both bounded by the segment's box).
fn line_may_meet(segment: &Segment, origin: DVec3, direction: DVec3) -> bool {
    let (low, high) = (segment.low.y, segment.high.y);
    let largest_radius = segment.low.x.abs().max(segment.high.x.abs());
    let smallest_radius = if segment.low.x > 0.0 {
        segment.low.x
    } else if segment.high.x < 0.0 {
        -segment.high.x
    } else {
        0.0
    };
    // Squared distance from the axis: a s² + 2 half_b s + c, least at s = −half_b / a.
    let a = direction.x * direction.x + direction.z * direction.z;
    let half_b = origin.x * direction.x + origin.z * direction.z;
    let c = origin.x * origin.x + origin.z * origin.z;
    let (first, last) = if direction.y != 0.0 {
        let ends = (
            (low - origin.y) / direction.y,
            (high - origin.y) / direction.y,
        );
        (ends.0.min(ends.1), ends.0.max(ends.1))
    } else if origin.y >= low && origin.y <= high {
        (f64::NEG_INFINITY, f64::INFINITY)
    } else {
        return false;
    };
    let squared_at = |s: f64| (a * s + 2.0 * half_b) * s + c;
    let closest = if a > 0.0 {
        (-half_b / a).clamp(first, last)
    } else {
        first
    };
    let nearest_squared = if closest.is_finite() {
        let (x, z) = (
            origin.x + closest * direction.x,
            origin.z + closest * direction.z,
        );
        x * x + z * z
    } else {
        c - half_b * half_b / a
    };
    // A relative margin keeps rounding from dropping a grazing segment.
    let reach = largest_radius * largest_radius * (1.0 + 1e-9) + 1e-12;
    if nearest_squared.is_nan() || reach.is_nan() {
        return true;
    }
    if nearest_squared > reach {
        return false;
    }
    // The distance is convex along the line: its largest value in the range is at an end.
    if first.is_finite() && last.is_finite() && smallest_radius > 0.0 {
        let farthest_squared = squared_at(first).max(squared_at(last));
        let inner = smallest_radius * smallest_radius * (1.0 - 1e-9) - 1e-12;
        if farthest_squared < inner {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: DVec2, b: DVec2) -> [DVec2; 4] {
        [a, a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0), b]
    }

    /// A closed cylinder of radius 1 from y = 0 to 2 as a lathe.
    fn cylinder() -> Lathe {
        let p = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(0.0, 2.0),
        ];
        Lathe::new(&[line(p[0], p[1]), line(p[1], p[2]), line(p[2], p[3])]).unwrap()
    }

    #[test]
    fn lathe_cylinder_known_hits_and_normals() {
        let lathe = cylinder();
        let mut roots = Roots::new();
        lathe.intersect(DVec3::new(-5.0, 1.0, 0.0), DVec3::X, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 2);
        assert!((found[0] - 4.0).abs() < 1e-9 && (found[1] - 6.0).abs() < 1e-9);
        let (t, part) = roots.nearest_within(0.0, 10.0).unwrap();
        let normal = lathe.normal(DVec3::new(-5.0 + t, 1.0, 0.0), part);
        assert!(normal.abs_diff_eq(-DVec3::X, 1e-9), "{normal}");
        let mut roots = Roots::new();
        lathe.intersect(DVec3::new(0.5, 5.0, 0.0), -DVec3::Y, &mut roots);
        let (t, part) = roots.nearest_within(0.0, 10.0).unwrap();
        assert!((t - 3.0).abs() < 1e-9);
        assert!(lathe
            .normal(DVec3::new(0.5, 2.0, 0.0), part)
            .abs_diff_eq(DVec3::Y, 1e-9));
        assert!(lathe.inside(DVec3::new(0.3, 1.0, 0.3)));
        assert!(!lathe.inside(DVec3::new(1.3, 1.0, 0.3)));
    }

    #[test]
    fn lathe_crossings_agree_with_inside_test() {
        let curve = [
            line(DVec2::new(0.0, -1.0), DVec2::new(1.0, -1.0)),
            [
                DVec2::new(1.0, -1.0),
                DVec2::new(2.0, -0.5),
                DVec2::new(0.2, 0.5),
                DVec2::new(1.0, 1.0),
            ],
            line(DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0)),
        ];
        let lathe = Lathe::new(&curve).unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            7,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| lathe.intersect(origin, direction, roots),
            |point| lathe.inside(point),
        );
        assert!(Lathe::new(&[]).is_none());
        assert!(Lathe::new(&[[DVec2::splat(f64::NAN); 4]]).is_none());
    }
}
