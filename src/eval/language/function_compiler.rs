//! Compiling user functions (`function { .. }`, `function(a, b) { .. }`, and the pattern,
//! pigment, transform and spline functions) into the render-time form of [`crate::texture::function`],
//! and calling them from scene code.
//!
//! In: a function literal and the evaluator's current declarations. Out: an
//! `Arc<Function>`, or a spanned diagnostic for what a function body may not contain.
//! Holds: a literal is compiled when it is evaluated, so its identifiers are bound there (as
//! in POV-Ray); sub-expressions that do not read the parameters are evaluated once by the
//! scene evaluator (so `#declare`d constants, vector members and every SDL built-in work
//! there); the rest becomes VM nodes. Calls of other user functions share their compiled
//! form; chains of calls are bounded ([`CALL_DEPTH_LIMIT`]).

use crate::eval::language::stream::Stream;
use crate::eval::language::value::{UserFunction, Value, Vector};
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{
    Argument, BinaryOp, BlockHead, Call, Expr, FunctionBody, FunctionLiteral, Item, UnaryOp,
};
use crate::syntax::symbol::Symbol;
use crate::texture::function::{
    Binary, Body, Component, Function, Internal, Node, Output, Unary, MAX_PARAMETERS,
};
use crate::texture::Pigment;
use std::rc::Rc;
use std::sync::Arc;

/// Deepest chain of user functions calling each other (each call is a level of recursion
/// when the function is evaluated).
const CALL_DEPTH_LIMIT: usize = 64;

/// Something that gives a compiled function: a literal written in place (compiled now, in the
/// current scope) or a declared function value (compiled when it was declared).
pub(crate) trait FunctionSource {
    /// The compiled function, or the diagnostic that prevents it.
    fn compiled(&self, evaluator: &mut Evaluator) -> EvalResult<Arc<Function>>;
}

impl FunctionSource for Rc<FunctionLiteral> {
    fn compiled(&self, evaluator: &mut Evaluator) -> EvalResult<Arc<Function>> {
        evaluator.compile_literal(self)
    }
}

impl FunctionSource for Rc<UserFunction> {
    fn compiled(&self, _: &mut Evaluator) -> EvalResult<Arc<Function>> {
        self.compiled.clone()
    }
}

impl Evaluator {
    /// Compiles a user function for fast evaluation (isosurfaces, patterns, height fields).
    pub(crate) fn compile_function(
        &mut self,
        function: &impl FunctionSource,
    ) -> EvalResult<Arc<Function>> {
        function.compiled(self)
    }

    /// The value of a function literal: compiled here, where its identifiers are bound (as
    /// POV-Ray does), with its mistakes reported here. Only an `internal(N)` function durer
    /// lacks is kept, to be refused where it is called (functions.inc declares them all).
    pub(crate) fn function_value(&mut self, literal: &Rc<FunctionLiteral>) -> EvalResult<Value> {
        let compiled = self.compile_literal(literal);
        let is_internal = matches!(&literal.body, FunctionBody::Expr(Expr::Call(call)) if &*call.name == "internal");
        Ok(Value::Function(Rc::new(UserFunction {
            literal: literal.clone(),
            compiled: if is_internal { compiled } else { Ok(compiled?) },
        })))
    }

    /// A user function's compiled form for a call; a function that could not be compiled is
    /// reported at the call.
    fn compiled_for_call(
        &mut self,
        function: &Rc<UserFunction>,
        call: &Call,
    ) -> EvalResult<Arc<Function>> {
        function.compiled.clone().map_err(|error| {
            let mut diagnostic = self
                .runtime
                .error(call.span, format!("`{}`: {}", call.name, error.message))
                .with_label("called here")
                .with_secondary(error.span, "defined here");
            diagnostic.help = error.help.clone();
            Box::new(diagnostic)
        })
    }

    fn compile_literal(&mut self, function: &Rc<FunctionLiteral>) -> EvalResult<Arc<Function>> {
        let body = match &function.body {
            FunctionBody::Items(items) => return self.compile_vector_function(function, items),
            FunctionBody::Expr(body) => body,
        };
        if let Expr::Call(call) = body {
            if &*call.name == "internal" {
                let internal = self.internal_function(call)?;
                let arity = internal.arity();
                let arguments = (0..arity).map(Node::Parameter).collect();
                let node = if internal == Internal::Noise3d {
                    Node::SceneNoise(self.scene.scene_noise_generator(), arguments)
                } else {
                    Node::Internal(internal, arguments)
                };
                return Ok(Arc::new(Function::new(node, arity)));
            }
        }
        let parameters: Vec<Symbol> = if function.parameters.is_empty() {
            ["x", "y", "z"]
                .iter()
                .map(|name| Symbol::intern(name))
                .collect()
        } else {
            function.parameters.clone()
        };
        if parameters.len() > MAX_PARAMETERS {
            return Err(self
                .runtime
                .error(
                    function.span,
                    format!("a function may take at most {MAX_PARAMETERS} parameters"),
                )
                .into());
        }
        if let Expr::Ident(name, span) = body {
            if let Some(Value::Spline(_)) = self.runtime.lookup(*name) {
                return Err(self
                    .runtime
                    .error(
                        *span,
                        format!("a function cannot be the spline `{name}` itself"),
                    )
                    .with_label("POV-Ray refuses a spline identifier here")
                    .with_help(format!("write `function {{ spline {{ {name} }} }}`"))
                    .into());
            }
        }
        let arity = parameters.len();
        let mut names = parameters;
        if !self.reads_parameters(body, &names) {
            // A body that does not read the parameters is evaluated once; a macro there may
            // expand to a pigment (`function { BlurPigment(P, 0.1, 9) }`, where the macro's
            // body is `pigment { average pigment_map { .. } }`), which POV-Ray takes as
            // `function { pigment { .. } }`.
            let value = self.eval_expr(body)?;
            if let Value::Pigment(pigment) = value {
                let pigment = Rc::unwrap_or_clone(pigment);
                return Ok(Arc::new(Function::with_body(Body::Pigment(Box::new(
                    pigment,
                )))));
            }
            let root = Node::Constant(self.to_float(value, body.span())?);
            return Ok(Arc::new(Function::new(root, arity)));
        }
        let root = self.compile_expr(body, &mut names)?;
        Ok(Arc::new(Function::new(root, arity)))
    }

    /// `function { pattern { .. } }`, `function { pigment { .. } }`,
    /// `function { transform { .. } }` or `function { spline { .. } }`.
    fn compile_vector_function(
        &mut self,
        function: &FunctionLiteral,
        items: &Rc<[Item]>,
    ) -> EvalResult<Arc<Function>> {
        let mut stream = Stream::new(items.clone());
        let mut body = None;
        while let Some(item) = self.next_item(&mut stream)? {
            let block = match &item {
                Item::Comma(_) => continue,
                Item::Block(block) if body.is_none() => block,
                _ => return Err(self.unexpected_in(&item, "function")),
            };
            let BlockHead::Word(word) = &block.head else {
                return Err(self.unexpected_in(&item, "function"));
            };
            body = Some(match &**word {
                "pattern" => {
                    let pigment = self.eval_pigment(&mut Stream::new(block.body.clone()))?;
                    let Pigment::Pattern {
                        pattern, transform, ..
                    } = pigment
                    else {
                        return Err(self
                            .runtime
                            .error(block.span, "a pattern function needs a pattern")
                            .with_label("no pattern keyword in this block")
                            .with_help("e.g. `function { pattern { bozo scale 0.5 } }`")
                            .into());
                    };
                    Body::Pattern { pattern, transform }
                }
                "pigment" => {
                    let pigment = self.eval_pigment(&mut Stream::new(block.body.clone()))?;
                    Body::Pigment(Box::new(pigment))
                }
                "transform" => match self.eval_block(block)? {
                    Value::Transform(transform) => Body::Transform(Rc::unwrap_or_clone(transform)),
                    _ => return Err(self.unexpected_in(&item, "function")),
                },
                "spline" => match self.eval_block(block)? {
                    Value::Spline(spline) => Body::Spline(Arc::new((*spline).clone())),
                    _ => return Err(self.unexpected_in(&item, "function")),
                },
                _ => {
                    return Err(self
                        .runtime
                        .error(block.head_span, format!("`{word}` cannot make a function"))
                        .with_label("expected `pattern`, `pigment`, `transform` or `spline`")
                        .into())
                }
            });
        }
        match body {
            Some(body) => Ok(Arc::new(Function::with_body(body))),
            None => Err(self
                .runtime
                .error(function.span, "this function is empty")
                .with_label("expected an expression or a pattern, pigment, transform or spline")
                .into()),
        }
    }

    /// Which internal function `internal(N)` names, or a diagnostic when durer lacks it.
    fn internal_function(&mut self, call: &Call) -> EvalResult<Internal> {
        let number = match call.arguments.as_slice() {
            [Argument::Expr(expr)] => {
                self.run_directives_at(call, 0)?;
                let number = self.eval_float(expr)?;
                self.run_directives_at(call, 1)?;
                number
            }
            _ => {
                return Err(self
                    .runtime
                    .error(call.span, "`internal` takes one number")
                    .into())
            }
        };
        Internal::from_number(number).ok_or_else(|| {
            self.runtime
                .error(
                    call.span,
                    format!("POV-Ray's internal function {number} is not implemented in durer"),
                )
                .with_label("called through this definition")
                .with_help(
                    "durer implements every function of functions.inc: internal(0) to \
                 internal(76) and internal(78)",
                )
                .into()
        })
    }

    /// Compiles one expression; `names` are the parameters (and `sum`/`prod` counters).
    fn compile_expr(&mut self, expr: &Expr, names: &mut Vec<Symbol>) -> EvalResult<Node> {
        if !self.reads_parameters(expr, names) {
            let value = self.eval_expr(expr)?;
            return Ok(Node::Constant(self.to_float(value, expr.span())?));
        }
        Ok(match expr {
            Expr::Ident(name, _) => Node::Parameter(parameter_index(names, *name).unwrap_or(0)),
            Expr::Unary(op, operand, _) => {
                let operand = self.compile_expr(operand, names)?;
                match op {
                    UnaryOp::Plus => operand,
                    UnaryOp::Negate => Node::Unary(Unary::Negate, Box::new(operand)),
                    UnaryOp::Not => Node::Unary(Unary::Not, Box::new(operand)),
                }
            }
            Expr::Binary(op, lhs, rhs, _) => {
                let a = self.compile_expr(lhs, names)?;
                let b = self.compile_expr(rhs, names)?;
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
                    self.compile_expr(condition, names)?,
                    self.compile_expr(a, names)?,
                    self.compile_expr(b, names)?,
                ]))
            }
            Expr::Call(call) => self.compile_call(call, names)?,
            Expr::Member(base, member, span) => self.compile_member(base, member, *span, names)?,
            other => {
                return Err(self
                    .runtime
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
    fn compile_call(&mut self, call: &Call, names: &mut Vec<Symbol>) -> EvalResult<Node> {
        let name = &*call.name;
        if let Some(callee) = self.called_function(call, names)? {
            if callee.output() != Output::Float {
                let example = match callee.output() {
                    Output::Colour => ".red",
                    _ => ".x",
                };
                return Err(self
                    .runtime
                    .error(
                        call.span,
                        format!(
                            "`{name}` returns {}; pick one of its components",
                            output_name(callee.output())
                        ),
                    )
                    .with_label("a function computes floats")
                    .with_help(format!("add a member, e.g. `{name}(..){example}`"))
                    .into());
            }
            let arguments = self.compile_arguments(call, names)?;
            return Ok(Node::Call(callee, arguments.into_boxed_slice()));
        }
        if let Some(Value::Spline(_)) = self.runtime.lookup(call.name) {
            return Err(self.spline_call_error(call));
        }
        if matches!(name, "sum" | "prod") {
            return self.compile_series(call, names);
        }
        let arguments = self.compile_arguments(call, names)?;
        let found = arguments.len();
        let wrong_count = |evaluator: &Evaluator, wanted: &str| -> Box<crate::diag::Diagnostic> {
            Box::new(evaluator.runtime.error(
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
                .runtime
                .error(
                    call.name_span,
                    format!("`{name}` cannot be used inside a function"),
                )
                .with_label("not a float function durer compiles")
                .into()),
        }
    }

    /// The compiled user function `call` names, checked against the call's argument count;
    /// `None` when the name is not a function.
    fn called_function(
        &mut self,
        call: &Call,
        names: &[Symbol],
    ) -> EvalResult<Option<Arc<Function>>> {
        let callee = match &call.element {
            Some(element) => self.element_function(call, element, names)?,
            None => match self.runtime.lookup(call.name) {
                Some(Value::Function(callee)) => callee.clone(),
                _ => return Ok(None),
            },
        };
        let compiled = self.checked_callee(&callee, call)?;
        if compiled.call_depth() >= CALL_DEPTH_LIMIT {
            return Err(self
                .runtime
                .error(call.span, "functions call each other too deeply")
                .with_label(format!("more than {CALL_DEPTH_LIMIT} nested calls"))
                .into());
        }
        Ok(Some(compiled))
    }

    /// The function an array element called inside a function holds (`Fns[2](x, y, z)`);
    /// the element is chosen when the function is compiled.
    fn element_function(
        &mut self,
        call: &Call,
        element: &Expr,
        names: &[Symbol],
    ) -> EvalResult<Rc<UserFunction>> {
        if self.reads_parameters(element, names) {
            return Err(self
                .runtime
                .error(
                    element.span(),
                    "the element called cannot depend on the parameters",
                )
                .with_label("the index must be known when the function is declared")
                .into());
        }
        match self.eval_expr(element)? {
            Value::Function(function) => Ok(function),
            other => Err(self.element_not_a_function(call, &other, "called inside a function")),
        }
    }

    /// `F(..).member` inside a function: one component of a pigment, transformation or spline
    /// function's result.
    fn compile_member(
        &mut self,
        base: &Expr,
        member: &str,
        span: crate::diag::Span,
        names: &mut Vec<Symbol>,
    ) -> EvalResult<Node> {
        let Expr::Call(call) = base else {
            return Err(self
                .runtime
                .error(base.span(), "this cannot depend on a function's parameters")
                .with_label(
                    "only a call of a pigment, transform or spline function has members here",
                )
                .into());
        };
        let Some(callee) = self.called_function(call, names)? else {
            if let Some(Value::Spline(_)) = self.runtime.lookup(call.name) {
                return Err(self.spline_call_error(call));
            }
            return Err(self
                .runtime
                .error(
                    call.name_span,
                    format!("`{}` has no members inside a function", call.name),
                )
                .with_label("not a pigment, transform or spline function")
                .into());
        };
        let Some(component) = Component::from_member(member, callee.output()) else {
            let message = match callee.output() {
                Output::Float => format!(
                    "`{}` returns a float, which has no member `.{member}`",
                    call.name
                ),
                output => format!(
                    "`{}` returns {}, which has no member `.{member}`",
                    call.name,
                    output_name(output)
                ),
            };
            return Err(self
                .runtime
                .error(span, message)
                .with_help(
                    "members are .x .y .z .t .u .v .red .green .blue .filter .transmit .gray .hf",
                )
                .into());
        };
        let arguments = self.compile_arguments(call, names)?;
        Ok(Node::Member(
            callee,
            component,
            arguments.into_boxed_slice(),
        ))
    }

    /// POV-Ray does not call splines inside functions; a spline function does it.
    fn spline_call_error(&self, call: &Call) -> Box<crate::diag::Diagnostic> {
        let name = &call.name;
        self.runtime
            .error(
                call.name_span,
                format!("the spline `{name}` cannot be called inside a function"),
            )
            .with_label("POV-Ray refuses splines here")
            .with_help(format!(
                "make it a function: `#declare F = function {{ spline {{ {name} }} }}`, then call \
             `F(t).x`"
            ))
            .into()
    }

    /// `sum(i, from, to, body)` / `prod(..)`.
    fn compile_series(&mut self, call: &Call, names: &mut Vec<Symbol>) -> EvalResult<Node> {
        let [Argument::Expr(Expr::Ident(counter, _)), Argument::Expr(from), Argument::Expr(to), Argument::Expr(body)] =
            call.arguments.as_slice()
        else {
            return Err(self
                .runtime
                .error(
                    call.span,
                    format!("`{}` takes a counter name, from, to and a body", call.name),
                )
                .into());
        };
        if names.len() >= MAX_PARAMETERS {
            return Err(self
                .runtime
                .error(call.span, "too many nested sums and products")
                .into());
        }
        self.run_directives_at(call, 0)?;
        self.run_directives_at(call, 1)?;
        let from = self.compile_expr(from, names)?;
        self.run_directives_at(call, 2)?;
        let to = self.compile_expr(to, names)?;
        self.run_directives_at(call, 3)?;
        let index = names.len();
        names.push(*counter);
        let body = self.compile_expr(body, names);
        names.pop();
        self.run_directives_at(call, 4)?;
        Ok(Node::Series {
            product: &*call.name == "prod",
            counter: index,
            parts: Box::new([from, to, body?]),
        })
    }

    fn compile_arguments(&mut self, call: &Call, names: &mut Vec<Symbol>) -> EvalResult<Vec<Node>> {
        if call.arguments.len() > MAX_PARAMETERS {
            return Err(self
                .runtime
                .error(call.span, format!("more than {MAX_PARAMETERS} arguments"))
                .into());
        }
        let mut nodes = Vec::with_capacity(call.arguments.len());
        for (index, argument) in call.arguments.iter().enumerate() {
            self.run_directives_at(call, index)?;
            nodes.push(match argument {
                Argument::Expr(expr) => self.compile_expr(expr, names)?,
                Argument::Block(block) => {
                    return Err(self
                        .runtime
                        .error(block.span, "a function argument must be a float")
                        .into())
                }
            });
        }
        self.run_directives_at(call, call.arguments.len())?;
        Ok(nodes)
    }

    /// True when `expr` reads a parameter or calls a user function (so it must be compiled
    /// rather than evaluated now).
    fn reads_parameters(&self, expr: &Expr, names: &[Symbol]) -> bool {
        match expr {
            Expr::Ident(name, _) => parameter_index(names, *name).is_some(),
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
                call.element.is_some()
                    || matches!(self.runtime.lookup(call.name), Some(Value::Function(_)))
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

/// The index of the parameter `name` reads: the last parameter of that name, or, in a
/// function of the default parameters `x, y, z`, `u` for `x` and `v` for `y` (as in POV-Ray,
/// where a `parametric`'s functions are written in `u` and `v`).
fn parameter_index(names: &[Symbol], name: Symbol) -> Option<usize> {
    names.iter().rposition(|n| *n == name).or_else(|| {
        let default_parameters = names.len() >= 2 && &*names[0] == "x" && &*names[1] == "y";
        match &*name {
            "u" if default_parameters => Some(0),
            "v" if default_parameters => Some(1),
            _ => None,
        }
    })
}

/// How messages name what a function returns.
fn output_name(output: Output) -> &'static str {
    match output {
        Output::Float => "a float",
        Output::Colour => "a colour",
        Output::Vector(_) => "a vector",
    }
}

impl Evaluator {
    /// The compiled form of `function` for `call`, which must pass as many arguments as the
    /// function takes.
    fn checked_callee(
        &mut self,
        function: &Rc<UserFunction>,
        call: &Call,
    ) -> EvalResult<Arc<Function>> {
        let compiled = self.compiled_for_call(function, call)?;
        if call.arguments.len() != compiled.arity() {
            return Err(self
                .runtime
                .error(
                    call.span,
                    format!(
                        "function `{}` takes {} arguments, found {}",
                        call.name,
                        compiled.arity(),
                        call.arguments.len()
                    ),
                )
                .with_secondary(function.literal.span, "the function is declared here")
                .into());
        }
        Ok(compiled)
    }

    /// Calls a user function from scene code: float arguments, and the compiled function's
    /// float, colour or vector. A function that could not be compiled is reported here.
    pub(crate) fn call_user_function(
        &mut self,
        function: &Rc<UserFunction>,
        call: &Call,
    ) -> EvalResult<Value> {
        let compiled = self.checked_callee(function, call)?;
        let mut arguments = [0.0; MAX_PARAMETERS];
        for (index, slot) in arguments.iter_mut().enumerate().take(compiled.arity()) {
            *slot = self.argument_float(call, index)?;
        }
        let arguments = &arguments[..compiled.arity()];
        Ok(match compiled.output() {
            Output::Float => Value::Float(compiled.eval(arguments)),
            Output::Colour => Value::Colour(crate::math::Colour::from_array(
                compiled.eval_vector(arguments),
            )),
            Output::Vector(len) => {
                let components = compiled.eval_vector(arguments);
                Value::Vector(Vector::from_slice(
                    &components[..usize::from(len).clamp(1, 5)],
                ))
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::language::value::Value;
    use crate::eval::{EvalOptions, Evaluator};

    /// Every operator and built-in a compiled function knows, as a function body and as a
    /// macro body the scene language evaluates with `x, y, z` bound to macro arguments.
    const FORMULA: &str = "
  G(x, y) + sin(3 * z) * (x < y ? 2 : -1) + select(x - 0.1, 1, 2, 3) + select(y, 4, 5)
  + mod(z * 7, 2) + atan2(y, x) + pow(abs(x), 1.5) + max(x, y, z) + min(x, 2 * y)
  + ln(2 + x) + log(3 + y) + floor(x * 3) + ceil(y * 3) + int(z * 2.5) + degrees(x)
  + radians(y) + exp(z) + !(x > 0) + (x > 0 & y > 0) + (x < 0 | z > 0) + (x = y)
  + (x != y) + (x <= 0.3) + (y >= -0.2) + sqrt(abs(z)) + cos(x) * tan(y / 2) + -x / 3
  + asin(x / 2) + acos(y / 2) + atan(z) + sinh(x) + cosh(y) + tanh(z) + asinh(x)
  + acosh(2 + y) + atanh(z / 2)
";

    /// The compiled function `F` and the macro `Formula` over the same formula; `Values` holds
    /// the scene language's values at `Points`.
    fn scene() -> String {
        format!(
            r#"
#declare C = 0.25;
#declare V = <0.5, 2, 3>;
#declare G = function(a, b) {{ a * b - C * V.y }}
#declare F = function {{ {FORMULA} }}
#macro Formula(x, y, z) ({FORMULA}) #end
#declare Points = array[5] {{ <0.3, -0.2, 0.7>, <-0.5, 0.5, -0.1>, <0, 0, 0>,
  <0.9, 0.4, -0.8>, <0.1, 0.1, 0.3> }}
#declare Values = array[5];
#for (I, 0, 4)
  #declare Values[I] = Formula(Points[I].x, Points[I].y, Points[I].z);
#end
"#
        )
    }

    #[test]
    fn compiled_functions_equal_the_scene_languages_values() {
        let folder = std::env::temp_dir().join(format!("durer-function-vm-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("functions.pov");
        std::fs::write(&path, scene()).unwrap();
        let mut evaluator = Evaluator::new(EvalOptions::default());
        let result = evaluator.run_main(&path);
        std::fs::remove_dir_all(&folder).ok();
        assert!(result.is_ok(), "{:?}", result.err());
        let Some(Value::Function(literal)) = evaluator
            .runtime
            .lookup(crate::syntax::symbol::Symbol::intern("F"))
            .cloned()
        else {
            panic!("F is not a function");
        };
        let compiled = evaluator.compile_function(&literal).unwrap();
        let array = |name: &str| match evaluator
            .runtime
            .lookup(crate::syntax::symbol::Symbol::intern(name))
        {
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
