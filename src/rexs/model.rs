//! A REXS model as read, format aside: components with typed attributes, relations tying them by
//! id with roles, and the load spectrum's cases (REXS, the FVA's Reusable Engineering EXchange
//! Standard, rexs.info; file structure after its `rexs-file.xsd` and `rexs-file.json`).

use std::collections::BTreeMap;

/// An attribute's value as written.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum AttributeValue {
    Number(f64),
    Text(String),
    Bool(bool),
    Numbers(Vec<f64>),
    /// A boolean per gear (`is_engaged` of a switchable coupling, one per gear shift index).
    Bools(Vec<bool>),
    /// A value this reader does not use (matrices, coded arrays of arrays, file references).
    Other,
}

/// One attribute: its REXS id, its unit as written (None when the file gives none) and value.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Attribute {
    pub id: String,
    pub unit: Option<String>,
    pub value: AttributeValue,
}

/// One component.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Component {
    pub id: u64,
    pub kind: String,
    pub name: String,
    pub attributes: Vec<Attribute>,
}

impl Component {
    /// The first attribute with any of `ids` (a renamed attribute's names, newest first).
    pub(crate) fn attribute(&self, ids: &[&str]) -> Option<&Attribute> {
        ids.iter().find_map(|id| self.attributes.iter().find(|a| a.id == *id))
    }
}

/// One reference of a relation.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Reference {
    pub id: u64,
    pub role: String,
    pub hint: Option<String>,
}

/// One relation.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Relation {
    pub kind: String,
    pub refs: Vec<Reference>,
}

impl Relation {
    /// The component in `role`.
    pub(crate) fn role(&self, role: &str) -> Option<u64> {
        self.refs.iter().find(|r| r.role == role).map(|r| r.id)
    }
}

/// One load case: per component id, the attributes it adds or overrides.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct LoadCase {
    pub id: u64,
    pub components: BTreeMap<u64, Vec<Attribute>>,
}

/// A whole model.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct RexsModel {
    pub version: String,
    pub application: String,
    pub components: BTreeMap<u64, Component>,
    pub relations: Vec<Relation>,
    pub load_cases: Vec<LoadCase>,
}

impl RexsModel {
    /// The components of `kind`, in id order.
    pub(crate) fn of_kind<'a>(&'a self, kind: &'a str) -> impl Iterator<Item = &'a Component> + 'a {
        self.components.values().filter(move |c| c.kind == kind)
    }

    /// The relations of `kind` whose `role` is component `id`.
    pub(crate) fn relations_with<'a>(
        &'a self,
        kind: &'a str,
        role: &'a str,
        id: u64,
    ) -> impl Iterator<Item = &'a Relation> + 'a {
        self.relations.iter().filter(move |r| r.kind == kind && r.role(role) == Some(id))
    }
}
