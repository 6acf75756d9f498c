//! Text macros: running a macro body whose directives cut across braces, token by token.
//!
//! In: a macro's body text ([`MacroBody::Text`](crate::syntax::ast::MacroBody)), called with
//! its arguments already bound in the innermost scope. Out: the items the body produced,
//! parsed from the text it emitted, for the caller's stream; directives (`#if`, loops,
//! `#local`, `#write` whose argument list spans directives, ...) run as they are met, and
//! macro calls and `#include`s met in the body run at once with their tokens spliced in, as
//! in POV-Ray's token stream. Holds: a name bound to a variable when it is emitted is replaced
//! by its value (a number or vector) or by a hidden name bound (in the text macro's scope) to
//! a snapshot of its value at that moment, so `P[J]` emitted inside a loop keeps that pass's
//! `J`; spans of everything parsed from the emitted text point into the macro body.

use super::value::Value;
use super::{Entered, Entering, EvalResult, Evaluator, Scope};
use crate::diag::{Diagnostic, FileId, Span};
use crate::syntax::ast::{Item, MacroBody};
use crate::syntax::mapping::OffsetMap;
use crate::syntax::symbol::Symbol;
use crate::syntax::tokens::{next_token, Token, TokenKind};
use crate::syntax::{parse_generated, parse_prefix, Prefix, Rule};
use std::collections::HashMap;
use std::rc::Rc;

mod directives;

use directives::Control;

/// Text emitted by a text macro, with the map leading it back to the body.
#[derive(Default)]
struct Emitted {
    text: String,
    map: OffsetMap,
    /// Where the last token emitted ends in its file: a gap before the next one (or a token
    /// from elsewhere) becomes a space.
    last_end: Option<(FileId, u32)>,
}

impl Emitted {
    /// Appends `text` standing for the source token at `source`.
    fn push(&mut self, text: &str, source: Span) {
        if self.last_end != Some((source.file, source.start)) && !self.text.is_empty() {
            self.text.push(' ');
        }
        self.map.record(self.text.len(), source);
        self.text.push_str(text);
        self.last_end = Some((source.file, source.end));
    }
}

/// A directive that runs across other directives, collected token by token until it is
/// complete: a `#write(` until its `)`, a `#local`/`#declare` whose value is a block opened
/// under an `#if` until that block's `}` (or a `;`).
struct PendingDirective {
    /// `write`, `local` or `declare`.
    rule: Rule,
    emitted: Emitted,
    /// Parentheses (`#write`) or braces (declarations) open in the collected text.
    depth: usize,
    /// The directive word's span.
    span: Span,
}

impl PendingDirective {
    /// Counts the brackets of `token`; returns whether it completes the directive.
    fn completed_by(&mut self, token: &str) -> bool {
        let (open, close) = if self.rule == Rule::write {
            ("(", ")")
        } else {
            ("{", "}")
        };
        if token == open {
            self.depth += 1;
        } else if token == close && self.depth > 0 {
            self.depth -= 1;
            return self.depth == 0;
        }
        self.rule != Rule::write && self.depth == 0 && token == ";"
    }
}

/// What a text macro call emits, shared with the macro calls spliced into it.
struct Sink {
    emitted: Emitted,
    pending: Option<PendingDirective>,
    /// Whether the last token emitted was `.` (a following word is a member, not a name).
    after_dot: bool,
    /// The scope of the text macro call, where hidden names are bound.
    bind_scope: usize,
    hidden_names: usize,
    /// What was parsed at each file offset, so loops and repeated calls parse once.
    parsed: HashMap<(FileId, usize), Parsed>,
}

/// A piece parsed from a body and its length, or why it does not parse.
type Parsed = Result<(Rc<Prefix>, usize), Box<Diagnostic>>;

/// The state of running one macro body token by token.
struct TextRun<'t, 's> {
    text: &'t str,
    file: FileId,
    /// File offset of the body's first byte.
    base: usize,
    /// Body offset of the next token to read.
    position: usize,
    controls: Vec<Control>,
    /// The hidden name and value last snapshotted for each name.
    snapshots: HashMap<Rc<str>, (Rc<str>, Value)>,
    sink: &'s mut Sink,
}

impl TextRun<'_, '_> {
    /// The file span of body bytes `start..end`.
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, self.base + start, self.base + end)
    }

    /// The map for text parsed straight from the body at `start`.
    fn map_from(&self, start: usize) -> OffsetMap {
        OffsetMap::copied(self.span(start, self.text.len()))
    }

    /// Parses `rule` at body offset `start` (once per offset).
    fn parse_at(&mut self, rule: Rule, start: usize) -> Parsed {
        let key = (self.file, self.base + start);
        if let Some(parsed) = self.sink.parsed.get(&key) {
            return parsed.clone();
        }
        let parsed = parse_prefix(rule, &self.text[start..], &self.map_from(start))
            .map(|(prefix, length)| (Rc::new(prefix), length));
        self.sink.parsed.insert(key, parsed.clone());
        parsed
    }

    /// Skips to just past the `#end` closing the innermost open directive, passing over
    /// nested ones.
    fn skip_to_end(&mut self) {
        self.skip_to(&[]);
    }

    /// Skips to just past the next directive among `stops` (or `#end`) that is not nested in
    /// another directive, and returns its word (`None` at the end of the text).
    fn skip_to(&mut self, stops: &[&str]) -> Option<&'static str> {
        let mut depth = 0usize;
        while let Some(token) = next_token(self.text, self.position) {
            self.position = token.end;
            let word = token.directive_word(self.text);
            match word {
                "if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro" => depth += 1,
                "end" if depth == 0 => return Some("end"),
                "end" => depth -= 1,
                _ if depth == 0 => {
                    if let Some(stop) = stops.iter().find(|stop| **stop == word) {
                        return Some(static_word(stop));
                    }
                }
                _ => {}
            }
        }
        None
    }
}

/// The directive words `skip_to` stops at, as static strings.
fn static_word(word: &str) -> &'static str {
    match word {
        "elseif" => "elseif",
        "else" => "else",
        "case" => "case",
        "range" => "range",
        _ => "end",
    }
}

/// A finite float or vector written as SDL that reads back as the same value (negative
/// numbers in parentheses, so that they stay one operand).
fn literal(value: &Value) -> Option<String> {
    let number = |x: f64| {
        if x < 0.0 || (x == 0.0 && x.is_sign_negative()) {
            format!("({x:?})")
        } else {
            format!("{x:?}")
        }
    };
    match value {
        Value::Float(x) if x.is_finite() => Some(number(*x)),
        Value::Vector(vector) if vector.len >= 2 => {
            let components = &vector.components[..usize::from(vector.len)];
            if !components.iter().all(|x| x.is_finite()) {
                return None;
            }
            let parts: Vec<String> = components.iter().map(|x| number(*x)).collect();
            Some(format!("<{}>", parts.join(",")))
        }
        _ => None,
    }
}

/// Whether two snapshots are the same value, so one hidden name serves both (cheap checks
/// only: numbers, vectors and shared values; anything else gets a new name).
fn same_snapshot(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Float(x), Value::Float(y)) => x.to_bits() == y.to_bits(),
        (Value::Vector(x), Value::Vector(y)) => x == y,
        (Value::String(x), Value::String(y)) => Rc::ptr_eq(x, y),
        (Value::Array(x), Value::Array(y)) => Rc::ptr_eq(x, y),
        (Value::Object(x), Value::Object(y)) => std::sync::Arc::ptr_eq(x, y),
        (Value::Function(x), Value::Function(y)) => Rc::ptr_eq(x, y),
        _ => false,
    }
}

impl Evaluator {
    /// Runs a text macro's body (its arguments bound in the innermost scope) and returns the
    /// items it produced.
    pub(crate) fn expand_text_macro(&mut self, text: &str, span: Span) -> EvalResult<Rc<[Item]>> {
        let mut sink = Sink {
            emitted: Emitted::default(),
            pending: None,
            after_dot: false,
            bind_scope: self.scopes.len() - 1,
            hidden_names: 0,
            parsed: HashMap::new(),
        };
        self.run_body(text, span, &mut sink)?;
        if let Some(pending) = &sink.pending {
            return Err(self
                .error(pending.span, "this directive is never completed")
                .with_label("its arguments or value do not end before the macro does")
                .into());
        }
        parse_generated(&sink.emitted.text, &sink.emitted.map).map_err(|mut d| {
            d.trace = self.trace_for_diagnostic();
            d.message = format!("in the text this macro produced: {}", d.message);
            d
        })
    }

    /// Runs one macro body (`text`, at `span`) token by token into `sink`, up to its closing
    /// `#end` or the end of the text.
    fn run_body(&mut self, text: &str, span: Span, sink: &mut Sink) -> EvalResult<()> {
        let mut run = TextRun {
            text,
            file: span.file,
            base: span.start as usize,
            position: 0,
            controls: Vec::new(),
            snapshots: HashMap::new(),
            sink,
        };
        loop {
            let Some(token) = next_token(text, run.position) else {
                if run.controls.is_empty() {
                    return Ok(());
                }
                return Err(self
                    .error(span, "macro body ends inside a directive")
                    .with_label("a directive here has no `#end`")
                    .into());
            };
            run.position = token.end;
            match token.kind {
                TokenKind::Directive => {
                    if self.text_directive(&mut run, token)? {
                        return Ok(());
                    }
                }
                TokenKind::Word if !run.sink.after_dot && self.is_macro_call(&run, token) => {
                    self.splice_call(&mut run, token)?
                }
                _ => self.emit(&mut run, token)?,
            }
        }
    }

    /// Whether `token` names a macro and a `(` follows it.
    fn is_macro_call(&self, run: &TextRun, token: Token) -> bool {
        matches!(
            self.lookup(Symbol::intern(token.text(run.text))),
            Some(Value::Macro(_))
        ) && next_token(run.text, token.end).is_some_and(|next| next.text(run.text) == "(")
    }

    /// Runs a macro call met in a text body at once, as POV-Ray does: its arguments are
    /// evaluated now and its body's tokens are spliced into the output (directives in it run
    /// in order with the caller's).
    fn splice_call(&mut self, run: &mut TextRun, token: Token) -> EvalResult<()> {
        let (parsed, length) = self.traced(run.parse_at(Rule::call, token.start))?;
        run.position = token.start + length;
        let Prefix::Call(call) = &*parsed else {
            return Ok(());
        };
        let definition = self.bind_macro_call(call)?;
        let result = match &definition.body {
            MacroBody::Text { text, span } => self.run_body(text, *span, run.sink),
            MacroBody::Items(_, span) => {
                let text = self
                    .sources
                    .file(span.file)
                    .map(|file| file.text.clone())
                    .and_then(|text| {
                        text.get(span.start as usize..span.end as usize)
                            .map(Rc::from)
                    });
                match text {
                    Some(text) => self.run_body(&text, *span, run.sink),
                    None => Err(self
                        .error(call.span, "cannot find the text of this macro's body")
                        .into()),
                }
            }
        };
        self.leave_macro_call();
        result
    }

    /// Runs an included file token by token into `sink`, as POV-Ray reads it into the macro's
    /// token stream (in its own scope, as any included file).
    fn splice_include(&mut self, name: &str, span: Span, sink: &mut Sink) -> EvalResult<()> {
        let path = self.find_file(name, span, "include file", "included here")?;
        self.enter_nesting(span)?;
        self.trace.push(Entered {
            what: Entering::File(Rc::from(name)),
            span,
        });
        let result = self.load_file(&path, Some(span)).and_then(|_| {
            let key = path.canonicalize().unwrap_or_else(|_| path.clone());
            let file = self.parsed.get(&key).map(|(file, _)| *file);
            let text = file
                .and_then(|file| self.sources.file(file))
                .map(|f| f.text.clone());
            let (Some(file), Some(text)) = (file, text) else {
                return Err(self
                    .error(span, format!("cannot find the text of `{name}`"))
                    .into());
            };
            self.scopes.push(Scope::default());
            let result = self.run_body(&text, Span::new(file, 0, text.len()), sink);
            self.scopes.pop();
            result
        });
        self.trace.pop();
        self.nesting -= 1;
        result
    }

    /// Appends a token to the emitted text (or to a pending directive, running it once it
    /// is complete), naming snapshots for names bound to variables.
    fn emit(&mut self, run: &mut TextRun, token: Token) -> EvalResult<()> {
        let text = token.text(run.text);
        let hidden = if token.kind == TokenKind::Word && !run.sink.after_dot {
            self.snapshot_name(run, text)
        } else {
            None
        };
        run.sink.after_dot = text == ".";
        let source = run.span(token.start, token.end);
        let shown = hidden.as_deref().unwrap_or(text);
        let Some(pending) = &mut run.sink.pending else {
            run.sink.emitted.push(shown, source);
            return Ok(());
        };
        pending.emitted.push(shown, source);
        if !pending.completed_by(text) {
            return Ok(());
        }
        let Some(pending) = run.sink.pending.take() else {
            return Ok(());
        };
        let collected = &pending.emitted;
        let (parsed, length) =
            self.traced(parse_prefix(pending.rule, &collected.text, &collected.map))?;
        if length < collected.text.trim_end().len() {
            let rest = collected.map.span(length, collected.text.len());
            return Err(self
                .error(rest, "unexpected text after the directive")
                .with_label("the directive, collected across other directives, ends before this")
                .with_secondary(pending.span, "the directive")
                .into());
        }
        self.run_whole_directive(&parsed)
    }

    /// Starts collecting the directive `token` (`rule`), which runs across other directives.
    /// A declaration's target is copied as written (it names no value).
    fn start_pending(&mut self, run: &mut TextRun, token: Token, rule: Rule) -> EvalResult<()> {
        let span = run.span(token.start, token.end);
        if run.sink.pending.is_some() {
            return Err(self
                .error(
                    span,
                    "directive runs across directives inside another such directive",
                )
                .with_label("durer cannot collect this one")
                .into());
        }
        let mut emitted = Emitted::default();
        emitted.push(token.text(run.text), span);
        if rule != Rule::write {
            if let Some(target) =
                next_token(run.text, run.position).filter(|target| target.kind == TokenKind::Word)
            {
                emitted.push(target.text(run.text), run.span(target.start, target.end));
                run.position = target.end;
            }
        }
        run.sink.pending = Some(PendingDirective {
            rule,
            emitted,
            depth: 0,
            span,
        });
        Ok(())
    }

    /// What to emit for `name`: its value written out when it is a finite number or vector,
    /// else a hidden name bound to a snapshot of its value; `None` when `name` is no variable
    /// (a keyword, a function's parameter, a macro).
    fn snapshot_name(&mut self, run: &mut TextRun, name: &str) -> Option<Rc<str>> {
        let value = self.lookup(Symbol::intern(name))?;
        if let Some(literal) = literal(value) {
            return Some(Rc::from(literal));
        }
        if matches!(value, Value::Macro(_)) {
            return None;
        }
        if let Some((hidden, snapshot)) = run.snapshots.get(name) {
            if same_snapshot(snapshot, value) {
                return Some(hidden.clone());
            }
        }
        let value = value.clone();
        let hidden: Rc<str> = Rc::from(format!("_text_{}", run.sink.hidden_names));
        run.sink.hidden_names += 1;
        self.scopes
            .insert(run.sink.bind_scope, Symbol::intern(&hidden), value.clone());
        run.snapshots
            .insert(Rc::from(name), (hidden.clone(), value));
        Some(hidden)
    }
}
