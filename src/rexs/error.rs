//! A REXS model that cannot be imported: what is wrong, where (the component), and what to do.

use super::model::Component;

#[derive(Debug, Clone, PartialEq)]
pub struct RexsError {
    /// `component 6 (cylindrical_gear "Cylindrical gear [27]")`, when one is at fault.
    pub component: Option<String>,
    pub message: String,
    pub hint: String,
    /// The model's further errors, found in the same reading (every stage, shaft and load case is
    /// read even after one fails), in the order met.
    pub more: Vec<RexsError>,
}

impl RexsError {
    pub(crate) fn new(message: impl Into<String>, hint: impl Into<String>) -> RexsError {
        RexsError { component: None, message: message.into(), hint: hint.into(), more: Vec::new() }
    }

    /// The first of `errors` carrying the rest; `None` when there are none.
    pub(crate) fn gather(errors: Vec<RexsError>) -> Option<RexsError> {
        let mut all = errors.into_iter().flat_map(|e| e.all().cloned().collect::<Vec<_>>());
        let first = all.next()?;
        Some(RexsError { more: all.map(|e| RexsError { more: Vec::new(), ..e }).collect(), ..first })
    }

    /// This error and every further one, each with its own component and hint.
    pub fn all(&self) -> impl Iterator<Item = &RexsError> {
        std::iter::once(self).chain(self.more.iter())
    }

    /// An error at component `c`.
    pub(crate) fn at(c: &Component, message: impl Into<String>, hint: impl Into<String>) -> RexsError {
        RexsError { component: Some(describe(c)), ..RexsError::new(message, hint) }
    }
}

/// `component 6 (cylindrical_gear "Cylindrical gear [27]")`.
pub(crate) fn describe(c: &Component) -> String {
    format!("component {} ({} \"{}\")", c.id, c.kind, c.name)
}

impl std::fmt::Display for RexsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.component {
            Some(c) => write!(f, "{c}: {}", self.message),
            None => write!(f, "{}", self.message),
        }
    }
}

impl std::error::Error for RexsError {}
