//! The reporting edge: internal [`Diagnostic`]s become miette reports with source snippets.

use crate::diag::{Diagnostic, Severity, SourceMap};
use miette::{LabeledSpan, NamedSource, SourceSpan};
use std::fmt;

/// A diagnostic prepared for miette: message, labelled source snippet, help and trace.
#[derive(Debug)]
pub struct Report {
    message: String,
    severity: Severity,
    source: Option<NamedSource<String>>,
    labels: Vec<LabeledSpan>,
    help: Option<String>,
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Report {}

impl miette::Diagnostic for Report {
    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
        })
    }

    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        self.source.as_ref().map(|s| s as &dyn miette::SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        if self.labels.is_empty() {
            None
        } else {
            Some(Box::new(self.labels.iter().cloned()))
        }
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }
}

/// Builds a miette-ready report for a diagnostic, with `file:line:col` in the message and
/// the macro/include trace in the help text.
pub fn to_report(diagnostic: &Diagnostic, sources: &SourceMap) -> Report {
    let file = sources.file(diagnostic.span.file);
    let location = match file {
        Some(_) => format!("{}: ", sources.describe(diagnostic.span)),
        None => String::new(),
    };
    // miette pads snippet lines with `{:width$}`, which panics past 65,535 columns: a
    // snippet that would show such a line is left out (the message still has line:column).
    let file = file.filter(|f| {
        let mut spans = vec![diagnostic.span];
        spans.extend(
            diagnostic
                .labels
                .iter()
                .map(|(s, _)| *s)
                .filter(|s| s.file == diagnostic.span.file),
        );
        spans
            .iter()
            .all(|s| !near_long_line(&f.text, s.start as usize, s.end as usize))
    });
    let source = file.map(|f| NamedSource::new(f.path.display().to_string(), f.text.to_string()));
    let mut labels = Vec::new();
    if file.is_some() {
        let span = SourceSpan::new(
            (diagnostic.span.start as usize).into(),
            (diagnostic.span.end - diagnostic.span.start) as usize,
        );
        let label = if diagnostic.label.is_empty() {
            None
        } else {
            Some(diagnostic.label.clone())
        };
        labels.push(LabeledSpan::new_primary_with_span(label, span));
        for (span, text) in &diagnostic.labels {
            if span.file == diagnostic.span.file {
                let s = SourceSpan::new(
                    (span.start as usize).into(),
                    (span.end - span.start) as usize,
                );
                labels.push(LabeledSpan::new_with_span(Some(text.clone()), s));
            }
        }
    }
    let mut help_lines: Vec<String> = Vec::new();
    if let Some(help) = &diagnostic.help {
        help_lines.push(help.clone());
    }
    for (span, text) in &diagnostic.labels {
        if span.file != diagnostic.span.file {
            help_lines.push(format!("{text} (at {})", sources.describe(*span)));
        }
    }
    // Deep recursion repeats one entry thousands of times: show each run once with a count.
    let mut index = 0;
    while index < diagnostic.trace.len() {
        let entry = &diagnostic.trace[index];
        let run = diagnostic.trace[index..]
            .iter()
            .take_while(|e| *e == entry)
            .count();
        let place = sources.describe(entry.span);
        let verb = if entry.what.starts_with("file") {
            "included"
        } else {
            "called"
        };
        if run > 1 {
            help_lines.push(format!(
                "in {}, {verb} at {place} ({run} times)",
                entry.what
            ));
        } else {
            help_lines.push(format!("in {}, {verb} at {place}", entry.what));
        }
        index += run;
    }
    Report {
        message: format!("{location}{}", diagnostic.message),
        severity: diagnostic.severity,
        source,
        labels,
        help: if help_lines.is_empty() {
            None
        } else {
            Some(help_lines.join("\n"))
        },
    }
}

/// Longest source line shown in a snippet, in bytes (miette's limit is 65,535 columns).
const LONGEST_SHOWN_LINE: usize = 10_000;

/// Whether the lines from two before `start` to two after `end` (those a snippet shows)
/// include one longer than [`LONGEST_SHOWN_LINE`].
fn near_long_line(text: &str, start: usize, end: usize) -> bool {
    let bytes = text.as_bytes();
    let start = start.min(bytes.len());
    let end = end.clamp(start, bytes.len());
    let mut from = start;
    for _ in 0..3 {
        from = bytes[..from].iter().rposition(|&b| b == b'\n').unwrap_or(0);
    }
    let mut to = end;
    for _ in 0..3 {
        to = bytes[to..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |p| (to + p + 1).min(bytes.len()));
    }
    bytes[from..to]
        .split(|&b| b == b'\n' || b == b'\r')
        .any(|line| line.len() > LONGEST_SHOWN_LINE)
}

/// Renders a diagnostic as plain text (no colours), as the CLI prints it to a pipe.
pub fn render_plain(diagnostic: &Diagnostic, sources: &SourceMap) -> String {
    let report = to_report(diagnostic, sources);
    let handler =
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
            .with_width(1000);
    let mut out = String::new();
    if handler.render_report(&mut out, &report).is_err() {
        out = report.message.clone();
    }
    out
}
