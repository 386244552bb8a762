//! SVG plots drawn with plotters' SVG backend (no system fonts: text is laid out by plotters' own estimate).
//! Every plot reads the report only.

mod contact;
mod contours;
mod curve;
mod dynamics;
mod helical;
mod losses;
pub(crate) mod maps;
mod palette;
mod panel;
mod sweeps;
mod teeth;
mod thermal;

pub use contact::{contact_state, film, point_friction};
pub(crate) use contours::Field;
pub use dynamics::{dynamics_point, free_response, stability_map, work_precision};
pub(crate) use helical::figure as plane_of_action_figure;
pub use helical::plane_of_action;
pub(crate) use losses::{budget_bars, draw_field};
pub use maps::efficiency_map;
pub(crate) use panel::fitted;
pub use panel::{figure, figure_with_legend, Panel};
pub use sweeps::{composite_mu_vs_speed, sweep, sweep_mu};
pub use teeth::{load_share, mesh_stiffness, transmission_error};
pub(crate) use thermal::{duty_energy_figure, duty_temperature_figure, heat_balance_figure};
