//! `ovus { bottom_radius, top_radius }` and
//! `lemon { base, base_radius, cap, cap_radius, inner_radius [open] }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Ovus`] or [`Shape::Lemon`]. Holds: a
//! lemon's inner radius too small to bulge outwards is raised, with a warning, to the radius
//! whose arc centre lies on the axis; the stream is left at the
//! object modifiers (`open` among them).

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::geometry::lemon_smallest_inner_radius;
use crate::scene::{Lemon, Shape};
use std::sync::Arc;

impl Evaluator {
    /// Reads an ovus's two radii.
    pub(crate) fn eval_ovus(&mut self, stream: &mut Stream) -> EvalResult<Shape> {
        let bottom_radius = self.expect_float(stream, "the bottom radius")?;
        let top_radius = self.expect_float(stream, "the top radius")?;
        Ok(Shape::Ovus {
            bottom_radius,
            top_radius,
        })
    }

    /// Reads a lemon's rims and arc radius.
    pub(crate) fn eval_lemon(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let base = self.expect_vector(stream, "the base point")?;
        let base_radius = self.expect_float(stream, "the base radius")?;
        let cap = self.expect_vector(stream, "the cap point")?;
        let cap_radius = self.expect_float(stream, "the cap radius")?;
        let inner_radius = self.expect_float(stream, "the inner radius")?;
        if base == cap {
            return Err(self
                .runtime
                .error(span, "a lemon's base and cap points must differ")
                .into());
        }
        if base_radius < 0.0 || cap_radius < 0.0 {
            return Err(self
                .runtime
                .error(span, "a lemon's base and cap radii must not be negative")
                .into());
        }
        if !inner_radius.is_finite() {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("a lemon's inner radius must be finite, found {inner_radius}"),
                )
                .into());
        }
        let length = base.distance(cap);
        let smallest = lemon_smallest_inner_radius(base_radius, cap_radius, length);
        let inner_radius = if inner_radius < smallest {
            // POV-Ray 3.7.1 warns and raises the radius likewise.
            self.runtime.warn(
                span,
                format!(
                    "a lemon's inner radius {inner_radius} is too small to bulge outwards; \
                     using {smallest}, the radius whose centre lies on the axis"
                ),
            );
            smallest
        } else {
            inner_radius
        };
        Ok(Shape::Lemon(Arc::new(Lemon {
            base,
            base_radius,
            cap,
            cap_radius,
            inner_radius,
            open: false,
        })))
    }
}
