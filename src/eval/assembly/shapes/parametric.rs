//! `parametric { function { .. } function { .. } function { .. } <u1, v1>, <u2, v2>
//! contained_by { .. } max_gradient accuracy precompute }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Parametric`] with the functions
//! compiled and POV-Ray's defaults filled in (container `box { -1, 1 }`, max_gradient 1.1,
//! accuracy 0.001). Holds: `precompute DEPTH, x, y, z` is read and ignored (it only speeds
//! POV-Ray up); the stream is left at the object modifiers.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{Container, Parametric, Shape};
use crate::syntax::ast::{BlockHead, Expr, Item};
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// Deepest `precompute` POV-Ray accepts.
const MAX_PRECOMPUTE_DEPTH: f64 = 20.0;

impl Evaluator {
    /// Reads a parametric surface's functions, uv rectangle and settings.
    pub(crate) fn eval_parametric(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let mut functions = Vec::with_capacity(3);
        while functions.len() < 3 {
            match self.next_item(stream)? {
                Some(Item::Comma(_)) => {}
                Some(Item::Expr(Expr::Function(literal))) => {
                    let function = self.compile_function(&literal)?;
                    if function.arity() > 3 {
                        return Err(self
                            .runtime
                            .error(literal.span, "a parametric's functions take u and v")
                            .with_label(format!("this one takes {} parameters", function.arity()))
                            .into());
                    }
                    functions.push(function);
                }
                other => {
                    let at = other.as_ref().map_or(span, Item::span);
                    return Err(self
                        .runtime
                        .error(at, "a parametric needs three functions, of x, y and z")
                        .into());
                }
            }
        }
        let uv_corner1 = self
            .expect_vector(stream, "the first uv corner")?
            .truncate();
        let uv_corner2 = self
            .expect_vector(stream, "the second uv corner")?
            .truncate();
        let mut container = Container::Box {
            corner1: DVec3::splat(-1.0),
            corner2: DVec3::splat(1.0),
        };
        let mut max_gradient = 1.1;
        let mut accuracy = 0.001;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "contained_by") =>
                {
                    container = self.eval_container(block.span, &block.body)?;
                }
                Item::Keyword(word, keyword_span) => match &**word {
                    "max_gradient" => {
                        max_gradient = self.expect_float(stream, "the maximum gradient")?
                    }
                    "accuracy" => accuracy = self.expect_float(stream, "the accuracy")?,
                    "precompute" => self.skip_precompute(*keyword_span, stream)?,
                    _ => {
                        stream.push_back(item);
                        break;
                    }
                },
                Item::Comma(_) => {}
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        if !(accuracy > 0.0 && max_gradient > 0.0) {
            return Err(self
                .runtime
                .error(span, "accuracy and max_gradient must be positive")
                .into());
        }
        if uv_corner1.x == uv_corner2.x || uv_corner1.y == uv_corner2.y {
            // povray renders nothing there (a scene's `<0, 0>, <2*pi, pi*clock>` at clock 0).
            self.runtime.warn(
                span,
                "the uv rectangle of this parametric has no area: it shows nothing",
            );
            return Ok(Shape::Csg {
                operation: crate::scene::CsgOperation::Union,
                children: Vec::new(),
            });
        }
        let [x, y, z]: [_; 3] = functions
            .try_into()
            .unwrap_or_else(|_| unreachable!("three functions were read"));
        Ok(Shape::Parametric(Arc::new(Parametric {
            functions: [x, y, z],
            uv_corner1: DVec2::new(uv_corner1.x, uv_corner1.y),
            uv_corner2: DVec2::new(uv_corner2.x, uv_corner2.y),
            container,
            max_gradient,
            accuracy,
        })))
    }

    /// `precompute DEPTH, x, y, z` (any of the three axes): checked and skipped.
    fn skip_precompute(&mut self, span: Span, stream: &mut Stream) -> EvalResult<()> {
        let depth = self.expect_float(stream, "the precompute depth")?;
        if !(0.0..=MAX_PRECOMPUTE_DEPTH).contains(&depth) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("precompute depth must be 0 to {MAX_PRECOMPUTE_DEPTH}, found {depth}"),
                )
                .into());
        }
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Comma(_) => {}
                Item::Expr(Expr::Ident(name, _)) if matches!(&**name, "x" | "y" | "z") => {}
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        Ok(())
    }
}
