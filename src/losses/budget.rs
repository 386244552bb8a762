//! The loss budget of one operating point beside the mesh: gear churning or jet impulse, bearings
//! (no-load and load-dependent) and seals, with the bearing loads it took them from.
//!
//! Bearing loads come from the mesh force: the transverse force F_bt = T_1/r_b1 along the line of
//! action (the same on both shafts) and, for a helical pair, the axial force F_a with its moment
//! F_a r_w. With positions on a shaft of two bearing places the lever rule splits them (the gear
//! at position 0, the axial moment acting along the line of centres); without positions each of
//! the shaft's bearings carries F_bt / (number of bearings) and the axial moment is not taken up.
//! The axial force goes to the shaft's first bearing place (the locating bearing).

use serde::Serialize;

use super::{gear_no_load::GearsRunning, Gearbox, Oil};
use crate::geometry::PairGeometry;

/// The loads and losses of one bearing place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingLoss {
    /// "pinion" or "wheel".
    pub shaft: &'static str,
    pub kind: &'static str,
    pub count: usize,
    /// Radial and axial load of one bearing (N).
    pub radial_load: f64,
    pub axial_load: f64,
    /// Power loss of all `count` bearings (W): no-load and load-dependent.
    pub no_load: f64,
    /// `None` when the bearing's f_1 needs a static load rating it lacks (lowering refuses such a
    /// scene; a bearing built in code without one adds no load-dependent loss).
    pub load: Option<f64>,
}

/// Everything but the mesh at one operating point (W); parts the scene does not describe are `None`.
/// (Where a model leaves its tested range the report says so once for the run:
/// [`super::Lubrication::note`].)
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct LossBudget {
    pub gear_no_load: Option<f64>,
    pub bearings_no_load: Option<f64>,
    pub bearings_load: Option<f64>,
    pub seals: Option<f64>,
    pub bearings: Vec<BearingLoss>,
}

impl LossBudget {
    /// The sum of the parts present (W).
    pub fn beside_mesh(&self) -> f64 {
        [self.gear_no_load, self.bearings_no_load, self.bearings_load, self.seals].iter().flatten().sum()
    }
}

/// The budget of one (operating point, law, formulation): the mesh loss it was given plus the parts
/// beside the mesh, the total and the total efficiency 1 − P_total/P_in, as the record files carry it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct BudgetParts {
    #[serde(rename = "gear_no_load_W", skip_serializing_if = "Option::is_none", default)]
    pub gear_no_load: Option<f64>,
    #[serde(rename = "bearings_no_load_W", skip_serializing_if = "Option::is_none", default)]
    pub bearings_no_load: Option<f64>,
    #[serde(rename = "bearings_load_W", skip_serializing_if = "Option::is_none", default)]
    pub bearings_load: Option<f64>,
    #[serde(rename = "seals_W", skip_serializing_if = "Option::is_none", default)]
    pub seals: Option<f64>,
    #[serde(rename = "total_loss_W")]
    pub total_loss: f64,
    pub total_efficiency: f64,
}

impl LossBudget {
    /// The parts with a mesh loss `mesh` (W) at input power `input` (W).
    pub fn with_mesh(&self, mesh: f64, input: f64) -> BudgetParts {
        let total = mesh + self.beside_mesh();
        BudgetParts {
            gear_no_load: self.gear_no_load,
            bearings_no_load: self.bearings_no_load,
            bearings_load: self.bearings_load,
            seals: self.seals,
            total_loss: total,
            total_efficiency: 1.0 - total / input,
        }
    }
}

/// Radial and axial load per bearing place of one shaft (N).
fn place_loads(places: &[super::Bearing], f_bt: f64, alpha_wt: f64, axial: f64, r_w: f64) -> Vec<(f64, f64)> {
    let count: usize = places.iter().map(|b| b.count).sum();
    let axial_at = |i: usize| if i == 0 { axial / places[0].count as f64 } else { 0.0 };
    match places {
        [a, b] if a.position.is_some() && b.position.is_some() => {
            let (p1, p2) = (a.position.unwrap_or(0.0), b.position.unwrap_or(0.0));
            let span = p2 - p1;
            let (ft, fr) = (f_bt * alpha_wt.cos(), f_bt * alpha_wt.sin());
            let moment = axial * r_w / span;
            [(p2 / span, -moment, a.count, 0), (-p1 / span, moment, b.count, 1)]
                .iter()
                .map(|&(lever, m, n, i)| ((lever * ft).hypot(lever * fr + m) / n as f64, axial_at(i)))
                .collect()
        }
        _ => (0..places.len()).map(|i| (f_bt / count as f64, axial_at(i))).collect(),
    }
}

/// The budget at pinion torque T_1 (N·m) and speed ω_1 (rad/s) in `oil`.
pub fn loss_budget(gearbox: &Gearbox, g: &PairGeometry, torque: f64, omega_1: f64, oil: &Oil) -> LossBudget {
    let mut out = LossBudget::default();
    let omegas = [omega_1, omega_1 / g.gear_ratio];
    if let Some(l) = &gearbox.lubrication {
        let gears = GearsRunning { omega: omegas, pitch_radius: g.working_pitch_radius, face_width: g.face_width };
        out.gear_no_load = Some(l.power_loss(&gears, oil));
    }
    let f_bt = torque / g.base_radius[0];
    let axial = g.axial_force(torque);
    if gearbox.bearings.iter().any(|b| !b.is_empty()) {
        let (mut no_load, mut load) = (0.0, 0.0);
        for (s, places) in gearbox.bearings.iter().enumerate().filter(|(_, p)| !p.is_empty()) {
            let loads = place_loads(places, f_bt, g.operating_pressure_angle, axial, g.working_pitch_radius[s]);
            for (b, (fr, fa)) in places.iter().zip(loads) {
                let n = b.count as f64;
                let (m0, m1) = b.moments(fr, fa, oil.nu, omegas[s], oil.mineral);
                let p0 = m0 * omegas[s] * n;
                let p1 = m1.map(|m| m * omegas[s] * n);
                no_load += p0;
                load += p1.unwrap_or(0.0);
                out.bearings.push(BearingLoss {
                    shaft: ["pinion", "wheel"][s],
                    kind: b.kind.name(),
                    count: b.count,
                    radial_load: fr,
                    axial_load: fa,
                    no_load: p0,
                    load: p1,
                });
            }
        }
        out.bearings_no_load = Some(no_load);
        out.bearings_load = Some(load);
    }
    if gearbox.seals.iter().any(|s| !s.is_empty()) {
        out.seals = Some(
            gearbox.seals.iter().zip(omegas).flat_map(|(seals, w)| seals.iter().map(move |s| s.power_loss(w))).sum(),
        );
    }
    out
}
