//! A shaft's supports under its gears' loads: the reactions of every bearing place (a rigid beam's
//! statics on two places, the elastic beam of [`super::shaft_beam`] on more) and, for a shaft with
//! sections, its bending: the deflection and slope at each gear, the bending moment along it and
//! the largest bending stress, located.
//!
//! The bending moment in each plane follows from the loads and the reactions alone (statics, not
//! the stiffness solve): M(z) = Σ_{z_i < z} (F_i (z − z_i) − C_i), with a jump of −C at a gear whose
//! axial force makes a couple. Its resultant |M| = √(M_x² + M_y²) is a norm of a function affine in
//! z between nodes, so convex there: its largest value on an element is at one of its ends. The
//! largest stress σ = |M|/W (W = π (D⁴ − d⁴)/(32 D)) is therefore located exactly by the one-sided
//! limits at every node, each with the section on its own side (Niemann & Winter,
//! *Maschinenelemente* I, the nominal bending stress of a shaft).

use serde::{Deserialize, Serialize};

use super::forces::GearLoad;
use super::layout::{Member, Shaft};
use super::shaft_beam::{solve, BeamSolution, BeamTheory, PlaneLoad, PreparedBeam, Support};

/// A gear on its bent shaft.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GearDeflection {
    pub stage: usize,
    pub member: Member,
    /// Its `at` (m).
    pub at: f64,
    /// [w_x, w_y] (m) and the section's rotation [θ_x, θ_y] (rad, each plane's slope).
    pub deflection: [f64; 2],
    pub slope: [f64; 2],
}

/// A shaft's bending at one operating point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShaftBending {
    pub theory: BeamTheory,
    pub gears: Vec<GearDeflection>,
    /// At each node: z (m), the resultant bending moment just left of it and just right of it (N·m).
    pub moment: Vec<[f64; 3]>,
    /// The largest nominal bending stress (Pa), where (m), the moment there (N·m) and the section's
    /// outer diameter there (m).
    pub max_stress: f64,
    pub max_stress_at: f64,
    pub max_stress_moment: f64,
    pub max_stress_diameter: f64,
    /// The largest deflection |w| over the nodes (m) and where.
    pub max_deflection: f64,
    pub max_deflection_at: f64,
}

/// The reactions [R_x, R_y, R_z] (N, on the shaft) of every place of `shaft` under `on`, and with
/// `bent` its bending when it has sections. One place (a floating sun's shaft): −ΣF. Two places: the rigid beam's statics
/// ([`super::statics::shaft_reactions`], whatever the sections and springs: two places are
/// statically determinate); more: the elastic beam. The locating place takes −ΣF_z.
/// `beam`, when given, is the shaft's beam made ready ([`shaft_beam_of`]); else it is made here.
pub fn support_reactions(
    shaft: &Shaft,
    on: &[GearLoad],
    bent: bool,
    beam: Option<&PreparedBeam>,
) -> (Vec<[f64; 3]>, Option<ShaftBending>) {
    if shaft.bearings.iter().any(|b| b.position.is_none()) {
        return (shared_reactions(shaft, on), None);
    }
    let positions: Vec<f64> = shaft.bearings.iter().map(|b| b.position.unwrap_or(0.0)).collect();
    let needs_beam = positions.len() > 2 || (bent && shaft.body.is_some());
    let planes = plane_loads(on);
    let solution = match (&shaft.body, needs_beam) {
        (Some(body), true) => beam.and_then(|b| b.solve(&planes)).or_else(|| solve(body, &supports(shaft), &planes)),
        _ => None,
    };
    let reactions: Vec<[f64; 3]> = match (positions.as_slice(), &solution) {
        // A floating sun's shaft: its one place takes what its planets leave, nothing with n ≥ 2
        // equally spaced planets but the helical sun's axial force.
        ([_], _) => vec![[0, 1, 2].map(|k| -on.iter().map(|l| l.force[k]).sum::<f64>())],
        ([a, b], _) => super::statics::shaft_reactions(on, [*a, *b], shaft.locating).to_vec(),
        (_, Some(s)) => {
            let axial: f64 = -on.iter().map(|l| l.force[2]).sum::<f64>();
            s.reactions
                .iter()
                .enumerate()
                .map(|(i, r)| [r[0], r[1], if i == shaft.locating { axial } else { 0.0 }])
                .collect()
        }
        // Lowering gives every shaft of more than two places its sections; a beam that cannot be
        // solved shows as NaN, which the report refuses to print silently.
        (_, None) => vec![[f64::NAN; 3]; positions.len()],
    };
    let bending = match (bent, &shaft.body, &solution) {
        (true, Some(body), Some(s)) => Some(bending(body, on, &positions, &reactions, s)),
        _ => None,
    };
    (reactions, bending)
}

/// The reactions of a shaft whose places have no positions (a one-pair scene's shaft written without
/// `at`, the pair's reading): every bearing carries an equal share of the gears' transverse force,
/// place i the share count_i/Σcount of −(ΣF_x, ΣF_y), and the locating place (the first unless one
/// says `locating`) the whole axial −ΣF_z. For one gear on the shaft each bearing's radial load is
/// F_bt/Σcount (|(F_t, F_r)| = F_bt), the one-pair budget's rule (`losses::parts::bearings`); the
/// moments of the mesh force are not taken up (no positions, no lever arms).
pub(crate) fn shared_reactions(shaft: &Shaft, on: &[GearLoad]) -> Vec<[f64; 3]> {
    let total: usize = shaft.bearings.iter().map(|b| b.count).sum();
    let sum = |k: usize| on.iter().map(|l| l.force[k]).sum::<f64>();
    let (fx, fy, fz) = (sum(0), sum(1), sum(2));
    shaft
        .bearings
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let share = b.count as f64 / total as f64;
            [-fx * share, -fy * share, if i == shaft.locating { -fz } else { 0.0 }]
        })
        .collect()
}

/// Shaft `shaft`'s beam made ready for loads at `gear_positions` (m); None without sections.
pub fn shaft_beam_of(shaft: &Shaft, gear_positions: &[f64]) -> Option<PreparedBeam> {
    PreparedBeam::new(shaft.body.as_ref()?, &supports(shaft), gear_positions)
}

/// The shaft's bearing places as the beam's supports: each `at` with its radial stiffness.
fn supports(shaft: &Shaft) -> Vec<Support> {
    shaft
        .bearings
        .iter()
        .enumerate()
        .map(|(i, b)| Support { at: b.position.unwrap_or(0.0), stiffness: shaft.stiffness.get(i).copied().flatten() })
        .collect()
}

fn bending(
    body: &super::shaft_beam::ShaftBody,
    on: &[GearLoad],
    positions: &[f64],
    reactions: &[[f64; 3]],
    s: &BeamSolution,
) -> ShaftBending {
    let mut items: Vec<PlaneLoad> = plane_loads(on);
    items.extend(positions.iter().zip(reactions).map(|(&at, r)| PlaneLoad {
        at,
        force: [r[0], r[1]],
        couple: [0.0, 0.0],
    }));
    let node_of: Vec<usize> = items.iter().map(|l| s.node(l.at)).collect();
    let mut moment = Vec::with_capacity(s.nodes.len());
    for (k, &z) in s.nodes.iter().enumerate() {
        let (mut left, mut jump) = ([0.0; 2], [0.0; 2]);
        for (l, &i) in items.iter().zip(&node_of) {
            for p in 0..2 {
                if i < k {
                    left[p] += l.force[p] * (z - l.at) - l.couple[p];
                } else if i == k {
                    jump[p] -= l.couple[p];
                }
            }
        }
        let right = [left[0] + jump[0], left[1] + jump[1]];
        moment.push([z, left[0].hypot(left[1]), right[0].hypot(right[1])]);
    }
    let mut most = (0.0_f64, s.nodes[0], 0.0, body.sections[0].outer_diameter);
    for k in 0..s.nodes.len().saturating_sub(1) {
        let Some(section) = body.section_at(0.5 * (s.nodes[k] + s.nodes[k + 1])) else { continue };
        for (z, m) in [(moment[k][0], moment[k][2]), (moment[k + 1][0], moment[k + 1][1])] {
            let sigma = m / section.section_modulus();
            if sigma > most.0 {
                most = (sigma, z, m, section.outer_diameter);
            }
        }
    }
    let (mut w_max, mut w_at) = (0.0_f64, s.nodes[0]);
    for (z, w) in s.nodes.iter().zip(&s.deflection) {
        if w[0].hypot(w[1]) > w_max {
            (w_max, w_at) = (w[0].hypot(w[1]), *z);
        }
    }
    ShaftBending {
        theory: body.theory,
        gears: on
            .iter()
            .map(|l| {
                let i = s.node(l.point[2]);
                GearDeflection {
                    stage: l.stage,
                    member: l.member,
                    at: l.point[2],
                    deflection: s.deflection[i],
                    slope: s.slope[i],
                }
            })
            .collect(),
        moment,
        max_stress: most.0,
        max_stress_at: most.1,
        max_stress_moment: most.2,
        max_stress_diameter: most.3,
        max_deflection: w_max,
        max_deflection_at: w_at,
    }
}

/// The mesh misalignment a stage's bent shafts imply (m): the face width times the two gears'
/// relative tilt projected on the line of action, |b (θ_pinion − θ_wheel) · ê|, ê the transverse
/// direction of the mesh force (ISO 6336-1:2019, 7.6: the component f_sh of the deformations in
/// the plane of action; reported, not fed back into the mesh).
pub fn mesh_misalignment(face_width: f64, pinion: &GearDeflection, wheel: &GearDeflection, force: [f64; 3]) -> f64 {
    let norm = force[0].hypot(force[1]);
    if norm == 0.0 {
        return 0.0;
    }
    let e = [force[0] / norm, force[1] / norm];
    let d = [pinion.slope[0] - wheel.slope[0], pinion.slope[1] - wheel.slope[1]];
    (face_width * (d[0] * e[0] + d[1] * e[1])).abs()
}

/// Each plane's loads of a shaft from its gears' force vectors: the transverse force at the gear's
/// `at`, and the axial force's couple at its point (x, y): −x F_z in the x–z plane, −y F_z in the
/// y–z plane.
pub fn plane_loads(loads: &[GearLoad]) -> Vec<PlaneLoad> {
    loads
        .iter()
        .map(|l| {
            let ([x, y, z], [fx, fy, fz]) = (l.point, l.force);
            PlaneLoad { at: z, force: [fx, fy], couple: [-x * fz, -y * fz] }
        })
        .collect()
}

/// Stage `k`'s mesh misalignment from its two gears' tilts on their bent shafts (a parallel stage
/// whose shafts both have sections), m: `bending` by shaft, `loads` every gear's.
pub(crate) fn stage_misalignment(
    bending: &[Option<&ShaftBending>],
    loads: &[GearLoad],
    (k, stage): (usize, &super::layout::Stage),
    face_width: f64,
) -> Option<f64> {
    if !stage.model().one_pair_on_two_shafts() {
        return None;
    }
    let gear = |m: usize| {
        let j = stage.places[m].shaft;
        let bent = bending.get(j).copied().flatten()?.gears.iter().find(|g| g.stage == k)?;
        let load = loads.iter().find(|l| l.stage == k && l.shaft == j)?;
        Some((bent, load.force))
    };
    let ((pinion, force), (wheel, _)) = (gear(0)?, gear(1)?);
    Some(mesh_misalignment(face_width, pinion, wheel, force))
}

/// Each shaft of `drive` with its beam made ready ([`shaft_beam_of`] at the places its stages put
/// gears on it).
pub(crate) fn prepared_beams(drive: &super::layout::Drive) -> Vec<Option<PreparedBeam>> {
    (0..drive.shafts.len())
        .map(|j| {
            let at: Vec<f64> =
                drive.stages.iter().flat_map(|s| s.places).filter(|p| p.shaft == j).map(|p| p.at).collect();
            shaft_beam_of(&drive.shafts[j], &at)
        })
        .collect()
}
