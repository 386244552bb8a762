//! The units report.md, the plots and the findings show results in: SI engineering units (mm, µm, N, MPa, W, °C), or for a
//! scene whose pair is sized in inch units (a diametral pitch, a module or face width in `in`) the
//! inch–pound units a US gear engineer reads (in, µin, lbf, ksi, hp, °F). report.json, the record
//! files and the scene table's SI column stay in SI.
//!
//! One [`Shown`] per kind of quantity: its unit's name, how an SI value becomes a value in it, and
//! how many decimals it takes beside the SI decimals a table chose (an inch holds 25.4 mm: one
//! decimal more). The factors are the definitions (1 in = 0.0254 m, 1 lbf = 0.453 592 37 kg ×
//! 9.806 65 m/s², 1 hp = 550 lbf·ft/s, 1 Btu_IT = 1055.055 852 62 J); a test checks them against
//! the language's unit table.
//!
//! ```
//! use gearloss::report::units::Units;
//! let us = Units::inch_pound();
//! assert_eq!(us.length().with(0.03175, 3), "1.2500 in");
//! assert_eq!(Units::si().length().with(0.03175, 3), "31.750 mm");
//! assert_eq!(us.temperature().with(273.15 + 100.0, 1), "212.0 °F");
//! ```

use super::number::{UnitSystem, Q};
use crate::numerics::rounding::fixed;

/// 1 in in m.
pub const INCH: f64 = 0.0254;
/// 1 lbf in N.
pub const POUND_FORCE: f64 = 0.453_592_37 * 9.806_65;
/// 1 hp (mechanical, 550 lbf·ft/s) in W.
pub const HORSEPOWER: f64 = 550.0 * POUND_FORCE * 12.0 * INCH;
/// 1 psi in Pa.
pub const PSI: f64 = POUND_FORCE / (INCH * INCH);
/// 1 Btu (International Table) in J.
pub const BTU: f64 = 1_055.055_852_62;
/// 1 lb in kg.
pub const POUND: f64 = 0.453_592_37;

/// How an SI value becomes the shown value.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Op {
    Times(f64),
    Over(f64),
    Celsius,
    Fahrenheit,
}

/// A kind of quantity as shown: unit name, conversion from SI and decimals beside the SI table's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shown {
    pub unit: &'static str,
    op: Op,
    extra_decimals: i32,
}

impl Shown {
    const fn new(unit: &'static str, op: Op, extra_decimals: i32) -> Shown {
        Shown { unit, op, extra_decimals }
    }

    /// The SI value in this unit.
    pub fn value(&self, si: f64) -> f64 {
        match self.op {
            Op::Times(f) => si * f,
            Op::Over(f) => si / f,
            Op::Celsius => si - 273.15,
            Op::Fahrenheit => (si - 273.15) * 1.8 + 32.0,
        }
    }

    /// A temperature in °C in this unit (°C stays as it is).
    pub fn from_celsius(&self, celsius: f64) -> f64 {
        if self.op == Op::Fahrenheit {
            celsius * 1.8 + 32.0
        } else {
            celsius
        }
    }

    /// Shown degrees per kelvin of a temperature difference (1.8 in °F, else 1).
    pub fn per_kelvin(&self) -> f64 {
        if self.op == Op::Fahrenheit {
            1.8
        } else {
            1.0
        }
    }

    /// Decimals for a table that shows the SI unit with `si_decimals`.
    pub fn decimals(&self, si_decimals: usize) -> usize {
        (si_decimals as i32 + self.extra_decimals).max(0) as usize
    }

    /// The value alone, fixed decimals (`—` when not finite).
    pub fn cell(&self, si: f64, si_decimals: usize) -> String {
        fixed(self.value(si), self.decimals(si_decimals))
    }

    /// A report quantity's value alone.
    pub fn q(&self, q: &Q, si_decimals: usize) -> String {
        self.cell(q.si(), si_decimals)
    }

    /// The value and its unit: `1.2500 in`.
    pub fn with(&self, si: f64, si_decimals: usize) -> String {
        format!("{} {}", self.cell(si, si_decimals), self.unit)
    }

    /// A heading with its unit in brackets: `F_t (N)`, `F_t (lbf)`.
    pub fn titled(&self, name: &str) -> String {
        format!("{name} ({})", self.unit)
    }

    /// A column heading: `d mm`, `d in`.
    pub fn heading(&self, name: &str) -> String {
        format!("{name} {}", self.unit)
    }
}

/// The units of one report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    system: UnitSystem,
}

macro_rules! kinds {
    ($($(#[$doc:meta])* $name:ident: $si:expr, $us:expr;)*) => {
        impl Units {
            $(
                $(#[$doc])*
                pub fn $name(&self) -> Shown {
                    match self.system {
                        UnitSystem::Si => $si,
                        UnitSystem::Inch => $us,
                    }
                }
            )*
        }
    };
}

use Op::{Over, Times};

kinds! {
    /// Diameters, positions, radii: mm | in.
    length: Shown::new("mm", Times(1e3), 0), Shown::new("in", Over(INCH), 1);
    /// Film thickness, roughness, transmission error, relief, half-widths: µm | µin.
    micro: Shown::new("µm", Times(1e6), 0), Shown::new("µin", Over(INCH * 1e-6), -1);
    /// Forces: N | lbf.
    force: Shown::new("N", Times(1.0), 0), Shown::new("lbf", Over(POUND_FORCE), 1);
    /// Load per unit face width: N/mm | lbf/in.
    force_per_width: Shown::new("N/mm", Times(1e-3), 0), Shown::new("lbf/in", Times(INCH / POUND_FORCE), 0);
    /// Contact pressure: MPa | ksi.
    pressure: Shown::new("MPa", Times(1e-6), 0), Shown::new("ksi", Over(1e3 * PSI), 1);
    /// Elastic moduli: GPa | Mpsi.
    modulus: Shown::new("GPa", Times(1e-9), 0), Shown::new("Mpsi", Over(1e6 * PSI), 1);
    /// Surface and air velocities: m/s | ft/min.
    velocity: Shown::new("m/s", Times(1.0), 0), Shown::new("ft/min", Times(60.0 / (12.0 * INCH)), -2);
    /// Power losses: W | hp.
    power: Shown::new("W", Times(1.0), 0), Shown::new("hp", Over(HORSEPOWER), 3);
    /// Transmitted power: kW | hp.
    kilowatt: Shown::new("kW", Over(1e3), 0), Shown::new("hp", Over(HORSEPOWER), 0);
    /// Torques: N·m | lbf·in.
    torque: Shown::new("N·m", Times(1.0), 0), Shown::new("lbf·in", Over(POUND_FORCE * INCH), -1);
    /// Temperatures: °C | °F.
    temperature: Shown::new("°C", Op::Celsius, 0), Shown::new("°F", Op::Fahrenheit, 0);
    /// Energy: kJ | Btu.
    energy: Shown::new("kJ", Over(1e3), 0), Shown::new("Btu", Over(BTU), 0);
    /// Areas: m² | ft².
    area: Shown::new("m²", Times(1.0), 0), Shown::new("ft²", Over(144.0 * INCH * INCH), -1);
    /// Heat transfer coefficients: W/(m² K) | Btu/(h ft² °F).
    heat_transfer: Shown::new("W/(m² K)", Times(1.0), 0),
        Shown::new("Btu/(h ft² °F)", Times(3600.0 * 144.0 * INCH * INCH / (BTU * 1.8)), 1);
    /// Thermal conductances: W/K | Btu/(h °F).
    conductance: Shown::new("W/K", Times(1.0), 0), Shown::new("Btu/(h °F)", Times(3600.0 / (BTU * 1.8)), 0);
    /// Heat capacities: kJ/K | Btu/°F.
    heat_capacity: Shown::new("kJ/K", Over(1e3), 0), Shown::new("Btu/°F", Over(BTU * 1.8), 0);
    /// Mesh stiffness per unit face width: N/(mm·µm) | lbf/(in·µin).
    stiffness_per_width: Shown::new("N/(mm·µm)", Times(1e-9), 0), Shown::new("lbf/(in·µin)", Over(1e6 * PSI), 1);
    /// Mesh stiffness: N/µm | lbf/µin.
    stiffness: Shown::new("N/µm", Times(1e-6), 0), Shown::new("lbf/µin", Over(POUND_FORCE / (INCH * 1e-6)), 1);
    /// Oil density: kg/m³ | lb/ft³.
    density: Shown::new("kg/m³", Times(1.0), 0), Shown::new("lb/ft³", Over(POUND / (1728.0 * INCH * INCH * INCH)), 1);
    /// Pressure–viscosity coefficient: 1/GPa | 1/ksi.
    pressure_viscosity: Shown::new("1/GPa", Times(1e9), 0), Shown::new("1/ksi", Times(1e3 * PSI), 2);
    /// Masses: kg | lb.
    mass: Shown::new("kg", Times(1.0), 0), Shown::new("lb", Over(POUND), 0);
    /// Viscous damping: N·s/m | lbf·s/in.
    damping: Shown::new("N·s/m", Times(1.0), 0), Shown::new("lbf·s/in", Times(INCH / POUND_FORCE), 0);
    /// Kinematic viscosity: mm²/s | cSt (the same number).
    kinematic_viscosity: Shown::new("mm²/s", Times(1e6), 0), Shown::new("cSt", Times(1e6), 0);
    /// Dynamic viscosity: mPa·s | cP (the same number).
    dynamic_viscosity: Shown::new("mPa·s", Times(1e3), 0), Shown::new("cP", Times(1e3), 0);
}

impl Units {
    /// The units of a unit system.
    pub fn of_system(system: UnitSystem) -> Units {
        Units { system }
    }

    pub fn si() -> Units {
        Units { system: UnitSystem::Si }
    }

    pub fn inch_pound() -> Units {
        Units { system: UnitSystem::Inch }
    }

    pub fn is_si(&self) -> bool {
        self.system == UnitSystem::Si
    }
}

/// A thermal balance's status in words, its temperatures in `u` (`finds no balance up to 392 °F`).
pub fn balance_words(status: crate::thermal::BalanceStatus, u: Units) -> String {
    match status {
        crate::thermal::BalanceStatus::NoEquilibrium => {
            format!("finds no balance up to {}", u.temperature().with(crate::thermal::balance::SEARCH_LIMIT, 0))
        }
        other => other.words().to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::units::lookup;

    /// The factors here equal the language's unit table (relative 1e-15).
    #[test]
    fn factors_equal_the_unit_table() {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
        assert!(close(INCH, lookup("in").unwrap().factor));
        assert!(close(POUND_FORCE, lookup("lbf").unwrap().factor));
        assert!(close(HORSEPOWER, lookup("hp").unwrap().factor));
        assert!(close(PSI, lookup("psi").unwrap().factor));
        assert!(close(POUND, lookup("lb").unwrap().factor));
    }

    /// Every inch–pound kind is the SI kind times its own factor: 1 unit shown as 1.
    #[test]
    fn one_of_each_unit_reads_one() {
        let us = Units::inch_pound();
        let one = |s: Shown, si: f64| assert!((s.value(si) - 1.0).abs() < 1e-12, "{}: {}", s.unit, s.value(si));
        one(us.length(), INCH);
        one(us.micro(), INCH * 1e-6);
        one(us.force(), POUND_FORCE);
        one(us.force_per_width(), POUND_FORCE / INCH);
        one(us.pressure(), 1e3 * PSI);
        one(us.velocity(), 12.0 * INCH / 60.0);
        one(us.power(), HORSEPOWER);
        one(us.torque(), POUND_FORCE * INCH);
        one(us.energy(), BTU);
        one(us.area(), 144.0 * INCH * INCH);
        one(us.heat_transfer(), BTU * 1.8 / (3600.0 * 144.0 * INCH * INCH));
        one(us.conductance(), BTU * 1.8 / 3600.0);
        one(us.heat_capacity(), BTU * 1.8);
        one(us.stiffness(), POUND_FORCE / (INCH * 1e-6));
        one(us.density(), POUND / (1728.0 * INCH * INCH * INCH));
        one(us.pressure_viscosity(), 1.0 / (1e3 * PSI));
        one(us.mass(), POUND);
        one(us.damping(), POUND_FORCE / INCH);
        assert_eq!(us.temperature().cell(273.15, 2), "32.00");
        assert_eq!(us.temperature().cell(373.15, 2), "212.00");
    }

    /// No balance up to the search's 200 °C, said in each system's temperature.
    #[test]
    fn balance_words_follow_the_units() {
        use crate::thermal::BalanceStatus;
        assert_eq!(balance_words(BalanceStatus::NoEquilibrium, Units::si()), "finds no balance up to 200 °C");
        assert_eq!(balance_words(BalanceStatus::NoEquilibrium, Units::inch_pound()), "finds no balance up to 392 °F");
        assert_eq!(balance_words(BalanceStatus::Ok, Units::inch_pound()), BalanceStatus::Ok.words());
    }
}
