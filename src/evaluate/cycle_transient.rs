//! The sump's temperature over a drive cycle: C dθ/dt = P_V(t, θ) − P_Q(θ) from a start
//! temperature, P_V the drive's whole loss at the cycle's load at time t with the oil at θ, P_Q
//! what the housing gives off ([`crate::thermal::Housing::dissipation`]).
//!
//! Each piece of the cycle is one step of s-stage Gauss collocation
//! ([`crate::numerics::collocation`], order 2s): the stage temperatures θ_i = θ₀ + h Σ a_ij f_j
//! are found by fixed-point iteration (the housing's time constant C/(dP_Q/dθ) is thousands of
//! seconds, a piece at most a few: each pass shrinks the change some thousand times) until no
//! stage moves by more than [`TOLERANCE`] θ₀. The losses' integrals over the piece are then
//! h Σ b_j P(t_j, θ_j) — the Gauss–Legendre rule along the temperature's own path — and
//! θ_end = θ₀ + h Σ b_j f_j, so C (θ_end − θ₀) = E_lost − E_dissipated holds on every piece to
//! rounding. The run is made at [`LOW_ORDER`] and [`HIGH_ORDER`] stages (side by side); the
//! higher is reported, their difference is the error estimate. The highest θ of a piece is
//! located on its collocation polynomial (a root of its slope), not sampled.

use rayon::prelude::*;

use super::cycle_pieces::{
    cut_at_switches, integrands_at, PieceIntegrals, PieceThermal, HIGH_ORDER, LOW_ORDER, N, PARTS,
};
use super::drive_setup::DriveSetup;
use crate::efficiency::Formulation;
use crate::model::DriveCycleSpec;
use crate::numerics::collocation::Collocation;
use crate::thermal::Housing;
use crate::vehicle::{Mode, Piece};

/// Stages settle when none moves by more than this, relative to θ₀.
pub(crate) const TOLERANCE: f64 = 1e-13;
/// Passes of the fixed-point iteration before a piece gives up.
const MAX_PASSES: usize = 60;

/// One piece of one order's run.
#[derive(Debug, Clone, Copy)]
struct Step {
    integrals: [f64; N],
    thermal: PieceThermal,
}

/// The cycle's integrals and thermal path, or why the transient stopped.
pub(crate) fn run(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    pieces: &[Piece],
    housing: &Housing,
    c: f64,
    start: f64,
) -> Result<(Vec<PieceIntegrals>, Vec<PieceThermal>, usize), String> {
    let march = |s: usize| march(setup, spec, row, pieces, (housing, c, start), s);
    let (low, high) = rayon::join(|| march(LOW_ORDER), || march(HIGH_ORDER));
    let ((low, _), (high, switches)) = (low?, high?);
    let mut integrals = Vec::with_capacity(pieces.len());
    let mut thermal = Vec::with_capacity(pieces.len());
    for (l, h) in low.iter().zip(&high) {
        integrals.push(PieceIntegrals::of(&l.integrals, &h.integrals));
        thermal.push(PieceThermal { error: (h.thermal.end - l.thermal.end).abs(), ..h.thermal });
    }
    Ok((integrals, thermal, switches))
}

/// The whole cycle at `s` stages, piece after piece; each moving piece in parts between the
/// switches [`cut_at_switches`] locates at the piece's start temperature, one collocation step a
/// part; and how many switches it located.
fn march(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    pieces: &[Piece],
    (housing, c, start): (&Housing, f64, f64),
    s: usize,
) -> Result<(Vec<Step>, usize), String> {
    let g = Collocation::new(s);
    let (mut theta, mut slope) = (start, 0.0);
    let mut out = Vec::with_capacity(pieces.len());
    let mut switches = 0;
    for piece in pieces {
        let parts = match piece.mode {
            Mode::Standing => vec![piece.clone()],
            _ => cut_at_switches(&setup.at_oil_temperature(theta), spec, row, piece),
        };
        switches += parts.len() - 1;
        let mut whole: Option<Step> = None;
        for part in &parts {
            let step = collocate(setup, spec, row, part, (housing, c), &g, (theta, slope))?;
            slope = (step.thermal.end - theta) / (part.to - part.from);
            theta = step.thermal.end;
            whole = Some(match whole {
                None => step,
                Some(w) => Step {
                    integrals: std::array::from_fn(|k| w.integrals[k] + step.integrals[k]),
                    thermal: PieceThermal {
                        end: step.thermal.end,
                        dissipated: w.thermal.dissipated + step.thermal.dissipated,
                        highest: if step.thermal.highest.0 > w.thermal.highest.0 {
                            step.thermal.highest
                        } else {
                            w.thermal.highest
                        },
                        error: 0.0,
                    },
                },
            });
        }
        out.push(whole.expect("a piece has a part"));
    }
    Ok((out, switches))
}

/// One step of `g`'s collocation over `piece` from θ₀ = `theta` (the previous step's `slope`
/// starts the stages).
fn collocate(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    piece: &Piece,
    (housing, c): (&Housing, f64),
    g: &Collocation,
    (theta, slope): (f64, f64),
) -> Result<Step, String> {
    let h = piece.to - piece.from;
    let at = |x: f64, temperature: f64| -> [f64; N] {
        if piece.mode == Mode::Standing {
            return [0.0; N];
        }
        integrands_at(&setup.at_oil_temperature(temperature), spec, row, piece, piece.from + x * h)
    };
    let mut stage: Vec<f64> = g.c.iter().map(|x| theta + x * h * slope).collect();
    let mut settled = None;
    for _ in 0..MAX_PASSES {
        let values: Vec<[f64; N]> = g.c.par_iter().zip(&stage).map(|(&x, &t)| at(x, t)).collect();
        let lost: Vec<f64> = values.iter().map(|v| v[..PARTS].iter().sum()).collect();
        let given: Vec<f64> = stage.iter().map(|&t| housing.dissipation(t).total).collect();
        let f: Vec<f64> = lost.iter().zip(&given).map(|(l, q)| (l - q) / c).collect();
        let next: Vec<f64> =
            g.a.iter().map(|a| theta + h * a.iter().zip(&f).map(|(a, f)| a * f).sum::<f64>()).collect();
        let moved = next.iter().zip(&stage).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        if !moved.is_finite() {
            return Err(format!("the sump's temperature is not finite at {} s", piece.from));
        }
        if moved <= TOLERANCE * theta {
            settled = Some((values, given, f));
            break;
        }
        stage = next;
    }
    let Some((values, given, f)) = settled else {
        return Err(format!(
            "the sump's temperature did not settle on the piece from {} s to {} s",
            piece.from, piece.to
        ));
    };
    let mut integrals = [0.0; N];
    for (v, b) in values.iter().zip(&g.b) {
        for (s, v) in integrals.iter_mut().zip(v) {
            *s += h * b * v;
        }
    }
    let end = theta + h * g.b.iter().zip(&f).map(|(b, f)| b * f).sum::<f64>();
    let dissipated = h * g.b.iter().zip(&given).map(|(b, q)| b * q).sum::<f64>();
    let highest = highest_on(g, &f, theta, end, (piece.from, h));
    Ok(Step { integrals, thermal: PieceThermal { end, dissipated, highest, error: 0.0 } })
}

/// The highest θ on a piece (K, s): its ends, or where the collocation polynomial's slope falls
/// through zero inside (a root located by Brent's method).
fn highest_on(g: &Collocation, f: &[f64], theta: f64, end: f64, (from, h): (f64, f64)) -> (f64, f64) {
    let mut best = if end > theta { (end, from + h) } else { (theta, from) };
    let mut xs = vec![0.0];
    xs.extend(&g.c);
    xs.push(1.0);
    for w in xs.windows(2) {
        let (a, b) = (g.slope_at(f, w[0]), g.slope_at(f, w[1]));
        if a > 0.0 && b < 0.0 {
            let x = crate::numerics::roots::brent(|x| g.slope_at(f, x), w[0], w[1], 1e-14);
            let t = theta + h * g.rise_to(f, x);
            if t > best.0 {
                best = (t, from + x * h);
            }
        }
    }
    best
}
