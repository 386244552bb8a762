//! The rolling bearings' loss P_VL as a part of the budget, bearing place by bearing place with the
//! loads each carries (the moments are `crate::losses::bearings` and
//! `crate::losses::skf_bearing`).
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

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::bearing_loss::{BearingLoads, BearingLoss};
use crate::losses::bearings::Bearing;
use crate::losses::gearbox::Gearbox;
use crate::losses::oil::Oil;

/// The bearing places of [pinion shaft, wheel shaft].
pub struct Bearings<'a>(pub &'a [Vec<Bearing>; 2]);

/// The part of `gearbox`, when it has a bearing.
pub fn of(gearbox: &Gearbox) -> Option<Box<dyn LossPart + '_>> {
    gearbox.bearings.iter().any(|b| !b.is_empty()).then(|| Box::new(Bearings(&gearbox.bearings)) as Box<dyn LossPart>)
}

impl LossPart for Bearings<'_> {
    fn id(&self) -> LossPartId {
        LossPartId::Bearings
    }

    /// Per bearing place: its loads, M_0 (or M_rr) and M_1 (or M_sl) at the shaft's speed, times
    /// the place's count; the no-load and load columns add them up.
    fn losses(&self, at: &PartState, oil: &Oil, out: &mut PartLosses) {
        let f_bt = at.transverse_force;
        let force = |s: usize| GearForce {
            tangential: f_bt * at.pressure_angle.cos(),
            radial: f_bt * at.pressure_angle.sin(),
            axial: if s == 0 { at.axial_force } else { -at.axial_force },
            radius: at.pitch_radius[s],
        };
        // Lowering refuses bearings in an oil without ν; no ν, no bearing columns.
        let Some(nu) = oil.nu else { return };
        for (s, places) in self.0.iter().enumerate().filter(|(_, p)| !p.is_empty()) {
            let loads = place_loads(places, force(s), f_bt);
            // The shaft's columns, then added to the budget's shaft by shaft.
            let mut shaft = PartLosses::default();
            for (b, (fr, fa)) in places.iter().zip(loads) {
                let n = b.count as f64;
                let (m0, m1) = b.moments(fr, fa, nu, at.omega[s], oil.mineral);
                let p0 = m0 * at.omega[s] * n;
                let p1 = m1.map(|m| m * at.omega[s] * n);
                shaft.add(LossColumn::BearingsNoLoad, p0);
                shaft.add(LossColumn::BearingsLoad, p1.unwrap_or(0.0));
                out.bearings.push(BearingLoss {
                    shaft: ["pinion", "wheel"][s],
                    kind: b.kind.name(),
                    model: b.model_name(),
                    count: b.count,
                    position: b.position,
                    loads: BearingLoads { radial_load: fr, axial_load: fa, no_load: p0, load: p1 },
                });
            }
            for (c, p) in shaft.powers {
                out.add(c, p);
            }
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
/// use gearloss::losses::parts::bearings::{shaft_reactions, GearForce};
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
