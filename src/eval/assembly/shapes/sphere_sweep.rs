//! `sphere_sweep { linear_spline | b_spline | cubic_spline N, <centre>, radius, .. [tolerance T] }`.
//!
//! In: the item stream after the brace. Out: [`Shape::SphereSweep`]. Holds: the sphere count
//! is checked against the spline's minimum (2 for linear, 4 for the cubic kinds) with a
//! spanned diagnostic; the stream is left at the object modifiers.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Shape, SphereSweep, SweepSpline};
use crate::syntax::ast::Item;
use std::sync::Arc;

/// Most spheres one sweep may list (guards huge allocations).
const SPHERE_LIMIT: f64 = 1e5;

impl Evaluator {
    /// Reads a sphere sweep's spline kind, spheres and tolerance.
    pub(crate) fn eval_sphere_sweep(
        &mut self,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Shape> {
        let spline = match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "linear_spline" => SweepSpline::Linear,
            Some(Item::Keyword(word, _)) if &*word == "b_spline" => SweepSpline::BSpline,
            Some(Item::Keyword(word, _)) if &*word == "cubic_spline" => SweepSpline::Cubic,
            other => {
                let at = other.as_ref().map_or(span, Item::span);
                return Err(self
                    .runtime
                    .error(at, "expected linear_spline, b_spline or cubic_spline")
                    .into());
            }
        };
        let count_span = self.peek_item(stream)?.as_ref().map_or(span, Item::span);
        let count = self.expect_float(stream, "the number of spheres")?;
        let minimum = if spline == SweepSpline::Linear {
            2.0
        } else {
            4.0
        };
        if !(minimum..=SPHERE_LIMIT).contains(&count) {
            return Err(self
                .runtime
                .error(
                    count_span,
                    format!("this sphere_sweep needs at least {minimum} spheres, found {count}"),
                )
                .into());
        }
        self.skip_comma(stream)?;
        let mut spheres = Vec::with_capacity((count as usize).min(1 << 20));
        for _ in 0..count as usize {
            let centre = self.expect_vector(stream, "a sphere's centre")?;
            self.skip_comma(stream)?;
            let radius = self.expect_float(stream, "a sphere's radius")?;
            self.skip_comma(stream)?;
            spheres.push((centre, radius));
        }
        let mut tolerance = 1e-6;
        match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "tolerance" => {
                tolerance = self.expect_float(stream, "the tolerance")?;
            }
            Some(other) => stream.push_back(other),
            None => {}
        }
        Ok(Shape::SphereSweep(Arc::new(SphereSweep {
            spline,
            spheres,
            tolerance,
        })))
    }
}
