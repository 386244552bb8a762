//! Speeds and torques in a drive's report.md in the units the scene wrote them in: speeds (`rpm`,
//! `rad/s`, `1/min`, ...) from rad/s (the drive's points) or from rpm (the report's `…_rpm` fields),
//! torques (`N*m`, `lbf*in`, `kN*m`, ...) from N·m. In rpm and N·m the conversions are the ones
//! report.md always used (×30/π, or none), so such a scene's report reads as it did to the byte.

use crate::report::number::DisplayUnit;
use crate::report::units::Units;

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

/// The units one report shows its speeds and torques in (as the scene wrote them), and its
/// forces, powers, lengths and temperatures in (SI, or inch–pound for a drive sized in inches).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Shown<'a> {
    pub(crate) speed: Speed<'a>,
    pub(crate) torque: Torque<'a>,
    pub(crate) units: Units,
}

impl<'a> Shown<'a> {
    /// The units the drive's report was written in.
    pub(crate) fn of(r: &'a crate::report::drive::DriveReport) -> Shown<'a> {
        Shown { speed: Speed(&r.speed_unit), torque: Torque(&r.torque_unit), units: Units::of_system(r.unit_system) }
    }
}

/// The torque unit of one report.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Torque<'a>(pub(crate) &'a DisplayUnit);

impl Torque<'_> {
    /// A torque in N·m in this unit.
    pub(crate) fn of_si(&self, t: f64) -> f64 {
        if self.0.is_newton_metre() {
            t
        } else {
            t / self.0.factor
        }
    }

    /// The unit as headings print it (`N·m`, `lbf·in`).
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

    /// 100 N·m = 885.07… lbf·in (1 lbf·in = 0.112 984 829 N·m); N·m passes through.
    #[test]
    fn a_torque_shows_in_the_unit_written() {
        let lbf_in = DisplayUnit { name: "lbf*in".into(), factor: 4.448_221_615_260_5 * 0.0254 };
        assert!((Torque(&lbf_in).of_si(100.0) - 885.074_579_7).abs() < 1e-6);
        assert_eq!(Torque(&lbf_in).unit(), "lbf·in");
        assert_eq!(Torque(&DisplayUnit::newton_metre()).of_si(123.456), 123.456);
        assert_eq!(Torque(&DisplayUnit::newton_metre()).unit(), "N·m");
    }
}
