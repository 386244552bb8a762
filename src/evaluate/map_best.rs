//! A map's best operating point, located (`drive_map_best.rs` reads it for each law and
//! formulation of a drive's map): where the efficiency peaks over the map's torque × speed
//! rectangle.
//!
//! The grid's best cell starts the search; the box of its neighbouring cells (clipped to the map) is
//! searched by coordinate ascent: a golden-section maximisation along torque at the current speed,
//! then along speed at the current torque, the box's ends included (the best point of a gearbox is
//! often at the map's highest torque), until a sweep moves the point by less than
//! [`POINT_TOLERANCE`] of the box in both directions. Each evaluation is the drive walked afresh at
//! that torque and speed: the located point is a point of the model, not of the grid. A local maximum next to the grid's best cell: with another peak between
//! grid points elsewhere, the grid must be finer to see it.

/// The search stops when a sweep moves the point by less than this fraction of the box.
pub(crate) const POINT_TOLERANCE: f64 = 1e-7;
/// The golden-section search along one direction stops at this fraction of its interval.
const LINE_TOLERANCE: f64 = 1e-8;

/// The maximum (x, f(x)) of `f` on [a, b] by golden sections, the ends included.
fn golden_max(f: impl Fn(f64) -> f64, a: f64, b: f64, count: &mut usize) -> (f64, f64) {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (a, b);
    let mut best =
        [(a, f(a)), (b, f(b))].into_iter().fold((a, f64::NEG_INFINITY), |m, p| if p.1 > m.1 { p } else { m });
    *count += 2;
    let (mut x1, mut x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    *count += 2;
    while hi - lo > LINE_TOLERANCE * (b - a) {
        if f1 >= f2 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - r * (hi - lo);
            f1 = f(x1);
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + r * (hi - lo);
            f2 = f(x2);
        }
        *count += 1;
        for p in [(x1, f1), (x2, f2)] {
            if p.1 > best.1 {
                best = p;
            }
        }
    }
    best
}

/// The maximum of `eta(torque, speed)` next to the grid cell `grid` (indices into `torques` and
/// `speeds`, ascending): coordinate ascent by golden sections over the box of the cell's neighbours
/// (clipped to the grid), the box's ends included, until a sweep moves the point by less than
/// [`POINT_TOLERANCE`] of the box in both directions (at most 50 sweeps). Returns (torque, speed,
/// η) at the located point and the evaluations used.
pub(crate) fn locate_max(
    torques: &[f64],
    speeds: &[f64],
    grid: (usize, usize),
    eta: impl Fn(f64, f64) -> f64,
) -> ((f64, f64, f64), usize) {
    let around = |v: &[f64], i: usize| (v[i.saturating_sub(1)], v[(i + 1).min(v.len() - 1)]);
    let ((t0, t1), (n0, n1)) = (around(torques, grid.0), around(speeds, grid.1));
    let mut count = 0;
    let (mut t, mut n) = (torques[grid.0], speeds[grid.1]);
    for _ in 0..50 {
        let t_new = if t1 > t0 { golden_max(|x| eta(x, n), t0, t1, &mut count).0 } else { t };
        let n_new = if n1 > n0 { golden_max(|x| eta(t_new, x), n0, n1, &mut count).0 } else { n };
        let moved = (t_new - t).abs() > POINT_TOLERANCE * (t1 - t0) || (n_new - n).abs() > POINT_TOLERANCE * (n1 - n0);
        (t, n) = (t_new, n_new);
        if !moved {
            break;
        }
    }
    ((t, n, eta(t, n)), count + 1)
}
