//! Compiling user functions (`function { .. }`, `function(a, b) { .. }`) into the render-time
//! form of [`crate::function`].
//!
//! In: a function literal and the evaluator's current declarations. Out: an
//! `Arc<Function>`, or a spanned diagnostic for what a function body may not contain.
//! Holds: sub-expressions that do not read the parameters are evaluated once here by the
//! scene evaluator (so `#declare`d constants, vector members and every SDL built-in work
//! there); the rest becomes VM nodes. Calls of other user functions are compiled once per
//! compilation and shared.

use crate::eval::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::function::{Binary, Function, Internal, Node, Unary, MAX_PARAMETERS};
use crate::syntax::ast::{Argument, BinaryOp, Call, Expr, FunctionBody, FunctionLiteral, UnaryOp};
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

/// Deepest chain of user functions calling each other (a function redeclared in terms of
/// itself would otherwise never end).
const CALL_DEPTH_LIMIT: usize = 64;

/// State of one compilation: functions compiled so far and the call depth.
#[derive(Default)]
struct Compilation {
    compiled: HashMap<*const FunctionLiteral, Arc<Function>>,
    depth: usize,
}

impl Evaluator {
    /// Compiles a user function for fast evaluation (isosurfaces, height fields).
    pub(crate) fn compile_function(
        &mut self,
        function: &Rc<FunctionLiteral>,
    ) -> EvalResult<Arc<Function>> {
        self.compile_literal(function, &mut Compilation::default())
    }

    fn compile_literal(
        &mut self,
        function: &Rc<FunctionLiteral>,
        state: &mut Compilation,
    ) -> EvalResult<Arc<Function>> {
        if let Some(done) = state.compiled.get(&Rc::as_ptr(function)) {
            return Ok(done.clone());
        }
        let FunctionBody::Expr(body) = &function.body else {
            return Err(self
                .error(
                    function.span,
                    "pattern and pigment functions cannot be compiled yet",
                )
                .with_label("durer compiles float functions only")
                .into());
        };
        if let Expr::Call(call) = body {
            if &*call.name == "internal" {
                let internal = self.internal_function(call)?;
                let arity = internal.arity();
                let arguments = (0..arity).map(Node::Parameter).collect();
                let compiled = Arc::new(Function::new(Node::Internal(internal, arguments), arity));
                state
                    .compiled
                    .insert(Rc::as_ptr(function), compiled.clone());
                return Ok(compiled);
            }
        }
        let parameters: Vec<Rc<str>> = if function.parameters.is_empty() {
            ["x", "y", "z"].iter().map(|name| Rc::from(*name)).collect()
        } else {
            function.parameters.clone()
        };
        if parameters.len() > MAX_PARAMETERS {
            return Err(self
                .error(
                    function.span,
                    format!("a function may take at most {MAX_PARAMETERS} parameters"),
                )
                .into());
        }
        let arity = parameters.len();
        let mut names = parameters;
        let root = self.compile_expr(body, &mut names, state)?;
        let compiled = Arc::new(Function::new(root, arity));
        state
            .compiled
            .insert(Rc::as_ptr(function), compiled.clone());
        Ok(compiled)
    }

    /// Which internal function `internal(N)` names, or a diagnostic when durer lacks it.
    fn internal_function(&mut self, call: &Call) -> EvalResult<Internal> {
        let number = match call.arguments.as_slice() {
            [Argument::Expr(expr)] => self.eval_float(expr)?,
            _ => return Err(self.error(call.span, "`internal` takes one number").into()),
        };
        Internal::from_number(number).ok_or_else(|| {
            self.error(
                call.span,
                format!("POV-Ray's internal function {number} is not implemented in durer"),
            )
            .with_label("called through this definition")
            .with_help(
                "implemented: f_ellipsoid, f_paraboloid, f_ph, f_r, f_rounded_box, f_sphere, \
                 f_superellipsoid, f_th, f_torus, f_torus2, f_noise3d, f_noise_generator",
            )
            .into()
        })
    }

    /// Compiles one expression; `names` are the parameters (and `sum`/`prod` counters).
    fn compile_expr(
        &mut self,
        expr: &Expr,
        names: &mut Vec<Rc<str>>,
        state: &mut Compilation,
    ) -> EvalResult<Node> {
        if !self.reads_parameters(expr, names) {
            let value = self.eval_expr(expr)?;
            return Ok(Node::Constant(self.to_float(value, expr.span())?));
        }
        Ok(match expr {
            Expr::Ident(name, _) => {
                let index = names.iter().rposition(|n| n == name).unwrap_or(0);
                Node::Parameter(index)
            }
            Expr::Unary(op, operand, _) => {
                let operand = self.compile_expr(operand, names, state)?;
                match op {
                    UnaryOp::Plus => operand,
                    UnaryOp::Negate => Node::Unary(Unary::Negate, Box::new(operand)),
                    UnaryOp::Not => Node::Unary(Unary::Not, Box::new(operand)),
                }
            }
            Expr::Binary(op, lhs, rhs, _) => {
                let a = self.compile_expr(lhs, names, state)?;
                let b = self.compile_expr(rhs, names, state)?;
                let op = match op {
                    BinaryOp::Add => Binary::Add,
                    BinaryOp::Subtract => Binary::Subtract,
                    BinaryOp::Multiply => Binary::Multiply,
                    BinaryOp::Divide => Binary::Divide,
                    BinaryOp::Less => Binary::Less,
                    BinaryOp::LessEqual => Binary::LessEqual,
                    BinaryOp::Equal => Binary::Equal,
                    BinaryOp::NotEqual => Binary::NotEqual,
                    BinaryOp::GreaterEqual => Binary::GreaterEqual,
                    BinaryOp::Greater => Binary::Greater,
                    BinaryOp::And => Binary::And,
                    BinaryOp::Or => Binary::Or,
                };
                Node::Binary(op, Box::new([a, b]))
            }
            Expr::Conditional(parts, _) => {
                let (condition, a, b) = &**parts;
                Node::Conditional(Box::new([
                    self.compile_expr(condition, names, state)?,
                    self.compile_expr(a, names, state)?,
                    self.compile_expr(b, names, state)?,
                ]))
            }
            Expr::Call(call) => self.compile_call(call, names, state)?,
            other => {
                return Err(self
                    .error(
                        other.span(),
                        "this cannot depend on a function's parameters",
                    )
                    .with_label("functions compute floats from float parameters")
                    .into())
            }
        })
    }

    /// Compiles a call inside a function body.
    fn compile_call(
        &mut self,
        call: &Call,
        names: &mut Vec<Rc<str>>,
        state: &mut Compilation,
    ) -> EvalResult<Node> {
        let name = &*call.name;
        if let Some(Value::Function(callee)) = self.lookup(name) {
            let callee = callee.clone();
            if state.depth >= CALL_DEPTH_LIMIT {
                return Err(self
                    .error(call.span, "functions call each other too deeply")
                    .with_label(format!("more than {CALL_DEPTH_LIMIT} nested calls"))
                    .into());
            }
            state.depth += 1;
            let compiled = self.compile_literal(&callee, state);
            state.depth -= 1;
            let compiled = compiled?;
            if call.arguments.len() != compiled.arity() {
                return Err(self
                    .error(
                        call.span,
                        format!(
                            "function `{name}` takes {} arguments, found {}",
                            compiled.arity(),
                            call.arguments.len()
                        ),
                    )
                    .with_secondary(callee.span, "the function is declared here")
                    .into());
            }
            let arguments = self.compile_arguments(call, names, state)?;
            return Ok(Node::Call(compiled, arguments.into_boxed_slice()));
        }
        if matches!(name, "sum" | "prod") {
            return self.compile_series(call, names, state);
        }
        let arguments = self.compile_arguments(call, names, state)?;
        let found = arguments.len();
        let wrong_count = |evaluator: &Evaluator, wanted: &str| -> Box<crate::diag::Diagnostic> {
            Box::new(evaluator.error(
                call.span,
                format!("`{name}` takes {wanted} arguments, found {found}"),
            ))
        };
        if let Some(op) = Unary::from_name(name) {
            let [a]: [Node; 1] = arguments.try_into().map_err(|_| wrong_count(self, "1"))?;
            return Ok(Node::Unary(op, Box::new(a)));
        }
        match name {
            "pow" | "atan2" | "mod" => {
                let op = match name {
                    "pow" => Binary::Pow,
                    "atan2" => Binary::Atan2,
                    _ => Binary::Mod,
                };
                let pair: [Node; 2] = arguments.try_into().map_err(|_| wrong_count(self, "2"))?;
                Ok(Node::Binary(op, Box::new(pair)))
            }
            "min" | "max" => {
                let op = if name == "min" {
                    Binary::Min
                } else {
                    Binary::Max
                };
                let mut nodes = arguments.into_iter();
                let first = nodes.next().ok_or_else(|| wrong_count(self, "1 or more"))?;
                Ok(nodes.fold(first, |all, next| Node::Binary(op, Box::new([all, next]))))
            }
            "select" => {
                let parts: [Node; 4] = match arguments.len() {
                    3 => {
                        let [a, negative, positive]: [Node; 3] = arguments
                            .try_into()
                            .map_err(|_| wrong_count(self, "3 or 4"))?;
                        [a, negative, positive.clone(), positive]
                    }
                    _ => arguments
                        .try_into()
                        .map_err(|_| wrong_count(self, "3 or 4"))?,
                };
                Ok(Node::Select(Box::new(parts)))
            }
            _ => Err(self
                .error(
                    call.name_span,
                    format!("`{name}` cannot be used inside a function"),
                )
                .with_label("not a float function durer compiles")
                .into()),
        }
    }

    /// `sum(i, from, to, body)` / `prod(..)`.
    fn compile_series(
        &mut self,
        call: &Call,
        names: &mut Vec<Rc<str>>,
        state: &mut Compilation,
    ) -> EvalResult<Node> {
        let [Argument::Expr(Expr::Ident(counter, _)), Argument::Expr(from), Argument::Expr(to), Argument::Expr(body)] =
            call.arguments.as_slice()
        else {
            return Err(self
                .error(
                    call.span,
                    format!("`{}` takes a counter name, from, to and a body", call.name),
                )
                .into());
        };
        if names.len() >= MAX_PARAMETERS {
            return Err(self
                .error(call.span, "too many nested sums and products")
                .into());
        }
        let from = self.compile_expr(from, names, state)?;
        let to = self.compile_expr(to, names, state)?;
        let index = names.len();
        names.push(counter.clone());
        let body = self.compile_expr(body, names, state);
        names.pop();
        Ok(Node::Series {
            product: &*call.name == "prod",
            counter: index,
            parts: Box::new([from, to, body?]),
        })
    }

    fn compile_arguments(
        &mut self,
        call: &Call,
        names: &mut Vec<Rc<str>>,
        state: &mut Compilation,
    ) -> EvalResult<Vec<Node>> {
        if call.arguments.len() > MAX_PARAMETERS {
            return Err(self
                .error(call.span, format!("more than {MAX_PARAMETERS} arguments"))
                .into());
        }
        call.arguments
            .iter()
            .map(|argument| match argument {
                Argument::Expr(expr) => self.compile_expr(expr, names, state),
                Argument::Block(block) => Err(self
                    .error(block.span, "a function argument must be a float")
                    .into()),
            })
            .collect()
    }

    /// True when `expr` reads a parameter or calls a user function (so it must be compiled
    /// rather than evaluated now).
    fn reads_parameters(&self, expr: &Expr, names: &[Rc<str>]) -> bool {
        match expr {
            Expr::Ident(name, _) => names.contains(name),
            Expr::Unary(_, operand, _) => self.reads_parameters(operand, names),
            Expr::Binary(_, a, b, _) => {
                self.reads_parameters(a, names) || self.reads_parameters(b, names)
            }
            Expr::Conditional(parts, _) => {
                let (c, a, b) = &**parts;
                self.reads_parameters(c, names)
                    || self.reads_parameters(a, names)
                    || self.reads_parameters(b, names)
            }
            Expr::Member(base, _, _) => self.reads_parameters(base, names),
            Expr::Index(base, index, _) => {
                self.reads_parameters(base, names) || self.reads_parameters(index, names)
            }
            Expr::Vector(elements, _) => elements.iter().any(|e| self.reads_parameters(e, names)),
            Expr::Call(call) => {
                matches!(self.lookup(&call.name), Some(Value::Function(_)))
                    || matches!(&*call.name, "sum" | "prod")
                    || call.arguments.iter().any(|argument| match argument {
                        Argument::Expr(e) => self.reads_parameters(e, names),
                        Argument::Block(_) => false,
                    })
            }
            Expr::Number(..)
            | Expr::String(..)
            | Expr::Colour(_)
            | Expr::Array(_)
            | Expr::Function(_)
            | Expr::Directive(_) => false,
        }
    }
}

impl Evaluator {
    /// Calls one of POV-Ray's internal functions (`f_sphere(..)` of functions.inc) from scene
    /// code: the arguments as floats, the value from the compiled function.
    pub(crate) fn call_internal_function(
        &mut self,
        function: &Rc<FunctionLiteral>,
        call: &Call,
    ) -> EvalResult<Value> {
        let compiled = self.compile_function(function).map_err(|error| {
            let mut diagnostic = self
                .error(call.span, format!("`{}`: {}", call.name, error.message))
                .with_label("called here")
                .with_secondary(error.span, "defined here");
            diagnostic.help = error.help.clone();
            Box::new(diagnostic)
        })?;
        if call.arguments.len() != compiled.arity() {
            return Err(self
                .error(
                    call.span,
                    format!(
                        "function `{}` takes {} arguments, found {}",
                        call.name,
                        compiled.arity(),
                        call.arguments.len()
                    ),
                )
                .into());
        }
        let mut arguments = [0.0; MAX_PARAMETERS];
        for (index, slot) in arguments.iter_mut().enumerate().take(compiled.arity()) {
            *slot = self.argument_float(call, index)?;
        }
        Ok(Value::Float(compiled.eval(&arguments[..compiled.arity()])))
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::value::Value;
    use crate::eval::{EvalOptions, Evaluator};

    /// Every operator and built-in a compiled function knows, evaluated by the scene language
    /// at a few points (stored in `Values`) and by the compiled function.
    const SCENE: &str = r#"
#declare C = 0.25;
#declare V = <0.5, 2, 3>;
#declare G = function(a, b) { a * b - C * V.y }
#declare F = function {
  G(x, y) + sin(3 * z) * (x < y ? 2 : -1) + select(x - 0.1, 1, 2, 3) + select(y, 4, 5)
  + mod(z * 7, 2) + atan2(y, x) + pow(abs(x), 1.5) + max(x, y, z) + min(x, 2 * y)
  + ln(2 + x) + log(3 + y) + floor(x * 3) + ceil(y * 3) + int(z * 2.5) + degrees(x)
  + radians(y) + exp(z) + !(x > 0) + (x > 0 & y > 0) + (x < 0 | z > 0) + (x = y)
  + (x != y) + (x <= 0.3) + (y >= -0.2) + sqrt(abs(z)) + cos(x) * tan(y / 2) + -x / 3
  + asin(x / 2) + acos(y / 2) + atan(z) + sinh(x) + cosh(y) + tanh(z) + asinh(x)
  + acosh(2 + y) + atanh(z / 2)
}
#declare Points = array[5] { <0.3, -0.2, 0.7>, <-0.5, 0.5, -0.1>, <0, 0, 0>,
  <0.9, 0.4, -0.8>, <0.1, 0.1, 0.3> }
#declare Values = array[5];
#for (I, 0, 4)
  #declare Values[I] = F(Points[I].x, Points[I].y, Points[I].z);
#end
"#;

    #[test]
    fn compiled_functions_equal_the_scene_languages_values() {
        let folder = std::env::temp_dir().join(format!("durer-function-vm-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("functions.pov");
        std::fs::write(&path, SCENE).unwrap();
        let mut evaluator = Evaluator::new(EvalOptions::default());
        let result = evaluator.run_main(&path);
        std::fs::remove_dir_all(&folder).ok();
        assert!(result.is_ok(), "{:?}", result.err());
        let Some(Value::Function(literal)) = evaluator.lookup("F").cloned() else {
            panic!("F is not a function");
        };
        let compiled = evaluator.compile_function(&literal).unwrap();
        let array = |name: &str| match evaluator.lookup(name) {
            Some(Value::Array(array)) => array.elements.clone(),
            _ => panic!("{name} is not an array"),
        };
        for (point, value) in array("Points").iter().zip(array("Values").iter()) {
            let (Some(Value::Vector(point)), Some(Value::Float(expected))) = (point, value) else {
                panic!("unexpected array contents");
            };
            let p = point.to_dvec3();
            let found = compiled.eval(&[p.x, p.y, p.z]);
            assert!(
                (found - expected).abs() <= 1e-12 * expected.abs().max(1.0),
                "at {p}: compiled {found}, scene language {expected}"
            );
        }
    }
}
