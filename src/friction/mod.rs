//! Friction laws along the line of action: one file per law behind a small trait.

pub mod catalog;
