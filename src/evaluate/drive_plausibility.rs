//! A drive's results that no gear mesh can have or whose formulas no longer hold, found at every
//! row as a pair's tally finds them of its own mesh ([`super::stream`]): a stage mesh whose
//! efficiency lies outside [0, 1] beyond rounding (a law giving negative friction or more loss than
//! the mesh carries), and a contact whose Hertzian half-width exceeds a tenth of its reduced radius
//! of curvature, b_H > R/10 (Hertz's line contact assumes b_H ≪ R; the pressure, the film and
//! every law that reads them stop holding there). The half-width is read at the contacts of a
//! pair's contact table (A to E in equal steps, B, P and D among them: `super::cases::table_positions`)
//! of each mesh at its driving member's torque and speed, as the pair alone reads it.

use serde::{Deserialize, Serialize};

use super::stage_mesh::StageMesh;
use super::tally::HALF_WIDTH_LIMIT;
use super::tally::{furthest_beyond_half_width, outside_unit_interval};
use crate::drive::DrivePoint;
use crate::model::SceneDrive;

/// What is implausible on one stage at one row: its index in the drive, its mesh's name (a stage
/// of several meshes) and what.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StageImplausible {
    pub stage: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh: Option<String>,
    pub what: Implausibility,
}

/// The mesh's efficiency outside [0, 1]; or the contact furthest beyond b_H = R/10 (m): its
/// half-width, the limit R/10, its place along the line of action from T1 and its name (`B`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Implausibility {
    Efficiency(f64),
    HalfWidth { half_width: f64, limit: f64, u: f64, named: Option<String> },
}

/// The first stage of `drive` (in its order, a stage's meshes in theirs; `stages` their meshes as
/// its setup holds them) with an implausible result at `point`; an efficiency is checked before the
/// contacts.
pub(crate) fn implausible(drive: &SceneDrive, stages: &[StageMesh], point: &DrivePoint) -> Option<StageImplausible> {
    for (k, s) in point.stages.iter().enumerate() {
        for m in drive.layout.stages[k].mesh_states(s) {
            let at = |what| StageImplausible { stage: k, mesh: m.name.map(str::to_string), what };
            if outside_unit_interval(m.efficiency) {
                return Some(at(Implausibility::Efficiency(m.efficiency)));
            }
            if m.torque <= 0.0 {
                continue;
            }
            let mesh = &stages[k];
            let (ctx, _) = mesh.law_context(m.mesh, m.driving, m.torque, m.speed);
            let contacts = mesh.table_positions(m.mesh, m.driving).iter().map(|(name, u)| (*name, ctx.contact_at(*u)));
            let worst = furthest_beyond_half_width(contacts);
            if let Some((name, c)) = worst {
                return Some(at(Implausibility::HalfWidth {
                    half_width: c.hertz_half_width,
                    limit: HALF_WIDTH_LIMIT * c.reduced_radius,
                    u: c.u,
                    named: name.map(str::to_string),
                }));
            }
        }
    }
    None
}
