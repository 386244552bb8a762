//! The rolling bearings' loss P_VL as a part of the budget, bearing place by bearing place with the
//! loads each carries (the moments are `crate::losses::bearings` and `crate::losses::skf_bearing`):
//! per place, M_0 (or M_rr) and M_1 (or M_sl) at its shaft's speed under the loads its shaft's
//! statics put on one of its bearings, times the place's count.

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::bearing_loss::BearingLoads;
use crate::losses::oil::Oil;

/// Every bearing place of every shaft.
pub(crate) struct Bearings;

impl LossPart for Bearings {
    fn id(&self) -> LossPartId {
        LossPartId::Bearings
    }

    fn present(&self, on: &PartState) -> bool {
        on.shafts.iter().any(|s| !s.bearings.is_empty())
    }

    fn reads_loads(&self) -> bool {
        true
    }

    /// Per bearing place: M_0 (or M_rr) and M_1 (or M_sl) at the shaft's speed under its loads,
    /// times the place's count; the no-load and load columns add them up. A place whose model has
    /// no load moment (a bearing without the C_0 its f_1 needs) adds none and keeps none.
    fn losses(&self, on: &PartState, oil: &Oil, out: &mut PartLosses) {
        // Lowering refuses bearings in an oil without ν; no ν, no bearing columns.
        let Some(nu) = oil.nu else { return };
        for (j, shaft) in on.shafts.iter().enumerate().filter(|(_, s)| !s.bearings.is_empty()) {
            let w = shaft.speed;
            for (b, &[fr, fa]) in shaft.bearings.iter().zip(shaft.loads) {
                let n = b.count as f64;
                let (m0, m1) = b.moments(fr, fa, nu, w, oil.mineral);
                let p0 = m0 * w * n;
                let p1 = m1.map(|m| m * w * n);
                out.add(j, LossColumn::BearingsNoLoad, p0);
                out.add(j, LossColumn::BearingsLoad, p1.unwrap_or(0.0));
                if let Some(places) = out.places.as_mut() {
                    places[j].push(BearingLoads { radial_load: fr, axial_load: fa, no_load: p0, load: p1 });
                }
            }
        }
    }
}
