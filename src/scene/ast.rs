//! The syntax tree of a `.gear` file: what was written, with spans, before any name or unit is checked.

pub(crate) use crate::diagnostics::Span;

impl From<pest::Span<'_>> for Span {
    fn from(s: pest::Span<'_>) -> Self {
        Span::new(s.start(), s.end())
    }
}

/// A name as written, with where it stands.
#[derive(Debug, Clone, PartialEq)]
pub struct Name {
    pub text: String,
    pub span: Span,
}

/// `scene "label" { ... }`
#[derive(Debug, Clone, PartialEq)]
pub struct SceneAst {
    pub title: String,
    pub title_span: Span,
    pub items: Vec<Item>,
}

/// One entry inside a block body.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// `key = value`
    Assignment { key: Name, value: Value },
    /// `kind label? { items }`
    Block(Block),
    /// `name` or `name(arg = value, ...)`
    Call(Call),
}

impl Item {
    /// The name that starts the item (key, block kind or call name).
    pub fn head(&self) -> &Name {
        match self {
            Item::Assignment { key, .. } => key,
            Item::Block(b) => &b.kind,
            Item::Call(c) => &c.name,
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    pub kind: Name,
    pub label: Option<Name>,
    pub items: Vec<Item>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Call {
    pub name: Name,
    pub arguments: Vec<(Name, Value)>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Value {
    pub kind: ValueKind,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub enum ValueKind {
    /// `4.5 mm`, `16`
    Quantity { number: f64, unit: Option<UnitExpr> },
    /// `[1, 2, 3] rpm`, `[external, internal]`
    List { items: Vec<ListItem>, unit: Option<UnitExpr> },
    /// `100..3000 rpm step 100`
    Range { from: f64, to: f64, unit: Option<UnitExpr>, step: Option<RangeStep> },
    /// `equal`, `coulomb(mu = 0.08)`
    Call(Call),
    /// `"ISO VG 100"`
    Text(String),
}

#[derive(Debug, Clone, PartialEq)]
pub enum ListItem {
    Number(f64, Span),
    Name(Name),
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RangeStep {
    /// `step 100`: every 100 units from `from` to `to` inclusive.
    Step(f64, Span),
    /// `count 30`: 30 evenly spaced values including both ends.
    Count(f64, Span),
}

/// A unit expression: a product of powers of unit names.
#[derive(Debug, Clone, PartialEq)]
pub struct UnitExpr {
    pub text: String,
    pub span: Span,
    /// (unit name, its span, exponent); `1/Pa` is `[("Pa", -1)]`.
    pub factors: Vec<(String, Span, i32)>,
}
