//! The readings a drive's loss parts rest on, in words (which radius, which direction, which
//! constants), for the parts its stages and shafts use: what report.md's "How these numbers are
//! found" states beside the walk.

use crate::drive::Drive;
use crate::losses::Lubrication;

/// The readings behind the loss parts `drive` uses: its stages' lubrication (Mauz's churning for dip;
/// the jet's impulse and the gears' windage for injection) and its bearings' models (Palmgren, the
/// SKF model); empty for a drive of no gearbox parts.
pub(crate) fn loss_readings(drive: &Drive) -> Vec<String> {
    let mut out = Vec::new();
    let lubrication = |dip: bool| {
        drive
            .stages
            .iter()
            .any(|s| matches!(s.lubrication, Some(Lubrication::Dip { .. })) == dip && s.lubrication.is_some())
    };
    if lubrication(true) {
        out.push("churning (Mauz, ISO/TR 14179-2): T_H is a dip-lubricated stage's hydraulic loss torque read at its pinion's shaft, P = T_H ω_pinion, at the pitch-line speed v_t = ω_pinion r_w of the pinion's working pitch circle; it contains the dipping gears' windage".to_string());
    }
    if lubrication(false) {
        out.push("jet impulse ρ Q v_t (v_t + v_j) (Ariura et al.): the jet meets the teeth head-on; a jet into the mesh entry moving with the teeth would lose the smaller ρ Q v_t (v_t − v_j)".to_string());
        out.push("windage (Anderson & Loewenthal, NASA TP-1622): their pitch radius R read as the working pitch radius r_w of each gear".to_string());
    }
    let bearings: Vec<_> = drive.shafts.iter().flat_map(|s| &s.bearings).collect();
    if bearings.iter().any(|b| b.skf.is_none()) {
        out.push("bearings (Palmgren): f_0, f_1, P_1 for oil-bath lubrication as SKF's General Catalogue 4000 E (1989) gives them and ISO/TR 14179-2 tabulates them; a tapered roller bearing's Y is its `y` (1.6 when not given)".to_string());
    }
    if bearings.iter().any(|b| b.skf.is_some()) {
        out.push("bearings (SKF model, SKF Rolling bearings catalogue 2018): the series' constants R1, R2, S1, S2 as the scene gives them; K_rs = 3e-8 (low oil level, jet); no drag or seal moment".to_string());
    }
    out
}

#[cfg(test)]
mod tests {
    /// The FZG C14 gearbox (dip, Palmgren) states Mauz's reading and Palmgren's, the injection spec
    /// (SKF bearings) the jet's, the windage's and the SKF model's, and neither states the other's.
    #[test]
    fn each_drive_states_the_readings_of_the_parts_it_uses() {
        let readings = |spec: &str| {
            let path = format!("{}/specs/{spec}", env!("CARGO_MANIFEST_DIR"));
            let scene = crate::scene::check::check(spec, &std::fs::read_to_string(path).unwrap()).unwrap();
            super::loss_readings(&scene.drive.unwrap().layout)
        };
        let starts = |r: &[String]| r.iter().map(|x| x.split(' ').next().unwrap().to_string()).collect::<Vec<_>>();
        assert_eq!(starts(&readings("fzg_c14_gearbox.gear")), ["churning", "bearings"]);
        let injection = readings("fzg_c14_injection.gear");
        assert_eq!(starts(&injection), ["jet", "windage", "bearings"]);
        assert!(injection[2].contains("SKF model"), "{injection:?}");
    }
}
