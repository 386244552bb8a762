//! report.md's section on the drive's stages analysed as pairs alone: for each analysed mesh and
//! point, the state the drive's walk gave it, the mesh efficiency the walk charged beside the pair
//! alone's, and a link to the pair's own report.

use crate::render::markup::md;
use crate::render::table::{fixed, header, row};
use crate::report::drive::DriveReport;

/// The section, when the scene asks for analyses of one pair.
pub(crate) fn section(out: &mut String, r: &DriveReport) {
    let Some(first) = r.stage_pairs.first() else { return };
    let n = super::shown_units::Speed(&r.speed_unit);
    md!(out, "## Stage meshes analysed as pairs\n");
    if first.point.is_none() {
        return whole_sweep(out, r);
    }
    md!(
        out,
        "Each analysed stage's mesh (each mesh of a planetary stage) is run as its pair alone at the state the drive's power walk gives it, the drive solved {}: the driving member in the pinion's place (the planet in a planet–ring mesh, as the walk evaluates it), the pinion's torque into the mesh (per planet for a planetary stage) and its speed (in the carrier's frame for a planetary stage), the scene's lubricant, laws and analyses. Its report (μ along the line of action, film, contact, dynamics as the scene asks) is a report of one pair, in the folder linked; the same pair written alone with `pinion_torque` and `pinion_speed` at these values gives the same numbers.\n",
        if first.law.is_empty() {
            "with its meshes passing their power whole (the scene lists no friction law; the bearings, seals and gears' no-load parts are charged)".to_string()
        } else {
            format!("under {} ({})", first.law, first.formulation)
        }
    );
    header(
        out,
        &[
            "stage",
            "mesh",
            "drive point",
            "pinion's / wheel's place",
            &format!("T_pinion ({})", super::shown_units::Torque(&r.torque_unit).unit()),
            &format!("n_pinion ({})", n.unit()),
            "η_mesh in the drive",
            "η of the pair alone (as charged)",
            "η̄ of the pair alone (line integral)",
            "report",
        ],
    );
    for p in &r.stage_pairs {
        row(
            out,
            &[
                p.stage.clone(),
                p.mesh.clone().unwrap_or_else(|| "pinion–wheel".to_string()),
                format!("{}: {}", p.point.unwrap_or_default(), p.point_words),
                format!("{} / {}", p.pinion, p.wheel),
                shown(p.pinion_torque.map(|t| super::shown_units::Torque(&r.torque_unit).of_si(t)), 4),
                shown(p.pinion_speed_rpm.map(|s| n.of_rpm(s)), 3),
                percent(p.mesh_efficiency),
                percent(p.pair_charged_efficiency),
                percent(p.pair_mean_efficiency),
                match (&p.folder, &p.not_run) {
                    (Some(f), _) => format!("[{f}/report.md]({f}/report.md)"),
                    (None, Some(why)) => format!("not run: {why}"),
                    (None, None) => "no load through the mesh".to_string(),
                },
            ],
        );
    }
    if first.law.is_empty() {
        md!(out, "\nη_mesh is what the walk charged: with no friction law, none (100 %); the pair alone reports no efficiency.\n");
        return;
    }
    md!(out, "\nη_mesh is what the walk charged: 1 − P_mesh/(T ω) with the mesh loss a loss budget charges (for ISO/TR 14179-2 on a helical pair, P_in μ̄ H_V with Ohlendorf's H_V; else the contact-line integral). The pair alone's η as charged is the same loss read from its own report (`ohlendorf_power_loss` or `power_loss`), and equals η_mesh; its η̄ is the mean of η(t) along the mesh cycle of the contact-line integral, the pair report's headline.\n");
}

/// The stage of a scene of one pair, analysed over the scene's whole sweep: what it is and where.
fn whole_sweep(out: &mut String, r: &DriveReport) {
    for p in &r.stage_pairs {
        let link = match (&p.folder, &p.not_run) {
            (Some(f), _) => format!("its report is [{f}/report.md]({f}/report.md)"),
            (None, Some(why)) => format!("it was not run: {why}"),
            (None, None) => "no load goes through its mesh".to_string(),
        };
        md!(
            out,
            "Stage `{}` is the scene's one pair. At every operating point its pinion drives at the scene's own torque and speed (`pinion_torque` is the torque at the pinion gear; the walk raises only the input's by the pinion shaft's own losses), so its mesh is analysed as the pair alone over the scene's whole sweep: its geometry, the contact along the line of action, each law's efficiency along the mesh cycle (η̄ with its error estimate, Ohlendorf's H_V beside the contact-line integral) and every analysis of one pair the scene asks for, at its points in full and its detail points; {link}. The loss budget, the thermal balance, the duty cycle and the loss map above are the drive's own.\n",
            p.stage
        );
    }
}

/// A value to `places`, or a dash.
fn shown(x: Option<f64>, places: usize) -> String {
    x.map_or_else(|| "—".to_string(), |v| fixed(v, places))
}

/// A fraction in percent to six places, or a dash.
fn percent(x: Option<f64>) -> String {
    x.map_or_else(|| "—".to_string(), |e| format!("{} %", fixed(100.0 * e, 6)))
}
