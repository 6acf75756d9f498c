//! Splines: `spline { [kind] t, <point> ... }` blocks and calls `S(t [, kind])`.
//!
//! In: a spline block's items (or a call's arguments). Out: a [`Spline`] value, or the point
//! at a parameter. Holds: points are sorted by parameter, a repeated parameter replaces its
//! point (POV-Ray's exception: see [`Spline::insert`]); values match what POV-Ray 3.7 prints
//! for every kind, inside and outside the range.

use super::stream::Stream;
use super::value::{Value, Vector};
use crate::diag::Span;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Argument, Call, Expr, Item};
use std::rc::Rc;

pub use crate::texture::function::spline::{Spline, SplineKind};

impl Evaluator {
    /// Evaluates the body of a `spline { ... }` block.
    pub(crate) fn eval_spline(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Value> {
        let mut spline = Spline::new(SplineKind::Linear);
        while let Some(item) = self.next_item(stream)? {
            match item {
                Item::Comma(_) => {}
                Item::Keyword(word, word_span) => match SplineKind::from_keyword(&word) {
                    Some(kind) => spline.kind = kind,
                    None => {
                        return Err(self
                            .runtime
                            .error(
                                word_span,
                                format!("`{word}` is not allowed inside `spline`"),
                            )
                            .with_label("expected a spline kind, a parameter or a point")
                            .into())
                    }
                },
                other => {
                    let item_span = other.span();
                    let value = self.item_value(&other)?;
                    if let Value::Spline(base) = value {
                        // A spline identifier copies that spline (its kind and points).
                        spline = (*base).clone();
                        continue;
                    }
                    let t = self.to_float(value, item_span)?;
                    let (point, point_span) = self.expect_value(stream, "a spline point")?;
                    let (components, len) = spline_point(self, point, point_span)?;
                    spline.insert(t, components, len);
                }
            }
        }
        if spline.is_empty() {
            return Err(self
                .runtime
                .error(span, "a spline needs at least one point")
                .with_label("this spline has none")
                .with_help("write parameter and point pairs: `spline { 0, <0,0,0> 1, <1,2,0> }`")
                .into());
        }
        Ok(Value::Spline(Rc::new(spline)))
    }
}

/// The components of a spline point and how many are used (a float counts as two equal
/// components, as in POV-Ray).
fn spline_point(ev: &Evaluator, value: Value, span: Span) -> EvalResult<([f64; 5], u8)> {
    match value {
        Value::Float(f) => Ok(([f, f, 0.0, 0.0, 0.0], 2)),
        Value::Vector(v) => Ok((v.components, v.len.max(2))),
        Value::Colour(c) => Ok((c.to_array(), 5)),
        other => Err(ev
            .runtime
            .error(
                span,
                format!(
                    "expected a spline point (a vector), found {}",
                    other.type_name()
                ),
            )
            .with_label("not a point")
            .into()),
    }
}

/// Evaluates `S(t)` or `S(t, kind)` for a spline value.
pub(crate) fn call_spline(ev: &mut Evaluator, spline: &Spline, call: &Call) -> EvalResult<Value> {
    if !(1..=2).contains(&call.arguments.len()) {
        return Err(ev
            .runtime
            .error(
                call.span,
                format!(
                    "spline `{}` takes a parameter and an optional spline kind, found {} arguments",
                    call.name,
                    call.arguments.len()
                ),
            )
            .with_label("called here")
            .into());
    }
    let t = ev.argument_float(call, 0)?;
    let kind = match call.arguments.get(1) {
        None => spline.kind,
        Some(argument) => {
            let named = match argument {
                Argument::Expr(Expr::Ident(word, _)) => SplineKind::from_keyword(word),
                _ => None,
            };
            named.ok_or_else(|| {
                ev.runtime
                    .error(argument.span(), "expected a spline kind")
                    .with_label(
                        "not one of linear_spline, quadratic_spline, cubic_spline, natural_spline",
                    )
            })?
        }
    };
    let point = spline.evaluate(t, kind);
    let len = usize::from(spline.components);
    Ok(Value::Vector(Vector::from_slice(&point[..len])))
}
