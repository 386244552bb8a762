//! Plots along the line of action: the contact state, and μ, local power loss and η(t) at one operating point.

use super::panel::{figure, Panel};
use crate::report::Report;

/// Positions along the line of action in the report's length unit (mm or in).
fn mm(r: &Report, v: &[f64]) -> Vec<f64> {
    let len = r.units().length();
    v.iter().map(|u| len.value(*u)).collect()
}

fn marks_mm(r: &Report) -> Vec<(String, f64)> {
    let len = r.units().length();
    r.curves.marks.iter().map(|(n, u)| (n.clone(), len.value(*u))).collect()
}

/// `distance from T1 (mm)`.
fn along_label(r: &Report) -> String {
    format!("distance from T1 ({})", r.units().length().unit)
}

/// contact_state.svg: v_s (per speed), SR and p_H (per torque) along the line of action.
pub fn contact_state(r: &Report) -> Result<String, String> {
    let c = &r.curves;
    let u = r.units();
    let along = |y: &str, series: Vec<(String, Vec<f64>)>| Panel {
        y_label: y.into(),
        x_label: along_label(r),
        x: mm(r, &c.u),
        series,
        marks: marks_mm(r),
        ..Default::default()
    };
    let panels = [
        along(
            &format!("sliding velocity v_s ({})", u.velocity().unit),
            c.sliding_velocity
                .iter()
                .map(|(l, v)| (l.clone(), v.iter().map(|x| u.velocity().value(*x)).collect()))
                .collect(),
        ),
        along("slide-to-roll ratio SR", vec![(String::new(), c.slide_to_roll.clone())]),
        along(
            &format!("Hertzian pressure p_H per contact ({})", u.pressure().unit),
            c.hertz_pressure
                .iter()
                .map(|(l, v)| (l.clone(), v.iter().map(|p| u.pressure().value(*p)).collect()))
                .collect(),
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
    let x = mm(r, &c.u);
    let u = r.units();
    let p_mm = u.length().value(r.geometry.points_from_t1.P.si());
    let span = (x[x.len() - 1] - x[0]) * 0.06;
    let power: Vec<(String, Vec<f64>)> =
        pc.power_loss.iter().map(|(l, v)| (l.clone(), v.iter().map(|p| u.power().value(*p)).collect())).collect();
    let panels = [
        Panel {
            y_label: "coefficient of friction μ (signed)".into(),
            x_label: along_label(r),
            clip: Some(mu_clip(&x, &pc.mu, p_mm, span)),
            x: x.clone(),
            series: pc.mu.clone(),
            marks: marks_mm(r),
            bands: pc
                .regime_bands
                .iter()
                .map(|(a, b, l)| (u.length().value(*a), u.length().value(*b), l.clone()))
                .collect(),
            ..Default::default()
        },
        Panel {
            y_label: format!("friction power of one contact, |μ| F v_s ({})", u.power().unit),
            x_label: along_label(r),
            clip: Some(mu_clip(&x, &power, p_mm, span)),
            x,
            series: power,
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
    let (len, micro) = (r.units().length(), r.units().micro());
    let xy = |get: &dyn Fn(&crate::report::friction::FilmRow) -> Option<f64>| -> Vec<(String, Vec<(f64, f64)>)> {
        picked
            .iter()
            .map(|o| {
                let rows = o.film.as_deref().unwrap_or(&[]);
                let pts = rows.iter().filter_map(|f| Some((len.value(f.distance_from_t1.si()), get(f)?))).collect();
                (o.label.clone(), pts)
            })
            .collect()
    };
    let mut panels = vec![
        Panel {
            y_label: micro.titled("central film h_c"),
            x_label: along_label(r),
            xy: xy(&|f| Some(micro.value(f.central_film.si()))),
            marks: marks_mm(r),
            ..Default::default()
        },
        Panel {
            y_label: micro.titled("minimum film h_min"),
            x_label: along_label(r),
            xy: xy(&|f| Some(micro.value(f.minimum_film.si()))),
            marks: marks_mm(r),
            ..Default::default()
        },
    ];
    let lambda = xy(&|f| f.lambda.map(|l| l.0));
    if lambda.iter().any(|(_, p)| !p.is_empty()) {
        panels.push(Panel {
            y_label: "film parameter Λ_HCS (He–Cho–Singh)".into(),
            x_label: along_label(r),
            xy: lambda,
            marks: marks_mm(r),
            ..Default::default()
        });
    }
    figure(&format!("{}: film thickness and Λ_HCS along the line of action", r.title), &panels)
}
