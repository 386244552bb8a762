//! The thermal balance of a gearbox: the housing as one thermal node (`housing`), the oil
//! temperature it settles at and its thermal rating ([`balance()`]), and a duty cycle's transient
//! ([`transient`]). Each takes the losses as a function of the oil temperature; the evaluation
//! (`evaluate/thermal.rs`) supplies the loss budget at that temperature.
//!
//! What one node leaves out: no conduction along the shafts, no temperature differences inside
//! the box (the oil, the housing wall and the gears share θ), no solar or other heat input.

pub(crate) mod balance;
pub(crate) mod duty_cycle;
pub(crate) mod housing;
pub(crate) mod transient;

pub use balance::{balance, rating_torque, ratings, Balance, BalanceStatus, Ratings};
pub use duty_cycle::{DutyCycle, DutyStep};
pub use housing::{Cooler, Dissipation, Housing};
pub use transient::{transient, StepEnd, Transient};
