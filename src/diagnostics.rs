//! Diagnostics for every stage: kind, span, reason and hints, rendered with miette.
//!
//! The library never prints; `SceneErrors::render` returns the text that the binary writes.

use std::fmt;

use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan, NamedSource, SourceSpan};
use serde::Serialize;

/// A byte range in the scene source.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

impl Span {
    pub fn new(start: usize, end: usize) -> Self {
        Span { start, end }
    }
    pub fn len(&self) -> usize {
        self.end - self.start
    }
    pub fn is_empty(&self) -> bool {
        self.end == self.start
    }
}

/// What went wrong, in one word a test or a tool can match on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DiagnosticKind {
    /// The text does not follow the grammar.
    Syntax,
    /// A block, key, call, argument or value name that the language does not know.
    UnknownName,
    /// A key that the scene needs is absent.
    MissingKey,
    /// A key given twice in one block.
    DuplicateKey,
    /// A unit name that is not in the unit table.
    UnknownUnit,
    /// A quantity whose unit has the wrong dimension for its key.
    WrongDimension,
    /// A name (material, ...) used but never defined.
    Undefined,
    /// A value that is not finite, not whole where it must be, or outside its physical range.
    OutOfRange,
    /// Geometry that cannot mesh: pointed or undercut teeth, interference, contact ratio out of range.
    Geometry,
}

impl DiagnosticKind {
    pub fn code(self) -> &'static str {
        match self {
            DiagnosticKind::Syntax => "gearloss::syntax",
            DiagnosticKind::UnknownName => "gearloss::unknown_name",
            DiagnosticKind::MissingKey => "gearloss::missing_key",
            DiagnosticKind::DuplicateKey => "gearloss::duplicate_key",
            DiagnosticKind::UnknownUnit => "gearloss::unknown_unit",
            DiagnosticKind::WrongDimension => "gearloss::wrong_dimension",
            DiagnosticKind::Undefined => "gearloss::undefined",
            DiagnosticKind::OutOfRange => "gearloss::out_of_range",
            DiagnosticKind::Geometry => "gearloss::geometry",
        }
    }
}

/// One problem in a scene: where, what and how to fix it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    pub kind: DiagnosticKind,
    pub span: Span,
    pub reason: String,
    pub hints: Vec<String>,
}

impl Diagnostic {
    pub fn new(kind: DiagnosticKind, span: Span, reason: impl Into<String>) -> Self {
        Diagnostic { kind, span, reason: one_line(reason.into()), hints: Vec::new() }
    }

    pub fn hint(mut self, hint: impl Into<String>) -> Self {
        self.hints.push(one_line(hint.into()));
        self
    }
}

/// A message on one line: line ends and other control characters (from the scene's text quoted in
/// a message) are written as escapes, so that a message never breaks a terminal line or a log.
pub(crate) fn one_line(s: String) -> String {
    if !s.chars().any(char::is_control) {
        return s;
    }
    s.chars()
        .map(|c| match c {
            '\n' => "\\n".to_string(),
            '\r' => "\\r".to_string(),
            '\t' => "\\t".to_string(),
            c if c.is_control() => format!("\\u{{{:04X}}}", c as u32),
            c => c.to_string(),
        })
        .collect()
}

/// All problems found in one scene file, with its source for rendering.
#[derive(Debug, Clone)]
pub struct SceneErrors {
    pub source_name: String,
    pub source: String,
    pub diagnostics: Vec<Diagnostic>,
}

impl SceneErrors {
    /// Line and column (both 1-based, column in characters) of a byte offset.
    pub fn line_column(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.source.len());
        let before = &self.source[..floor_char_boundary(&self.source, offset)];
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        (line, column)
    }

    /// Renders every diagnostic as miette draws it (no colour when `color` is false), followed by a count.
    pub fn render(&self, color: bool) -> String {
        let theme = if color { GraphicalTheme::unicode() } else { GraphicalTheme::unicode_nocolor() };
        let handler = GraphicalReportHandler::new_themed(theme).with_width(100);
        let named = NamedSource::new(self.source_name.clone(), self.source.clone());
        let mut out = String::new();
        for d in &self.diagnostics {
            let (line, column) = self.line_column(d.span.start);
            out.push_str(&format!("{}:{}:{}: {}\n", self.source_name, line, column, d.reason));
            let one = OneDiagnostic { diagnostic: d, source: &named };
            if handler.render_report(&mut out, &one).is_err() {
                out.push_str(&d.reason);
            }
            out.push('\n');
        }
        let n = self.diagnostics.len();
        out.push_str(&format!("{} {} in {}\n", n, if n == 1 { "error" } else { "errors" }, self.source_name));
        out
    }
}

impl fmt::Display for SceneErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(false))
    }
}

impl std::error::Error for SceneErrors {}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

struct OneDiagnostic<'a> {
    diagnostic: &'a Diagnostic,
    source: &'a NamedSource<String>,
}

impl fmt::Debug for OneDiagnostic<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.diagnostic, f)
    }
}

impl fmt::Display for OneDiagnostic<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.diagnostic.reason)
    }
}

impl std::error::Error for OneDiagnostic<'_> {}

impl miette::Diagnostic for OneDiagnostic<'_> {
    fn code<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        Some(Box::new(self.diagnostic.kind.code()))
    }

    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        if self.diagnostic.hints.is_empty() {
            None
        } else {
            Some(Box::new(self.diagnostic.hints.join("\n")))
        }
    }

    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        Some(self.source)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let s = self.diagnostic.span;
        let span =
            SourceSpan::new(s.start.into(), s.len().max(if s.start < self.source.inner().len() { 1 } else { 0 }));
        Some(Box::new(std::iter::once(LabeledSpan::new_with_span(Some("here".into()), span))))
    }
}
