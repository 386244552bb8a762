//! The loss budget of one operating point beside the mesh: gear churning or jet impulse, bearings
//! (no-load and load-dependent) and seals, with the bearing loads it took them from.
//!
//! Bearing loads come from the mesh force at the gear's mid-plane: the transverse force
//! F_bt = T_1/r_b1 along the line of action (the same on both shafts; tangential part
//! F_t = F_bt cos α_wt, radial part F_r = F_bt sin α_wt) and, for a helical pair, the axial force
//! F_a = F_t tan β_w acting at the working pitch radius r_w. With positions on a shaft of two bearing
//! places, the shaft is a beam on them and [`shaft_reactions`] solves its statics (3 forces, 2
//! moments); without positions each of the shaft's bearings carries F_bt / (number of bearings) and
//! the axial moment is not taken up. The axial force goes to the shaft's first bearing place (the
//! locating bearing), divided by its count.
//!
//! Axial convention: `at` is measured on one common axial direction for both shafts, from the gear
//! mid-plane. The axial mesh force on the pinion points towards increasing `at`, the wheel's (its
//! reaction) towards decreasing `at`. For a pair of the other hand, or turning the other way, the
//! axial forces reverse: mirror the positions (write each `at` with the opposite sign).

use serde::Serialize;

use super::bearings::Bearing;
use super::gear_no_load::GearsRunning;
use super::gearbox::Gearbox;
use super::oil::Oil;
use crate::geometry::PairGeometry;

/// The loads and losses of one bearing place.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingLoss {
    /// "pinion" or "wheel".
    pub shaft: &'static str,
    pub kind: &'static str,
    /// "palmgren" or "skf".
    pub model: &'static str,
    pub count: usize,
    /// Axial position `at` (m), when the scene gives one.
    pub position: Option<f64>,
    /// The numbers: loads of one bearing, losses of all `count`.
    pub loads: BearingLoads,
}

/// What one bearing place carries and loses at an operating point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BearingLoads {
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
/// [`super::gear_no_load::Lubrication::note`].)
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
/// beside the mesh, the total and the total efficiency 1 − P_total/P_in, and every bearing place's
/// loads and losses in the scene's order (pinion shaft, then wheel shaft), as the record files carry
/// it ([`super::columns`] names the columns).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BudgetParts {
    pub gear_no_load: Option<f64>,
    pub bearings_no_load: Option<f64>,
    pub bearings_load: Option<f64>,
    pub seals: Option<f64>,
    pub total_loss: f64,
    pub total_efficiency: f64,
    pub bearings: Vec<BearingLoads>,
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
            bearings: self.bearings.iter().map(|b| b.loads).collect(),
        }
    }
}

/// The mesh force on one shaft's gear (N) and the radius where the axial part acts (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearForce {
    pub tangential: f64,
    pub radial: f64,
    /// Along the common axial direction of `at` (+F_a on the pinion, −F_a on the wheel).
    pub axial: f64,
    /// The working pitch radius r_w of this shaft's gear.
    pub radius: f64,
}

/// The reactions [x, y, z] (N) of a shaft's two bearing places at positions p_1 ≠ p_2 (m) on the
/// gear force `f`, by statics of the shaft as a beam. Frame of the shaft: x along the line of
/// centres towards the mesh, y along the tangential force, z the common axial direction of `at`;
/// the gear force (−F_r, F_t, F_a) acts at (r_w, 0, 0). Forces: R_1 + R_2 + F = 0; moments about the
/// gear centre's x and y axes: Σ p_i e_z × R_i + r_w e_x × F = 0 (the z moment is the shaft's torque).
/// The axial reaction is all at the first place.
///
/// ```
/// use gearloss::losses::budget::{shaft_reactions, GearForce};
/// let f = GearForce { tangential: 1000.0, radial: 364.0, axial: 268.0, radius: 0.04 };
/// let [r1, r2] = shaft_reactions(f, [-0.05, 0.05]);
/// // Force balance, and the moment about y: p_1 R_1x + p_2 R_2x = r_w F_a.
/// assert!((r1[0] + r2[0] - 364.0).abs() < 1e-12 && (r1[1] + r2[1] + 1000.0).abs() < 1e-12);
/// assert!((-0.05 * r1[0] + 0.05 * r2[0] - 0.04 * 268.0).abs() < 1e-12);
/// ```
pub fn shaft_reactions(f: GearForce, [p1, p2]: [f64; 2]) -> [[f64; 3]; 2] {
    let span = p2 - p1;
    let x2 = (f.radius * f.axial - p1 * f.radial) / span;
    let y2 = p1 * f.tangential / span;
    [[f.radial - x2, -f.tangential - y2, -f.axial], [x2, y2, 0.0]]
}

/// Radial and axial load of one bearing at each bearing place of one shaft (N).
fn place_loads(places: &[Bearing], f: GearForce, f_bt: f64) -> Vec<(f64, f64)> {
    let count: usize = places.iter().map(|b| b.count).sum();
    let axial_at = |i: usize| if i == 0 { f.axial.abs() / places[0].count as f64 } else { 0.0 };
    match places {
        [a, b] if a.position.is_some() && b.position.is_some() => {
            let p = [a.position.unwrap_or(0.0), b.position.unwrap_or(0.0)];
            let r = shaft_reactions(f, p);
            [a.count, b.count]
                .iter()
                .enumerate()
                .map(|(i, &n)| (r[i][0].hypot(r[i][1]) / n as f64, axial_at(i)))
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
    let force = |s: usize| GearForce {
        tangential: f_bt * g.operating_pressure_angle.cos(),
        radial: f_bt * g.operating_pressure_angle.sin(),
        axial: if s == 0 { axial } else { -axial },
        radius: g.working_pitch_radius[s],
    };
    if gearbox.bearings.iter().any(|b| !b.is_empty()) {
        let (mut no_load, mut load) = (0.0, 0.0);
        for (s, places) in gearbox.bearings.iter().enumerate().filter(|(_, p)| !p.is_empty()) {
            let loads = place_loads(places, force(s), f_bt);
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
                    model: b.model_name(),
                    count: b.count,
                    position: b.position,
                    loads: BearingLoads { radial_load: fr, axial_load: fa, no_load: p0, load: p1 },
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
