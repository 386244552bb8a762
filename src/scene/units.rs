//! The one unit table of the language.
//!
//! Every unit name the `.gear` language accepts is in [`UNITS`], with its factor to SI, its
//! dimension and, for derived units and aliases, the composition it must equal (tested in
//! `tests/it/units.rs`: `psi` equals `lbf/in^2`, `cP` equals `mPa*s`, ...). A written unit
//! expression (`lbf*in`, `1/GPa`) is the product of its factors' powers.
//!
//! Angle is kept as a dimension of its own, so that `module = 20 deg` is refused.

use std::f64::consts::PI;
use std::fmt;

pub use crate::quantity::Dimension;

/// One named unit.
#[derive(Debug, Clone, Copy)]
pub struct UnitDef {
    pub name: &'static str,
    /// Value in SI of one of this unit (for temperatures: of one degree).
    pub factor: f64,
    pub dimension: Dimension,
    /// Added after scaling (only `degC`: 273.15 K); forbidden inside compound units.
    pub offset: f64,
    /// What this unit must equal, as `(multiplier, unit expression)`; tested.
    pub composition: Option<(f64, &'static str)>,
    pub description: &'static str,
    /// An energy (J, kWh): SI-equal to a torque (N·m) but not one. A torque is a force times a
    /// length; a key that expects a torque refuses an energy unit ([`UnitDef::quantity`]).
    pub energy: bool,
}

impl UnitDef {
    /// The quantity this unit measures, as `gearloss units` lists it: its dimension's name, or
    /// "energy" for the energy units that share the torque's SI dimension.
    pub fn quantity(&self) -> &'static str {
        if self.energy {
            "energy"
        } else {
            self.dimension.name()
        }
    }
}

/// An energy unit (dimension N·m, [`UnitDef::energy`]).
const fn e(name: &'static str, factor: f64, composition: (f64, &'static str), description: &'static str) -> UnitDef {
    UnitDef { energy: true, ..c(name, factor, Dimension::TORQUE, composition, description) }
}

const fn u(name: &'static str, factor: f64, dimension: Dimension, description: &'static str) -> UnitDef {
    UnitDef { name, factor, dimension, offset: 0.0, composition: None, description, energy: false }
}

const fn c(
    name: &'static str,
    factor: f64,
    dimension: Dimension,
    composition: (f64, &'static str),
    description: &'static str,
) -> UnitDef {
    UnitDef { name, factor, dimension, offset: 0.0, composition: Some(composition), description, energy: false }
}

const INCH: f64 = 0.0254;
const POUND: f64 = 0.453_592_37;
const STANDARD_GRAVITY: f64 = 9.806_65;
const LBF: f64 = POUND * STANDARD_GRAVITY;

/// The unit table. Base units first, then every derived unit with the composition it must equal.
pub const UNITS: &[UnitDef] = &[
    // length
    u("m", 1.0, Dimension::LENGTH, "metre"),
    c("cm", 1e-2, Dimension::LENGTH, (1e-2, "m"), "centimetre"),
    c("mm", 1e-3, Dimension::LENGTH, (1e-3, "m"), "millimetre"),
    c("um", 1e-6, Dimension::LENGTH, (1e-3, "mm"), "micrometre"),
    c("µm", 1e-6, Dimension::LENGTH, (1.0, "um"), "micrometre (micro sign)"),
    c("μm", 1e-6, Dimension::LENGTH, (1.0, "um"), "micrometre (Greek mu)"),
    c("in", INCH, Dimension::LENGTH, (25.4, "mm"), "inch"),
    c("uin", INCH * 1e-6, Dimension::LENGTH, (1e-6, "in"), "microinch"),
    c("µin", INCH * 1e-6, Dimension::LENGTH, (1.0, "uin"), "microinch (micro sign)"),
    c("μin", INCH * 1e-6, Dimension::LENGTH, (1.0, "uin"), "microinch (Greek mu)"),
    c("ft", 12.0 * INCH, Dimension::LENGTH, (12.0, "in"), "foot"),
    c("km", 1e3, Dimension::LENGTH, (1e3, "m"), "kilometre"),
    // mass
    c("l", 1e-3, Dimension::VOLUME, (1e-3, "m^3"), "litre"),
    u("kg", 1.0, Dimension::MASS, "kilogram"),
    c("g", 1e-3, Dimension::MASS, (1e-3, "kg"), "gram"),
    c("lb", POUND, Dimension::MASS, (0.453_592_37, "kg"), "pound (mass)"),
    // time
    u("s", 1.0, Dimension::TIME, "second"),
    c("ms", 1e-3, Dimension::TIME, (1e-3, "s"), "millisecond"),
    c("min", 60.0, Dimension::TIME, (60.0, "s"), "minute"),
    c("h", 3600.0, Dimension::TIME, (60.0, "min"), "hour"),
    c("Hz", 1.0, Dimension::FREQUENCY, (1.0, "1/s"), "hertz"),
    // angle
    u("rad", 1.0, Dimension::ANGLE, "radian"),
    c("deg", PI / 180.0, Dimension::ANGLE, (PI / 180.0, "rad"), "degree"),
    c("°", PI / 180.0, Dimension::ANGLE, (1.0, "deg"), "degree (sign)"),
    c("rev", 2.0 * PI, Dimension::ANGLE, (2.0 * PI, "rad"), "revolution"),
    c("rpm", 2.0 * PI / 60.0, Dimension::ANGULAR_VELOCITY, (1.0, "rev/min"), "revolutions per minute"),
    // temperature
    u("K", 1.0, Dimension::TEMPERATURE, "kelvin"),
    UnitDef {
        name: "degC",
        factor: 1.0,
        dimension: Dimension::TEMPERATURE,
        offset: 273.15,
        composition: None,
        energy: false,
        description: "degree Celsius (absolute temperature, only on its own)",
    },
    UnitDef {
        name: "°C",
        factor: 1.0,
        dimension: Dimension::TEMPERATURE,
        offset: 273.15,
        composition: None,
        energy: false,
        description: "degree Celsius (sign; the same as degC)",
    },
    UnitDef {
        name: "degF",
        factor: 5.0 / 9.0,
        dimension: Dimension::TEMPERATURE,
        offset: 459.67 * 5.0 / 9.0,
        composition: None,
        energy: false,
        description: "degree Fahrenheit (absolute temperature, only on its own): K = (°F + 459.67) · 5/9",
    },
    UnitDef {
        name: "°F",
        factor: 5.0 / 9.0,
        dimension: Dimension::TEMPERATURE,
        offset: 459.67 * 5.0 / 9.0,
        composition: None,
        energy: false,
        description: "degree Fahrenheit (sign; the same as degF)",
    },
    // force
    c("N", 1.0, Dimension::FORCE, (1.0, "kg*m/s^2"), "newton"),
    c("mN", 1e-3, Dimension::FORCE, (1e-3, "N"), "millinewton"),
    c("kN", 1e3, Dimension::FORCE, (1e3, "N"), "kilonewton"),
    c("MN", 1e6, Dimension::FORCE, (1e3, "kN"), "meganewton"),
    c("lbf", LBF, Dimension::FORCE, (STANDARD_GRAVITY, "lb*m/s^2"), "pound-force"),
    // pressure and modulus
    c("Pa", 1.0, Dimension::PRESSURE, (1.0, "N/m^2"), "pascal"),
    c("mPa", 1e-3, Dimension::PRESSURE, (1e-3, "Pa"), "millipascal (for mPa*s)"),
    c("kPa", 1e3, Dimension::PRESSURE, (1e3, "Pa"), "kilopascal"),
    c("MPa", 1e6, Dimension::PRESSURE, (1.0, "N/mm^2"), "megapascal"),
    c("GPa", 1e9, Dimension::PRESSURE, (1e3, "MPa"), "gigapascal"),
    c("bar", 1e5, Dimension::PRESSURE, (1e5, "Pa"), "bar"),
    c("psi", LBF / (INCH * INCH), Dimension::PRESSURE, (1.0, "lbf/in^2"), "pound-force per square inch"),
    c("ksi", 1e3 * LBF / (INCH * INCH), Dimension::PRESSURE, (1e3, "psi"), "kilopound-force per square inch"),
    // viscosity
    c("P", 0.1, Dimension::DYNAMIC_VISCOSITY, (0.1, "Pa*s"), "poise"),
    c("cP", 1e-3, Dimension::DYNAMIC_VISCOSITY, (1.0, "mPa*s"), "centipoise"),
    c("reyn", LBF / (INCH * INCH), Dimension::DYNAMIC_VISCOSITY, (1.0, "lbf*s/in^2"), "reyn"),
    c("St", 1e-4, Dimension::KINEMATIC_VISCOSITY, (1.0, "cm^2/s"), "stokes"),
    c("cSt", 1e-6, Dimension::KINEMATIC_VISCOSITY, (1.0, "mm^2/s"), "centistokes"),
    // power and energy
    e("J", 1.0, (1.0, "N*m"), "joule"),
    e("kJ", 1e3, (1e3, "J"), "kilojoule"),
    e("MJ", 1e6, (1e3, "kJ"), "megajoule"),
    c("W", 1.0, Dimension::POWER, (1.0, "J/s"), "watt"),
    c("mW", 1e-3, Dimension::POWER, (1e-3, "W"), "milliwatt"),
    c("kW", 1e3, Dimension::POWER, (1e3, "W"), "kilowatt"),
    c("MW", 1e6, Dimension::POWER, (1e3, "kW"), "megawatt"),
    e("Wh", 3600.0, (3600.0, "J"), "watt-hour"),
    e("kWh", 3.6e6, (1e3, "Wh"), "kilowatt-hour"),
    c("hp", 550.0 * LBF * 12.0 * INCH, Dimension::POWER, (550.0, "lbf*ft/s"), "horsepower (mechanical)"),
];

/// Example units of a dimension from the table, for hints.
pub fn example_units(dimension: Dimension) -> String {
    // A torque has no named unit of its own: the compound units people write. (Energies share
    // its SI dimension but are never an example of a torque.)
    if dimension == Dimension::TORQUE {
        return "N*m, N*mm, kN*m, lbf*in, lbf*ft".into();
    }
    let names: Vec<&str> =
        UNITS.iter().filter(|u| u.dimension == dimension && !u.energy).map(|u| u.name).take(6).collect();
    if names.is_empty() {
        dimension.si_unit()
    } else {
        names.join(", ")
    }
}

/// The inch system's lengths: a pair sized in them (`face_width = 1.25 in`, a diametral pitch in
/// `1/in`) has its results shown in inch–pound units.
pub const INCH_LENGTHS: &[&str] = &["in", "uin", "µin", "μin", "ft"];

/// Whether a value as written (`1.25 in`, `8 1/in`, `1/(8 1/in)`) names one of [`INCH_LENGTHS`].
///
/// ```
/// use gearloss::scene::units::written_in_inches;
/// assert!(written_in_inches("1.25 in") && written_in_inches("8 1/in"));
/// assert!(!written_in_inches("20 mm") && !written_in_inches("0.5 min"));
/// ```
pub fn written_in_inches(written: &str) -> bool {
    written.split(|c: char| !c.is_alphanumeric()).any(|token| INCH_LENGTHS.contains(&token))
}

/// Looks a unit name up in the table.
pub fn lookup(name: &str) -> Option<&'static UnitDef> {
    UNITS.iter().find(|u| u.name == name)
}

/// A unit expression evaluated against the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    pub factor: f64,
    pub offset: f64,
    pub dimension: Dimension,
}

impl Scale {
    pub const ONE: Scale = Scale { factor: 1.0, offset: 0.0, dimension: Dimension::NONE };

    /// Converts a number written in this unit to SI.
    pub fn to_si(&self, x: f64) -> f64 {
        x * self.factor + self.offset
    }

    /// Converts an SI value back to this unit.
    pub fn from_si(&self, x: f64) -> f64 {
        (x - self.offset) / self.factor
    }
}

/// Why a unit expression could not be evaluated: the index of the offending factor.
#[derive(Debug, Clone, PartialEq)]
pub enum UnitError {
    Unknown {
        index: usize,
        name: String,
        suggestion: Option<&'static str>,
    },
    OffsetInCompound {
        index: usize,
        name: String,
    },
    /// An exponent of a base dimension leaves ±`crate::quantity::MAX_EXPONENT` at this factor.
    ExponentOverflow {
        index: usize,
    },
}

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitError::Unknown { name, .. } => write!(f, "unknown unit `{name}`"),
            UnitError::OffsetInCompound { name, .. } => {
                write!(f, "`{name}` is an absolute temperature and cannot be part of a compound unit")
            }
            UnitError::ExponentOverflow { .. } => write!(
                f,
                "the unit's powers overflow: an exponent of a base unit exceeds ±{}",
                crate::quantity::MAX_EXPONENT
            ),
        }
    }
}

/// Evaluates a product of `(name, exponent)` factors.
pub fn evaluate<'a>(factors: impl IntoIterator<Item = (&'a str, i32)>) -> Result<Scale, UnitError> {
    let factors: Vec<(&str, i32)> = factors.into_iter().collect();
    let mut scale = Scale::ONE;
    for (index, (name, exponent)) in factors.iter().enumerate() {
        let def = lookup(name).ok_or_else(|| UnitError::Unknown {
            index,
            name: name.to_string(),
            suggestion: suggest(name),
        })?;
        if def.offset != 0.0 {
            if factors.len() != 1 || *exponent != 1 {
                return Err(UnitError::OffsetInCompound { index, name: name.to_string() });
            }
            scale.offset = def.offset;
        }
        scale.factor *= def.factor.powi(*exponent);
        scale.dimension = def
            .dimension
            .checked_pow(*exponent)
            .and_then(|d| scale.dimension.checked_times(d))
            .ok_or(UnitError::ExponentOverflow { index })?;
    }
    Ok(scale)
}

/// What people write for a unit the table spells otherwise: the unit they mean.
const WRITTEN_FOR: &[(&str, &str)] = &[
    ("Nm", "N*m"),
    ("Nmm", "N*mm"),
    ("kNm", "kN*m"),
    ("lbfin", "lbf*in"),
    ("lbft", "lbf*ft"),
    ("ftlb", "lbf*ft"),
    ("C", "degC"),
    ("F", "degF"),
    ("celsius", "degC"),
    ("fahrenheit", "degF"),
    ("Celsius", "degC"),
    ("Fahrenheit", "degF"),
    ("degc", "degC"),
    ("degf", "degF"),
    ("kgm2", "kg*m^2"),
    ("RPM", "rpm"),
    ("cps", "cP"),
    ("cst", "cSt"),
    ("CST", "cSt"),
];

/// The nearest unit name, for "did you mean" hints: what the name usually stands for when it is a
/// common way of writing a unit (`WRITTEN_FOR`: `Nm` → `N*m`, `C` → `degC`), else the table's
/// closest name by Jaro–Winkler similarity.
pub fn suggest(name: &str) -> Option<&'static str> {
    if let Some((_, meant)) = WRITTEN_FOR.iter().find(|(w, _)| *w == name) {
        return Some(meant);
    }
    let lower = name.to_ascii_lowercase();
    UNITS
        .iter()
        .map(|u| (strsim::jaro_winkler(&lower, &u.name.to_ascii_lowercase()), u.name))
        .filter(|(s, _)| *s > 0.75)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, n)| n)
}

/// A uom quantity type that a scene value can be lowered into: its dimension in the unit table
/// and how to build it from an SI number.
pub trait SiQuantity: Sized {
    const DIMENSION: Dimension;
    fn from_si(value: f64) -> Self;
    fn si(&self) -> f64;
}

macro_rules! si_quantity {
    ($ty:ty, $dim:expr) => {
        impl SiQuantity for $ty {
            const DIMENSION: Dimension = $dim;
            fn from_si(value: f64) -> Self {
                <$ty>::from_si_value(value)
            }
            fn si(&self) -> f64 {
                self.value
            }
        }
    };
}

/// Builds a uom quantity from its SI value (uom stores SI values in its `value` field).
trait FromSiValue {
    fn from_si_value(value: f64) -> Self;
}

impl<D, U> FromSiValue for uom::si::Quantity<D, U, f64>
where
    D: uom::si::Dimension + ?Sized,
    U: uom::si::Units<f64> + ?Sized,
{
    fn from_si_value(value: f64) -> Self {
        uom::si::Quantity { dimension: std::marker::PhantomData, units: std::marker::PhantomData, value }
    }
}

use crate::model as q;
si_quantity!(q::Length, Dimension::LENGTH);
si_quantity!(q::ReciprocalLength, Dimension::RECIPROCAL_LENGTH);
si_quantity!(q::Angle, Dimension::ANGLE);
si_quantity!(q::Torque, Dimension::TORQUE);
si_quantity!(q::AngularVelocity, Dimension::ANGULAR_VELOCITY);
si_quantity!(q::Pressure, Dimension::PRESSURE);
si_quantity!(q::ReciprocalPressure, Dimension::RECIPROCAL_PRESSURE);
si_quantity!(q::DynamicViscosity, Dimension::DYNAMIC_VISCOSITY);
si_quantity!(q::KinematicViscosity, Dimension::KINEMATIC_VISCOSITY);
si_quantity!(q::MassDensity, Dimension::DENSITY);
si_quantity!(q::MomentOfInertia, Dimension::MOMENT_OF_INERTIA);
si_quantity!(q::Mass, Dimension::MASS);
si_quantity!(q::Stiffness, Dimension::STIFFNESS);
si_quantity!(q::ThermodynamicTemperature, Dimension::TEMPERATURE);
si_quantity!(q::Velocity, Dimension::VELOCITY);
si_quantity!(q::Force, Dimension::FORCE);
si_quantity!(q::VolumeRate, Dimension::VOLUME_RATE);
si_quantity!(q::Area, Dimension::AREA);
si_quantity!(q::HeatCapacity, Dimension::HEAT_CAPACITY);
si_quantity!(q::ThermalConductance, Dimension::THERMAL_CONDUCTANCE);
si_quantity!(q::Time, Dimension::TIME);
si_quantity!(q::MassRate, Dimension::MASS_RATE);
si_quantity!(q::MassPerLength, Dimension::MASS_PER_LENGTH);
