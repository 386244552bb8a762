//! The columns of the loss budget: one power (W) each, in the order every table, record file and
//! plot shows them.

/// A column of the budget (its index in [`COLUMNS`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LossColumn {
    GearNoLoad,
    BearingsNoLoad,
    BearingsLoad,
    Seals,
}

/// How a column is named where it is shown.
#[derive(Debug, Clone, Copy)]
pub struct ColumnEntry {
    pub column: LossColumn,
    /// The key in report.json (`gear_no_load`); the record files add `_W`.
    pub key: &'static str,
    /// The heading of report.md's budget table.
    pub heading: &'static str,
    /// The label of its part of a bar in loss_budget.svg.
    pub bar: &'static str,
    /// Whether it grows with the transmitted load (false: the no-load losses).
    pub load_dependent: bool,
}

impl LossColumn {
    pub fn entry(self) -> &'static ColumnEntry {
        &COLUMNS[self as usize]
    }

    pub fn key(self) -> &'static str {
        self.entry().key
    }

    /// The column of report.json's key, if any.
    pub fn of_key(key: &str) -> Option<LossColumn> {
        COLUMNS.iter().find(|c| c.key == key).map(|c| c.column)
    }

    /// The column of a record file's name (`gear_no_load_W`), if any.
    pub fn of_record(name: &str) -> Option<LossColumn> {
        name.strip_suffix("_W").and_then(LossColumn::of_key)
    }
}

/// Every column, in order.
pub const COLUMNS: &[ColumnEntry] = &[
    ColumnEntry {
        column: LossColumn::GearNoLoad,
        key: "gear_no_load",
        heading: "gears no-load W",
        bar: "gears no-load",
        load_dependent: false,
    },
    ColumnEntry {
        column: LossColumn::BearingsNoLoad,
        key: "bearings_no_load",
        heading: "bearings no-load W",
        bar: "bearings, no-load",
        load_dependent: false,
    },
    ColumnEntry {
        column: LossColumn::BearingsLoad,
        key: "bearings_load",
        heading: "bearings load W",
        bar: "bearings, load",
        load_dependent: true,
    },
    ColumnEntry { column: LossColumn::Seals, key: "seals", heading: "seals W", bar: "seals", load_dependent: false },
];
