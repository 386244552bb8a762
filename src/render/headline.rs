//! The headline of a pair's report: the answer first, in its report.md and on the terminal. Per
//! analysis: the mesh efficiency (input power, mesh loss and η̄ per operating point, or the sweep's
//! corners and ranges when it has many points; the loss budget, the thermal balance and the map
//! are its one-stage drive's), and the dynamics (per formulation: stability verdict at the operating points,
//! unstable speed ranges of the map, peak dynamic factor and where, DTE peak-to-peak).

use super::markup::{counted, md, put};

use super::table::{fixed, header, law_words, row, sig};
use crate::report::dynamics::{DynamicsReport, FormulationReport};
use crate::report::friction::EfficiencyRecord;
use crate::report::Report;

/// Rows of the efficiency table before the headline shows the sweep's corners and ranges instead.
pub(crate) const HEADLINE_ROWS: usize = 12;

/// `239.3 N·m, 1500 rpm`: a record's operating point in the units the scene wrote.
pub(crate) fn point_label(r: &Report, e: &EfficiencyRecord) -> String {
    point_at(r, &e.pinion_torque, &e.pinion_speed)
}

/// `1500 lbf·in, 1800 rpm`: a torque and a speed (SI) in the units the scene wrote them in.
pub(crate) fn point_at(r: &Report, torque: &crate::report::number::Q, speed: &crate::report::number::Q) -> String {
    crate::report::number::operating_point_words(&r.torque_unit, &r.speed_unit, torque, speed)
}

/// Efficiency: a row per operating point and law (the first formulation), or when there
/// are more than [`HEADLINE_ROWS`] the sweep's four corners per law and each law's range.
pub(crate) fn efficiency(out: &mut String, r: &Report) {
    let Some(first) = r.efficiency.first().map(|e| e.formulation) else { return };
    let recs: Vec<&EfficiencyRecord> = r.efficiency.iter().filter(|e| e.formulation == first).collect();
    let formulations = r.efficiency.iter().filter(|e| e.case == recs[0].case && e.label == recs[0].label).count();
    let shown: Vec<&EfficiencyRecord> = if recs.len() <= HEADLINE_ROWS { recs.clone() } else { corners(&recs) };
    let u = r.units();
    let (kw, w) = (u.kilowatt(), u.power());
    let cols =
        vec!["operating point".to_string(), kw.heading("P_in"), "law".into(), "η̄ mesh %".into(), w.heading("P mesh")];
    md!(
        out,
        "Efficiency, {} formulation{}{}:\n",
        first.name(),
        if formulations > 1 { " (the others under Efficiency)" } else { "" },
        if shown.len() < recs.len() { "; the sweep's corners, then each law's range" } else { "" }
    );
    header(out, &cols);
    for e in &shown {
        let cells = [
            point_label(r, e),
            kw.cell(e.pinion_torque.si() * e.pinion_speed.si(), 3),
            law_words(&e.label),
            fixed(100.0 * e.mean_efficiency.0, 3),
            w.q(&e.power_loss, 2),
        ];
        row(out, &cells);
    }
    md!(out);
    if shown.len() < recs.len() {
        ranges(out, r, &recs);
    }
}

/// The records' law labels, each once, in the order they first appear.
fn laws_in_order<'a>(recs: &[&'a EfficiencyRecord]) -> Vec<&'a str> {
    let mut labels: Vec<&str> = Vec::new();
    for e in recs {
        if !labels.contains(&e.label.as_str()) {
            labels.push(&e.label);
        }
    }
    labels
}

/// Per law, the records at the lowest and highest torque and speed of the sweep.
fn corners<'a>(recs: &[&'a EfficiencyRecord]) -> Vec<&'a EfficiencyRecord> {
    let (t0, t1) = (recs.iter().map(|e| e.torque_index).min(), recs.iter().map(|e| e.torque_index).max());
    let (s0, s1) = (recs.iter().map(|e| e.speed_index).min(), recs.iter().map(|e| e.speed_index).max());
    let mut out: Vec<&EfficiencyRecord> = Vec::new();
    for label in laws_in_order(recs) {
        for (t, s) in [(t0, s0), (t0, s1), (t1, s0), (t1, s1)] {
            let hit = recs.iter().find(|e| e.label == label && Some(e.torque_index) == t && Some(e.speed_index) == s);
            if let Some(e) = hit.filter(|e| !out.iter().any(|o| std::ptr::eq(*o, **e))) {
                out.push(e);
            }
        }
    }
    out
}

/// Per law the lowest and highest mesh efficiency with their points: over every operating point of
/// the sweep (its extremes, located as the points were computed), else over the records the report
/// keeps.
fn ranges(out: &mut String, r: &Report, recs: &[&EfficiencyRecord]) {
    let eta = |e: &EfficiencyRecord| e.mean_efficiency.0;
    let what = "η̄ mesh";
    let formulation = recs.first().map(|e| e.formulation.name()).unwrap_or_default();
    for label in laws_in_order(recs) {
        let swept = r.sweep.as_ref().and_then(|s| {
            let x = s.efficiency.iter().find(|x| x.label == label && x.formulation == formulation)?;
            let (lo, hi) = (x.min_efficiency.as_ref()?, x.max_efficiency.as_ref()?);
            let at = |v: &crate::report::sweep::ValueAt<crate::report::number::Num>| {
                Some((v.value.0, point_at(r, v.pinion_torque.as_ref()?, v.pinion_speed.as_ref()?)))
            };
            Some((at(lo)?, at(hi)?, s.operating_points))
        });
        let kept = || {
            let of: Vec<&&EfficiencyRecord> = recs.iter().filter(|e| e.label == label).collect();
            let lo = of.iter().min_by(|a, b| eta(a).total_cmp(&eta(b)))?;
            let hi = of.iter().max_by(|a, b| eta(a).total_cmp(&eta(b)))?;
            Some(((eta(lo), point_label(r, lo)), (eta(hi), point_label(r, hi)), of.len()))
        };
        if let Some(((lo, lo_at), (hi, hi_at), count)) = swept.or_else(kept) {
            md!(
                out,
                "- {}: {what} from {} % ({lo_at}) to {} % ({hi_at}) over {count} operating points.",
                law_words(label),
                fixed(100.0 * lo, 3),
                fixed(100.0 * hi, 3),
            );
        }
    }
    md!(out);
}

/// Dynamics: per formulation the verdict at the operating points, the map's unstable ranges, the
/// peak dynamic factor with its point and the DTE peak-to-peak range.
pub(crate) fn dynamics(out: &mut String, d: &DynamicsReport, u: crate::report::units::Units) {
    let Some(first) = d.points.first() else {
        if let Some(map) = &d.stability_map {
            map_ranges(out, d, map, u);
        }
        return;
    };
    md!(out, "Dynamics ({} model, {}):\n", d.model, counted(d.points.len(), "operating point", "operating points"));
    for (i, f) in first.formulations.iter().enumerate() {
        fn nth(p: &crate::report::dynamics::DynamicsPointReport, i: usize) -> Option<&FormulationReport> {
            p.formulations.get(i)
        }
        let at = |p| nth(p, i);
        let rho = d.points.iter().filter_map(at).map(|x| x.spectral_radius.0).fold(0.0, f64::max);
        let unstable: Vec<&str> = d
            .points
            .iter()
            .filter(|p| at(p).is_some_and(|x| x.verdict == crate::dynamics::floquet::Verdict::Unstable))
            .map(|p| p.label.as_str())
            .collect();
        let verdict = if unstable.is_empty() {
            format!("stable at every operating point (largest ρ {})", fixed(rho, 4))
        } else {
            format!("**unstable** at {} (largest ρ {})", unstable.join("; "), fixed(rho, 4))
        };
        let kv = d
            .points
            .iter()
            .filter_map(|p| at(p).and_then(|x| x.dynamic_factor).map(|k| (k.0, p.label.as_str())))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        let dte: Vec<f64> = d
            .points
            .iter()
            .filter_map(|p| at(p).and_then(|x| x.dte_peak_to_peak))
            .map(|q| u.micro().value(q.si()))
            .collect();
        let mut line = format!("- {}: {verdict}", f.formulation.name());
        if let Some((k, label)) = kv {
            put!(line, "; peak K_v {} at {label}", fixed(k, 3));
        }
        if let (Some(lo), Some(hi)) = (dte.iter().copied().reduce(f64::min), dte.iter().copied().reduce(f64::max)) {
            let (unit, d) = (u.micro().unit, u.micro().decimals(3));
            if fixed(lo, d) == fixed(hi, d) {
                put!(line, "; DTE peak-to-peak {} {unit}", fixed(lo, d));
            } else {
                put!(line, "; DTE peak-to-peak {}–{} {unit}", fixed(lo, d), fixed(hi, d));
            }
        }
        md!(out, "{line}.");
    }
    md!(out);
    if let Some(map) = &d.stability_map {
        map_ranges(out, d, map, u);
    }
}

/// The stability map's located unstable speed ranges, per formulation.
fn map_ranges(
    out: &mut String,
    _d: &DynamicsReport,
    map: &crate::report::dynamics::StabilityMapReport,
    u: crate::report::units::Units,
) {
    let unit = &map.speed_unit;
    let end = map.points.last().map(|p| p.pinion_speed.si());
    for (f, ranges) in map.formulations.iter().zip(&map.unstable_ranges) {
        let list: Vec<String> = ranges
            .iter()
            .map(|[a, b]| {
                let open = if Some(b.si()) == end { " (to the map's end)" } else { "" };
                format!("{:.0}–{:.0} {}{open}", unit.value(a), unit.value(b), unit.name)
            })
            .collect();
        md!(
            out,
            "- Stability map, {} at {} {}: {}.",
            f.name(),
            sig(u.torque().value(map.pinion_torque.si())),
            u.torque().unit,
            if list.is_empty() {
                "stable over the whole map".to_string()
            } else {
                format!("unstable at {}", list.join(", "))
            }
        );
    }
    md!(out);
}
