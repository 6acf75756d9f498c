//! Expression evaluation: arithmetic with POV-Ray's float/vector/colour promotion, member
//! access, built-in constants and functions.

use super::stream::array_offset;
use super::value::{Value, Vector};
use crate::diag::Span;
use crate::eval::{EvalResult, Evaluator};
use crate::math::Colour;
use crate::syntax::ast::{BinaryOp, Call, Expr, Item, UnaryOp};
use crate::syntax::symbol::Symbol;
use glam::DVec3;
use std::rc::Rc;

/// Tolerance POV-Ray uses for `=` and `!=` on floats.
const EQUALITY_EPSILON: f64 = 1e-10;

impl Evaluator {
    /// The value of an item in value position: an expression or a block.
    pub(crate) fn item_value(&mut self, item: &Item) -> EvalResult<Value> {
        match item {
            Item::Expr(expr) => self.eval_expr(expr),
            Item::Block(block) => self.eval_block(block),
            Item::Directive(directive) => self.directive_value(directive),
            other => Err(self
                .runtime
                .error(other.span(), "expected a value")
                .with_label("not a value")
                .into()),
        }
    }

    /// A directive used where a value is expected (`#declare A = #if (..) 1 #else 2 #end`).
    fn directive_value(
        &mut self,
        directive: &Rc<crate::syntax::ast::Directive>,
    ) -> EvalResult<Value> {
        let items: Rc<[Item]> = Rc::from(vec![Item::Directive(directive.clone())]);
        let mut stream = super::stream::Stream::new(items);
        let mut result = None;
        while let Some(item) = self.next_item(&mut stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let value = self.item_value(&item)?;
            if result.is_none() {
                result = Some(value);
            }
        }
        result.ok_or_else(|| {
            self.runtime
                .error(directive.span, "this directive yields no value")
                .into()
        })
    }

    /// Evaluates an expression.
    pub(crate) fn eval_expr(&mut self, expr: &Expr) -> EvalResult<Value> {
        match expr {
            Expr::Number(n, _) => Ok(Value::Float(*n)),
            Expr::String(s, _) => Ok(Value::String(s.clone())),
            Expr::Vector(elements, span) => {
                if elements.len() < 2 || elements.len() > 5 {
                    return Err(self
                        .runtime
                        .error(
                            *span,
                            format!("a vector has 2 to 5 components, found {}", elements.len()),
                        )
                        .into());
                }
                let mut components = [0.0; 5];
                for (component, e) in components.iter_mut().zip(elements.iter()) {
                    *component = self.eval_float(e)?;
                }
                Ok(Value::Vector(Vector::from_slice(
                    &components[..elements.len()],
                )))
            }
            Expr::Ident(name, span) => self.eval_ident(name, *span),
            Expr::Call(call) => self.eval_call(call),
            Expr::Unary(op, operand, span) => {
                let value = self.eval_expr(operand)?;
                match op {
                    UnaryOp::Plus => Ok(value),
                    UnaryOp::Negate => self.map_numeric(value, *span, |v| -v),
                    UnaryOp::Not => {
                        let f = self.to_float(value, operand.span())?;
                        Ok(Value::Float(if f == 0.0 { 1.0 } else { 0.0 }))
                    }
                }
            }
            Expr::Binary(op, lhs, rhs, span) => {
                let a = self.eval_expr(lhs)?;
                let b = self.eval_expr(rhs)?;
                self.binary(*op, a, b, *span)
            }
            Expr::Conditional(parts, _) => {
                let (condition, a, b) = &**parts;
                if self.eval_condition(condition)? {
                    self.eval_expr(a)
                } else {
                    self.eval_expr(b)
                }
            }
            Expr::Member(base, member, span) => {
                let value = self.eval_expr(base)?;
                self.member(value, member, *span)
            }
            Expr::Index(base, index, span) => {
                let mut indices = vec![self.eval_float(index)?];
                let mut root = &**base;
                while let Expr::Index(inner, index, _) = root {
                    indices.push(self.eval_float(index)?);
                    root = inner;
                }
                indices.reverse();
                let value = self.eval_expr(root)?;
                let Value::Array(array) = value else {
                    return Err(self
                        .runtime
                        .error(
                            root.span(),
                            format!("expected an array, found {}", value.type_name()),
                        )
                        .with_label("indexed here")
                        .into());
                };
                let Some(offset) = array_offset(&array.sizes, &indices) else {
                    let shown: Vec<String> =
                        indices.iter().map(|i| format!("{}", i.trunc())).collect();
                    let sizes: Vec<String> = array.sizes.iter().map(|s| s.to_string()).collect();
                    return Err(self
                        .runtime
                        .error(
                            *span,
                            format!("array index [{}] out of range", shown.join("][")),
                        )
                        .with_label(format!("the array's size is [{}]", sizes.join("][")))
                        .into());
                };
                match &array.elements[offset] {
                    Some(v) => Ok(v.clone()),
                    None => Err(self
                        .runtime
                        .error(*span, "array element used before it was assigned")
                        .with_label("not assigned")
                        .into()),
                }
            }
            Expr::Colour(literal) => self.eval_colour_literal(literal),
            Expr::Array(literal) => self.eval_array(literal),
            Expr::Function(function) => self.function_value(function),
            Expr::Directive(directive) => self.directive_value(directive),
        }
    }

    /// Evaluates an expression that must be a float.
    pub(crate) fn eval_float(&mut self, expr: &Expr) -> EvalResult<f64> {
        let value = self.eval_expr(expr)?;
        self.to_float(value, expr.span())
    }

    /// Evaluates an expression that must be a string.
    pub(crate) fn eval_string(&mut self, expr: &Expr) -> EvalResult<Rc<str>> {
        match self.eval_expr(expr)? {
            Value::String(s) => Ok(s),
            other => Err(self
                .runtime
                .error(
                    expr.span(),
                    format!("expected a string, found {}", other.type_name()),
                )
                .into()),
        }
    }

    /// Converts a value to a float, or explains which type was found.
    pub(crate) fn to_float(&self, value: Value, span: Span) -> EvalResult<f64> {
        match value {
            Value::Float(f) => Ok(f),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected a float, found {}", other.type_name()),
                )
                .with_label("must be a float")
                .into()),
        }
    }

    /// Converts a value to a 3-vector (floats promote to all three components).
    pub(crate) fn to_vector3(&self, value: Value, span: Span) -> EvalResult<DVec3> {
        match value {
            Value::Float(f) => Ok(DVec3::splat(f)),
            Value::Vector(v) => Ok(v.to_dvec3()),
            Value::Colour(c) => Ok(c.rgb_vec()),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected a vector, found {}", other.type_name()),
                )
                .with_label("must be a vector")
                .into()),
        }
    }

    /// Converts a value to a colour (a float fills all five components, as POV-Ray does).
    pub(crate) fn to_colour(&self, value: Value, span: Span) -> EvalResult<Colour> {
        match value {
            Value::Colour(c) => Ok(c),
            Value::Float(f) => Ok(Colour::rgbft(f, f, f, f, f)),
            Value::Vector(v) => {
                let c = v.components;
                Ok(Colour::rgbft(c[0], c[1], c[2], c[3], c[4]))
            }
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected a colour, found {}", other.type_name()),
                )
                .with_label("must be a colour")
                .into()),
        }
    }

    /// Whether a name is a built-in constant (not a variable).
    pub(crate) fn is_builtin_name(&self, name: &str) -> bool {
        builtin_constant(name, self).is_some()
    }

    fn eval_ident(&mut self, name: &Symbol, span: Span) -> EvalResult<Value> {
        if let Some(value) = self.runtime.lookup(*name) {
            return Ok(value.clone());
        }
        if let Some(value) = builtin_constant(name, self) {
            return Ok(value);
        }
        Err(self.runtime.undefined(name, span).into())
    }

    fn map_numeric(&self, value: Value, span: Span, f: impl Fn(f64) -> f64) -> EvalResult<Value> {
        match value {
            Value::Float(x) => Ok(Value::Float(f(x))),
            Value::Vector(mut v) => {
                for c in v.components.iter_mut().take(v.len as usize) {
                    *c = f(*c);
                }
                Ok(Value::Vector(v))
            }
            Value::Colour(c) => Ok(Value::Colour(Colour::from_array(c.to_array().map(&f)))),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("cannot do arithmetic on {}", other.type_name()),
                )
                .into()),
        }
    }

    /// Applies a binary operator with POV-Ray's promotion rules.
    pub(crate) fn binary(&self, op: BinaryOp, a: Value, b: Value, span: Span) -> EvalResult<Value> {
        use BinaryOp::*;
        if let (Value::String(x), Value::String(y)) = (&a, &b) {
            let ordering = x.cmp(y);
            let result = match op {
                Less => ordering.is_lt(),
                LessEqual => ordering.is_le(),
                Equal => ordering.is_eq(),
                NotEqual => ordering.is_ne(),
                GreaterEqual => ordering.is_ge(),
                Greater => ordering.is_gt(),
                _ => {
                    return Err(self
                        .runtime
                        .error(
                            span,
                            format!("operator `{}` cannot combine two strings", op.symbol()),
                        )
                        .with_help("use concat(a, b) to join strings")
                        .into())
                }
            };
            return Ok(Value::Float(f64::from(result)));
        }
        if matches!(
            op,
            Less | LessEqual | Equal | NotEqual | GreaterEqual | Greater | And | Or
        ) {
            let x = self.to_float(a, span)?;
            let y = self.to_float(b, span)?;
            let result = match op {
                Less => x < y,
                // POV-Ray's `<=` and `>=` accept a difference below the epsilon, like `=`.
                // A difference that is no number (infinity minus infinity) counts as equal,
                // as in POV-Ray (measured: with K = 5/0, K = K, K <= K and K >= K are 1,
                // K != K is 0).
                LessEqual => (x - y).is_nan() || x - y < EQUALITY_EPSILON,
                Equal => (x - y).is_nan() || (x - y).abs() < EQUALITY_EPSILON,
                NotEqual => (x - y).abs() >= EQUALITY_EPSILON,
                GreaterEqual => (y - x).is_nan() || y - x < EQUALITY_EPSILON,
                Greater => x > y,
                And => x != 0.0 && y != 0.0,
                _ => x != 0.0 || y != 0.0,
            };
            return Ok(Value::Float(f64::from(result)));
        }
        let numeric =
            |v: &Value| matches!(v, Value::Float(_) | Value::Vector(_) | Value::Colour(_));
        if !numeric(&a) || !numeric(&b) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!(
                        "operator `{}` cannot combine {} and {}",
                        op.symbol(),
                        a.type_name(),
                        b.type_name()
                    ),
                )
                .with_label(format!("{} met {}", a.type_name(), b.type_name()))
                .into());
        }
        // Dividing by zero gives positive infinity whatever the numerator (POV-Ray warns
        // "Divide by zero" and goes on; measured: 5/0, -5/0 and 0/0 all print inf, as do the
        // components of <5,-5,0>/0).
        let apply = |x: f64, y: f64| match op {
            Add => x + y,
            Subtract => x - y,
            Multiply => x * y,
            _ if y == 0.0 => f64::INFINITY,
            _ => x / y,
        };
        match (&a, &b) {
            (Value::Float(x), Value::Float(y)) => Ok(Value::Float(apply(*x, *y))),
            (Value::Colour(_), _) | (_, Value::Colour(_)) => {
                let x = self.to_colour(a.clone(), span)?.to_array();
                let y = self.to_colour(b.clone(), span)?.to_array();
                Ok(Value::Colour(Colour::from_array(std::array::from_fn(
                    |i| apply(x[i], y[i]),
                ))))
            }
            (Value::Vector(_), _) | (_, Value::Vector(_)) => {
                let len = match (&a, &b) {
                    (Value::Vector(v), Value::Vector(w)) => v.len.max(w.len),
                    (Value::Vector(v), _) | (_, Value::Vector(v)) => v.len,
                    _ => 3,
                };
                let x = self.promote_vector(&a, len, span)?;
                let y = self.promote_vector(&b, len, span)?;
                let mut components = [0.0; 5];
                for i in 0..len as usize {
                    components[i] = apply(x[i], y[i]);
                }
                Ok(Value::Vector(Vector { components, len }))
            }
            _ => {
                let culprit = if matches!(a, Value::Float(_)) { &b } else { &a };
                Err(self
                    .runtime
                    .error(
                        span,
                        format!(
                            "operator `{}` cannot be applied to {}",
                            op.symbol(),
                            culprit.type_name()
                        ),
                    )
                    .with_label(format!("{} met {}", a.type_name(), b.type_name()))
                    .into())
            }
        }
    }

    fn promote_vector(&self, value: &Value, len: u8, span: Span) -> EvalResult<[f64; 5]> {
        match value {
            Value::Float(f) => {
                let mut c = [0.0; 5];
                for x in c.iter_mut().take(len as usize) {
                    *x = *f;
                }
                Ok(c)
            }
            Value::Vector(v) => Ok(v.components),
            other => Err(self
                .runtime
                .error(
                    span,
                    format!("expected a vector, found {}", other.type_name()),
                )
                .into()),
        }
    }

    fn member(&self, value: Value, member: &str, span: Span) -> EvalResult<Value> {
        let components: [f64; 5] = match &value {
            Value::Vector(v) => v.components,
            Value::Colour(c) => c.to_array(),
            Value::Float(f) => [*f; 5],
            other => {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!("`.{member}` cannot be applied to {}", other.type_name()),
                    )
                    .into())
            }
        };
        let index =
            match member {
                "x" | "u" | "red" => 0,
                "y" | "v" | "green" => 1,
                "z" | "blue" => 2,
                "t" | "filter" => 3,
                "transmit" => 4,
                "gray" | "grey" => {
                    let [r, g, b, ..] = components;
                    return Ok(Value::Float(0.297 * r + 0.589 * g + 0.114 * b));
                }
                _ => return Err(self
                    .runtime
                    .error(span, format!("unknown member `.{member}`"))
                    .with_help(
                        "members are .x .y .z .t .u .v .red .green .blue .filter .transmit .gray",
                    )
                    .into()),
            };
        if let Value::Vector(v) = &value {
            if index >= v.len as usize
                && !matches!(member, "filter" | "transmit" | "red" | "green" | "blue")
            {
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!("`.{member}` does not exist on a {}-component vector", v.len),
                    )
                    .into());
            }
        }
        Ok(Value::Float(components[index]))
    }

    fn eval_call(&mut self, call: &Rc<Call>) -> EvalResult<Value> {
        if let Some(element) = &call.element {
            let callee = self.eval_expr(element)?;
            return self.call_value(callee, call);
        }
        match self.runtime.lookup(call.name) {
            Some(Value::Macro(_)) => self.call_macro_value(call),
            Some(Value::Function(function)) => {
                let function = function.clone();
                self.with_argument_directives(call, |ev| ev.call_user_function(&function, call))
            }
            Some(Value::Spline(spline)) => {
                let spline = spline.clone();
                self.with_argument_directives(call, |ev| {
                    super::splines::call_spline(ev, &spline, call)
                })
            }
            _ => self.with_argument_directives(call, |ev| super::builtins::call_builtin(ev, call)),
        }
    }

    /// Calls the value of an array element (`Fns[I](x)`): a function or a spline.
    pub(crate) fn call_value(&mut self, callee: Value, call: &Rc<Call>) -> EvalResult<Value> {
        match callee {
            Value::Function(function) => {
                self.with_argument_directives(call, |ev| ev.call_user_function(&function, call))
            }
            Value::Spline(spline) => self.with_argument_directives(call, |ev| {
                super::splines::call_spline(ev, &spline, call)
            }),
            other => Err(self.element_not_a_function(call, &other, "called here")),
        }
    }

    /// The error for `array[i](..)` whose element is `found`, not a function.
    pub(crate) fn element_not_a_function(
        &self,
        call: &Call,
        found: &Value,
        label: &str,
    ) -> Box<crate::diag::Diagnostic> {
        let message = format!(
            "this element of `{}` is {}, not a function",
            call.name,
            found.type_name()
        );
        Box::new(
            self.runtime
                .error(call.name_span, message)
                .with_label(label),
        )
    }

    /// Evaluates the argument at `index` as a float.
    pub(crate) fn argument_float(&mut self, call: &Call, index: usize) -> EvalResult<f64> {
        let value = self.argument(call, index)?;
        self.to_float(value, call.arguments[index].span())
    }

    /// Evaluates the argument at `index`.
    pub(crate) fn argument(&mut self, call: &Call, index: usize) -> EvalResult<Value> {
        self.run_directives_before(call, index)?;
        match call.arguments.get(index) {
            Some(crate::syntax::ast::Argument::Expr(e)) => self.eval_expr(e),
            Some(crate::syntax::ast::Argument::Block(b)) => self.eval_block(b),
            None => Err(self
                .runtime
                .error(call.span, format!("`{}` needs more arguments", call.name))
                .into()),
        }
    }

    /// Checks a string's size against the limit.
    pub(crate) fn checked_string(&self, s: String, span: Span) -> EvalResult<Value> {
        let limit = self.runtime.options().limits.string_size;
        if s.len() as u64 > limit {
            return Err(self
                .runtime
                .error(span, format!("string longer than {limit} bytes"))
                .with_help(crate::limits::Limits::raise_hint("string-size", limit))
                .into());
        }
        Ok(Value::String(Rc::from(s)))
    }
}

/// Built-in identifiers that are values.
pub(crate) fn builtin_constant(name: &str, evaluator: &Evaluator) -> Option<Value> {
    let v3 = |x, y, z| Value::Vector(Vector::from_slice(&[x, y, z]));
    Some(match name {
        "x" => v3(1.0, 0.0, 0.0),
        "y" => v3(0.0, 1.0, 0.0),
        "z" => v3(0.0, 0.0, 1.0),
        "t" => Value::Vector(Vector::from_slice(&[0.0, 0.0, 0.0, 1.0])),
        "u" => Value::Vector(Vector::from_slice(&[1.0, 0.0])),
        "v" => Value::Vector(Vector::from_slice(&[0.0, 1.0])),
        "pi" => Value::Float(std::f64::consts::PI),
        "tau" => Value::Float(std::f64::consts::TAU),
        "true" | "yes" | "on" => Value::Float(1.0),
        "false" | "no" | "off" => Value::Float(0.0),
        "clock" => Value::Float(evaluator.runtime.options.clock),
        "clock_delta" => Value::Float(evaluator.runtime.options.animation.clock_delta),
        "clock_on" => Value::Float(f64::from(u8::from(
            evaluator.runtime.options.animation.clock_on,
        ))),
        "initial_clock" => Value::Float(evaluator.runtime.options.animation.initial_clock),
        "final_clock" => Value::Float(evaluator.runtime.options.animation.final_clock),
        "frame_number" => Value::Float(evaluator.runtime.options.animation.frame_number),
        "initial_frame" => Value::Float(evaluator.runtime.options.animation.initial_frame),
        "final_frame" => Value::Float(evaluator.runtime.options.animation.final_frame),
        "image_width" => Value::Float(f64::from(evaluator.runtime.options.image_width)),
        "image_height" => Value::Float(f64::from(evaluator.runtime.options.image_height)),
        "version" => Value::Float(evaluator.runtime.version),
        "now" => Value::Float(super::datetime::now_in_days()),
        "input_file_name" => Value::String(Rc::from(evaluator.runtime.input_file_name.as_str())),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    /// `y (-1)` is read as two items because `y` is a constant; that rule needs no built-in
    /// function to share a constant's name.
    #[test]
    fn no_built_in_function_is_named_like_a_constant() {
        let evaluator = crate::eval::Evaluator::new(crate::eval::EvalOptions::default());
        for name in crate::eval::language::builtins::FUNCTIONS {
            let constant = super::builtin_constant(name, &evaluator);
            assert!(
                constant.is_none(),
                "`{name}` is both a function and a constant"
            );
        }
    }
}
