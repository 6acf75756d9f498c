//! Text macros: running a macro body whose directives cut across braces, token by token.
//!
//! In: a macro's body text ([`MacroBody::Text`](crate::syntax::ast::MacroBody)), called with
//! its arguments already bound in the innermost scope. Out: the items the body produced,
//! parsed from the text it emitted, for the caller's stream; directives (`#if`, loops,
//! `#local`, `#write` whose argument list spans directives, ...) run as they are met, and
//! macro calls and `#include`s met in the body run at once with their tokens spliced in, as
//! in POV-Ray's token stream. Holds: a name bound to a variable when it is emitted is replaced
//! by a hidden name bound (in the text macro's scope) to a snapshot of its value at that
//! moment, so `P[J]` emitted inside a loop keeps that pass's `J`; spans of everything parsed
//! from the emitted text point into the macro body. What is parsed is kept for later calls
//! ([`TextMacroCache`]), so repeated calls parse nothing again.

use super::value::Value;
use crate::diag::{Diagnostic, FileId, Span};
use crate::eval::language::{Entered, Entering, Scope};
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{Item, MacroBody};
use crate::syntax::mapping::OffsetMap;
use crate::syntax::symbol::Symbol;
use crate::syntax::tokens::{next_token, Token, TokenKind};
use crate::syntax::{parse_generated, parse_prefix, Prefix, Rule};
use std::collections::HashMap;
use std::path::PathBuf;
use std::rc::Rc;
use std::sync::Arc;

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

/// A directive or macro call that runs across other directives, collected token by token
/// until it is complete: a `#write(` or a macro call until its `)`, a `#local`/`#declare`
/// whose value is a block opened under an `#if` until that block's `}` (or a `;`).
struct PendingDirective {
    /// `write`, `local`, `declare` or `call`.
    rule: Rule,
    emitted: Emitted,
    /// Parentheses (`#write`, calls) or braces (declarations) open in the collected text.
    depth: usize,
    /// Braces, brackets and vectors open directly inside a call's parentheses.
    inner_depth: usize,
    /// Whether the last token collected directly inside a call's parentheses ends a value (a
    /// number, name, string or closing bracket): POV-Ray's argument reader takes no
    /// directive there.
    after_value: bool,
    /// The directive word's (or macro name's) span.
    span: Span,
    /// How many scopes were open when collecting started (they still are when it ends).
    scope_depth: usize,
}

impl PendingDirective {
    /// Whether the brackets are parentheses (else braces).
    fn in_parentheses(&self) -> bool {
        matches!(self.rule, Rule::write | Rule::call)
    }

    /// Counts the brackets of `token`; returns whether it completes the directive.
    fn completed_by(&mut self, token: &str) -> bool {
        let (open, close) = if self.in_parentheses() {
            ("(", ")")
        } else {
            ("{", "}")
        };
        if token == open {
            self.depth += 1;
        } else if token == close && self.depth > 0 {
            self.depth -= 1;
            if self.depth == 0 {
                return true;
            }
        }
        if self.depth == 1 && self.rule == Rule::call {
            let opens_vector = token == "<" && !self.after_value;
            if token == "{" || token == "[" || opens_vector {
                self.inner_depth += 1;
            } else if (token == "}" || token == "]" || token == ">") && self.inner_depth > 0 {
                self.inner_depth -= 1;
            }
            self.after_value = ends_value(token);
        }
        !self.in_parentheses() && self.depth == 0 && token == ";"
    }

    /// Whether a directive met now comes right after a complete argument of a call, where
    /// POV-Ray ends the argument list.
    fn directive_ends_arguments(&self) -> bool {
        self.rule == Rule::call && self.depth == 1 && self.inner_depth == 0 && self.after_value
    }
}

/// Whether `token` ends a value: a number, name, string or closing bracket.
fn ends_value(token: &str) -> bool {
    token.starts_with(|c: char| c.is_ascii_alphanumeric() || matches!(c, '_' | '"' | '.'))
        || matches!(token, ")" | "]" | "}" | ">")
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
}

/// What text macros parsed, kept for all later calls: a body's directives and calls are
/// parsed once per place in their file, and an expansion once per distinct emitted text.
/// Names are emitted as hidden names (never as their values), so a macro that takes the
/// same path through its directives emits the same text on every call and is parsed once.
#[derive(Default)]
pub(crate) struct TextMacroCache {
    /// What was parsed with each rule at each file offset.
    pieces: HashMap<(FileId, usize, Rule), Parsed>,
    /// The items parsed from each emitted text (with the map leading it back to its source).
    expansions: HashMap<(String, OffsetMap), Rc<[Item]>>,
    /// Bytes of emitted text held in `expansions`.
    expansion_bytes: usize,
    /// The `rand(...)` calls evaluated as they are met, parsed once per place in a file
    /// (`None`: not a call that can be evaluated on its own).
    eager: HashMap<(FileId, usize), Option<Rc<crate::syntax::ast::Expr>>>,
    /// Files included by text macros (read, never parsed whole), by path.
    included: HashMap<PathBuf, (FileId, Arc<str>)>,
}

/// Emitted texts longer than this are parsed every time rather than kept (such big
/// expansions, meshes written out by loops, rarely repeat).
const CACHED_EXPANSION_MAX_LENGTH: usize = 64 * 1024;

/// How much emitted text (in bytes) the kept expansions may hold in all; later ones are
/// parsed every time.
const CACHED_EXPANSIONS_MAX_BYTES: usize = 8 << 20;

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
    /// Parses `rule` at body offset `start` of `run` (once per place in a file, for all
    /// calls).
    fn parse_at(&mut self, run: &TextRun, rule: Rule, start: usize) -> Parsed {
        let key = (run.file, run.base + start, rule);
        if let Some(parsed) = self.runtime.text_macro_cache.pieces.get(&key) {
            return parsed.clone();
        }
        let parsed = parse_prefix(rule, &run.text[start..], &run.map_from(start))
            .map(|(prefix, length)| (Rc::new(prefix), length));
        self.runtime
            .text_macro_cache
            .pieces
            .insert(key, parsed.clone());
        parsed
    }

    /// Runs a text macro's body (its arguments bound in the innermost scope), or a whole file
    /// run as text, and returns the items it produced; `owner` ("macro" or "file") names it
    /// in messages.
    pub(crate) fn expand_text_macro(
        &mut self,
        text: &str,
        span: Span,
        owner: &str,
    ) -> EvalResult<Rc<[Item]>> {
        let mut sink = Sink {
            emitted: Emitted::default(),
            pending: None,
            after_dot: false,
            bind_scope: self.runtime.scopes.len() - 1,
            hidden_names: 0,
        };
        self.run_body(text, span, &mut sink)?;
        if let Some(pending) = &sink.pending {
            return Err(self
                .runtime
                .error(pending.span, "this directive is never completed")
                .with_label(format!(
                    "its arguments or value do not end before the {owner} does"
                ))
                .into());
        }
        let key = (sink.emitted.text, sink.emitted.map);
        if let Some(items) = self.runtime.text_macro_cache.expansions.get(&key) {
            return Ok(items.clone());
        }
        let items = parse_generated(&key.0, &key.1).map_err(|mut d| {
            d.trace = self.runtime.trace_for_diagnostic();
            d.message = format!("in the text this {owner} produced: {}", d.message);
            d
        })?;
        let cache = &mut self.runtime.text_macro_cache;
        let length = key.0.len();
        if length <= CACHED_EXPANSION_MAX_LENGTH
            && cache.expansion_bytes + length <= CACHED_EXPANSIONS_MAX_BYTES
        {
            cache.expansion_bytes += length;
            cache.expansions.insert(key, items.clone());
        }
        Ok(items)
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
                    .runtime
                    .error(span, "macro body ends inside a directive")
                    .with_label("a directive here has no `#end`")
                    .into());
            };
            run.position = token.end;
            match token.kind {
                TokenKind::Directive => {
                    self.check_directive_in_call(&run, token)?;
                    if self.text_directive(&mut run, token)? {
                        return Ok(());
                    }
                }
                TokenKind::Word if !run.sink.after_dot && self.is_macro_call(&run, token) => {
                    self.splice_call(&mut run, token)?
                }
                TokenKind::Word if !run.sink.after_dot && token.text(text) == "rand" => {
                    if !self.eager_rand(&mut run, token)? {
                        self.emit(&mut run, token)?
                    }
                }
                _ => self.emit(&mut run, token)?,
            }
        }
    }

    /// Evaluates a `rand(...)` call met in a text body at once and emits a hidden name bound
    /// to its number, as POV-Ray draws the number when it reads the call: left in the
    /// emitted text, it would be drawn only when that text is run, after every directive that
    /// followed it (a `#declare N = rand(S)` later in a loop would draw first and the
    /// sequence would be dealt out in another order). Returns `false` (the call is emitted as
    /// text) when a directive comes before its closing `)`.
    fn eager_rand(&mut self, run: &mut TextRun, token: Token) -> EvalResult<bool> {
        let mut depth = 0usize;
        let mut position = token.end;
        let mut end = None;
        while let Some(next) = next_token(run.text, position) {
            position = next.end;
            if next.kind == TokenKind::Directive {
                return Ok(false);
            }
            match next.text(run.text) {
                "(" => depth += 1,
                ")" if depth <= 1 => {
                    end = Some(next.end);
                    break;
                }
                ")" => depth -= 1,
                _ if depth == 0 => return Ok(false),
                _ => {}
            }
        }
        let Some(end) = end else {
            return Ok(false);
        };
        let key = (run.file, run.base + token.start);
        let parsed = match self.runtime.text_macro_cache.eager.get(&key) {
            Some(parsed) => parsed.clone(),
            None => {
                let text = &run.text[token.start..end];
                let parsed = parse_prefix(Rule::expr, text, &run.map_from(token.start))
                    .ok()
                    .and_then(|(prefix, length)| match prefix {
                        Prefix::Expr(expr) if length == text.len() => Some(Rc::new(expr)),
                        _ => None,
                    });
                self.runtime
                    .text_macro_cache
                    .eager
                    .insert(key, parsed.clone());
                parsed
            }
        };
        let Some(expr) = parsed else {
            return Ok(false);
        };
        let value = self.eval_expr(&expr)?;
        run.position = end;
        let hidden: Rc<str> = Rc::from(format!("_text_{}", run.sink.hidden_names));
        run.sink.hidden_names += 1;
        self.runtime
            .scopes
            .insert(run.sink.bind_scope, Symbol::intern(&hidden), value);
        run.sink.after_dot = false;
        let source = run.span(token.start, end);
        let Some(pending) = &mut run.sink.pending else {
            run.sink.emitted.push(&hidden, source);
            return self
                .check_emitted_size(run.sink.emitted.text.len(), source)
                .map(|()| true);
        };
        pending.emitted.push(&hidden, source);
        pending.completed_by(&hidden);
        Ok(true)
    }

    /// Refuses a directive met inside a collected macro call's arguments where POV-Ray's
    /// argument reader does not take one: anywhere but at an argument's start or inside
    /// brackets, POV-Ray ends the argument list there.
    fn check_directive_in_call(&self, run: &TextRun, token: Token) -> EvalResult<()> {
        let Some(pending) = &run.sink.pending else {
            return Ok(());
        };
        if !pending.directive_ends_arguments() {
            return Ok(());
        }
        Err(self
            .runtime
            .error(
                run.span(token.start, token.end),
                "directive after a macro argument",
            )
            .with_label("POV-Ray ends the argument list here: put the directive before an argument")
            .with_secondary(pending.span, "the macro call")
            .into())
    }

    /// Whether `token` names a macro and a `(` follows it.
    fn is_macro_call(&self, run: &TextRun, token: Token) -> bool {
        matches!(
            self.runtime.lookup(Symbol::intern(token.text(run.text))),
            Some(Value::Macro(_))
        ) && next_token(run.text, token.end).is_some_and(|next| next.text(run.text) == "(")
    }

    /// Runs a macro call met in a text body at once, as POV-Ray does: its arguments are
    /// evaluated now and its body's tokens are spliced into the output (directives in it run
    /// in order with the caller's).
    /// A call whose argument list runs across directives is collected token by token first.
    fn splice_call(&mut self, run: &mut TextRun, token: Token) -> EvalResult<()> {
        if self.call_crosses_directive(run, token) {
            return self.start_pending(run, token, Rule::call);
        }
        let parsed = self.parse_at(run, Rule::call, token.start);
        let (parsed, length) = self.traced(parsed)?;
        run.position = token.start + length;
        self.run_spliced_call(&parsed, run.sink)
    }

    /// Whether a directive comes before the `)` closing the call at `name`.
    fn call_crosses_directive(&self, run: &TextRun, name: Token) -> bool {
        let mut depth = 0usize;
        let mut position = name.end;
        while let Some(token) = next_token(run.text, position) {
            position = token.end;
            match token.text(run.text) {
                _ if token.kind == TokenKind::Directive => return true,
                "(" => depth += 1,
                ")" if depth <= 1 => return false,
                ")" => depth -= 1,
                _ => {}
            }
        }
        false
    }

    /// Runs a parsed macro call, its body's tokens going to `sink`.
    fn run_spliced_call(&mut self, parsed: &Prefix, sink: &mut Sink) -> EvalResult<()> {
        let Prefix::Call(call) = parsed else {
            return Ok(());
        };
        let definition = self.bind_macro_call(call)?;
        let result = match &definition.body {
            MacroBody::Text { text, span } => self.run_body(text, *span, sink),
            MacroBody::Items(_, span) => {
                let text = self
                    .runtime
                    .sources
                    .file(span.file)
                    .map(|file| file.text.clone())
                    .and_then(|text| {
                        text.get(span.start as usize..span.end as usize)
                            .map(Rc::from)
                    });
                match text {
                    Some(text) => self.run_body(&text, *span, sink),
                    None => Err(self
                        .runtime
                        .error(call.span, "cannot find the text of this macro's body")
                        .into()),
                }
            }
        };
        self.leave_macro_call();
        result
    }

    /// Runs an included file token by token into `sink`, as POV-Ray reads it into the macro's
    /// token stream (in its own scope, as any included file). The file need not parse on its
    /// own: its tokens join the macro's wherever they fall (it may close a block the macro
    /// opened).
    fn splice_include(&mut self, name: &str, span: Span, sink: &mut Sink) -> EvalResult<()> {
        let path = self.runtime.find_included(name, span)?;
        self.runtime.enter_nesting(span)?;
        self.runtime.trace.push(Entered {
            what: Entering::File(Rc::from(name)),
            span,
        });
        let result = self.included_text(path, span).and_then(|(file, text)| {
            self.runtime.scopes.push(Scope::default());
            let result = self.run_body(&text, Span::new(file, 0, text.len()), sink);
            self.runtime.scopes.pop();
            result
        });
        self.runtime.trace.pop();
        self.runtime.nesting -= 1;
        result
    }

    /// The text of a file included by a text macro, read once.
    fn included_text(&mut self, path: PathBuf, span: Span) -> EvalResult<(FileId, Arc<str>)> {
        let key = path.canonicalize().unwrap_or_else(|_| path.clone());
        if let Some(known) = self.runtime.text_macro_cache.included.get(&key) {
            return Ok(known.clone());
        }
        let source = self.runtime.read_source(&path, Some(span))?;
        self.runtime
            .text_macro_cache
            .included
            .insert(key, source.clone());
        Ok(source)
    }

    /// Stops a text-macro call whose emitted text has grown past the `macro-text` limit.
    fn check_emitted_size(&self, bytes: usize, at: Span) -> EvalResult<()> {
        let limit = self.runtime.options().limits.macro_text;
        if bytes as u64 <= limit {
            return Ok(());
        }
        Err(self
            .runtime
            .error(
                at,
                format!("this macro call emits more than {limit} bytes of scene text"),
            )
            .with_label("emitted past the limit here")
            .with_help(format!(
                "a loop in the macro body that never ends can cause this; {}",
                crate::limits::Limits::raise_hint("macro-text", limit)
            ))
            .into())
    }

    /// Appends a token to the emitted text (or to a pending directive, running it once it
    /// is complete), naming snapshots for names bound to variables.
    fn emit(&mut self, run: &mut TextRun, token: Token) -> EvalResult<()> {
        let text = token.text(run.text);
        // A call's arguments are read when it is complete, right after: a name still bound
        // then stays itself (so that it is passed by reference); one bound in a scope that
        // ends first (an included file's, a spliced macro's) is snapshotted.
        let kept_for_call = run.sink.pending.as_ref().is_some_and(|pending| {
            pending.rule == Rule::call
                && self
                    .runtime
                    .scopes
                    .innermost_binding(Symbol::intern(text))
                    .is_none_or(|(scope, _)| scope < pending.scope_depth)
        });
        let hidden = if token.kind == TokenKind::Word && !run.sink.after_dot && !kept_for_call {
            self.snapshot_name(run, text)
        } else {
            None
        };
        run.sink.after_dot = text == ".";
        let source = run.span(token.start, token.end);
        let shown = hidden.as_deref().unwrap_or(text);
        let Some(pending) = &mut run.sink.pending else {
            run.sink.emitted.push(shown, source);
            return self.check_emitted_size(run.sink.emitted.text.len(), source);
        };
        pending.emitted.push(shown, source);
        let collected = pending.emitted.text.len();
        self.check_emitted_size(collected, source)?;
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
                .runtime
                .error(rest, "unexpected text after the directive")
                .with_label("the directive, collected across other directives, ends before this")
                .with_secondary(pending.span, "the directive")
                .into());
        }
        if pending.rule == Rule::call {
            return self.run_spliced_call(&parsed, run.sink);
        }
        self.run_whole_directive(&parsed)
    }

    /// Starts collecting the directive `token` (`rule`), which runs across other directives.
    /// A declaration's target is copied as written (it names no value).
    fn start_pending(&mut self, run: &mut TextRun, token: Token, rule: Rule) -> EvalResult<()> {
        let span = run.span(token.start, token.end);
        if run.sink.pending.is_some() {
            return Err(self
                .runtime
                .error(
                    span,
                    "directive runs across directives inside another such directive",
                )
                .with_label("durer cannot collect this one")
                .into());
        }
        let mut emitted = Emitted::default();
        emitted.push(token.text(run.text), span);
        if matches!(rule, Rule::local | Rule::declare) {
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
            inner_depth: 0,
            after_value: false,
            scope_depth: self.runtime.scopes.len(),
            span,
        });
        Ok(())
    }

    /// What to emit for `name`: a hidden name bound to a snapshot of its value; `None` when
    /// `name` is no variable (a keyword, a function's parameter, a macro).
    fn snapshot_name(&mut self, run: &mut TextRun, name: &str) -> Option<Rc<str>> {
        let value = self.runtime.lookup(Symbol::intern(name))?;
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
        self.runtime
            .scopes
            .insert(run.sink.bind_scope, Symbol::intern(&hidden), value.clone());
        run.snapshots
            .insert(Rc::from(name), (hidden.clone(), value));
        Some(hidden)
    }
}
