//! `julia_fractal { <p> [quaternion|hypercomplex] [sqr|cube|exp|..|pwr(x, y)] max_iteration n
//! precision p slice <n>, d }`.
//!
//! In: the item stream after the brace. Out: [`Shape::JuliaFractal`] with POV-Ray's defaults
//! filled in (quaternion, sqr, max_iteration 20, precision 20, slice <0, 0, 0, 1>, 0).
//! Holds: as in POV-Ray, quaternions take only `sqr` and `cube` (checked once the whole
//! shape is read, since the algebra may follow the function), and a slice normal must be
//! non-zero with a non-zero fourth component; the stream is left at the object modifiers.

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::scene::{JuliaAlgebra, JuliaFractal, JuliaFunction, Shape};
use crate::syntax::ast::{Argument, Expr, Item};
use glam::{DVec2, DVec4};
use std::sync::Arc;

/// The function keywords without arguments.
fn function_named(name: &str) -> Option<JuliaFunction> {
    Some(match name {
        "sqr" => JuliaFunction::Sqr,
        "cube" => JuliaFunction::Cube,
        "exp" => JuliaFunction::Exp,
        "reciprocal" => JuliaFunction::Reciprocal,
        "sin" => JuliaFunction::Sin,
        "asin" => JuliaFunction::Asin,
        "sinh" => JuliaFunction::Sinh,
        "asinh" => JuliaFunction::Asinh,
        "cos" => JuliaFunction::Cos,
        "acos" => JuliaFunction::Acos,
        "cosh" => JuliaFunction::Cosh,
        "acosh" => JuliaFunction::Acosh,
        "tan" => JuliaFunction::Tan,
        "atan" => JuliaFunction::Atan,
        "tanh" => JuliaFunction::Tanh,
        "atanh" => JuliaFunction::Atanh,
        "ln" => JuliaFunction::Ln,
        _ => return None,
    })
}

impl Evaluator {
    /// Reads a julia fractal's parameter and settings.
    pub(crate) fn eval_julia_fractal(
        &mut self,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Shape> {
        let mut fractal = JuliaFractal {
            parameter: self.expect_vector4(stream, "the 4D julia parameter")?,
            ..JuliaFractal::default()
        };
        // Where the function was named, for the error when the algebra lacks it.
        let mut function_span = span;
        while let Some(item) = self.next_item(stream)? {
            match &item {
                Item::Keyword(word, keyword_span) => {
                    if let Some(function) = function_named(word) {
                        fractal.function = function;
                        function_span = *keyword_span;
                        continue;
                    }
                    match &**word {
                        "quaternion" => fractal.algebra = JuliaAlgebra::Quaternion,
                        "hypercomplex" => fractal.algebra = JuliaAlgebra::Hypercomplex,
                        "max_iteration" => {
                            let count = self.expect_float(stream, "the iteration count")?;
                            // POV-Ray reads an integer; a fraction is cut off.
                            fractal.max_iteration = count.clamp(0.0, u32::MAX as f64) as u32;
                        }
                        "precision" => {
                            fractal.precision = self.expect_float(stream, "the precision")?
                        }
                        "slice" => {
                            let normal = self.expect_vector4(stream, "the 4D slice normal")?;
                            let distance = self.expect_float(stream, "the slice distance")?;
                            if normal.length_squared() == 0.0 {
                                return Err(self
                                    .runtime
                                    .error(*keyword_span, "the slice normal is zero")
                                    .into());
                            }
                            if normal.w == 0.0 {
                                return Err(self
                                    .runtime
                                    .error(
                                        *keyword_span,
                                        "the slice normal needs a non-zero fourth component",
                                    )
                                    .into());
                            }
                            fractal.slice_normal = normal;
                            fractal.slice_distance = distance;
                        }
                        _ => {
                            stream.push_back(item);
                            break;
                        }
                    }
                }
                // Function names such as `sin` reach here as identifiers.
                Item::Expr(Expr::Ident(name, name_span)) if function_named(name).is_some() => {
                    fractal.function = function_named(name).unwrap_or(fractal.function);
                    function_span = *name_span;
                }
                Item::Expr(Expr::Call(call)) if &*call.name == "pwr" => {
                    let [Argument::Expr(real), Argument::Expr(imaginary)] = &call.arguments[..]
                    else {
                        return Err(self
                            .runtime
                            .error(call.span, "`pwr` takes two floats: pwr(x, y)")
                            .into());
                    };
                    self.run_directives_at(call, 0)?;
                    let real_part = self.eval_expr(real)?;
                    let real_part = self.to_float(real_part, real.span())?;
                    self.run_directives_at(call, 1)?;
                    let imaginary_part = self.eval_expr(imaginary)?;
                    let imaginary_part = self.to_float(imaginary_part, imaginary.span())?;
                    self.run_directives_at(call, 2)?;
                    fractal.function = JuliaFunction::Power(DVec2::new(real_part, imaginary_part));
                    function_span = call.span;
                }
                Item::Comma(_) => {}
                _ => {
                    stream.push_back(item);
                    break;
                }
            }
        }
        if fractal.algebra == JuliaAlgebra::Quaternion
            && !matches!(fractal.function, JuliaFunction::Sqr | JuliaFunction::Cube)
        {
            return Err(self
                .runtime
                .error(
                    function_span,
                    "quaternion julia fractals take only `sqr` or `cube`",
                )
                .with_label("needs `hypercomplex`")
                .into());
        }
        Ok(Shape::JuliaFractal(Arc::new(fractal)))
    }

    /// Reads a 4D vector (a float fills all four components; missing ones are zero).
    fn expect_vector4(&mut self, stream: &mut Stream, what: &str) -> EvalResult<DVec4> {
        let (value, span) = self.expect_value(stream, what)?;
        match value {
            Value::Float(f) => Ok(DVec4::splat(f)),
            Value::Vector(v) => Ok(DVec4::new(
                v.components[0],
                v.components[1],
                v.components[2],
                v.components[3],
            )),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected {what}, found {}", other.type_name()),
                )
                .with_label("must be a 4D vector")
                .into()),
        }
    }
}
