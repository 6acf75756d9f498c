//! The height field: a grid of heights over the unit square in x and z, two triangles per
//! grid cell.
//!
//! In: a [`HeightField`](crate::scene::HeightField) (heights row by row from z = 0, smooth
//! flag, water level). Out: crossings of a line (the line walks the grid cell by cell, nearest
//! first), inside test (below the surface over the unit square), flat or smoothed normals,
//! bounds from the water level (or the lowest point) to the highest point, as POV-Ray's.
//! Holds: each cell from (x0, z0) to (x1, z1) is split along the diagonal from (x1, z0) to
//! (x0, z1), as POV-Ray splits it (measured with `trace`); crossings below the water level are
//! dropped; smoothed normals follow POV-Ray's rule exactly (see [`vertex_normal`], measured
//! with `trace` to 1e-9); nothing allocates per ray.

use super::roots::{Roots, MAX_ROOTS};
use crate::accel::Aabb;
use crate::scene::HeightField as HeightFieldSpec;
use glam::{DMat3, DVec2, DVec3};

/// Heights are 16-bit values over this many units.
const HEIGHT_UNITS: f64 = 65536.0;
/// Smoothed vertex normals are stored as 16-bit integers of this full scale.
const NORMAL_UNITS: f64 = 32767.0;

/// A height field in its local space.
#[derive(Clone, Debug)]
pub struct HeightField {
    columns: usize,
    rows: usize,
    heights: Vec<f64>,
    smooth: bool,
    /// With `smooth`, each grid point's normal in grid units (see [`vertex_normal`]).
    vertex_normals: Vec<[i16; 3]>,
    water_level: f64,
    lowest: f64,
    highest: f64,
}

impl HeightField {
    /// The height field of a scene description; `None` with fewer than 2 by 2 points or
    /// heights that do not fill the grid.
    pub fn new(spec: &HeightFieldSpec) -> Option<HeightField> {
        let usable = spec.columns >= 2
            && spec.rows >= 2
            && spec.heights.len() == spec.columns * spec.rows
            && spec.heights.iter().all(|h| h.is_finite());
        if !usable {
            return None;
        }
        let highest = spec.heights.iter().copied().fold(0.0, f64::max);
        let lowest = spec.heights.iter().copied().fold(highest, f64::min);
        let mut field = HeightField {
            columns: spec.columns,
            rows: spec.rows,
            heights: spec.heights.clone(),
            smooth: spec.smooth,
            vertex_normals: Vec::new(),
            water_level: spec.water_level,
            lowest,
            highest,
        };
        if field.smooth {
            field.vertex_normals = (0..field.rows as isize)
                .flat_map(|row| (0..field.columns as isize).map(move |column| (column, row)))
                .map(|(column, row)| vertex_normal(&field, column, row))
                .collect();
        }
        Some(field)
    }

    /// The height at grid point (`column`, `row`), clamped into the grid.
    #[inline]
    fn height(&self, column: isize, row: isize) -> f64 {
        let column = column.clamp(0, self.columns as isize - 1) as usize;
        let row = row.clamp(0, self.rows as isize - 1) as usize;
        self.heights[row * self.columns + column]
    }

    /// Grid cells per unit along x and z.
    fn cells(&self) -> DVec2 {
        DVec2::new((self.columns - 1) as f64, (self.rows - 1) as f64)
    }

    /// Pushes the crossings of the line `origin + t direction`, nearest first.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        // Clip the line to the grid's box.
        let low = DVec3::new(0.0, self.lowest, 0.0);
        let high = DVec3::new(1.0, self.highest, 1.0);
        let mut entry = f64::NEG_INFINITY;
        let mut exit = f64::INFINITY;
        for axis in 0..3 {
            if direction[axis] == 0.0 {
                if origin[axis] < low[axis] || origin[axis] > high[axis] {
                    return;
                }
                continue;
            }
            let first = (low[axis] - origin[axis]) / direction[axis];
            let second = (high[axis] - origin[axis]) / direction[axis];
            entry = entry.max(first.min(second));
            exit = exit.min(first.max(second));
        }
        if entry > exit || !entry.is_finite() || !exit.is_finite() {
            return;
        }
        // Start at the ray's origin when it is inside the box: crossings behind it would only
        // take the places of the ones ahead in the bounded list of roots.
        let entry = entry.max(0.0);
        if entry > exit {
            return;
        }
        // Walk the cells in grid coordinates.
        let cells = self.cells();
        let grid_origin = DVec2::new(origin.x * cells.x, origin.z * cells.y);
        let grid_direction = DVec2::new(direction.x * cells.x, direction.z * cells.y);
        let start = grid_origin + grid_direction * entry;
        let last_column = self.columns as isize - 2;
        let last_row = self.rows as isize - 2;
        let mut column = (start.x.floor() as isize).clamp(0, last_column);
        let mut row = (start.y.floor() as isize).clamp(0, last_row);
        let step_column: isize = if grid_direction.x > 0.0 { 1 } else { -1 };
        let step_row: isize = if grid_direction.y > 0.0 { 1 } else { -1 };
        let next_boundary = |cell: isize, step: isize| (cell + (step > 0) as isize) as f64;
        let crossing = |boundary: f64, from: f64, speed: f64| {
            if speed == 0.0 {
                f64::INFINITY
            } else {
                (boundary - from) / speed
            }
        };
        let mut next_column_t = crossing(
            next_boundary(column, step_column),
            grid_origin.x,
            grid_direction.x,
        );
        let mut next_row_t = crossing(
            next_boundary(row, step_row),
            grid_origin.y,
            grid_direction.y,
        );
        let column_t_step = (1.0 / grid_direction.x).abs();
        let row_t_step = (1.0 / grid_direction.y).abs();
        let mut found = 0;
        let mut cell_entry = entry;
        loop {
            let cell_exit = next_column_t.min(next_row_t).min(exit);
            // Skip cells the line passes above or below.
            let y_in = origin.y + direction.y * cell_entry;
            let y_out = origin.y + direction.y * cell_exit;
            let corners = [
                self.height(column, row),
                self.height(column + 1, row),
                self.height(column, row + 1),
                self.height(column + 1, row + 1),
            ];
            let cell_low = corners.iter().copied().fold(f64::INFINITY, f64::min);
            let cell_high = corners.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if y_in.min(y_out) <= cell_high && y_in.max(y_out) >= cell_low {
                let mut hits = [f64::INFINITY; 2];
                for (slot, triangle) in hits.iter_mut().zip(self.cell_triangles(column, row)) {
                    if let Some(t) = triangle_crossing(origin, direction, &triangle) {
                        if t >= cell_entry - 1e-9 && t <= cell_exit + 1e-9 {
                            let y = origin.y + direction.y * t;
                            if y > self.water_level || self.water_level <= 0.0 {
                                *slot = t;
                            }
                        }
                    }
                }
                if hits[1] < hits[0] {
                    hits.swap(0, 1);
                }
                for t in hits.into_iter().filter(|t| t.is_finite()) {
                    roots.push(t, 0);
                    found += 1;
                }
                if found >= MAX_ROOTS {
                    return;
                }
            }
            if cell_exit >= exit {
                return;
            }
            cell_entry = cell_exit;
            if next_column_t < next_row_t {
                column += step_column;
                next_column_t += column_t_step;
                if column < 0 || column > last_column {
                    return;
                }
            } else {
                row += step_row;
                next_row_t += row_t_step;
                if row < 0 || row > last_row {
                    return;
                }
            }
        }
    }

    /// The local corner positions of grid point (`column`, `row`).
    fn corner(&self, column: isize, row: isize) -> DVec3 {
        let cells = self.cells();
        DVec3::new(
            column as f64 / cells.x,
            self.height(column, row),
            row as f64 / cells.y,
        )
    }

    /// The two triangles of a cell, each as corners (with their grid points).
    fn cell_triangles(&self, column: isize, row: isize) -> [[(DVec3, isize, isize); 3]; 2] {
        let at = |c: isize, r: isize| (self.corner(c, r), c, r);
        [
            [at(column, row), at(column + 1, row), at(column, row + 1)],
            [
                at(column + 1, row),
                at(column + 1, row + 1),
                at(column, row + 1),
            ],
        ]
    }

    /// True when `point` lies over the unit square and below the surface.
    pub fn inside(&self, point: DVec3) -> bool {
        if !(0.0..=1.0).contains(&point.x) || !(0.0..=1.0).contains(&point.z) {
            return false;
        }
        let (triangle, weights) = self.locate(point);
        let height: f64 = triangle
            .iter()
            .zip(weights)
            .map(|((corner, _, _), weight)| corner.y * weight)
            .sum();
        point.y < height
    }

    /// The triangle under `point` and the barycentric weights of its corners there.
    fn locate(&self, point: DVec3) -> ([(DVec3, isize, isize); 3], [f64; 3]) {
        let cells = self.cells();
        let grid = DVec2::new(point.x * cells.x, point.z * cells.y);
        let column = (grid.x.floor() as isize).clamp(0, self.columns as isize - 2);
        let row = (grid.y.floor() as isize).clamp(0, self.rows as isize - 2);
        let u = grid.x - column as f64;
        let v = grid.y - row as f64;
        let [lower, upper] = self.cell_triangles(column, row);
        if u + v <= 1.0 {
            (lower, [1.0 - u - v, u, v])
        } else {
            // Corners (x1, z0), (x1, z1), (x0, z1).
            (upper, [1.0 - v, u + v - 1.0, 1.0 - u])
        }
    }

    /// The upward local normal at a surface point of the untransformed field.
    pub fn normal(&self, point: DVec3) -> DVec3 {
        self.world_normal(point, DMat3::IDENTITY)
    }

    /// The upward normal (any length) at the local surface `point`, in the space that
    /// `world_from_local_normal` maps local normals into: the triangle's, or when smooth the
    /// bilinear blend of the cell's four corner normals, each taken into that space and made
    /// unit length first (as POV-Ray blends them, measured under non-uniform scales).
    pub fn world_normal(&self, point: DVec3, world_from_local_normal: DMat3) -> DVec3 {
        if !self.smooth {
            let ([(a, _, _), (b, _, _), (c, _, _)], _) = self.locate(point);
            let normal = (c - a).cross(b - a);
            let normal = if normal.y < 0.0 { -normal } else { normal };
            return world_from_local_normal * normal;
        }
        let cells = self.cells();
        let grid = DVec2::new(point.x * cells.x, point.z * cells.y);
        let column = (grid.x.floor() as isize).clamp(0, self.columns as isize - 2);
        let row = (grid.y.floor() as isize).clamp(0, self.rows as isize - 2);
        let u = (grid.x - column as f64).clamp(0.0, 1.0);
        let v = (grid.y - row as f64).clamp(0.0, 1.0);
        let corner = |c: isize, r: isize| {
            let [x, y, z] = self.vertex_normals[r as usize * self.columns + c as usize];
            // Grid units to the unit square: x and z over the cells, y over the height units.
            let local = DVec3::new(
                f64::from(x) * cells.x,
                f64::from(y) * HEIGHT_UNITS,
                f64::from(z) * cells.y,
            );
            (world_from_local_normal * local).normalize_or_zero()
        };
        corner(column, row) * ((1.0 - u) * (1.0 - v))
            + corner(column + 1, row) * (u * (1.0 - v))
            + corner(column, row + 1) * ((1.0 - u) * v)
            + corner(column + 1, row + 1) * (u * v)
    }

    /// Bounds: the unit square from the water level (or the lowest point) to the highest.
    pub fn bounds(&self) -> Aabb {
        let lowest = self.water_level.clamp(self.lowest, self.highest);
        Aabb::from_points([
            DVec3::new(0.0, lowest, 0.0),
            DVec3::new(1.0, self.highest, 1.0),
        ])
    }
}

/// Where the line crosses a triangle (any side), by the Möller-Trumbore test.
fn triangle_crossing(
    origin: DVec3,
    direction: DVec3,
    triangle: &[(DVec3, isize, isize); 3],
) -> Option<f64> {
    let (a, b, c) = (triangle[0].0, triangle[1].0, triangle[2].0);
    let edge1 = b - a;
    let edge2 = c - a;
    let p = direction.cross(edge2);
    let determinant = edge1.dot(p);
    if determinant.abs() < 1e-300 {
        return None;
    }
    let inverse = 1.0 / determinant;
    let offset = origin - a;
    let u = offset.dot(p) * inverse;
    if !(-1e-12..=1.0 + 1e-12).contains(&u) {
        return None;
    }
    let q = offset.cross(edge1);
    let v = direction.dot(q) * inverse;
    if v < -1e-12 || u + v > 1.0 + 1e-12 {
        return None;
    }
    Some(edge2.dot(q) * inverse)
}

/// POV-Ray's smoothed normal at grid point (`column`, `row`), in grid units (one unit per
/// cell across, one per 1/65536 of height up): the sum of the unit normals of the planes
/// through the point and each pair of its x and z neighbours that both exist, made unit
/// length and cut to 16-bit integers of full scale 32767 (truncated, as POV-Ray stores it).
fn vertex_normal(field: &HeightField, column: isize, row: isize) -> [i16; 3] {
    let height = |c: isize, r: isize| field.height(c, r) * HEIGHT_UNITS;
    let centre = height(column, row);
    let mut sum = DVec3::ZERO;
    for step_column in [-1isize, 1] {
        for step_row in [-1isize, 1] {
            let (neighbour_column, neighbour_row) = (column + step_column, row + step_row);
            let exists = (0..field.columns as isize).contains(&neighbour_column)
                && (0..field.rows as isize).contains(&neighbour_row);
            if !exists {
                continue;
            }
            let along_x = DVec3::new(
                step_column as f64,
                height(neighbour_column, row) - centre,
                0.0,
            );
            let along_z = DVec3::new(0.0, height(column, neighbour_row) - centre, step_row as f64);
            let normal = along_z.cross(along_x);
            let normal = if normal.y < 0.0 { -normal } else { normal };
            sum += normal.normalize_or_zero();
        }
    }
    let unit = sum.normalize_or(DVec3::Y);
    let stored = |value: f64| (value * NORMAL_UNITS).trunc() as i16;
    [stored(unit.x), stored(unit.y), stored(unit.z)]
}
