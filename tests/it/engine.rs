//! The n-state engine on a model with more than two states: two SDOF systems side by side, uncoupled
//! (a block-diagonal 4-state model). Every result of the engine must be the union of the two 2-state
//! results: multipliers, periodic state, trajectory extrema, integrators — through the general paths
//! (dynamic matrix exponentials, Schur eigenvalues, LU solve) that a 2-state model never takes.

use gearloss::dynamics::numerics::{reference, relative_error, study_times};
use gearloss::dynamics::Method;
use gearloss::dynamics::Trajectory;
use gearloss::dynamics::{integrate, Integrator};
use gearloss::dynamics::{DynamicFormulation, Floquet, SdofSystem, StiffnessModel};
use gearloss::dynamics::{PeriodicModel, Segment};
use gearloss::friction::Coulomb;
use gearloss::friction::LawContext;
use gearloss::geometry::OperatingState;
use gearloss::geometry::Sharing;
use nalgebra::{SMatrix, SVector};

/// Two SDOF systems with the same segments, uncoupled: X = [x₁, ẋ₁, x₂, ẋ₂].
struct Side<'a> {
    a: &'a SdofSystem<'a>,
    b: &'a SdofSystem<'a>,
}

impl PeriodicModel<4> for Side<'_> {
    fn name(&self) -> &'static str {
        "two_sdof"
    }
    fn period(&self) -> f64 {
        self.a.period
    }
    fn segments(&self) -> &[Segment] {
        &self.a.segments
    }
    fn system(&self, t: f64) -> (SMatrix<f64, 4, 4>, SVector<f64, 4>) {
        let (aa, ba) = self.a.system(t);
        let (ab, bb) = self.b.system(t);
        let mut m = SMatrix::<f64, 4, 4>::zeros();
        m.fixed_view_mut::<2, 2>(0, 0).copy_from(&aa);
        m.fixed_view_mut::<2, 2>(2, 2).copy_from(&ab);
        (m, SVector::<f64, 4>::new(ba[0], ba[1], bb[0], bb[1]))
    }
    fn segment_is_affine(&self, j: usize) -> bool {
        self.a.segment_is_affine(j) && self.b.segment_is_affine(j)
    }
    fn state_scale(&self) -> SVector<f64, 4> {
        let (sa, sb) = (self.a.state_scale(), self.b.state_scale());
        SVector::<f64, 4>::new(sa[0], sa[1], sb[0], sb[1])
    }
    fn highest_frequency(&self, t: f64) -> f64 {
        self.a.highest_frequency(t).max(self.b.highest_frequency(t))
    }
}

fn sorted(mut v: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    v.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
    v
}

/// Base + external (both affine: the exact route, a 6×6 dynamic exponential) and external + internal
/// (Magnus on 5×5): multipliers equal the union of the parts' to 1e-9, the periodic state equals
/// the parts' to 1e-8 of the state scale (Magnus' 1e-11 per segment through (I − Φ(T))⁻¹), Liouville holds to 1e-9, the trajectory's located DTE extrema equal
/// the parts' to 1e-9, and DOP853 at rtol 1e-10 reaches 1e-8 of the DTE peak-to-peak.
#[test]
fn four_state_model_is_the_union_of_its_parts() {
    let scene = crate::scene(&crate::root().join("specs/fzg_type_c.gear"));
    let g = scene.gears.geometry().unwrap();
    let law = Coulomb { mu: 0.08 };
    let k = StiffnessModel::pairs_in_contact(1.96e8, 3.92e8, 5.88e8);
    let ctx = LawContext {
        geometry: &g,
        state: OperatingState { pinion_torque: 239.3, pinion_speed: 1000.0 * std::f64::consts::PI / 30.0 },
        tribology: scene.mesh().tribology(226e9),
        sharing: Sharing::Equal,
    };
    let make = |f: DynamicFormulation| {
        let l: Option<&dyn gearloss::friction::FrictionLaw> =
            if f == DynamicFormulation::Base { None } else { Some(&law) };
        SdofSystem::new(ctx, l, f, k.clone(), [3.45e-4, 15.24e-4], 0.05)
    };
    use DynamicFormulation::*;
    for (fa, fb, method) in [(Base, External, Method::Exact), (External, Internal, Method::Magnus4)] {
        let (a, b) = (make(fa), make(fb));
        assert_eq!(a.segments, b.segments);
        let side = Side { a: &a, b: &b };
        let (fl, fla, flb) = (Floquet::analyse(&side), Floquet::analyse(&a), Floquet::analyse(&b));
        assert_eq!(fl.method, method);
        let whole = sorted(fl.multipliers.iter().map(|m| (m.re, m.im)).collect());
        let parts = sorted(fla.multipliers.iter().chain(&flb.multipliers).map(|m| (m.re, m.im)).collect());
        for (w, p) in whole.iter().zip(&parts) {
            assert!((w.0 - p.0).abs() < 1e-9 && (w.1 - p.1).abs() < 1e-9, "{fa:?}+{fb:?}: {whole:?} vs {parts:?}");
        }
        assert!(((fl.determinant - fl.liouville) / fl.liouville).abs() < 1e-9);
        let (x, xa, xb) = (fl.periodic_state.unwrap(), fla.periodic_state.unwrap(), flb.periodic_state.unwrap());
        // Where a part is exact alone but Magnus in the whole (external + internal), they agree to
        // Magnus' tolerance on the state scale (x_s, x_s ω_n), amplified by (I − Φ(T))⁻¹: 1e-8.
        let s = side.state_scale();
        for (i, v) in [xa[0], xa[1], xb[0], xb[1]].iter().enumerate() {
            assert!((x[i] - v).abs() <= 1e-8 * s[i], "{fa:?}+{fb:?} state {i}: {} vs {v}", x[i]);
        }
        let tr = Trajectory::new(&side, &fl.period, x);
        let tra = Trajectory::new(&a, &fla.period, xa);
        let dte = tr.extrema(|p, t| tr.state(p, t)[0], |p, t| tr.state(p, t)[1]);
        let dte_a = tra.extrema(|p, t| tra.state(p, t)[0], |p, t| tra.state(p, t)[1]);
        let scale = dte_a.max.value - dte_a.min.value;
        assert!((dte.max.value - dte_a.max.value).abs() < 1e-9 * scale, "{fa:?}: max");
        assert!((dte.min.value - dte_a.min.value).abs() < 1e-9 * scale, "{fa:?}: min");
        let times = study_times(side.period());
        let x0 = SVector::<f64, 4>::new(xa[0], 0.0, xb[0], 0.0);
        let exact = reference(&side, x0, &times);
        let (states, _) = integrate(&side, Integrator::Dop853, 1e-10, x0.into(), &times).unwrap();
        let err = relative_error(&side, &states, &exact);
        assert!(err < 1e-8, "{fa:?}+{fb:?}: DOP853 error {err:e}");
    }
}

/// A Mathieu oscillator (ω²(1 + a cos 2πνt/T), many oscillations per period) whose spring force also
/// drives a second oscillator: A(t) varies along the row of x₁ only, the spectral rank-one route.
struct Driven {
    a: f64,
    /// ν: 1, or a ripple too fast for a Chebyshev interpolant of a segment (the model is then
    /// evaluated at every collocation node).
    ripple: f64,
    structured: bool,
    segments: Vec<Segment>,
}

const W1: f64 = 40.0;
const W2: f64 = 55.0;

impl PeriodicModel<4> for Driven {
    fn name(&self) -> &'static str {
        "driven_mathieu"
    }
    fn period(&self) -> f64 {
        1.0
    }
    fn segments(&self) -> &[Segment] {
        &self.segments
    }
    fn system(&self, t: f64) -> (SMatrix<f64, 4, 4>, SVector<f64, 4>) {
        let k = W1 * W1 * (1.0 + self.a * (2.0 * std::f64::consts::PI * self.ripple * t).cos());
        #[rustfmt::skip]
        let m = SMatrix::<f64, 4, 4>::new(
            0.0, 1.0, 0.0, 0.0,
            -k, -0.04 * W1, 0.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
            0.3 * k, 0.0, -W2 * W2, -0.06 * W2,
        );
        (m, SVector::<f64, 4>::new(0.0, 1.0, 0.0, 0.0))
    }
    fn segment_is_affine(&self, _segment: usize) -> bool {
        false
    }
    fn varying_row(&self, _segment: usize) -> Option<SVector<f64, 4>> {
        self.structured.then(|| SVector::<f64, 4>::new(1.0, 0.0, 0.0, 0.0))
    }
    fn state_scale(&self) -> SVector<f64, 4> {
        SVector::<f64, 4>::new(1.0 / (W1 * W1), 1.0 / W1, 1.0 / (W1 * W1), 1.0 / W1)
    }
    fn highest_frequency(&self, _t: f64) -> f64 {
        W2
    }
}

/// The spectral rank-one propagator against converged Magnus on the same model (periodic state and
/// multipliers to 1e-10), Liouville (tr A is constant: det Φ(T) = e^{−0.04 W1 − 0.06 W2}, to 1e-12
/// relative), and the limit a = 0, where A is constant and the exact propagator is taken. With
/// ν = 1 the varying column is a Chebyshev interpolant of each segment; with a ripple of 12 per
/// period (30 rad over the first segment) no interpolant of degree 32 reproduces it and every node
/// evaluates the model: both agree with Magnus.
#[test]
fn spectral_rank_one_route_matches_magnus_and_liouville() {
    let segments = vec![Segment { start: 0.0, end: 0.4 }, Segment { start: 0.4, end: 1.0 }];
    for ripple in [1.0, 12.0] {
        let model = |a: f64, structured: bool| Driven { a, ripple, structured, segments: segments.clone() };
        let (spectral, magnus) = (Floquet::analyse(&model(0.2, true)), Floquet::analyse(&model(0.2, false)));
        assert_eq!((spectral.method, magnus.method), (Method::Spectral, Method::Magnus4));
        let liouville = (-0.04 * W1 - 0.06 * W2).exp();
        assert!((spectral.determinant / liouville - 1.0).abs() < 1e-12, "{} vs {liouville}", spectral.determinant);
        let (xs, xm) = (spectral.periodic_state.unwrap(), magnus.periodic_state.unwrap());
        let scale = model(0.2, true).state_scale();
        let error = (xs - xm).component_div(&scale).norm() / xm.component_div(&scale).norm();
        assert!(error < 1e-10, "ripple {ripple}, periodic state: {error:e}");
        for (a, b) in spectral.multipliers.iter().zip(&magnus.multipliers) {
            assert!((a.re - b.re).abs() + (a.im - b.im).abs() < 1e-10, "ripple {ripple}: {a:?} vs {b:?}");
        }
        assert_eq!(Floquet::analyse(&model(0.0, true)).method, Method::Exact);
    }
}
