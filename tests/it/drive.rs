//! Gearboxes with several stages: the drive's physics against its own balances (every shaft's
//! statics, the power balance), the kinematics, drive against coast, the fixed point, and a
//! one-stage drive against the loss budget of one pair.

use gearloss::drive::statics::residuals;
use gearloss::drive::{DrivePoint, PowerFlow};
use gearloss::evaluate::drive::evaluate_drive;

fn ev_reducer() -> gearloss::Scene {
    crate::scene(&crate::root().join("specs/ev_two_stage_reducer.gear"))
}

fn points(scene: &gearloss::Scene) -> Vec<DrivePoint> {
    evaluate_drive(scene, scene.drive.as_ref().unwrap()).rows.into_iter().map(|r| r.point).collect()
}

/// Every shaft balances forces and moments (five equations from its bearing reactions, the sixth,
/// about its axis, from the torques the walk passes through it) to 1e-12 of the largest force.
#[test]
fn every_shaft_balances_forces_and_moments() {
    for p in points(&ev_reducer()) {
        for s in &p.shafts {
            let largest = s.gear_loads.iter().flat_map(|l| l.force).fold(0.0f64, |m, f| m.max(f.abs()));
            assert!(largest > 0.0);
            let positions = [s.bearings[0].position, s.bearings[1].position];
            let reactions = [s.bearings[0].reaction, s.bearings[1].reaction];
            for r in residuals(&s.gear_loads, positions, &reactions) {
                assert!(r.abs() <= 1e-12 * largest, "{}: residual {r} of {largest} N", s.name);
            }
            // The axis: received − passed = the shaft's own loss moments (powers over |ω|).
            let own = s.losses() / s.speed.abs();
            let torque = s.received_torque - s.passed_torque - own;
            assert!(torque.abs() <= 1e-12 * s.received_torque.abs().max(1.0), "{}: {torque}", s.name);
        }
    }
}

/// P_source − P_sink = Σ parts, to 1e-9 of the source's power, drive and coast.
#[test]
fn power_lost_is_the_sum_of_the_parts() {
    let all = points(&ev_reducer());
    assert!(all.iter().any(|p| p.flow == PowerFlow::Coast) && all.iter().any(|p| p.flow == PowerFlow::Drive));
    for p in all {
        let parts = p.losses.total();
        let source = p.input_power.abs().max(p.output_power.abs());
        assert!((p.power_lost() - parts).abs() <= 1e-9 * source, "{} vs {parts}", p.power_lost());
        let stages: f64 = p.stages.iter().map(|s| s.mesh_loss + s.no_load).sum();
        let shafts: f64 = p.shafts.iter().map(|s| s.losses()).sum();
        let no_load: f64 = p.stages.iter().map(|s| s.no_load).sum();
        assert!((stages + shafts - no_load - parts).abs() <= 1e-9 * source);
    }
}

/// Speeds by the ratios: ω_lay = −ω_motor 23/68, ω_out = ω_motor (23/68)(20/78), to 1e-14.
#[test]
fn speeds_follow_the_ratios() {
    for p in points(&ev_reducer()) {
        let w = |n: &str| p.shafts.iter().find(|s| s.name == n).unwrap().speed;
        let (motor, lay, out) = (w("motor"), w("lay"), w("output"));
        assert!(motor > 0.0, "the input turns counter-clockwise");
        assert!((lay / motor + 23.0 / 68.0).abs() < 1e-14);
        assert!((out / motor - 23.0 / 68.0 * 20.0 / 78.0).abs() < 1e-14);
        assert!((p.output_speed - out.abs()).abs() <= 1e-14 * p.output_speed);
    }
}

/// The fixed point settles in a few passes (3–8), every point.
#[test]
fn the_fixed_point_settles_in_a_few_passes() {
    for p in points(&ev_reducer()) {
        assert!((3..=8).contains(&p.iterations), "{} passes", p.iterations);
    }
}

#[test]
#[ignore]
fn print_ev_reducer() {
    for p in points(&ev_reducer()) {
        println!(
            "{} T_in {:.4} n_in {:.3} P_in {:.3} T_out {:.4} P_out {:.3} eta {:.6} it {} loss {:?}",
            p.flow.name(),
            p.input_torque,
            p.input_speed * 30.0 / std::f64::consts::PI,
            p.input_power,
            p.output_torque,
            p.output_power,
            p.efficiency,
            p.iterations,
            p.losses
        );
        for s in &p.stages {
            println!(
                "  stage {} {:?} Td {:.4} Tn {:.4} eta {:.6} loss {:.3} noload {:.3}",
                s.name, s.driving, s.driving_torque, s.driven_torque, s.mesh_efficiency, s.mesh_loss, s.no_load
            );
        }
        for s in &p.shafts {
            println!(
                "  shaft {} w {:.3} in {:.4} out {:.4} seals {:.3}",
                s.name, s.speed, s.received_torque, s.passed_torque, s.seals
            );
            for b in &s.bearings {
                println!(
                    "    at {:.4} Fr {:.2} Fa {:.2} P0 {:.3} P1 {:.3}",
                    b.position, b.radial_load, b.axial_load, b.no_load, b.load
                );
            }
        }
    }
}
