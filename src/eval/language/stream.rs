//! Item streams: the items of a block body, with directives run and macro calls expanded
//! as they are reached, the way POV-Ray reads its token stream.

use super::value::Value;
use crate::diag::Span;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Directive, DirectiveKind, Expr, Item, MessageLevel, SwitchLabel};
use crate::syntax::symbol::Symbol;
use std::rc::Rc;

/// A stack of item lists being read; the top frame is read first.
pub(crate) struct Stream {
    frames: Vec<Frame>,
    pushed_back: Option<Item>,
    /// The span of the last item read: where a block that ends too early is reported
    /// ("expected the radius, found the end of the block" points after it).
    last_read: Option<crate::diag::Span>,
}

struct Frame {
    items: Rc<[Item]>,
    position: usize,
    kind: FrameKind,
}

enum FrameKind {
    /// A block body or a chosen `#if` branch.
    Plain,
    /// A macro body: its scope and trace entry are dropped when the frame ends.
    Macro,
    /// An included file: its scope and trace entry are dropped when the frame ends.
    Include,
    /// A `#while` loop body.
    While {
        directive: Rc<Directive>,
        iterations: u64,
    },
    /// A `#for` loop body.
    For {
        directive: Rc<Directive>,
        value: f64,
        end: f64,
        step: f64,
        iterations: u64,
    },
    /// A `#switch` clause body; `clause` is the index of the clause running.
    Switch {
        directive: Rc<Directive>,
        clause: usize,
    },
}

impl Stream {
    /// A stream over `items`.
    pub(crate) fn new(items: Rc<[Item]>) -> Stream {
        Stream {
            frames: vec![Frame {
                items,
                position: 0,
                kind: FrameKind::Plain,
            }],
            pushed_back: None,
            last_read: None,
        }
    }

    /// Puts an item back to be returned by the next read.
    pub(crate) fn push_back(&mut self, item: Item) {
        self.pushed_back = Some(item);
    }

    fn push(&mut self, items: Rc<[Item]>, kind: FrameKind) {
        self.frames.push(Frame {
            items,
            position: 0,
            kind,
        });
    }

    pub(crate) fn push_include(&mut self, items: Rc<[Item]>) {
        self.push(items, FrameKind::Include);
    }

    /// Starts a macro body (its scope and trace entry are pushed by the caller).
    pub(crate) fn push_macro(&mut self, items: Rc<[Item]>) {
        self.push(items, FrameKind::Macro);
    }

    /// A stream with nothing to read yet.
    pub(crate) fn empty() -> Stream {
        Stream {
            frames: Vec::new(),
            pushed_back: None,
            last_read: None,
        }
    }

    /// The span of the last item read, if any.
    pub(crate) fn last_read(&self) -> Option<crate::diag::Span> {
        self.last_read
    }

    /// Whether every frame has been read.
    pub(crate) fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }
}

impl Evaluator {
    /// The next item of the stream that is not a directive, expanding macro calls.
    pub(crate) fn next_item(&mut self, stream: &mut Stream) -> EvalResult<Option<Item>> {
        if let Some(item) = stream.pushed_back.take() {
            return Ok(Some(item));
        }
        loop {
            let Some(frame) = stream.frames.last_mut() else {
                return Ok(None);
            };
            if frame.position >= frame.items.len() {
                self.end_frame(stream)?;
                continue;
            }
            let item = frame.items[frame.position].clone();
            frame.position += 1;
            match item {
                Item::Directive(directive) => self.run_directive(&directive, stream)?,
                Item::Expr(Expr::Call(ref call))
                    if call.element.is_none() && self.is_macro(call.name) =>
                {
                    self.enter_macro(call, stream)?
                }
                other => {
                    stream.last_read = Some(other.span());
                    return Ok(Some(other));
                }
            }
        }
    }

    /// Like [`Self::next_item`] but consumes a following comma-free peek: returns the item and
    /// leaves the stream positioned after it.
    pub(crate) fn peek_item(&mut self, stream: &mut Stream) -> EvalResult<Option<Item>> {
        let item = self.next_item(stream)?;
        if let Some(item) = &item {
            stream.push_back(item.clone());
        }
        Ok(item)
    }

    /// Skips one comma if it comes next.
    pub(crate) fn skip_comma(&mut self, stream: &mut Stream) -> EvalResult<()> {
        match self.next_item(stream)? {
            Some(Item::Comma(_)) | None => {}
            Some(other) => stream.push_back(other),
        }
        Ok(())
    }

    fn is_macro(&self, name: Symbol) -> bool {
        matches!(self.runtime.lookup(name), Some(Value::Macro(_)))
    }

    /// Pops the top frame, or restarts it when it is a loop whose condition still holds.
    fn end_frame(&mut self, stream: &mut Stream) -> EvalResult<()> {
        let Some(frame) = stream.frames.last_mut() else {
            return Ok(());
        };
        match &mut frame.kind {
            FrameKind::Plain => {}
            FrameKind::Macro | FrameKind::Include => {
                self.runtime.scopes.pop();
                self.runtime.trace.pop();
                self.runtime.nesting -= 1;
            }
            FrameKind::While {
                directive,
                iterations,
            } => {
                let directive = directive.clone();
                let DirectiveKind::While { condition, .. } = &directive.kind else {
                    unreachable!()
                };
                *iterations += 1;
                let count = *iterations;
                if count >= self.runtime.options().limits.iterations {
                    return Err(self.loop_limit(directive.span));
                }
                self.runtime.check_deadline(directive.span)?;
                if self.eval_condition(condition)? {
                    if let Some(frame) = stream.frames.last_mut() {
                        frame.position = 0;
                    }
                    return Ok(());
                }
            }
            FrameKind::For {
                directive,
                value,
                end,
                step,
                iterations,
            } => {
                let directive = directive.clone();
                let DirectiveKind::For { variable, .. } = &directive.kind else {
                    unreachable!()
                };
                *iterations += 1;
                // POV-Ray reads the loop variable back, so the body may change it.
                let current = match self.runtime.lookup(*variable) {
                    Some(Value::Float(f)) => *f,
                    _ => *value,
                };
                let next = current + *step;
                let (end, step, count) = (*end, *step, *iterations);
                if count >= self.runtime.options().limits.iterations {
                    return Err(self.loop_limit(directive.span));
                }
                self.runtime.check_deadline(directive.span)?;
                // The variable ends one step past the last value, as in POV-Ray.
                self.assign_local(variable, Value::Float(next));
                if for_continues(next, end, step) {
                    if let Some(Frame {
                        kind: FrameKind::For { value, .. },
                        position,
                        ..
                    }) = stream.frames.last_mut()
                    {
                        *value = next;
                        *position = 0;
                    }
                    return Ok(());
                }
            }
            FrameKind::Switch { directive, clause } => {
                // Without `#break`, POV-Ray falls through into the following clauses' bodies
                // (their labels are not tested) and then the `#else`.
                let directive = directive.clone();
                let next = *clause + 1;
                stream.frames.pop();
                if let DirectiveKind::Switch {
                    clauses, otherwise, ..
                } = &directive.kind
                {
                    if let Some(clause) = clauses.get(next) {
                        let kind = FrameKind::Switch {
                            directive: directive.clone(),
                            clause: next,
                        };
                        stream.push(clause.body.clone(), kind);
                    } else if let Some(otherwise) = otherwise {
                        stream.push(otherwise.clone(), FrameKind::Plain);
                    }
                }
                return Ok(());
            }
        }
        stream.frames.pop();
        Ok(())
    }

    pub(crate) fn loop_limit(&self, span: Span) -> Box<crate::diag::Diagnostic> {
        let limit = self.runtime.options().limits.iterations;
        self.runtime
            .error(span, format!("loop ran {limit} times without ending"))
            .with_label("this loop")
            .with_help(format!(
                "check that the loop condition eventually becomes false; {}",
                crate::limits::Limits::raise_hint("iterations", limit)
            ))
            .into()
    }

    /// `#declare`-style assignment of a plain name (the innermost existing version, else global).
    pub(crate) fn assign_declare_name(&mut self, name: &Symbol, value: Value) {
        let (scope, name) = self.runtime.declare_slot(*name);
        self.runtime.scopes.insert(scope, name, value);
    }

    /// `#local`-style assignment of a plain name in the innermost scope.
    pub(crate) fn assign_local(&mut self, name: &Symbol, value: Value) {
        let (scope, name) = self.runtime.local_slot(*name);
        self.runtime.scopes.insert(scope, name, value);
    }

    pub(crate) fn eval_condition(&mut self, condition: &Expr) -> EvalResult<bool> {
        let value = self.eval_float(condition)?;
        Ok(value != 0.0)
    }

    /// Runs one directive, possibly pushing frames onto the stream.
    pub(crate) fn run_directive(
        &mut self,
        directive: &Rc<Directive>,
        stream: &mut Stream,
    ) -> EvalResult<()> {
        let span = directive.span;
        if directive.without_hash {
            let word = if matches!(directive.kind, DirectiveKind::Include(..)) {
                "include"
            } else {
                "declare"
            };
            self.runtime.warn(
                Span {
                    end: span.start + word.len() as u32,
                    ..span
                },
                format!("`{word}` should be `#{word}` (POV-Ray 2's spelling, still read)"),
            );
        }
        match &directive.kind {
            DirectiveKind::Declare {
                local,
                target,
                prelude,
                value,
                layers,
            } => {
                if !prelude.is_empty() {
                    // Only directives: the stream returns nothing, having run them all.
                    let mut directives = Stream::new(prelude.clone());
                    if let Some(item) = self.next_item(&mut directives)? {
                        return Err(self
                            .runtime
                            .error(item.span(), "expected the declared value")
                            .into());
                    }
                }
                let value = self.item_value(value)?;
                let value = self.layer_textures(value, layers)?;
                self.assign(*local, target, value)?;
            }
            DirectiveKind::TextRun { text, span } => {
                let items = self.expand_text_macro(text, *span, "file")?;
                stream.push(items, FrameKind::Plain);
            }
            DirectiveKind::Undef(target) if !target.indices.is_empty() => {
                self.undefine_element(target)?;
            }
            DirectiveKind::Undef(target) => {
                let name = target.name;
                if self.runtime.scopes.innermost_holder(name).is_none() {
                    self.runtime.warn(
                        target.span,
                        format!("`#undef` of unknown identifier `{name}`"),
                    );
                }
                self.undefine(name);
            }
            DirectiveKind::If { branches, .. } => self.run_first_true_branch(branches, stream)?,
            DirectiveKind::IfDefined {
                negate,
                target,
                then,
                rest,
            } => {
                let defined = self.is_defined(target)?;
                if defined != *negate {
                    stream.push(then.clone(), FrameKind::Plain);
                } else {
                    self.run_first_true_branch(rest, stream)?;
                }
            }
            DirectiveKind::While { condition, body } => {
                if self.eval_condition(condition)? {
                    stream.push(
                        body.clone(),
                        FrameKind::While {
                            directive: directive.clone(),
                            iterations: 0,
                        },
                    );
                }
            }
            DirectiveKind::For {
                variable,
                start,
                end,
                step,
                body,
                ..
            } => {
                let start = self.eval_float(start)?;
                let end = self.eval_float(end)?;
                let step = match step {
                    Some(step) => self.eval_float(step)?,
                    None => 1.0,
                };
                if step == 0.0 {
                    return Err(self
                        .runtime
                        .error(span, "`#for` step is zero")
                        .with_label("this loop would never end")
                        .into());
                }
                // POV-Ray makes the loop variable local to the current macro or file.
                self.assign_local(variable, Value::Float(start));
                if for_continues(start, end, step) {
                    let kind = FrameKind::For {
                        directive: directive.clone(),
                        value: start,
                        end,
                        step,
                        iterations: 0,
                    };
                    stream.push(body.clone(), kind);
                }
            }
            DirectiveKind::Switch { .. } => self.run_switch(directive, stream)?,
            DirectiveKind::Break => self.run_break(stream),
            DirectiveKind::Macro(definition) => {
                self.runtime
                    .scopes
                    .insert(0, definition.name, Value::Macro(definition.clone()));
            }
            DirectiveKind::Include(name) => {
                let name = self
                    .eval_string(name)
                    .map_err(|d| unquoted_include(name, d))?;
                self.runtime.include(&name, span, stream)?;
            }
            DirectiveKind::Version(version) => {
                let version = self.eval_float(version)?;
                self.runtime.set_version(version);
            }
            DirectiveKind::Default(items) => self.run_default(items.clone())?,
            DirectiveKind::Message { level, text } => {
                let text = self.eval_string(text)?;
                match level {
                    MessageLevel::Debug => {
                        if self.runtime.options.print_debug {
                            eprint!("{text}");
                        }
                    }
                    MessageLevel::Warning => {
                        let mut d =
                            crate::diag::Diagnostic::warning(span, text.trim_end().to_string());
                        d.trace = self.runtime.trace_for_diagnostic();
                        self.runtime.warnings.push(d);
                    }
                    MessageLevel::Error => {
                        return Err(self
                            .runtime
                            .error(span, text.trim_end().to_string())
                            .with_label("`#error` reached")
                            .into())
                    }
                }
            }
            DirectiveKind::FileOpen { handle, path, mode } => {
                self.file_open(handle, path, mode, span)?
            }
            DirectiveKind::FileClose(handle) => self.file_close(handle, span)?,
            DirectiveKind::FileRead { handle, targets } => self.file_read(handle, targets, span)?,
            DirectiveKind::FileWrite { handle, values } => self.file_write(handle, values, span)?,
        }
        Ok(())
    }

    /// Streams the body of the first branch whose condition holds (`#else` always holds).
    fn run_first_true_branch(
        &mut self,
        branches: &[crate::syntax::ast::Branch],
        stream: &mut Stream,
    ) -> EvalResult<()> {
        for branch in branches {
            let chosen = match &branch.condition {
                Some(condition) => self.eval_condition(condition)?,
                None => true,
            };
            if chosen {
                stream.push(branch.body.clone(), FrameKind::Plain);
                break;
            }
        }
        Ok(())
    }

    /// Starts the first clause whose label holds, or the `#else`.
    fn run_switch(&mut self, directive: &Rc<Directive>, stream: &mut Stream) -> EvalResult<()> {
        let DirectiveKind::Switch {
            value,
            clauses,
            otherwise,
        } = &directive.kind
        else {
            return Ok(());
        };
        let value = self.eval_float(value)?;
        for (index, clause) in clauses.iter().enumerate() {
            let holds = match &clause.label {
                SwitchLabel::Case(case) => (self.eval_float(case)? - value).abs() < 1e-10,
                SwitchLabel::Range(low, high) => {
                    let low = self.eval_float(low)?;
                    let high = self.eval_float(high)?;
                    low <= value && value <= high
                }
            };
            if holds {
                stream.push(
                    clause.body.clone(),
                    FrameKind::Switch {
                        directive: directive.clone(),
                        clause: index,
                    },
                );
                return Ok(());
            }
        }
        if let Some(otherwise) = otherwise {
            stream.push(otherwise.clone(), FrameKind::Plain);
        }
        Ok(())
    }

    /// `#break`: leaves the innermost switch, loop or macro.
    fn run_break(&mut self, stream: &mut Stream) {
        while let Some(frame) = stream.frames.pop() {
            match frame.kind {
                FrameKind::Plain => continue,
                FrameKind::Include => {
                    // A break never leaves a file: put it back and stop.
                    stream.frames.push(frame);
                    return;
                }
                FrameKind::Macro => {
                    self.runtime.scopes.pop();
                    self.runtime.trace.pop();
                    self.runtime.nesting -= 1;
                    return;
                }
                FrameKind::While { .. } | FrameKind::For { .. } | FrameKind::Switch { .. } => {
                    return
                }
            }
        }
    }

    /// Drops the top frame, leaving its scope if it has one (used when a value-mode macro
    /// call fails part-way).
    pub(crate) fn unwind_frame(&mut self, stream: &mut Stream) {
        if let Some(frame) = stream.frames.pop() {
            if matches!(frame.kind, FrameKind::Macro | FrameKind::Include) {
                self.runtime.scopes.pop();
                self.runtime.trace.pop();
                self.runtime.nesting -= 1;
            }
        }
    }

    /// Whether `#ifdef` finds the target (an identifier or an assigned array element).
    pub(crate) fn is_defined(&mut self, target: &crate::syntax::ast::Target) -> EvalResult<bool> {
        let Some(value) = self.runtime.lookup(target.name).cloned() else {
            return Ok(false);
        };
        if target.indices.is_empty() {
            return Ok(true);
        }
        let Value::Array(array) = value else {
            return Ok(false);
        };
        let mut indices = Vec::new();
        for index in &target.indices {
            indices.push(self.eval_float(index)?);
        }
        Ok(array_offset(&array.sizes, &indices)
            .and_then(|o| array.elements.get(o))
            .is_some_and(|e| e.is_some()))
    }

    /// `#undef A[i]..`: the element becomes uninitialised, as in POV-Ray (reading it is
    /// then an error, `#ifdef` says no). An index out of range or a name that is not an
    /// array is an error; an unknown name is warned about, as for a plain `#undef`.
    fn undefine_element(&mut self, target: &crate::syntax::ast::Target) -> EvalResult<()> {
        let mut indices = Vec::new();
        for index in &target.indices {
            indices.push(self.eval_float(index)?);
        }
        if self.runtime.scopes.innermost_holder(target.name).is_none() {
            self.runtime.warn(
                target.span,
                format!("`#undef` of unknown identifier `{}`", target.name),
            );
            return Ok(());
        }
        let (scope, name) = self.runtime.declare_slot(target.name);
        let offset = self.element_offset(scope, name, target, &indices)?;
        if let Some(Value::Array(array)) = self.runtime.scopes.get_mut(scope, name) {
            Rc::make_mut(array).elements[offset] = None;
        }
        Ok(())
    }

    /// The offset of `target`'s element in the array held at (`scope`, `name`), or the
    /// error for a name that is not an array or an index out of range.
    fn element_offset(
        &self,
        scope: usize,
        name: Symbol,
        target: &crate::syntax::ast::Target,
        indices: &[f64],
    ) -> EvalResult<usize> {
        let sizes = match self.runtime.scopes.get(scope, name) {
            Some(Value::Array(array)) => &array.sizes,
            _ => {
                return Err(self
                    .runtime
                    .error(target.span, format!("`{}` is not an array", target.name))
                    .with_label("indexed here")
                    .into())
            }
        };
        array_offset(sizes, indices).ok_or_else(|| {
            self.runtime
                .error(
                    target.span,
                    format!("array index {indices:?} out of range for size {sizes:?}"),
                )
                .with_label("index out of range")
                .into()
        })
    }

    /// Stores a value for `#declare`/`#local`, including array elements.
    pub(crate) fn assign(
        &mut self,
        local: bool,
        target: &crate::syntax::ast::Target,
        value: Value,
    ) -> EvalResult<()> {
        let value = match value {
            Value::Reference { scope, name } => match self.runtime.lookup_from(scope, name) {
                Some(v) => v.clone(),
                None => return Err(self.runtime.undefined(&name, target.span).into()),
            },
            v => v,
        };
        let (scope, name) = if local {
            self.runtime.local_slot(target.name)
        } else {
            self.runtime.declare_slot(target.name)
        };
        if target.indices.is_empty() {
            self.runtime.scopes.insert(scope, name, value);
            return Ok(());
        }
        let mut indices = Vec::new();
        for index in &target.indices {
            indices.push(self.eval_float(index)?);
        }
        let (scope, name) = if local && self.runtime.scopes.get(scope, name).is_none() {
            self.runtime.declare_slot(target.name)
        } else {
            (scope, name)
        };
        let offset = self.element_offset(scope, name, target, &indices)?;
        // Changed in place: the elements are copied only when another value shares them.
        if let Some(Value::Array(array)) = self.runtime.scopes.get_mut(scope, name) {
            Rc::make_mut(array).elements[offset] = Some(value);
        }
        Ok(())
    }
}

/// Row-major offset of an element, or `None` when an index is out of range.
pub(crate) fn array_offset(sizes: &[usize], indices: &[f64]) -> Option<usize> {
    if sizes.len() != indices.len() {
        return None;
    }
    let mut offset = 0usize;
    for (size, index) in sizes.iter().zip(indices) {
        let i = index.trunc();
        if i < 0.0 || i >= *size as f64 {
            return None;
        }
        offset = offset * size + i as usize;
    }
    Some(offset)
}

pub(crate) fn for_continues(value: f64, end: f64, step: f64) -> bool {
    if step > 0.0 {
        value <= end + 1e-10
    } else {
        value >= end - 1e-10
    }
}

/// `#include colors.inc`: a file name written without quotes reads as an undefined name;
/// say that the quotes are missing (any other error of the name is kept).
fn unquoted_include(
    name: &crate::syntax::ast::Expr,
    d: Box<crate::diag::Diagnostic>,
) -> Box<crate::diag::Diagnostic> {
    use crate::syntax::ast::Expr;
    let file = match name {
        Expr::Ident(word, _) => word.to_string(),
        Expr::Member(base, extension, _) => match &**base {
            Expr::Ident(word, _) => format!("{word}.{extension}"),
            _ => return d,
        },
        _ => return d,
    };
    if !d.message.starts_with("undefined identifier") {
        return d;
    }
    let mut quoted =
        crate::diag::Diagnostic::error(name.span(), "the file name of `#include` needs quotes")
            .with_label("read as an undefined name")
            .with_help(format!("write `#include \"{file}\"`"));
    quoted.trace = d.trace.clone();
    Box::new(quoted)
}
