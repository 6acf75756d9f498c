//! `ovus { bottom_radius, top_radius }` and
//! `lemon { base, base_radius, cap, cap_radius, inner_radius [open] }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Ovus`] or [`Shape::Lemon`]. Holds: a
//! lemon whose arc cannot join its rims gets a spanned diagnostic; the stream is left at the
//! object modifiers (`open` among them).

use super::super::stream::Stream;
use super::super::{EvalResult, Evaluator};
use crate::diag::Span;
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
                .error(span, "a lemon's base and cap points must differ")
                .into());
        }
        if base_radius < 0.0 || cap_radius < 0.0 {
            return Err(self
                .error(span, "a lemon's base and cap radii must not be negative")
                .into());
        }
        let length = base.distance(cap);
        let half_chord = 0.5 * (length * length + (base_radius - cap_radius).powi(2)).sqrt();
        if inner_radius.is_nan() || inner_radius < half_chord {
            return Err(self
                .error(
                    span,
                    format!(
                        "a lemon's inner radius must be at least {half_chord}, found {inner_radius}"
                    ),
                )
                .with_label("half the distance between the base rim and the cap rim")
                .into());
        }
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
