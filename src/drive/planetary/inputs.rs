//! A planetary stage's inputs in the report (its `StageModel::inputs`): its members and where they
//! sit, the planets, the ratios, both meshes' sizes, the assembly and neighbour conditions with
//! their numbers.

use serde::{Deserialize, Serialize};

use crate::drive::kinematics::planetary::{stationary_ratio, PlanetaryLayout, PlanetaryMember};
use crate::drive::layout::{Drive, Stage};
use crate::geometry::PairGeometry;

/// A planetary stage as the scene gives it.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PlanetaryInputs {
    pub planets: u32,
    /// K_γ: the most loaded planet's share over the mean (1: equal sharing).
    pub load_sharing_factor: f64,
    /// [sun, planet, ring].
    pub teeth: [u32; 3],
    /// Each member with its shaft ("housing" where held).
    pub members: Vec<(PlanetaryMember, String)>,
    /// i₀ = −z_ring/z_sun and the ratio ω_place0/ω_place1 with the held member at rest.
    pub stationary_ratio: f64,
    pub ratio: f64,
    /// (z_sun + z_ring)/n, a whole number.
    pub assembly: f64,
    /// 2 a_w sin(π/n) − d_a,planet (mm): the gap between neighbouring planets' tips (none for one
    /// planet: left out of report.json, where a null would read as a number that is not finite).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub neighbour_gap_mm: Option<f64>,
    /// The planet–ring mesh: its working pressure angle (°), ε_α, the ring's tip diameter (mm).
    pub ring_pressure_angle_deg: f64,
    pub ring_contact_ratio: f64,
    pub ring_tip_diameter_mm: f64,
    pub planet_mass_kg: f64,
    /// The planet's bearing: type × count per planet, mean diameter (mm); "" without.
    pub planet_bearing: String,
}

/// The inputs of planetary stage `stage` (`p` its layout) on `layout`'s shafts; `ring` is its
/// planet–ring mesh's geometry (its mesh 1).
pub(crate) fn planetary_inputs(
    layout: &Drive,
    stage: &Stage,
    p: &PlanetaryLayout,
    ring: Option<&PairGeometry>,
) -> Option<PlanetaryInputs> {
    let ring = ring?;
    let shaft_of = |m: PlanetaryMember| {
        p.place_of(m).map_or_else(|| "housing".to_string(), |i| layout.shafts[stage.places[i].shaft].name.clone())
    };
    let speeds = p.kinematics().member_speeds(p.members[0], 1.0);
    let n = f64::from(p.planets);
    Some(PlanetaryInputs {
        planets: p.planets,
        load_sharing_factor: p.load_sharing_factor,
        teeth: p.teeth,
        members: PlanetaryMember::ALL.iter().map(|m| (*m, shaft_of(*m))).collect(),
        stationary_ratio: stationary_ratio(p.teeth[0], p.teeth[2]),
        ratio: speeds[p.members[0].index()] / speeds[p.members[1].index()],
        assembly: f64::from(p.teeth[0] + p.teeth[2]) / n,
        neighbour_gap_mm: (p.planets > 1)
            .then(|| (2.0 * p.center_distance * (std::f64::consts::PI / n).sin() - 2.0 * p.planet_tip_radius) * 1e3),
        ring_pressure_angle_deg: ring.operating_pressure_angle.to_degrees(),
        ring_contact_ratio: ring.contact_ratio,
        ring_tip_diameter_mm: 2e3 * ring.tip_radius[1],
        planet_mass_kg: p.planet_mass,
        planet_bearing: p.planet_bearing.map_or_else(String::new, |b| {
            format!(
                "{} × {} per planet, d_m {} mm",
                b.kind.name(),
                b.count,
                crate::numerics::rounding::sig(b.mean_diameter * 1e3)
            )
        }),
    })
}
