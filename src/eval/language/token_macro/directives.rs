//! Directives met while running a text macro: conditionals, loops and `#switch` run token by
//! token over the body; the others are parsed whole and run at once.
//!
//! In: a directive token of a body being run ([`TextRun`]). Out: the run moved on (into the
//! chosen branch, back to a loop's start, past a skipped part) and the directive's effects.
//! Holds: every open `#if`, loop and `#switch` is one [`Control`] until its `#end`.

use super::{Prefix, Rule, TextRun};
use crate::diag::{Diagnostic, Span};
use crate::eval::language::stream::{for_continues, Stream};
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{DirectiveKind, Expr};
use crate::syntax::symbol::Symbol;
use crate::syntax::tokens::{next_token, skip_trivia, Token, TokenKind};

/// An open conditional or loop of the body, innermost last.
pub(super) enum Control {
    /// Running the chosen branch of an `#if`/`#ifdef`/`#ifndef`.
    If,
    /// Running a `#while` body that starts at body offset `body`.
    While {
        condition: Expr,
        body: usize,
        iterations: u64,
        span: Span,
    },
    /// Running a `#for` body that starts at body offset `body`.
    For {
        variable: Symbol,
        /// The value the loop last gave the variable, used when the body leaves it no number.
        value: f64,
        end: f64,
        step: f64,
        body: usize,
        iterations: u64,
        span: Span,
    },
    /// Running a `#switch` clause (falling through the following ones without `#break`).
    Switch,
}

/// The grammar rule of a directive run whole when met (the conditionals and loops are run
/// token by token instead).
fn directive_rule(word: &str) -> Option<Rule> {
    Some(match word {
        "declare" => Rule::declare,
        "local" => Rule::local,
        "undef" => Rule::undef,
        "version" => Rule::version,
        "default" => Rule::default,
        "debug" => Rule::debug,
        "warning" => Rule::warning,
        "error" => Rule::error,
        "fopen" => Rule::fopen,
        "fclose" => Rule::fclose,
        "read" => Rule::read,
        "write" => Rule::write,
        "macro" => Rule::macro_directive,
        _ => return None,
    })
}

impl Evaluator {
    /// Runs the directive `token` of a text body; returns whether it ended the body.
    pub(super) fn text_directive(&mut self, run: &mut TextRun, token: Token) -> EvalResult<bool> {
        let word = token.directive_word(run.text);
        let span = run.span(token.start, token.end);
        match word {
            "if" => {
                let chosen = self.text_condition(run)?;
                self.enter_branch(run, chosen)?;
            }
            "ifdef" | "ifndef" => {
                self.expect_punctuation(run, "(", span)?;
                let start = skip_trivia(run.text, run.position);
                let parsed = self.parse_at(run, Rule::ifdef_target, start);
                let (target, length) = self.traced(parsed)?;
                run.position = start + length;
                self.expect_punctuation(run, ")", span)?;
                let Prefix::Target(target) = &*target else {
                    return Ok(false);
                };
                let defined = self.is_defined(target)?;
                self.enter_branch(run, defined != (word == "ifndef"))?;
            }
            "elseif" | "else" => match run.controls.last() {
                Some(Control::Switch) if word == "else" => {}
                Some(Control::If) => {
                    run.controls.pop();
                    run.skip_to_end();
                }
                _ => return Err(self.stray(span, word)),
            },
            "end" => return self.text_end(run),
            "while" => {
                let condition = self.directive_operand(run)?;
                if self.eval_condition(&condition)? {
                    run.controls.push(Control::While {
                        condition,
                        body: run.position,
                        iterations: 0,
                        span,
                    });
                } else {
                    run.skip_to_end();
                }
            }
            "for" => self.text_for(run, span)?,
            "switch" => self.text_switch(run)?,
            "case" | "range" => {
                if !matches!(run.controls.last(), Some(Control::Switch)) {
                    return Err(self.stray(span, word));
                }
                // Falling through from the clause before: the label is not tested.
                self.switch_label(run, word, span)?;
            }
            "break" => return Ok(self.text_break(run)),
            "include" => {
                let parsed = self.parse_at(run, Rule::include, token.start);
                let (parsed, length) = self.traced(parsed)?;
                run.position = token.start + length;
                if let Prefix::Directive(directive) = &*parsed {
                    if let DirectiveKind::Include(name) = &directive.kind {
                        let name = self.eval_string(name)?;
                        self.splice_include(&name, directive.span, run.sink)?;
                    }
                }
            }
            _ => {
                let Some(rule) = directive_rule(word) else {
                    return Err(self.stray(span, word));
                };
                match self.parse_at(run, rule, token.start) {
                    Ok((directive, length)) => {
                        run.position = token.start + length;
                        self.run_whole_directive(&directive)?;
                    }
                    // `#write(` whose arguments, or a declaration whose value, run across
                    // directives: collect it.
                    Err(_) if matches!(rule, Rule::write | Rule::local | Rule::declare) => {
                        self.start_pending(run, token, rule)?
                    }
                    Err(d) => return Err(self.traced(Err(d))?),
                }
            }
        }
        Ok(false)
    }

    /// A parse result whose error carries the macro call trace.
    pub(super) fn traced<T>(&self, parsed: Result<T, Box<Diagnostic>>) -> EvalResult<T> {
        parsed.map_err(|mut d| {
            d.trace = self.runtime.trace_for_diagnostic();
            d
        })
    }

    /// An error for a directive that belongs to no open directive of the body.
    fn stray(&self, span: Span, word: &str) -> Box<Diagnostic> {
        self.runtime
            .error(
                span,
                format!("`#{word}` outside the directive it belongs to"),
            )
            .with_label("nothing open here takes it")
            .into()
    }

    /// Runs a directive parsed whole (`#local`, `#write`, `#fopen` ...) at once.
    pub(super) fn run_whole_directive(&mut self, parsed: &Prefix) -> EvalResult<()> {
        let Prefix::Directive(directive) = parsed else {
            return Ok(());
        };
        // None of these directives streams anything.
        self.run_directive(directive, &mut Stream::empty())
    }

    /// Parses an expression at the run's position (`rule` is `expr` or `full_expr`).
    fn text_expression(&mut self, run: &mut TextRun, rule: Rule) -> EvalResult<Expr> {
        let start = skip_trivia(run.text, run.position);
        let parsed = self.parse_at(run, rule, start);
        let (parsed, length) = self.traced(parsed)?;
        run.position = start + length;
        match &*parsed {
            Prefix::Expr(expr) => Ok(expr.clone()),
            _ => Err(self
                .runtime
                .error(run.span(start, start + length), "expected an expression")
                .into()),
        }
    }

    /// Parses and tests a condition at the run's position.
    fn text_condition(&mut self, run: &mut TextRun) -> EvalResult<bool> {
        let condition = self.directive_operand(run)?;
        self.eval_condition(&condition)
    }

    /// Parses the operand of `#if`, `#while`, `#switch` or `#case`: as in POV-Ray, just the
    /// parenthesised expression when there is one (`#if (A) -1 #end` emits `-1`).
    fn directive_operand(&mut self, run: &mut TextRun) -> EvalResult<Expr> {
        let start = skip_trivia(run.text, run.position);
        let rule = if run.text[start..].starts_with('(') {
            Rule::paren
        } else {
            Rule::expr
        };
        self.text_expression(run, rule)
    }

    /// Reads the punctuation `expected` at the run's position.
    fn expect_punctuation(&self, run: &mut TextRun, expected: &str, at: Span) -> EvalResult<()> {
        match next_token(run.text, run.position) {
            Some(token) if token.text(run.text) == expected => {
                run.position = token.end;
                Ok(())
            }
            found => {
                let span = found.map_or(at, |token| run.span(token.start, token.end));
                Err(self
                    .runtime
                    .error(span, format!("expected `{expected}`"))
                    .with_label(format!("expected `{expected}` here"))
                    .into())
            }
        }
    }

    /// Enters the branch of an `#if` whose first condition gave `chosen`: runs it, or skips to
    /// the first `#elseif` that holds or the `#else` (or past the `#end`).
    fn enter_branch(&mut self, run: &mut TextRun, mut chosen: bool) -> EvalResult<()> {
        loop {
            if chosen {
                run.controls.push(Control::If);
                return Ok(());
            }
            match run.skip_to(&["elseif", "else"]) {
                Some("elseif") => chosen = self.text_condition(run)?,
                Some("else") => chosen = true,
                _ => return Ok(()),
            }
        }
    }

    /// `#end`: closes the innermost open directive, repeating a loop whose condition holds;
    /// returns whether it ended the body.
    fn text_end(&mut self, run: &mut TextRun) -> EvalResult<bool> {
        match run.controls.pop() {
            None => return Ok(true),
            Some(Control::If | Control::Switch) => {}
            Some(Control::While {
                condition,
                body,
                iterations,
                span,
            }) => {
                if iterations + 1 >= self.runtime.options().limits.iterations {
                    return Err(self.loop_limit(span));
                }
                self.runtime.check_deadline(span)?;
                if self.eval_condition(&condition)? {
                    run.position = body;
                    run.controls.push(Control::While {
                        condition,
                        body,
                        iterations: iterations + 1,
                        span,
                    });
                }
            }
            Some(Control::For {
                variable,
                value,
                end,
                step,
                body,
                iterations,
                span,
            }) => {
                if iterations + 1 >= self.runtime.options().limits.iterations {
                    return Err(self.loop_limit(span));
                }
                self.runtime.check_deadline(span)?;
                // POV-Ray reads the loop variable back, so the body may change it.
                let current = match self.runtime.lookup(variable) {
                    Some(Value::Float(current)) => *current,
                    _ => value,
                };
                let next = current + step;
                self.assign_local(&variable, Value::Float(next));
                if for_continues(next, end, step) {
                    run.position = body;
                    run.controls.push(Control::For {
                        variable,
                        value: next,
                        end,
                        step,
                        body,
                        iterations: iterations + 1,
                        span,
                    });
                }
            }
        }
        Ok(false)
    }

    /// `#for (Name, start, end[, step])`.
    fn text_for(&mut self, run: &mut TextRun, span: Span) -> EvalResult<()> {
        self.expect_punctuation(run, "(", span)?;
        let name = next_token(run.text, run.position)
            .filter(|token| token.kind == TokenKind::Word)
            .ok_or_else(|| {
                Box::new(
                    self.runtime
                        .error(span, "expected the loop variable")
                        .with_label("`#for` needs `(Name, start, end)`"),
                )
            })?;
        run.position = name.end;
        let variable = Symbol::intern(name.text(run.text));
        self.expect_punctuation(run, ",", span)?;
        let start = self.text_expression(run, Rule::full_expr)?;
        self.expect_punctuation(run, ",", span)?;
        let end = self.text_expression(run, Rule::full_expr)?;
        let step = match next_token(run.text, run.position) {
            Some(token) if token.text(run.text) == "," => {
                run.position = token.end;
                Some(self.text_expression(run, Rule::full_expr)?)
            }
            _ => None,
        };
        self.expect_punctuation(run, ")", span)?;
        let start = self.eval_float(&start)?;
        let end = self.eval_float(&end)?;
        let step = match step {
            Some(step) => self.eval_float(&step)?,
            None => 1.0,
        };
        if step == 0.0 {
            return Err(self
                .runtime
                .error(span, "`#for` step is zero")
                .with_label("this loop would never end")
                .into());
        }
        self.assign_local(&variable, Value::Float(start));
        if for_continues(start, end, step) {
            run.controls.push(Control::For {
                variable,
                value: start,
                end,
                step,
                body: run.position,
                iterations: 0,
                span,
            });
        } else {
            run.skip_to_end();
        }
        Ok(())
    }

    /// `#switch (value)`: runs from the first `#case`/`#range` that holds, or the `#else`.
    fn text_switch(&mut self, run: &mut TextRun) -> EvalResult<()> {
        let value = self.directive_operand(run)?;
        let value = self.eval_float(&value)?;
        loop {
            let label_start = run.position;
            match run.skip_to(&["case", "range", "else"]) {
                Some(word @ ("case" | "range")) => {
                    let span = run.span(label_start, run.position);
                    let (low, high) = self.switch_label(run, word, span)?;
                    let holds = match high {
                        None => (self.eval_float(&low)? - value).abs() < 1e-10,
                        Some(high) => {
                            let low = self.eval_float(&low)?;
                            low <= value && value <= self.eval_float(&high)?
                        }
                    };
                    if holds {
                        run.controls.push(Control::Switch);
                        return Ok(());
                    }
                }
                Some("else") => {
                    run.controls.push(Control::Switch);
                    return Ok(());
                }
                _ => return Ok(()),
            }
        }
    }

    /// Reads a `#case (value)` or `#range (low, high)` label: the value, or low and high.
    fn switch_label(
        &mut self,
        run: &mut TextRun,
        word: &str,
        span: Span,
    ) -> EvalResult<(Expr, Option<Expr>)> {
        if word == "case" {
            return Ok((self.directive_operand(run)?, None));
        }
        self.expect_punctuation(run, "(", span)?;
        let low = self.text_expression(run, Rule::full_expr)?;
        self.expect_punctuation(run, ",", span)?;
        let high = self.text_expression(run, Rule::full_expr)?;
        self.expect_punctuation(run, ")", span)?;
        Ok((low, Some(high)))
    }

    /// `#break`: leaves the innermost loop or switch, or the macro when none is open; returns
    /// whether it ended the body.
    fn text_break(&mut self, run: &mut TextRun) -> bool {
        while let Some(control) = run.controls.pop() {
            run.skip_to_end();
            if !matches!(control, Control::If) {
                return false;
            }
        }
        true
    }
}
