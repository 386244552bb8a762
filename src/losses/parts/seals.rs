//! The shaft seals' loss P_VD as a part of the budget (ISO/TR 14179-2:2001 after Linke; the model
//! is `crate::losses::seals`): every seal of every shaft at its shaft's speed.

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::oil::Oil;

/// Every seal of every shaft.
pub struct Seals;

impl LossPart for Seals {
    fn id(&self) -> LossPartId {
        LossPartId::Seals
    }

    fn present(&self, on: &PartState) -> bool {
        on.shafts.iter().any(|s| !s.seals.is_empty())
    }

    fn reads_loads(&self) -> bool {
        false
    }

    fn losses(&self, on: &PartState, _oil: &Oil, out: &mut PartLosses) {
        for (j, shaft) in on.shafts.iter().enumerate() {
            out.add(j, LossColumn::Seals, shaft.seals.iter().map(|s| s.power_loss(shaft.speed)).sum());
        }
    }
}
