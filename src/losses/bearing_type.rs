//! The rolling-bearing types the budget knows, with Palmgren's f_0, f_1 and P_1 of each (the table
//! and its sources are in [`super::bearings`]).

/// Y of a tapered roller bearing when the scene gives none: the axial load factor of the small
/// single-row tapered roller bearings of the 302 and 303 series (e.g. 30206: e = 0.37, Y = 1.6, in
/// SKF's and the other makers' catalogues). Give `y` for the bearing's own.
pub(crate) const TAPERED_Y: f64 = 1.6;

/// The bearing types of the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BearingType {
    DeepGrooveBall,
    AngularContactBall,
    CylindricalRoller,
    TaperedRoller,
    SphericalRoller,
}

impl BearingType {
    pub const NAMES: &'static [&'static str] =
        &["deep_groove_ball", "angular_contact_ball", "cylindrical_roller", "tapered_roller", "spherical_roller"];
    const ALL: [BearingType; 5] = [
        BearingType::DeepGrooveBall,
        BearingType::AngularContactBall,
        BearingType::CylindricalRoller,
        BearingType::TaperedRoller,
        BearingType::SphericalRoller,
    ];

    pub fn from_name(name: &str) -> Option<Self> {
        Self::NAMES.iter().position(|n| *n == name).map(|i| Self::ALL[i])
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// f_0 for oil-bath lubrication.
    pub fn f0(self) -> f64 {
        match self {
            BearingType::DeepGrooveBall | BearingType::AngularContactBall => 2.0,
            BearingType::CylindricalRoller => 2.5,
            BearingType::TaperedRoller => 4.5,
            BearingType::SphericalRoller => 5.0,
        }
    }

    /// Whether f_1 needs the static load rating C_0.
    pub fn needs_static_rating(self) -> bool {
        matches!(self, BearingType::DeepGrooveBall | BearingType::AngularContactBall | BearingType::SphericalRoller)
    }

    /// f_1 at radial and axial loads F_r, F_a (N) and static rating C_0 (N, where needed).
    pub fn f1(self, fr: f64, fa: f64, c0: Option<f64>) -> Option<f64> {
        let p0 = static_equivalent_load(fr, fa);
        Some(match self {
            BearingType::DeepGrooveBall => 0.0007 * (p0 / c0?).powf(0.5),
            BearingType::AngularContactBall => 0.001 * (p0 / c0?).powf(0.33),
            BearingType::CylindricalRoller => 0.0003,
            BearingType::TaperedRoller => 0.0004,
            BearingType::SphericalRoller => 0.0005 * (p0 / c0?).powf(0.33),
        })
    }

    /// P_1 (N) at F_r, F_a; `y` the tapered roller bearing's axial load factor.
    pub fn p1(self, fr: f64, fa: f64, y: f64) -> f64 {
        match self {
            BearingType::DeepGrooveBall => (3.0 * fa - 0.1 * fr).max(fr),
            BearingType::AngularContactBall => (fa - 0.1 * fr).max(fr),
            BearingType::CylindricalRoller => fr,
            BearingType::TaperedRoller => (2.0 * y * fa).max(fr),
            BearingType::SphericalRoller => (fr + 2.5 * fa).max(fr),
        }
    }
}

/// The static equivalent load P_0 = max(0.6 F_r + 0.5 F_a, F_r) (N) that Palmgren's f_1 reads
/// against C_0 (SKF General Catalogue 4000 E, 1989, the deep groove ball bearing's factors).
pub(crate) fn static_equivalent_load(fr: f64, fa: f64) -> f64 {
    (0.6 * fr + 0.5 * fa).max(fr)
}

/// The largest static load ratio P_0/C_0 the bearing models read as data: f_1's power laws in
/// P_0/C_0 were fitted for bearings inside their static rating (static safety s_0 = C_0/P_0 ≥ 1,
/// ISO 76); beyond it the bearing deforms permanently and its loss is extrapolated. A report
/// warns at the bearing and the point where a ratio exceeds it.
pub(crate) const MAX_STATIC_LOAD_RATIO: f64 = 1.0;
