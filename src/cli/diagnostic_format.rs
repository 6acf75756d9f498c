//! `--format human|json|sarif`: diagnostics for people, for scripts (JSON lines, described
//! by docs/diagnostics.schema.json) and for code-scanning tools (SARIF 2.1.0).
//!
//! JSON is written with `serde_json` (escaping and number formatting are its job); SARIF is
//! the same data laid out as SARIF's `runs[0].results`, checked against the official
//! 2.1.0 schema by the integration tests (no SARIF crate: the few objects durer needs are
//! plainer to build than a crate's full object model).

use durer::diag::{Diagnostic, Severity, SourceMap, Span};
use serde_json::{json, Value};

/// How diagnostics are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// miette reports with source snippets (colour on a terminal).
    Human,
    /// One JSON object per line (docs/diagnostics.schema.json).
    Json,
    /// One SARIF 2.1.0 log.
    Sarif,
}

/// A position: 1-based line, 1-based column in Unicode characters, byte offset.
pub struct Position {
    pub line: usize,
    pub column: usize,
    pub utf16_column: usize,
    pub offset: usize,
}

/// The position of byte `offset` in `text` (clamped to the text, on a char boundary).
pub fn position(text: &str, offset: usize) -> Position {
    let mut offset = offset.min(text.len());
    while offset > 0 && !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line_start = before.rfind('\n').map_or(0, |n| n + 1);
    let prefix = &before[line_start..];
    Position {
        line: before.matches('\n').count() + 1,
        column: prefix.chars().count() + 1,
        utf16_column: prefix.encode_utf16().count(),
        offset,
    }
}

/// A span's file name and start and end positions (none for a span outside every file).
fn locate(span: Span, sources: &SourceMap) -> Option<(String, Position, Position)> {
    let file = sources.file(span.file)?;
    Some((
        file.path.display().to_string(),
        position(&file.text, span.start as usize),
        position(&file.text, span.end as usize),
    ))
}

fn place_json(span: Span, sources: &SourceMap) -> Value {
    match locate(span, sources) {
        Some((file, start, end)) => json!({
            "file": file,
            "line": start.line,
            "column": start.column,
            "end_line": end.line,
            "end_column": end.column,
            "byte_start": start.offset,
            "byte_end": end.offset,
        }),
        None => json!({ "file": null }),
    }
}

fn severity_name(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
    }
}

/// One diagnostic as the JSON object of `--format json`.
pub fn json_object(diagnostic: &Diagnostic, sources: &SourceMap) -> Value {
    let mut object = place_json(diagnostic.span, sources);
    let labels: Vec<Value> = std::iter::once((diagnostic.span, diagnostic.label.as_str()))
        .filter(|(_, text)| !text.is_empty())
        .chain(diagnostic.labels.iter().map(|(s, t)| (*s, t.as_str())))
        .map(|(span, text)| {
            let mut label = place_json(span, sources);
            label["message"] = json!(text);
            label
        })
        .collect();
    let trace: Vec<Value> = diagnostic
        .trace
        .iter()
        .map(|entry| {
            let mut step = place_json(entry.span, sources);
            step["what"] = json!(entry.what);
            step
        })
        .collect();
    object["severity"] = json!(severity_name(diagnostic.severity));
    object["code"] = json!(diagnostic.code);
    object["message"] = json!(diagnostic.message);
    object["labels"] = json!(labels);
    object["help"] = json!(diagnostic.help);
    object["trace"] = json!(trace);
    object
}

/// A file path as a SARIF URI reference: a `file://` URL for an absolute path, else the
/// relative path with the characters a URI may not hold percent-encoded.
pub fn uri_reference(path: &str) -> String {
    if path.starts_with('/') {
        if let Ok(url) = lsp_types::Url::from_file_path(path) {
            return url.to_string();
        }
    }
    let mut out = String::new();
    for byte in path.bytes() {
        if byte.is_ascii_alphanumeric() || b"-._~/".contains(&byte) {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

fn sarif_location(span: Span, sources: &SourceMap, message: Option<&str>) -> Option<Value> {
    let (file, start, end) = locate(span, sources)?;
    let mut location = json!({
        "physicalLocation": {
            "artifactLocation": { "uri": uri_reference(&file) },
            "region": {
                "startLine": start.line,
                "startColumn": start.column,
                "endLine": end.line,
                "endColumn": end.column.max(if end.line == start.line { start.column } else { 1 }),
                "byteOffset": start.offset,
                "byteLength": end.offset.saturating_sub(start.offset),
            }
        }
    });
    if let Some(text) = message.filter(|t| !t.is_empty()) {
        location["message"] = json!({ "text": text });
    }
    Some(location)
}

/// All diagnostics as one SARIF 2.1.0 log.
pub fn sarif_log(diagnostics: &[Diagnostic], sources: &SourceMap) -> Value {
    let mut rule_ids: Vec<&str> = diagnostics.iter().map(|d| d.code).collect();
    rule_ids.sort_unstable();
    rule_ids.dedup();
    let rules: Vec<Value> = rule_ids.iter().map(|id| json!({ "id": id })).collect();
    let results: Vec<Value> = diagnostics
        .iter()
        .map(|d| {
            let mut text = d.message.clone();
            if let Some(help) = &d.help {
                text.push_str("\nhelp: ");
                text.push_str(help);
            }
            let mut result = json!({
                "ruleId": d.code,
                "ruleIndex": rule_ids.iter().position(|id| *id == d.code).unwrap_or(0),
                "level": severity_name(d.severity),
                "message": { "text": text },
                "locations": sarif_location(d.span, sources, Some(&d.label)).into_iter().collect::<Vec<_>>(),
            });
            let related: Vec<Value> = d
                .labels
                .iter()
                .filter_map(|(span, label)| sarif_location(*span, sources, Some(label)))
                .enumerate()
                .map(|(index, mut location)| {
                    location["id"] = json!(index);
                    location
                })
                .collect();
            if !related.is_empty() {
                result["relatedLocations"] = json!(related);
            }
            let frames: Vec<Value> = d
                .trace
                .iter()
                .filter_map(|entry| {
                    let mut location = sarif_location(entry.span, sources, None)?;
                    location["message"] = json!({ "text": entry.what });
                    Some(json!({ "location": location }))
                })
                .collect();
            if !frames.is_empty() {
                result["stacks"] = json!([{
                    "message": { "text": "macro calls and includes, innermost first" },
                    "frames": frames,
                }]);
            }
            result
        })
        .collect();
    json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {
                "driver": {
                    "name": "durer",
                    "version": env!("CARGO_PKG_VERSION"),
                    "informationUri": "https://www.povray.org/documentation/3.7.0/",
                    "rules": rules,
                }
            },
            "columnKind": "unicodeCodePoints",
            "results": results,
        }]
    })
}

/// The text printed for `diagnostics` in a machine format: JSON lines, or one SARIF log.
pub fn machine_text(format: Format, diagnostics: &[&Diagnostic], sources: &SourceMap) -> String {
    match format {
        Format::Human => String::new(),
        Format::Json => diagnostics
            .iter()
            .map(|d| format!("{}\n", json_object(d, sources)))
            .collect(),
        Format::Sarif => {
            let owned: Vec<Diagnostic> = diagnostics.iter().map(|d| (*d).clone()).collect();
            format!("{}\n", sarif_log(&owned, sources))
        }
    }
}
