//! A vehicle over a drive cycle through the scene's drive (README, "Vehicles and drive cycles").
//!
//! On every piece of the cycle ([`crate::vehicle::Cycle::pieces`]: an interval of the trace, cut
//! where the wheel force changes sign, where it crosses the recuperation limit and at the phase
//! boundaries) the gearbox's output carries the wheel torque F r_dyn (or the limit) over the final
//! ratio at the wheel speed v/r_dyn times it; the drive is solved there (`DriveSetup::point`)
//! and its loss parts, the motor's power and the output's power are integrated over the piece by
//! Gauss–Legendre at [`LOW_ORDER`] and [`HIGH_ORDER`] nodes: the higher order's value is reported,
//! the difference of the two is its error estimate. A piece on which the drive's losses change
//! form (in coast, where the power through a stage reverses) is integrated part by part between
//! the located switches, so that the estimate bounds the error. Standing pieces lose nothing.
//!
//! With a fixed oil temperature every piece is independent (evaluated in parallel). With the
//! housing's heat capacity the sump follows the cycle (`super::cycle_transient`).

use rayon::prelude::*;

pub(crate) use super::cycle_pieces::box_load;
use super::cycle_pieces::{fixed_integrals, integrate};
pub use super::cycle_pieces::{
    PieceIntegrals, PieceThermal, ANGLE, HIGH_ORDER, LOW_ORDER, MOTOR, N, OUTPUT, PARTS, QUANTITIES,
};
use super::drive_setup::DriveSetup;
use crate::drive::{EndValue, ShaftEnd};
use crate::efficiency::Formulation;
use crate::model::{DriveCycleSpec, Scene, SceneDrive};
use crate::vehicle::{Mode, Piece};

/// Where a stage's law leaves its validity range over the cycle.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StageValidity {
    pub pieces: usize,
    pub seconds: f64,
    pub first: Option<(f64, &'static str)>,
    /// The law's notes at the pieces' middles (an input read at a bound of its range), by kind
    /// (the note with its numbers taken out): (the first piece's note, its start (s), pieces,
    /// seconds).
    pub notes: Vec<(String, f64, usize, f64)>,
}

/// A note's kind: its text without the numbers in it (the same bound met at other values).
pub(crate) fn note_kind(note: &str) -> String {
    note.chars().filter(|c| !c.is_ascii_digit() && *c != '.' && *c != '-').collect()
}

/// How the oil temperature is taken over the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CycleOil {
    /// Fixed (K).
    Fixed(f64),
    /// The sump's transient from `start` (K) with heat capacity `c` (J/K).
    Transient { start: f64, c: f64 },
}

/// A drive cycle evaluated under one law and formulation.
#[derive(Debug, Clone)]
pub struct CycleEvaluation {
    pub law_index: usize,
    pub formulation: Formulation,
    pub oil: CycleOil,
    pub pieces: Vec<Piece>,
    pub integrals: Vec<PieceIntegrals>,
    /// How many switches inside the pieces the integrals were cut at (where the power through a
    /// stage reverses in coast: `super::cycle_pieces::cut_at_switches`).
    pub switches: usize,
    /// With the transient, per piece.
    pub thermal: Vec<PieceThermal>,
    /// Why the transient stopped, if it did.
    pub failure: Option<String>,
    /// By stage: the pieces whose middle finds the law outside its validity range on that stage's
    /// mesh, their time (s), and the first one's time and reason.
    pub validity: Vec<StageValidity>,
    /// The bearing places' static loads at the cycle's two torque extremes (in drive, in
    /// recuperation), for the check of their static ratings.
    pub bearings: super::cycle_bearings::CycleBearingLoads,
    /// The box's map for the plot (output torque N·m × output speed rad/s at the fixed or start
    /// temperature): torques, speeds, `[torque][speed]` η (NaN where both ends deliver).
    pub map: (Vec<f64>, Vec<f64>, Vec<Vec<f64>>),
}

/// ∫ P_V dt (J) over the whole cycle at the scene's fixed oil temperature by the `n`-node
/// Gauss–Legendre rule on each of `parts` equal parts of every piece, the pieces not cut at the
/// switches inside them: the independent reference the error estimate is checked against (a
/// composite rule converges at kinks too, if slowly).
pub fn loss_energy_at_order(scene: &Scene, drive: &SceneDrive, spec: &DriveCycleSpec, n: usize, parts: usize) -> f64 {
    let setup = DriveSetup::new(scene, drive);
    let formulation = scene.analyses.first_formulation();
    spec.cycle
        .pieces()
        .par_iter()
        .filter(|p| p.mode != Mode::Standing)
        .flat_map(|p| {
            let h = (p.to - p.from) / parts as f64;
            (0..parts)
                .map(|i| {
                    p.between(p.from + i as f64 * h, if i + 1 == parts { p.to } else { p.from + (i + 1) as f64 * h })
                })
                .collect::<Vec<_>>()
        })
        .map(|p| integrate(&setup, spec, (0, formulation), &p, n)[..PARTS].iter().sum::<f64>())
        .sum()
}

/// The scene's drive cycle under its first law and formulation.
pub fn evaluate_cycle(scene: &Scene, drive: &SceneDrive, spec: &DriveCycleSpec) -> CycleEvaluation {
    let setup = DriveSetup::new(scene, drive);
    let formulation = scene.analyses.first_formulation();
    let row = (0, formulation);
    let pieces = spec.cycle.pieces();
    let fixed = scene.operating.oil_temperature.as_ref().map(|t| t.value.value);
    let transient = scene.housing.as_ref().and_then(|h| h.heat_capacity.map(|c| (h, c)));
    let (oil, (integrals, switches), thermal, failure) = match transient {
        Some((housing, c)) => {
            let start = spec.start_temperature.unwrap_or(housing.ambient);
            let run = super::cycle_transient::run(&setup, spec, row, &pieces, housing, c, start);
            let failure = run.as_ref().err().cloned();
            let (integrals, thermal, switches) = run.unwrap_or_default();
            (CycleOil::Transient { start, c }, (integrals, switches), thermal, failure)
        }
        None => {
            let theta = fixed.expect("a cycle without a heat capacity has its oil temperature (checked)");
            (CycleOil::Fixed(theta), fixed_integrals(&setup, spec, row, &pieces), Vec::new(), None)
        }
    };
    let map_setup = match oil {
        CycleOil::Transient { start, .. } => setup.at_oil_temperature(start),
        CycleOil::Fixed(_) => setup,
    };
    let map = cycle_map(&map_setup, spec, row, &pieces);
    let validity = validity(&map_setup, spec, row, &pieces, &thermal);
    let bearings = super::cycle_bearings::cycle_bearing_loads(&map_setup, (drive, spec), row, &pieces, &thermal);
    CycleEvaluation {
        law_index: 0,
        formulation,
        oil,
        pieces,
        integrals,
        switches,
        thermal,
        failure,
        validity,
        bearings,
        map,
    }
}

/// The law's validity on each stage at the middle of every moving piece (the oil at the piece's
/// end temperature with the transient, else `setup`'s): a flag, not a reported number.
fn validity(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    (law, formulation): (usize, Formulation),
    pieces: &[Piece],
    thermal: &[PieceThermal],
) -> Vec<StageValidity> {
    type Verdict = (Option<&'static str>, Vec<String>);
    let verdicts: Vec<(f64, f64, Vec<Verdict>)> = pieces
        .par_iter()
        .enumerate()
        .filter(|(_, p)| p.mode != Mode::Standing)
        .map(|(k, p)| {
            let mid = 0.5 * (p.from + p.to);
            let (torque, speed) = box_load(spec, p, mid);
            let at = thermal.get(k).map(|t| setup.at_oil_temperature(t.end));
            let setup = at.as_ref().unwrap_or(setup);
            let point = setup.point(
                law,
                formulation,
                EndValue { at: ShaftEnd::Output, value: torque },
                EndValue { at: ShaftEnd::Output, value: speed },
            );
            let stages = setup
                .validity(law, &point)
                .into_iter()
                .map(|v| ((v.outside > 0).then(|| v.intervals.first().map_or("outside", |i| i.2)), v.notes))
                .collect();
            (p.from, p.to - p.from, stages)
        })
        .collect();
    let stages = verdicts.first().map_or(0, |v| v.2.len());
    let mut out = vec![StageValidity::default(); stages];
    for (from, length, v) in &verdicts {
        for (s, (reason, notes)) in out.iter_mut().zip(v) {
            if let Some(reason) = reason {
                s.pieces += 1;
                s.seconds += length;
                s.first.get_or_insert((*from, reason));
            }
            for note in notes {
                let kind = note_kind(note);
                match s.notes.iter_mut().find(|n| note_kind(&n.0) == kind) {
                    Some(n) => {
                        n.2 += 1;
                        n.3 += length;
                    }
                    None => s.notes.push((note.clone(), *from, 1, *length)),
                }
            }
        }
    }
    out
}

/// Grid of the map drawn under the cycle's operating points: torques × speeds.
const MAP_GRID: (usize, usize) = (41, 30);

/// η of the box over the output torques and speeds the cycle reaches (a plot's grid).
fn cycle_map(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    (law, formulation): (usize, Formulation),
    pieces: &[Piece],
) -> (Vec<f64>, Vec<f64>, Vec<Vec<f64>>) {
    let (mut lo, mut hi, mut top) = (0.0f64, 0.0f64, 0.0f64);
    for p in pieces.iter().filter(|p| p.mode != Mode::Standing) {
        for t in [p.from, p.to] {
            let (torque, speed) = box_load(spec, p, t);
            (lo, hi, top) = (lo.min(torque), hi.max(torque), top.max(speed));
        }
    }
    if top <= 0.0 {
        return (Vec::new(), Vec::new(), Vec::new());
    }
    let (lo, hi) = (1.05 * lo.min(-1.0), 1.05 * hi.max(1.0));
    let torques: Vec<f64> = (0..MAP_GRID.0).map(|i| lo + (hi - lo) * i as f64 / (MAP_GRID.0 - 1) as f64).collect();
    let speeds: Vec<f64> = (1..=MAP_GRID.1).map(|i| 1.05 * top * i as f64 / MAP_GRID.1 as f64).collect();
    let eta = torques
        .par_iter()
        .map(|&torque| {
            speeds
                .iter()
                .map(|&speed| {
                    let p = setup.point(
                        law,
                        formulation,
                        EndValue { at: ShaftEnd::Output, value: torque },
                        EndValue { at: ShaftEnd::Output, value: speed },
                    );
                    if p.both_ends_deliver {
                        f64::NAN
                    } else {
                        p.efficiency
                    }
                })
                .collect()
        })
        .collect();
    (torques, speeds, eta)
}
