//! The unit table: every alias equals its composition, compound units multiply, and the factors
//! agree with uom's own unit definitions.

use gearloss::scene::lower::unit_scale;
use gearloss::scene::parse::parse_unit_text;
use gearloss::scene::units::{self, Dimension, UNITS};

fn scale(text: &str) -> units::Scale {
    let u = parse_unit_text(text).unwrap_or_else(|e| panic!("{text}: {e:?}"));
    units::evaluate(u.factors.iter().map(|(n, _, e)| (n.as_str(), *e))).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// Relative tolerance for factor comparisons: table constants are exact decimals, so only rounding differs.
const TOL: f64 = 1e-12;

fn close(a: f64, b: f64) -> bool {
    ((a - b) / b).abs() < TOL
}

#[test]
fn every_alias_equals_its_composition() {
    let mut checked = 0;
    for u in UNITS {
        let Some((k, expr)) = u.composition else {
            continue;
        };
        let s = scale(expr);
        assert_eq!(s.dimension, u.dimension, "{} vs {expr}", u.name);
        assert!(close(u.factor, k * s.factor), "{}: {} vs {} × {expr} = {}", u.name, u.factor, k, k * s.factor);
        checked += 1;
    }
    assert!(checked >= 40, "only {checked} compositions checked");
}

#[test]
fn compound_units_multiply() {
    let lbf = scale("lbf").factor;
    let inch = scale("in").factor;
    assert!(close(scale("lbf*in").factor, lbf * inch));
    assert_eq!(scale("lbf*in").dimension, Dimension::TORQUE);
    assert!(close(scale("lbf*ft").factor, lbf * 12.0 * inch));
    assert!(close(scale("N*mm").factor, 1e-3));
    assert!(close(scale("lbf*s^2*in").factor, lbf * inch));
    assert_eq!(scale("lbf*s^2*in").dimension, Dimension::MOMENT_OF_INERTIA);
    assert_eq!(scale("kg*m^2").dimension, Dimension::MOMENT_OF_INERTIA);
    assert!(close(scale("1/GPa").factor, 1e-9));
    assert!(close(scale("1/psi").factor, 1.0 / scale("psi").factor));
    assert_eq!(scale("1/Pa").dimension, Dimension::RECIPROCAL_PRESSURE);
    assert!(close(scale("N/um").factor, 1e6));
    assert_eq!(scale("N/m").dimension, Dimension::STIFFNESS);
    assert!(close(scale("mm^2/s").factor, scale("cSt").factor));
    assert!(close(scale("rad/s").factor, 1.0));
    assert!(close(scale("1/in").factor, 1.0 / 0.0254));
    assert_eq!(scale("kg/m^3").dimension, Dimension::DENSITY);
}

#[test]
fn units_the_issue_names_are_all_present() {
    for name in [
        "m",
        "mm",
        "um",
        "µm",
        "in",
        "uin",
        "µin",
        "deg",
        "rad",
        "N*m",
        "N*mm",
        "lbf*in",
        "lbf*ft",
        "rpm",
        "rad/s",
        "Pa",
        "kPa",
        "MPa",
        "GPa",
        "psi",
        "Pa*s",
        "mPa*s",
        "cP",
        "reyn",
        "cSt",
        "mm^2/s",
        "m^2/s",
        "kg*m^2",
        "lbf*s^2*in",
        "kg/m^3",
        "1/Pa",
        "1/GPa",
        "1/psi",
        "N/m",
        "N/um",
        "W",
        "kW",
        "hp",
        "degC",
    ] {
        scale(name);
    }
}

#[test]
fn factors_agree_with_uom() {
    use uom::si::f64::*;
    use uom::si::{angular_velocity, dynamic_viscosity, force, length, power, pressure, torque};
    let pairs = [
        ("in", Length::new::<length::inch>(1.0).value),
        ("uin", Length::new::<length::microinch>(1.0).value),
        ("ft", Length::new::<length::foot>(1.0).value),
        ("lbf", Force::new::<force::pound_force>(1.0).value),
        ("psi", Pressure::new::<pressure::pound_force_per_square_inch>(1.0).value),
        ("lbf*in", Torque::new::<torque::pound_force_inch>(1.0).value),
        ("lbf*ft", Torque::new::<torque::pound_force_foot>(1.0).value),
        ("rpm", AngularVelocity::new::<angular_velocity::revolution_per_minute>(1.0).value),
        ("cP", DynamicViscosity::new::<dynamic_viscosity::centipoise>(1.0).value),
        ("reyn", DynamicViscosity::new::<dynamic_viscosity::reyn>(1.0).value),
        ("hp", Power::new::<power::horsepower>(1.0).value),
    ];
    // uom rounds the pound-force to 4.448222 N (7 digits); the table uses the exact 0.45359237 kg × 9.80665 m/s².
    for (name, uom_value) in pairs {
        assert!(
            ((scale(name).factor - uom_value) / uom_value).abs() < 2e-7,
            "{name}: table {} vs uom {uom_value}",
            scale(name).factor
        );
    }
}

#[test]
fn celsius_is_absolute_and_alone() {
    let s = scale("degC");
    assert_eq!(s.to_si(90.0), 363.15);
    assert!(units::evaluate([("degC", 1), ("s", 1)]).is_err());
}

#[test]
fn wrong_dimension_is_refused_with_the_expected_name() {
    let errors = unit_scale("N", Dimension::LENGTH).unwrap_err();
    assert!(errors[0].reason.contains("expects a length"), "{}", errors[0].reason);
    assert_eq!(unit_scale("lbf*in", Dimension::TORQUE).unwrap(), scale("lbf").factor * 0.0254);
}

#[test]
fn unknown_units_get_a_suggestion() {
    let err = units::evaluate([("mmm", 1)]).unwrap_err();
    assert!(matches!(err, units::UnitError::Unknown { suggestion: Some("mm"), .. }), "{err:?}");
}

/// °F and degF are absolute: K = (°F + 459.67) · 5/9 (212 °F = 373.15 K, 32 °F = 273.15 K,
/// within 1e-12 K); °C equals degC.
#[test]
fn fahrenheit_and_the_degree_signs_are_absolute_temperatures() {
    for name in ["degF", "°F"] {
        let s = scale(name);
        assert!((s.to_si(212.0) - 373.15).abs() < 1e-12 && (s.to_si(32.0) - 273.15).abs() < 1e-12, "{name}");
        assert!(units::evaluate([(name, 1), ("s", 1)]).is_err(), "{name} in a compound");
    }
    assert_eq!(scale("°C").to_si(90.0), scale("degC").to_si(90.0));
}

/// The hint names the unit a common spelling stands for: `Nm` → `N*m` (not `N`), `C` → `degC`,
/// `F` → `degF`, `Nmm` → `N*mm`.
#[test]
fn common_spellings_get_the_unit_they_mean() {
    for (written, meant) in [("Nm", "N*m"), ("C", "degC"), ("F", "degF"), ("Nmm", "N*mm"), ("celsius", "degC")] {
        let err = units::evaluate([(written, 1)]).unwrap_err();
        assert!(
            matches!(err, units::UnitError::Unknown { suggestion: Some(s), .. } if s == meant),
            "{written}: {err:?}"
        );
    }
}

/// Issue 46: the energies (J, kJ, MJ, Wh, kWh) share the torque's SI dimension but are not torques:
/// a key that expects a torque refuses them with a hint of torque units only, `gearloss units`
/// lists them as energies, and they still compose (`kJ/K` is a heat capacity, `kWh` = 3.6e6 N·m).
#[test]
fn energies_are_not_torques() {
    let energies: Vec<&str> = UNITS.iter().filter(|u| u.energy).map(|u| u.name).collect();
    assert_eq!(energies, ["J", "kJ", "MJ", "Wh", "kWh"]);
    for name in &energies {
        let def = units::lookup(name).unwrap();
        assert_eq!(def.dimension, Dimension::TORQUE);
        assert_eq!(def.quantity(), "energy");
        let errors = unit_scale(name, Dimension::TORQUE).unwrap_err();
        assert!(errors[0].reason.contains("is an energy"), "{}", errors[0].reason);
        let hint = errors[0].hints.join(" ");
        assert!(hint.contains("lbf*in") && !energies.iter().any(|e| hint.contains(&format!(" {e},"))), "{hint}");
    }
    assert_eq!(unit_scale("kJ/K", Dimension::HEAT_CAPACITY).unwrap(), 1e3);
    assert!(close(scale("kWh").factor, 3.6e6));
    assert!(close(unit_scale("N*mm", Dimension::TORQUE).unwrap(), 1e-3));
    assert!(!units::example_units(Dimension::TORQUE).contains('J'));
    assert_eq!(units::lookup("N").unwrap().quantity(), "force");
}
