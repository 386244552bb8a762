//! Helical pairs (He & Singh), the physics: efficiency along the contact lines against ISO/TR
//! 14179-2 and an independent integration, effective stiffness, Floquet stability and the spur limit.

use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
use gearloss::efficiency::{mean_efficiency, ohlendorf_loss_factor};
use gearloss::friction::Coulomb;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::{reduced_modulus, Sharing};
use gearloss::geometry::{OperatingState, PairGeometry, PairInput};
use gearloss::model::Formulation::{External, Internal};

const LBF_IN: f64 = 4.448_221_615_260_5 * 0.0254;
/// J_p, J_g of the NASA-ART pair (8.33e-3 and 1.64e-2 lb·s²·in) in kg·m².
const J: [f64; 2] = [8.33e-3 * LBF_IN, 1.64e-2 * LBF_IN];
/// The stiffness density of specs/nasa_art_helical.gear (f_n = 9.5 f_mesh at 1000 rpm).
const K: f64 = 5.676e9;

fn rpm(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

fn ctx(g: &PairGeometry, speed_rpm: f64) -> LawContext<'_> {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: 2000.0 * LBF_IN, pinion_speed: rpm(speed_rpm) },
        tribology: scene.mesh().tribology(reduced_modulus([206e9; 2], [0.3; 2])),
        sharing: Sharing::Equal,
    }
}

fn system<'a>(c: LawContext<'a>, law: Option<&'a dyn FrictionLaw>, f: DynamicFormulation, zeta: f64) -> SdofSystem<'a> {
    let k = StiffnessModel::per_length(K, c.geometry);
    SdofSystem::new(c, law, f, k, J, zeta)
}

pub(crate) fn system_at<'a>(
    g: &'a PairGeometry,
    speed_rpm: f64,
    law: Option<&'a dyn FrictionLaw>,
    f: DynamicFormulation,
) -> SdofSystem<'a> {
    system(ctx(g, speed_rpm), law, f, 0.0)
}

/// He & Singh's statement after Fig. 6: f_n = 9.5 f_mesh at 1000 rpm (the spec's k, to 1e-4).
#[test]
fn natural_frequency_is_9_5_mesh_frequencies() {
    let g = crate::helical::nasa_art(21.5);
    let sys = system(ctx(&g, 1000.0), None, DynamicFormulation::Base, 0.0);
    let ratio = sys.natural_frequency() / (1000.0 / 60.0 * 25.0);
    assert!((ratio - 9.5).abs() < 1e-3, "f_n/f_mesh = {ratio}");
}

/// Figs 8–9: undamped, μ = 0.2: stable at 18 000 rpm (ρ = 1 to 1e-9), unstable at 19 000 rpm
/// (ρ > 1.01), in the exact internal formulation and in the eq-25 chord variant.
#[test]
fn stable_at_18000_unstable_at_19000_rpm() {
    let g = crate::helical::nasa_art(21.5);
    let law = Coulomb { mu: 0.2 };
    for f in [DynamicFormulation::Internal, DynamicFormulation::InternalChord] {
        let c18 = ctx(&g, 18000.0);
        let c19 = ctx(&g, 19000.0);
        let rho18 = Floquet::analyse(&system(c18, Some(&law), f, 0.0)).spectral_radius;
        let rho19 = Floquet::analyse(&system(c19, Some(&law), f, 0.0)).spectral_radius;
        assert!((rho18 - 1.0).abs() < 1e-9, "{f:?}: ρ(18000) = {rho18}");
        assert!(rho19 > 1.01, "{f:?}: ρ(19000) = {rho19}");
    }
}

/// Figs 4–5 with Table 1's geometry (β_b = 21.5°): at μ = 0, K_e = k cos²β_b L(t) is a symmetric
/// trapezoid of four linear pieces (slopes +s, 0, −s, 0, to 1e-9 s); at μ = 0.4 the internal K_e has
/// six pieces whose slope breaks at the two extra break times (the pitch-line passages of region
/// 1→2 and 4→5), each a jump of more than 1 % of s; found from the geometry, never from the table.
#[test]
fn effective_stiffness_pieces_match_figs_4_and_5() {
    let g = crate::helical::nasa_art(crate::helical::reference_for_base(21.5));
    let c = ctx(&g, 1000.0);
    let law = Coulomb { mu: 0.4 };
    let base = system(c, None, DynamicFormulation::Base, 0.0);
    let internal = system(c, Some(&law), DynamicFormulation::Internal, 0.0);
    let t = base.period;
    let k_e = |s: &SdofSystem, tau: f64| -s.matrices(tau * t).0[1][0] * s.equivalent_mass;
    let slope = |s: &SdofSystem, a: f64, b: f64| (k_e(s, b) - k_e(s, a)) / (b - a);
    // μ = 0: merge segments of equal slope.
    let breaks = g.cycle_break_times(&[]);
    assert_eq!(breaks.len() - 1, 6, "six regions with the pitch passages: {breaks:?}");
    let slopes: Vec<f64> =
        breaks.windows(2).map(|w| slope(&base, w[0] + 0.1 * (w[1] - w[0]), w[0] + 0.9 * (w[1] - w[0]))).collect();
    let s = slopes.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut pieces: Vec<f64> = Vec::new();
    // Rotate so that the cycle starts at a slope change (the pieces wrap around τ = 0).
    for x in &slopes {
        if pieces.last().is_none_or(|p| (p - x).abs() > 1e-9 * s) {
            pieces.push(*x);
        }
    }
    if pieces.len() > 1 && (pieces[0] - pieces[pieces.len() - 1]).abs() <= 1e-9 * s {
        pieces.pop();
    }
    assert_eq!(pieces.len(), 4, "μ = 0 pieces {pieces:?}");
    let mut sorted = pieces.clone();
    sorted.sort_by(f64::total_cmp);
    assert!((sorted[0] + s).abs() < 1e-9 * s && (sorted[3] - s).abs() < 1e-9 * s, "{sorted:?}");
    assert!(sorted[1].abs() < 1e-9 * s && sorted[2].abs() < 1e-9 * s, "{sorted:?}");
    // μ = 0.4: at every one of the six breaks the one-sided slopes differ.
    let h = 1e-7;
    for &b in &breaks[1..breaks.len() - 1] {
        let left = slope(&internal, b - 2.0 * h, b - h);
        let right = slope(&internal, b + h, b + 2.0 * h);
        assert!((left - right).abs() > 0.01 * s, "no slope break at τ = {b}: {left} vs {right}");
    }
    // And inside a piece K_e is quadratic, not linear: the midpoint lies off the chord somewhere.
    let bowed = breaks.windows(2).any(|w| {
        let (a, b) = (w[0] + 1e-9, w[1] - 1e-9);
        let mid = k_e(&internal, 0.5 * (a + b));
        (mid - 0.5 * (k_e(&internal, a) + k_e(&internal, b))).abs() > 1e-6 * k_e(&internal, a)
    });
    assert!(bowed, "the exact K_e with friction is piecewise quadratic (physics notes)");
}

/// The spur limit: β = 1e-7 rad gives the spur pair's mean efficiencies (to 1e-9) and its
/// dynamics (ρ and DTE to 1e-6) on FZG type C with the same stiffness density.
#[test]
fn tiny_helix_angle_reproduces_the_spur_pair() {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let spur_in = scene.gears.pair_input();
    let helical_in = PairInput { helix_angle: 1e-7, ..spur_in };
    let spur = PairGeometry::compute(&spur_in).unwrap();
    let helical = PairGeometry::compute(&helical_in).unwrap();
    assert!(helical.is_helical());
    let state = OperatingState { pinion_torque: 239.3, pinion_speed: rpm(1000.0) };
    let mk = |g| LawContext { state, ..ctx(g, 1000.0) };
    let law = Coulomb { mu: 0.08 };
    for f in [External, Internal] {
        let a = mean_efficiency(&mk(&spur), &law, f).value;
        let b = mean_efficiency(&mk(&helical), &law, f).value;
        assert!((a - b).abs() < 1e-9, "{f:?}: spur {a} helical {b}");
    }
    let k = 1.4e10;
    let fzg_j = [3.45e-4, 15.24e-4];
    for f in [DynamicFormulation::Base, DynamicFormulation::Internal] {
        let l: Option<&dyn FrictionLaw> = if f == DynamicFormulation::Base { None } else { Some(&law) };
        let s1 = SdofSystem::new(mk(&spur), l, f, StiffnessModel::per_length(k, &spur), fzg_j, 0.05);
        let s2 = SdofSystem::new(mk(&helical), l, f, StiffnessModel::per_length(k, &helical), fzg_j, 0.05);
        let (f1, f2) = (Floquet::analyse(&s1), Floquet::analyse(&s2));
        assert!((f1.spectral_radius - f2.spectral_radius).abs() < 1e-6, "{f:?}");
        let x1 = f1.periodic_state.unwrap()[0];
        let x2 = f2.periodic_state.unwrap()[0];
        assert!((x1 - x2).abs() < 1e-6 * x1.abs(), "{f:?}: {x1} vs {x2}");
    }
}

/// Physics notes: under constant stiffness density 1 − μ H_V is not the helical mean. The loss
/// ratio (1 − η̄_ext)/(μ H_V) is ≈ 1.18 at β = 15° for the NASA-ART transverse geometry (between 1.1
/// and 1.25), tends to 1 as β → 0 (to 1e-3 at 0.01°), and when ε_β is an integer L(t) is constant
/// and the loss is the uniform-load closed form μ (1/r_b1 + 1/r_b2)/cos β_b · (AP² + PE²)/(2 AE)
/// (to 1e-9 relative).
#[test]
fn ohlendorf_is_the_slice_model_not_constant_density() {
    let law = Coulomb { mu: 0.05 };
    let loss = |g: &PairGeometry| 1.0 - mean_efficiency(&ctx(g, 1000.0), &law, External).value;
    let ratio = |g: &PairGeometry| loss(g) / (0.05 * ohlendorf_loss_factor(&ctx(g, 1000.0)));
    let r15 = ratio(&crate::helical::nasa_art(15.0));
    assert!(r15 > 1.1 && r15 < 1.25, "β = 15°: {r15}");
    let r_small = ratio(&crate::helical::nasa_art(0.01));
    assert!((r_small - 1.0).abs() < 1e-3, "β = 0.01°: {r_small}");
    // Face width for ε_β = 1 at β = 15°: b = π m_n / sin β.
    let g15 = crate::helical::nasa_art(15.0);
    let b = std::f64::consts::PI * g15.module / 15f64.to_radians().sin();
    let input = PairInput {
        module: g15.module,
        pressure_angle: g15.pressure_angle,
        helix_angle: g15.helix_angle,
        teeth: [25, 31],
        profile_shift: [0.0, 0.0],
        tip_diameter: [Some(3.38 * 25.4e-3), Some(4.13 * 25.4e-3)],
        center_distance: Some(3.5 * 25.4e-3),
        face_width: b,
        internal: false,
    };
    let g1 = PairGeometry::compute(&input).unwrap();
    assert!((g1.overlap_ratio - 1.0).abs() < 1e-12);
    let spread =
        (0..100).map(|i| g1.contact_length(i as f64 / 100.0)).fold((f64::MAX, 0.0f64), |a, l| (a.0.min(l), a.1.max(l)));
    assert!(spread.1 - spread.0 < 1e-12, "L(t) constant at ε_β = 1: {spread:?}");
    let p = g1.points;
    let closed = 0.05 * (1.0 / g1.base_radius[0] + 1.0 / g1.base_radius[1]) / g1.base_helix_angle.cos()
        * ((p.p - p.a).powi(2) + (p.e - p.p).powi(2))
        / (2.0 * (p.e - p.a));
    assert!((loss(&g1) / closed - 1.0).abs() < 1e-9, "{} vs {closed}", loss(&g1));
}

/// Energy balance along the lines: the external efficiency is 1 − ∫|μ| w v_s dl/(T_p ω1); with
/// Coulomb μ its mean from the line quadrature equals the independent slice-by-slice integral
/// over z of the spur-like contacts (100 × 100 Gauss–Legendre over z and τ, to 1e-9).
#[test]
fn external_mean_equals_an_independent_double_integral() {
    let g = crate::helical::nasa_art(21.5);
    let c = ctx(&g, 1000.0);
    let mu = 0.07;
    let law = Coulomb { mu };
    let eta = mean_efficiency(&c, &law, External).value;
    // Independent: P_f(τ) = μ w ω1 (1 + 1/i) ∫ |u − P| dl, w = F_bn / L(τ); the integral over each
    // line in u in closed form; the mean over τ by composite Gauss–Legendre between the breaks.
    let (x, wt) = gearloss::numerics::gauss_legendre(20);
    let breaks = g.cycle_break_times(&[]);
    let fbn = g.normal_load(&c.state);
    let mut loss = 0.0;
    for w in breaks.windows(2) {
        for (xi, wi) in x.iter().zip(&wt) {
            let tau = w[0] + (w[1] - w[0]) * xi;
            let lines = g.contact_lines(tau);
            let l: f64 = lines.iter().map(|l| l.length).sum();
            let mut abs_s = 0.0;
            for line in lines.iter() {
                let (a, b) = (line.u[0] - g.points.p, line.u[1] - g.points.p);
                // ∫ |s| ds from a to b, divided by sin β_b for dl.
                let prim = |s: f64| 0.5 * s * s.abs();
                abs_s += (prim(b) - prim(a)) / g.base_helix_angle.sin();
            }
            let p = mu * fbn / l * c.state.pinion_speed * (1.0 + 1.0 / g.gear_ratio) * abs_s;
            loss += wi * (w[1] - w[0]) * p;
        }
    }
    let independent = 1.0 - loss / (c.state.pinion_torque * c.state.pinion_speed);
    assert!((eta - independent).abs() < 1e-9, "{eta} vs {independent}");
}

/// E' of a scene's two materials.
fn scene_modulus(scene: &gearloss::Scene) -> f64 {
    let (p, w) = (&scene.gears.pinion.material, &scene.gears.wheel.material);
    reduced_modulus(
        [p.youngs_modulus.value.value, w.youngs_modulus.value.value],
        [p.poisson_ratio.value, w.poisson_ratio.value],
    )
}

/// Issue 46: a helical pair's contact table is the efficiency's own contact model. At every row of
/// every operating point of specs/metric_helical.gear, the table's w, p_H and b_H equal the state
/// the laws read ([`LawContext::contact_at`]: the mean load per unit line length F_bn / L̄, built
/// here from the scene, not from the report), to 1e-12 relative, and each law's μ in the friction
/// table is that law's μ at that state (1e-12). Spur loads (1/n of F_bn/b, jumps at B and D) would
/// miss by 30 % or more.
#[test]
fn helical_contact_table_is_the_efficiency_contact_model() {
    use gearloss::report::friction::MuValue;
    let scene = crate::scene(&crate::root().join("specs/metric_helical.gear"));
    let report = gearloss::report_of(&scene);
    let g = scene.gears.geometry().unwrap();
    let e_r = scene_modulus(&scene);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1e-300);
    let l_bar = g.mean_contact_length();
    assert!(!report.operating_points.is_empty());
    for op in &report.operating_points {
        let state = OperatingState { pinion_torque: op.pinion_torque.si(), pinion_speed: op.pinion_speed.si() };
        let ctx = LawContext { geometry: &g, state, tribology: scene.mesh().tribology(e_r), sharing: Sharing::Equal };
        let f_bn = g.normal_load(&state);
        for (i, row) in op.contact.iter().enumerate() {
            let c = ctx.contact_at(row.distance_from_t1.si());
            assert!(close(row.load_per_width.si(), c.load_per_width), "w at row {i}");
            assert!(close(row.load_per_width.si(), f_bn / l_bar), "w = F_bn/L̄ at row {i}");
            assert!(close(row.hertz_pressure.si(), c.hertz_pressure), "p_H at row {i}");
            assert!(close(row.hertz_half_width.si(), c.hertz_half_width), "b_H at row {i}");
            for (law, spec) in op.friction.iter().zip(&scene.friction) {
                let built = spec.build(&ctx).unwrap();
                if let MuValue::Value(mu) = law.mu_along_loa[i].mu {
                    assert!(close(mu.0, built.mu(&c)), "μ of {} at row {i}: {} vs {}", law.label, mu.0, built.mu(&c));
                }
            }
        }
    }
}

/// Issue 46: with the law `iso_14179_2` on a helical pair, the whole loss is the standard's own:
/// the drive row's mesh loss is P_in μ_mZ H_V and its total that plus the pair's own budget beside
/// the mesh (`pair_alone`: its gearbox on its own two shafts) (specs/helical_gearbox.gear, every
/// record, 1e-12 relative), μ_mZ read from the law built here at the record's point and H_V from
/// Ohlendorf's formula; the line integral (constant stiffness density) stays in the pair's record,
/// 10–25 % higher.
#[test]
fn iso_total_of_a_helical_pair_is_the_standards_own() {
    let scene = crate::scene(&crate::root().join("specs/helical_gearbox.gear"));
    let report = gearloss::report_of(&scene);
    let rows = crate::pair_alone::DriveRows::of(&scene);
    let alone = crate::pair_alone::PairAlone::new(&scene);
    let g = scene.gears.geometry().unwrap();
    let e_r = scene_modulus(&scene);
    assert!(!report.efficiency.is_empty());
    for e in &report.efficiency {
        assert_eq!(e.law, gearloss::friction::LawId::Iso14179_2);
        let state = OperatingState { pinion_torque: e.pinion_torque.si(), pinion_speed: e.pinion_speed.si() };
        let ctx = LawContext { geometry: &g, state, tribology: scene.mesh().tribology(e_r), sharing: Sharing::Equal };
        let law = scene.friction[0].build(&ctx).unwrap();
        let mu = law.mu(&ctx.contact_at(g.points.e)).abs();
        let input = state.pinion_torque * state.pinion_speed;
        let iso = input * mu * ohlendorf_loss_factor(&ctx);
        let k = rows.find((e.torque_index, e.speed_index), 0, e.formulation);
        let mesh = rows.value(k, "meshes_W");
        assert!((mesh - iso).abs() <= 1e-12 * iso, "mesh {mesh} vs {iso}");
        let [_, beside] = alone.losses((0, e.formulation), (state.pinion_torque, state.pinion_speed));
        let total = rows.value(k, "total_W");
        assert!(((iso + beside) - total).abs() <= 1e-12 * total, "total {total} vs {iso} + {beside}");
        let ratio = e.power_loss.si() / iso;
        assert!((1.1..1.25).contains(&ratio), "line integral / ISO = {ratio}");
    }
}

/// Issue 46: the efficiency map of a helical gearbox with `iso_14179_2` charges the standard's mesh
/// loss too: every cell of its `loss_map.csv` has mesh loss = P_in μ_mZ H_V (μ_mZ from the law
/// built here at the cell's point) and total = mesh + parts, both to the CSV's ten digits (1e-9).
#[test]
fn helical_iso_map_charges_the_standards_mesh_loss() {
    let path = crate::root().join("specs/helical_gearbox.gear");
    let text = std::fs::read_to_string(&path).unwrap().replace(
        "efficiency(formulations = [external])",
        "efficiency(formulations = [external])\n        efficiency_map(pinion_torque = 50..400 N*m count 4, pinion_speed = 500..3000 rpm count 4)",
    );
    let scene = gearloss::check("specs/helical_gearbox.gear", &text).unwrap();
    // The scene's map: its one-stage drive's loss map (its meshes' loss is the pair's mesh loss).
    let files = gearloss::run_to_files("specs/helical_gearbox.gear", &text).unwrap().files;
    let csv = &files.iter().find(|(n, _)| n == "loss_map.csv").expect("a map").1;
    let g = scene.gears.geometry().unwrap();
    let e_r = scene_modulus(&scene);
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (t_at, n_at, mesh_at, total_at) =
        (col("pinion_torque_N_m"), col("pinion_speed_rad_s"), col("meshes_W"), col("total_loss_W"));
    let parts: Vec<usize> = ["gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"]
        .iter()
        .filter_map(|p| header.iter().position(|h| h == p))
        .collect();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
    let mut cells = 0;
    for line in csv.lines().skip(1) {
        // The law's label is quoted and holds no comma here.
        let v: Vec<&str> = line.split(',').collect();
        let x = |i: usize| v[i].parse::<f64>().unwrap_or(0.0);
        let state = OperatingState { pinion_torque: x(t_at), pinion_speed: x(n_at) };
        let ctx = LawContext { geometry: &g, state, tribology: scene.mesh().tribology(e_r), sharing: Sharing::Equal };
        let mu = scene.friction[0].build(&ctx).unwrap().mu(&ctx.contact_at(g.points.e)).abs();
        let iso = state.pinion_torque * state.pinion_speed * mu * ohlendorf_loss_factor(&ctx);
        assert!(close(x(mesh_at), iso), "mesh {} vs ISO {iso}", x(mesh_at));
        let sum: f64 = x(mesh_at) + parts.iter().map(|i| x(*i)).sum::<f64>();
        assert!(close(x(total_at), sum), "total {} vs {sum}", x(total_at));
        cells += 1;
    }
    assert_eq!(cells, 16);
}
