//! The bearings' static loads over a drive cycle, at the two states where they are greatest.
//!
//! Each bearing place's static equivalent load P_0 = max(0.6 F_r + 0.5 F_a, F_r) (ISO 76) is
//! homogeneous of degree one in its radial and axial loads, and a shaft's statics are linear in the
//! forces of the gears on it, which are linear in the torques the stages carry; each stage carries
//! the output torque through its ratio, plus the share of the losses downstream of it. At one sign
//! of the torque P_0 therefore grows with |T_out|, and over the cycle it is greatest where the
//! output torque is: at its largest value in drive and its most negative in recuperation. Both are
//! located exactly: on a moving piece the box carries F(t) r_dyn / i_final with F a quadratic in
//! time (or the recuperation limit, a constant), whose extremes lie at the piece's ends or F's
//! vertex ([`crate::vehicle::Piece::force_extremes`]). The drive is solved at each (the oil at the
//! piece's end temperature with the sump's transient), and the loads of every bearing place at the
//! two solutions are the cycle's tally ([`StaticLoads`], row 0 in drive, row 1 in recuperation),
//! read by the report's check of the static ratings (`report/bearing_checks.rs`). What the losses
//! add to the stages' torques moves them by their share of the power: the state found is the worst
//! to within that share (on the shipped WLTC reducer a sampled state's P_0 exceeds the located one's
//! by at most 0.04 %, on the input shaft, whose torque carries the whole box's losses).
//!
//! A torque extreme at standstill (a launch from rest, the end of braking to a stop) is taken as
//! the one-sided limit of the moving piece, the drive solved at the output speed [`CREEP`] (its
//! losses are continuous as the speed goes to 0⁺).

use super::cycle_pieces::{box_load, PieceThermal};
use super::drive_setup::DriveSetup;
use super::static_loads::StaticLoads;
use crate::drive::{EndValue, ShaftEnd};
use crate::efficiency::Formulation;
use crate::model::{DriveCycleSpec, SceneDrive};
use crate::vehicle::{Mode, Piece};

/// The output speed (rad/s) a torque extreme at standstill is evaluated at: the limit v → 0⁺.
pub(crate) const CREEP: f64 = 1e-6;

/// The cycle's bearing loads at its two torque extremes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CycleBearingLoads {
    /// Row 0: the greatest output torque in drive; row 1: the least in recuperation.
    pub(crate) loads: StaticLoads,
    /// Each row's state: (time s, output torque N·m); None where the cycle has no moving piece of
    /// that sign.
    pub peaks: [Option<(f64, f64)>; 2],
}

/// An extreme of the output torque: (torque N·m, time s, piece index).
type Extreme = (f64, f64, usize);

/// The greatest output torque in drive and the least in recuperation over the moving pieces.
fn torque_extremes(spec: &DriveCycleSpec, pieces: &[Piece]) -> [Option<Extreme>; 2] {
    let (mut high, mut low): (Option<Extreme>, Option<Extreme>) = (None, None);
    for (k, p) in pieces.iter().enumerate().filter(|(_, p)| p.mode != Mode::Standing) {
        let ((_, t_high), (_, t_low)) = p.force_extremes();
        for t in [p.from, p.to, t_high, t_low] {
            let (torque, _) = box_load(spec, p, t);
            if torque > 0.0 && high.is_none_or(|h| torque > h.0) {
                high = Some((torque, t, k));
            }
            if torque < 0.0 && low.is_none_or(|l| torque < l.0) {
                low = Some((torque, t, k));
            }
        }
    }
    [high, low]
}

/// The bearing places' loads at the cycle's two torque extremes under `row` (law, formulation).
pub(crate) fn cycle_bearing_loads(
    setup: &DriveSetup,
    (drive, spec): (&SceneDrive, &DriveCycleSpec),
    (law, formulation): (usize, Formulation),
    pieces: &[Piece],
    thermal: &[PieceThermal],
) -> CycleBearingLoads {
    let mut out = CycleBearingLoads::default();
    for (i, extreme) in torque_extremes(spec, pieces).into_iter().enumerate() {
        let Some((torque, t, k)) = extreme else { continue };
        let speed = box_load(spec, &pieces[k], t).1.max(CREEP);
        let at = thermal.get(k).map(|th| setup.at_oil_temperature(th.end));
        let point = at.as_ref().unwrap_or(setup).point(
            law,
            formulation,
            EndValue { at: ShaftEnd::Output, value: torque },
            EndValue { at: ShaftEnd::Output, value: speed },
        );
        out.loads.add_drive_row(&drive.layout, i, &point);
        out.peaks[i] = Some((t, torque));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The located extremes against the cycle sampled densely (a test's independent check, not how
    /// the tool finds them): on the shipped WLTC reducer at a fixed 80 °C, every bearing place's P_0
    /// at 9 times on every moving piece (ends and 7 inside) stays within 1 % of its P_0 at the
    /// located extreme of its sign (the losses' share of the torques, the module's stated reading),
    /// and the drive's extreme is the largest output torque sampled.
    #[test]
    fn the_located_extremes_bound_the_sampled_cycle() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/specs/ev_reducer_wltc.gear");
        let scene = crate::check(path, &std::fs::read_to_string(path).unwrap()).unwrap();
        let drive = scene.drive.as_ref().unwrap();
        let spec = drive.cycle.as_ref().unwrap();
        let setup = DriveSetup::new(&scene, drive);
        let row = (0, scene.analyses.first_formulation());
        let pieces = spec.cycle.pieces();
        let located = cycle_bearing_loads(&setup, (drive, spec), row, &pieces, &[]);
        let mut sampled = [StaticLoads::default(), StaticLoads::default()];
        let mut top_torque: f64 = 0.0;
        for p in pieces.iter().filter(|p| p.mode != Mode::Standing) {
            for j in 0..9 {
                let t = p.from + (p.to - p.from) * j as f64 / 8.0;
                let (torque, speed) = box_load(spec, p, t);
                top_torque = top_torque.max(torque);
                let end = |value| EndValue { at: ShaftEnd::Output, value };
                let point = setup.point(row.0, row.1, end(torque), end(speed.max(CREEP)));
                sampled[usize::from(torque < 0.0)].add_drive_row(&drive.layout, 0, &point);
            }
        }
        assert!(top_torque <= located.peaks[0].unwrap().1 * (1.0 + 1e-12), "{top_torque} vs {:?}", located.peaks);
        let mut places = 0;
        for (i, sampled) in sampled.iter().enumerate() {
            for (k, worst) in sampled.0.iter().enumerate() {
                let (Some((seen, _)), Some(Some((found, row)))) = (worst, located.loads.0.get(k)) else { continue };
                let found = if *row == i { *found } else { continue };
                assert!(*seen <= found * 1.01, "place {k}, sign {i}: sampled {seen} N above located {found} N");
                places += 1;
            }
        }
        assert!(places >= 4, "{places} places compared");
    }

    /// The static load is homogeneous of degree one in the bearing's loads (the reading the module
    /// rests on): doubling F_r and F_a doubles P_0, on either branch of the max (exact).
    #[test]
    fn static_load_scales_with_the_forces() {
        use crate::losses::bearing_type::static_equivalent_load as p0;
        for (fr, fa) in [(1000.0, 100.0), (100.0, 1000.0), (0.0, 500.0)] {
            assert_eq!(p0(2.0 * fr, 2.0 * fa), 2.0 * p0(fr, fa));
        }
    }
}
