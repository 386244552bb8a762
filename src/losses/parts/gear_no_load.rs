//! The gears' load-independent loss P_VZ0 as a part of the budget: churning by Mauz for dip
//! lubrication, the jet's impulse and the gears' windage for injection (ISO/TR 14179-2:2001; the
//! models and their sources are in [`crate::losses::gear_no_load`]).

use super::loss_column::LossColumn;
use super::loss_part::{LossPart, PartLosses, PartState};
use super::part_id::LossPartId;
use crate::losses::gear_no_load::{GearsRunning, Lubrication};
use crate::losses::gearbox::Gearbox;
use crate::losses::oil::Oil;

/// The scene's lubrication.
pub(crate) struct GearNoLoad<'a>(pub &'a Lubrication);

/// The part of `gearbox`, when it says how the gears are lubricated.
pub(crate) fn of(gearbox: &Gearbox) -> Option<Box<dyn LossPart + '_>> {
    gearbox.lubrication.as_ref().map(|l| Box::new(GearNoLoad(l)) as Box<dyn LossPart>)
}

impl LossPart for GearNoLoad<'_> {
    fn id(&self) -> LossPartId {
        LossPartId::GearNoLoad
    }

    fn losses(&self, at: &PartState, oil: &Oil, out: &mut PartLosses) {
        let gears = GearsRunning { omega: at.omega, pitch_radius: at.pitch_radius, face_width: at.face_width };
        // Lowering refuses jets in an oil without a density; no density, no column.
        if let Some(p) = self.0.power_loss(&gears, oil) {
            out.add(LossColumn::GearNoLoad, p);
        }
    }
}
