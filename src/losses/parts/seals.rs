//! The shaft seals' loss P_VD as a part of the budget (ISO/TR 14179-2:2001 after Linke; the model
//! is `crate::losses::seals`): every seal of both shafts at its shaft's speed.

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::gearbox::Gearbox;
use crate::losses::oil::Oil;
use crate::losses::seals::Seal;

/// The seals of [pinion shaft, wheel shaft].
pub struct Seals<'a>(pub &'a [Vec<Seal>; 2]);

/// The part of `gearbox`, when it has a seal.
pub fn of(gearbox: &Gearbox) -> Option<Box<dyn LossPart + '_>> {
    gearbox.seals.iter().any(|s| !s.is_empty()).then(|| Box::new(Seals(&gearbox.seals)) as Box<dyn LossPart>)
}

impl LossPart for Seals<'_> {
    fn id(&self) -> LossPartId {
        LossPartId::Seals
    }

    fn losses(&self, at: &PartState, _oil: &Oil, out: &mut PartLosses) {
        let p = self.0.iter().zip(at.omega).map(|(seals, w)| seals.iter().map(|s| s.power_loss(w)).sum::<f64>()).sum();
        out.add(LossColumn::Seals, p);
    }
}
