//! Shapes built on the lemon (the inner solid of a spindle torus): `ovus` and `lemon`.
//!
//! In: the radii of an ovus, or the rim points and radii of a lemon. Out: crossings of a line
//! (tagged with the piece hit), inside test, normals, bounds, the ovus's uv coordinates.
//! Holds: a lemon piece is the solid swept by turning the part of a circle of radius `minor`
//! centred at (-offset, centre_height) that lies on the positive side of the axis around the Y
//! axis, cut to a height range; it is convex, so a line meets it in one interval. An ovus is
//! the union of its bottom sphere, its top sphere and a lemon piece tangent to both (the
//! spheres lie inside the lemon); a lemon is one piece with flat caps unless open. Nothing
//! allocates.

use super::roots::{solve_quadratic, Roots};
use super::torus::{Torus, TorusShape};
use crate::accel::Aabb;
use glam::{DVec2, DVec3};

/// Surface part: the ovus's bottom sphere.
const BOTTOM_SPHERE: u8 = 0;
/// Surface part: the ovus's top sphere.
const TOP_SPHERE: u8 = 1;
/// Surface part: the curved lemon surface.
const LEMON_SIDE: u8 = 2;
/// Surface part: the flat cap at the low end of a lemon.
const LOW_CAP: u8 = 3;
/// Surface part: the flat cap at the high end of a lemon.
const HIGH_CAP: u8 = 4;

/// A parameter interval of a line inside a convex piece, with the parts at its ends.
#[derive(Clone, Copy, Debug)]
struct Interval {
    entry: f64,
    entry_part: u8,
    exit: f64,
    exit_part: u8,
}

/// The solid of revolution around Y of the disc of radius `minor` centred at
/// (-offset, centre_height), on the positive side of the axis, between two heights.
#[derive(Clone, Copy, Debug)]
struct LemonPiece {
    /// The spindle torus (centred at the origin) whose inner surface is the lemon's side.
    torus: Torus,
    /// Distance of the profile circle's centre from the axis, on the far side (signed).
    offset: f64,
    /// Radius of the profile circle.
    minor: f64,
    /// Height of the profile circle's centre.
    centre_height: f64,
    /// The height range of the piece.
    low: f64,
    high: f64,
}

impl LemonPiece {
    /// The piece; `None` for a degenerate circle or an empty height range.
    fn new(offset: f64, minor: f64, centre_height: f64, low: f64, high: f64) -> Option<Self> {
        let finite = [offset, minor, centre_height, low, high]
            .iter()
            .all(|v| v.is_finite());
        if !finite || minor <= 0.0 || low >= high || offset.abs() >= minor {
            return None;
        }
        // A zero offset is a sphere, which the torus solver does not represent.
        let torus = match Torus::from_radii(offset.abs().max(minor * 1e-9), minor)? {
            TorusShape::Torus(torus) => torus,
            TorusShape::Sphere(_) => return None,
        };
        Some(LemonPiece {
            torus,
            offset,
            minor,
            centre_height,
            low,
            high,
        })
    }

    /// How far `point` is outside the profile circle (negative inside), squared measure.
    fn excess(&self, point: DVec3) -> f64 {
        let radial = (point.x * point.x + point.z * point.z).sqrt();
        let height = point.y - self.centre_height;
        (radial + self.offset).powi(2) + height * height - self.minor * self.minor
    }

    /// Where the whole line crosses the lemon circle's surface, ignoring the height range:
    /// the entry and exit of the convex uncut solid.
    fn side_crossings(&self, origin: DVec3, direction: DVec3) -> Option<(f64, f64)> {
        let mut torus_roots = Roots::new();
        let shifted = origin - DVec3::Y * self.centre_height;
        self.torus.intersect(shifted, direction, &mut torus_roots);
        // The spindle torus's quartic also has the outer (apple) surface: keep the crossings
        // that lie on the lemon circle rather than on its mirror image.
        let mut entry = f64::INFINITY;
        let mut exit = f64::NEG_INFINITY;
        for (distance, _) in torus_roots.iter() {
            let point = origin + direction * distance;
            let radial = (point.x * point.x + point.z * point.z).sqrt();
            let height = point.y - self.centre_height;
            let minor_squared = self.minor * self.minor;
            let lemon = ((radial + self.offset).powi(2) + height * height - minor_squared).abs();
            let apple = ((radial - self.offset).powi(2) + height * height - minor_squared).abs();
            if lemon <= apple {
                entry = entry.min(distance);
                exit = exit.max(distance);
            }
        }
        (entry < exit).then_some((entry, exit))
    }

    /// True when the height of `point` is within the piece's range.
    fn in_height_range(&self, point: DVec3) -> bool {
        point.y >= self.low && point.y <= self.high
    }

    /// The interval of the line inside the piece (the slab ends tagged as caps).
    fn interval(&self, origin: DVec3, direction: DVec3) -> Option<Interval> {
        let (entry, exit) = self.side_crossings(origin, direction)?;
        let mut interval = Interval {
            entry,
            entry_part: LEMON_SIDE,
            exit,
            exit_part: LEMON_SIDE,
        };
        if direction.y == 0.0 {
            return (origin.y >= self.low && origin.y <= self.high).then_some(interval);
        }
        let at_low = (self.low - origin.y) / direction.y;
        let at_high = (self.high - origin.y) / direction.y;
        let (slab_entry, slab_exit) = if at_low < at_high {
            ((at_low, LOW_CAP), (at_high, HIGH_CAP))
        } else {
            ((at_high, HIGH_CAP), (at_low, LOW_CAP))
        };
        if slab_entry.0 > interval.entry {
            (interval.entry, interval.entry_part) = slab_entry;
        }
        if slab_exit.0 < interval.exit {
            (interval.exit, interval.exit_part) = slab_exit;
        }
        (interval.entry < interval.exit).then_some(interval)
    }

    /// True when `point` is inside the piece.
    fn contains(&self, point: DVec3) -> bool {
        self.in_height_range(point) && self.excess(point) < 0.0
    }

    /// Outward normal of the curved side at `point`: away from the profile circle's centre.
    fn side_normal(&self, point: DVec3) -> DVec3 {
        let radial = DVec3::new(point.x, 0.0, point.z);
        let length = radial.length();
        let towards_axis = if length > 0.0 {
            radial / length
        } else {
            DVec3::ZERO
        };
        let centre = -towards_axis * self.offset + DVec3::Y * self.centre_height;
        let normal = point - centre;
        if length > 0.0 {
            normal
        } else {
            DVec3::Y * normal.y.signum()
        }
    }

    /// The widest radius of the piece within its height range.
    fn widest(&self) -> f64 {
        let height = self.centre_height.clamp(self.low, self.high) - self.centre_height;
        ((self.minor * self.minor - height * height).max(0.0).sqrt() - self.offset).max(0.0)
    }

    fn bounds(&self) -> Aabb {
        let reach = self.widest();
        Aabb::from_corners(
            DVec3::new(-reach, self.low, -reach),
            DVec3::new(reach, self.high, reach),
        )
    }
}

/// A solid ball used as a piece of an ovus.
#[derive(Clone, Copy, Debug)]
struct Ball {
    height: f64,
    radius: f64,
}

impl Ball {
    fn centre(&self) -> DVec3 {
        DVec3::Y * self.height
    }

    fn interval(&self, origin: DVec3, direction: DVec3, part: u8) -> Option<Interval> {
        let offset = origin - self.centre();
        let (entry, exit) = solve_quadratic(
            direction.length_squared(),
            offset.dot(direction),
            offset.length_squared() - self.radius * self.radius,
        )?;
        (entry < exit).then_some(Interval {
            entry,
            entry_part: part,
            exit,
            exit_part: part,
        })
    }

    fn contains(&self, point: DVec3) -> bool {
        point.distance_squared(self.centre()) < self.radius * self.radius
    }

    fn bounds(&self) -> Aabb {
        Aabb::from_corners(
            self.centre() - DVec3::splat(self.radius),
            self.centre() + DVec3::splat(self.radius),
        )
    }
}

/// `ovus { bottom_radius, top_radius }`: an egg made of a bottom sphere at the origin, a top
/// sphere centred on the bottom sphere's top, and the lemon of radius twice the larger radius
/// tangent to both.
#[derive(Clone, Copy, Debug)]
pub struct Ovus {
    bottom: Option<Ball>,
    top: Option<Ball>,
    lemon: Option<LemonPiece>,
}

impl Ovus {
    /// The ovus of the two radii; `None` when nothing is left (both radii zero or less, or
    /// not finite). A top radius of at least twice the bottom one swallows the rest: the
    /// ovus is then the top sphere alone; a top radius of zero or less leaves the bottom
    /// sphere.
    pub fn new(bottom_radius: f64, top_radius: f64) -> Option<Ovus> {
        if !(bottom_radius.is_finite() && top_radius.is_finite()) {
            return None;
        }
        let bottom = (bottom_radius > 0.0).then_some(Ball {
            height: 0.0,
            radius: bottom_radius,
        });
        let top = (top_radius > 0.0).then_some(Ball {
            height: bottom_radius.max(0.0),
            radius: top_radius,
        });
        let ovus = match (bottom, top) {
            (None, None) => return None,
            (Some(_), None) => Ovus {
                bottom,
                top: None,
                lemon: None,
            },
            (_, Some(_)) if top_radius >= 2.0 * bottom_radius => Ovus {
                bottom: None,
                top,
                lemon: None,
            },
            // Both spheres, the top one less than twice the bottom one.
            _ => Ovus {
                bottom,
                top,
                lemon: connecting_lemon(bottom_radius, top_radius),
            },
        };
        Some(ovus)
    }

    /// Pushes the crossings of the line `origin + t direction`: the ends of the union of the
    /// pieces' intervals.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let intervals = [
            self.bottom
                .and_then(|ball| ball.interval(origin, direction, BOTTOM_SPHERE)),
            self.top
                .and_then(|ball| ball.interval(origin, direction, TOP_SPHERE)),
            self.lemon
                .and_then(|lemon| lemon.interval(origin, direction)),
        ];
        push_union(intervals, roots);
    }

    /// True when `point` is inside any piece.
    pub fn inside(&self, point: DVec3) -> bool {
        self.bottom.is_some_and(|ball| ball.contains(point))
            || self.top.is_some_and(|ball| ball.contains(point))
            || self.lemon.is_some_and(|lemon| lemon.contains(point))
    }

    /// Outward normal at a surface point of piece `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        match (part, self.bottom, self.top, self.lemon) {
            (BOTTOM_SPHERE, Some(ball), _, _) | (TOP_SPHERE, _, Some(ball), _) => {
                point - ball.centre()
            }
            (_, _, _, Some(lemon)) => lemon.side_normal(point),
            _ => point,
        }
    }

    /// POV-Ray's uv at a surface `point` (measured): the sphere's uv around the middle of
    /// the ovus's height range (u the angle around Y from +x towards +z, v the angle from
    /// the downward axis over pi). That middle is at half the top radius when both spheres
    /// show, at the top sphere's centre when it swallows the bottom one and at the origin
    /// without a top sphere.
    pub fn uv(&self, point: DVec3) -> DVec2 {
        let heights = [self.bottom, self.top].into_iter().flatten();
        let (low, high) = heights.fold((f64::INFINITY, f64::NEG_INFINITY), |(low, high), ball| {
            (
                low.min(ball.height - ball.radius),
                high.max(ball.height + ball.radius),
            )
        });
        let middle = if low <= high { (low + high) * 0.5 } else { 0.0 };
        super::uv::sphere_uv(point - DVec3::Y * middle)
    }

    /// The union of the pieces' bounds.
    pub fn bounds(&self) -> Aabb {
        let mut bounds = Aabb::EMPTY;
        for ball in [self.bottom, self.top].into_iter().flatten() {
            bounds = bounds.union(&ball.bounds());
        }
        if let Some(lemon) = self.lemon {
            bounds = bounds.union(&lemon.bounds());
        }
        bounds
    }
}

/// The lemon joining the bottom sphere (radius `bottom`, at the origin) and the top sphere
/// (radius `top`, centred at height `bottom`): its profile circle has radius twice the larger
/// sphere radius and touches both spheres' profiles from outside; the piece runs between the
/// two points of contact.
fn connecting_lemon(bottom: f64, top: f64) -> Option<LemonPiece> {
    let minor = 2.0 * bottom.max(top);
    // The centre (-offset, height) lies minor - bottom from the origin and minor - top from
    // the top sphere's centre (0, bottom).
    let to_bottom = minor - bottom;
    let to_top = minor - top;
    let height = (to_bottom * to_bottom - to_top * to_top + bottom * bottom) / (2.0 * bottom);
    let offset = (to_bottom * to_bottom - height * height).max(0.0).sqrt();
    // The points of contact lie on the lines from the centre through the spheres' centres.
    let low = height - minor * height / to_bottom;
    let high = height + minor * (bottom - height) / to_top;
    LemonPiece::new(offset, minor, height, low, high)
}

/// `lemon { base, base_radius, cap, cap_radius, inner_radius [open] }` in its own frame: the
/// base at the origin, the axis along +Y.
#[derive(Clone, Copy, Debug)]
pub struct Lemon {
    piece: LemonPiece,
    /// Without the flat caps.
    open: bool,
    /// Where the lemon's frame sits: the base point.
    base: DVec3,
    /// The frame's axes in the caller's space (unit, orthogonal; `axes[1]` points to the cap).
    axes: [DVec3; 3],
}

impl Lemon {
    /// The lemon whose side, a circle arc of radius `inner_radius` turned around the axis,
    /// runs from the rim of radius `base_radius` at `base` to the rim of radius
    /// `cap_radius` at `cap`, bulging outwards. An inner radius below
    /// [`lemon_smallest_inner_radius`] is raised to it. `None` when the axis has no length or
    /// the input is not finite.
    pub fn new(
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        inner_radius: f64,
        open: bool,
    ) -> Option<Lemon> {
        let axis = cap - base;
        let length = axis.length();
        if !(length > 0.0 && length.is_finite()) {
            return None;
        }
        let up = axis / length;
        let (side, across) = up.any_orthonormal_pair();
        let radius = inner_radius.max(lemon_smallest_inner_radius(base_radius, cap_radius, length));
        let (offset, height) = lemon_centre(base_radius, cap_radius, length, radius)?;
        let piece = LemonPiece::new(offset, radius, height, 0.0, length)?;
        Some(Lemon {
            piece,
            open,
            base,
            axes: [side, up, across],
        })
    }

    /// `point` in the lemon's frame.
    fn point_in_frame(&self, point: DVec3) -> DVec3 {
        let offset = point - self.base;
        DVec3::new(
            offset.dot(self.axes[0]),
            offset.dot(self.axes[1]),
            offset.dot(self.axes[2]),
        )
    }

    /// A frame vector in the caller's space.
    fn vector_out_of_frame(&self, vector: DVec3) -> DVec3 {
        self.axes[0] * vector.x + self.axes[1] * vector.y + self.axes[2] * vector.z
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let local_origin = self.point_in_frame(origin);
        let local_direction = self.direction_point_in_frame(direction);
        if self.open {
            // Only the curved side is there: its crossings within the height range.
            if let Some((entry, exit)) = self.piece.side_crossings(local_origin, local_direction) {
                for distance in [entry, exit] {
                    if self
                        .piece
                        .in_height_range(local_origin + local_direction * distance)
                    {
                        roots.push(distance, LEMON_SIDE);
                    }
                }
            }
        } else if let Some(interval) = self.piece.interval(local_origin, local_direction) {
            roots.push(interval.entry, interval.entry_part);
            roots.push(interval.exit, interval.exit_part);
        }
    }

    /// A direction in the lemon's frame.
    fn direction_point_in_frame(&self, direction: DVec3) -> DVec3 {
        DVec3::new(
            direction.dot(self.axes[0]),
            direction.dot(self.axes[1]),
            direction.dot(self.axes[2]),
        )
    }

    /// True when `point` is inside the solid.
    pub fn inside(&self, point: DVec3) -> bool {
        self.piece.contains(self.point_in_frame(point))
    }

    /// Outward normal at a surface point of part `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        match part {
            LOW_CAP => -self.axes[1],
            HIGH_CAP => self.axes[1],
            _ => self.vector_out_of_frame(self.piece.side_normal(self.point_in_frame(point))),
        }
    }

    /// Bounds of the lemon's frame box, mapped back.
    pub fn bounds(&self) -> Aabb {
        let local = self.piece.bounds();
        let corners = [0, 1, 2, 3, 4, 5, 6, 7].map(|index| {
            let pick = |bit: usize, low: f64, high: f64| if index & bit == 0 { low } else { high };
            let corner = DVec3::new(
                pick(1, local.min.x, local.max.x),
                pick(2, local.min.y, local.max.y),
                pick(4, local.min.z, local.max.z),
            );
            self.base + self.vector_out_of_frame(corner)
        });
        Aabb::from_points(corners)
    }
}

/// The smallest inner radius a lemon with rims of radii `base_radius` (at height 0) and
/// `cap_radius` (at height `length`) may have: the radius of the circle through both rims
/// whose centre lies on the axis. A smaller circle through the rims has its centre on the
/// rims' side of the axis, and the solid it sweeps is dimpled at the ends, not a lemon.
pub fn lemon_smallest_inner_radius(base_radius: f64, cap_radius: f64, length: f64) -> f64 {
    // The centre (0, height) is as far from (base_radius, 0) as from (cap_radius, length).
    let height =
        (cap_radius * cap_radius + length * length - base_radius * base_radius) / (2.0 * length);
    (base_radius * base_radius + height * height).sqrt()
}

/// The centre (-offset, height) of a circle of radius `radius` through (base_radius, 0) and
/// (cap_radius, length), on the far side of the axis from the rims (so the arc between them
/// bulges outwards); a radius below [`lemon_smallest_inner_radius`] is raised to it, so the
/// offset is never negative. `None` for degenerate input.
fn lemon_centre(base_radius: f64, cap_radius: f64, length: f64, radius: f64) -> Option<(f64, f64)> {
    let radius = radius.max(lemon_smallest_inner_radius(base_radius, cap_radius, length));
    let low = glam::DVec2::new(base_radius, 0.0);
    let high = glam::DVec2::new(cap_radius, length);
    let chord = high - low;
    let half = chord.length() * 0.5;
    if !(radius.is_finite() && half > 0.0) {
        return None;
    }
    let middle = (low + high) * 0.5;
    // The perpendicular pointing away from the rims' side (towards -x).
    let mut across = glam::DVec2::new(-chord.y, chord.x) / chord.length();
    if across.x > 0.0 {
        across = -across;
    }
    let centre = middle + across * (radius * radius - half * half).max(0.0).sqrt();
    Some(((-centre.x).max(0.0), centre.y))
}

/// Pushes the ends of the union of the intervals, each with its part.
fn push_union(mut intervals: [Option<Interval>; 3], roots: &mut Roots) {
    intervals.sort_by(|a, b| {
        let start = |i: &Option<Interval>| i.map_or(f64::INFINITY, |i| i.entry);
        start(a).total_cmp(&start(b))
    });
    let mut current: Option<Interval> = None;
    for interval in intervals.into_iter().flatten() {
        match current {
            Some(mut merged) if interval.entry <= merged.exit => {
                if interval.exit > merged.exit {
                    merged.exit = interval.exit;
                    merged.exit_part = interval.exit_part;
                }
                current = Some(merged);
            }
            Some(merged) => {
                roots.push(merged.entry, merged.entry_part);
                roots.push(merged.exit, merged.exit_part);
                current = Some(interval);
            }
            None => current = Some(interval),
        }
    }
    if let Some(merged) = current {
        roots.push(merged.entry, merged.entry_part);
        roots.push(merged.exit, merged.exit_part);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_support::assert_crossings_flip_inside;

    /// The nearest crossing ahead of `origin` along `direction`, with its part.
    fn first_hit(
        intersect: impl Fn(DVec3, DVec3, &mut Roots),
        origin: DVec3,
        direction: DVec3,
    ) -> Option<(f64, u8)> {
        let mut roots = Roots::new();
        intersect(origin, direction, &mut roots);
        roots.nearest_within(1e-9, f64::INFINITY)
    }

    #[test]
    fn ovus_uv_centres_on_the_middle_of_its_height() {
        // Measured with POV-Ray: uv-mapped gradients on ovus { 1, 0.6 } (middle at 0.3),
        // ovus { 0.5, 1.2 } (the top sphere alone, middle at its centre 0.5) and
        // ovus { 1, 0 } (the bottom sphere alone, middle at 0).
        let egg = Ovus::new(1.0, 0.6).unwrap();
        let uv = egg.uv(DVec3::new(0.425, -0.0084, -0.9052));
        assert!(uv.abs_diff_eq(DVec2::new(0.81987, 0.40479), 2e-4), "{uv}");
        let uv = egg.uv(DVec3::new(0.0916, 1.4083, -0.4301));
        assert!(uv.abs_diff_eq(DVec2::new(0.78341, 0.87974), 2e-4), "{uv}");
        let top_alone = Ovus::new(0.5, 1.2).unwrap();
        let uv = top_alone.uv(DVec3::new(0.0, 0.5, 1.2));
        assert!(uv.abs_diff_eq(DVec2::new(0.25, 0.5), 1e-12), "{uv}");
        let bottom_alone = Ovus::new(1.0, 0.0).unwrap();
        let uv = bottom_alone.uv(DVec3::new(-1.0, 0.0, 0.0));
        assert!(uv.abs_diff_eq(DVec2::new(0.5, 0.5), 1e-12), "{uv}");
    }

    #[test]
    fn ovus_profile_matches_povray() {
        // Measured with POV-Ray's trace(): points and normals of ovus { 1, 0.6 } hit by rays
        // along -x at several heights (bottom sphere, lemon, top sphere).
        let ovus = Ovus::new(1.0, 0.6).unwrap();
        let cases = [
            (-0.51, 0.860174, DVec3::new(0.860174, -0.51, 0.0)),
            (0.51, 0.939246, DVec3::new(0.969523, 0.245, 0.0)),
            (1.35, 0.493887, DVec3::new(0.746843, 0.665, 0.0)),
        ];
        for (height, x, normal) in cases {
            let intersect = |o, d, r: &mut Roots| ovus.intersect(o, d, r);
            let (distance, part) =
                first_hit(intersect, DVec3::new(5.0, height, 0.0), -DVec3::X).unwrap();
            assert!((5.0 - distance - x).abs() < 1e-5, "{height}: {distance}");
            let found = ovus
                .normal(DVec3::new(5.0 - distance, height, 0.0), part)
                .normalize();
            assert!(
                found.abs_diff_eq(normal.normalize(), 1e-5),
                "{height}: {found}"
            );
        }
    }

    #[test]
    fn big_top_sphere_swallows_the_ovus() {
        let ovus = Ovus::new(1.0, 2.1).unwrap();
        let intersect = |o, d, r: &mut Roots| ovus.intersect(o, d, r);
        let (distance, _) = first_hit(intersect, DVec3::new(5.0, 0.3, 0.0), -DVec3::X).unwrap();
        assert!((5.0 - distance - 1.979899).abs() < 1e-5);
        assert!(ovus.bounds().min.y < -1.09);
        assert!(Ovus::new(0.0, 0.0).is_none());
        assert!(Ovus::new(f64::NAN, 1.0).is_none());
        let sphere = Ovus::new(1.0, 0.0).unwrap();
        assert!(sphere.inside(DVec3::new(0.0, 0.9, 0.0)));
        assert!(!sphere.inside(DVec3::new(0.0, 1.1, 0.0)));
    }

    #[test]
    fn ovus_crossings_agree_with_inside_test() {
        for (bottom, top) in [(1.0, 0.6), (1.0, 1.0), (0.5, 0.9), (1.0, 0.05), (1.0, 1.99)] {
            let ovus = Ovus::new(bottom, top).unwrap();
            assert_crossings_flip_inside(
                5,
                3.0,
                1e-6,
                1e-7,
                |origin, direction, roots| ovus.intersect(origin, direction, roots),
                |point| ovus.inside(point),
            );
        }
    }

    #[test]
    fn ovus_surface_points_have_outward_normals_and_lie_in_bounds() {
        let ovus = Ovus::new(1.0, 0.7).unwrap();
        let bounds = ovus.bounds();
        let mut random = crate::geometry::test_support::Random::new(3);
        for _ in 0..500 {
            let ray = random.ray(4.0);
            let intersect = |o, d, r: &mut Roots| ovus.intersect(o, d, r);
            let Some((distance, part)) = first_hit(intersect, ray.origin, ray.direction) else {
                continue;
            };
            let point = ray.at(distance);
            assert!((point - point.clamp(bounds.min, bounds.max)).length() < 1e-9);
            let normal = ovus.normal(point, part).normalize();
            assert!(!ovus.inside(point + normal * 1e-6));
            assert!(ovus.inside(point - normal * 1e-6) || distance < 1e-6);
        }
    }

    #[test]
    fn lemon_rims_caps_and_open_ends() {
        let lemon = Lemon::new(DVec3::ZERO, 0.5, DVec3::Y * 2.0, 0.3, 1.5, false).unwrap();
        // The rims lie on the surface.
        assert!(lemon.inside(DVec3::new(0.49, 0.001, 0.0)));
        assert!(!lemon.inside(DVec3::new(0.51, 0.001, 0.0)));
        assert!(lemon.inside(DVec3::new(0.29, 1.999, 0.0)));
        assert!(!lemon.inside(DVec3::new(0.31, 1.999, 0.0)));
        // Straight down the axis: the flat caps.
        let intersect = |o, d, r: &mut Roots| lemon.intersect(o, d, r);
        let (distance, part) = first_hit(intersect, DVec3::Y * 5.0, -DVec3::Y).unwrap();
        assert!((distance - 3.0).abs() < 1e-9);
        assert_eq!(lemon.normal(DVec3::Y * 2.0, part), DVec3::Y);
        // Open: the ray goes in through the top and meets nothing but the curved side.
        let open = Lemon::new(DVec3::ZERO, 0.5, DVec3::Y * 2.0, 0.3, 1.5, true).unwrap();
        let mut roots = Roots::new();
        open.intersect(DVec3::Y * 5.0, -DVec3::Y, &mut roots);
        assert_eq!(roots.iter().count(), 0);
        assert!(Lemon::new(DVec3::ZERO, 0.5, DVec3::ZERO, 0.3, 2.0, false).is_none());
    }

    #[test]
    fn too_small_inner_radius_is_raised_to_put_the_centre_on_the_axis() {
        // The case: radius 0.5 is above half the chord (0.3) but below the radius at
        // which the centre reaches the axis.
        let smallest = lemon_smallest_inner_radius(0.3, 0.3, 0.3);
        assert!((smallest - (0.09f64 + 0.0225).sqrt()).abs() < 1e-12);
        for (base, cap, length, radius) in [(0.3, 0.3, 0.3, 0.5), (0.5, 0.3, 2.0, 0.9)] {
            let (offset, _) = lemon_centre(base, cap, length, radius).unwrap();
            assert!(offset >= 0.0);
            let lemon =
                Lemon::new(DVec3::ZERO, base, DVec3::Y * length, cap, radius, false).unwrap();
            // The axis points just inside the caps are inside (no dimples).
            assert!(lemon.inside(DVec3::Y * 1e-6));
            assert!(lemon.inside(DVec3::Y * (length - 1e-6)));
            assert!(lemon.inside(DVec3::Y * length * 0.5));
            // The rims stay on the surface.
            assert!(lemon.inside(DVec3::new(base - 1e-3, 1e-6, 0.0)));
            assert!(!lemon.inside(DVec3::new(base + 1e-3, 1e-6, 0.0)));
        }
        // At the smallest radius the centre sits on the axis.
        let (offset, height) = lemon_centre(0.3, 0.3, 0.3, smallest).unwrap();
        assert!(offset.abs() < 1e-9 && (height - 0.15).abs() < 1e-12);
    }

    #[test]
    fn tilted_lemon_crossings_agree_with_inside_test() {
        let lemon = Lemon::new(
            DVec3::new(-0.5, -1.0, 0.2),
            0.2,
            DVec3::new(0.7, 1.0, -0.3),
            0.0,
            2.0,
            false,
        )
        .unwrap();
        assert_crossings_flip_inside(
            9,
            3.0,
            1e-6,
            1e-7,
            |origin, direction, roots| lemon.intersect(origin, direction, roots),
            |point| lemon.inside(point),
        );
    }
}
