//! The surface of revolution (`sor`): radius² given as a cubic in the height on each
//! segment, turned around the Y axis, with flat caps unless open.
//!
//! In: the points `<r, h>` (the first and last only set slopes: radius² has slope 2 r dr/dh
//! at each joint, dr/dh from its two neighbours). Out: crossings of a line (a
//! cubic per segment), inside test, outward normals, bounds. Holds: segments whose heights do
//! not increase are dropped; nothing allocates per ray.

use super::roots::{real_roots_between, solve_quadratic, Roots, CROSSING_BUFFER, MAX_DEGREE};
use crate::accel::Aabb;
use glam::{DVec2, DVec3};

/// Part tag of the bottom cap.
const BOTTOM_CAP: u8 = 0;
/// Part tag of the top cap.
const TOP_CAP: u8 = 1;
/// Part tag of the curved side.
const SIDE: u8 = 2;

/// One segment: radius² = ((a h + b) h + c) h + d for h in [low, high].
#[derive(Clone, Copy, Debug)]
struct Piece {
    coefficients: [f64; 4],
    low: f64,
    high: f64,
}

impl Piece {
    fn radius_squared(&self, h: f64) -> f64 {
        let [a, b, c, d] = self.coefficients;
        ((a * h + b) * h + c) * h + d
    }

    fn slope(&self, h: f64) -> f64 {
        let [a, b, c, _] = self.coefficients;
        (3.0 * a * h + 2.0 * b) * h + c
    }
}

/// Solves the 4×4 system `matrix · x = right` by Gaussian elimination with pivoting.
fn solve4(mut matrix: [[f64; 4]; 4], mut right: [f64; 4]) -> Option<[f64; 4]> {
    for column in 0..4 {
        let pivot = (column..4)
            .max_by(|&a, &b| matrix[a][column].abs().total_cmp(&matrix[b][column].abs()))?;
        if matrix[pivot][column] == 0.0 {
            return None;
        }
        matrix.swap(column, pivot);
        right.swap(column, pivot);
        for row in column + 1..4 {
            let factor = matrix[row][column] / matrix[column][column];
            let pivot_row = matrix[column];
            for (value, pivot_value) in matrix[row].iter_mut().zip(pivot_row).skip(column) {
                *value -= factor * pivot_value;
            }
            right[row] -= factor * right[column];
        }
    }
    let mut x = [0.0; 4];
    for row in (0..4).rev() {
        let mut sum = right[row];
        for k in row + 1..4 {
            sum -= matrix[row][k] * x[k];
        }
        x[row] = sum / matrix[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// A surface of revolution.
#[derive(Clone, Debug)]
pub struct Sor {
    pieces: Vec<Piece>,
    open: bool,
    bottom: (f64, f64),
    top: (f64, f64),
    radius: f64,
}

impl Sor {
    /// A surface of revolution; `None` with fewer than four points or no usable segment.
    pub fn new(points: &[DVec2], open: bool) -> Option<Sor> {
        if points.len() < 4 || points.iter().any(|p| !p.is_finite()) {
            return None;
        }
        let mut pieces = Vec::new();
        for j in 1..points.len() - 2 {
            let (before, from, to, after) =
                (points[j - 1], points[j], points[j + 1], points[j + 2]);
            if to.y.partial_cmp(&from.y) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            let row = |h: f64| [h * h * h, h * h, h, 1.0];
            let slope_row = |h: f64| [3.0 * h * h, 2.0 * h, 1.0, 0.0];
            let w = |p: DVec2| p.x * p.x;
            let matrix = [row(from.y), row(to.y), slope_row(from.y), slope_row(to.y)];
            // The slopes of radius² at the ends are 2 r dr/dh, dr/dh from the neighbouring
            // points (as POV-Ray's, measured with `trace` to 1e-9).
            let right = [
                w(from),
                w(to),
                2.0 * from.x * (to.x - before.x) / (to.y - before.y),
                2.0 * to.x * (after.x - from.x) / (after.y - from.y),
            ];
            if let Some(coefficients) = solve4(matrix, right) {
                pieces.push(Piece {
                    coefficients,
                    low: from.y,
                    high: to.y,
                });
            }
        }
        let first = pieces.first()?;
        let last = pieces.last()?;
        let bottom = (first.low, first.radius_squared(first.low).max(0.0));
        let top = (last.high, last.radius_squared(last.high).max(0.0));
        let radius = points[1..points.len() - 1]
            .iter()
            .fold(0.0f64, |m, p| m.max(p.x.abs()))
            .max(
                pieces
                    .iter()
                    .flat_map(|piece| {
                        (0..=8).map(move |i| {
                            let h = piece.low + (piece.high - piece.low) * f64::from(i) / 8.0;
                            piece.radius_squared(h).max(0.0).sqrt()
                        })
                    })
                    .fold(0.0, f64::max),
            );
        Some(Sor {
            pieces,
            open,
            bottom,
            top,
            radius: radius * 1.05,
        })
    }

    fn piece_at(&self, h: f64) -> Option<&Piece> {
        self.pieces.iter().find(|p| h >= p.low && h <= p.high)
    }

    /// Pushes the crossings of the line `origin + t direction`.
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        let (o, d) = (origin, direction);
        // Gathered first, so that the nearest crossings are kept when there are many.
        let mut crossings = [(0.0, 0u8); CROSSING_BUFFER];
        let mut count = 0;
        let mut record = |t: f64, part: u8| {
            if count < CROSSING_BUFFER {
                crossings[count] = (t, part);
                count += 1;
            }
        };
        if !self.open && d.y != 0.0 {
            for ((height, radius_squared), part) in [(self.bottom, BOTTOM_CAP), (self.top, TOP_CAP)]
            {
                let t = (height - o.y) / d.y;
                let (x, z) = (o.x + t * d.x, o.z + t * d.z);
                if x * x + z * z <= radius_squared {
                    record(t, part);
                }
            }
        }
        for piece in &self.pieces {
            let [a, b, c, e] = piece.coefficients;
            if d.y != 0.0 {
                // x(t)² + z(t)² - w(oy + t dy) = 0.
                let (q2, q1, q0) = (
                    d.x * d.x + d.z * d.z,
                    2.0 * (o.x * d.x + o.z * d.z),
                    o.x * o.x + o.z * o.z,
                );
                let (y0, y1) = (o.y, d.y);
                let cubic = [
                    -a * y1 * y1 * y1,
                    q2 - (3.0 * a * y0 * y1 * y1 + b * y1 * y1),
                    q1 - (3.0 * a * y0 * y0 * y1 + 2.0 * b * y0 * y1 + c * y1),
                    q0 - (((a * y0 + b) * y0 + c) * y0 + e),
                ];
                let first = (piece.low - o.y) / d.y;
                let second = (piece.high - o.y) / d.y;
                let mut found = [0.0; MAX_DEGREE];
                let count =
                    real_roots_between(&cubic, first.min(second), first.max(second), &mut found);
                for &t in &found[..count] {
                    record(t, SIDE);
                }
            } else if o.y >= piece.low && o.y < piece.high {
                let radius_squared = piece.radius_squared(o.y);
                let quadratic_a = d.x * d.x + d.z * d.z;
                let half_b = o.x * d.x + o.z * d.z;
                let constant = o.x * o.x + o.z * o.z - radius_squared;
                if let Some((near, far)) = solve_quadratic(quadratic_a, half_b, constant) {
                    record(near, SIDE);
                    if far != near {
                        record(far, SIDE);
                    }
                }
            }
        }
        roots.push_nearest(&mut crossings[..count]);
    }

    /// True when `point` is inside the solid.
    pub fn inside(&self, point: DVec3) -> bool {
        self.piece_at(point.y).is_some_and(|piece| {
            point.x * point.x + point.z * point.z < piece.radius_squared(point.y)
        })
    }

    /// POV-Ray's uv at the surface `point` of part `part` (measured): u the angle around Y
    /// from +x towards +z; on the side v is the height's place along the pieces (each piece
    /// an equal share), on the bottom cap the distance from the axis over the cap's radius,
    /// on the top cap one minus that.
    pub fn uv(&self, point: DVec3, part: u8) -> DVec2 {
        let u = super::uv::sphere_uv(DVec3::new(point.x, 0.0, point.z)).x;
        let radius = DVec2::new(point.x, point.z).length();
        let share_of_cap = |radius_squared: f64| {
            let cap = radius_squared.sqrt();
            if cap > 0.0 {
                (radius / cap).min(1.0)
            } else {
                0.0
            }
        };
        let v = match part {
            BOTTOM_CAP => share_of_cap(self.bottom.1),
            TOP_CAP => 1.0 - share_of_cap(self.top.1),
            _ => {
                let count = self.pieces.len() as f64;
                self.pieces
                    .iter()
                    .position(|piece| point.y >= piece.low && point.y <= piece.high)
                    .map_or(0.0, |index| {
                        let piece = &self.pieces[index];
                        let along = (point.y - piece.low) / (piece.high - piece.low);
                        (index as f64 + along.clamp(0.0, 1.0)) / count
                    })
            }
        };
        DVec2::new(u, v)
    }

    /// Outward normal at the surface `point` of part `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        match part {
            BOTTOM_CAP => -DVec3::Y,
            TOP_CAP => DVec3::Y,
            _ => {
                let slope = self.piece_at(point.y).map_or(0.0, |p| p.slope(point.y));
                DVec3::new(2.0 * point.x, -slope, 2.0 * point.z)
            }
        }
    }

    /// Bounds of the solid.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_points([
            DVec3::new(-self.radius, self.bottom.0, -self.radius),
            DVec3::new(self.radius, self.top.0, self.radius),
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_sor_is_a_cylinder() {
        let points = [
            DVec2::new(1.0, -1.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(1.0, 3.0),
        ];
        let sor = Sor::new(&points, false).unwrap();
        let mut roots = Roots::new();
        sor.intersect(DVec3::new(-5.0, 1.0, 0.0), DVec3::X, &mut roots);
        let mut found: Vec<f64> = roots.iter().map(|r| r.0).collect();
        found.sort_by(f64::total_cmp);
        assert_eq!(found.len(), 2);
        assert!((found[0] - 4.0).abs() < 1e-9 && (found[1] - 6.0).abs() < 1e-9);
        let mut roots = Roots::new();
        sor.intersect(DVec3::new(0.2, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert_eq!(roots.nearest_within(0.0, 10.0), Some((3.0, TOP_CAP)));
        assert!(sor.inside(DVec3::new(0.5, 1.0, 0.0)));
        assert!(!sor.inside(DVec3::new(0.5, 2.5, 0.0)));
        let open = Sor::new(&points, true).unwrap();
        let mut roots = Roots::new();
        open.intersect(DVec3::new(0.2, 5.0, 0.0), -DVec3::Y, &mut roots);
        assert_eq!(roots.iter().count(), 0);
        assert!(Sor::new(&points[..3], false).is_none());
        let n = sor.normal(DVec3::new(1.0, 1.0, 0.0), SIDE).normalize();
        assert!(n.abs_diff_eq(DVec3::X, 1e-9));
    }

    /// POV-Ray's bottle of objects/sor1.pov (its Glas6): where a ray along x meets the side
    /// (`trace` in POV-Ray 3.7 from x = -1, z = 0.0001), on segments whose radius changes fast.
    #[test]
    fn sor_radius_matches_povray() {
        let points = [
            (0.150754, 0.0),
            (0.150754, 0.0),
            (0.150754, 0.155779),
            (0.150754, 0.391960),
            (0.140704, 0.449749),
            (0.082915, 0.489950),
            (0.125628, 0.530151),
            (0.140704, 0.582915),
            (0.047739, 0.919598),
            (0.047739, 1.0),
            (0.0, 1.035176),
        ]
        .map(|(r, h)| DVec2::new(r, h));
        let sor = Sor::new(&points, true).unwrap();
        for (height, hit_depth) in [
            (0.21, 0.151081468),
            (0.46, 0.129063726),
            (0.61, 0.135016225),
            (0.91, 0.049987190),
            (0.96, 0.049643888),
        ] {
            let mut roots = Roots::new();
            sor.intersect(DVec3::new(-1.0, height, 0.0001), DVec3::X, &mut roots);
            let (t, _) = roots.nearest_within(0.0, 10.0).unwrap();
            assert!(
                (1.0 - t - hit_depth).abs() < 1e-8,
                "at {height}: {}",
                1.0 - t
            );
        }
    }
}
