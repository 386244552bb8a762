//! The gears' load-independent loss P_VZ0 as a part of the budget: churning by Mauz for dip
//! lubrication, the jet's impulse and the gears' windage for injection (ISO/TR 14179-2:2001; the
//! models and their sources are in [`crate::losses::gear_no_load`]). Each stage's mesh parts and its
//! first gear's windage are charged to the shaft the stage names first, the second gear's windage
//! to its own shaft ([`crate::losses::Lubrication::power_loss_by_gear`]).

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::oil::Oil;

/// The gears of every stage its lubrication sets running.
pub(crate) struct GearNoLoad;

impl LossPart for GearNoLoad {
    fn id(&self) -> LossPartId {
        LossPartId::GearNoLoad
    }

    fn present(&self, on: &PartState) -> bool {
        on.stages.iter().any(|s| s.lubrication.is_some())
    }

    fn reads_loads(&self) -> bool {
        false
    }

    fn losses(&self, on: &PartState, oil: &Oil, out: &mut PartLosses) {
        for (k, stage) in on.stages.iter().enumerate() {
            // Lowering refuses jets in an oil without a density; no density, nothing charged.
            let by_gear = stage.lubrication.and_then(|l| l.power_loss_by_gear(&stage.running, oil));
            let [own, other] = by_gear.unwrap_or([0.0; 2]);
            out.add(stage.shafts[0], LossColumn::GearNoLoad, own);
            out.add(stage.shafts[1], LossColumn::GearNoLoad, other);
            out.stages[k] = own + other;
        }
    }
}
