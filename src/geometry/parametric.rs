//! The parametric surface: the points (x(u,v), y(u,v), z(u,v)) for (u, v) in a rectangle,
//! where the container holds them.
//!
//! In: a [`Parametric`](crate::scene::Parametric) (three compiled functions of u and v, the
//! uv rectangle, container, max_gradient, accuracy). Out: the nearest crossing of a line,
//! normals, uv coordinates (the parameters), bounds; the surface is a shell with no inside.
//! Holds: the search splits the uv rectangle in quarters, bounding each piece's points by a
//! box around the point at its centre grown by `max_gradient` times the piece's half sizes
//! (the manual's meaning of max_gradient: a bound of all six partial derivatives), keeps the
//! pieces whose boxes the line meets, nearest first. Down to [`TABLE_DEPTH`] the boxes are
//! measured once from sampled points; in deeper pieces Newton's method looks for the exact
//! crossing, and pieces where it fails are split a few more times (or until their box is
//! smaller than `accuracy`; shallower pieces are always split). A
//! too-low max_gradient loses pieces of the surface, as in POV-Ray. The normal is the cross
//! product of the partial derivatives at the uv point nearest the hit. Nothing allocates; a
//! search spends at most [`MAX_PIECES`] pieces.

use super::isosurface::line_in_container;
use super::roots::Roots;
use crate::accel::Aabb;
use crate::scene::{Container, Parametric as ParametricSpec};
use crate::texture::function::Function;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// Room for the pieces waiting on the search stack (three siblings per level).
const STACK_SIZE: usize = 3 * (TABLE_DEPTH + SPLIT_DEPTH) + 4;
/// Most pieces one search may look at (a huge max_gradient with a tiny accuracy would
/// otherwise take hours); past it the search gives up.
const MAX_PIECES: u32 = 1 << 16;
/// Depth down to which the pieces' boxes are measured once, from points sampled on a
/// `2^TABLE_DEPTH` by `2^TABLE_DEPTH` grid (much tighter than `max_gradient` alone allows).
const TABLE_DEPTH: usize = 7;
/// How many times a measured piece where Newton's method fails is split further before the
/// search gives it up.
const SPLIT_DEPTH: usize = 3;
/// Crossings nearer than this along the line are not reported (the surface has no inside, so
/// a line leaving the surface would otherwise find its own start point first).
const NEAREST_CROSSING: f64 = 1e-5;
/// Most crossings one line reports.
const CROSSINGS_PER_LINE: usize = 2;
/// How far past its edges (relative to its size) a piece claims the crossings Newton's
/// method finds from it.
const PIECE_MARGIN: f64 = 0.01;
/// Most Newton steps refining a crossing.
const NEWTON_STEPS: usize = 12;
/// Step of the central differences for the partial derivatives, relative to the uv sizes.
const DERIVATIVE_STEP: f64 = 1e-5;

/// A piece of the uv rectangle waiting to be searched: its corners and where the line
/// enters its box.
#[derive(Clone, Copy, Debug, Default)]
struct Piece {
    low: DVec2,
    high: DVec2,
    entry: f64,
    depth: usize,
    /// The piece's column and row among the `2^depth` by `2^depth` pieces of its depth.
    cell: (usize, usize),
}

impl Piece {
    /// The four quarters of the piece (their entries still unset).
    fn quarters(&self) -> [Piece; 4] {
        let middle = (self.low + self.high) * 0.5;
        let (column, row) = (2 * self.cell.0, 2 * self.cell.1);
        let quarter = |low: DVec2, high: DVec2, cell: (usize, usize)| Piece {
            low,
            high,
            entry: 0.0,
            depth: self.depth + 1,
            cell,
        };
        [
            quarter(self.low, middle, (column, row)),
            quarter(
                DVec2::new(middle.x, self.low.y),
                DVec2::new(self.high.x, middle.y),
                (column + 1, row),
            ),
            quarter(
                DVec2::new(self.low.x, middle.y),
                DVec2::new(middle.x, self.high.y),
                (column, row + 1),
            ),
            quarter(middle, self.high, (column + 1, row + 1)),
        ]
    }
}

/// A parametric surface in its local space.
#[derive(Clone, Debug)]
pub struct ParametricSurface {
    functions: [Arc<Function>; 3],
    uv_low: DVec2,
    uv_high: DVec2,
    container: Container,
    max_gradient: f64,
    accuracy: f64,
    /// The boxes of the pieces down to depth [`TABLE_DEPTH`], depth by depth, each depth row
    /// by row (`table_offset(depth) + row * 2^depth + column`).
    table: Vec<Aabb>,
}

/// Offset of the first box of `depth` in [`ParametricSurface::table`].
fn table_offset(depth: usize) -> usize {
    // 1 + 4 + .. + 4^(depth-1).
    ((1 << (2 * depth)) - 1) / 3
}

impl ParametricSurface {
    /// The surface of a scene description; `None` for an empty uv rectangle, a degenerate
    /// container or settings that are not positive and finite.
    pub fn new(spec: &ParametricSpec) -> Option<ParametricSurface> {
        let uv_low = spec.uv_corner1.min(spec.uv_corner2);
        let uv_high = spec.uv_corner1.max(spec.uv_corner2);
        let usable = uv_low.is_finite()
            && uv_high.is_finite()
            && uv_low.cmplt(uv_high).all()
            && spec.max_gradient > 0.0
            && spec.max_gradient.is_finite()
            && spec.accuracy > 0.0
            && spec.accuracy.is_finite()
            && container_bounds(&spec.container).is_finite();
        if !usable {
            return None;
        }
        let mut surface = ParametricSurface {
            functions: spec.functions.clone(),
            uv_low,
            uv_high,
            container: spec.container,
            max_gradient: spec.max_gradient,
            accuracy: spec.accuracy,
            table: Vec::new(),
        };
        surface.table = surface.piece_table();
        Some(surface)
    }

    /// The boxes of the pieces down to [`TABLE_DEPTH`]: at the deepest, the box of the
    /// points at a piece's corners and centre, grown by what `max_gradient` allows in
    /// between; above, the union of the four quarters' boxes.
    fn piece_table(&self) -> Vec<Aabb> {
        let side = 1usize << TABLE_DEPTH;
        let size = (self.uv_high - self.uv_low) / side as f64;
        let corner = |column: usize, row: usize| {
            self.point(self.uv_low + size * DVec2::new(column as f64, row as f64))
        };
        let corners: Vec<DVec3> = (0..=side)
            .flat_map(|row| (0..=side).map(move |column| (column, row)))
            .map(|(column, row)| corner(column, row))
            .collect();
        let mut table = vec![Aabb::EMPTY; table_offset(TABLE_DEPTH + 1)];
        let reach = DVec3::splat(self.max_gradient * 0.5 * (size.x + size.y) * 0.5);
        let deepest = table_offset(TABLE_DEPTH);
        for row in 0..side {
            for column in 0..side {
                let centre = self
                    .point(self.uv_low + size * DVec2::new(column as f64 + 0.5, row as f64 + 0.5));
                let at = |c: usize, r: usize| corners[r * (side + 1) + c];
                let points = Aabb::from_points([
                    at(column, row),
                    at(column + 1, row),
                    at(column, row + 1),
                    at(column + 1, row + 1),
                    centre,
                ]);
                table[deepest + row * side + column] = Aabb {
                    min: points.min - reach,
                    max: points.max + reach,
                };
            }
        }
        for depth in (0..TABLE_DEPTH).rev() {
            let side = 1usize << depth;
            for row in 0..side {
                for column in 0..side {
                    let child = |c: usize, r: usize| {
                        table[table_offset(depth + 1) + (2 * row + r) * (2 * side) + 2 * column + c]
                    };
                    table[table_offset(depth) + row * side + column] = child(0, 0)
                        .union(&child(1, 0))
                        .union(&child(0, 1))
                        .union(&child(1, 1));
                }
            }
        }
        table
    }

    /// The whole uv rectangle as a piece.
    fn whole(&self) -> Piece {
        Piece {
            low: self.uv_low,
            high: self.uv_high,
            entry: 0.0,
            depth: 0,
            cell: (0, 0),
        }
    }

    /// The surface point at `uv`.
    fn point(&self, uv: DVec2) -> DVec3 {
        let parameters = [uv.x, uv.y, 0.0];
        DVec3::new(
            self.functions[0].eval(&parameters),
            self.functions[1].eval(&parameters),
            self.functions[2].eval(&parameters),
        )
    }

    /// The box holding the points of `piece`: from the table, or below its depth the point
    /// at the piece's centre grown by what `max_gradient` allows.
    fn piece_box(&self, piece: &Piece) -> Aabb {
        if piece.depth <= TABLE_DEPTH {
            let side = 1usize << piece.depth;
            return self.table[table_offset(piece.depth) + piece.cell.1 * side + piece.cell.0];
        }
        let half = (piece.high - piece.low) * 0.5;
        let reach = DVec3::splat(self.max_gradient * (half.x + half.y));
        let centre = self.point(piece.low + half);
        Aabb {
            min: centre - reach,
            max: centre + reach,
        }
    }

    /// Pushes the first crossings of the line `origin + t direction` ahead of
    /// [`NEAREST_CROSSING`] within the container (at most [`CROSSINGS_PER_LINE`]).
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let Some((near, far)) = line_in_container(&self.container, origin, direction) else {
            return;
        };
        let length = direction.length();
        if !(length > 0.0 && length.is_finite()) {
            return;
        }
        let mut lower = near.max(NEAREST_CROSSING);
        for _ in 0..CROSSINGS_PER_LINE {
            match self.first_crossing(origin, direction, lower, far) {
                Some(distance) => {
                    roots.push(distance, 0);
                    lower = distance + NEAREST_CROSSING;
                }
                None => break,
            }
        }
    }

    /// The nearest crossing of the line beyond `lower` and before `upper`.
    fn first_crossing(
        &self,
        origin: DVec3,
        direction: DVec3,
        lower: f64,
        upper: f64,
    ) -> Option<f64> {
        let inverse_direction = direction.recip();
        let enters = |piece_box: &Aabb, limit: f64| {
            piece_box.ray_entry(origin, inverse_direction, lower, limit)
        };
        let mut stack = [Piece::default(); STACK_SIZE];
        let mut stack_len = 0;
        let whole = self.whole();
        if let Some(entry) = enters(&self.piece_box(&whole), upper) {
            stack[0] = Piece { entry, ..whole };
            stack_len = 1;
        }
        let mut nearest = f64::INFINITY;
        let mut pieces = 0;
        while stack_len > 0 && pieces < MAX_PIECES {
            stack_len -= 1;
            let piece = stack[stack_len];
            if piece.entry >= nearest {
                continue;
            }
            pieces += 1;
            if piece.depth >= TABLE_DEPTH {
                // Small enough for Newton's method to settle on the crossing inside it.
                if let Some(distance) = self.solve_crossing(origin, direction, &piece) {
                    if distance > lower && distance < upper.min(nearest) {
                        nearest = distance;
                        continue;
                    }
                }
            }
            let half = (piece.high - piece.low) * 0.5;
            let size = 2.0 * self.max_gradient * (half.x + half.y);
            // `accuracy` only ends the splitting of pieces Newton's method has been tried on.
            let accurate = size < self.accuracy && piece.depth >= TABLE_DEPTH;
            if accurate || piece.depth >= TABLE_DEPTH + SPLIT_DEPTH {
                continue;
            }
            let mut children = [Piece::default(); 4];
            let mut count = 0;
            for quarter in piece.quarters() {
                if let Some(entry) = enters(&self.piece_box(&quarter), upper.min(nearest)) {
                    children[count] = Piece { entry, ..quarter };
                    count += 1;
                }
            }
            // Nearest on top of the stack.
            let children = &mut children[..count];
            children.sort_unstable_by(|a, b| b.entry.total_cmp(&a.entry));
            for child in children.iter() {
                if stack_len < STACK_SIZE {
                    stack[stack_len] = *child;
                    stack_len += 1;
                }
            }
        }
        nearest.is_finite().then_some(nearest)
    }

    /// Where the line meets the surface in a small piece: Newton's method on
    /// P(u, v) = origin + t direction from the piece's centre and box entry. `None` when it
    /// does not settle, or settles outside the piece or the uv rectangle.
    fn solve_crossing(&self, origin: DVec3, direction: DVec3, piece: &Piece) -> Option<f64> {
        let mut uv = (piece.low + piece.high) * 0.5;
        let mut distance = piece.entry;
        let step = (self.uv_high - self.uv_low) * DERIVATIVE_STEP;
        let tolerance = self.accuracy * 1e-3;
        for _ in 0..NEWTON_STEPS {
            let miss = self.point(uv) - (origin + direction * distance);
            if !miss.is_finite() {
                return None;
            }
            let (along_u, along_v) = self.partials(uv, step);
            let jacobian = glam::DMat3::from_cols(along_u, along_v, -direction);
            let determinant = jacobian.determinant();
            if determinant == 0.0 || !determinant.is_finite() {
                return None;
            }
            let correction = jacobian.inverse() * miss;
            uv -= DVec2::new(correction.x, correction.y);
            distance -= correction.z;
            if miss.length() < tolerance {
                // The crossing must lie in the piece (a little grown, so that crossings on
                // its edges are not lost) and in the uv rectangle.
                let margin = (piece.high - piece.low) * PIECE_MARGIN;
                let inside = uv.cmpge(self.uv_low.max(piece.low - margin)).all()
                    && uv.cmple(self.uv_high.min(piece.high + margin)).all();
                return inside.then_some(distance);
            }
        }
        None
    }

    /// The partial derivatives of the surface point along u and v at `uv` (central
    /// differences with steps `step`).
    fn partials(&self, uv: DVec2, step: DVec2) -> (DVec3, DVec3) {
        let along_u = (self.point(uv + DVec2::new(step.x, 0.0))
            - self.point(uv - DVec2::new(step.x, 0.0)))
            / (2.0 * step.x);
        let along_v = (self.point(uv + DVec2::new(0.0, step.y))
            - self.point(uv - DVec2::new(0.0, step.y)))
            / (2.0 * step.y);
        (along_u, along_v)
    }

    /// The uv point whose surface point is nearest `point`: the centre of the nearest
    /// measured piece whose box holds the point, polished by Gauss-Newton steps.
    fn nearest_uv(&self, point: DVec3) -> DVec2 {
        let mut stack = [self.whole(); STACK_SIZE];
        let mut stack_len = 1;
        let mut best = (f64::INFINITY, (self.uv_low + self.uv_high) * 0.5);
        while stack_len > 0 {
            stack_len -= 1;
            let piece = stack[stack_len];
            if piece.depth == TABLE_DEPTH {
                let middle = (piece.low + piece.high) * 0.5;
                let distance = self.point(middle).distance(point);
                if distance < best.0 {
                    best = (distance, middle);
                }
                continue;
            }
            for quarter in piece.quarters() {
                let piece_box = self.piece_box(&quarter);
                let margin = DVec3::splat(self.accuracy);
                let holds = point.cmpge(piece_box.min - margin).all()
                    && point.cmple(piece_box.max + margin).all();
                if holds && stack_len < STACK_SIZE {
                    stack[stack_len] = quarter;
                    stack_len += 1;
                }
            }
        }
        let step = (self.uv_high - self.uv_low) * DERIVATIVE_STEP;
        let mut uv = best.1;
        for _ in 0..NEWTON_STEPS {
            let miss = self.point(uv) - point;
            let (along_u, along_v) = self.partials(uv, step);
            let (uu, uv_, vv) = (
                along_u.dot(along_u),
                along_u.dot(along_v),
                along_v.dot(along_v),
            );
            let determinant = uu * vv - uv_ * uv_;
            if !(determinant.abs() > 0.0 && determinant.is_finite()) {
                break;
            }
            let (gu, gv) = (along_u.dot(miss), along_v.dot(miss));
            let delta = DVec2::new(vv * gu - uv_ * gv, uu * gv - uv_ * gu) / determinant;
            uv = (uv - delta).clamp(self.uv_low, self.uv_high);
        }
        uv
    }

    /// POV-Ray's uv at a surface `point` (measured): the surface's own `(u, v)` parameters
    /// there, not rescaled to the unit square.
    pub fn uv(&self, point: DVec3) -> DVec2 {
        self.nearest_uv(point)
    }

    /// The normal at a surface `point`: the cross product of the partial derivatives at the
    /// nearest uv point.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        self.normal_at_uv(self.nearest_uv(point))
    }

    /// The normal and the uv at a surface `point`, from one search for its nearest uv point.
    pub fn normal_and_uv(&self, point: DVec3) -> (DVec3, DVec2) {
        let uv = self.nearest_uv(point);
        (self.normal_at_uv(uv), uv)
    }

    /// The normal at the surface point of parameters `uv`.
    fn normal_at_uv(&self, uv: DVec2) -> DVec3 {
        let (along_u, along_v) = self.partials(uv, (self.uv_high - self.uv_low) * DERIVATIVE_STEP);
        let normal = along_u.cross(along_v);
        if normal.is_finite() && normal != DVec3::ZERO {
            normal
        } else {
            DVec3::Y
        }
    }

    /// The container's bounds.
    pub fn bounds(&self) -> Aabb {
        container_bounds(&self.container)
    }
}

/// The box around a container.
fn container_bounds(container: &Container) -> Aabb {
    match *container {
        Container::Box { corner1, corner2 } => Aabb::from_corners(corner1, corner2),
        Container::Sphere { centre, radius } => Aabb::from_corners(
            centre - DVec3::splat(radius.abs()),
            centre + DVec3::splat(radius.abs()),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::function::{Binary, Node};

    /// The plane sheet (u, v, 0.5 u) over the uv square [-1, 1]².
    fn sheet() -> ParametricSurface {
        sheet_over(DVec2::splat(-1.0), DVec2::splat(1.0), 0.001)
    }

    /// The plane sheet (u, v, 0.5 u) over the uv rectangle from `low` to `high`.
    fn sheet_over(low: DVec2, high: DVec2, accuracy: f64) -> ParametricSurface {
        let function = |node: Node| Arc::new(Function::new(node, 3));
        let half_u = Node::Binary(
            Binary::Multiply,
            Box::new([Node::Constant(0.5), Node::Parameter(0)]),
        );
        ParametricSurface::new(&ParametricSpec {
            functions: [
                function(Node::Parameter(0)),
                function(Node::Parameter(1)),
                function(half_u),
            ],
            uv_corner1: low,
            uv_corner2: high,
            container: Container::Box {
                corner1: DVec3::splat(-2.0),
                corner2: DVec3::splat(2.0),
            },
            max_gradient: 1.1,
            accuracy,
        })
        .unwrap()
    }

    #[test]
    fn random_lines_meet_the_sheet_where_it_is() {
        let surface = sheet();
        let mut random = crate::geometry::test_support::Random::new(7);
        let mut hits = 0;
        for _ in 0..300 {
            let origin = random.vector(1.5) - DVec3::Z * 3.0;
            let target = DVec3::new(random.range(-1.2, 1.2), random.range(-1.2, 1.2), 0.0);
            let target = DVec3::new(target.x, target.y, 0.5 * target.x);
            let direction = target - origin;
            let mut roots = Roots::new();
            surface.intersect(origin, direction, &mut roots);
            let inside = target.x.abs() < 0.999 && target.y.abs() < 0.999;
            let outside = target.x.abs() > 1.001 || target.y.abs() > 1.001;
            match roots.nearest_within(0.0, f64::INFINITY) {
                Some((distance, _)) => {
                    assert!(!outside, "hit outside the uv square at {target}");
                    assert!((distance - 1.0).abs() < 1e-6, "{distance} for {target}");
                    let normal = surface.normal(origin + direction * distance).normalize();
                    let expected = DVec3::new(-0.5, 0.0, 1.0).normalize();
                    assert!(
                        normal.abs_diff_eq(expected, 1e-4) || normal.abs_diff_eq(-expected, 1e-4)
                    );
                    hits += 1;
                }
                None => assert!(!inside, "missed the sheet at {target}"),
            }
        }
        assert!(hits > 100);
    }

    #[test]
    fn a_coarse_accuracy_still_finds_the_surface() {
        // Pieces above the table depth are smaller than this accuracy already; the search
        // must still reach the depth where Newton's method is tried.
        let surface = sheet_over(DVec2::ZERO, DVec2::ONE, 0.05);
        let mut random = crate::geometry::test_support::Random::new(3);
        for _ in 0..50 {
            let target = DVec3::new(random.range(0.05, 0.95), random.range(0.05, 0.95), 0.0);
            let target = DVec3::new(target.x, target.y, 0.5 * target.x);
            let origin = target - DVec3::new(0.1, 0.2, 1.0);
            let mut roots = Roots::new();
            surface.intersect(origin, target - origin, &mut roots);
            let (distance, _) = roots
                .nearest_within(0.0, f64::INFINITY)
                .unwrap_or_else(|| panic!("missed the sheet at {target}"));
            assert!((distance - 1.0).abs() < 1e-3, "{distance} for {target}");
        }
    }

    #[test]
    fn uv_is_the_surface_parameters() {
        // POV-Ray's uv_mapping on a parametric surface sees its (u, v) parameters as they
        // are (measured: a sheet over u in [0.2, 0.7] shows u = x, not (x - 0.2) / 0.5).
        let surface = sheet_over(DVec2::new(0.2, 0.1), DVec2::new(0.7, 0.9), 0.001);
        for parameters in [DVec2::new(0.25, 0.15), DVec2::new(0.6, 0.8)] {
            let point = DVec3::new(parameters.x, parameters.y, 0.5 * parameters.x);
            assert!(surface.uv(point).abs_diff_eq(parameters, 1e-6));
        }
    }

    #[test]
    fn lines_from_the_surface_do_not_meet_their_start() {
        let surface = sheet();
        let start = DVec3::new(0.3, 0.2, 0.15);
        let mut roots = Roots::new();
        surface.intersect(start, DVec3::new(0.2, 0.1, 1.0), &mut roots);
        assert_eq!(roots.iter().count(), 0);
        assert!(!surface.bounds().is_empty());
    }
}
