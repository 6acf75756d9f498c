//! `isosurface { function { .. } contained_by { .. } threshold accuracy max_gradient evaluate
//! open max_trace all_intersections }`.
//!
//! In: the item stream after the brace. Out: [`Shape::Isosurface`] with the function
//! compiled and POV-Ray's defaults filled in (container `box { -1, 1 }`, threshold 0,
//! accuracy 0.001, max_gradient 1.1, max_trace 1). Holds: `evaluate` is read and ignored
//! (durer keeps max_gradient fixed), with a warning; the stream is left at the modifiers.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::geometry::MAX_CROSSINGS;
use crate::scene::{Container, Isosurface, Shape};
use crate::syntax::ast::{BlockHead, Item};
use glam::DVec3;
use std::sync::Arc;

impl Evaluator {
    /// Reads an isosurface's function and settings.
    pub(crate) fn eval_isosurface(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Shape> {
        let mut function = None;
        let mut container = Container::Box {
            corner1: DVec3::splat(-1.0),
            corner2: DVec3::splat(1.0),
        };
        let mut threshold = 0.0;
        let mut accuracy = 0.001;
        let mut max_gradient = 1.1;
        let mut open = false;
        let mut max_trace = 1;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Expr(crate::syntax::ast::Expr::Function(literal)) => {
                    function = Some(self.compile_function(literal)?);
                }
                Item::Block(block) if matches!(&block.head, BlockHead::Word(w) if &**w == "contained_by") =>
                {
                    container = self.eval_container(block.span, &block.body)?;
                }
                Item::Keyword(word, keyword_span) => match &**word {
                    "threshold" => threshold = self.expect_float(stream, "the threshold")?,
                    "accuracy" => accuracy = self.expect_float(stream, "the accuracy")?,
                    "max_gradient" => {
                        max_gradient = self.expect_float(stream, "the maximum gradient")?
                    }
                    "open" => open = true,
                    "all_intersections" => max_trace = MAX_CROSSINGS,
                    "max_trace" => {
                        let count = self.expect_float(stream, "the number of crossings")?;
                        max_trace = count.clamp(1.0, MAX_CROSSINGS as f64) as usize;
                    }
                    "evaluate" => {
                        for what in [
                            "the minimum factor",
                            "the maximum factor",
                            "the attenuation",
                        ] {
                            self.expect_float(stream, what)?;
                            self.skip_comma(stream)?;
                        }
                        self.runtime.warn(
                            *keyword_span,
                            "`evaluate` is ignored: durer keeps max_gradient fixed",
                        );
                    }
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
        let Some(function) = function else {
            return Err(self
                .runtime
                .error(span, "an isosurface needs `function { .. }`")
                .into());
        };
        if function.arity() != 3 {
            return Err(self
                .runtime
                .error(span, "an isosurface's function must take x, y and z")
                .with_label(format!("this one takes {} parameters", function.arity()))
                .into());
        }
        if !(accuracy > 0.0 && max_gradient > 0.0) {
            return Err(self
                .runtime
                .error(span, "accuracy and max_gradient must be positive")
                .into());
        }
        Ok(Shape::Isosurface(Arc::new(Isosurface {
            function,
            container,
            threshold,
            accuracy,
            max_gradient,
            open,
            max_trace,
        })))
    }

    /// `contained_by { box { .. } }` or `contained_by { sphere { .. } }`.
    pub(crate) fn eval_container(
        &mut self,
        span: Span,
        body: &std::rc::Rc<[Item]>,
    ) -> EvalResult<Container> {
        let mut body = Stream::new(body.clone());
        let (value, value_span) = self.expect_value(&mut body, "a box or a sphere")?;
        let shape = match value {
            Value::Object(object) => object.shape.clone(),
            other => {
                return Err(self
                    .runtime
                    .error(
                        value_span,
                        format!("expected a box or a sphere, found {}", other.type_name()),
                    )
                    .into())
            }
        };
        match shape {
            Shape::Box { corner1, corner2 } => Ok(Container::Box { corner1, corner2 }),
            Shape::Sphere { centre, radius } => Ok(Container::Sphere { centre, radius }),
            _ => Err(self
                .runtime
                .error(span, "contained_by takes a box or a sphere")
                .into()),
        }
    }
}
