//! `bicubic_patch { type 0|1 [flatness F] [u_steps U] [v_steps V] <16 points> }`.
//!
//! In: the item stream after the brace. Out: a [`Shape::Mesh`] of smooth triangles: the Bézier
//! patch split into 2^u_steps by 2^v_steps pieces, each piece two triangles through its
//! corners on the surface with the surface's exact normals there. Holds: both types give
//! the same surface; with a `flatness`, the split goes on evenly (up to 2^6 pieces a side)
//! until every piece is that flat, where POV-Ray splits only the curved parts; each corner
//! carries its uv: the patch parameters mapped onto the `uv_vectors` corners.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Mesh, MeshTriangle, Shape};
use crate::syntax::ast::Item;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// Largest u_steps or v_steps (2^8 pieces per side is far beyond any visible difference).
const MAX_STEPS: f64 = 8.0;
/// Most steps a `flatness` test may split to.
const FLAT_STEPS: u32 = 6;

impl Evaluator {
    /// Reads a bicubic patch and triangulates it.
    pub(crate) fn eval_bicubic_patch(
        &mut self,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Shape> {
        let mut u_steps = 0.0;
        let mut v_steps = 0.0;
        let mut patch_type = None;
        let mut flatness = 0.0;
        let mut corner_uvs = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        let mut points = Vec::with_capacity(16);
        while points.len() < 16 {
            let Some(item) = self.next_item(stream)? else {
                break;
            };
            match &item {
                Item::Keyword(word, keyword_span) => match &**word {
                    "type" => {
                        let value = self.expect_float(stream, "the patch type")?;
                        if value != 0.0 && value != 1.0 {
                            return Err(self
                                .runtime
                                .error(
                                    *keyword_span,
                                    format!("patch type must be 0 or 1, found {value}"),
                                )
                                .into());
                        }
                        patch_type = Some(value);
                    }
                    "flatness" => {
                        flatness = self.expect_float(stream, "the flatness")?;
                    }
                    "uv_vectors" => corner_uvs = self.patch_uv_vectors(stream)?,
                    "u_steps" | "v_steps" => {
                        let value = self.expect_float(stream, "the number of steps")?.floor();
                        let steps = value.clamp(0.0, MAX_STEPS);
                        if &**word == "u_steps" {
                            u_steps = steps;
                        } else {
                            v_steps = steps;
                        }
                    }
                    _ => {
                        stream.push_back(item);
                        break;
                    }
                },
                Item::Comma(_) => {}
                _ => {
                    stream.push_back(item);
                    points.push(self.expect_vector(stream, "a control point")?);
                }
            }
        }
        if patch_type.is_none() {
            return Err(self
                .runtime
                .error(span, "a bicubic_patch needs `type 0` or `type 1`")
                .into());
        }
        let Ok(controls) = <[DVec3; 16]>::try_from(points.as_slice()) else {
            return Err(self
                .runtime
                .error(
                    span,
                    format!(
                        "a bicubic_patch needs 16 control points, found {}",
                        points.len()
                    ),
                )
                .into());
        };
        match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "uv_vectors" => {
                corner_uvs = self.patch_uv_vectors(stream)?;
            }
            Some(other) => stream.push_back(other),
            None => {}
        }
        let (mut u_steps, mut v_steps) = (u_steps as u32, v_steps as u32);
        // With a flatness, POV-Ray keeps splitting curved parts past the steps given.
        while flatness > 0.0
            && (u_steps < FLAT_STEPS || v_steps < FLAT_STEPS)
            && !flat_enough(&controls, 1 << u_steps, 1 << v_steps, flatness)
        {
            u_steps = (u_steps + 1).min(FLAT_STEPS.max(u_steps));
            v_steps = (v_steps + 1).min(FLAT_STEPS.max(v_steps));
        }
        let (triangles, triangle_uvs) = triangulate(&controls, 1 << u_steps, 1 << v_steps);
        let mut mesh = Mesh::from_triangles(&triangles);
        mesh.ignores_clipped_by = true;
        // Each corner's uv: the patch parameters mapped bilinearly onto the uv_vectors.
        for [s_t_a, s_t_b, s_t_c] in triangle_uvs {
            let first = mesh.uvs.len() as u32;
            mesh.uvs
                .extend([s_t_a, s_t_b, s_t_c].map(|at| bilinear(&corner_uvs, at)));
            mesh.face_uvs.push([first, first + 1, first + 2]);
        }
        Ok(Shape::Mesh(Arc::new(mesh)))
    }

    /// The four uv corners after `uv_vectors`.
    fn patch_uv_vectors(&mut self, stream: &mut Stream) -> EvalResult<[DVec2; 4]> {
        let mut corners = [DVec2::ZERO; 4];
        for corner in &mut corners {
            let vector = self.expect_vector(stream, "a uv vector")?;
            *corner = DVec2::new(vector.x, vector.y);
            self.skip_comma(stream)?;
        }
        Ok(corners)
    }
}

/// Bernstein weights of degree 3 at `t`, and their derivatives.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    (
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
        [
            -3.0 * s * s,
            3.0 * s * s - 6.0 * t * s,
            6.0 * t * s - 3.0 * t * t,
            3.0 * t * t,
        ],
    )
}

/// The patch point and its normal (`∂P/∂u × ∂P/∂v`, any length) at (u, v); control point
/// `controls[4 * row + column]` has u along the columns and v along the rows.
fn evaluate(controls: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let mut point = DVec3::ZERO;
    let mut along_u = DVec3::ZERO;
    let mut along_v = DVec3::ZERO;
    for row in 0..4 {
        for column in 0..4 {
            let control = controls[4 * row + column];
            point += control * (bu[column] * bv[row]);
            along_u += control * (du[column] * bv[row]);
            along_v += control * (bu[column] * dv[row]);
        }
    }
    (point, along_u.cross(along_v))
}

/// True when every piece of a `columns` by `rows` split is within `flatness` of the flat
/// quadrilateral through its corners (checked at its centre and edge midpoints).
fn flat_enough(controls: &[DVec3; 16], columns: usize, rows: usize, flatness: f64) -> bool {
    let point = |u: f64, v: f64| evaluate(controls, u, v).0;
    (0..rows).all(|row| {
        (0..columns).all(|column| {
            let (u0, u1) = (
                column as f64 / columns as f64,
                (column + 1) as f64 / columns as f64,
            );
            let (v0, v1) = (row as f64 / rows as f64, (row + 1) as f64 / rows as f64);
            let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
            let [a, b, c, d] = [point(u0, v0), point(u1, v0), point(u1, v1), point(u0, v1)];
            [
                (point(um, vm), (a + b + c + d) * 0.25),
                (point(um, v0), (a + b) * 0.5),
                (point(u1, vm), (b + c) * 0.5),
                (point(um, v1), (c + d) * 0.5),
                (point(u0, vm), (d + a) * 0.5),
            ]
            .iter()
            .all(|(surface, flat)| surface.distance(*flat) <= flatness)
        })
    })
}

/// The uv at patch parameters `at` (s along a row of control points, t across rows) from the
/// uv of the patch corners, in POV-Ray's order: (0, 0), (1, 0), (1, 1), (0, 1).
fn bilinear(corners: &[DVec2; 4], at: DVec2) -> DVec2 {
    let bottom = corners[0].lerp(corners[1], at.x);
    let top = corners[3].lerp(corners[2], at.x);
    bottom.lerp(top, at.y)
}

/// Two smooth triangles for each of `columns` by `rows` pieces of the patch, with the patch
/// parameters (s, t) of each triangle's corners.
fn triangulate(
    controls: &[DVec3; 16],
    columns: usize,
    rows: usize,
) -> (Vec<MeshTriangle>, Vec<[DVec2; 3]>) {
    let mut grid = Vec::with_capacity((columns + 1) * (rows + 1));
    for row in 0..=rows {
        for column in 0..=columns {
            grid.push(evaluate(
                controls,
                column as f64 / columns as f64,
                row as f64 / rows as f64,
            ));
        }
    }
    let at = |column: usize, row: usize| grid[row * (columns + 1) + column];
    let parameters = |column: usize, row: usize| {
        DVec2::new(column as f64 / columns as f64, row as f64 / rows as f64)
    };
    let mut triangles = Vec::with_capacity(2 * columns * rows);
    let mut triangle_uvs = Vec::with_capacity(2 * columns * rows);
    for row in 0..rows {
        for column in 0..columns {
            let corners = [
                at(column, row),
                at(column + 1, row),
                at(column + 1, row + 1),
                at(column, row + 1),
            ];
            let corner_parameters = [
                parameters(column, row),
                parameters(column + 1, row),
                parameters(column + 1, row + 1),
                parameters(column, row + 1),
            ];
            for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
                let (pa, pb, pc) = (corners[a].0, corners[b].0, corners[c].0);
                let face = (pb - pa).cross(pc - pa);
                let normal = |n: DVec3| {
                    n.try_normalize()
                        .or_else(|| face.try_normalize())
                        .unwrap_or(DVec3::Y)
                };
                triangle_uvs.push([
                    corner_parameters[a],
                    corner_parameters[b],
                    corner_parameters[c],
                ]);
                triangles.push(MeshTriangle {
                    corners: [pa, pb, pc],
                    normals: Some([
                        normal(corners[a].1),
                        normal(corners[b].1),
                        normal(corners[c].1),
                    ]),
                });
            }
        }
    }
    (triangles, triangle_uvs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat patch over the unit square in x/z.
    fn flat() -> [DVec3; 16] {
        std::array::from_fn(|index| {
            DVec3::new((index % 4) as f64 / 3.0, 0.0, (index / 4) as f64 / 3.0)
        })
    }

    #[test]
    fn corners_are_on_the_patch() {
        let controls = flat();
        assert_eq!(evaluate(&controls, 0.0, 0.0).0, controls[0]);
        assert_eq!(evaluate(&controls, 1.0, 1.0).0, controls[15]);
        let (middle, normal) = evaluate(&controls, 0.5, 0.5);
        assert!((middle - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-12);
        assert!(normal.normalize().abs().abs_diff_eq(DVec3::Y, 1e-12));
    }

    #[test]
    fn steps_give_two_triangles_per_piece() {
        assert_eq!(triangulate(&flat(), 8, 4).0.len(), 64);
        assert_eq!(triangulate(&flat(), 1, 1).0.len(), 2);
        let at = DVec2::new(0.25, 0.5);
        let corners = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        assert_eq!(bilinear(&corners, at), at);
    }
}
