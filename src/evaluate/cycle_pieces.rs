//! The pieces of a drive cycle as the gearbox sees them: the load its output carries, the
//! integrands at a point (each loss part, the motor's and the output's power, the motor's speed),
//! and their integrals over a piece by Gauss–Legendre at two orders (README, "Vehicles and drive
//! cycles"); at a fixed oil temperature every piece on its own, in parallel.

use rayon::prelude::*;

use super::drive_setup::DriveSetup;
use crate::drive::{DrivePoint, EndValue, ShaftEnd};
use crate::efficiency::Formulation;
use crate::model::DriveCycleSpec;
use crate::vehicle::{Mode, Piece};

/// Gauss–Legendre nodes of the two rules on each piece.
pub const LOW_ORDER: usize = 3;
pub const HIGH_ORDER: usize = 5;

/// What is integrated over a piece (J, and rad for the motor's angle), in this order.
pub const QUANTITIES: [&str; 8] =
    ["meshes", "gear_no_load", "bearings_no_load", "bearings_load", "seals", "motor", "output", "motor_angle"];
pub const N: usize = QUANTITIES.len();
/// Index of the motor's energy ∫ P_in dt, the output's ∫ P_out dt, and the motor's angle ∫ |ω_in| dt.
pub const MOTOR: usize = 5;
pub const OUTPUT: usize = 6;
pub const ANGLE: usize = 7;
/// The loss parts: the first five quantities.
pub const PARTS: usize = 5;

/// The integrands at one point of the drive.
pub(crate) fn integrands(p: &DrivePoint) -> [f64; N] {
    let l = &p.losses;
    [
        l.meshes,
        l.gear_no_load,
        l.bearings_no_load,
        l.bearings_load,
        l.seals,
        p.input_power,
        p.output_power,
        p.input_speed,
    ]
}

/// One piece's integrals: the higher order's value and |high − low|.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PieceIntegrals {
    pub value: [f64; N],
    pub error: [f64; N],
}

impl PieceIntegrals {
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

/// The integrands at `t` on `piece` with the drive's `setup` (zero standing or at zero speed).
pub(crate) fn integrands_at(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    (law, formulation): (usize, Formulation),
    piece: &Piece,
    t: f64,
) -> [f64; N] {
    let (torque, speed) = box_load(spec, piece, t);
    if piece.mode == Mode::Standing || speed <= 0.0 {
        return [0.0; N];
    }
    let point = setup.point(
        law,
        formulation,
        EndValue { at: ShaftEnd::Output, value: torque },
        EndValue { at: ShaftEnd::Output, value: speed },
    );
    integrands(&point)
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

/// The integrals of every piece at a fixed oil temperature, in parallel.
pub(crate) fn fixed_integrals(
    setup: &DriveSetup,
    spec: &DriveCycleSpec,
    row: (usize, Formulation),
    pieces: &[Piece],
) -> Vec<PieceIntegrals> {
    pieces
        .par_iter()
        .map(|p| {
            if p.mode == Mode::Standing {
                return PieceIntegrals::default();
            }
            let (low, high) = (integrate(setup, spec, row, p, LOW_ORDER), integrate(setup, spec, row, p, HIGH_ORDER));
            PieceIntegrals::of(&low, &high)
        })
        .collect()
}
