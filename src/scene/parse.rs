//! Stage 1, parse: `.gear` text → [`SceneAst`], with pest (`grammar/gear.pest`).
//!
//! One `parse_x(pair)` per grammar rule, each matching on `as_rule()`; children are never taken by
//! position. A syntax error becomes a [`Diagnostic`] that says, in words, what was expected.

use pest::iterators::Pair;
use pest::Parser;

use super::ast::*;
pub use super::grammar::{GearParser, Rule};
use super::syntax_errors::syntax_error;
use crate::diagnostics::{Diagnostic, DiagnosticKind};

pub use super::syntax_errors::describe_rule;

/// Parses a whole scene file.
pub fn parse_scene_text(source: &str) -> Result<SceneAst, Vec<Diagnostic>> {
    let screened = super::screen::screen(source);
    if !screened.is_empty() {
        return Err(screened);
    }
    let mut pairs = GearParser::parse(Rule::file, source).map_err(|e| vec![syntax_error(source, e)])?;
    let file = pairs.next().expect("pest returns the file rule on success");
    let mut errors = Vec::new();
    let mut scene = None;
    for pair in file.into_inner() {
        match pair.as_rule() {
            Rule::scene => scene = Some(parse_scene(pair, &mut errors)),
            Rule::EOI => {}
            rule => unreachable!("file holds only a scene, got {rule:?}"),
        }
    }
    match scene {
        Some(scene) if errors.is_empty() => Ok(scene),
        _ => Err(errors),
    }
}

/// Parses a lone unit expression such as `lbf*in` or `1/GPa` (used by the unit table's tests and `gearloss units`).
pub fn parse_unit_text(text: &str) -> Result<UnitExpr, Vec<Diagnostic>> {
    let mut pairs = GearParser::parse(Rule::unit, text).map_err(|e| vec![syntax_error(text, e)])?;
    let pair = pairs.next().expect("pest returns the unit rule on success");
    if pair.as_span().end() != text.len() {
        let at = pair.as_span().end();
        return Err(vec![Diagnostic::new(
            DiagnosticKind::Syntax,
            Span::new(at, text.len()),
            "unexpected text after the unit",
        )]);
    }
    let mut errors = Vec::new();
    let unit = parse_unit(pair, &mut errors);
    if errors.is_empty() {
        Ok(unit)
    } else {
        Err(errors)
    }
}

fn parse_scene(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> SceneAst {
    let mut scene = SceneAst { title: String::new(), title_span: pair.as_span().into(), items: Vec::new() };
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::kw_scene => {}
            Rule::string => {
                scene.title_span = p.as_span().into();
                scene.title = parse_string(p);
            }
            Rule::body => scene.items = parse_body(p, errors),
            rule => unreachable!("scene: {rule:?}"),
        }
    }
    scene
}

fn parse_body(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Vec<Item> {
    let mut items = Vec::new();
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::lbrace | Rule::rbrace => {}
            Rule::assignment => items.push(parse_assignment(p, errors)),
            Rule::block => items.push(Item::Block(parse_block(p, errors))),
            Rule::call => items.push(Item::Call(parse_call(p, errors))),
            rule => unreachable!("body: {rule:?}"),
        }
    }
    items
}

fn parse_assignment(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Item {
    let mut key = None;
    let mut value = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::ident => key = Some(parse_ident(p)),
            Rule::eq => {}
            _ => value = Some(parse_value(p, errors)),
        }
    }
    Item::Assignment {
        key: key.expect("grammar: assignment has a key"),
        value: value.expect("grammar: assignment has a value"),
    }
}

fn parse_block(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Block {
    let span = pair.as_span().into();
    let mut kind = None;
    let mut label = None;
    let mut items = Vec::new();
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::ident => kind = Some(parse_ident(p)),
            Rule::label => label = Some(parse_label(p)),
            Rule::body => items = parse_body(p, errors),
            rule => unreachable!("block: {rule:?}"),
        }
    }
    Block { kind: kind.expect("grammar: block has a kind"), label, items, span }
}

fn parse_label(pair: Pair<Rule>) -> Name {
    let span: Span = pair.as_span().into();
    let mut text = String::new();
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::string => text = parse_string(p),
            Rule::ident => text = p.as_str().to_string(),
            rule => unreachable!("label: {rule:?}"),
        }
    }
    Name { text, span }
}

fn parse_call(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Call {
    // The span ends at the name or the closing parenthesis, never on whitespace pest skipped.
    let mut span = Span::new(pair.as_span().start(), pair.as_span().start());
    let mut name = None;
    let mut arguments = Vec::new();
    for p in pair.into_inner() {
        span.end = p.as_span().end();
        match p.as_rule() {
            Rule::ident => name = Some(parse_ident(p)),
            Rule::arguments => {
                let n = name.as_ref().expect("grammar: the name comes first");
                arguments = parse_arguments(p, n, errors)
            }
            rule => unreachable!("call: {rule:?}"),
        }
    }
    Call { name: name.expect("grammar: call has a name"), arguments, span }
}

/// Functions whose arguments may be given in order, and the names the positions stand for.
const POSITIONAL: &[(&str, &[&str])] = &[("iso_vg", &["grade", "base"])];
/// Functions that take a bare flag among their arguments (`bearing(..., locating)`): the flag is
/// read as an argument of its own name.
const FLAGS: &[(&str, &[&str])] = &[("bearing", &["locating"])];

/// The flag's name when `value` is a bare flag of `call`.
fn flag_of(call: &Name, value: &Value) -> Option<Name> {
    let flags = FLAGS.iter().find(|(f, _)| *f == call.text).map_or(&[][..], |(_, n)| *n);
    match &value.kind {
        ValueKind::Call(c) if c.arguments.is_empty() && flags.contains(&c.name.text.as_str()) => Some(c.name.clone()),
        _ => None,
    }
}

fn parse_arguments(pair: Pair<Rule>, call: &Name, errors: &mut Vec<Diagnostic>) -> Vec<(Name, Value)> {
    let mut out = Vec::new();
    let names = POSITIONAL.iter().find(|(f, _)| *f == call.text).map_or(&[][..], |(_, n)| *n);
    let mut position = 0;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::lparen | Rule::rparen | Rule::comma => {}
            Rule::argument => {
                let (key, value) = parse_argument(p, errors);
                match key {
                    Some(key) => out.push((key, value)),
                    None if flag_of(call, &value).is_some() => {
                        out.extend(flag_of(call, &value).map(|name| (name, value)));
                    }
                    None => {
                        match names.get(position) {
                            Some(name) => out.push((Name { text: name.to_string(), span: value.span }, value)),
                            None => errors.push(
                                Diagnostic::new(
                                    DiagnosticKind::Syntax,
                                    value.span,
                                    format!("`{}` takes its arguments by name", call.text),
                                )
                                .hint(if names.is_empty() {
                                    "write `name = value`, e.g. `coulomb(mu = 0.04)`".to_string()
                                } else {
                                    format!(
                                        "`{}` takes {} arguments in order: {}",
                                        call.text,
                                        names.len(),
                                        names.join(", ")
                                    )
                                }),
                            ),
                        }
                        position += 1;
                    }
                }
            }
            rule => unreachable!("arguments: {rule:?}"),
        }
    }
    out
}

fn parse_argument(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> (Option<Name>, Value) {
    let mut key = None;
    let mut value = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::ident => key = Some(parse_ident(p)),
            Rule::eq => {}
            _ => value = Some(parse_value(p, errors)),
        }
    }
    (key, value.expect("grammar: argument has a value"))
}

fn parse_value(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Value {
    let span: Span = pair.as_span().into();
    let kind = match pair.as_rule() {
        Rule::quantity => parse_quantity(pair, errors),
        Rule::list => parse_list(pair, errors),
        Rule::range => parse_range(pair, errors),
        Rule::call => ValueKind::Call(parse_call(pair, errors)),
        Rule::string => ValueKind::Text(parse_string(pair)),
        rule => unreachable!("value: {rule:?}"),
    };
    Value { kind, span }
}

fn parse_quantity(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> ValueKind {
    let mut number = None;
    let mut unit = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::number => number = Some(parse_number(p)),
            Rule::unit => unit = Some(parse_unit(p, errors)),
            rule => unreachable!("quantity: {rule:?}"),
        }
    }
    let number = number.unwrap_or_else(|| unreachable!("the grammar gives every quantity its number"));
    ValueKind::Quantity { number, unit }
}

fn parse_list(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> ValueKind {
    let mut items = Vec::new();
    let mut unit = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::lbracket | Rule::comma => {}
            Rule::number => {
                let span = p.as_span().into();
                items.push(ListItem::Number(parse_number(p), span));
            }
            Rule::ident => items.push(ListItem::Name(parse_ident(p))),
            Rule::list_end => unit = parse_list_end(p, errors),
            rule => unreachable!("list: {rule:?}"),
        }
    }
    ValueKind::List { items, unit }
}

fn parse_list_end(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> Option<UnitExpr> {
    let mut unit = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::rbracket => {}
            Rule::unit => unit = Some(parse_unit(p, errors)),
            rule => unreachable!("list_end: {rule:?}"),
        }
    }
    unit
}

fn parse_range(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> ValueKind {
    let mut bounds = Vec::with_capacity(2);
    let mut unit = None;
    let mut step = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::number => bounds.push(parse_number(p)),
            Rule::dotdot => {}
            Rule::unit => unit = Some(parse_unit(p, errors)),
            Rule::range_step => step = Some(parse_range_step(p)),
            rule => unreachable!("range: {rule:?}"),
        }
    }
    ValueKind::Range { from: bounds[0], to: bounds[1], unit, step }
}

fn parse_range_step(pair: Pair<Rule>) -> RangeStep {
    let mut is_count = false;
    let mut value = None;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::kw_step => is_count = false,
            Rule::kw_count => is_count = true,
            Rule::number => value = Some((parse_number(p.clone()), p.as_span().into())),
            rule => unreachable!("range_step: {rule:?}"),
        }
    }
    let value: (f64, Span) = value.unwrap_or_else(|| unreachable!("the grammar gives every step its number"));
    if is_count {
        RangeStep::Count(value.0, value.1)
    } else {
        RangeStep::Step(value.0, value.1)
    }
}

fn parse_unit(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> UnitExpr {
    let text = pair.as_str().to_string();
    let span = pair.as_span().into();
    let mut factors = Vec::new();
    let mut sign = 1;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::unit_one | Rule::star => sign = 1,
            Rule::slash => sign = -1,
            Rule::unit_factor => {
                let (name, name_span, exponent) = parse_unit_factor(p, errors);
                factors.push((name, name_span, sign * exponent));
            }
            rule => unreachable!("unit: {rule:?}"),
        }
    }
    UnitExpr { text, span, factors }
}

fn parse_unit_factor(pair: Pair<Rule>, errors: &mut Vec<Diagnostic>) -> (String, Span, i32) {
    let mut name = (String::new(), Span::default());
    let mut exponent = 1;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::unit_name => name = (p.as_str().to_string(), p.as_span().into()),
            Rule::caret => {}
            Rule::exponent => {
                exponent = match p.as_str().parse::<i32>() {
                    Ok(e) if (-6..=6).contains(&e) && e != 0 => e,
                    _ => {
                        errors.push(
                            Diagnostic::new(
                                DiagnosticKind::Syntax,
                                p.as_span().into(),
                                format!("unit exponent `{}` is not supported", p.as_str()),
                            )
                            .hint("exponents are whole numbers from -6 to 6, not 0, as in `kg*m^2`"),
                        );
                        1
                    }
                }
            }
            rule => unreachable!("unit_factor: {rule:?}"),
        }
    }
    (name.0, name.1, exponent)
}

fn parse_ident(pair: Pair<Rule>) -> Name {
    Name { text: pair.as_str().to_string(), span: pair.as_span().into() }
}

fn parse_number(pair: Pair<Rule>) -> f64 {
    // The grammar admits only decimal numbers and the words NaN, inf and infinity, which
    // `f64::from_str` always accepts (an overflow gives ±inf, which lowering reports as non-finite).
    let text = pair.as_str();
    text.parse().unwrap_or_else(|_| unreachable!("the grammar admits `{text}` as a number"))
}

fn parse_string(pair: Pair<Rule>) -> String {
    pair.into_inner().filter(|p| p.as_rule() == Rule::string_inner).map(|p| p.as_str().to_string()).collect()
}
