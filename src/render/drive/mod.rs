//! The files of a drive's report folder: report.md ([`markdown`]), report.json (the serde data),
//! power_flow.svg ([`power_flow`]: the power from input to output with every loss branching off),
//! with a gearbox loss_budget.svg ([`loss_budget`]: each kept point's losses part by part),
//! each helical stage mesh's `plane_of_action_<stage>.svg` (the figure of a helical pair's report),
//! with a thermal balance or a duty cycle a pair's heat_balance.svg, duty_cycle_temperature.svg and
//! duty_cycle_energy.svg, with shafts that have sections shaft_moments.svg ([`shaft_bending`]) and,
//! with a map, loss_map.svg (total loss and η over the ends' torque × speed, drive above zero
//! torque, coast below) and loss_map.csv (its cells as data). Renderers read the [`DriveReport`];
//! they never compute physics.

pub(crate) mod cycle;
pub(crate) mod cycle_plots;
pub(crate) mod kind_pieces;
pub(crate) mod loss_budget;
pub(crate) mod loss_map;
pub(crate) mod markdown;
pub(crate) mod oil_sweep;
pub(crate) mod planetary;
pub(crate) mod point_tables;
pub(crate) mod power_flow;
pub(crate) mod shaft_bending;
pub(crate) mod shown_units;
pub(crate) mod stage_pairs;

use crate::render::RenderedReport;
use crate::report::drive::DriveReport;

/// report.json of a drive: pretty, plain arrays on one line.
pub(crate) fn render_drive_json(report: &DriveReport) -> String {
    crate::render::json_text::json_text(report, "the report")
}

/// Every file of a drive's report folder.
pub(crate) fn render_drive(report: &DriveReport) -> Result<RenderedReport, String> {
    let mut files = vec![
        ("report.md".to_string(), markdown::render_drive_markdown(report)),
        ("report.json".to_string(), render_drive_json(report)),
    ];
    if let Some(svg) = power_flow::power_flow(report)? {
        files.push((power_flow::FILE.to_string(), svg));
    }
    if let Some(svg) = loss_budget::loss_budget(report) {
        files.push((loss_budget::FILE.to_string(), svg?));
    }
    if !report.maps.is_empty() {
        files.push((loss_map::FILE.to_string(), loss_map::loss_map(report)?));
        files.push((loss_map::CSV_FILE.to_string(), loss_map::csv(report)));
    }
    if let Some(svg) = shaft_bending::moments(report) {
        files.push((shaft_bending::FILE.to_string(), svg?));
    }
    for s in &report.stage_geometry {
        if let (Some(h), Some(p)) = (&s.geometry.helical, &s.plot) {
            let len = crate::report::units::Units::of_system(report.unit_system).length();
            let title = format!("{}: {}", report.title, p.title.replace('`', ""));
            files.push((p.file.clone(), crate::render::svg::plane_of_action_figure(&title, h, None, len)?));
        }
    }
    let units = crate::report::units::Units::of_system(report.unit_system);
    if let Some(h) = &report.heat.heat_balance {
        let svg = crate::render::svg::heat_balance_figure(&report.title, h, units)?;
        files.push((crate::report::PlotKind::HeatBalance.file().to_string(), svg));
    }
    if let Some(d) = &report.heat.duty_cycle {
        if d.samples.is_some() {
            let svg = crate::render::svg::duty_temperature_figure(&report.title, d, units)?;
            files.push((crate::report::PlotKind::DutyCycleTemperature.file().to_string(), svg));
        }
        let svg = crate::render::svg::duty_energy_figure(&report.title, d, units)?;
        files.push((crate::report::PlotKind::DutyCycleEnergy.file().to_string(), svg));
    }
    if let Some(c) = &report.cycle {
        files.push((crate::report::drive_cycle_series::FILE.to_string(), c.series.to_csv()));
        files.push((cycle_plots::TRACE_FILE.to_string(), cycle_plots::trace(&report.title, c)?));
        if !c.map.torques.is_empty() {
            files.push((
                cycle_plots::MAP_FILE.to_string(),
                cycle_plots::map(&report.title, c, shown_units::Shown::of(report))?,
            ));
        }
    }
    Ok(RenderedReport { slug: report.slug.clone(), files })
}
