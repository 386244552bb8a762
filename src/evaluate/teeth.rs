//! The teeth as bodies, when a scene asks for them (`transmission_error`, `mesh_stiffness =
//! potential_energy`, or a pair that gives a relief, root or bore): the pair's stiffness, ISO 6336-1
//! Method B beside it, the largest single-pair stiffness located, and the transmission error at
//! each asked torque.

use crate::geometry::stiffness::iso_6336;
use crate::geometry::teeth::iso_6336_method_b::IsoStiffness;
use crate::geometry::teeth::load_sharing::LoadSharing;
use crate::geometry::teeth::transmission_error::TransmissionError;
use crate::geometry::PairGeometry;
use crate::mesh::MeshProblem;
use crate::numerics::roots::extrema;

/// What the report's stiffness and transmission-error sections read.
#[derive(Debug, Clone)]
pub struct TeethDetails {
    pub sharing: LoadSharing,
    pub iso: IsoStiffness,
    /// (k_w, s) of the stiffest single pair, located.
    pub max_single: (f64, f64),
    pub transmission_error: Vec<TransmissionError>,
}

/// The details, when the mesh's problem asks for them (lowering has checked that they can be computed).
pub fn teeth_details(problem: &MeshProblem, g: &PairGeometry) -> Option<TeethDetails> {
    if !problem.gears.wants_teeth(&problem.analyses, problem.dynamics.as_ref()) {
        return None;
    }
    let stiffness = problem.gears.pair_stiffness()?;
    let iso = iso_6336::method_b(g, &problem.gears.bodies());
    let xtol = 1e-13 * stiffness.path;
    let scale = stiffness.per_width(0.5 * stiffness.path);
    let (_, (k, at)) = extrema(|s| stiffness.per_width(s) / scale, &[0.0, stiffness.path], 32, xtol);
    let sharing = LoadSharing { stiffness, reliefs: problem.gears.reliefs() };
    let torques = problem.analyses.transmission_error.as_ref().map_or(&[][..], |t| &t.values[..]);
    let transmission_error =
        torques.iter().map(|t| sharing.transmission_error(t.value, g.base_radius[0])).collect::<Vec<_>>();
    Some(TeethDetails { sharing, iso, max_single: (k * scale, at), transmission_error })
}
