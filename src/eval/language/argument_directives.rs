//! Directives among a call's arguments (`M(1, #declare R = 5; R)`, `max(1, #local Q = 2; Q)`):
//! each runs once, in the caller's scope, after the arguments before it are evaluated and
//! before the ones after it.
//!
//! In: calls whose lowered `directives` are not empty. Out: the directives' effects (variables,
//! messages, files...), or a diagnostic when one leaves a value or stands where POV-Ray
//! refuses it. Holds: for calls of built-in and user functions and splines, which read their
//! arguments through [`Evaluator::argument`], how far each running call has got.

use super::stream::Stream;
use super::value::Value;
use crate::diag::Span;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{ArgumentDirective, Call, Directive, Item};
use std::rc::Rc;

/// How far a running non-macro call has got through its argument directives.
pub(crate) struct DirectiveCursor {
    /// The call, compared by address.
    call: Rc<Call>,
    /// The index of the next directive to run.
    next: usize,
}

impl Evaluator {
    /// Runs `call` (a built-in or user function or a spline) through `dispatch`, running its
    /// argument directives as the arguments after them are read and the rest at the end.
    pub(crate) fn with_argument_directives<T>(
        &mut self,
        call: &Rc<Call>,
        dispatch: impl FnOnce(&mut Self) -> EvalResult<T>,
    ) -> EvalResult<T> {
        if call.directives.is_empty() {
            return dispatch(self);
        }
        self.runtime.directive_cursors.push(DirectiveCursor {
            call: call.clone(),
            next: 0,
        });
        let result = dispatch(self).and_then(|value| {
            self.run_directives_before(call, call.arguments.len())?;
            Ok(value)
        });
        self.runtime.directive_cursors.pop();
        result
    }

    /// Runs the directives of the running `call` that stand before its argument `index`
    /// and have not run yet (nothing when `call` is not the innermost running call).
    pub(crate) fn run_directives_before(&mut self, call: &Call, index: usize) -> EvalResult<()> {
        loop {
            let Some(cursor) = self.runtime.directive_cursors.last_mut() else {
                return Ok(());
            };
            if !std::ptr::eq(&*cursor.call, call) {
                return Ok(());
            }
            let Some(directive) = call.directives.get(cursor.next) else {
                return Ok(());
            };
            if directive.before_argument > index {
                return Ok(());
            }
            // Advanced before running, so that a call the directive makes never runs it again.
            cursor.next += 1;
            self.run_argument_directive(directive)?;
        }
    }

    /// Runs the directives of a macro call that stand before its argument `index` (those
    /// after the last argument when `index` is the number of arguments). POV-Ray reads a
    /// directive in a macro call only after `(` or a comma.
    pub(crate) fn run_macro_directives_before(
        &mut self,
        call: &Call,
        index: usize,
    ) -> EvalResult<()> {
        for directive in call
            .directives
            .iter()
            .filter(|d| d.before_argument == index)
        {
            if directive.follows_argument {
                // The wording of the text macros' check (token_macro), which meets the same
                // case token by token.
                return Err(self
                    .runtime
                    .error(directive.directive.span, "directive after a macro argument")
                    .with_label(
                        "POV-Ray ends the argument list here: put the directive before an \
                         argument",
                    )
                    .with_secondary(call.span, "the macro call")
                    .with_help("a directive may follow `(` or a comma")
                    .into());
            }
            self.run_argument_directive(directive)?;
        }
        Ok(())
    }

    /// A directive standing as a whole macro argument: the value it leaves, if any (`M(1, 2,
    /// #if (C) #declare R = 1; #end)` passes two arguments).
    pub(crate) fn macro_directive_argument(
        &mut self,
        directive: &Rc<Directive>,
    ) -> EvalResult<Option<Value>> {
        let mut left = self.directive_values(directive)?.into_iter();
        let value = left.next().map(|(value, _)| value);
        if let Some((_, span)) = left.next() {
            return Err(self
                .runtime
                .error(
                    span,
                    "a directive standing as a macro argument left two values",
                )
                .with_label("the second value")
                .with_secondary(directive.span, "the directive")
                .with_help("separate arguments with commas outside the directive")
                .into());
        }
        Ok(value)
    }

    /// Runs the directives that stand before argument `index` of a call read in one pass
    /// (a call in a function body, compiled where the function is declared, when POV-Ray
    /// runs them).
    pub(crate) fn run_directives_at(&mut self, call: &Call, index: usize) -> EvalResult<()> {
        for directive in call
            .directives
            .iter()
            .filter(|d| d.before_argument == index)
        {
            self.run_argument_directive(directive)?;
        }
        Ok(())
    }

    /// Runs one directive among a call's arguments to its end; it may not leave a value (one
    /// that ends a slot of its own is that slot's argument instead, see `lower.rs`).
    fn run_argument_directive(&mut self, directive: &ArgumentDirective) -> EvalResult<()> {
        let left = self.directive_values(&directive.directive)?;
        if let Some((_, span)) = left.first() {
            return Err(self
                .runtime
                .error(
                    *span,
                    "a directive among a call's arguments left a value where POV-Ray reads none",
                )
                .with_label("this value")
                .with_secondary(directive.directive.span, "left by this directive")
                .with_help(
                    "a directive may leave a value only as a whole argument, alone between \
                     commas: `max(1, #if (C) 2 #else 3 #end)`, `Add(1, #include \"value.inc\")`",
                )
                .into());
        }
        Ok(())
    }

    /// Runs a directive in the current scope and returns the values it leaves, with their
    /// spans (commas between them are skipped): to its end, or up to the second value,
    /// which is already an error for both callers (a loop emitting values without end
    /// would otherwise fill memory).
    fn directive_values(&mut self, directive: &Rc<Directive>) -> EvalResult<Vec<(Value, Span)>> {
        let items: Rc<[Item]> = Rc::from(vec![Item::Directive(directive.clone())]);
        let mut stream = Stream::new(items);
        let mut values = Vec::new();
        while let Some(item) = self.next_item(&mut stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let span = item.span();
            values.push((self.item_value(&item)?, span));
            if values.len() == 2 {
                break;
            }
        }
        Ok(values)
    }
}
