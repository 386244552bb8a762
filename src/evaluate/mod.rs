//! Stage 3, evaluate: computes only what the scene asks for, in plain SI `f64`.
//!
//! The operating points reported in full become [`Case`]s (`cases`); at each case the contact state along the
//! line of action is always computed, friction, efficiency and film thickness only when the scene's
//! `analyses` name them (`laws`), and the dynamics only when it has a `dynamics` block and asks for
//! them (`dynamics`). Report and render read the evaluation; they never recompute physics.

pub(crate) mod cases;
pub(crate) mod contact_curves;
pub(crate) mod cycle_bearings;
pub(crate) mod cycle_pieces;
pub(crate) mod cycle_transient;
pub(crate) mod details;
pub(crate) mod drive;
pub mod drive_cycle;
pub(crate) mod drive_grid;
pub(crate) mod drive_map_best;
pub(crate) mod drive_map_cell;
pub(crate) mod drive_plausibility;
pub(crate) mod drive_records;
pub(crate) mod drive_setup;
pub(crate) mod drive_thermal;
pub(crate) mod dynamics;
pub(crate) mod evaluation;
pub(crate) mod first_balance;
pub(crate) mod laws;
pub(crate) mod map_best;
pub(crate) mod pair_records;
pub(crate) mod plan;
pub(crate) mod prepare;
pub(crate) mod record_cells;
pub(crate) mod record_files;
pub(crate) mod record_parquet;
pub(crate) mod record_parquet_read;
pub(crate) mod records;
pub(crate) mod setup;
pub(crate) mod stage_mesh;
pub(crate) mod stage_pairs;
pub(crate) mod stages;
pub(crate) mod static_loads;
pub(crate) mod ste_row;
pub(crate) mod stream;
pub(crate) mod tally;
pub(crate) mod teeth;
pub(crate) mod thermal;

use crate::mesh::MeshProblem;

pub use cases::{
    case_at, cycle_times, pick, state_at, table_positions, Case, CURVE_SAMPLES, MAX_CURVES, TABLE_INTERVALS,
};
pub use contact_curves::ContactCurves;
pub use details::evaluate_details;
pub use evaluation::{Evaluation, PointEvaluation};
pub use laws::{LawCurves, LawEvaluation, ValiditySummary};

pub use crate::thermal::Ratings;
pub use drive::{evaluate_drive, evaluate_drive_into, DriveEvaluation, DriveTally};
pub use drive_thermal::{drive_duty, DriveLosses};
pub use plan::{evenly, ALL_IN_DETAIL, MAP_VALUES, PLOTTED_VALUES};
pub use plan::{Plan, Shard};
pub use prepare::prepare;
pub use record_cells::Cell;
pub use record_parquet::ColumnType;
pub use record_parquet_read::read_parquet_records;
pub use records::{ExtraColumns, NoRecords};
pub use records::{RecordSink, SummaryRow};
pub use setup::{contact_table, Setup};
pub use stage_pairs::{stage_pairs, MeshAtPoint, StagePair};
pub use stream::evaluate_records;
pub use tally::implausible_efficiency;
pub use tally::Tally;
pub use teeth::{teeth_details, TeethDetails};
pub use thermal::DutyCycleResult;

/// Evaluates one mesh's problem in full: every operating point in detail (small scenes, tests and
/// benches; a run over a sweep uses [`prepare`], [`stream::evaluate_records`] and [`evaluate_details`]).
pub fn evaluate_mesh(problem: &MeshProblem) -> Evaluation {
    let plan = Plan::new(&problem.operating, None, &[]);
    let mut eval = prepare(problem, &plan);
    evaluate_details(problem, &mut eval, &plan, &Default::default(), &|| {});
    eval
}
