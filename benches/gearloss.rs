//! Speed targets (issue 3), measured with divan: `cargo bench`.
//!
//! - one operating point, every law, both formulations, means to a relative tolerance of 1e-10 (target < 200 µs);
//! - a 10 000-point torque × speed sweep with three laws, the whole evaluation stage (target < 2 s on 2 cores).

use gearloss::efficiency::{mean_abs_mu, mean_efficiency};
use gearloss::friction;
use gearloss::model::Formulation;

fn main() {
    divan::main();
}

const ALL_LAWS: &str = r#"
scene "bench" {
    gears {
        module = 4.5 mm  pressure_angle = 20 deg  center_distance = 91.5 mm  face_width = 14 mm
        pinion { teeth = 16  profile_shift = 0.1817  tip_diameter = 82.45 mm  material = steel
                 roughness_ra = 0.3 um  roughness_rq = 0.4 um  roughness_rz = 2 um }
        wheel  { teeth = 24  profile_shift = 0.1715  tip_diameter = 118.35 mm  material = steel
                 roughness_ra = 0.3 um  roughness_rq = 0.4 um  roughness_rz = 2 um }
    }
    material steel { youngs_modulus = 206 GPa  poisson_ratio = 0.3 }
    lubricant "oil" { dynamic_viscosity = 95 mPa*s  density = 880 kg/m^3  pressure_viscosity = 2e-8 1/Pa }
    operating { pinion_torque = OP_TORQUE  pinion_speed = OP_SPEED }
    friction { LAWS }
    analyses { efficiency  friction_along_loa }
}
"#;

fn scene(torque: &str, speed: &str, laws: &str) -> gearloss::Scene {
    let text = ALL_LAWS.replace("OP_TORQUE", torque).replace("OP_SPEED", speed).replace("LAWS", laws);
    gearloss::check("bench.gear", &text).unwrap_or_else(|e| panic!("{e}"))
}

const EVERY_LAW: &str = "coulomb(mu = 0.05) benedict_kelley benedict_kelley_bernard xu smoothed_coulomb(mu = 0.05) \
    composite misharin odonoghue_cameron drozdov_gavrikov iso_14179_2 matsumoto";

/// Every law at one operating point: build, mean |μ| and η̄ for both formulations (tolerance 1e-10).
#[divan::bench]
fn one_point_all_laws_both_formulations(bencher: divan::Bencher) {
    let scene = scene("302 N*m", "1500 rpm", EVERY_LAW);
    let eval = gearloss::evaluate(&scene);
    let ctx = eval.law_context(eval.points[0].state);
    bencher.bench(|| {
        let mut sum = 0.0;
        for spec in &scene.friction {
            let law = friction::build(spec, &ctx);
            sum += mean_abs_mu(&ctx, law.as_ref()).value;
            for f in [Formulation::External, Formulation::Internal] {
                sum += mean_efficiency(&ctx, law.as_ref(), f).value;
            }
        }
        divan::black_box(sum)
    });
}

/// The evaluate stage on a 100 × 100 torque × speed sweep with three laws.
#[divan::bench(sample_count = 3, sample_size = 1)]
fn sweep_10000_points_three_laws(bencher: divan::Bencher) {
    let scene = scene("50..500 N*m count 100", "100..10000 rpm count 100", "coulomb(mu = 0.05) xu benedict_kelley");
    bencher.bench(|| divan::black_box(gearloss::evaluate(&scene).points.len()));
}
