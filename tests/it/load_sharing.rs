//! `load_sharing = stiffness`: the contacts the friction laws and the efficiency read carry each
//! pair's own share of the load, from the potential-energy stiffness and the tip relief, checked
//! against the stiffness directly, the balance of forces and an independent integral of the loss.

use gearloss::efficiency::{mean_efficiency, Formulation};
use gearloss::friction::Coulomb;
use gearloss::friction::LawContext;
use gearloss::geometry::teeth::{Bodies, PairStiffness};
use gearloss::geometry::teeth::{LoadSharing, ReliefShape, Reliefs, TipRelief};
use gearloss::geometry::Sharing;
use gearloss::geometry::{Mesh, LINE_NODES};
use gearloss::geometry::{OperatingState, PairGeometry};
use gearloss::numerics::integrate;

fn steel() -> Bodies {
    Bodies { young: [206e9; 2], poisson: [0.3; 2], root_radius: [None; 2], bore_radius: [None; 2] }
}

fn geometry(path: &str) -> PairGeometry {
    crate::scene(&crate::root().join(path)).gears.geometry().unwrap()
}

fn model(g: &PairGeometry, relief: Option<f64>) -> LoadSharing {
    let r = relief.map(|amount| TipRelief { amount, length: 1.8e-3, shape: ReliefShape::Linear });
    LoadSharing { stiffness: PairStiffness::new(g, &steel()).unwrap(), reliefs: Reliefs([r, r]) }
}

const STATE: OperatingState = OperatingState { pinion_torque: 135.0, pinion_speed: 100.0 };

fn mesh<'a>(g: &'a PairGeometry, sharing: Sharing<'a>) -> Mesh<'a> {
    Mesh { pair: g, state: STATE, reduced_modulus: 226.4e9, sharing }
}

/// Spur pair without relief: at every instant each contact's share (law and balance alike) is
/// k_j / Σ k of the pairs in contact, read from the stiffness directly, and the shares add to one
/// (1e-12).
#[test]
fn spur_shares_follow_the_stiffness() {
    let g = geometry("specs/fzg_type_c.gear");
    let m = model(&g, None);
    let k = &m.stiffness;
    for i in 0..200 {
        let tau = (i as f64 + 0.37) / 200.0;
        let contacts = mesh(&g, Sharing::Stiffness(&m)).contacts_at(tau);
        let q: Vec<f64> = contacts.iter().map(|c| c.u - g.points.a).collect();
        let total: f64 = q.iter().map(|q| k.pair_at(*q)).sum();
        for (c, q) in contacts.iter().zip(&q) {
            let expected = k.pair_at(*q) / total;
            assert!((c.force_share - expected).abs() < 1e-12, "τ = {tau}: {} vs {expected}", c.force_share);
            assert_eq!(c.load_share, c.force_share);
        }
        let sum: f64 = contacts.iter().map(|c| c.force_share).sum();
        assert!((sum - 1.0).abs() < 1e-12, "τ = {tau}: Σ = {sum}");
    }
}

/// With 20 µm × 1.8 mm linear relief on both gears: the shares still add to one (1e-12); a pair
/// entering at A or leaving at E carries less than the equal half (it enters relieved) and the
/// single pair at the pitch point carries everything.
#[test]
fn relief_unloads_the_pairs_at_the_ends_of_the_path() {
    let g = geometry("specs/fzg_type_c.gear");
    let m = model(&g, Some(20e-6));
    for i in 0..200 {
        let tau = (i as f64 + 0.37) / 200.0;
        let sum: f64 = mesh(&g, Sharing::Stiffness(&m)).contacts_at(tau).iter().map(|c| c.force_share).sum();
        assert!((sum - 1.0).abs() < 1e-12, "τ = {tau}: Σ = {sum}");
    }
    let at = |u: f64| mesh(&g, Sharing::Stiffness(&m)).contact_at(u);
    let entering = at(g.points.a + 1e-9);
    let leaving = at(g.points.e - 1e-9);
    assert_eq!((entering.pairs_in_contact, leaving.pairs_in_contact), (2, 2));
    assert!(entering.load_share < 0.1 && leaving.load_share < 0.1, "{} {}", entering.load_share, leaving.load_share);
    assert!(entering.load_share >= 0.0 && leaving.load_share >= 0.0);
    let pitch = at(g.points.p);
    assert_eq!(pitch.pairs_in_contact, 1);
    assert!((pitch.load_share - 1.0).abs() < 1e-12);
}

/// Coulomb friction, spur pair, no relief: the external formulation's loss 1 − η̄ equals
/// μ (1/r_b1 + 1/r_b2) ∫₀¹ Σ_j w_j |s_j| dτ with w_j = k(q_j)/Σk, integrated here from the
/// stiffness alone (pairs at q_j = (τ + j) p_b, breaks where a pair enters, leaves or passes P):
/// 1e-9 relative. The shares by stiffness put more load near P, where sliding is slow, so the
/// loss is below equal sharing's.
#[test]
fn coulomb_loss_with_stiffness_sharing_matches_an_independent_integral() {
    let g = geometry("specs/fzg_type_c.gear");
    let m = model(&g, None);
    let k = &m.stiffness;
    let (pb, path, to_p) = (g.base_pitch, g.points.e - g.points.a, g.points.p - g.points.a);
    let pairs = |tau: f64| (0..4).map(move |j| (tau + j as f64) * pb).filter(move |q| *q < path);
    let integrand = |tau: f64| {
        let total: f64 = pairs(tau).map(|q| k.pair_at(q)).sum();
        pairs(tau).map(|q| k.pair_at(q) / total * (q - to_p).abs()).sum::<f64>()
    };
    let mut breaks = vec![0.0, 1.0];
    for x in [path, to_p] {
        breaks.extend((0..4).map(|j| x / pb - j as f64).filter(|t| *t > 0.0 && *t < 1.0));
    }
    breaks.sort_by(f64::total_cmp);
    let mu = 0.04;
    let expected = mu * (1.0 / g.base_radius[0] + 1.0 / g.base_radius[1]) * integrate(integrand, &breaks, 1e-13).value;
    let law = Coulomb { mu };
    let ctx = |sharing| LawContext { geometry: &g, state: STATE, tribology: Default::default(), sharing };
    let stiff = 1.0 - mean_efficiency(&ctx(Sharing::Stiffness(&m)), &law, Formulation::External).value;
    assert!((stiff / expected - 1.0).abs() < 1e-9, "{stiff} vs {expected}");
    let equal = 1.0 - mean_efficiency(&ctx(Sharing::Equal), &law, Formulation::External).value;
    assert!(stiff < equal, "{stiff} vs equal {equal}");
}

/// Helical pairs (with and without relief): the nodes of the contact lines carry line loads that
/// add up to the normal load, Σ w dl / F_bn = Σ force shares = 1: 1e-6 with the rule the efficiency
/// uses and 1e-10 with the doubled rule its error estimate compares against (the lines are cut where
/// the relief bends the load, so each Gauss rule meets smooth pieces; equal sharing's is exact).
#[test]
fn helical_line_loads_carry_the_normal_load() {
    for p in ["specs/metric_helical.gear", "specs/nasa_art_helical.gear"] {
        let g = geometry(p);
        for relief in [None, Some(10e-6)] {
            let mut m = model(&g, None);
            if let Some(amount) = relief {
                let r = TipRelief { amount, length: 0.3 * m.stiffness.path, shape: ReliefShape::Parabolic };
                m.reliefs = Reliefs([Some(r), Some(r)]);
            }
            for i in 0..50 {
                let tau = (i as f64 + 0.37) / 50.0;
                for (nodes, tol) in [(LINE_NODES, 1e-6), (2 * LINE_NODES, 1e-10)] {
                    let stiff = mesh(&g, Sharing::Stiffness(&m)).line_contacts(tau, nodes);
                    let sum: f64 = stiff.iter().map(|c| c.force_share).sum();
                    assert!((sum - 1.0).abs() < tol, "{p} {relief:?} τ = {tau}, {nodes} nodes: Σ w dl / F_bn = {sum}");
                }
            }
        }
    }
}

/// A helical scene with `load_sharing = stiffness` runs end to end: its report says how the load is
/// shared (not He & Singh's constant density, which the same scene states under equal sharing) and
/// its mean efficiency differs from equal sharing's.
#[test]
fn helical_scene_shares_by_stiffness_end_to_end() {
    let text = std::fs::read_to_string(crate::root().join("specs/metric_helical.gear")).unwrap();
    let stiff = text.replace("face_width      = 30 mm", "face_width      = 30 mm\n        load_sharing    = stiffness");
    assert_ne!(stiff, text);
    let report = |t: &str| gearloss::report_of(&gearloss::check("specs/metric_helical.gear", t).unwrap());
    let (equal, by_stiffness) = (report(&text), report(&stiff));
    let says = |r: &gearloss::Report, words: &str| r.findings.iter().any(|f| f.message.contains(words));
    assert!(says(&by_stiffness, "by stiffness along the contact lines") && !says(&by_stiffness, "He & Singh"));
    assert!(says(&equal, "constant stiffness density") && !says(&equal, "by stiffness"));
    let eta = |r: &gearloss::Report| serde_json::to_value(r).unwrap()["efficiency"][0]["mean_efficiency"].as_f64();
    let (a, b) = (eta(&equal), eta(&by_stiffness));
    assert!(a.is_some() && b.is_some() && a != b, "{a:?} vs {b:?}");
}

/// The pair's records.csv and records.jsonl (stages/pair/) carry the static transmission error: one `transmission_error` row
/// per torque of the analysis, before the operating points, with the report's peak-to-peak and
/// mean (report.json rounds to 10 digits: 1e-9 relative). Run as two shards and merged, the record
/// files equal a single run's byte for byte (the rows come from the shard holding point 1).
#[test]
fn transmission_error_rows_in_the_records() {
    let path = crate::root().join("specs/fzg_c_tip_relief.gear");
    let source = std::fs::read_to_string(&path).unwrap();
    let scene = crate::scene(&path);
    let out = std::env::temp_dir().join(format!("gearloss-te-records-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let single = gearloss::run_into("tip.gear", &source, &scene, &out.join("single"), None, &gearloss::Quiet).unwrap();
    let pair = single.folder.join("stages/pair");
    let csv = std::fs::read_to_string(pair.join("records.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().skip(1).map(|l| l.split(',').collect()).collect();
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(pair.join("report.json")).unwrap()).unwrap();
    let te = report["transmission_error"].as_array().unwrap();
    assert_eq!(te.len(), 3);
    for (i, t) in te.iter().enumerate() {
        let r = &rows[i];
        assert_eq!(
            (r[col("kind")], r[col("point")], r[col("torque_index")]),
            ("transmission_error", "0", &*i.to_string())
        );
        let close = |cell: &str, v: &serde_json::Value| {
            let (a, b) = (cell.parse::<f64>().unwrap(), v["value"].as_f64().unwrap());
            assert!((a - b).abs() <= 1e-9 * b.abs(), "{a} vs {b}");
        };
        close(r[col("pinion_torque_N_m")], &t["pinion_torque"]);
        close(r[col("ste_peak_to_peak_m")], &t["peak_to_peak"]);
        close(r[col("ste_mean_m")], &t["mean"]);
    }
    assert!(rows[3..].iter().all(|r| r[col("kind")] != "transmission_error" && r[col("ste_mean_m")].is_empty()));
    let jsonl = std::fs::read_to_string(pair.join("records.jsonl")).unwrap();
    assert_eq!(jsonl.lines().count(), rows.len());
    assert!(jsonl.lines().next().unwrap().contains("\"kind\":\"transmission_error\",\"law\":\"\""));
    let mut shards = Vec::new();
    for index in 1..=2 {
        let shard = Some(gearloss::Shard { index, count: 2 });
        shards.push(
            gearloss::run_into("tip.gear", &source, &scene, &out.join("shards"), shard, &gearloss::Quiet)
                .unwrap()
                .folder,
        );
    }
    let merged = gearloss::merge_into(&shards, &out.join("merged"), &gearloss::Quiet).unwrap();
    for f in ["stages/pair/records.csv", "stages/pair/records.jsonl", "drive_records.csv"] {
        assert!(std::fs::read(single.folder.join(f)).unwrap() == std::fs::read(merged.folder.join(f)).unwrap(), "{f}");
    }
    std::fs::remove_dir_all(&out).unwrap();
}
