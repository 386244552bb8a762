//! The pest parser generated from `grammar/gear.pest`, and its [`Rule`]s.

use pest_derive::Parser;

#[derive(Parser)]
#[grammar = "../grammar/gear.pest"]
pub struct GearParser;
