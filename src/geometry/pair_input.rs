//! What the pair geometry is computed from (SI), and the problems that stop a pair from meshing.

/// Largest ε_γ supported: at most [`super::contact_lines::MAX_LINES`] lines in contact.
pub(crate) const MAX_TOTAL_CONTACT_RATIO: f64 = 7.0;

/// What the geometry needs, in SI units (m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairInput {
    /// Normal module m_n (the module of a spur pair).
    pub module: f64,
    /// Normal pressure angle α_n.
    pub pressure_angle: f64,
    /// Helix angle β at the reference circle (0 for a spur pair).
    pub helix_angle: f64,
    /// [pinion, wheel]
    pub teeth: [u32; 2],
    pub profile_shift: [f64; 2],
    pub tip_diameter: [Option<f64>; 2],
    pub center_distance: Option<f64>,
    pub face_width: f64,
    /// An internal pair: the wheel is a ring with its teeth inside (ISO 21771). Its teeth, diameters
    /// and the centre distance are given as magnitudes; the geometry carries ISO's signs where the
    /// physics reads them ([`super::pair::PairGeometry::wheel_sign`]).
    pub internal: bool,
}

/// Which gear or quantity a geometry problem is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairPart {
    Teeth(usize),
    ProfileShift(usize),
    TipDiameter(usize),
    CenterDistance,
    Pair,
}

/// A pair that cannot mesh as specified.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryProblem {
    pub part: PairPart,
    pub reason: String,
    pub hint: String,
}

pub(crate) fn gear_name(i: usize) -> &'static str {
    if i == 0 {
        "pinion"
    } else {
        "wheel"
    }
}

/// The sign ISO 21771 gives the wheel's teeth, diameters and the centre distance: −1 for an
/// internal pair (a ring), +1 for an external one.
pub(crate) fn wheel_sign(internal: bool) -> f64 {
    if internal {
        -1.0
    } else {
        1.0
    }
}
