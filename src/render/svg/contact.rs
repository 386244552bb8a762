//! Plots along the line of action: the contact state, and μ, local power loss and η(t) at one operating point.

use super::panel::{figure, Panel};
use crate::report::Report;

fn mm(v: &[f64]) -> Vec<f64> {
    v.iter().map(|u| u * 1e3).collect()
}

fn marks_mm(r: &Report) -> Vec<(String, f64)> {
    r.curves.marks.iter().map(|(n, u)| (n.clone(), u * 1e3)).collect()
}

/// contact_state.svg: v_s (per speed), SR and p_H (per torque) along the line of action.
pub fn contact_state(r: &Report) -> Result<String, String> {
    let c = &r.curves;
    let along = |y: &str, series: Vec<(String, Vec<f64>)>| Panel {
        y_label: y.into(),
        x_label: "distance from T1 (mm)".into(),
        x: mm(&c.u),
        series,
        marks: marks_mm(r),
        ..Default::default()
    };
    let panels = [
        along("sliding velocity v_s (m/s)", c.sliding_velocity.clone()),
        along("slide-to-roll ratio SR", vec![(String::new(), c.slide_to_roll.clone())]),
        along(
            "Hertzian pressure p_H per contact (MPa)",
            c.hertz_pressure.iter().map(|(l, v)| (l.clone(), v.iter().map(|p| p * 1e-6).collect())).collect(),
        ),
        along("load share of one contact", vec![(String::new(), c.load_share.clone())]),
    ];
    figure(&format!("{}: contact along the line of action", r.title), &panels)
}

/// A symmetric clip level for signed μ curves: 1.3 × the largest |μ| away from the pitch point.
fn mu_clip(x_mm: &[f64], series: &[(String, Vec<f64>)], p_mm: f64, half_width_mm: f64) -> f64 {
    let mut max: f64 = 0.0;
    for (_, ys) in series {
        for (x, y) in x_mm.iter().zip(ys) {
            if (x - p_mm).abs() > half_width_mm && y.is_finite() {
                max = max.max(y.abs());
            }
        }
    }
    if max > 0.0 {
        1.3 * max
    } else {
        1.0
    }
}

/// point_K_friction.svg: μ and local power loss along the line of action, η over one mesh cycle.
pub fn point_friction(r: &Report, k: usize) -> Result<String, String> {
    let c = &r.curves;
    let pc = &c.points[k];
    let x = mm(&c.u);
    let p_mm = r.geometry.points_from_t1.P.si() * 1e3;
    let span = (x[x.len() - 1] - x[0]) * 0.06;
    let panels = [
        Panel {
            y_label: "coefficient of friction μ (signed)".into(),
            x_label: "distance from T1 (mm)".into(),
            clip: Some(mu_clip(&x, &pc.mu, p_mm, span)),
            x: x.clone(),
            series: pc.mu.clone(),
            marks: marks_mm(r),
            bands: pc.regime_bands.iter().map(|(a, b, l)| (a * 1e3, b * 1e3, l.clone())).collect(),
            ..Default::default()
        },
        Panel {
            y_label: "friction power loss per unit path, one contact (W)".into(),
            x_label: "distance from T1 (mm)".into(),
            clip: Some(mu_clip(&x, &pc.power_loss, p_mm, span)),
            x,
            series: pc.power_loss.clone(),
            marks: marks_mm(r),
            ..Default::default()
        },
        Panel {
            y_label: "instantaneous efficiency η (%)".into(),
            x_label: "time in mesh periods (0: a pair enters at A)".into(),
            x: c.tau.clone(),
            series: pc.efficiency.iter().map(|(l, v)| (l.clone(), v.iter().map(|e| 100.0 * e).collect())).collect(),
            ..Default::default()
        },
    ];
    figure(&format!("{}: friction at {}", r.title, pc.label), &panels)
}

/// film.svg: central and minimum film thickness and Λ along the line of action at up to six
/// operating points (at the contact-state table's positions).
pub fn film(r: &Report) -> Result<String, String> {
    let with_film: Vec<&crate::report::OperatingPointReport> =
        r.operating_points.iter().filter(|o| o.film.is_some()).collect();
    let picked: Vec<&crate::report::OperatingPointReport> =
        crate::report::pick(with_film.len()).into_iter().map(|i| with_film[i]).collect();
    let xy = |get: &dyn Fn(&crate::report::friction::FilmRow) -> Option<f64>| -> Vec<(String, Vec<(f64, f64)>)> {
        picked
            .iter()
            .map(|o| {
                let rows = o.film.as_deref().unwrap_or(&[]);
                let pts = rows.iter().filter_map(|f| Some((f.distance_from_t1.si() * 1e3, get(f)?))).collect();
                (o.label.clone(), pts)
            })
            .collect()
    };
    let mut panels = vec![
        Panel {
            y_label: "central film h_c (µm)".into(),
            x_label: "distance from T1 (mm)".into(),
            xy: xy(&|f| Some(f.central_film.si() * 1e6)),
            marks: marks_mm(r),
            ..Default::default()
        },
        Panel {
            y_label: "minimum film h_min (µm)".into(),
            x_label: "distance from T1 (mm)".into(),
            xy: xy(&|f| Some(f.minimum_film.si() * 1e6)),
            marks: marks_mm(r),
            ..Default::default()
        },
    ];
    let lambda = xy(&|f| f.lambda.map(|l| l.0));
    if lambda.iter().any(|(_, p)| !p.is_empty()) {
        panels.push(Panel {
            y_label: "film parameter Λ".into(),
            x_label: "distance from T1 (mm)".into(),
            xy: lambda,
            marks: marks_mm(r),
            ..Default::default()
        });
    }
    figure(&format!("{}: film thickness and Λ along the line of action", r.title), &panels)
}
