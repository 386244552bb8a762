//! A REXS model that cannot be imported: what is wrong, where (the component), and what to do.

use super::model::Component;

#[derive(Debug, Clone, PartialEq)]
pub struct RexsError {
    /// `component 6 (cylindrical_gear "Cylindrical gear [27]")`, when one is at fault.
    pub component: Option<String>,
    pub message: String,
    pub hint: String,
}

impl RexsError {
    pub(crate) fn new(message: impl Into<String>, hint: impl Into<String>) -> RexsError {
        RexsError { component: None, message: message.into(), hint: hint.into() }
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
