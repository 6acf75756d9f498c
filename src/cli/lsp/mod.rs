//! `durer lsp`: a Language Server Protocol server on standard input and output.
//!
//! Built on `lsp-server` (the message loop and framing rust-analyzer uses) and
//! `lsp-types` (the protocol's types), rather than an async framework: the server is one
//! loop over messages plus one analysis thread, which needs no runtime.
//!
//! - Diagnostics: each opened or changed text is evaluated (unsaved text, not the file on
//!   disk) on the analysis thread after a pause in typing ([`DEBOUNCE`]), within a time
//!   budget ([`DEFAULT_BUDGET`]) after which the evaluator stops itself; requests are
//!   answered meanwhile. An error inside an included file or a macro defined elsewhere is
//!   shown at the line of the open file that led there.
//! - Hover, go to definition, completion and document symbols read the text's tokens
//!   ([`outline`]), so they work on text that does not parse; included files are found as
//!   the evaluator finds them, durer's embedded standard include files last.

mod keyword_help;
mod outline;

use durer::diag::{Diagnostic, Severity, SourceMap};
use durer::eval::{evaluate_file, standard_names, EvalOptions};
use lsp_server::{Connection, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument,
    Notification as NotificationTrait, PublishDiagnostics,
};
use lsp_types::request::{
    Completion, DocumentSymbolRequest, GotoDefinition, HoverRequest, Request as RequestTrait,
};
use lsp_types::{
    CompletionItem, CompletionItemKind, CompletionOptions, CompletionParams, CompletionResponse,
    DiagnosticRelatedInformation, DiagnosticSeverity, DocumentSymbol, DocumentSymbolParams,
    DocumentSymbolResponse, GotoDefinitionParams, GotoDefinitionResponse, Hover, HoverContents,
    HoverParams, HoverProviderCapability, Location, MarkupContent, MarkupKind, NumberOrString,
    OneOf, Position, PublishDiagnosticsParams, Range, ServerCapabilities,
    TextDocumentContentChangeEvent, TextDocumentSyncCapability, TextDocumentSyncKind, Url,
};
use outline::{IncludedFile, Source, SymbolKind};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Pause in typing before a changed text is evaluated.
const DEBOUNCE: Duration = Duration::from_millis(150);
/// Longest evaluation of one text (`timeBudgetMs` in the initialization options, or the
/// `DURER_LSP_BUDGET_MS` variable, changes it).
const DEFAULT_BUDGET: Duration = Duration::from_secs(3);

/// An open document.
struct Document {
    text: String,
    version: i32,
}

/// A text to evaluate.
struct Job {
    uri: Url,
    version: i32,
    text: Arc<str>,
}

/// Settings from the client's initialization options.
#[derive(Clone)]
struct Settings {
    library: Vec<PathBuf>,
    budget: Duration,
}

/// Runs the server until the client says `exit`; returns the exit code.
pub fn run() -> i32 {
    let (connection, io_threads) = Connection::stdio();
    let code = match serve(&connection) {
        Ok(()) => 0,
        Err(message) => {
            eprintln!("durer lsp: {message}");
            1
        }
    };
    drop(connection);
    let _ = io_threads.join();
    code
}

fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(
            TextDocumentSyncKind::INCREMENTAL,
        )),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec!["#".into()]),
            ..CompletionOptions::default()
        }),
        document_symbol_provider: Some(OneOf::Left(true)),
        ..ServerCapabilities::default()
    }
}

fn serve(connection: &Connection) -> Result<(), String> {
    let capabilities = serde_json::to_value(capabilities()).map_err(|e| e.to_string())?;
    let init = connection
        .initialize(capabilities)
        .map_err(|e| e.to_string())?;
    let options = init.get("initializationOptions");
    let library = options
        .and_then(|o| o.get("library"))
        .and_then(|l| l.as_array())
        .map(|l| {
            l.iter()
                .filter_map(|p| p.as_str().map(PathBuf::from))
                .collect()
        })
        .unwrap_or_default();
    let budget_ms = options
        .and_then(|o| o.get("timeBudgetMs"))
        .and_then(|b| b.as_u64())
        .or_else(|| {
            std::env::var("DURER_LSP_BUDGET_MS")
                .ok()
                .and_then(|b| b.parse().ok())
        });
    let settings = Settings {
        library,
        budget: budget_ms.map_or(DEFAULT_BUDGET, Duration::from_millis),
    };
    let (jobs, job_receiver) = mpsc::channel::<Job>();
    let sender = connection.sender.clone();
    let worker_settings = settings.clone();
    let worker = std::thread::Builder::new()
        .name("durer-lsp-analysis".into())
        .spawn(move || {
            analyse(
                job_receiver,
                move |message| sender.send(message).is_ok(),
                worker_settings,
            )
        })
        .map_err(|e| e.to_string())?;
    let mut documents: HashMap<Url, Document> = HashMap::new();
    for message in &connection.receiver {
        match message {
            Message::Request(request) => {
                if connection
                    .handle_shutdown(&request)
                    .map_err(|e| e.to_string())?
                {
                    break;
                }
                let response = answer(&request, &documents, &settings);
                connection
                    .sender
                    .send(Message::Response(response))
                    .map_err(|e| e.to_string())?;
            }
            Message::Notification(notification) => {
                if let Some(job) = notify(notification, &mut documents) {
                    let _ = jobs.send(job);
                }
            }
            Message::Response(_) => {}
        }
    }
    drop(jobs);
    let _ = worker.join();
    Ok(())
}

/// Applies a notification to the open documents; returns the text to evaluate, if any.
fn notify(notification: Notification, documents: &mut HashMap<Url, Document>) -> Option<Job> {
    match notification.method.as_str() {
        DidOpenTextDocument::METHOD => {
            let params: lsp_types::DidOpenTextDocumentParams =
                serde_json::from_value(notification.params).ok()?;
            let document = params.text_document;
            documents.insert(
                document.uri.clone(),
                Document {
                    text: document.text,
                    version: document.version,
                },
            );
            job_for(&document.uri, documents)
        }
        DidChangeTextDocument::METHOD => {
            let params: lsp_types::DidChangeTextDocumentParams =
                serde_json::from_value(notification.params).ok()?;
            let uri = params.text_document.uri;
            let document = documents.get_mut(&uri)?;
            for change in params.content_changes {
                apply_change(&mut document.text, change);
            }
            document.version = params.text_document.version;
            job_for(&uri, documents)
        }
        DidCloseTextDocument::METHOD => {
            let params: lsp_types::DidCloseTextDocumentParams =
                serde_json::from_value(notification.params).ok()?;
            documents.remove(&params.text_document.uri);
            None
        }
        _ => None,
    }
}

fn job_for(uri: &Url, documents: &HashMap<Url, Document>) -> Option<Job> {
    let document = documents.get(uri)?;
    Some(Job {
        uri: uri.clone(),
        version: document.version,
        text: Arc::from(document.text.as_str()),
    })
}

fn apply_change(text: &mut String, change: TextDocumentContentChangeEvent) {
    match change.range {
        None => *text = change.text,
        Some(range) => {
            let start = offset_of(text, range.start);
            let end = offset_of(text, range.end).max(start);
            text.replace_range(start..end, &change.text);
        }
    }
}

/// Byte offset of an LSP position (UTF-16 columns), clamped to the text.
fn offset_of(text: &str, position: Position) -> usize {
    let mut line_start = 0;
    for _ in 0..position.line {
        match text[line_start..].find('\n') {
            Some(n) => line_start += n + 1,
            None => return text.len(),
        }
    }
    let line_end = text[line_start..]
        .find('\n')
        .map_or(text.len(), |n| line_start + n);
    let mut units = 0u32;
    for (index, c) in text[line_start..line_end].char_indices() {
        if units >= position.character {
            return line_start + index;
        }
        units += c.len_utf16() as u32;
    }
    line_end
}

/// LSP position of a byte offset.
fn position_of(text: &str, offset: usize) -> Position {
    let p = super::diagnostic_format::position(text, offset);
    Position::new((p.line - 1) as u32, p.utf16_column as u32)
}

fn range_of(text: &str, (start, end): (usize, usize)) -> Range {
    Range::new(position_of(text, start), position_of(text, end))
}

/// The analysis thread: waits for texts, lets typing settle, evaluates, publishes.
fn analyse(jobs: mpsc::Receiver<Job>, send: impl Fn(Message) -> bool, settings: Settings) {
    while let Ok(first) = jobs.recv() {
        let mut pending: Vec<Job> = vec![first];
        // Debounce: newer texts replace older ones of the same document.
        while let Ok(job) = jobs.recv_timeout(DEBOUNCE) {
            pending.retain(|p| p.uri != job.uri);
            pending.push(job);
        }
        for job in pending {
            let diagnostics = diagnose(&job, &settings);
            let params = PublishDiagnosticsParams {
                uri: job.uri.clone(),
                diagnostics,
                version: Some(job.version),
            };
            let notification = Notification::new(PublishDiagnostics::METHOD.to_string(), params);
            if !send(Message::Notification(notification)) {
                return;
            }
        }
    }
}

/// The path a document stands for (an unsaved, untitled one: `untitled.pov` in the
/// current folder).
fn document_path(uri: &Url) -> PathBuf {
    uri.to_file_path().unwrap_or_else(|_| {
        std::env::current_dir()
            .unwrap_or_default()
            .join("untitled.pov")
    })
}

/// Evaluates a text within the budget and turns its diagnostics into the protocol's.
fn diagnose(job: &Job, settings: &Settings) -> Vec<lsp_types::Diagnostic> {
    let path = document_path(&job.uri);
    let options = EvalOptions {
        include_paths: settings.library.clone(),
        print_debug: false,
        main_text: Some(job.text.clone()),
        deadline: Some(Instant::now() + settings.budget),
        ..EvalOptions::default()
    };
    let worker_path = path.clone();
    let evaluated = std::thread::Builder::new()
        .stack_size(super::EVALUATION_STACK_BYTES)
        .spawn(move || evaluate_file(&worker_path, &options))
        .ok()
        .and_then(|handle| handle.join().ok());
    let Some(evaluated) = evaluated else {
        return vec![lsp_types::Diagnostic {
            range: Range::default(),
            severity: Some(DiagnosticSeverity::ERROR),
            source: Some("durer".into()),
            message: "internal error while evaluating the scene".into(),
            ..lsp_types::Diagnostic::default()
        }];
    };
    let main = (0..u32::MAX)
        .take_while(|id| evaluated.sources.file(*id).is_some())
        .find(|id| evaluated.sources.file(*id).is_some_and(|f| f.path == path));
    evaluated
        .diagnostics
        .iter()
        .map(|d| to_lsp(d, &evaluated.sources, main, &job.text))
        .collect()
}

/// A file's URI for locations: its path, or for an embedded standard include file a copy
/// written once to the temporary folder, so an editor can open it.
fn file_uri(path: &Path, text: &str) -> Option<Url> {
    let shown = path.display().to_string();
    if let Some(name) = shown.strip_prefix("<durer standard library>/") {
        return embedded_uri(name, text);
    }
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().ok()?.join(path)
    };
    Url::from_file_path(absolute).ok()
}

fn embedded_uri(name: &str, text: &str) -> Option<Url> {
    let installed = Path::new("/usr/share/povray-3.7/include").join(name);
    if installed.is_file() && std::fs::read_to_string(&installed).is_ok_and(|t| t == text) {
        return Url::from_file_path(installed).ok();
    }
    let folder = std::env::temp_dir().join("durer-standard-library");
    let copy = folder.join(name);
    if !copy.is_file() {
        std::fs::create_dir_all(&folder).ok()?;
        let partial = folder.join(format!(".{name}.{}", std::process::id()));
        std::fs::write(&partial, text).ok()?;
        std::fs::rename(&partial, &copy).ok()?;
    }
    Url::from_file_path(copy).ok()
}

fn location_in(sources: &SourceMap, span: durer::diag::Span) -> Option<Location> {
    let file = sources.file(span.file)?;
    Some(Location {
        uri: file_uri(&file.path, &file.text)?,
        range: range_of(&file.text, (span.start as usize, span.end as usize)),
    })
}

fn to_lsp(
    d: &Diagnostic,
    sources: &SourceMap,
    main: Option<u32>,
    main_text: &str,
) -> lsp_types::Diagnostic {
    let mut related = Vec::new();
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message.push_str("\nhelp: ");
        message.push_str(help);
    }
    let span = if Some(d.span.file) == main {
        Some(d.span)
    } else {
        // Shown at the include line or macro call of the open file that led there.
        if let Some(location) = location_in(sources, d.span) {
            related.push(DiagnosticRelatedInformation {
                location,
                message: d.message.clone(),
            });
        }
        let outer = d.trace.iter().find(|entry| Some(entry.span.file) == main);
        if let (Some(entry), Some(inner)) = (outer, sources.file(d.span.file)) {
            let (line, _) = sources.line_column(d.span.file, d.span.start);
            message = format!(
                "in {} ({}:{line}): {message}",
                entry.what,
                inner.path.display()
            );
        }
        outer.map(|entry| entry.span)
    };
    for (label_span, text) in &d.labels {
        if let Some(location) = location_in(sources, *label_span) {
            related.push(DiagnosticRelatedInformation {
                location,
                message: text.clone(),
            });
        }
    }
    let range = span.map_or_else(Range::default, |s| {
        range_of(main_text, (s.start as usize, s.end as usize))
    });
    lsp_types::Diagnostic {
        range,
        severity: Some(match d.severity {
            Severity::Error => DiagnosticSeverity::ERROR,
            Severity::Warning => DiagnosticSeverity::WARNING,
        }),
        code: Some(NumberOrString::String(d.code.to_string())),
        source: Some("durer".into()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        ..lsp_types::Diagnostic::default()
    }
}

/// Answers one request.
fn answer(request: &Request, documents: &HashMap<Url, Document>, settings: &Settings) -> Response {
    let id = request.id.clone();
    let params = request.params.clone();
    let result = match request.method.as_str() {
        HoverRequest::METHOD => serde_json::from_value::<HoverParams>(params)
            .ok()
            .map(|p| serde_json::to_value(hover(&p, documents, settings))),
        GotoDefinition::METHOD => serde_json::from_value::<GotoDefinitionParams>(params)
            .ok()
            .map(|p| serde_json::to_value(definition(&p, documents, settings))),
        Completion::METHOD => serde_json::from_value::<CompletionParams>(params)
            .ok()
            .map(|p| serde_json::to_value(completion(&p, documents, settings))),
        DocumentSymbolRequest::METHOD => serde_json::from_value::<DocumentSymbolParams>(params)
            .ok()
            .map(|p| serde_json::to_value(symbols(&p, documents))),
        _ => {
            return Response::new_err(
                id,
                lsp_server::ErrorCode::MethodNotFound as i32,
                format!("durer lsp does not answer `{}`", request.method),
            )
        }
    };
    match result {
        Some(Ok(value)) => Response::new_ok(id, value),
        _ => Response::new_err(
            id,
            lsp_server::ErrorCode::InvalidParams as i32,
            "invalid parameters".into(),
        ),
    }
}

/// A declaration found for a name: in the open text or in a file it includes.
struct Found {
    symbol: outline::Symbol,
    /// `None` for the open text.
    file: Option<IncludedFile>,
}

fn included(document: &Document, uri: &Url, settings: &Settings) -> Vec<IncludedFile> {
    let path = document_path(uri);
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    outline::included_files(&document.text, &folder, &settings.library)
}

fn find_declaration(
    name: &str,
    document: &Document,
    uri: &Url,
    settings: &Settings,
) -> Option<Found> {
    let own = outline::outline(&document.text);
    if let Some(symbol) = own
        .symbols
        .into_iter()
        .find(|s| s.name == name && s.kind != SymbolKind::Object)
    {
        return Some(Found { symbol, file: None });
    }
    for file in included(document, uri, settings) {
        if let Some(symbol) = outline::outline(&file.text)
            .symbols
            .into_iter()
            .find(|s| s.name == name && s.kind != SymbolKind::Object)
        {
            return Some(Found {
                symbol,
                file: Some(file),
            });
        }
    }
    None
}

fn word_at(text: &str, position: Position) -> Option<(String, (usize, usize), bool)> {
    let offset = offset_of(text, position);
    let token = outline::token_at(text, offset)?;
    let is_string = token.kind == durer::syntax::tokens::TokenKind::String;
    let word = match token.kind {
        durer::syntax::tokens::TokenKind::Directive => token.directive_word(text).to_string(),
        durer::syntax::tokens::TokenKind::String => token.text(text).trim_matches('"').to_string(),
        _ => token.text(text).to_string(),
    };
    Some((word, (token.start, token.end), is_string))
}

fn hover(
    params: &HoverParams,
    documents: &HashMap<Url, Document>,
    settings: &Settings,
) -> Option<Hover> {
    let at = &params.text_document_position_params;
    let document = documents.get(&at.text_document.uri)?;
    let (word, range, is_string) = word_at(&document.text, at.position)?;
    let text = if is_string {
        let folder = document_path(&at.text_document.uri)
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        let file = outline::find_include(&word, &folder, &settings.library)?;
        match file.source {
            Source::Disk(path) => format!("include file `{}`", path.display()),
            Source::Embedded(name) => {
                format!("standard include file `{name}` (durer's embedded copy)")
            }
        }
    } else if let Some(found) = find_declaration(&word, document, &at.text_document.uri, settings) {
        let symbol = &found.symbol;
        let (head, kind) = match &symbol.kind {
            SymbolKind::Macro { .. } => {
                (format!("#macro {}{}", symbol.name, symbol.detail), "macro")
            }
            SymbolKind::Local => (
                format!("#local {} = {}", symbol.name, symbol.detail),
                "local identifier",
            ),
            _ => (
                format!("#declare {} = {}", symbol.name, symbol.detail),
                "identifier",
            ),
        };
        let (where_text, file_text) = match &found.file {
            None => ("this file".to_string(), document.text.as_str()),
            Some(file) => (format!("`{}`", file.name), file.text.as_str()),
        };
        let line = position_of(file_text, symbol.name_range.0).line + 1;
        format!("```pov\n{head}\n```\n{kind} declared in {where_text}, line {line}")
    } else if let Some(standard) = standard_names::standard_name(&word) {
        let kind = if standard.is_macro {
            "macro"
        } else {
            "identifier"
        };
        format!(
            "{kind} of the standard include file `{}` (not included: add `#include \"{}\"`)",
            standard.file, standard.include
        )
    } else if let Some(meaning) = keyword_help::meaning(&word) {
        format!("`{word}`: {meaning}")
    } else if durer::syntax::keywords::ALL.contains(&word.as_str()) {
        format!("`{word}`: a POV-Ray keyword")
    } else {
        return None;
    };
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: text,
        }),
        range: Some(range_of(&document.text, range)),
    })
}

fn included_location(file: &IncludedFile, range: (usize, usize)) -> Option<Location> {
    let uri = match &file.source {
        Source::Disk(path) => Url::from_file_path(path).ok()?,
        Source::Embedded(name) => embedded_uri(name, &file.text)?,
    };
    Some(Location {
        uri,
        range: range_of(&file.text, range),
    })
}

fn definition(
    params: &GotoDefinitionParams,
    documents: &HashMap<Url, Document>,
    settings: &Settings,
) -> Option<GotoDefinitionResponse> {
    let at = &params.text_document_position_params;
    let uri = &at.text_document.uri;
    let document = documents.get(uri)?;
    let (word, _, is_string) = word_at(&document.text, at.position)?;
    let location = if is_string {
        let folder = document_path(uri)
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        let file = outline::find_include(&word, &folder, &settings.library)?;
        included_location(&file, (0, 0))?
    } else if let Some(found) = find_declaration(&word, document, uri, settings) {
        match &found.file {
            None => Location {
                uri: uri.clone(),
                range: range_of(&document.text, found.symbol.name_range),
            },
            Some(file) => included_location(file, found.symbol.name_range)?,
        }
    } else {
        let standard = standard_names::standard_name(&word)?;
        let text = standard_names::embedded_include(standard.file)?;
        let uri = embedded_uri(standard.file, text)?;
        Location {
            uri,
            range: range_of(text, (standard.start, standard.end)),
        }
    };
    Some(GotoDefinitionResponse::Scalar(location))
}

/// The directive words, offered after `#`.
const DIRECTIVE_WORDS: &[&str] = &[
    "declare", "local", "undef", "ifdef", "ifndef", "if", "elseif", "else", "end", "while", "for",
    "switch", "case", "range", "break", "macro", "include", "version", "default", "debug",
    "warning", "error", "fopen", "fclose", "read", "write",
];

/// Words that may start a statement at file level.
const TOP_LEVEL: &[&str] = &[
    "camera",
    "light_source",
    "global_settings",
    "background",
    "sky_sphere",
    "fog",
    "rainbow",
    "media",
    "photons",
    "radiosity",
    "light_group",
];

fn completion(
    params: &CompletionParams,
    documents: &HashMap<Url, Document>,
    settings: &Settings,
) -> Option<CompletionResponse> {
    let at = &params.text_document_position;
    let uri = &at.text_document.uri;
    let document = documents.get(uri)?;
    let offset = offset_of(&document.text, at.position);
    let (depth, directive) = outline::context_at(&document.text, offset);
    let mut items: Vec<CompletionItem> = Vec::new();
    let keyword = |label: &str, detail: Option<&str>| CompletionItem {
        label: label.to_string(),
        kind: Some(CompletionItemKind::KEYWORD),
        detail: detail.map(str::to_string),
        ..CompletionItem::default()
    };
    if directive {
        for word in DIRECTIVE_WORDS {
            items.push(keyword(word, keyword_help::meaning(word)));
        }
        return Some(CompletionResponse::Array(items));
    }
    let own = outline::outline(&document.text);
    // Macro parameters of the macro the cursor is in.
    for symbol in &own.symbols {
        if let SymbolKind::Macro { parameters } = &symbol.kind {
            if symbol.range.0 < offset && offset <= symbol.range.1 {
                for parameter in parameters {
                    items.push(CompletionItem {
                        label: parameter.clone(),
                        kind: Some(CompletionItemKind::VARIABLE),
                        detail: Some(format!("parameter of macro {}", symbol.name)),
                        ..CompletionItem::default()
                    });
                }
            }
        }
    }
    let mut seen = std::collections::HashSet::new();
    let mut add_symbols =
        |symbols: Vec<outline::Symbol>, from: &str, items: &mut Vec<CompletionItem>| {
            for symbol in symbols {
                if symbol.kind == SymbolKind::Object || !seen.insert(symbol.name.clone()) {
                    continue;
                }
                let (kind, detail) = match &symbol.kind {
                    SymbolKind::Macro { .. } => (
                        CompletionItemKind::FUNCTION,
                        format!("macro {}{} ({from})", symbol.name, symbol.detail),
                    ),
                    _ => (
                        CompletionItemKind::VARIABLE,
                        format!("{} ({from})", symbol.detail),
                    ),
                };
                items.push(CompletionItem {
                    label: symbol.name,
                    kind: Some(kind),
                    detail: Some(detail),
                    ..CompletionItem::default()
                });
            }
        };
    add_symbols(own.symbols, "this file", &mut items);
    for file in included(document, uri, settings) {
        let symbols = outline::outline(&file.text).symbols;
        add_symbols(symbols, &file.name, &mut items);
    }
    let words: Vec<&str> = if depth == 0 {
        let mut words: Vec<&str> = TOP_LEVEL.to_vec();
        words.extend(outline::OBJECT_WORDS.iter().filter(|w| **w != "media"));
        words
    } else {
        durer::syntax::keywords::ALL.to_vec()
    };
    for word in words {
        items.push(keyword(word, keyword_help::meaning(word)));
    }
    Some(CompletionResponse::Array(items))
}

fn symbols(
    params: &DocumentSymbolParams,
    documents: &HashMap<Url, Document>,
) -> Option<DocumentSymbolResponse> {
    let document = documents.get(&params.text_document.uri)?;
    let text = &document.text;
    let list = outline::outline(text)
        .symbols
        .into_iter()
        .map(|symbol| {
            let kind = match symbol.kind {
                SymbolKind::Declare | SymbolKind::Local => lsp_types::SymbolKind::VARIABLE,
                SymbolKind::Macro { .. } => lsp_types::SymbolKind::FUNCTION,
                SymbolKind::Object => lsp_types::SymbolKind::OBJECT,
            };
            #[allow(deprecated)]
            DocumentSymbol {
                name: symbol.name,
                detail: (!symbol.detail.is_empty()).then_some(symbol.detail),
                kind,
                tags: None,
                deprecated: None,
                range: range_of(text, symbol.range),
                selection_range: range_of(text, symbol.name_range),
                children: None,
            }
        })
        .collect();
    Some(DocumentSymbolResponse::Nested(list))
}
