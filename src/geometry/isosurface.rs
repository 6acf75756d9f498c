//! The isosurface: where a compiled function equals its threshold, inside a container.
//!
//! In: an [`Isosurface`](crate::scene::Isosurface) (function, container, threshold, accuracy,
//! max_gradient, open, max_trace). Out: crossings of a line, inside test, gradient normals,
//! bounds. Holds: the root search is POV-Ray's: an interval of the ray is split in halves
//! until it is shorter than `accuracy`, and dropped when the function values at its ends are
//! too far from the threshold for a function whose slope stays under `max_gradient` to reach
//! it in between; a crossing is the far end of its last interval, up to `accuracy` past the
//! surface, and a ray starting inside the surface begins 5 `accuracy` steps out (both as
//! POV-Ray's `trace` shows). A too-low `max_gradient` therefore loses pieces of the surface or
//! finds points past it, as in POV-Ray. A ray spends at most [`MAX_EVALUATIONS`] function values.
//! Where the function is below the threshold on the container's boundary, the container's
//! surface shows unless `open`. Nothing allocates.

use super::roots::{Roots, MAX_ROOTS};
use crate::accel::Aabb;
use crate::scene::{Container, Isosurface as IsosurfaceSpec};
use crate::texture::function::Function;
use glam::DVec3;
use std::sync::Arc;

/// Surface part of crossings on the function's surface.
const FUNCTION_PART: u8 = 0;
/// Surface part of crossings on the container's surface.
const CONTAINER_PART: u8 = 1;
/// Deepest halving of a ray interval (far beyond any useful accuracy).
const MAX_DEPTH: u32 = 60;
/// Accuracy steps a ray starting inside the surface skips before its search begins.
const INSIDE_START_SKIP: f64 = 5.0;
/// Most function evaluations one ray may spend (a huge `max_gradient` with a tiny `accuracy`
/// would otherwise take hours); past it the search gives up on the rest of the ray.
const MAX_EVALUATIONS: u32 = 1 << 16;

/// An isosurface in its local space.
#[derive(Clone, Debug)]
pub struct Isosurface {
    function: Arc<Function>,
    container: Container,
    threshold: f64,
    accuracy: f64,
    max_gradient: f64,
    open: bool,
    max_trace: usize,
}

/// Crossings found along one ray, in order (at most [`MAX_ROOTS`]).
struct Found {
    crossings: [(f64, u8); MAX_ROOTS],
    len: usize,
    limit: usize,
    evaluations: u32,
}

impl Found {
    fn full(&self) -> bool {
        self.len >= self.limit || self.evaluations >= MAX_EVALUATIONS
    }

    fn push(&mut self, distance: f64, part: u8) {
        if !self.full() {
            self.crossings[self.len] = (distance, part);
            self.len += 1;
        }
    }
}

impl Isosurface {
    /// The isosurface of a scene description; `None` for a degenerate container or
    /// non-positive accuracy or max_gradient.
    pub fn new(spec: &IsosurfaceSpec) -> Option<Isosurface> {
        let container_ok = match spec.container {
            Container::Box { corner1, corner2 } => {
                corner1.is_finite() && corner2.is_finite() && corner1 != corner2
            }
            Container::Sphere { centre, radius } => centre.is_finite() && radius > 0.0,
        };
        (container_ok
            && spec.accuracy > 0.0
            && spec.max_gradient > 0.0
            && spec.threshold.is_finite())
        .then(|| Isosurface {
            function: spec.function.clone(),
            container: spec.container,
            threshold: spec.threshold,
            accuracy: spec.accuracy,
            max_gradient: spec.max_gradient,
            open: spec.open,
            max_trace: spec.max_trace.clamp(1, MAX_ROOTS),
        })
    }

    /// The function minus the threshold: negative inside.
    #[inline]
    fn field(&self, point: DVec3) -> f64 {
        self.function.eval_point(point) - self.threshold
    }

    /// The parameter interval of the line inside the container.
    fn container_span(&self, origin: DVec3, direction: DVec3) -> Option<(f64, f64)> {
        line_in_container(&self.container, origin, direction)
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let Some((entry, exit)) = self.container_span(origin, direction) else {
            return;
        };
        if exit <= 0.0 {
            return;
        }
        // Work in local distances so accuracy and max_gradient keep their meaning.
        let length = direction.length();
        if length == 0.0 || !length.is_finite() {
            return;
        }
        let unit = direction / length;
        let end = exit * length;
        let at = |distance: f64| self.field(origin + unit * distance);
        let mut start = entry.max(0.0) * length;
        // A ray that starts inside the surface (a secondary ray leaving a hit, which lies past
        // the surface) skips its first `INSIDE_START_SKIP` accuracy steps, as POV-Ray's does:
        // measured on planes, its crossings then lie on the halvings of the rest of the span.
        if entry < 0.0 && at(start) < 0.0 {
            start = (INSIDE_START_SKIP * self.accuracy).min(end);
        }
        let mut found = Found {
            crossings: [(0.0, 0); MAX_ROOTS],
            len: 0,
            limit: self.max_trace,
            evaluations: 0,
        };
        let start_value = at(start);
        if entry >= 0.0 && !self.open && start_value < 0.0 {
            found.push(start, CONTAINER_PART);
        }
        let end_value = at(end);
        // Each search looks for the next point on the other side of the surface from where
        // it starts: the values are turned so that this side is positive.
        let mut from = start;
        let mut side = if start_value < 0.0 { -1.0 } else { 1.0 };
        let mut from_value = side * start_value;
        while !found.full() && from_value.is_finite() {
            let turned = |distance: f64| side * at(distance);
            let Some(crossing) = self.search(
                from,
                from_value,
                end,
                side * end_value,
                &turned,
                &mut found,
                0,
            ) else {
                break;
            };
            // A crossing within `accuracy` of the ray's start is the surface a secondary ray
            // leaves from; it must not use up `max_trace`.
            if crossing > self.accuracy {
                found.push(crossing, FUNCTION_PART);
            }
            if crossing >= end {
                break;
            }
            // The crossing is on the surface: the search goes on from the other side.
            side = -side;
            from = crossing;
            from_value = (side * at(crossing)).max(0.0);
            found.evaluations += 1;
        }
        if !self.open && end_value < 0.0 {
            found.push(end, CONTAINER_PART);
        }
        for &(distance, part) in &found.crossings[..found.len] {
            roots.push(distance / length, part);
        }
    }

    /// POV-Ray's search for the first point where `value` (positive at `low`) is negative:
    /// an interval is dropped when its end values are too large for a slope of
    /// `max_gradient` to bring their sum to zero, otherwise halved, left half first, until it
    /// is shorter than `accuracy`; then, if the value is negative at its far end, that end is
    /// the answer. With a too-low `max_gradient` this drops real crossings, or finds a point
    /// past the surface, as POV-Ray does.
    #[allow(clippy::too_many_arguments)]
    fn search(
        &self,
        low: f64,
        low_value: f64,
        high: f64,
        high_value: f64,
        value: &impl Fn(f64) -> f64,
        found: &mut Found,
        depth: u32,
    ) -> Option<f64> {
        if found.evaluations >= MAX_EVALUATIONS
            || !(low_value.is_finite() && high_value.is_finite())
        {
            return None;
        }
        let span = high - low;
        if low_value + high_value > self.max_gradient * span {
            return None;
        }
        if span < self.accuracy || depth >= MAX_DEPTH {
            // The answer is the interval's far end, as POV-Ray's: its `trace` results lie on
            // the grid of halvings of the container span, past the surface by up to
            // `accuracy` (measured with planes and accuracies from 0.001 to 0.3).
            return (high_value < 0.0).then_some(high);
        }
        let middle = 0.5 * (low + high);
        let middle_value = value(middle);
        found.evaluations += 1;
        self.search(
            low,
            low_value,
            middle,
            middle_value,
            value,
            found,
            depth + 1,
        )
        .or_else(|| {
            self.search(
                middle,
                middle_value,
                high,
                high_value,
                value,
                found,
                depth + 1,
            )
        })
    }

    /// True when `point` is in the container and below the threshold.
    pub fn inside(&self, point: DVec3) -> bool {
        self.in_container(point) && self.field(point) < 0.0
    }

    fn in_container(&self, point: DVec3) -> bool {
        match self.container {
            Container::Box { corner1, corner2 } => {
                point.cmpge(corner1.min(corner2)).all() && point.cmple(corner1.max(corner2)).all()
            }
            Container::Sphere { centre, radius } => {
                point.distance_squared(centre) <= radius * radius
            }
        }
    }

    /// Outward normal at a surface point of the given part.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        if part == CONTAINER_PART {
            return match self.container {
                Container::Box { corner1, corner2 } => {
                    let low = corner1.min(corner2);
                    let high = corner1.max(corner2);
                    let mut best = (f64::INFINITY, DVec3::Y);
                    for axis in 0..3 {
                        let mut unit = DVec3::ZERO;
                        unit[axis] = 1.0;
                        for (distance, normal) in [
                            ((point[axis] - low[axis]).abs(), -unit),
                            ((point[axis] - high[axis]).abs(), unit),
                        ] {
                            if distance < best.0 {
                                best = (distance, normal);
                            }
                        }
                    }
                    best.1
                }
                Container::Sphere { centre, .. } => point - centre,
            };
        }
        // Forward differences over one `accuracy` step, as POV-Ray takes them (measured on
        // y - 0.1 sin(kx) and y + 30y² - 0.1 sin(300x): its normals match these to 12
        // digits; central differences differ wherever the function curves within a step).
        let step = self.accuracy;
        let here = self.field(point);
        let gradient = |axis: DVec3| self.field(point + axis * step) - here;
        DVec3::new(gradient(DVec3::X), gradient(DVec3::Y), gradient(DVec3::Z))
    }

    /// The container's bounds.
    pub fn bounds(&self) -> Aabb {
        match self.container {
            Container::Box { corner1, corner2 } => {
                Aabb::from_points([corner1.min(corner2), corner1.max(corner2)])
            }
            Container::Sphere { centre, radius } => {
                Aabb::from_points([centre - DVec3::splat(radius), centre + DVec3::splat(radius)])
            }
        }
    }
}
/// The parameter interval of the line `origin + t direction` inside `container`.
pub(super) fn line_in_container(
    container: &Container,
    origin: DVec3,
    direction: DVec3,
) -> Option<(f64, f64)> {
    match *container {
        Container::Box { corner1, corner2 } => {
            let low = corner1.min(corner2);
            let high = corner1.max(corner2);
            let mut entry = f64::NEG_INFINITY;
            let mut exit = f64::INFINITY;
            for axis in 0..3 {
                if direction[axis] == 0.0 {
                    if origin[axis] < low[axis] || origin[axis] > high[axis] {
                        return None;
                    }
                    continue;
                }
                let first = (low[axis] - origin[axis]) / direction[axis];
                let second = (high[axis] - origin[axis]) / direction[axis];
                entry = entry.max(first.min(second));
                exit = exit.min(first.max(second));
            }
            (entry < exit).then_some((entry, exit))
        }
        Container::Sphere { centre, radius } => {
            let offset = origin - centre;
            let a = direction.length_squared();
            let half_b = offset.dot(direction);
            let c = offset.length_squared() - radius * radius;
            super::roots::solve_quadratic(a, half_b, c).filter(|(near, far)| near < far)
        }
    }
}
