//! The 6-DOF model (He–Cho–Singh eqs 1–9): limits, balances and Floquet identities on FZG type C.

use gearloss::dynamics::six_dof::{Bearing, SixDofSystem};
use gearloss::dynamics::{DynamicFormulation, Floquet, PeriodicModel, SdofSystem, StiffnessModel};
use gearloss::evaluate::tribology;
use gearloss::friction::coulomb::Coulomb;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::contact::Sharing;
use gearloss::geometry::{OperatingState, PairGeometry};

const K: StiffnessModel = StiffnessModel::PairsInContact { single: 1.96e8, double: 3.92e8, triple: 5.88e8 };
const J: [f64; 2] = [3.45e-4, 15.24e-4];
/// FZG type C gears as steel discs: m = ρ π b d² / 4 with b = 14 mm (spec comment of fzg_bearings.gear).
const MASS: [f64; 2] = [0.58, 1.26];

pub fn fzg() -> (gearloss::Scene, PairGeometry) {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let g = scene.gears.geometry().unwrap();
    (scene, g)
}

pub fn ctx<'a>(scene: &gearloss::Scene, g: &'a PairGeometry, rpm: f64) -> LawContext<'a> {
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: 239.3, pinion_speed: rpm * std::f64::consts::PI / 30.0 },
        tribology: tribology(scene, 226e9),
        sharing: Sharing::Equal,
    }
}

fn bearings(k: f64) -> [Bearing; 2] {
    [Bearing { loa: k, oloa: k, damping_ratio: 0.02 }; 2]
}

fn six<'a>(c: LawContext<'a>, law: Option<&'a dyn FrictionLaw>, k: f64) -> SixDofSystem<'a> {
    let f = if law.is_some() { DynamicFormulation::Internal } else { DynamicFormulation::Base };
    SixDofSystem::new(SdofSystem::new(c, law, f, K.clone(), J, 0.05), MASS, bearings(k))
}

/// Bearings → ∞: the torsional result tends to the SDOF internal formulation (base at μ = 0) with
/// an error like 1/K: the DTE of the periodic state at t = 0 and the spectral radius of the mesh mode
/// differ by less than 2e-3 relative at K = 1e11 N/m, and the error falls by 10 ± 3 per decade of K.
#[test]
fn stiff_bearings_give_the_sdof_model() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    for l in [None, Some(&law as &dyn FrictionLaw)] {
        let c = ctx(&scene, &g, 1000.0);
        let f = if l.is_some() { DynamicFormulation::Internal } else { DynamicFormulation::Base };
        let sdof = Floquet::analyse(&SdofSystem::new(c, l, f, K.clone(), J, 0.05));
        let x_ref = sdof.periodic_state.unwrap()[0];
        let errors: Vec<f64> = [1e11, 1e12, 1e13]
            .iter()
            .map(|k| {
                let s = six(c, l, *k);
                let fl = Floquet::analyse(&s);
                let x = fl.periodic_state.unwrap();
                (SixDofSystem::deflection(&x).0 - x_ref).abs() / x_ref.abs()
            })
            .collect();
        assert!(errors[0] < 2e-3, "{errors:?}");
        for w in errors.windows(2) {
            let ratio = w[0] / w[1];
            assert!((7.0..13.0).contains(&ratio), "1/K convergence: {errors:?}");
        }
    }
}

/// μ = 0: the OLOA motions are exactly zero in the periodic state.
#[test]
fn without_friction_nothing_moves_off_the_line_of_action() {
    let (scene, g) = fzg();
    let s = six(ctx(&scene, &g, 1000.0), None, 5e8);
    let x = Floquet::analyse(&s).periodic_state.unwrap();
    for i in [3, 4, 8, 9] {
        assert_eq!(x[i], 0.0, "state {i}");
    }
    assert!(x[1] != 0.0 && x[2] != 0.0);
}

/// det Φ(T) = exp(∫ tr A dt) (Liouville) to 1e-9 relative with friction, and the exact and Magnus
/// propagations of the frictionless model agree to 1e-9 (periodic state, relative to its norm).
#[test]
fn liouville_and_two_propagation_methods() {
    let (scene, g) = fzg();
    let law = Coulomb { mu: 0.08 };
    let s = six(ctx(&scene, &g, 1000.0), Some(&law), 5e8);
    let fl = Floquet::analyse(&s);
    assert!((fl.determinant / fl.liouville - 1.0).abs() < 1e-9, "{} vs {}", fl.determinant, fl.liouville);
    let exact = six(ctx(&scene, &g, 1000.0), None, 5e8);
    let mut magnus = six(ctx(&scene, &g, 1000.0), None, 5e8);
    magnus.mesh.allow_exact = false;
    let (a, b) = (Floquet::analyse(&exact), Floquet::analyse(&magnus));
    assert_eq!(format!("{:?}", a.method), "Exact");
    assert_eq!(format!("{:?}", b.method), "Magnus4");
    let (xa, xb) = (a.periodic_state.unwrap(), b.periodic_state.unwrap());
    assert!(
        (xa - xb).component_div(&exact.state_scale()).norm() < 1e-9 * xa.component_div(&exact.state_scale()).norm()
    );
    assert!((a.spectral_radius - b.spectral_radius).abs() < 1e-9);
}
