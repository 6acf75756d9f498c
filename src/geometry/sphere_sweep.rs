//! The sphere sweep: the volume a sphere of varying radius covers while it moves along a
//! spline.
//!
//! In: a [`SphereSweep`](crate::scene::SphereSweep) (spline kind, control spheres). Out:
//! crossings of a line, inside test, normals, bounds. Holds: a linear sweep is exactly the
//! union of its spheres and of the cone frustums tangent to each pair of neighbours; a cubic or
//! B-spline sweep is sampled along each segment into such a chain (fine enough that the
//! difference to POV-Ray's exact sweep is below a pixel at usual sizes). A line's crossings
//! are the ends of the union of the pieces' intervals along it. The pieces sit in a small
//! bounding hierarchy, so a line, a point or a normal only looks at the pieces near it;
//! nothing allocates.

use super::roots::{solve_quadratic, Roots};
use crate::accel::{Aabb, Bvh};
use crate::scene::{SphereSweep as SphereSweepSpec, SweepSpline};
use glam::DVec3;

/// Samples per spline segment of a cubic or B-spline sweep.
const SAMPLES_PER_SEGMENT: usize = 24;
/// Most pieces' intervals one line keeps (more is possible only for very long sweeps seen
/// end on; the nearest of them are kept).
const MAX_INTERVALS: usize = 256;

/// A sphere of the chain.
#[derive(Clone, Copy, Debug)]
struct Ball {
    centre: DVec3,
    radius: f64,
}

/// A cone frustum tangent to two neighbouring balls, as a solid.
#[derive(Clone, Copy, Debug)]
struct Frustum {
    /// The axial origin (the first ball's centre).
    start: DVec3,
    /// Unit axis towards the second ball.
    axis: DVec3,
    /// Axial range of the solid.
    near: f64,
    far: f64,
    /// Radius at `near` and its growth per unit along the axis.
    radius: f64,
    slope: f64,
    /// Cosine and sine of the half-angle (the outward normal is `cos * radial + sin * axis`).
    cos: f64,
    sin: f64,
    /// Bounding sphere for a quick rejection.
    centre: DVec3,
    reach: f64,
}

/// One piece of the chain: a ball or the frustum joining two neighbours.
#[derive(Clone, Copy, Debug)]
enum Piece {
    Ball(Ball),
    Frustum(Frustum),
}

impl Piece {
    /// The parameter interval of the line inside the piece.
    fn interval(&self, origin: DVec3, direction: DVec3) -> Option<(f64, f64)> {
        match self {
            Piece::Ball(ball) => ball_interval(ball.centre, ball.radius, origin, direction),
            Piece::Frustum(frustum) => {
                ball_interval(frustum.centre, frustum.reach, origin, direction)?;
                frustum.interval(origin, direction)
            }
        }
    }

    fn contains(&self, point: DVec3) -> bool {
        match self {
            Piece::Ball(ball) => point.distance_squared(ball.centre) < ball.radius * ball.radius,
            Piece::Frustum(frustum) => frustum.contains(point),
        }
    }

    /// Distance-like gap of `point` from the piece's surface, and the outward normal there.
    fn surface_gap(&self, point: DVec3) -> Option<(f64, DVec3)> {
        match self {
            Piece::Ball(ball) => {
                let offset = point - ball.centre;
                Some(((offset.length() - ball.radius).abs(), offset))
            }
            Piece::Frustum(frustum) => frustum.surface_gap(point),
        }
    }

    /// Bounds of the piece, grown by `margin`: a frustum lies within its two balls' boxes.
    fn bounds(&self, margin: f64) -> Aabb {
        let ball_box = |centre: DVec3, radius: f64| {
            let reach = DVec3::splat(radius + margin);
            Aabb::from_corners(centre - reach, centre + reach)
        };
        match self {
            Piece::Ball(ball) => ball_box(ball.centre, ball.radius),
            Piece::Frustum(frustum) => {
                // The solid is the hull of its two end discs; a disc across unit axis `a`
                // reaches `radius * sqrt(1 - a_i²)` along each coordinate axis.
                let spread = (DVec3::ONE - frustum.axis * frustum.axis).max(DVec3::ZERO);
                let spread = DVec3::new(spread.x.sqrt(), spread.y.sqrt(), spread.z.sqrt());
                let disc = |along: f64| {
                    let centre = frustum.start + frustum.axis * along;
                    let half = spread * frustum.radius_at(along);
                    Aabb::from_points([centre - half, centre + half])
                };
                disc(frustum.near).union(&disc(frustum.far))
            }
        }
    }
}

/// A sphere sweep in its local space.
#[derive(Clone, Debug)]
pub struct SphereSweep {
    /// The balls, then the frustums, in the order of `tree`'s leaves.
    pieces: Vec<Piece>,
    /// Hierarchy over the pieces' slightly grown boxes (so that a surface point found by a
    /// line is inside the box of the piece it lies on).
    tree: Bvh,
    bounds: Aabb,
}

impl SphereSweep {
    /// The sweep of a scene description; `None` without enough usable spheres.
    pub fn new(spec: &SphereSweepSpec) -> Option<SphereSweep> {
        let usable = spec
            .spheres
            .iter()
            .all(|(centre, radius)| centre.is_finite() && radius.is_finite());
        if !usable {
            return None;
        }
        let balls: Vec<Ball> = match spec.spline {
            SweepSpline::Linear => spec
                .spheres
                .iter()
                .map(|&(centre, radius)| Ball { centre, radius })
                .collect(),
            SweepSpline::BSpline | SweepSpline::Cubic => sample_spline(spec),
        };
        let balls: Vec<Ball> = balls.into_iter().filter(|b| b.radius > 0.0).collect();
        if balls.len() < 2 && spec.spline != SweepSpline::Linear {
            return None;
        }
        let frustums: Vec<Frustum> = balls
            .windows(2)
            .filter_map(|pair| Frustum::between(pair[0], pair[1]))
            .collect();
        let bounds = balls.iter().fold(Aabb::EMPTY, |all, ball| {
            all.union(&Aabb::from_points([
                ball.centre - DVec3::splat(ball.radius),
                ball.centre + DVec3::splat(ball.radius),
            ]))
        });
        if balls.is_empty() {
            return None;
        }
        let margin = bounds.extent().max_element() * 1e-9;
        let pieces: Vec<Piece> = balls
            .into_iter()
            .map(Piece::Ball)
            .chain(frustums.into_iter().map(Piece::Frustum))
            .collect();
        let piece_bounds: Vec<Aabb> = pieces.iter().map(|piece| piece.bounds(margin)).collect();
        let (tree, order) = Bvh::build(&piece_bounds);
        let pieces = order.iter().map(|&index| pieces[index as usize]).collect();
        Some(SphereSweep {
            pieces,
            tree,
            bounds,
        })
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let mut intervals = [(0.0, 0.0); MAX_INTERVALS];
        let mut count = 0;
        let mut add = |interval: (f64, f64)| {
            if count < MAX_INTERVALS {
                intervals[count] = interval;
                count += 1;
            } else if let Some(farthest) = intervals
                .iter_mut()
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .filter(|farthest| farthest.0 > interval.0)
            {
                *farthest = interval;
            }
        };
        self.tree.for_each_on_ray(
            origin,
            direction.recip(),
            f64::NEG_INFINITY,
            f64::INFINITY,
            |position| {
                if let Some(interval) = self.pieces[position].interval(origin, direction) {
                    add(interval);
                }
            },
        );
        let intervals = &mut intervals[..count];
        intervals.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let mut current: Option<(f64, f64)> = None;
        for &(entry, exit) in intervals.iter() {
            match current {
                Some((start, end)) if entry <= end => current = Some((start, end.max(exit))),
                Some((start, end)) => {
                    roots.push(start, 0);
                    roots.push(end, 0);
                    current = Some((entry, exit));
                }
                None => current = Some((entry, exit)),
            }
        }
        if let Some((start, end)) = current {
            roots.push(start, 0);
            roots.push(end, 0);
        }
    }

    /// True when `point` is inside any sphere or frustum of the chain.
    pub fn inside(&self, point: DVec3) -> bool {
        self.tree
            .any_containing(point, |position| self.pieces[position].contains(point))
    }

    /// Outward normal at a surface point: that of the piece whose surface is nearest (among
    /// the pieces whose box holds the point; the piece the point lies on is one of them). A
    /// point no box holds (rounding at a box's face) takes the nearest of all pieces.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        // The (gap, normal) of the nearest surface so far.
        let consider = |best: &mut Option<(f64, DVec3)>, piece: &Piece| {
            if let Some((gap, normal)) = piece.surface_gap(point) {
                if best.is_none_or(|(nearest, _)| gap < nearest) {
                    *best = Some((gap, normal));
                }
            }
        };
        let mut best = None;
        self.tree.any_containing(point, |position| {
            consider(&mut best, &self.pieces[position]);
            false
        });
        if best.is_none() {
            for piece in &self.pieces {
                consider(&mut best, piece);
            }
        }
        best.map_or(DVec3::Y, |(_, normal)| normal)
    }

    /// Bounds of all spheres of the chain.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }
}

impl Frustum {
    /// The solid frustum tangent to both balls; `None` when one ball contains the other.
    fn between(first: Ball, second: Ball) -> Option<Frustum> {
        let offset = second.centre - first.centre;
        let distance = offset.length();
        if distance <= (first.radius - second.radius).abs() || distance == 0.0 {
            return None;
        }
        let axis = offset / distance;
        let sin = (first.radius - second.radius) / distance;
        let cos = (1.0 - sin * sin).max(0.0).sqrt();
        let near = first.radius * sin;
        let far = distance + second.radius * sin;
        let radius = first.radius * cos;
        let slope = (second.radius * cos - radius) / (far - near);
        let reach = first.radius.max(second.radius) + 0.5 * distance;
        Some(Frustum {
            start: first.centre,
            axis,
            near,
            far,
            radius,
            slope,
            cos,
            sin,
            centre: first.centre + offset * 0.5,
            reach,
        })
    }

    /// The frustum's radius at axial position `along`.
    fn radius_at(&self, along: f64) -> f64 {
        self.radius + self.slope * (along - self.near)
    }

    fn contains(&self, point: DVec3) -> bool {
        let offset = point - self.start;
        let along = offset.dot(self.axis);
        if along < self.near || along > self.far {
            return false;
        }
        let radial = (offset - self.axis * along).length();
        radial < self.radius_at(along)
    }

    /// Distance-like gap from the lateral surface and the outward normal there.
    fn surface_gap(&self, point: DVec3) -> Option<(f64, DVec3)> {
        let offset = point - self.start;
        let along = offset.dot(self.axis);
        if along < self.near || along > self.far {
            return None;
        }
        let radial = offset - self.axis * along;
        let radial_length = radial.length();
        let gap = ((radial_length - self.radius_at(along)) * self.cos).abs();
        let outward = radial.try_normalize()?;
        Some((gap, outward * self.cos + self.axis * self.sin))
    }

    /// The parameter interval of the line inside the solid frustum.
    fn interval(&self, origin: DVec3, direction: DVec3) -> Option<(f64, f64)> {
        let offset = origin - self.start;
        let origin_along = offset.dot(self.axis);
        let direction_along = direction.dot(self.axis);
        // The slab near <= along <= far.
        let (slab_in, slab_out) = if direction_along == 0.0 {
            if origin_along < self.near || origin_along > self.far {
                return None;
            }
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            let a = (self.near - origin_along) / direction_along;
            let b = (self.far - origin_along) / direction_along;
            (a.min(b), a.max(b))
        };
        // The cone: |radial|² <= radius(along)².
        let radial_origin = offset - self.axis * origin_along;
        let radial_direction = direction - self.axis * direction_along;
        let base = self.radius_at(origin_along);
        let a =
            radial_direction.length_squared() - self.slope * self.slope * direction_along.powi(2);
        let half_b = radial_origin.dot(radial_direction) - self.slope * base * direction_along;
        let c = radial_origin.length_squared() - base * base;
        let clip = |low: f64, high: f64| {
            let low = low.max(slab_in);
            let high = high.min(slab_out);
            (low < high).then_some((low, high))
        };
        if a.abs() < 1e-12 * radial_direction.length_squared().max(1e-300) {
            // Linear: the line runs parallel to the cone's side.
            if half_b == 0.0 {
                return (c <= 0.0)
                    .then(|| clip(f64::NEG_INFINITY, f64::INFINITY))
                    .flatten();
            }
            let root = -c / (2.0 * half_b);
            return if half_b > 0.0 {
                clip(f64::NEG_INFINITY, root)
            } else {
                clip(root, f64::INFINITY)
            };
        }
        let (first, second) = solve_quadratic(a, half_b, c)?;
        if a > 0.0 {
            clip(first, second)
        } else {
            match (clip(f64::NEG_INFINITY, first), clip(second, f64::INFINITY)) {
                (Some(x), Some(y)) => Some((x.0.min(y.0), x.1.max(y.1))),
                (x, y) => x.or(y),
            }
        }
    }
}

/// The parameter interval of the line inside a ball.
fn ball_interval(
    centre: DVec3,
    radius: f64,
    origin: DVec3,
    direction: DVec3,
) -> Option<(f64, f64)> {
    let offset = origin - centre;
    let a = direction.length_squared();
    let half_b = offset.dot(direction);
    let c = offset.length_squared() - radius * radius;
    solve_quadratic(a, half_b, c).filter(|(near, far)| near < far)
}

/// The balls along a cubic or B-spline sweep, sampled evenly in the spline parameter.
fn sample_spline(spec: &SphereSweepSpec) -> Vec<Ball> {
    let controls = &spec.spheres;
    let mut balls = Vec::new();
    if controls.len() < 4 {
        return balls;
    }
    for window in controls.windows(4) {
        let first_segment = balls.is_empty();
        for sample in 0..=SAMPLES_PER_SEGMENT {
            if sample == 0 && !first_segment {
                continue;
            }
            let t = sample as f64 / SAMPLES_PER_SEGMENT as f64;
            let weights = match spec.spline {
                SweepSpline::BSpline => b_spline_weights(t),
                _ => catmull_rom_weights(t),
            };
            let mut centre = DVec3::ZERO;
            let mut radius = 0.0;
            for (weight, (point, r)) in weights.iter().zip(window) {
                centre += *point * *weight;
                radius += r * weight;
            }
            balls.push(Ball { centre, radius });
        }
    }
    balls
}

/// Uniform cubic B-spline weights of four control points at `t` in [0, 1].
fn b_spline_weights(t: f64) -> [f64; 4] {
    let t2 = t * t;
    let t3 = t2 * t;
    [
        (1.0 - t).powi(3) / 6.0,
        (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
        (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
        t3 / 6.0,
    ]
}

/// Catmull-Rom weights of four control points at `t` in [0, 1] (the curve runs from the
/// second point to the third).
fn catmull_rom_weights(t: f64) -> [f64; 4] {
    let t2 = t * t;
    let t3 = t2 * t;
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_outside_every_box_takes_the_nearest_pieces_normal() {
        let sweep = SphereSweep::new(&SphereSweepSpec {
            spline: SweepSpline::Linear,
            spheres: vec![(DVec3::ZERO, 1.0), (DVec3::X * 4.0, 1.0)],
            tolerance: 1e-6,
        })
        .unwrap();
        // On the surface: the ball's own normal.
        let on_surface = sweep.normal(DVec3::new(-1.0, 0.0, 0.0)).normalize();
        assert!(on_surface.abs_diff_eq(-DVec3::X, 1e-9));
        // Beyond every piece's box (as rounding may leave a hit point): still the nearest
        // piece's normal, not a fixed direction.
        let beyond = sweep.normal(DVec3::new(-1.5, 0.0, 0.0)).normalize();
        assert!(beyond.abs_diff_eq(-DVec3::X, 1e-9), "{beyond}");
        let above_the_cone = sweep.normal(DVec3::new(2.0, 0.0, -1.5)).normalize();
        assert!(
            above_the_cone.abs_diff_eq(-DVec3::Z, 1e-9),
            "{above_the_cone}"
        );
    }
}
