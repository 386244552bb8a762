//! Stage 3 as the pipeline calls it: the plan's points streamed into a record sink, and the
//! detail points in full, each announcing itself to a [`Progress`].

use super::evaluation::Evaluation;
use super::plan::Plan;
use super::records::RecordSink;
use super::stream::{evaluate_records, Streamed};
use crate::mesh::MeshProblem;
use crate::progress::Progress;

/// The plan's points streamed: summary rows to `sink` in sweep order, the tally and the detail
/// points' dynamics returned.
pub(crate) fn stream(
    problem: &MeshProblem,
    plan: &Plan,
    sink: &mut dyn RecordSink,
    progress: &dyn Progress,
) -> std::io::Result<Streamed> {
    let eval = super::prepare::prepare(problem, plan);
    progress.stage("evaluate", plan.range.len() as u64);
    evaluate_records(problem, &eval, plan, sink, &|n| {
        progress.advance(n as u64);
        !progress.cancelled()
    })
}

/// The plan's detail points in full, reusing what the stream computed (`known`).
pub(crate) fn details(problem: &MeshProblem, plan: &Plan, known: &Streamed, progress: &dyn Progress) -> Evaluation {
    let mut eval = super::prepare::prepare(problem, plan);
    progress.stage("details", plan.detail.len() as u64);
    super::details::evaluate_details(problem, &mut eval, plan, known, &|| progress.advance(1));
    eval
}
