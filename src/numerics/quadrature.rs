//! Adaptive Gauss–Kronrod quadrature (7-point Gauss, 15-point Kronrod; Piessens et al., QUADPACK, 1983).
//!
//! The interval is first split at every given break point (zone boundaries, the pitch point,
//! regime switches), so that the integrand is smooth inside each piece; integrable endpoint
//! singularities (log, |s|^−1/4, |s|^−1/3 at the pitch point) are handled by bisection towards them,
//! since no node ever lies on an endpoint.
//!
//! ```
//! use gearloss::numerics::integrate;
//! // ∫₀¹ −ln x dx = 1, with a log singularity at 0.
//! let r = integrate(|x| -x.ln(), &[0.0, 1.0], 1e-10);
//! assert!((r.value - 1.0).abs() < 1e-9 && r.error < 1e-9);
//! ```

/// An integral and its estimated absolute error.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Integral {
    pub value: f64,
    pub error: f64,
    /// Integrand evaluations used.
    pub evaluations: usize,
}

const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const WG: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// The QUADPACK (dqk15) error estimate of one component: the Kronrod–Gauss difference scaled by the
/// integrand's variation, (200 |K − G| / I_asc)^1.5 · I_asc, floored at 50 ε |I|.
fn dqk15_error(k: f64, g: f64, asc: f64, abs: f64) -> f64 {
    let mut err = (k - g).abs();
    if asc != 0.0 && err != 0.0 {
        err = asc * (200.0 * err / asc).powf(1.5).min(1.0);
    }
    if abs > f64::MIN_POSITIVE / (50.0 * f64::EPSILON) {
        err = err.max(50.0 * f64::EPSILON * abs);
    }
    err
}

/// One 15-point Kronrod estimate of N integrands on [a, b], each with its QUADPACK error estimate.
fn gk15<const N: usize>(f: &impl Fn(f64) -> [f64; N], a: f64, b: f64) -> ([f64; N], [f64; N]) {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut values = [([0.0; N], [0.0; N]); 7];
    for (j, v) in values.iter_mut().enumerate() {
        let x = h * XGK[j];
        *v = (f(c - x), f(c + x));
    }
    let mut out = ([0.0; N], [0.0; N]);
    for n in 0..N {
        let mut k = fc[n] * WGK[7];
        let mut g = fc[n] * WG[3];
        for (j, (f1, f2)) in values.iter().enumerate() {
            k += WGK[j] * (f1[n] + f2[n]);
            if j % 2 == 1 {
                g += WG[j / 2] * (f1[n] + f2[n]);
            }
        }
        let mean = 0.5 * k;
        let mut asc = WGK[7] * (fc[n] - mean).abs();
        let mut abs = WGK[7] * fc[n].abs();
        for (j, (f1, f2)) in values.iter().enumerate() {
            asc += WGK[j] * ((f1[n] - mean).abs() + (f2[n] - mean).abs());
            abs += WGK[j] * (f1[n].abs() + f2[n].abs());
        }
        out.0[n] = k * h;
        out.1[n] = dqk15_error(k * h, g * h, asc * h.abs(), abs * h.abs());
    }
    out
}

/// Integrates `f` over `[breaks[0], breaks[last]]`, split at every interior break, to a relative
/// tolerance `rel_tol` of the whole integral (with an absolute floor of 1e-300).
pub fn integrate(f: impl Fn(f64) -> f64, breaks: &[f64], rel_tol: f64) -> Integral {
    let [r] = integrate_singular_n(|x, _| [f(x)], breaks, &[], rel_tol);
    r
}

/// As [`integrate`], for an integrand with integrable singularities (or singular derivatives) at the
/// break points listed in `singular`: on each piece next to one, x = a + (b − a) t⁴ turns |x − a|^−p
/// (p ≤ 1/2) into t^(3−4p) and log|x − a| into t³ log t, both smooth enough for Gauss–Kronrod to
/// converge fast instead of bisecting towards the singular point.
///
/// `f(x, d)` also receives d = x − (the singular point of its piece), computed exactly from the
/// map (x itself cannot resolve a point 1e-20 away from a singular point at 0.01); d is NaN on
/// pieces that touch no singular point it is `None`.
pub(crate) fn integrate_singular(
    f: impl Fn(f64, Option<f64>) -> f64,
    breaks: &[f64],
    singular: &[f64],
    rel_tol: f64,
) -> Integral {
    let [r] = integrate_singular_n(|x, d| [f(x, d)], breaks, singular, rel_tol);
    r
}

/// As [`integrate_singular`] for N integrands that share their (expensive) evaluation points; each
/// meets the tolerance, the pieces are refined where any of them needs it.
pub(crate) fn integrate_singular_n<const N: usize>(
    f: impl Fn(f64, Option<f64>) -> [f64; N],
    breaks: &[f64],
    singular: &[f64],
    rel_tol: f64,
) -> [Integral; N] {
    let mut points: Vec<f64> = breaks.iter().copied().filter(|x| x.is_finite()).collect();
    points.sort_by(f64::total_cmp);
    points.dedup_by(|a, b| (*a - *b).abs() <= 1e-15 * (1.0 + b.abs()));
    let is_singular = |x: f64| singular.iter().any(|s| (s - x).abs() <= 1e-12 * (1.0 + x.abs()));
    let mut split = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        match (is_singular(a), is_singular(b)) {
            (false, false) => split.push((a, b, 0)),
            (true, false) => split.push((a, b, 1)),
            (false, true) => split.push((a, b, 2)),
            (true, true) => {
                let m = 0.5 * (a + b);
                split.push((a, m, 1));
                split.push((m, b, 2));
            }
        }
    }
    let mut out = [Integral { value: 0.0, error: 0.0, evaluations: 0 }; N];
    for (a, b, kind) in split {
        let scale = |v: [f64; N], w: f64| v.map(|x| x * w);
        let (values, errors, evaluations) = match kind {
            0 => adaptive(&|x: f64| f(x, None), a, b, rel_tol),
            1 => adaptive(
                &|t: f64| {
                    let d = (b - a) * t.powi(4);
                    scale(f(a + d, Some(d)), 4.0 * (b - a) * t.powi(3))
                },
                0.0,
                1.0,
                rel_tol,
            ),
            _ => adaptive(
                &|t: f64| {
                    let d = (b - a) * t.powi(4);
                    scale(f(b - d, Some(-d)), 4.0 * (b - a) * t.powi(3))
                },
                0.0,
                1.0,
                rel_tol,
            ),
        };
        for n in 0..N {
            out[n].value += values[n];
            out[n].error += errors[n];
            out[n].evaluations += evaluations;
        }
    }
    out
}

type Piece<const N: usize> = (f64, f64, [f64; N], [f64; N]);

fn adaptive<const N: usize>(f: &impl Fn(f64) -> [f64; N], a: f64, b: f64, rel_tol: f64) -> ([f64; N], [f64; N], usize) {
    let width = b - a;
    let (v, e) = gk15(f, a, b);
    let mut pieces: Vec<Piece<N>> = vec![(a, b, v, e)];
    let mut evaluations = 15;
    let sums = |pieces: &[Piece<N>]| {
        let mut total = [0.0; N];
        let mut err = [0.0; N];
        for p in pieces {
            for n in 0..N {
                total[n] += p.2[n];
                err[n] += p.3[n];
            }
        }
        (total, err)
    };
    for _ in 0..5000 {
        let (total, err) = sums(&pieces);
        // The worst ratio of error to allowance over the components.
        let ratio = |e: &[f64; N]| (0..N).map(|n| e[n] / (rel_tol * total[n].abs()).max(1e-300)).fold(0.0, f64::max);
        if ratio(&err) <= 1.0 || err.iter().any(|e| !e.is_finite()) {
            break;
        }
        let (i, _) =
            pieces.iter().enumerate().max_by(|x, y| ratio(&x.1 .3).total_cmp(&ratio(&y.1 .3))).expect("a piece");
        let (a, b, _, _) = pieces[i];
        let m = 0.5 * (a + b);
        // Round-off: a piece this narrow cannot be refined meaningfully; keep its error estimate.
        if m <= a || m >= b || (b - a) < 1e-14 * width {
            break;
        }
        let (v1, e1) = gk15(f, a, m);
        let (v2, e2) = gk15(f, m, b);
        evaluations += 30;
        pieces[i] = (a, m, v1, e1);
        pieces.push((m, b, v2, e2));
    }
    let (total, err) = sums(&pieces);
    (total, err, evaluations)
}

/// As [`integrate_singular_n`] without singular points, to an absolute tolerance per component over
/// the whole interval: each piece between breaks gets the share of it that its width has, and is
/// bisected until its QUADPACK estimate is below that share (at most 40 bisections deep, never below
/// 1e-14 of the piece, and at most [`MAX_PIECE_EVALUATIONS`] integrand evaluations in all: past that
/// budget the remaining pieces are taken as they are and their error estimates say the tolerance was
/// not met, so that a nearly singular integrand costs seconds, never hours). For integrands such as Fourier coefficients whose value may be near zero,
/// where a relative tolerance could never be met.
///
/// ```
/// use gearloss::numerics::integrate_pieces_n;
/// // ∫₀^2π [sin² x, sin x] dx = [π, 0], the second to an absolute 1e-12.
/// let [a, b] = integrate_pieces_n(|x| [x.sin().powi(2), x.sin()], &[0.0, 3.0, 6.283185307179586], [1e-12, 1e-12]);
/// assert!((a.value - std::f64::consts::PI).abs() < 1e-11 && b.value.abs() < 1e-11);
/// assert!(a.error <= 1e-12 && b.error <= 1e-12);
/// ```
/// The evaluation budget of [`integrate_pieces_n`].
pub(crate) const MAX_PIECE_EVALUATIONS: usize = 30_000;

pub fn integrate_pieces_n<const N: usize>(
    f: impl Fn(f64) -> [f64; N],
    breaks: &[f64],
    abs_tol: [f64; N],
) -> [Integral; N] {
    let mut out = [Integral { value: 0.0, error: 0.0, evaluations: 0 }; N];
    let (Some(first), Some(last)) = (breaks.first(), breaks.last()) else { return out };
    let total = last - first;
    if total.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return out;
    }
    let mut stack = Vec::new();
    for w in breaks.windows(2) {
        if w[1] <= w[0] {
            continue;
        }
        stack.push((w[0], w[1], 0u32));
        while let Some((a, b, depth)) = stack.pop() {
            let (v, e) = gk15(&f, a, b);
            out[0].evaluations += 15;
            let share = (b - a) / total;
            let ok = (0..N).all(|n| e[n] <= abs_tol[n] * share || !e[n].is_finite());
            let m = 0.5 * (a + b);
            let spent = out[0].evaluations >= MAX_PIECE_EVALUATIONS;
            if ok || spent || depth >= 40 || m <= a || m >= b || (b - a) < 1e-14 * (w[1] - w[0]) {
                for n in 0..N {
                    out[n].value += v[n];
                    out[n].error += e[n];
                }
            } else {
                stack.push((m, b, depth + 1));
                stack.push((a, m, depth + 1));
            }
        }
    }
    let evaluations = out[0].evaluations;
    for o in out.iter_mut() {
        o.evaluations = evaluations;
    }
    out
}

/// Nodes and weights of the n-point Gauss–Legendre rule on [0, 1], by Newton's iteration on the
/// Legendre polynomial P_n from Tricomi's initial guesses (Abramowitz & Stegun 25.4.29; exact for
/// polynomials of degree 2n − 1).
///
/// ```
/// use gearloss::numerics::gauss_legendre;
/// let (x, w) = gauss_legendre(3);
/// let i: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(5)).sum();
/// assert!((i - 1.0 / 6.0).abs() < 1e-15);
/// ```
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            let p = if n == 0 { 1.0 } else { p1 };
            let prev = if n == 1 { 1.0 } else { p0 };
            dp = n as f64 * (x * p - prev) / (x * x - 1.0);
            let dx = p / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        nodes.push(0.5 * (1.0 - x));
        weights.push(1.0 / ((1.0 - x * x) * dp * dp));
    }
    (nodes, weights)
}
