//! report.md: the friction, film and efficiency sections.

use super::markup::md;

use super::table::{fixed, header, row};
use crate::report::friction::MuValue;
use crate::report::units::Units;
use crate::report::{formulation_name, OperatingPointReport, Report};

/// Film, μ along the line of action, and efficiency at one operating point; the notes that define
/// what the tables read (film parameters, the helical model) under the first operating point only.
pub(crate) fn point(out: &mut String, op: &OperatingPointReport, helical: bool, first: bool, u: Units) {
    if let Some(film) = &op.film {
        film_lines(out, film, first, u);
    }
    if op.friction.is_empty() {
        return;
    }
    mu_table(out, op, u);
    efficiency_table(out, op, u);
    md!(out);
    if helical && first {
        md!(out, "{HELICAL_NOTE}\n");
    }
    if let Some(plot) = &op.plot {
        md!(out, "![μ, local power loss and η over one mesh cycle]({plot})\n");
    }
}

/// μ of every law at the contact table's positions (regimes named for the composite law).
fn mu_table(out: &mut String, op: &OperatingPointReport, u: Units) {
    md!(out, "Signed coefficient of friction along the line of action (negative in approach):\n");
    let mut cols = vec!["point".to_string(), u.length().heading("T1C")];
    cols.extend(op.friction.iter().map(|l| format!("`{}`", l.label)));
    header(out, &cols);
    for (i, r) in op.friction[0].mu_along_loa.iter().enumerate() {
        let mut cells = vec![r.point.clone().unwrap_or_default(), u.length().q(&r.distance_from_t1, 3)];
        for law in &op.friction {
            let m = &law.mu_along_loa[i];
            let mut cell = match m.mu {
                MuValue::Value(v) => fixed(v.0, 5),
                MuValue::Text(t) => t.to_string(),
            };
            if let Some(reg) = m.regime {
                cell.push_str(&format!(" ({})", format!("{reg:?}").to_lowercase()));
            }
            cells.push(cell);
        }
        row(out, &cells);
    }
    md!(out);
}

/// Per law and formulation: mean |μ|, validity, η̄ with its error, the loss, η's range, 1 − μ̄ H_V.
fn efficiency_table(out: &mut String, op: &OperatingPointReport, u: Units) {
    let p_loss = u.power().heading("P_loss");
    header(
        out,
        &[
            "law",
            "mean abs μ (A–E)",
            "outside validity",
            "formulation",
            "η̄ %",
            "error est.",
            &p_loss,
            "η min %",
            "η max %",
            "1 − μ̄ H_V %",
        ],
    );
    for law in &op.friction {
        let validity = format!("{}/{}", law.validity.outside, law.validity.samples);
        if law.efficiency.is_empty() {
            row(
                out,
                &[
                    format!("`{}`", law.label),
                    fixed(law.mean_abs_mu.0, 5),
                    validity.clone(),
                    "—".into(),
                    "—".into(),
                    "—".into(),
                    "—".into(),
                    "—".into(),
                    "—".into(),
                    fixed(100.0 * law.ohlendorf_efficiency.0, 4),
                ],
            );
        }
        for e in &law.efficiency {
            row(
                out,
                &[
                    format!("`{}`", law.label),
                    fixed(law.mean_abs_mu.0, 5),
                    validity.clone(),
                    formulation_name(e.formulation).into(),
                    fixed(100.0 * e.mean_efficiency.0, 4),
                    format!("{:.1e}", e.error_estimate.0),
                    u.power().q(&e.power_loss, 2),
                    fixed(100.0 * e.min_efficiency.0, 4),
                    fixed(100.0 * e.max_efficiency.0, 4),
                    fixed(100.0 * law.ohlendorf_efficiency.0, 4),
                ],
            );
        }
    }
}

/// Why 1 − μ̄ H_V differs from the helical mean (physics notes, "Helical pairs").
pub(crate) const HELICAL_NOTE: &str = "Helical pair: μ is integrated along every contact line, each point a spur-like contact at its own u with the load per unit length w = F_bn / L(t) (constant stiffness density, He & Singh). The efficiency uses the normal-force arms r_b cos β_b (He & Singh eq 8). The last column, 1 − μ̄ H_V with Ohlendorf's H_V (ISO/TR 14179-2), is NOT the mean of this model: H_V is the mean loss of a slice model, in which each transverse slice of the face shares its load equally between its own pairs in contact. Constant stiffness density puts more load where more line length is, which weights the ends of the path of contact (where sliding is fastest): at β = 15° the loss is about 1.1–1.2 × μ H_V. The two agree as β → 0; when ε_β is an integer L(t) is constant and the loss is the uniform-load value μ (1/r_b1 + 1/r_b2)/cos β_b · (AP² + PE²)/(2 AE). The column μ along the line of action is evaluated under the mean load per unit length F_bn / L̄.";

/// What the film table's two parameters are and which law reads which.
pub(crate) const FILM_PARAMETERS: &str = "Λ_HCS = h_c / R_q,comp · √(L_x / 2b_H) is He–Cho–Singh's film parameter (eq 21a): the central film over the composite roughness R_q,comp = √(Rq1² + Rq2²) filtered at the cut-off L_x; the composite law picks its regime by it (boundary below 1, mixed to 4, full film above). λ = h_min / σ, σ = √(Rq1² + Rq2²), is the specific film thickness: the minimum film over the unfiltered composite roughness; Xu's validity reads it (a full-film fit, flagged where λ < 1). Neither is the other: Λ_HCS / λ = (h_c / h_min) · √(L_x / 2b_H), typically 2–4 at gear contact widths.";

/// The film thickness and both film parameters at the characteristic points.
fn film_lines(out: &mut String, film: &[crate::report::friction::FilmRow], first: bool, u: Units) {
    md!(out, "Film thickness (Dowson–Toyoda central h_c, Dowson–Higginson minimum h_min) and two film parameters:\n");
    let (len, micro) = (u.length(), u.micro());
    header(out, &["point", &len.heading("T1C"), &micro.heading("h_c"), &micro.heading("h_min"), "Λ_HCS", "λ"]);
    for f in film {
        row(
            out,
            &[
                f.point.clone().unwrap_or_default(),
                len.q(&f.distance_from_t1, 3),
                micro.q(&f.central_film, 4),
                micro.q(&f.minimum_film, 4),
                f.lambda.map_or("—".into(), |l| fixed(l.0, 3)),
                f.specific_film.map_or("—".into(), |l| fixed(l.0, 3)),
            ],
        );
    }
    md!(out);
    if first {
        md!(out, "{FILM_PARAMETERS}\n");
    }
}

/// The sweep table and plots.
pub(crate) fn sweep(out: &mut String, r: &Report) {
    if r.efficiency.is_empty() {
        return;
    }
    md!(out, "## Efficiency over the sweep\n");
    md!(
        out,
        "Mean efficiency over one mesh cycle (time mean, adaptive Gauss–Kronrod to a relative tolerance of 1e-10, split at every zone boundary, pitch-point passage and regime switch) and friction power loss P = (1 − η̄) T_p ω_p.\n"
    );
    let speed = format!("n_p {}", r.speed_unit.name);
    // A large sweep lists the points reported in full; the record files have every point.
    let full = r.records.as_ref().is_none_or(|x| x.reported_in_full >= x.operating_points);
    if !full {
        md!(
            out,
            "At the operating points reported in full (every point: `records.csv`):
"
        );
    }
    let u = r.units();
    header(out, &[&u.torque().heading("T_p"), &speed, "law", "formulation", "η̄ %", &u.power().heading("P_loss")]);
    let shown = |case: usize| full || r.operating_points.iter().any(|o| o.index == case);
    for rec in r.efficiency.iter().filter(|x| shown(x.case)) {
        row(
            out,
            &[
                u.torque().q(&rec.pinion_torque, 2),
                fixed(r.speed_unit.value(&rec.pinion_speed), 1),
                format!("`{}`", rec.label),
                formulation_name(rec.formulation).into(),
                fixed(100.0 * rec.mean_efficiency.0, 4),
                u.power().q(&rec.power_loss, 2),
            ],
        );
    }
    md!(out);
    for p in r.plots.iter().filter(|p| p.file.starts_with("sweep_") || p.file.starts_with("composite_")) {
        md!(out, "![{}]({})\n", p.title, p.file);
    }
}
