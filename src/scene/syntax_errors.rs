//! Syntax errors in words: what the grammar expected at the failing column, what was found there,
//! and a hint for the common slips.

use super::grammar::Rule;
use crate::diagnostics::Span;
use crate::diagnostics::{Diagnostic, DiagnosticKind};

/// A pest error as a diagnostic: "expected `=` or `{`, found `x`", at the exact column.
pub(super) fn syntax_error(source: &str, error: pest::error::Error<Rule>) -> Diagnostic {
    use pest::error::{ErrorVariant, InputLocation};
    let at = match error.location {
        InputLocation::Pos(p) => p,
        InputLocation::Span((s, _)) => s,
    };
    let found = found_token(source, at);
    let span = Span::new(at, at + found.len());
    let (mut expected, unexpected) = match &error.variant {
        ErrorVariant::ParsingError { positives, negatives } => (positives.clone(), negatives.clone()),
        ErrorVariant::CustomError { message } => {
            return Diagnostic::new(DiagnosticKind::Syntax, span, message.clone());
        }
    };
    expected.sort_by_key(|r| describe_rule(*r));
    expected.dedup_by_key(|r| describe_rule(*r));
    let mut words: Vec<&str> = expected.iter().map(|r| describe_rule(*r)).collect();
    words.dedup();
    let found_text = if found.is_empty() { "the end of the file".to_string() } else { format!("`{found}`") };
    let reason = if words.is_empty() {
        let not: Vec<&str> = unexpected.iter().map(|r| describe_rule(*r)).collect();
        format!("unexpected {}, found {found_text}", not.join(" or "))
    } else {
        format!("expected {}, found {found_text}", join_or(&words))
    };
    let mut d = Diagnostic::new(DiagnosticKind::Syntax, span, reason);
    d.hints.push(syntax_hint(&expected, found).to_string());
    d
}

fn syntax_hint(expected: &[Rule], found: &str) -> &'static str {
    if found == "," && !expected.contains(&Rule::rbracket) && !expected.contains(&Rule::rparen) {
        "items are separated by spaces or line ends, not commas (commas separate the values of a `[...]` list and the arguments of a call)"
    } else if expected.contains(&Rule::kw_scene) {
        "a .gear file holds one `scene \"name\" { ... }`"
    } else if expected.contains(&Rule::rbrace) && found.is_empty() {
        "every `{` needs a closing `}`; the file ended inside a block"
    } else if expected.contains(&Rule::rbracket) {
        "a list is `[a, b, c] unit`, values separated by commas"
    } else if expected.contains(&Rule::rparen) || expected.contains(&Rule::argument) {
        "arguments are written `name(key = value, key = value)`"
    } else if expected.contains(&Rule::number) || expected.contains(&Rule::quantity) || expected.contains(&Rule::range)
    {
        "a value is a number with a unit (`4.5 mm`), a list (`[1, 2] rpm`), a range (`100..3000 rpm step 100`), a name or a \"string\""
    } else if expected.contains(&Rule::eq) || expected.contains(&Rule::lbrace) {
        "a line is `key = value`, `block { ... }` or a call like `coulomb(mu = 0.05)`"
    } else if expected.contains(&Rule::EOI) {
        "nothing may follow the scene's closing `}`"
    } else {
        "see README.md for the language; `gearloss units` lists the units"
    }
}

fn join_or(words: &[&str]) -> String {
    match words {
        [] => String::new(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} or {}", init.join(", "), last),
    }
}

/// The token at a position, for "found ..." (a word, or one character).
fn found_token(source: &str, at: usize) -> &str {
    let rest = source.get(at..).unwrap_or("");
    let word_len: usize = rest
        .char_indices()
        .take_while(|(_, c)| c.is_alphanumeric() || *c == '_' || *c == '.')
        .map(|(_, c)| c.len_utf8())
        .sum();
    if word_len > 0 {
        &rest[..word_len]
    } else {
        rest.chars().next().map_or("", |c| &rest[..c.len_utf8()])
    }
}

/// What a grammar rule is called in an error message.
pub fn describe_rule(rule: Rule) -> &'static str {
    match rule {
        Rule::EOI => "the end of the file",
        Rule::file | Rule::scene | Rule::kw_scene => "`scene`",
        Rule::body | Rule::lbrace => "`{`",
        Rule::rbrace => "`}`",
        Rule::assignment | Rule::block | Rule::call | Rule::ident | Rule::label | Rule::argument => "a name",
        Rule::arguments | Rule::lparen => "`(`",
        Rule::rparen => "`)`",
        Rule::range | Rule::quantity | Rule::number => "a number",
        Rule::range_step => "`step` or `count`",
        Rule::kw_step => "`step`",
        Rule::kw_count => "`count`",
        Rule::list | Rule::lbracket => "`[`",
        Rule::rbracket | Rule::list_end => "`]`",
        Rule::unit | Rule::unit_factor | Rule::unit_name | Rule::unit_one => "a unit",
        Rule::exponent => "a whole-number exponent",
        Rule::string | Rule::quote => "a \"string\"",
        Rule::string_inner => "text",
        Rule::eq => "`=`",
        Rule::comma => "`,`",
        Rule::dotdot => "`..`",
        Rule::star => "`*`",
        Rule::slash => "`/`",
        Rule::caret => "`^`",
        _ => "a token",
    }
}
