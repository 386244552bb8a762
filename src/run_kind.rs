//! The shapes the run layer ([`crate::run`], [`crate::run_drive`], [`crate::run_pair`]) passes
//! between its parts: a file in memory, one run at an oil temperature, what a report.json read
//! back draws.

/// A file of a run in memory: its path in the report folder and its text.
pub(crate) type File = (String, String);

/// One run at an oil temperature, as the comparison of a sweep reads it: its label (`90 °C`), the
/// temperature (K), its folder (`oil_temperature_90degC`) and its report.
pub(crate) type OilRun<R> = (String, f64, String, R);

/// What a report.json read back draws: its files, and the folders inside its folder that hold
/// reports of their own.
pub(crate) type Redrawn = (Vec<File>, Vec<String>);
