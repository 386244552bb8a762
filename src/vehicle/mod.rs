//! A vehicle over a drive cycle: the speed trace (`trace`), the road load (`road_load`) and the
//! cycle cut into smooth pieces (`cycle`). What the gearbox loses on them is evaluated in
//! `evaluate::drive_cycle`.

pub(crate) mod cycle;
pub(crate) mod road_load;
pub(crate) mod trace;

pub use cycle::{Cycle, Mode, Phase, Piece};
pub use road_load::{RoadLoad, Vehicle, GRAVITY};
pub use trace::MAX_SAMPLES;
pub use trace::{Trace, TraceError};
