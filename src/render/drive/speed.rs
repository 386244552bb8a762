//! Speeds in a drive's report.md in the unit the scene wrote its speeds in (`rpm`, `rad/s`,
//! `1/min`, ...): from rad/s (the drive's points) or from rpm (the report's `…_rpm` fields). In rpm
//! the conversions are the ones report.md always used (×30/π, or none), so an rpm scene's report
//! reads as it did to the byte.

use crate::report::number::DisplayUnit;

/// rad/s to rpm.
const RPM: f64 = 30.0 / std::f64::consts::PI;

/// The speed unit of one report.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Speed<'a>(pub(crate) &'a DisplayUnit);

impl Speed<'_> {
    /// A speed in rad/s in this unit.
    pub(crate) fn of_rad_s(&self, w: f64) -> f64 {
        if self.0.is_rpm() {
            w * RPM
        } else {
            w / self.0.factor
        }
    }

    /// A speed in rpm in this unit.
    pub(crate) fn of_rpm(&self, n: f64) -> f64 {
        if self.0.is_rpm() {
            n
        } else {
            n / RPM / self.0.factor
        }
    }

    /// The unit as headings print it (`rpm`, `rad/s`).
    pub(crate) fn unit(&self) -> String {
        self.0.shown()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 1000 rpm = 104.719… rad/s = 1000 1/min, each shown in its own unit; rpm passes through.
    #[test]
    fn a_speed_shows_in_the_unit_written() {
        let rad_s = DisplayUnit { name: "rad/s".into(), factor: 1.0 };
        let per_min = DisplayUnit { name: "1/min".into(), factor: std::f64::consts::PI / 30.0 };
        let w = 1000.0 / RPM;
        assert!((Speed(&rad_s).of_rpm(1000.0) - w).abs() < 1e-12);
        assert!((Speed(&rad_s).of_rad_s(w) - w).abs() < 1e-12);
        assert!((Speed(&per_min).of_rad_s(w) - 1000.0).abs() < 1e-9);
        assert_eq!(Speed(&DisplayUnit::rpm()).of_rpm(1000.0), 1000.0);
        assert_eq!(Speed(&DisplayUnit::rpm()).of_rad_s(w), w * RPM);
        assert_eq!(Speed(&rad_s).unit(), "rad/s");
    }
}
