//! Speed targets (issue 3), measured with divan: `cargo bench`.
//!
//! - one operating point, every law, both formulations, means to a relative tolerance of 1e-10 (target < 200 µs);
//! - a 10 000-point torque × speed sweep with three laws, the whole evaluation stage (target < 2 s on 2 cores);
//! - a whole run of the binary over a 200 × 200 map with one law (target < 20 s on 2 cores);
//! - the plain sweep's per-point cost and a whole run in memory (issue 47: `plain_sweep`).

use gearloss::efficiency::{mean_abs_mu, mean_efficiencies};

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

/// A spec scene of a drive with everything from its `operating` block on replaced by `tail`.
fn drive_spec(file: &str, tail: &str) -> gearloss::Scene {
    let text = std::fs::read_to_string(format!("{}/specs/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let head = &text[..text.find("    operating {").unwrap()];
    gearloss::check("bench.gear", &format!("{head}{tail}}}\n")).unwrap_or_else(|e| panic!("{e}"))
}

const EVERY_LAW: &str = "coulomb(mu = 0.05) benedict_kelley benedict_kelley_bernard xu smoothed_coulomb(mu = 0.05) \
    composite misharin odonoghue_cameron drozdov_gavrikov iso_14179_2 matsumoto";

/// Every law at one operating point: build, η̄ of both formulations (tolerance 1e-10) and, when asked,
/// the mean |μ| over A–E.
fn one_point(bencher: divan::Bencher, with_mean_mu: bool) {
    let scene = scene("302 N*m", "1500 rpm", EVERY_LAW).pair_alone().unwrap();
    let eval = gearloss::evaluate(&scene);
    let ctx = eval.law_context(eval.points[0].state);
    bencher.bench(|| {
        let mut sum = 0.0;
        for spec in &scene.friction {
            let Ok(law) = spec.build(&ctx) else { continue };
            if with_mean_mu {
                sum += mean_abs_mu(&ctx, law.as_ref()).value;
            }
            let [external, internal] = mean_efficiencies(&ctx, law.as_ref());
            sum += external.value + internal.value;
        }
        divan::black_box(sum)
    });
}

/// Target < 200 µs.
#[divan::bench]
fn one_point_all_laws_both_formulations(bencher: divan::Bencher) {
    one_point(bencher, false);
}

/// What a report row also shows: the mean |μ| of every law.
#[divan::bench]
fn one_point_all_laws_with_mean_mu(bencher: divan::Bencher) {
    one_point(bencher, true);
}

/// The evaluate stage on a 100 × 100 torque × speed sweep with three laws: every point streamed
/// (summary rows built, tally folded; the rows go nowhere here).
#[divan::bench(sample_count = 3, sample_size = 1)]
fn sweep_10000_points_three_laws(bencher: divan::Bencher) {
    let scene = scene("50..500 N*m count 100", "100..10000 rpm count 100", "coulomb(mu = 0.05) xu benedict_kelley")
        .pair_alone()
        .unwrap();
    let plan = gearloss::Plan::new(&scene.operating, None, &[]);
    bencher.bench(|| {
        let tally = gearloss::evaluate_sweep(&scene, &plan, &mut gearloss::evaluate::NoRecords, &gearloss::Quiet);
        divan::black_box(tally.expect("no writes").points)
    });
}

/// Issue 9's whole-run target: `gearloss run` on a 200 × 200 torque × speed map with one law, efficiency
/// only, records and report written (target < 20 s on 2 cores; peak memory < 300 MB is measured with
/// farm-bench, README "Sweeps at scale").
#[divan::bench(sample_count = 3, sample_size = 1)]
fn whole_run_200x200(bencher: divan::Bencher) {
    let dir = std::env::temp_dir().join(format!("gearloss-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = ALL_LAWS
        .replace("OP_TORQUE", "50..400 N*m count 200")
        .replace("OP_SPEED", "100..6000 rpm count 200")
        .replace("LAWS", "coulomb(mu = 0.04)")
        .replace("efficiency  friction_along_loa", "efficiency(formulations = [external])");
    let path = dir.join("map.gear");
    std::fs::write(&path, text).unwrap();
    bencher.bench(|| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_gearloss"))
            .arg("run")
            .arg(&path)
            .arg("--out")
            .arg(dir.join("out"))
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    });
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 47's guard: the plain sweep (a spur pair, one Coulomb law, both formulations, efficiency
/// only, no gearbox) that got 1.2× slower and 1.3× bigger in one round of work without anyone
/// asking for more. README "Sweeps at scale" has the whole-run figure; DEVELOPING.md "Speed" says
/// how to compare a change against the previous release.
mod plain_sweep {
    fn plain(torques: &str, speeds: &str) -> gearloss::Scene {
        let text = super::ALL_LAWS
            .replace("OP_TORQUE", torques)
            .replace("OP_SPEED", speeds)
            .replace("LAWS", "coulomb(mu = 0.05)")
            .replace("efficiency  friction_along_loa", "efficiency(formulations = [external, internal])");
        gearloss::check("plain.gear", &text).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The per-point cost: 400 points streamed (η̄ of both formulations to 1e-10, η(τ)'s range
    /// located, the summary rows built and the tally folded; the rows go nowhere), as items.
    #[divan::bench(sample_count = 10, sample_size = 1)]
    fn per_point_coulomb_both_formulations(bencher: divan::Bencher) {
        let scene = plain("50..400 N*m count 20", "100..3000 rpm count 20").pair_alone().unwrap();
        let plan = gearloss::Plan::new(&scene.operating, None, &[]);
        bencher.counter(divan::counter::ItemsCount::new(400usize)).bench(|| {
            let tally = gearloss::evaluate_sweep(&scene, &plan, &mut gearloss::evaluate::NoRecords, &gearloss::Quiet);
            divan::black_box(tally.expect("no writes").points)
        });
    }

    /// The whole run in memory on 40 × 40 points: the sweep, the records, the report (its 3 000
    /// kept rows), report.json written and read back, report.md and the plots.
    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn whole_run_in_memory_1600_points(bencher: divan::Bencher) {
        let scene = super::ALL_LAWS
            .replace("OP_TORQUE", "50..400 N*m count 40")
            .replace("OP_SPEED", "100..3000 rpm count 40")
            .replace("LAWS", "coulomb(mu = 0.05)")
            .replace("efficiency  friction_along_loa", "efficiency(formulations = [external, internal])");
        bencher.bench(|| divan::black_box(gearloss::run_to_files("plain.gear", &scene).expect("runs").files.len()));
    }
}

mod dynamics {
    use gearloss::dynamics::period_segments;
    use gearloss::dynamics::PeriodicResponse;
    use gearloss::dynamics::{integrate, Integrator};
    use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
    use gearloss::friction::Coulomb;
    use gearloss::geometry::OperatingState;

    /// FZG type C rectangular stiffness (N/m).
    fn rectangular() -> StiffnessModel {
        StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8)
    }

    fn fzg() -> gearloss::Scene {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_type_c.gear")).unwrap();
        gearloss::check("fzg", &text).unwrap()
    }

    fn with_system<R>(rpm: f64, f: impl FnOnce(&SdofSystem) -> R) -> R {
        let scene = fzg().pair_alone().unwrap();
        let eval = gearloss::evaluate(&scene);
        let law = Coulomb { mu: 0.08 };
        let ctx =
            eval.law_context(OperatingState { pinion_torque: 239.3, pinion_speed: rpm * std::f64::consts::PI / 30.0 });
        let sys =
            SdofSystem::new(ctx, Some(&law), DynamicFormulation::External, rectangular(), [3.45e-4, 15.24e-4], 0.05);
        f(&sys)
    }

    /// Exact propagator (segment exponentials and 200 periods of chaining), FZG at 1000 rpm. Target < 10 µs.
    #[divan::bench]
    fn exact_propagator_200_periods(bencher: divan::Bencher) {
        with_system(1000.0, |sys| {
            bencher.bench(|| {
                let segs = period_segments(sys).segments;
                let mut x = sys.static_state();
                for _ in 0..200 {
                    for s in &segs {
                        x = s.apply(&x);
                    }
                }
                divan::black_box(x)
            })
        });
    }

    /// Floquet: monodromy, multipliers and the periodic state. Target < 5 µs.
    #[divan::bench]
    fn floquet_periodic_state(bencher: divan::Bencher) {
        with_system(1000.0, |sys| bencher.bench(|| divan::black_box(Floquet::analyse(sys).periodic_state)));
    }

    fn ten_periods(sys: &SdofSystem) -> Vec<f64> {
        (0..=64).map(|i| 9.0 * sys.period + sys.period * i as f64 / 64.0).collect()
    }

    /// DOP853 with restarts, 10 periods, rtol 1e-10 (error ≤ 1e-8 of the peak-to-peak DTE, tested). Target < 15 ms.
    #[divan::bench(sample_count = 10)]
    fn dop853_nominal_1e_8(bencher: divan::Bencher) {
        with_system(1000.0, |sys| {
            let times = ten_periods(sys);
            let x0: [f64; 2] = sys.static_state().into();
            bencher.bench(|| divan::black_box(integrate(sys, Integrator::Dop853, 1e-10, x0, &times).unwrap().1))
        });
    }

    /// The issue-8 protocol against SciPy: FZG type C, 239.3 N·m, 1000 rpm, Coulomb μ 0.08 (external),
    /// ζ 0.05, 10 periods from the static deflection with restarts at every switch, error = max DTE
    /// error over the last period / DTE peak-to-peak. DOP853 at the loosest rtol of the ladder that
    /// reaches 1e-8 (checked before timing). SciPy's best (LSODA, same restarts): 0.19 s. Target ≥ 50×: < 3.8 ms.
    #[divan::bench(sample_count = 20)]
    fn scipy_protocol_dop853_1e_8(bencher: divan::Bencher) {
        use gearloss::dynamics::numerics::{reference, relative_error, study_times, LADDER};
        with_system(1000.0, |sys| {
            let times = study_times(sys.period);
            let x0 = sys.static_state();
            let exact = reference(sys, x0, &times);
            let rtol = LADDER
                .into_iter()
                .find(|r| {
                    let (s, _) = integrate(sys, Integrator::Dop853, *r, [x0[0], x0[1]], &times).unwrap();
                    relative_error(sys, &s, &exact) <= 1e-8
                })
                .expect("DOP853 reaches 1e-8 on the ladder");
            bencher
                .bench(|| divan::black_box(integrate(sys, Integrator::Dop853, rtol, [x0[0], x0[1]], &times).unwrap().1))
        });
    }

    /// The same protocol by the exact route (`reference_seconds` of the numerics study: segment
    /// exponentials, 10 periods, 129 output states). SciPy's best 0.19 s; target ≥ 10 000×: < 19 µs.
    #[divan::bench(sample_count = 100)]
    fn scipy_protocol_exact_route(bencher: divan::Bencher) {
        use gearloss::dynamics::numerics::{reference, study_times};
        with_system(1000.0, |sys| {
            let times = study_times(sys.period);
            let x0 = sys.static_state();
            bencher.bench(|| divan::black_box(reference(sys, x0, &times)))
        });
    }

    /// The stiff case, f_n/f_mesh ≈ 1000 (22.4 rpm), Radau5 at rtol 1e-12 (error ≤ 1e-6, tested). Target < 0.5 s.
    #[divan::bench(sample_count = 3)]
    fn radau5_stiff_1e_6(bencher: divan::Bencher) {
        with_system(22.4, |sys| {
            let times = ten_periods(sys);
            let x0: [f64; 2] = sys.static_state().into();
            bencher.bench(|| divan::black_box(integrate(sys, Integrator::Radau5, 1e-12, x0, &times).unwrap().1))
        });
    }

    /// The periodic response with every extremum located, means and spectrum integrated (external
    /// formulation, FZG at 1000 rpm, f_n/f_mesh ≈ 22). Target < 20 ms.
    #[divan::bench(sample_count = 20)]
    fn periodic_response_located_1000_rpm(bencher: divan::Bencher) {
        with_system(1000.0, |sys| {
            let fl = Floquet::analyse(sys);
            bencher.bench(|| divan::black_box(PeriodicResponse::compute(sys, &fl).map(|r| r.dte_peak_to_peak)))
        });
    }

    /// Spectral radius at 1000 speeds (external formulation). Target < 50 ms.
    #[divan::bench(sample_count = 10)]
    fn stability_map_1000_speeds(bencher: divan::Bencher) {
        let scene = fzg().pair_alone().unwrap();
        let eval = gearloss::evaluate(&scene);
        let law = Coulomb { mu: 0.08 };
        bencher.bench(|| {
            let mut max: f64 = 0.0;
            for i in 0..1000 {
                let rpm = 1000.0 + 59.0 * i as f64;
                let ctx = eval.law_context(OperatingState {
                    pinion_torque: 239.3,
                    pinion_speed: rpm * std::f64::consts::PI / 30.0,
                });
                let sys = SdofSystem::new(
                    ctx,
                    Some(&law),
                    DynamicFormulation::External,
                    rectangular(),
                    [3.45e-4, 15.24e-4],
                    0.05,
                );
                max = max.max(Floquet::analyse(&sys).spectral_radius);
            }
            divan::black_box(max)
        });
    }
}

/// The 6-DOF model (issue 11): FZG type C on bearings (specs/fzg_bearings.gear), Coulomb μ 0.08,
/// internal formulation (friction inside the system matrix: 4th-order Magnus on every segment).
mod six_dof {
    use gearloss::dynamics::numerics::{reference, relative_error, study_times, LADDER};
    use gearloss::dynamics::{integrate, Integrator};
    use gearloss::dynamics::{Bearing, SixDofSystem};
    use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
    use gearloss::friction::Coulomb;
    use gearloss::geometry::OperatingState;

    /// FZG type C rectangular stiffness (N/m).
    fn rectangular() -> StiffnessModel {
        StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8)
    }

    fn with_system<R>(rpm: f64, bearing: f64, f: impl FnOnce(&SixDofSystem) -> R) -> R {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_type_c.gear")).unwrap();
        let scene = gearloss::check("fzg", &text).unwrap().pair_alone().unwrap();
        let eval = gearloss::evaluate(&scene);
        let law = Coulomb { mu: 0.08 };
        let ctx =
            eval.law_context(OperatingState { pinion_torque: 239.3, pinion_speed: rpm * std::f64::consts::PI / 30.0 });
        let mesh =
            SdofSystem::new(ctx, Some(&law), DynamicFormulation::Internal, rectangular(), [3.45e-4, 15.24e-4], 0.05);
        let b = Bearing { loa: bearing, oloa: bearing, damping_ratio: 0.02 };
        f(&SixDofSystem::new(mesh, [0.59, 1.21], [b, b]))
    }

    /// Floquet for one operating point: monodromy, multipliers and the periodic state. Target < 200 µs.
    #[divan::bench]
    fn floquet_one_point(bencher: divan::Bencher) {
        with_system(1000.0, 5e8, |sys| bencher.bench(|| divan::black_box(Floquet::analyse(sys).periodic_state)));
    }

    /// The same without friction (A constant on every segment: the exact propagator), for comparison.
    #[divan::bench]
    fn floquet_one_point_base(bencher: divan::Bencher) {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_type_c.gear")).unwrap();
        let scene = gearloss::check("fzg", &text).unwrap().pair_alone().unwrap();
        let eval = gearloss::evaluate(&scene);
        let ctx = eval
            .law_context(OperatingState { pinion_torque: 239.3, pinion_speed: 1000.0 * std::f64::consts::PI / 30.0 });
        let mesh = SdofSystem::new(ctx, None, DynamicFormulation::Base, rectangular(), [3.45e-4, 15.24e-4], 0.05);
        let b = Bearing { loa: 5e8, oloa: 5e8, damping_ratio: 0.02 };
        let sys = SixDofSystem::new(mesh, [0.59, 1.21], [b, b]);
        bencher.bench(|| divan::black_box(Floquet::analyse(&sys).periodic_state));
    }

    /// A 1000-speed stability map (spectral radius), the scene parsed once. Target < 0.5 s.
    #[divan::bench(sample_count = 3)]
    fn stability_map_1000_speeds(bencher: divan::Bencher) {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_type_c.gear")).unwrap();
        let scene = gearloss::check("fzg", &text).unwrap().pair_alone().unwrap();
        let eval = gearloss::evaluate(&scene);
        let law = Coulomb { mu: 0.08 };
        let b = Bearing { loa: 5e8, oloa: 5e8, damping_ratio: 0.02 };
        bencher.bench(|| {
            let mut max: f64 = 0.0;
            for i in 0..1000 {
                let rpm = 1000.0 + 59.0 * i as f64;
                let ctx = eval.law_context(OperatingState {
                    pinion_torque: 239.3,
                    pinion_speed: rpm * std::f64::consts::PI / 30.0,
                });
                let mesh = SdofSystem::new(
                    ctx,
                    Some(&law),
                    DynamicFormulation::Internal,
                    rectangular(),
                    [3.45e-4, 15.24e-4],
                    0.05,
                );
                let sys = SixDofSystem::new(mesh, [0.59, 1.21], [b, b]);
                max = max.max(Floquet::analyse(&sys).spectral_radius);
            }
            divan::black_box(max)
        });
    }

    /// The stiff case, bearings 1e11 N/m (highest/lowest natural frequency ≈ 20): the best general
    /// integrator (DOP853) at the loosest rtol of the ladder that reaches 1e-6 relative DTE error over
    /// the numerics study's 10 periods (checked before timing). Target < 1 s.
    #[divan::bench(sample_count = 3)]
    fn stiff_bearings_dop853_1e_6(bencher: divan::Bencher) {
        with_system(1000.0, 1e11, |sys| {
            let times = study_times(sys.mesh.period);
            let x0 = sys.static_state();
            let exact = reference(sys, x0, &times);
            let rtol = LADDER
                .into_iter()
                .find(|r| {
                    let (s, _) = integrate(sys, Integrator::Dop853, *r, x0.into(), &times).unwrap();
                    relative_error(sys, &s, &exact) <= 1e-6
                })
                .expect("DOP853 reaches 1e-6 on the ladder");
            bencher.bench(|| divan::black_box(integrate(sys, Integrator::Dop853, rtol, x0.into(), &times).unwrap().1))
        });
    }
}

/// The thermal balance (issue 27) on `specs/fzg_c14_thermal.gear`: P_V(θ) is its one-stage drive's
/// whole loss with the oil read at θ (`evaluate::DriveLosses`).
mod thermal {
    use gearloss::evaluate::{drive_duty, DriveLosses};
    use gearloss::model::Formulation;

    fn scene() -> gearloss::Scene {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/fzg_c14_thermal.gear")).unwrap();
        gearloss::check("thermal", &text).unwrap()
    }

    /// The spec's first point: its pinion torque and speed.
    fn first_point(scene: &gearloss::Scene) -> (f64, f64) {
        (scene.operating.pinion_torque.values[0].value, scene.operating.pinion_speed.values[0].value)
    }

    /// One P_V(θ) as the balance reads it (`DriveLosses::total`): the losses' own cost, against
    /// which the balance is measured.
    #[divan::bench]
    fn losses_at_one_temperature(b: divan::Bencher) {
        let scene = scene();
        let losses = DriveLosses::new(&scene, scene.drive.as_ref().unwrap());
        let point = first_point(&scene);
        b.bench(|| losses.total(0, Formulation::External, point, 350.0));
    }

    /// θ* of one operating point (the P_Q-led secant, about eight P_V). Target: < 50 µs beyond the budget's own cost.
    #[divan::bench]
    fn balance_of_one_point(b: divan::Bencher) {
        let scene = scene();
        let losses = DriveLosses::new(&scene, scene.drive.as_ref().unwrap());
        let housing = scene.housing.clone().unwrap();
        let point = first_point(&scene);
        b.bench(|| gearloss::thermal::balance(|t| losses.total(0, Formulation::External, point, t), &housing));
    }

    /// The 51-minute, 9-step cycle's transient at two tolerances and its fixed-temperature energy,
    /// each P_V(θ) the scene's one-stage drive walked (the duty cycle a scene of one pair reports).
    /// Target < 5 ms.
    #[divan::bench(sample_count = 10, sample_size = 1)]
    fn duty_cycle_transient(b: divan::Bencher) {
        let scene = scene();
        let housing = scene.housing.clone().unwrap();
        let cycle = scene.duty_cycle.clone().unwrap();
        b.bench(|| drive_duty(&scene, scene.drive.as_ref().unwrap(), &housing, &cycle));
    }

    /// Issue 40: one step of 10⁶ h (120 N·m, 2500 rpm) with the scene's own P_V(θ): the step settles
    /// within hours and its rest is closed form (84 s before, marching to the end). Target < 10 ms.
    #[divan::bench(sample_count = 10, sample_size = 1)]
    fn duty_cycle_settled_million_hours(b: divan::Bencher) {
        let scene = scene();
        let housing = scene.housing.clone().unwrap();
        let mut cycle = scene.duty_cycle.clone().unwrap();
        cycle.steps = vec![gearloss::thermal::DutyStep { duration: 3.6e9, ..cycle.steps[1].clone() }];
        b.bench(|| drive_duty(&scene, scene.drive.as_ref().unwrap(), &housing, &cycle));
    }
}

mod teeth {
    use gearloss::geometry::teeth::PairStiffness;
    use gearloss::geometry::teeth::SERIES_POINTS;
    use gearloss::geometry::teeth::{LoadSharing, ReliefShape, Reliefs, TipRelief};

    fn pair(path: &str) -> (gearloss::Scene, gearloss::geometry::PairGeometry) {
        let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let scene = gearloss::check(path, &text).unwrap();
        let g = scene.gears.geometry().unwrap();
        (scene, g)
    }

    /// The whole job of the issue's target: the pair's PEM stiffness built from the teeth, K(s) at
    /// 256 positions of a cycle, and the STE at three torques with tip relief on both gears.
    fn job(scene: &gearloss::Scene, g: &gearloss::geometry::PairGeometry) -> f64 {
        let k = PairStiffness::new(g, &scene.gears.bodies()).unwrap();
        let s0 = k.position_at(0.0);
        let mut sum: f64 =
            (0..SERIES_POINTS).map(|i| k.mesh_at(s0 + k.base_pitch * i as f64 / SERIES_POINTS as f64)).sum();
        let relief = Some(TipRelief { amount: 10e-6, length: 1.8e-3, shape: ReliefShape::Linear });
        let sharing = LoadSharing { stiffness: k, reliefs: Reliefs([relief, relief]) };
        for t in [50.0, 135.0, 300.0] {
            sum += sharing.transmission_error(t, g.base_radius[0]).peak_to_peak();
        }
        sum
    }

    /// FZG C (spur). Target < 5 ms.
    #[divan::bench(sample_count = 20, sample_size = 1)]
    fn spur_stiffness_and_three_ste(b: divan::Bencher) {
        let (scene, g) = pair("specs/fzg_type_c.gear");
        b.bench(|| job(&scene, &g));
    }

    /// The metric helical pair. Target < 50 ms.
    #[divan::bench(sample_count = 10, sample_size = 1)]
    fn helical_stiffness_and_three_ste(b: divan::Bencher) {
        let (scene, g) = pair("specs/metric_helical.gear");
        b.bench(|| job(&scene, &g));
    }
}

/// Several stages (issue 41): the two-stage EV reducer (two meshes, six bearings, three seals,
/// injection, the fixed point). Targets: one operating point < 100 µs; its 41 × 30 map < 0.5 s; a
/// 10⁵-point sweep within 1.2× of ten times the 10⁴-point sweep (linear).
mod several_stages {
    use gearloss::evaluate::evaluate_drive_into;

    /// The EV reducer with `operating` and `analyses` swapped in.
    fn reducer(torques: &str, speeds: &str, analyses: &str) -> gearloss::Scene {
        reducer_of("ev_two_stage_reducer.gear", torques, speeds, analyses)
    }

    /// The reducer of spec `file` with `operating` and `analyses` swapped in.
    fn reducer_of(file: &str, torques: &str, speeds: &str, analyses: &str) -> gearloss::Scene {
        super::drive_spec(
            file,
            &format!("    operating {{ output_torque = {torques}  output_speed = {speeds}  oil_temperature = 80 degC }}\n    friction {{ iso_14179_2(x_l = 0.75) }}\n    analyses {{ {analyses} }}\n"),
        )
    }

    fn run(scene: &gearloss::Scene) -> usize {
        let drive = scene.drive.as_ref().unwrap();
        evaluate_drive_into(scene, drive, &mut std::io::sink()).unwrap().tally.rows
    }

    /// One operating point, its stages' meshes set up (both members driving) and the drive solved.
    /// Target < 100 µs.
    #[divan::bench]
    fn one_point(b: divan::Bencher) {
        let scene = reducer("800 N*m", "900 rpm", "efficiency(formulations = [external])");
        b.bench(|| run(&scene));
    }

    /// The same point with the lay shaft an elastic beam on three places, one sprung
    /// (specs/ev_reducer_three_bearing_lay_shaft.gear): the beam solved at every pass of the fixed
    /// point, every shaft's bending at the end. Target < 100 µs.
    #[divan::bench]
    fn one_point_lay_shaft_on_three_places(b: divan::Bencher) {
        let scene = reducer_of(
            "ev_reducer_three_bearing_lay_shaft.gear",
            "800 N*m",
            "900 rpm",
            "efficiency(formulations = [external])",
        );
        b.bench(|| run(&scene));
    }

    /// 10⁴ and 10⁵ points of that drive: the second within 1.2× of ten times the first (linear;
    /// records streamed to a sink, memory bounded).
    #[divan::bench(args = [100, 316], sample_count = 3, sample_size = 1)]
    fn sweep_lay_shaft_on_three_places(b: divan::Bencher, n: usize) {
        let scene = reducer_of(
            "ev_reducer_three_bearing_lay_shaft.gear",
            &format!("-1000..1000 N*m count {n}"),
            &format!("10..1500 rpm count {n}"),
            "efficiency(formulations = [external])",
        );
        b.bench(|| run(&scene));
    }

    /// The 41 × 30 map over output torque (drive and coast) × speed. Target < 0.5 s.
    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn map_41_by_30(b: divan::Bencher) {
        let scene = reducer(
            "500 N*m",
            "900 rpm",
            "efficiency(formulations = [external])  efficiency_map(output_torque = -1000..1000 N*m count 41, output_speed = 10..1500 rpm count 30)",
        );
        b.bench(|| gearloss::evaluate::evaluate_drive(&scene, scene.drive.as_ref().unwrap()).map.len());
    }

    /// 10⁴ and 10⁵ points (records written to a sink): the second within 1.2× of ten times the first.
    #[divan::bench(args = [100, 316], sample_count = 3, sample_size = 1)]
    fn sweep(b: divan::Bencher, n: usize) {
        let scene = reducer(
            &format!("-1000..1000 N*m count {n}"),
            &format!("10..1500 rpm count {n}"),
            "efficiency(formulations = [external])",
        );
        b.bench(|| run(&scene));
    }
}

/// A scene of one pair's map, its one-stage drive's: specs/fzg_c14_gearbox.gear (bearings, seals,
/// dip lubrication, two laws, both formulations) with a 40 × 40 map over pinion torque × speed, and
/// the budget beside the mesh at one point of its sweep. (The pair's report had a map of its own
/// until a scene of one pair ran as its one-stage drive; the drive's map is the one map.)
mod one_pair {
    fn scene() -> gearloss::Scene {
        super::drive_spec(
            "fzg_c14_gearbox.gear",
            "    operating { pinion_torque = 94.1 N*m  pinion_speed = 500 rpm  oil_temperature = 90 degC }\n    gearbox {\n        lubrication = dip(pinion_immersion = 41.2 mm, wheel_immersion = 59.2 mm, axis_height = 100 mm, housing_width = 200 mm)\n        pinion_shaft { bearing(type = cylindrical_roller, bore = 30 mm, outside = 90 mm, count = 2)  seal(diameter = 30 mm) }\n        wheel_shaft { bearing(type = cylindrical_roller, bore = 30 mm, outside = 90 mm, count = 2)  seal(diameter = 30 mm) }\n    }\n    friction { iso_14179_2(x_l = 0.846)  iso_14179_2 }\n    analyses { efficiency(formulations = [external, internal])  efficiency_map(pinion_torque = 10..400 N*m count 40, pinion_speed = 100..6000 rpm count 40) }\n",
        )
    }

    /// The same map as its one-stage drive evaluates it.
    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn map_40_by_40_as_its_one_stage_drive(b: divan::Bencher) {
        let scene = scene();
        b.bench(|| gearloss::evaluate::evaluate_drive(&scene, scene.drive.as_ref().unwrap()).map.len());
    }

    /// The budget beside the mesh at one point on the pair's own two-shaft statics
    /// (`losses::loss_budget`), the reference the one-stage drive's losses are tested against.
    #[divan::bench]
    fn budget_at_a_point_on_the_pairs_own_statics(b: divan::Bencher) {
        let scene = scene();
        let eval = gearloss::evaluate::prepare(
            &scene.pair_alone().unwrap(),
            &gearloss::evaluate::Plan::new(&scene.operating, None, &[]),
        );
        let state = gearloss::evaluate::state_at(&scene.operating, 0);
        let (g, gearbox) = (&eval.geometry, scene.gearbox.as_ref().unwrap());
        let oil = scene.mesh().budget_oil(&eval.tribology);
        b.bench(|| {
            gearloss::losses::loss_budget(gearbox, g, state.pinion_torque, state.pinion_speed, &oil).beside_mesh()
        });
    }
}

mod planetary {
    use gearloss::evaluate::evaluate_drive_into;

    /// specs/planetary_reducer.gear with one operating point and one law.
    fn reducer(torque: &str, speed: &str) -> gearloss::Scene {
        super::drive_spec(
            "planetary_reducer.gear",
            &format!("    operating {{ input_torque = {torque}  input_speed = {speed}  oil_temperature = 70 degC }}\n    friction {{ iso_14179_2 }}\n    analyses {{ efficiency(formulations = [external]) }}\n"),
        )
    }

    /// One operating point of the planetary reducer: the sun–planet pair (both roles) and the
    /// internal planet–ring pair set up, η₀ from both meshes, the planets' bearings and the carrier's
    /// churning, the fixed point, both meshes' validity. Target < 50 µs.
    #[divan::bench]
    fn one_point(b: divan::Bencher) {
        let scene = reducer("150 N*m", "3000 rpm");
        b.bench(|| {
            let drive = scene.drive.as_ref().unwrap();
            evaluate_drive_into(&scene, drive, &mut std::io::sink()).unwrap().tally.rows
        });
    }
}

mod drive_cycle {
    use gearloss::evaluate::drive_cycle::evaluate_cycle;

    /// specs/ev_reducer_wltc.gear, with its heat capacity (`transient`) or the oil fixed at 80 °C.
    fn wltc(transient: bool) -> gearloss::Scene {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/specs/ev_reducer_wltc.gear");
        let mut text = std::fs::read_to_string(path).unwrap();
        if !transient {
            text = text.replacen("\n                  heat_capacity = 12 kJ/K }", " }", 1);
        }
        gearloss::check(path, &text).unwrap_or_else(|e| panic!("{e}"))
    }

    fn run(scene: &gearloss::Scene) -> usize {
        let drive = scene.drive.as_ref().unwrap();
        evaluate_cycle(scene, drive, drive.cycle.as_ref().unwrap()).integrals.len()
    }

    /// WLTC 3b (1800 s) through the two-stage box at a fixed oil temperature: every piece at 3 and
    /// 5 Gauss nodes, the law's validity at each piece's middle, the map for the plot. Target < 0.3 s.
    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn wltc_fixed_oil(b: divan::Bencher) {
        let scene = wltc(false);
        b.bench(|| run(&scene));
    }

    /// The same with the sump's transient (Gauss collocation at 3 and 5 stages, side by side).
    /// Target < 1 s.
    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn wltc_transient(b: divan::Bencher) {
        let scene = wltc(true);
        b.bench(|| run(&scene));
    }
}

/// The record files' writing on their own: the plain sweep's 20 000 rows (100 × 100 points, two
/// formulations) streamed once, then written as CSV + JSON Lines or as Parquet into memory. The
/// million-point whole runs with their sizes are README "Record files"' figures (target: Parquet
/// no slower than CSV + JSON Lines).
mod record_files {
    use gearloss::evaluate::{ExtraColumns, RecordSink, SummaryRow};
    use gearloss::{RecordFiles, RecordFormats};

    /// Collects the rows of a sweep.
    struct Keep(Vec<SummaryRow>);

    impl RecordSink for Keep {
        fn write_rows(&mut self, rows: &[SummaryRow]) -> std::io::Result<()> {
            self.0.extend_from_slice(rows);
            Ok(())
        }
    }

    fn rows() -> (Vec<SummaryRow>, ExtraColumns) {
        let text = super::ALL_LAWS
            .replace("OP_TORQUE", "50..400 N*m count 100")
            .replace("OP_SPEED", "100..3000 rpm count 100")
            .replace("LAWS", "coulomb(mu = 0.05)")
            .replace("efficiency  friction_along_loa", "efficiency(formulations = [external, internal])");
        let scene = gearloss::check("plain.gear", &text).unwrap_or_else(|e| panic!("{e}")).pair_alone().unwrap();
        let plan = gearloss::Plan::new(&scene.operating, None, &[]);
        let mut keep = Keep(Vec::new());
        gearloss::evaluate_sweep(&scene, &plan, &mut keep, &gearloss::Quiet).unwrap();
        (keep.0, ExtraColumns::of(&scene))
    }

    fn write(formats: &str, bencher: divan::Bencher) {
        let (rows, extra) = rows();
        let formats: RecordFormats = formats.parse().unwrap();
        bencher.counter(divan::counter::ItemsCount::new(rows.len())).bench(|| {
            let mut files = RecordFiles::new(formats, &extra, |_| Ok(Vec::new())).unwrap();
            for block in rows.chunks(2048) {
                files.write_rows(block).unwrap();
            }
            files.finish().unwrap();
        });
    }

    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn csv_and_jsonl_20000_rows(bencher: divan::Bencher) {
        write("csv,jsonl", bencher);
    }

    #[divan::bench(sample_count = 5, sample_size = 1)]
    fn parquet_20000_rows(bencher: divan::Bencher) {
        write("parquet", bencher);
    }
}
