//! Physical dimensions: the exponents of length, mass, time, temperature and plane angle that every
//! quantity of the language has, their names in words and their SI unit symbols.
//!
//! The bottom layer: the DSL's unit table (`scene::units`) and the friction-law catalogue both
//! describe their quantities with [`Dimension`].

/// Exponents of length, mass, time, temperature and plane angle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension {
    pub length: i8,
    pub mass: i8,
    pub time: i8,
    pub temperature: i8,
    pub angle: i8,
}

/// Largest power of a base dimension a unit may carry (m^12 is far beyond any physical quantity;
/// the bound keeps every exponent exact, never saturated).
pub(crate) const MAX_EXPONENT: i32 = 24;

const fn dim(length: i8, mass: i8, time: i8, temperature: i8, angle: i8) -> Dimension {
    Dimension { length, mass, time, temperature, angle }
}

impl Dimension {
    pub const NONE: Dimension = dim(0, 0, 0, 0, 0);
    pub const LENGTH: Dimension = dim(1, 0, 0, 0, 0);
    pub const RECIPROCAL_LENGTH: Dimension = dim(-1, 0, 0, 0, 0);
    pub const MASS: Dimension = dim(0, 1, 0, 0, 0);
    pub const TIME: Dimension = dim(0, 0, 1, 0, 0);
    pub const TEMPERATURE: Dimension = dim(0, 0, 0, 1, 0);
    pub const ANGLE: Dimension = dim(0, 0, 0, 0, 1);
    pub const FORCE: Dimension = dim(1, 1, -2, 0, 0);
    pub const TORQUE: Dimension = dim(2, 1, -2, 0, 0);
    pub const ANGULAR_VELOCITY: Dimension = dim(0, 0, -1, 0, 1);
    pub const PRESSURE: Dimension = dim(-1, 1, -2, 0, 0);
    pub const RECIPROCAL_PRESSURE: Dimension = dim(1, -1, 2, 0, 0);
    pub const DYNAMIC_VISCOSITY: Dimension = dim(-1, 1, -1, 0, 0);
    pub const KINEMATIC_VISCOSITY: Dimension = dim(2, 0, -1, 0, 0);
    pub const DENSITY: Dimension = dim(-3, 1, 0, 0, 0);
    pub const MOMENT_OF_INERTIA: Dimension = dim(2, 1, 0, 0, 0);
    pub const STIFFNESS: Dimension = dim(0, 1, -2, 0, 0);
    pub const POWER: Dimension = dim(2, 1, -3, 0, 0);
    pub const VELOCITY: Dimension = dim(1, 0, -1, 0, 0);
    pub const FREQUENCY: Dimension = dim(0, 0, -1, 0, 0);
    pub const VOLUME: Dimension = dim(3, 0, 0, 0, 0);
    pub const VOLUME_RATE: Dimension = dim(3, 0, -1, 0, 0);
    pub const AREA: Dimension = dim(2, 0, 0, 0, 0);
    pub const HEAT_CAPACITY: Dimension = dim(2, 1, -2, -1, 0);
    pub const THERMAL_CONDUCTANCE: Dimension = dim(2, 1, -3, -1, 0);
    /// N·s/m = kg/s: a road load's speed coefficient f1.
    pub const MASS_RATE: Dimension = dim(0, 1, -1, 0, 0);
    /// N·s²/m² = kg/m: a road load's square coefficient f2.
    pub const MASS_PER_LENGTH: Dimension = dim(-1, 1, 0, 0, 0);

    /// This dimension to the power `e`; None when an exponent would leave ±`MAX_EXPONENT`.
    pub fn checked_pow(self, e: i32) -> Option<Dimension> {
        let p = |x: i8| i32::from(x).checked_mul(e).filter(|v| v.abs() <= MAX_EXPONENT).map(|v| v as i8);
        Some(dim(p(self.length)?, p(self.mass)?, p(self.time)?, p(self.temperature)?, p(self.angle)?))
    }

    /// The product of two dimensions; None when an exponent would leave ±`MAX_EXPONENT`.
    pub fn checked_times(self, o: Dimension) -> Option<Dimension> {
        let a = |x: i8, y: i8| Some(x + y).filter(|v| v.abs() <= MAX_EXPONENT as i8);
        Some(dim(
            a(self.length, o.length)?,
            a(self.mass, o.mass)?,
            a(self.time, o.time)?,
            a(self.temperature, o.temperature)?,
            a(self.angle, o.angle)?,
        ))
    }

    pub fn pow(self, e: i32) -> Dimension {
        self.checked_pow(e).expect("unit exponents stay within ±MAX_EXPONENT")
    }

    pub fn times(self, o: Dimension) -> Dimension {
        self.checked_times(o).expect("unit exponents stay within ±MAX_EXPONENT")
    }

    /// What a gear engineer calls a quantity of this dimension.
    pub fn name(self) -> &'static str {
        NAMED.iter().find(|(d, _)| *d == self).map_or("quantity", |(_, n)| n)
    }

    /// The SI unit written in reports and report.json.
    pub fn si_unit(self) -> String {
        if let Some((_, s)) = SI_NAMES.iter().find(|(d, _)| *d == self) {
            return (*s).to_string();
        }
        let mut num = Vec::new();
        let mut den = Vec::new();
        for (sym, e) in
            [("kg", self.mass), ("m", self.length), ("s", self.time), ("K", self.temperature), ("rad", self.angle)]
        {
            match e {
                0 => {}
                1 => num.push(sym.to_string()),
                e if e > 0 => num.push(format!("{sym}^{e}")),
                -1 => den.push(sym.to_string()),
                e => den.push(format!("{sym}^{}", -e)),
            }
        }
        match (num.is_empty(), den.is_empty()) {
            (true, true) => "1".into(),
            (false, true) => num.join("*"),
            (true, false) => format!("1/{}", den.join("/")),
            (false, false) => format!("{}/{}", num.join("*"), den.join("/")),
        }
    }
}

const NAMED: &[(Dimension, &str)] = &[
    (Dimension::NONE, "dimensionless number"),
    (Dimension::LENGTH, "length"),
    (Dimension::RECIPROCAL_LENGTH, "reciprocal length"),
    (Dimension::MASS, "mass"),
    (Dimension::TIME, "time"),
    (Dimension::TEMPERATURE, "temperature"),
    (Dimension::ANGLE, "angle"),
    (Dimension::FORCE, "force"),
    (Dimension::TORQUE, "torque"),
    (Dimension::ANGULAR_VELOCITY, "rotational speed"),
    (Dimension::PRESSURE, "pressure or elastic modulus"),
    (Dimension::RECIPROCAL_PRESSURE, "reciprocal pressure"),
    (Dimension::DYNAMIC_VISCOSITY, "dynamic viscosity"),
    (Dimension::KINEMATIC_VISCOSITY, "kinematic viscosity"),
    (Dimension::DENSITY, "density"),
    (Dimension::MOMENT_OF_INERTIA, "moment of inertia"),
    (Dimension::STIFFNESS, "stiffness"),
    (Dimension::POWER, "power"),
    (Dimension::VELOCITY, "velocity"),
    (Dimension::FREQUENCY, "frequency"),
    (Dimension::AREA, "area"),
    (Dimension::HEAT_CAPACITY, "heat capacity"),
    (Dimension::THERMAL_CONDUCTANCE, "thermal conductance"),
    (Dimension::MASS_RATE, "road-load speed coefficient (N*s/m)"),
    (Dimension::MASS_PER_LENGTH, "road-load square coefficient (N*s^2/m^2)"),
];

const SI_NAMES: &[(Dimension, &str)] = &[
    (Dimension::NONE, "1"),
    (Dimension::LENGTH, "m"),
    (Dimension::RECIPROCAL_LENGTH, "1/m"),
    (Dimension::ANGLE, "rad"),
    (Dimension::FORCE, "N"),
    (Dimension::TORQUE, "N*m"),
    (Dimension::ANGULAR_VELOCITY, "rad/s"),
    (Dimension::PRESSURE, "Pa"),
    (Dimension::RECIPROCAL_PRESSURE, "1/Pa"),
    (Dimension::DYNAMIC_VISCOSITY, "Pa*s"),
    (Dimension::KINEMATIC_VISCOSITY, "m^2/s"),
    (Dimension::DENSITY, "kg/m^3"),
    (Dimension::MOMENT_OF_INERTIA, "kg*m^2"),
    (Dimension::STIFFNESS, "N/m"),
    (Dimension::POWER, "W"),
    (Dimension::VELOCITY, "m/s"),
    (Dimension::FREQUENCY, "Hz"),
    (Dimension::TEMPERATURE, "K"),
    (Dimension::AREA, "m^2"),
    (Dimension::HEAT_CAPACITY, "J/K"),
    (Dimension::THERMAL_CONDUCTANCE, "W/K"),
];

/// A unit as written, as the report shows it: a product's `*` as the middle dot the tables write
/// (`N*m` → `N·m`, `lbf*in` → `lbf·in`).
///
pub(crate) fn shown_written_unit(unit: &str) -> String {
    unit.replace('*', "·")
}

/// A value of an operating sweep as a point's label shows it: as written where it has at most 9
/// significant digits (every value a person types), else to the fewest significant digits from 6
/// on that tell it from `neighbours` (the sweep's values beside it), rounded as the inputs table
/// rounds (`sig_digits`): a range's computed 2309.090909090909 rpm is `2309.09`, and 1000.0001
/// beside 1000.0002 in a dense range stays apart. The value itself (records, report.json's
/// numbers) is never rounded.
pub(crate) fn label_number(x: f64, neighbours: &[f64]) -> String {
    let full = x.to_string();
    let digits = full.trim_start_matches('-').replace('.', "");
    if digits.trim_start_matches('0').trim_end_matches('0').len() <= 9 {
        return full;
    }
    let rounded = crate::numerics::rounding::sig_digits;
    (6..=17)
        .map(|d| rounded(x, d))
        .zip(6..)
        .find(|(s, d)| neighbours.iter().all(|n| *n == x || rounded(*n, *d) != *s))
        .map_or(full, |(s, _)| s)
}

#[cfg(test)]
mod label_number_tests {
    use super::label_number;

    /// As written up to 9 significant digits; a computed value to 6, more where a neighbour would
    /// read the same; a value equal to its neighbour is itself.
    #[test]
    fn a_label_shows_what_tells_the_point_apart() {
        assert_eq!(label_number(200.0, &[]), "200");
        assert_eq!(label_number(-0.05, &[]), "-0.05");
        assert_eq!(label_number(123456.789, &[]), "123456.789");
        assert_eq!(label_number(2309.090909090909, &[1781.8181818181818, 2836.3636363636365]), "2309.09");
        assert_eq!(label_number(87.76372581794031, &[]), "87.7637");
        assert_eq!(label_number(0.1 + 0.2, &[]), "0.3");
        // A range of 1000..1001 count 10001 (step 1e-4): 1000.0001000000001 beside 1000 and 1000.0002.
        let (a, b, c) = (1000.0, 1000.0 + 1e-4 + 1e-13, 1000.0 + 2e-4);
        assert_eq!(label_number(b, &[a, c]), "1000.0001");
        assert_eq!(label_number(1000.0, &[1000.0]), "1000");
    }
}

#[cfg(test)]
mod shown_unit_tests {
    #[test]
    fn a_product_shows_its_middle_dot() {
        assert_eq!(super::shown_written_unit("N*m"), "N·m");
        assert_eq!(super::shown_written_unit("lbf*in"), "lbf·in");
        assert_eq!(super::shown_written_unit("rpm"), "rpm");
    }
}
