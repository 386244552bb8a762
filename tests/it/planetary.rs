//! Planetary stages: Willis, the torque balance with the meshes' losses, Krüger's one-member-fixed
//! efficiencies (from a published η₀ and from the tool's own), the stage inside a drive (every shaft
//! in balance, the loss its parts), and the planets' forces.

use crate::drive::points;
use gearloss::drive::kinematics::planetary::{
    member_torques, one_fixed_efficiency, willis, Planetary, PlanetaryMember, PlanetaryMember::*,
};

/// The six one-member-fixed cases: (held, input, output).
const CASES: [(PlanetaryMember, PlanetaryMember, PlanetaryMember); 6] = [
    (Ring, Sun, Carrier),
    (Ring, Carrier, Sun),
    (Sun, Ring, Carrier),
    (Sun, Carrier, Ring),
    (Carrier, Sun, Ring),
    (Carrier, Ring, Sun),
];

fn reducer() -> gearloss::Scene {
    crate::scene(&crate::root().join("specs/planetary_reducer.gear"))
}

/// Willis for every one-fixed case (z 24/72 and 17/73): the held member at rest, the equation's
/// residual below 1e-14 of the speeds, and the closed-form ratios 1 − i₀ (ring held, sun to carrier),
/// 1 − 1/i₀ (sun held, ring to carrier), i₀ (carrier held, sun to ring), to 1e-14.
#[test]
fn willis_speeds_for_all_six_one_fixed_cases() {
    for (z_sun, z_ring) in [(24u32, 72u32), (17, 73)] {
        let i0 = -f64::from(z_ring) / f64::from(z_sun);
        for (held, input, output) in CASES {
            let k = Planetary { sun_teeth: z_sun, ring_teeth: z_ring, members: [input, output] };
            let w = k.member_speeds(input, 314.159);
            assert_eq!(w[held.index()], 0.0);
            assert_eq!(w[input.index()], 314.159);
            let residual = w[0] - i0 * w[1] - (1.0 - i0) * w[2];
            assert!(residual.abs() < 1e-14 * 314.159, "{held:?} held: residual {residual}");
            let ratio = w[input.index()] / w[output.index()];
            let expected = match (input, output) {
                (Sun, Carrier) => 1.0 - i0,
                (Carrier, Sun) => 1.0 / (1.0 - i0),
                (Ring, Carrier) => 1.0 - 1.0 / i0,
                (Carrier, Ring) => 1.0 / (1.0 - 1.0 / i0),
                (Sun, Ring) => i0,
                (Ring, Sun) => 1.0 / i0,
                _ => unreachable!(),
            };
            assert!((ratio - expected).abs() < 1e-14 * expected.abs(), "{input:?}→{output:?}: {ratio} vs {expected}");
            // And back: from the output's speed, the input's.
            let back = willis(i0, (output, w[output.index()]), (held, 0.0));
            assert!((back[input.index()] - 314.159).abs() < 1e-13 * 314.159, "{input:?}: {}", back[input.index()]);
        }
    }
}

/// The torques with losses (η₀ = 0.97) in every one-fixed case, driven forwards and backwards: they
/// balance (Σ T = 0 to 1e-12), the stage loses Σ T ω = (1 − η₀) × the rolling power of the side
/// that drives the meshes (to 1e-12), never less than zero; with η₀ = 1 nothing is lost.
#[test]
fn torque_balance_with_losses() {
    let i0 = -3.0;
    for (held, input, output) in CASES {
        let w = willis(i0, (input, 100.0), (held, 0.0));
        for sign in [1.0, -1.0] {
            for eta0 in [0.97, 1.0] {
                let t = member_torques(i0, eta0, (input, sign * 50.0), w);
                let sum: f64 = t.torques.iter().sum();
                assert!(sum.abs() < 1e-12 * 50.0, "{input:?}→{output:?}: Σ T = {sum}");
                let loss = t.loss(w);
                let p_w = t.rolling_power.abs();
                let driving_side = if t.sun_drives_meshes { p_w } else { p_w / eta0 };
                let expected = (1.0 - eta0) * driving_side;
                assert!(
                    (loss - expected).abs() < 1e-12 * driving_side.max(1.0),
                    "{input:?}→{output:?}: {loss} vs {expected}"
                );
                assert!(loss >= -1e-12);
                // The ring's torque is −i₀ η₀^w times the sun's.
                let w_exp = if t.sun_drives_meshes { eta0 } else { 1.0 / eta0 };
                assert!((t.torques[1] + i0 * w_exp * t.torques[0]).abs() < 1e-12 * t.torques[1].abs().max(1.0));
            }
        }
    }
}

/// Krüger's one-member-fixed efficiencies (as Müller, *Die Umlaufgetriebe*, tabulates them for
/// i₀ < 0) from the tool's torque balance, every case to 1e-14; with i₀ = −3 and η₀ = 0.98505 the
/// published 0.98879 (sun → carrier) and 0.99626 (ring → carrier) to their five digits; η₀ = 1 gives 1.
#[test]
fn kruger_one_member_fixed_efficiencies() {
    for (i0, eta0) in [(-3.0, 0.98505), (-4.2941, 0.97), (-2.5, 0.99)] {
        for (held, input, output) in CASES {
            let eta = one_fixed_efficiency(i0, eta0, input, output);
            let kruger = match (input, output) {
                (Sun, Carrier) => (1.0 - i0 * eta0) / (1.0 - i0),
                (Carrier, Sun) => (1.0 - i0) / (1.0 - i0 / eta0),
                (Ring, Carrier) => (i0 - eta0) / (i0 - 1.0),
                (Carrier, Ring) => eta0 * (1.0 - i0) / (1.0 - i0 * eta0),
                (Sun, Ring) | (Ring, Sun) => eta0,
                _ => unreachable!(),
            };
            assert!((eta - kruger).abs() < 1e-14, "{held:?} held, {input:?}→{output:?}: {eta} vs {kruger}");
            assert!((one_fixed_efficiency(i0, 1.0, input, output) - 1.0).abs() < 1e-15);
        }
    }
    assert!((one_fixed_efficiency(-3.0, 0.98505, Sun, Carrier) - 0.98879).abs() < 5e-6);
    assert!((one_fixed_efficiency(-3.0, 0.98505, Ring, Carrier) - 0.99626).abs() < 5e-6);
}

/// The spec's reducer (sun in, carrier out, ring held, i₀ = −3): at every point, law and flow the
/// stage's η is Krüger's from the tool's own η₀ = η_sp η_pr (drive: (1 + 3η₀)/4; coast, carrier in:
/// 4η₀/(η₀ + 3)), to 1e-12; the meshes' losses add up to (1 − η) P_in (1e-9); the members' torques
/// balance and their powers add up to the meshes' loss (1e-9).
#[test]
fn kruger_from_the_tools_own_eta0() {
    let all = points(&reducer());
    // 3 torques × 2 speeds × 2 laws, drive and coast.
    assert_eq!(all.len(), 12);
    assert!(all.iter().any(|p| p.flow == gearloss::drive::PowerFlow::Coast));
    for p in all {
        let s = &p.stages[0];
        let pp = s.planetary().expect("a planetary stage");
        let eta0 = pp.basic_efficiency;
        assert!((eta0 - pp.mesh_efficiency[0] * pp.mesh_efficiency[1]).abs() < 1e-15);
        assert!(eta0 < 1.0 && eta0 > 0.95);
        let kruger = match pp.driving_member {
            Sun => (1.0 + 3.0 * eta0) / 4.0,
            Carrier => 4.0 * eta0 / (eta0 + 3.0),
            Ring => unreachable!(),
        };
        assert!((pp.efficiency - kruger).abs() < 1e-12, "{:?}: {} vs {kruger}", p.flow, pp.efficiency);
        assert!((s.mesh_efficiency - pp.efficiency).abs() < 1e-12, "the walk's η of the stage");
        let p_in = s.driving_torque * s.driving_speed;
        let meshes = pp.mesh_loss[0] + pp.mesh_loss[1];
        assert!(
            (meshes - (1.0 - pp.efficiency) * p_in).abs() < 1e-9 * p_in,
            "{meshes} vs {}",
            (1.0 - pp.efficiency) * p_in
        );
        assert!((s.mesh_loss - meshes).abs() < 1e-9 * p_in);
        let sum: f64 = pp.torques.iter().sum();
        assert!(sum.abs() < 1e-12 * pp.torques[2].abs());
        let power: f64 = (0..3).map(|i| pp.torques[i] * pp.speeds[i]).sum();
        assert!((power - meshes).abs() < 1e-9 * p_in, "Σ T ω = {power} vs {meshes}");
    }
}

/// The drive with the planetary stage: every shaft balances its forces and moments (five equations
/// from its two bearing places, to 1e-12 of the largest force; the sixth from the walk's torques
/// and the shaft's own losses), the sun's mesh forces turn it by −T_driving and the carrier's by the
/// lossless 4 T_driving (1e-12), and P_in − P_out is the sum of the parts (1e-9). Three planets
/// cancel each other's forces (the places carry none beyond 1e-9 of F_t); one planet loads them.
#[test]
fn the_planetary_stage_keeps_every_shaft_in_balance() {
    let one = crate::scene_from_text(
        &std::fs::read_to_string(crate::root().join("specs/planetary_reducer.gear"))
            .unwrap()
            .replace("planets = 3", "planets = 1"),
    );
    for (scene, planets) in [(reducer(), 3), (one, 1)] {
        for p in points(&scene) {
            let s = &p.stages[0];
            for shaft in &p.shafts {
                crate::drive::assert_shaft_balances(shaft);
                let reactions = [shaft.bearings[0].reaction, shaft.bearings[1].reaction];
                let radial = reactions.iter().map(|r| r[0].hypot(r[1])).fold(0.0f64, f64::max);
                if planets == 3 {
                    assert!(radial < 1e-9 * s.tangential_force, "{}: {radial} N with three planets", shaft.name);
                } else {
                    assert!(radial > 0.1 * s.tangential_force, "{}: {radial} N with one planet", shaft.name);
                }
            }
            let about_axis = |j: usize| p.shafts[j].gear_loads.iter().map(|l| l.torque()).sum::<f64>();
            let t = s.driving_torque;
            let (sun, carrier) = if s.driving == gearloss::drive::Member::Pinion { (0, 1) } else { (1, 0) };
            let (on_driving, on_driven) = (about_axis(sun), about_axis(carrier));
            let sense = p.shafts[sun].speed.signum();
            let expected = if s.driving == gearloss::drive::Member::Pinion { (-t, 4.0 * t) } else { (-t, t / 4.0) };
            assert!((on_driving * sense - expected.0).abs() < 1e-12 * t.abs(), "{on_driving} vs {}", expected.0);
            assert!((on_driven * sense - expected.1).abs() < 1e-12 * t.abs() * 4.0, "{on_driven} vs {}", expected.1);
            let parts = p.losses.total();
            assert!((p.power_lost() - parts).abs() < 1e-9 * p.input_power.abs(), "{} vs {parts}", p.power_lost());
        }
    }
}

/// One planet's bearing load by hand: F_t = T_sun/(n r_w,sun) on both meshes (the radial forces
/// cancel with equal pressure angles), |B| = √((2 F_t)² + (m ω_c² a_w)²), to 1e-12.
#[test]
fn planet_bearing_load_by_hand() {
    for p in points(&reducer()) {
        let pp = p.stages[0].planetary().unwrap();
        let f = &pp.forces;
        // The lossless sun torque: the driving torque, or the carrier's over 1 − i₀ = 4.
        let t = p.stages[0].driving_torque;
        let sun = if pp.driving_member == Sun { t } else { t / 4.0 };
        let expected_ft = sun / (3.0 * 0.024);
        assert!((f.tangential[0] - expected_ft).abs() < 1e-12 * expected_ft, "{} vs {expected_ft}", f.tangential[0]);
        assert!((f.tangential[1] - f.tangential[0]).abs() < 1e-12 * expected_ft);
        let mass = 7850.0 * std::f64::consts::PI / 4.0 * 0.048f64.powi(2) * 0.025;
        let centrifugal = mass * pp.speeds[2].powi(2) * 0.048;
        assert!((f.centrifugal - centrifugal).abs() < 1e-12 * centrifugal);
        let b = (2.0 * f.tangential[0]).hypot(centrifugal);
        assert!((f.bearing - b).abs() < 1e-12 * b, "{} vs {b}", f.bearing);
    }
}

/// The two-DOF stage (all three turning, two speeds given, the third by Willis; one torque given):
/// the torques balance and Σ T ω is the meshes' loss (1e-12); with the ring's speed going to zero
/// the stage's η goes to Krüger's ring-held value (continuity, 1e-9); turning as a block (ω_sun =
/// ω_carrier) nothing rolls and nothing is lost; a differential summing sun and ring into the carrier
/// loses only on the rolling power, so its η lies above the ring-held stage's.
#[test]
fn two_dof_stage_balances_and_meets_the_one_fixed_limits() {
    let (i0, eta0) = (-3.0, 0.98505);
    for ring in [-30.0, -1.0, 0.0, 1e-9, 20.0] {
        let w = willis(i0, (Sun, 300.0), (Ring, ring));
        let t = member_torques(i0, eta0, (Sun, 40.0), w);
        assert!(t.torques.iter().sum::<f64>().abs() < 1e-12 * 40.0);
        let expected = if t.sun_drives_meshes {
            (1.0 - eta0) * t.rolling_power.abs()
        } else {
            (1.0 / eta0 - 1.0) * t.rolling_power.abs()
        };
        assert!((t.loss(w) - expected).abs() < 1e-12 * t.rolling_power.abs());
        if ring.abs() < 1e-6 {
            let kruger = (1.0 - i0 * eta0) / (1.0 - i0);
            assert!((t.efficiency(w) - kruger).abs() < 1e-9, "ring at {ring}: {} vs {kruger}", t.efficiency(w));
        }
    }
    let block = willis(i0, (Sun, 100.0), (Carrier, 100.0));
    assert!((block[1] - 100.0).abs() < 1e-12);
    let t = member_torques(i0, eta0, (Sun, 40.0), block);
    assert!(t.rolling_power == 0.0 && t.loss(block).abs() < 1e-12 && t.efficiency(block) == 1.0);
    // Sun and ring both driving the carrier (the ring turning with the sun).
    let w = willis(i0, (Sun, 300.0), (Ring, 50.0));
    let t = member_torques(i0, eta0, (Carrier, -4.0 * 40.0), w);
    assert!(t.torques[0] * w[0] > 0.0 && t.torques[1] * w[1] > 0.0 && t.torques[2] * w[2] < 0.0);
    assert!(t.efficiency(w) > one_fixed_efficiency(i0, eta0, Sun, Carrier) && t.efficiency(w) < 1.0);
}

/// A load-sharing factor K_γ = 1.25 (three planets): the most loaded planet's forces are K_γ times
/// equal sharing's (1e-12); under Coulomb friction, whose mean loss is linear in the load, η₀ and η are
/// equal sharing's (1e-12); under Benedict–Kelley (μ varies with the load) η₀ moves; the planets'
/// bearings: the no-load part is unchanged (exactly), the load part grows a little (M_1 is linear in
/// |B|, and |B| = √((2F_t)² + (centrifugal)²) is convex in the planet's load), by less than 1e-3.
#[test]
fn load_sharing_factor_loads_one_planet_more() {
    let text = std::fs::read_to_string(crate::root().join("specs/planetary_reducer.gear")).unwrap();
    let with = |k: &str, friction: &str| {
        let t = text.replace("planets = 3", &format!("planets = 3  load_sharing_factor = {k}"));
        crate::scene_from_text(&t.replace("        iso_14179_2\n        benedict_kelley\n", friction))
    };
    for friction in ["        coulomb(mu = 0.05)\n", "        benedict_kelley\n"] {
        let (equal, unequal) = (points(&with("1", friction)), points(&with("1.25", friction)));
        assert_eq!(equal.len(), unequal.len());
        for (e, u) in equal.iter().zip(&unequal) {
            let (pe, pu) = (e.stages[0].planetary().unwrap(), u.stages[0].planetary().unwrap());
            // The lossless sun torque over n r_w,sun, times K_γ.
            let t = u.stages[0].driving_torque;
            let sun = if pu.driving_member == Sun { t } else { t / 4.0 };
            let f_t = 1.25 * sun / (3.0 * 0.024);
            assert!((pu.forces.tangential[0] - f_t).abs() < 1e-12 * f_t, "{} vs {f_t}", pu.forces.tangential[0]);
            assert!(pe.forces.tangential[0] < pu.forces.tangential[0]);
            let moved = (pu.basic_efficiency - pe.basic_efficiency).abs();
            if friction.contains("coulomb") {
                assert!(moved < 1e-12, "Coulomb: η₀ moved by {moved}");
            } else {
                assert!(moved > 1e-7, "Benedict–Kelley: η₀ moved by {moved} only");
            }
            let bearings = |p: &gearloss::drive::DrivePoint| {
                p.shafts
                    .iter()
                    .flat_map(|s| &s.bearings)
                    .filter(|b| b.of_stage_members)
                    .map(|b| [b.no_load, b.load])
                    .next()
                    .unwrap()
            };
            let (be, bu) = (bearings(e), bearings(u));
            assert_eq!(be[0], bu[0]);
            assert!(bu[1] >= be[1] && bu[1] - be[1] < 1e-3 * be[1], "{be:?} vs {bu:?}");
        }
    }
}

/// K_γ = n (one planet carries the whole load, the limit the language allows): every number of
/// every point finite (it gave NaN efficiencies), the most loaded planet's F_t the whole sun torque
/// over r_w,sun (1e-12), and with Coulomb's law η₀ the equal sharing's (1e-12: Coulomb's mesh loss is
/// linear in the load).
#[test]
fn load_sharing_factor_at_the_planets_count_is_one_planet_carrying_all() {
    let text = std::fs::read_to_string(crate::root().join("specs/planetary_reducer.gear")).unwrap();
    let with = |k: &str| {
        let t = text.replace("planets = 3", &format!("planets = 3  load_sharing_factor = {k}"));
        crate::scene_from_text(&t.replace(
            "        iso_14179_2
        benedict_kelley
",
            "        coulomb(mu = 0.05)
",
        ))
    };
    let (equal, all) = (points(&with("1")), points(&with("3")));
    for (e, a) in equal.iter().zip(&all) {
        assert!(a.efficiency.is_finite() && a.power_lost().is_finite(), "η {} loss {}", a.efficiency, a.power_lost());
        let (pe, pa) = (e.stages[0].planetary().unwrap(), a.stages[0].planetary().unwrap());
        assert!(pa.basic_efficiency.is_finite() && pa.efficiency.is_finite());
        let t = a.stages[0].driving_torque;
        let sun = if pa.driving_member == Sun { t } else { t / 4.0 };
        let f_t = sun / 0.024;
        assert!((pa.forces.tangential[0] - f_t).abs() < 1e-12 * f_t, "{} vs {f_t}", pa.forces.tangential[0]);
        assert!((pa.basic_efficiency - pe.basic_efficiency).abs() < 1e-12);
    }
}

/// With every loss zero (μ = 0, no bearings, seals or lubrication) the planetary reducer passes all
/// its power, drive and coast, with the sun or the carrier given (η = 1 to 1e-12), and the output
/// torque is the input's times the ratio 4 (1e-12).
#[test]
fn with_every_loss_zero_the_stage_passes_all_its_power() {
    let scene = |operating: &str| {
        crate::scene_from_text(&format!(
            r#"scene "lossless planetary" {{
    material steel {{ youngs_modulus = 210 GPa  poisson_ratio = 0.3 }}
    lubricant "oil" {{ nu_40 = 68 mm^2/s  nu_100 = 8.7 mm^2/s  density_15 = 880 kg/m^3  base = mineral }}
    stage "planetary" {{
        planetary {{
            planets = 3
            module = 2 mm  pressure_angle = 20 deg  face_width = 25 mm
            sun     {{ teeth = 24  shaft = motor  at = 60 mm  material = steel  roughness_ra = 0.4 um }}
            planet  {{ teeth = 24  material = steel  roughness_ra = 0.4 um }}
            ring    {{ teeth = 72  tip_diameter = 141 mm  shaft = housing  material = steel  roughness_ra = 0.4 um }}
            carrier {{ shaft = output  at = 40 mm }}
        }}
    }}
    gearbox {{ shaft motor {{ input }}  shaft output {{ output }} }}
    operating {{ {operating}  oil_temperature = 70 degC }}
    friction {{ coulomb(mu = 0) }}
    analyses {{ efficiency(formulations = [external, internal]) }}
}}"#
        ))
    };
    for operating in [
        "input_torque = [-80, 80] N*m  input_speed = 2000 rpm",
        "output_torque = [-300, 300] N*m  output_speed = 500 rpm",
    ] {
        let all = points(&scene(operating));
        assert_eq!(all.len(), 4);
        for p in all {
            assert!((p.efficiency - 1.0).abs() < 1e-12, "{operating}: η = {}", p.efficiency);
            assert!((p.output_torque - 4.0 * p.input_torque).abs() < 1e-12 * p.output_torque.abs());
            assert_eq!(p.stages[0].planetary().unwrap().basic_efficiency, 1.0);
        }
    }
}

/// The e-axle with its planetary first stage in the ID.3 over WLTC 3b at 80 °C: the motor's energy −
/// the output's = Σ parts (1e-9), and doubling the Gauss order moves the loss by less than its
/// estimate: the drive cycle reads the planetary stage as any other.
#[test]
fn a_planetary_box_over_a_drive_cycle_balances() {
    use gearloss::evaluate::drive_cycle::{evaluate_cycle, loss_energy_at_order, MOTOR, OUTPUT, PARTS};
    let text = std::fs::read_to_string(crate::root().join("specs/planetary_two_stage.gear")).unwrap();
    let trace = crate::root().join("specs/cycles/wltc_3b.csv");
    let head = &text[..text.find("    operating {").unwrap()];
    let scene = crate::scene_from_text(&format!(
        r#"{head}    operating {{ oil_temperature = 80 degC }}
    vehicle "ID.3" {{
        mass = 1976 kg  rotating_mass_factor = 1.07  wheel_radius = 0.335 m
        drag(coefficient = 0.267, frontal_area = 2.3903615 m^2, air_density = 1.225 kg/m^3)
        rolling_resistance = 0.009
        recuperation_limit = 900 N*m
    }}
    drive_cycle "WLTC class 3b" {{ trace = "{}" }}
    friction {{ iso_14179_2(x_l = 0.75) }}
    analyses {{ efficiency(formulations = [external])  drive_cycle }}
}}
"#,
        trace.display()
    ));
    let drive = scene.drive.as_ref().unwrap();
    let e = evaluate_cycle(&scene, drive, drive.cycle.as_ref().unwrap());
    let (motor, output): (f64, f64) =
        e.integrals.iter().fold((0.0, 0.0), |(a, b), r| (a + r.value[MOTOR], b + r.value[OUTPUT]));
    let lost: f64 = e.integrals.iter().map(|r| r.value[..PARTS].iter().sum::<f64>()).sum();
    assert!(lost > 0.0 && ((motor - output) - lost).abs() <= 1e-9 * motor.abs(), "{} vs {lost}", motor - output);
    let estimate: f64 = e.integrals.iter().map(|r| r.error[..PARTS].iter().sum::<f64>()).sum();
    let doubled = loss_energy_at_order(&scene, drive, drive.cycle.as_ref().unwrap(), 10, 1);
    assert!((doubled - lost).abs() < estimate, "moved {} J, estimate {estimate} J", (doubled - lost).abs());
}
