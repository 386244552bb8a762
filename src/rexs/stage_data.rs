//! A cylindrical stage as the import reads it: its two gears (pinion first) and their places.

/// One gear of a stage.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct GearData {
    pub id: u64,
    pub teeth: u32,
    /// m_n (mm), β at the reference diameter (deg, signed: > 0 right hand), b (mm), α_n (deg), x.
    pub module: f64,
    pub helix_angle: f64,
    pub face_width: f64,
    pub pressure_angle: f64,
    pub profile_shift: f64,
    /// Whether the model gives x, and how x was found when it does not (a `chosen:` note).
    pub profile_shift_given: bool,
    pub profile_shift_note: Option<String>,
    /// d_a (mm) when given and plausible.
    pub tip_diameter: Option<f64>,
    pub shaft: u64,
    /// The mid-plane on its shaft's axial coordinate (mm).
    pub at: f64,
}

/// One cylindrical stage: [pinion, wheel].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct StageData {
    pub id: u64,
    pub name: String,
    pub gears: [GearData; 2],
    pub center_distance: Option<f64>,
    /// gearloss's `direction` (deg): from the pinion's shaft to the wheel's, in (v, w) seen from +u.
    pub direction: f64,
    pub face_width: f64,
}
