//! Plots over the operating sweeps: mean efficiency and power loss against speed or torque, the
//! composite law's mean |μ| against speed, and η̄ against a swept μ.

use super::panel::{figure, Panel, Shading};
use crate::report::Report;

/// Mean η and power loss against the swept variable, at each value of the other one.
/// `by_speed`: x is the pinion speed (in the unit the scene wrote), one curve per (law, formulation, torque); else x is torque.
pub fn sweep(r: &Report, by_speed: bool) -> Result<String, String> {
    use crate::report::friction::EfficiencyRecord;
    // Records are grouped by their sweep indices, never by formatted values.
    let x_index = |rec: &EfficiencyRecord| if by_speed { rec.speed_index } else { rec.torque_index };
    let x_of = |rec: &EfficiencyRecord| {
        if by_speed {
            r.speed_unit.value(&rec.pinion_speed)
        } else {
            r.torque_unit.value(&rec.pinion_torque)
        }
    };
    let other = |rec: &EfficiencyRecord| {
        if by_speed {
            format!("{} {}", crate::render::table::sig(r.torque_unit.value(&rec.pinion_torque)), r.torque_unit.shown())
        } else {
            format!("{:.0} {}", r.speed_unit.value(&rec.pinion_speed), r.speed_unit.name)
        }
    };
    // One curve per picked value of the other variable ([`Report::sweep_curves`]).
    let on_curve = |rec: &&EfficiencyRecord| {
        let (t, s) = &r.sweep_curves;
        if by_speed {
            t.binary_search(&rec.torque_index).is_ok()
        } else {
            s.binary_search(&rec.speed_index).is_ok()
        }
    };
    let records: Vec<&EfficiencyRecord> = r.efficiency.iter().filter(on_curve).collect();
    // (sweep index, x), sorted by x.
    let mut columns: Vec<(usize, f64)> = Vec::new();
    for rec in &records {
        if !columns.iter().any(|(i, _)| *i == x_index(rec)) {
            columns.push((x_index(rec), x_of(rec)));
        }
    }
    columns.sort_by(|a, b| a.1.total_cmp(&b.1));
    let xs: Vec<f64> = columns.iter().map(|c| c.1).collect();
    let (labels, shading) = curves(r, &records, by_speed, &other);
    let mut eta: Vec<(String, Vec<f64>)> = labels.iter().map(|l| (l.clone(), vec![f64::NAN; xs.len()])).collect();
    let mut loss = eta.clone();
    let power = r.units().power();
    for rec in &records {
        let l = format!("{} {} @ {}", rec.label, crate::report::formulation_name(rec.formulation), other(rec));
        let i = labels.iter().position(|x| *x == l).expect("label collected above");
        let j = columns.iter().position(|c| c.0 == x_index(rec)).expect("column collected above");
        eta[i].1[j] = 100.0 * rec.mean_efficiency.0;
        loss[i].1[j] = power.value(rec.power_loss.si());
    }
    let x_label = if by_speed {
        format!("pinion speed ({})", r.speed_unit.name)
    } else {
        format!("pinion torque ({})", r.torque_unit.shown())
    };
    let panels = [
        Panel {
            y_label: "mean mesh efficiency η̄ (%)".into(),
            x_label: x_label.clone(),
            x: xs.clone(),
            series: eta,
            shading: Some(shading.clone()),
            ..Default::default()
        },
        Panel {
            y_label: power.titled("mesh friction power loss, all contacts"),
            x_label,
            x: xs,
            series: loss,
            shading: Some(shading),
            ..Default::default()
        },
    ];
    let what = if by_speed { "speed" } else { "torque" };
    figure(&format!("{}: mean efficiency and power loss against {what}", r.title), &panels)
}

/// The sweep plot's curves: one per law, formulation and value of the other variable, labelled
/// in order of first appearance, with their group (law and formulation) and the other variable's
/// value for the colour scale when there are too many curves to label one by one.
fn curves(
    r: &Report,
    records: &[&crate::report::friction::EfficiencyRecord],
    by_speed: bool,
    other: &dyn Fn(&crate::report::friction::EfficiencyRecord) -> String,
) -> (Vec<String>, Shading) {
    let mut labels: Vec<String> = Vec::new();
    let mut shading = Shading {
        value_label: if by_speed {
            format!("pinion torque ({})", r.torque_unit.shown())
        } else {
            format!("pinion speed ({})", r.speed_unit.name)
        },
        ..Default::default()
    };
    for rec in records {
        let l = format!("{} {} @ {}", rec.label, crate::report::formulation_name(rec.formulation), other(rec));
        if !labels.contains(&l) {
            labels.push(l);
            let group = format!("{} {}", rec.label, crate::report::formulation_name(rec.formulation));
            let g = match shading.group_labels.iter().position(|x| *x == group) {
                Some(g) => g,
                None => {
                    shading.group_labels.push(group);
                    shading.group_labels.len() - 1
                }
            };
            shading.group.push(g);
            shading.value.push(if by_speed {
                r.torque_unit.value(&rec.pinion_torque)
            } else {
                r.speed_unit.value(&rec.pinion_speed)
            });
        }
    }
    (labels, shading)
}

/// composite_mu_vs_speed.svg: mean |μ| of the composite law against speed, per torque (He–Cho–Singh Fig. 2b).
pub fn composite_mu_vs_speed(r: &Report) -> Result<String, String> {
    let mut xs: Vec<f64> = Vec::new();
    let mut series: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let curve_torques = &r.sweep_curves.0;
    for (ti, torque, speed, law, mu) in &r.composite_mu {
        if curve_torques.binary_search(ti).is_err() {
            continue;
        }
        let speed = r.speed_unit.of_si(*speed);
        let label =
            format!("{law} @ {} {}", crate::render::table::sig(r.torque_unit.of_si(*torque)), r.torque_unit.shown());
        match series.iter_mut().find(|(l, _)| *l == label) {
            Some((_, v)) => v.push((speed, *mu)),
            None => series.push((label, vec![(speed, *mu)])),
        }
        xs.push(speed);
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let series = series
        .into_iter()
        .map(|(l, pts)| {
            let ys = xs.iter().map(|x| pts.iter().find(|(px, _)| px == x).map_or(f64::NAN, |p| p.1)).collect();
            (l, ys)
        })
        .collect();
    let panel = Panel {
        y_label: "mean |μ| over A–E".into(),
        x_label: format!("pinion speed ({})", r.speed_unit.name),
        x: xs,
        series,
        ..Default::default()
    };
    figure(&format!("{}: composite law, mean |μ| against speed", r.title), &[panel])
}

/// sweep_mu.svg: mean η and power loss against μ for swept laws, at up to three operating points.
pub fn sweep_mu(r: &Report) -> Result<String, String> {
    let laws = crate::report::friction::mu_swept_laws(&r.efficiency);
    let ops: Vec<usize> = match r.operating_points.len() {
        0 => Vec::new(),
        1 => vec![0],
        2 => vec![0, 1],
        n => vec![0, n / 2, n - 1],
    };
    let mut xs: Vec<f64> = Vec::new();
    // (legend, [(μ, η̄ %, P_loss W)])
    type Curve = (String, Vec<(f64, f64, f64)>);
    let mut curves: Vec<Curve> = Vec::new();
    let power = r.units().power();
    for rec in r.efficiency.iter().filter(|x| laws.contains(&x.law)) {
        let Some(k) = ops.iter().position(|&k| r.operating_points[k].index == rec.case) else {
            continue;
        };
        let Some(mu) = rec.parameters.get("mu") else { continue };
        let label = format!(
            "{} {} @ {}",
            rec.law,
            crate::report::formulation_name(rec.formulation),
            r.operating_points[ops[k]].label
        );
        xs.push(mu);
        let point = (mu, 100.0 * rec.mean_efficiency.0, power.value(rec.power_loss.si()));
        match curves.iter_mut().find(|(l, _)| *l == label) {
            Some((_, v)) => v.push(point),
            None => curves.push((label, vec![point])),
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let pick = |j: usize| -> Vec<(String, Vec<f64>)> {
        curves
            .iter()
            .map(|(l, pts)| {
                let ys = xs
                    .iter()
                    .map(|x| pts.iter().find(|p| p.0 == *x).map_or(f64::NAN, |p| if j == 1 { p.1 } else { p.2 }))
                    .collect();
                (l.clone(), ys)
            })
            .collect()
    };
    let panels = [
        Panel {
            y_label: "mean mesh efficiency η̄ (%)".into(),
            x_label: "coefficient of friction μ".into(),
            x: xs.clone(),
            series: pick(1),
            ..Default::default()
        },
        Panel {
            y_label: power.titled("friction power loss"),
            x_label: "coefficient of friction μ".into(),
            x: xs.clone(),
            series: pick(2),
            ..Default::default()
        },
    ];
    figure(&format!("{}: mean efficiency and power loss against μ", r.title), &panels)
}
