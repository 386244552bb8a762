//! Property tests over random valid gear pairs and laws: energy balance, the μ → 0 limit, and
//! agreement of the two formulations to first order in μ.

use gearloss::efficiency::{efficiency_at, mean_efficiency};
use gearloss::friction::Coulomb;
use gearloss::friction::SmoothedCoulomb;
use gearloss::friction::Xu;
use gearloss::friction::{FrictionLaw, LawContext};
use gearloss::geometry::Sharing;
use gearloss::geometry::{OperatingState, PairGeometry, PairInput};
use gearloss::model::Formulation::{External, Internal};
use gearloss::tribology::Tribology;
use proptest::prelude::*;

fn pair() -> impl Strategy<Value = PairGeometry> {
    (14u32..40, 1.0f64..4.0, 0.5e-3f64..10e-3, -0.3f64..0.6, -0.3f64..0.6, 15.0f64..25.0).prop_filter_map(
        "meshing pair",
        |(z1, ratio, m, x1, x2, alpha)| {
            let z2 = (z1 as f64 * ratio).round() as u32;
            PairGeometry::compute(&PairInput {
                module: m,
                pressure_angle: alpha.to_radians(),
                helix_angle: 0.0,
                teeth: [z1, z2],
                profile_shift: [x1, x2],
                tip_diameter: [None, None],
                center_distance: None,
                face_width: 10.0 * m,
                internal: false,
            })
            .ok()
        },
    )
}

fn context<'a>(g: &'a PairGeometry, torque: f64, rpm: f64, sharing: Sharing<'a>) -> LawContext<'a> {
    LawContext {
        geometry: g,
        state: OperatingState { pinion_torque: torque, pinion_speed: rpm * std::f64::consts::PI / 30.0 },
        tribology: Tribology {
            dynamic_viscosity: 0.05,
            ra_mean: Some(0.3e-6),
            reduced_modulus: 226e9,
            lubricant_factor: 1.0,
            lubricant_family: "mineral",
            ..Tribology::default()
        },
        sharing,
    }
}

fn laws(mu: f64) -> Vec<Box<dyn FrictionLaw>> {
    vec![Box::new(Coulomb { mu }), Box::new(SmoothedCoulomb { mu, phi: 50e3 }), Box::new(Xu::from_units(50.0, 0.3))]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, failure_persistence: None, ..ProptestConfig::default() })]

    /// External η = 1 − friction power / input power, pointwise (tolerance 1e-12):
    /// friction power Σ |μ_j| F_bn/n v_s,j (the n forces add up to F_bn whatever load the law sees),
    /// input power T_p ω_p.
    #[test]
    fn external_efficiency_is_an_energy_balance(g in pair(), torque in 1.0f64..2000.0, rpm in 10.0f64..10000.0, tau in 0.0f64..1.0, mu in 0.01f64..0.2, whole in any::<bool>()) {
        let ctx = context(&g, torque, rpm, if whole { Sharing::Whole } else { Sharing::Equal });
        for law in laws(mu) {
            let contacts = ctx.mesh().contacts_at(tau);
            let friction_power: f64 = contacts.iter().map(|c| law.mu(c).abs() * g.normal_load(&ctx.state) / contacts.len() as f64 * c.sliding_velocity).sum();
            let input = torque * ctx.state.pinion_speed;
            let eta = efficiency_at(&ctx, law.as_ref(), External, tau);
            prop_assert!((eta - (1.0 - friction_power / input)).abs() < 1e-12, "{} {eta} vs {}", law.id(), 1.0 - friction_power / input);
        }
    }

    /// μ → 0 gives η → 1 for both formulations (|1 − η̄| ≤ 1e-8 at μ = 1e-9).
    #[test]
    fn vanishing_friction_gives_unit_efficiency(g in pair(), torque in 1.0f64..2000.0) {
        let ctx = context(&g, torque, 1000.0, Sharing::Equal);
        for law in [Coulomb { mu: 1e-9 }] {
            for f in [External, Internal] {
                let m = mean_efficiency(&ctx, &law, f).value;
                prop_assert!((1.0 - m).abs() < 1e-8, "{f:?}: {m}");
            }
        }
    }

    /// The formulations agree to first order in μ: their difference is O(μ²), so halving μ quarters it
    /// (ratio within 3.5–4.5 at μ = 1e-3).
    #[test]
    fn formulations_agree_to_first_order(g in pair(), tau in 0.0f64..1.0) {
        let ctx = context(&g, 100.0, 1000.0, Sharing::Equal);
        let diff = |mu: f64| {
            let law = Coulomb { mu };
            efficiency_at(&ctx, &law, External, tau) - efficiency_at(&ctx, &law, Internal, tau)
        };
        let (d1, d2) = (diff(1e-3), diff(5e-4));
        prop_assume!(d1.abs() > 1e-12);
        let ratio = d1 / d2;
        prop_assert!((3.5..4.5).contains(&ratio), "ratio {ratio}: d(μ) = {d1}, d(μ/2) = {d2}");
    }
}
