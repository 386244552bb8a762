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
                format!("{}: {}", p.point, p.point_words),
                format!("{} / {}", p.pinion, p.wheel),
                fixed(super::shown_units::Torque(&r.torque_unit).of_si(p.pinion_torque), 4),
                fixed(n.of_rpm(p.pinion_speed_rpm), 3),
                format!("{} %", fixed(100.0 * p.mesh_efficiency, 6)),
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

/// A fraction in percent to six places, or a dash.
fn percent(x: Option<f64>) -> String {
    x.map_or_else(|| "—".to_string(), |e| format!("{} %", fixed(100.0 * e, 6)))
}
