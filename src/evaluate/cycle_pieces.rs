//! The pieces of a drive cycle as the gearbox sees them: the load its output carries, the
//! integrands at a point (each loss part, the motor's and the output's power, the motor's speed),
//! and their integrals over a piece by Gauss–Legendre at two orders (README, "Vehicles and drive
//! cycles"); at a fixed oil temperature every piece on its own, in parallel.

use crate::losses::parts::{COLUMNS, COLUMN_COUNT};
use rayon::prelude::*;

use super::drive_setup::DriveSetup;
use crate::drive::{DrivePoint, EndValue, ShaftEnd};
use crate::efficiency::Formulation;
use crate::model::DriveCycleSpec;
use crate::vehicle::{Mode, Piece};

/// Gauss–Legendre nodes of the two rules on each piece.
pub const LOW_ORDER: usize = 3;
pub const HIGH_ORDER: usize = 5;

/// The loss parts: the meshes' and each loss-part column's (`crate::losses::parts::COLUMNS`),
/// the first quantities.
pub const PARTS: usize = 1 + COLUMN_COUNT;
/// Index of the motor's energy ∫ P_in dt, the output's ∫ P_out dt, and the motor's angle ∫ |ω_in| dt.
pub const MOTOR: usize = PARTS;
pub const OUTPUT: usize = PARTS + 1;
pub const ANGLE: usize = PARTS + 2;
pub const N: usize = PARTS + 3;
/// What is integrated over a piece (J, and rad for the motor's angle), in this order: `meshes`,
/// each column's key, `motor`, `output`, `motor_angle`.
pub const QUANTITIES: [&str; N] = quantities();

const fn quantities() -> [&'static str; N] {
    let mut q = [""; N];
    q[0] = "meshes";
    let mut i = 0;
    while i < COLUMN_COUNT {
        q[1 + i] = COLUMNS[i].key;
        i += 1;
    }
    q[MOTOR] = "motor";
    q[OUTPUT] = "output";
    q[ANGLE] = "motor_angle";
    q
}

/// The integrands at one point of the drive.
pub(crate) fn integrands(p: &DrivePoint) -> [f64; N] {
    let l = &p.losses;
    let mut v = [0.0; N];
    v[0] = l.meshes;
    v[1..PARTS].copy_from_slice(&l.parts);
    (v[MOTOR], v[OUTPUT], v[ANGLE]) = (p.input_power, p.output_power, p.input_speed);
    v
}

/// One piece's integrals: the higher order's value and |high − low|.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PieceIntegrals {
    pub value: [f64; N],
    pub error: [f64; N],
}

impl PieceIntegrals {
    /// Adds a part's values and errors (the errors' magnitudes, never cancelling).
    pub(crate) fn add(&mut self, part: &PieceIntegrals) {
        for k in 0..N {
            self.value[k] += part.value[k];
            self.error[k] += part.error[k];
        }
    }

    /// The higher order's value with |high − low| as its error.
    pub(crate) fn of(low: &[f64; N], high: &[f64; N]) -> PieceIntegrals {
        PieceIntegrals { value: *high, error: std::array::from_fn(|k| (high[k] - low[k]).abs()) }
    }
}

/// With the sump's transient: a piece's end temperature (K), the heat given off (J), the highest
/// θ on the piece (K) and its time (s), θ's difference between the two orders at the end (K).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PieceThermal {
    pub end: f64,
    pub dissipated: f64,
    pub highest: (f64, f64),
    pub error: f64,
}

/// What the gearbox's output carries at `t` on `piece`: (torque N·m, speed rad/s).
pub(crate) fn box_load(spec: &DriveCycleSpec, piece: &Piece, t: f64) -> (f64, f64) {
    let car = &spec.cycle.vehicle;
    let torque = piece.carried_force(t) * car.wheel_radius / car.final_ratio;
    let speed = piece.speed(t) / car.wheel_radius * car.final_ratio;
    (torque, speed)
}

/// The drive solved at `t` on `piece` with `setup` (`None` standing or at zero speed).
pub(crate) fn point_at(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    (law, formulation): (usize, Formulation),
    piece: &Piece,
    t: f64,
) -> Option<DrivePoint> {
    let (torque, speed) = box_load(spec, piece, t);
    if piece.mode == Mode::Standing || speed <= 0.0 {
        return None;
    }
    Some(setup.point(
        law,
        formulation,
        EndValue { at: ShaftEnd::Output, value: torque },
        EndValue { at: ShaftEnd::Output, value: speed },
    ))
}

/// The integrands at `t` on `piece` with the drive's `setup` (zero standing or at zero speed).
pub(crate) fn integrands_at(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    piece: &Piece,
    t: f64,
) -> [f64; N] {
    point_at(setup, spec, row, piece, t).map_or([0.0; N], |p| integrands(&p))
}

/// `piece` cut where the drive's losses change form inside it, so that every part's integrands
/// are smooth and Gauss–Legendre's two orders bound the error:
/// - where a shaft's speed passes one at which a bearing's model changes form (Palmgren's
///   ν n = 2000 mm²/s·rpm), in closed form ([`speed_switches`]);
/// - in coast, where the wheels' power stops covering the losses upstream of a stage, the power
///   through that stage reverses (its driving torque passes through zero: the mesh loss
///   |P|(1 − η) and the bearing loads it drives have a kink there). Each stage's signed driving
///   torque is read at the piece's ends, F's vertex and the higher rule's nodes; between two
///   readings of opposite sign the root is located by Brent's method to 1e-12 of the piece (the
///   drive solved afresh at every step). Drive pieces have none (the motor covers every loss).
pub(crate) fn cut_at_switches(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    piece: &Piece,
) -> Vec<Piece> {
    let mut cuts = speed_switches(setup, spec, piece);
    if matches!(piece.mode, Mode::Coast | Mode::CoastCapped) {
        cuts.extend(reversals(setup, spec, row, piece));
    }
    let h = piece.to - piece.from;
    let margin = 1e-9 * h;
    cuts.retain(|t| *t > piece.from + margin && *t < piece.to - margin);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|a, b| (*a - *b).abs() <= margin);
    let mut edges = vec![piece.from];
    edges.extend(cuts);
    edges.push(piece.to);
    edges.windows(2).map(|w| piece.between(w[0], w[1])).collect()
}

/// Where a shaft's speed passes a speed at which one of its bearings' models changes form
/// (Palmgren's ν n = 2000): every shaft turns in proportion to the output, whose speed is linear
/// on the piece, so each time is a closed form.
fn speed_switches(setup: &DriveSetup, spec: &DriveCycleSpec, piece: &Piece) -> Vec<f64> {
    let (w0, w1) = (box_load(spec, piece, piece.from).1, box_load(spec, piece, piece.to).1);
    setup
        .bearing_switch_output_speeds()
        .into_iter()
        .filter(|w| (w - w0) * (w - w1) < 0.0)
        .map(|w| piece.from + (w - w0) / (w1 - w0) * (piece.to - piece.from))
        .collect()
}

/// In coast, where the power through a stage reverses: between two readings of a stage's driving
/// torque of opposite sign, its root by Brent's method.
fn reversals(setup: &DriveSetup, spec: &DriveCycleSpec, row: (usize, Formulation), piece: &Piece) -> Vec<f64> {
    let h = piece.to - piece.from;
    let torques = |t: f64| -> Option<Vec<f64>> {
        point_at(setup, spec, row, piece, t).map(|p| p.stages.iter().map(|s| s.driving_torque).collect())
    };
    let (x, _) = crate::numerics::quadrature::gauss_legendre(HIGH_ORDER);
    let mut times: Vec<f64> = vec![piece.from, piece.to];
    times.extend(x.iter().map(|x| piece.from + x * h));
    times.extend(piece.force_vertex());
    times.sort_by(f64::total_cmp);
    let readings: Vec<(f64, Vec<f64>)> = times.iter().filter_map(|&t| torques(t).map(|q| (t, q))).collect();
    let mut cuts = Vec::new();
    for w in readings.windows(2) {
        let ((a, qa), (b, qb)) = (&w[0], &w[1]);
        for k in 0..qa.len() {
            if qa[k] * qb[k] < 0.0 {
                let stage_torque = |t: f64| torques(t).map_or(0.0, |q| q[k]);
                cuts.push(crate::numerics::roots::brent(stage_torque, *a, *b, 1e-12 * h));
            }
        }
    }
    cuts
}

/// ∫ over `piece` of the integrands by the `n`-node Gauss–Legendre rule at the setup's oil.
pub(crate) fn integrate(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    piece: &Piece,
    n: usize,
) -> [f64; N] {
    let (x, w) = crate::numerics::quadrature::gauss_legendre(n);
    let h = piece.to - piece.from;
    let mut sum = [0.0; N];
    for (x, w) in x.iter().zip(&w) {
        let v = integrands_at(setup, spec, row, piece, piece.from + x * h);
        for (s, v) in sum.iter_mut().zip(v) {
            *s += w * h * v;
        }
    }
    sum
}

/// The integrals of every piece at a fixed oil temperature, in parallel, each piece integrated
/// part by part between the switches [`cut_at_switches`] locates; and how many it located.
pub(crate) fn fixed_integrals(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    pieces: &[Piece],
) -> (Vec<PieceIntegrals>, usize) {
    let each: Vec<(PieceIntegrals, usize)> = pieces
        .par_iter()
        .map(|p| {
            if p.mode == Mode::Standing {
                return (PieceIntegrals::default(), 0);
            }
            let parts = cut_at_switches(setup, spec, row, p);
            let mut sum = PieceIntegrals::default();
            for part in &parts {
                let (l, h) =
                    (integrate(setup, spec, row, part, LOW_ORDER), integrate(setup, spec, row, part, HIGH_ORDER));
                sum.add(&PieceIntegrals::of(&l, &h));
            }
            (sum, parts.len() - 1)
        })
        .collect();
    let switches = each.iter().map(|(_, n)| n).sum();
    (each.into_iter().map(|(i, _)| i).collect(), switches)
}
