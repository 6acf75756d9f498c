//! Macro calls: argument binding (by reference for plain identifiers; directives among the
//! arguments run between them, see `argument_directives`), expansion in place
//! as stream items (a text body is run token by token first, see `token_macro`), and
//! evaluation as a single value inside expressions.

use super::stream::Stream;
use super::value::Value;
use crate::eval::language::{Entered, Entering};
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Call, Expr, Item, MacroBody, MacroDefinition};
use std::rc::Rc;

impl Evaluator {
    /// Expands a macro call in place: binds the arguments in a new scope and streams the body
    /// (a text body is run token by token first and its output streamed).
    pub(crate) fn enter_macro(&mut self, call: &Rc<Call>, stream: &mut Stream) -> EvalResult<()> {
        let definition = self.bind_macro_call(call)?;
        let body = match &definition.body {
            MacroBody::Items(items, _) => items.clone(),
            MacroBody::Text { text, span } => match self.expand_text_macro(text, *span, "macro") {
                Ok(items) => items,
                Err(error) => {
                    self.leave_macro_call();
                    return Err(error);
                }
            },
        };
        stream.push_macro(body);
        Ok(())
    }

    /// Starts a macro call: evaluates and binds its arguments in a new scope and records the
    /// call in the trace (undone by [`Self::leave_macro_call`] or the stream's macro frame).
    pub(crate) fn bind_macro_call(&mut self, call: &Rc<Call>) -> EvalResult<Rc<MacroDefinition>> {
        let Some(Value::Macro(definition)) = self.runtime.lookup(call.name).cloned() else {
            return Err(self.runtime.undefined(&call.name, call.name_span).into());
        };
        let values = self.macro_arguments(call)?;
        let required = definition.parameters.iter().filter(|p| !p.optional).count();
        if values.len() < required || values.len() > definition.parameters.len() {
            let names: Vec<&str> = definition.parameters.iter().map(|p| &*p.name).collect();
            let count = definition.parameters.len();
            return Err(self
                .runtime
                .error(
                    call.span,
                    format!(
                        "macro `{}` takes {count} argument{}, found {}",
                        definition.name,
                        if count == 1 { "" } else { "s" },
                        values.len()
                    ),
                )
                .with_label("called here")
                .with_secondary(
                    definition.header_span,
                    format!("parameters: ({})", names.join(", ")),
                )
                .into());
        }
        self.runtime.enter_nesting(call.span)?;
        self.runtime.trace.push(Entered {
            what: Entering::Macro(definition.name),
            span: call.span,
        });
        let names = definition.parameters.iter().map(|parameter| parameter.name);
        self.runtime.scopes.push(names.zip(values));
        Ok(definition)
    }

    /// Ends a macro call started by [`Self::bind_macro_call`]: drops its scope and trace entry.
    pub(crate) fn leave_macro_call(&mut self) {
        self.runtime.scopes.pop();
        self.runtime.trace.pop();
        self.runtime.nesting -= 1;
    }

    /// Evaluates a macro call's arguments in the caller's scope. Plain identifiers are passed
    /// by reference. As in POV-Ray, commas are optional, so `Obj -y` is two arguments when
    /// `Obj` is not a number: such a sum or difference is split in two. Directives among the
    /// arguments run in order between them (see `argument_directives`).
    fn macro_arguments(&mut self, call: &Call) -> EvalResult<Vec<Value>> {
        use crate::syntax::ast::Argument;
        let mut values = Vec::with_capacity(call.arguments.len());
        for (index, argument) in call.arguments.iter().enumerate() {
            self.run_macro_directives_before(call, index)?;
            match argument {
                Argument::Expr(Expr::Ident(name, span)) => {
                    // Point straight at the variable the name resolves to (following a
                    // reference the caller itself holds), so recursive macros passing a
                    // parameter on do not build chains of references.
                    let value = if let Some((index, value)) =
                        self.runtime.scopes.innermost_binding(*name)
                    {
                        match value {
                            Value::Reference { scope, name } => Value::Reference {
                                scope: *scope,
                                name: *name,
                            },
                            _ => Value::Reference {
                                scope: index,
                                name: *name,
                            },
                        }
                    } else if self.is_builtin_name(name) {
                        self.eval_expr(&Expr::Ident(*name, *span))?
                    } else {
                        // POV-Ray refuses to pass a name that holds no value.
                        let mut d = self.runtime.undefined(name, *span);
                        d.message = format!("cannot pass undefined identifier `{name}` to a macro");
                        return Err(d.into());
                    };
                    values.push(value);
                }
                Argument::Expr(Expr::Directive(directive)) => {
                    values.extend(self.macro_directive_argument(directive)?);
                }
                Argument::Expr(expr) => {
                    let (value, rest) = self.eval_value_pair(expr)?;
                    values.push(value);
                    if let Some(rest) = rest {
                        values.push(self.eval_expr(&rest)?);
                    }
                }
                Argument::Block(block) => values.push(self.eval_block(block)?),
            }
        }
        self.run_macro_directives_before(call, call.arguments.len())?;
        Ok(values)
    }

    /// Evaluates an expression where POV-Ray's optional commas matter: `A -b` is two values
    /// when `A` is not a number (an object, a string...). Returns the first value and, for
    /// such a pair, the signed second operand still to evaluate. Each operand is evaluated
    /// once, so macro calls and `rand` in it run once.
    pub(crate) fn eval_value_pair(&mut self, expr: &Expr) -> EvalResult<(Value, Option<Expr>)> {
        use crate::syntax::ast::{BinaryOp, UnaryOp};
        if let Expr::Call(call) = expr {
            if let Some(element) = &call.element {
                // `Fns[I](x)` calls the element; `Normals[I] (-1)` is two items.
                let value = self.eval_expr(element)?;
                return match (value, Self::single_argument(call)) {
                    (
                        value @ (Value::Float(_) | Value::Vector(_) | Value::Colour(_)),
                        Some(rest),
                    ) => Ok((value, Some(rest.clone()))),
                    (value, _) => Ok((self.call_value(value, call)?, None)),
                };
            }
            if let Some((value, rest)) = self.value_before_parentheses(call) {
                // `plane { y (-1) }`: a value that cannot be called, then a float.
                return Ok((value, Some(rest.clone())));
            }
        }
        let Expr::Binary(op @ (BinaryOp::Add | BinaryOp::Subtract), lhs, rhs, span) = expr else {
            return Ok((self.eval_expr(expr)?, None));
        };
        let left = self.eval_expr(lhs)?;
        if matches!(left, Value::Float(_) | Value::Vector(_) | Value::Colour(_)) {
            let right = self.eval_expr(rhs)?;
            return Ok((self.binary(*op, left, right, *span)?, None));
        }
        let sign = if *op == BinaryOp::Subtract {
            UnaryOp::Negate
        } else {
            UnaryOp::Plus
        };
        Ok((left, Some(Expr::Unary(sign, rhs.clone(), rhs.span()))))
    }

    /// For `NAME (EXPR)` where NAME holds a value that cannot be called (a declared vector
    /// or float, or a built-in constant such as `y`), that value: POV-Ray reads the two as
    /// separate items (`plane { y (-.05) }`), measured. `None` for a real call.
    fn value_before_parentheses<'a>(&self, call: &'a Call) -> Option<(Value, &'a Expr)> {
        let rest = Self::single_argument(call)?;
        let value = match self.runtime.lookup(call.name) {
            Some(value @ (Value::Float(_) | Value::Vector(_) | Value::Colour(_))) => value.clone(),
            Some(_) => return None,
            // No built-in constant shares a built-in function's name.
            None => super::expr::builtin_constant(&call.name, self)?,
        };
        Some((value, rest))
    }

    /// The argument of a call with exactly one expression argument and no directives.
    fn single_argument(call: &Call) -> Option<&Expr> {
        match call.arguments.as_slice() {
            [crate::syntax::ast::Argument::Expr(rest)] if call.directives.is_empty() => Some(rest),
            _ => None,
        }
    }

    /// Evaluates a macro call used as a value: its body must yield exactly one value.
    pub(crate) fn call_macro_value(&mut self, call: &Rc<Call>) -> EvalResult<Value> {
        let mut stream = Stream::empty();
        self.enter_macro(call, &mut stream)?;
        let mut result: Option<Value> = None;
        while let Some(item) = self.next_item(&mut stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let span = item.span();
            let value = self.item_value(&item)?;
            if result.is_some() {
                // Unwind what is left of the macro so scopes stay balanced.
                while !stream.is_empty() {
                    self.unwind_frame(&mut stream);
                }
                return Err(self
                    .runtime
                    .error(
                        span,
                        format!(
                            "macro `{}` used as a value produced more than one value",
                            call.name
                        ),
                    )
                    .with_label("extra value")
                    .into());
            }
            result = Some(value);
        }
        result.ok_or_else(|| {
            self.runtime
                .error(
                    call.span,
                    format!("macro `{}` produced no value", call.name),
                )
                .with_label("used as a value here")
                .into()
        })
    }
}
