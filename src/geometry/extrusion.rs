//! Extruded outlines: a region of the XY plane bounded by cubic Bézier segments, swept
//! along Z between two depths (text glyphs; prisms, whose outline is in XZ and sweep along Y).
//!
//! In: segments (start, two controls, end) forming closed outlines, the Z extent, whether the
//! caps are left out (`open`) and whether the shape is a prism (axes Y and Z swapped). Out: every
//! crossing of a line (caps and side walls), inside test (even-odd rule in XY, within the
//! depth), outward normals, bounds.
//! Holds: a side crossing carries its segment number in the part tag when it fits (else the
//! segment is found again from the point); at most [`MAX_ROOTS`] crossings are reported per
//! line, nearest ahead first when there are more; nothing allocates per ray.

use super::roots::{real_roots_between, Roots, CROSSING_BUFFER};
use crate::accel::Aabb;
use glam::{DVec2, DVec3};

/// Part tag of the cap at the smaller depth.
const FRONT_CAP: u8 = 0;
/// Part tag of the cap at the larger depth.
const BACK_CAP: u8 = 1;
/// Part tag of side walls whose segment number does not fit in a tag.
const UNKNOWN_SIDE: u8 = u8::MAX;

/// One cubic segment in power form: `a s³ + b s² + c s + start` for s in [0, 1].
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment {
    pub(super) start: DVec2,
    pub(super) c: DVec2,
    pub(super) b: DVec2,
    pub(super) a: DVec2,
    /// Corners of a box holding the segment: its control points' box, widened by a hair
    /// so that rounding in the power form never puts a point of the curve outside it.
    pub(super) low: DVec2,
    pub(super) high: DVec2,
}

impl Segment {
    pub(super) fn from_points([p0, p1, p2, p3]: [DVec2; 4]) -> Segment {
        let low = p0.min(p1).min(p2.min(p3));
        let high = p0.max(p1).max(p2.max(p3));
        let hair = 1e-9
            * (high - low)
                .max_element()
                .max(low.abs().max(high.abs()).max_element());
        Segment {
            start: p0,
            c: 3.0 * (p1 - p0),
            b: 3.0 * (p0 - 2.0 * p1 + p2),
            a: p3 - p0 + 3.0 * (p1 - p2),
            low: low - DVec2::splat(hair),
            high: high + DVec2::splat(hair),
        }
    }

    /// Whether the line of points `p` with `normal · p = offset` may meet the segment: it
    /// passes between the corners of the segment's box.
    #[inline]
    fn line_may_meet(&self, normal: DVec2, offset: f64) -> bool {
        let (low, high) = (normal * self.low, normal * self.high);
        let least = low.x.min(high.x) + low.y.min(high.y);
        let most = low.x.max(high.x) + low.y.max(high.y);
        offset >= least && offset <= most
    }

    #[inline]
    pub(super) fn at(&self, s: f64) -> DVec2 {
        ((self.a * s + self.b) * s + self.c) * s + self.start
    }

    #[inline]
    pub(super) fn tangent(&self, s: f64) -> DVec2 {
        (3.0 * self.a * s + 2.0 * self.b) * s + self.c
    }

    #[inline]
    fn second_derivative(&self, s: f64) -> DVec2 {
        6.0 * self.a * s + 2.0 * self.b
    }

    /// Parameters in [0, 1) where `normal · point` equals `offset`.
    #[inline]
    pub(super) fn crossings_with_line(&self, normal: DVec2, offset: f64) -> ([f64; 3], usize) {
        let coefficients = [
            normal.dot(self.a),
            normal.dot(self.b),
            normal.dot(self.c),
            normal.dot(self.start) - offset,
        ];
        // Coefficients that are rounding noise next to the others are dropped, so straight
        // and quadratic segments are solved at their true degree.
        let largest = coefficients.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let mut cleaned = coefficients;
        for value in &mut cleaned[..2] {
            if value.abs() <= 1e-14 * largest {
                *value = 0.0;
            }
        }
        let mut roots = [0.0; super::roots::MAX_DEGREE];
        let count = real_roots_between(&cleaned, 0.0, 1.0, &mut roots);
        let mut found = [0.0; 3];
        let mut kept = 0;
        for &s in &roots[..count] {
            if s < 1.0 && kept < 3 {
                found[kept] = s;
                kept += 1;
            }
        }
        (found, kept)
    }
}

/// An extruded outline in its local space.
#[derive(Clone, Debug)]
pub struct ExtrudedOutline {
    segments: Vec<Segment>,
    /// No caps (a prism's `open`).
    open: bool,
    /// A prism: the outline is in local XZ and the sweep runs along Y.
    along_y: bool,
    /// Conic sweep: at depth z the outline is scaled by z (apex at the origin).
    conic: bool,
    near_depth: f64,
    far_depth: f64,
    /// 2-D bounds of the outline.
    min: DVec2,
    max: DVec2,
}

impl ExtrudedOutline {
    /// An extrusion; `None` without segments, with non-finite values or zero depth.
    pub fn new(
        segments: &[[DVec2; 4]],
        depth: (f64, f64),
        open: bool,
        along_y: bool,
        conic: bool,
    ) -> Option<ExtrudedOutline> {
        let (near_depth, far_depth) = (depth.0.min(depth.1), depth.0.max(depth.1));
        let finite = segments.iter().flatten().all(|p| p.is_finite());
        let thick = far_depth > near_depth && far_depth.is_finite() && near_depth.is_finite();
        if segments.is_empty() || !finite || !thick {
            return None;
        }
        let mut min = DVec2::splat(f64::INFINITY);
        let mut max = DVec2::splat(f64::NEG_INFINITY);
        for point in segments.iter().flatten() {
            min = min.min(*point);
            max = max.max(*point);
        }
        Some(ExtrudedOutline {
            segments: segments.iter().copied().map(Segment::from_points).collect(),
            open,
            along_y,
            conic,
            near_depth,
            far_depth,
            min,
            max,
        })
    }

    /// True when the 2-D point is in the region (even-odd crossings of a line towards +x).
    pub fn covers(&self, point: DVec2) -> bool {
        if point.cmplt(self.min).any() || point.cmpgt(self.max).any() {
            return false;
        }
        let mut inside = false;
        for segment in &self.segments {
            // Only crossings to the right of the point count.
            if point.y < segment.low.y || point.y > segment.high.y || segment.high.x <= point.x {
                continue;
            }
            let (found, count) = segment.crossings_with_line(DVec2::Y, point.y);
            for &s in &found[..count] {
                if segment.at(s).x > point.x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let (origin, direction) = (self.swizzle(origin), self.swizzle(direction));
        let mut crossings = [(0.0, 0u8); CROSSING_BUFFER];
        let mut count = 0;
        let mut record = |t: f64, part: u8| {
            if t.is_finite() && count < CROSSING_BUFFER {
                crossings[count] = (t, part);
                count += 1;
            }
        };
        if direction.z != 0.0 && !self.open {
            for (depth, part) in [(self.near_depth, FRONT_CAP), (self.far_depth, BACK_CAP)] {
                let t = (depth - origin.z) / direction.z;
                let mut point = origin.truncate() + direction.truncate() * t;
                if self.conic {
                    point /= depth;
                }
                if self.covers(point) {
                    record(t, part);
                }
            }
        }
        let flat_direction = direction.truncate();
        let flat_speed = flat_direction.length_squared();
        if self.conic {
            // The plane through the apex and the line meets the outline's plane z = 1 in a
            // line; each crossing there gives a ray from the apex to meet.
            let plane = origin.cross(direction);
            let plane_normal = DVec2::new(plane.x, plane.y);
            for (index, segment) in self.segments.iter().enumerate() {
                if !segment.line_may_meet(plane_normal, -plane.z) {
                    continue;
                }
                let (found, found_count) = segment.crossings_with_line(plane_normal, -plane.z);
                for &s in &found[..found_count] {
                    let spot = segment.at(s);
                    let across_x = direction.x - spot.x * direction.z;
                    let across_y = direction.y - spot.y * direction.z;
                    let t = if across_x.abs() >= across_y.abs() {
                        (spot.x * origin.z - origin.x) / across_x
                    } else {
                        (spot.y * origin.z - origin.y) / across_y
                    };
                    let z = origin.z + direction.z * t;
                    if z >= self.near_depth && z <= self.far_depth {
                        let part = if index + 2 < UNKNOWN_SIDE as usize {
                            index as u8 + 2
                        } else {
                            UNKNOWN_SIDE
                        };
                        record(t, part);
                    }
                }
            }
        } else if flat_speed > 0.0 {
            let flat_origin = origin.truncate();
            let normal = flat_direction.perp();
            let offset = normal.dot(flat_origin);
            for (index, segment) in self.segments.iter().enumerate() {
                if !segment.line_may_meet(normal, offset) {
                    continue;
                }
                let (found, found_count) = segment.crossings_with_line(normal, offset);
                for &s in &found[..found_count] {
                    let t = (segment.at(s) - flat_origin).dot(flat_direction) / flat_speed;
                    let z = origin.z + direction.z * t;
                    if z >= self.near_depth && z <= self.far_depth {
                        let part = if index + 2 < UNKNOWN_SIDE as usize {
                            index as u8 + 2
                        } else {
                            UNKNOWN_SIDE
                        };
                        record(t, part);
                    }
                }
            }
        }
        roots.push_nearest(&mut crossings[..count]);
    }

    /// True when `point` is within the depth and its XY position is in the region.
    pub fn inside(&self, point: DVec3) -> bool {
        let point = self.swizzle(point);
        let flat = if self.conic {
            if point.z == 0.0 {
                return false;
            }
            point.truncate() / point.z
        } else {
            point.truncate()
        };
        point.z >= self.near_depth && point.z <= self.far_depth && self.covers(flat)
    }

    /// Outward normal at the surface `point` of part `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        let normal = self.extrusion_normal(self.swizzle(point), part);
        self.swizzle(normal)
    }

    /// Swaps Y and Z for prisms (its own inverse), so the rest works in extrusion space.
    #[inline]
    fn swizzle(&self, v: DVec3) -> DVec3 {
        if self.along_y {
            DVec3::new(v.x, v.z, v.y)
        } else {
            v
        }
    }

    /// Outward normal in extrusion space.
    fn extrusion_normal(&self, point: DVec3, part: u8) -> DVec3 {
        match part {
            FRONT_CAP => -DVec3::Z,
            BACK_CAP => DVec3::Z,
            _ if self.conic => {
                let flat = if point.z != 0.0 {
                    point.truncate() / point.z
                } else {
                    point.truncate()
                };
                let (segment, s) = self.side_segment(flat, part);
                let tangent = segment.tangent(s).extend(0.0);
                let mut normal = tangent.cross(flat.extend(1.0));
                let length = normal.length();
                if length == 0.0 || !length.is_finite() {
                    return DVec3::X;
                }
                normal /= length;
                let step =
                    1e-6 * (self.max - self.min).max_element().max(1e-9) * point.z.abs().max(1e-9);
                let probe = point + normal * step;
                if probe.z != 0.0 && self.covers(probe.truncate() / probe.z) {
                    normal = -normal;
                }
                normal
            }
            _ => {
                let flat = point.truncate();
                let (segment, s) = if part == UNKNOWN_SIDE {
                    self.closest_segment(flat)
                } else {
                    let segment = self
                        .segments
                        .get(usize::from(part - 2))
                        .copied()
                        .unwrap_or(self.segments[0]);
                    (segment, closest_parameter(&segment, flat))
                };
                let tangent = segment.tangent(s);
                let mut normal = DVec2::new(tangent.y, -tangent.x);
                let length = normal.length();
                if length == 0.0 || !length.is_finite() {
                    return DVec3::X;
                }
                normal /= length;
                let step = 1e-6 * (self.max - self.min).max_element().max(1e-9);
                if self.covers(flat + normal * step) {
                    normal = -normal;
                }
                normal.extend(0.0)
            }
        }
    }

    /// The side segment of part `part` (or the closest one) and the parameter nearest `flat`.
    fn side_segment(&self, flat: DVec2, part: u8) -> (Segment, f64) {
        if part == UNKNOWN_SIDE {
            return self.closest_segment(flat);
        }
        let segment = self
            .segments
            .get(usize::from(part - 2))
            .copied()
            .unwrap_or(self.segments[0]);
        (segment, closest_parameter(&segment, flat))
    }

    /// The segment passing closest to `point`, with the parameter of the closest point.
    fn closest_segment(&self, point: DVec2) -> (Segment, f64) {
        let mut best = (self.segments[0], 0.0, f64::INFINITY);
        for segment in &self.segments {
            let s = closest_parameter(segment, point);
            let distance = segment.at(s).distance_squared(point);
            if distance < best.2 {
                best = (*segment, s, distance);
            }
        }
        (best.0, best.1)
    }

    /// Bounds of the extruded outline.
    pub fn bounds(&self) -> Aabb {
        if self.conic {
            let corners = [self.near_depth, self.far_depth].map(|depth| {
                [
                    self.swizzle((self.min * depth).extend(depth)),
                    self.swizzle((self.max * depth).extend(depth)),
                ]
            });
            return Aabb::from_points(corners.into_iter().flatten());
        }
        Aabb::from_points([
            self.swizzle(self.min.extend(self.near_depth)),
            self.swizzle(self.max.extend(self.far_depth)),
        ])
    }
}

/// The parameter in [0, 1] of the point of `segment` closest to `point` (samples, then
/// Newton steps on the squared distance).
fn closest_parameter(segment: &Segment, point: DVec2) -> f64 {
    const SAMPLES: usize = 8;
    let mut best = 0.0;
    let mut best_distance = f64::INFINITY;
    for index in 0..=SAMPLES {
        let s = index as f64 / SAMPLES as f64;
        let distance = segment.at(s).distance_squared(point);
        if distance < best_distance {
            best = s;
            best_distance = distance;
        }
    }
    let mut s = best;
    for _ in 0..8 {
        let offset = segment.at(s) - point;
        let tangent = segment.tangent(s);
        let slope = offset.dot(tangent);
        let curvature = tangent.dot(tangent) + offset.dot(segment.second_derivative(s));
        if curvature <= 0.0 || !curvature.is_finite() {
            break;
        }
        s = (s - slope / curvature).clamp(0.0, 1.0);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: DVec2, b: DVec2) -> [DVec2; 4] {
        [a, a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0), b]
    }

    fn quadratic([p0, q, p1]: [DVec2; 3]) -> [DVec2; 4] {
        [
            p0,
            p0 + (q - p0) * (2.0 / 3.0),
            p1 + (q - p1) * (2.0 / 3.0),
            p1,
        ]
    }

    /// The outline of the square [-r, r]² as four straight segments.
    fn square(r: f64) -> impl Iterator<Item = [DVec2; 4]> {
        let c = [
            DVec2::new(-r, -r),
            DVec2::new(r, -r),
            DVec2::new(r, r),
            DVec2::new(-r, r),
        ];
        (0..4).map(move |i| line(c[i], c[(i + 1) % 4]))
    }

    fn square_with_hole() -> ExtrudedOutline {
        let segments: Vec<_> = square(2.0).chain(square(1.0)).collect();
        ExtrudedOutline::new(&segments, (0.0, 1.0), false, false, false).unwrap()
    }

    #[test]
    fn prism_frame_swaps_axes() {
        let segments: Vec<_> = square(1.0).collect();
        let prism = ExtrudedOutline::new(&segments, (0.0, 2.0), false, true, false).unwrap();
        assert!(prism.inside(DVec3::new(0.5, 1.5, 0.5)));
        assert!(!prism.inside(DVec3::new(0.5, 2.5, 0.5)));
        let mut roots = Roots::new();
        prism.intersect(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, &mut roots);
        let (t, part) = roots.nearest_within(0.0, 10.0).unwrap();
        assert_eq!(t, 3.0);
        assert!(prism
            .normal(DVec3::new(0.0, 2.0, 0.0), part)
            .abs_diff_eq(DVec3::Y, 1e-12));
        let open = ExtrudedOutline::new(&segments, (0.0, 2.0), true, true, false).unwrap();
        let mut roots = Roots::new();
        open.intersect(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert_eq!(roots.iter().count(), 0);
        assert!(prism
            .bounds()
            .max
            .abs_diff_eq(DVec3::new(1.0, 2.0, 1.0), 1e-12));
    }

    #[test]
    fn conic_pyramid_grows_with_depth() {
        let segments: Vec<_> = square(1.0).collect();
        let pyramid = ExtrudedOutline::new(&segments, (0.0, 2.0), false, false, true).unwrap();
        assert!(pyramid.inside(DVec3::new(0.4, 0.0, 0.5)));
        assert!(!pyramid.inside(DVec3::new(0.6, 0.0, 0.5)));
        let mut roots = Roots::new();
        pyramid.intersect(DVec3::new(-5.0, 0.0, 1.0), DVec3::X, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found, vec![4.0, 6.0]);
        let (t, part) = roots.nearest_within(0.0, 10.0).unwrap();
        let normal = pyramid.normal(DVec3::new(-5.0 + t, 0.0, 1.0), part);
        assert!(
            normal.abs_diff_eq(DVec3::new(-1.0, 0.0, -1.0).normalize(), 1e-9),
            "{normal}"
        );
        assert!(pyramid
            .bounds()
            .max
            .abs_diff_eq(DVec3::new(2.0, 2.0, 2.0), 1e-12));
    }

    #[test]
    fn square_frame_crossings_and_normals() {
        let shape = square_with_hole();
        let mut roots = Roots::new();
        shape.intersect(DVec3::new(-5.0, 0.0, 0.5), DVec3::X, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found, vec![3.0, 4.0, 6.0, 7.0]);
        let (t, part) = roots.nearest_within(0.0, 10.0).unwrap();
        assert_eq!(t, 3.0);
        let normal = shape.normal(DVec3::new(-2.0, 0.0, 0.5), part);
        assert!(normal.abs_diff_eq(-DVec3::X, 1e-9));
        let (t, part) = roots.nearest_within(3.5, 10.0).unwrap();
        let normal = shape.normal(DVec3::new(-5.0 + t, 0.0, 0.5), part);
        assert!(normal.abs_diff_eq(DVec3::X, 1e-9), "{normal}");
        assert!(shape.inside(DVec3::new(1.5, 0.0, 0.5)));
        assert!(!shape.inside(DVec3::new(0.0, 0.0, 0.5)));
        assert!(!shape.inside(DVec3::new(1.5, 0.0, 1.5)));
        let mut roots = Roots::new();
        shape.intersect(DVec3::new(1.5, 0.0, -3.0), DVec3::Z, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 10.0), Some((3.0, FRONT_CAP)));
    }

    #[test]
    fn curved_outline_agrees_with_inside_test() {
        // A closed shape of two arcs.
        let segments = [
            quadratic([
                DVec2::new(-1.0, 0.0),
                DVec2::new(0.0, 2.0),
                DVec2::new(1.0, 0.0),
            ]),
            [
                DVec2::new(1.0, 0.0),
                DVec2::new(0.5, -2.0),
                DVec2::new(-0.5, -1.0),
                DVec2::new(-1.0, 0.0),
            ],
        ];
        let shape = ExtrudedOutline::new(&segments, (-0.5, 0.5), false, false, false).unwrap();
        super::super::test_support::assert_crossings_flip_inside(
            99,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| shape.intersect(origin, direction, roots),
            |point| shape.inside(point),
        );
    }

    #[test]
    fn degenerate_extrusions_are_rejected() {
        let segment = [line(DVec2::ZERO, DVec2::X)];
        assert!(ExtrudedOutline::new(&[], (0.0, 1.0), false, false, false).is_none());
        assert!(ExtrudedOutline::new(&segment, (1.0, 1.0), false, false, false).is_none());
        assert!(ExtrudedOutline::new(&segment, (0.0, f64::NAN), false, true, false).is_none());
    }
}
