//! The lowered scene: names resolved, every quantity unit-checked and held as a uom value.
//!
//! This is what every later stage reads. Each given value keeps what the user wrote
//! (for the report's scene summary, in the user's units) and where (for diagnostics).

use uom::si::f64 as si;
use uom::si::{Quantity, ISQ, SI};
use uom::typenum::{N1, N2, N3, P1, P2, Z0};

use crate::diagnostics::Span;

pub use crate::efficiency::Formulation;
pub use crate::friction::catalog::{FrictionLawSpec, LawId};
pub use si::{
    Angle, AngularVelocity, Area, DiffusionCoefficient as KinematicViscosity, DynamicViscosity, Force, HeatCapacity,
    Length, Mass, MassDensity, MomentOfInertia, Pressure, ReciprocalLength, ThermodynamicTemperature, Time, Torque,
    Velocity, VolumeRate,
};

/// 1/Pa, the unit of the pressure–viscosity coefficient α (uom has no named quantity for it).
pub type ReciprocalPressure = Quantity<ISQ<P1, N1, P2, Z0, Z0, Z0, Z0>, SI<f64>, f64>;
/// N/m, the unit of mesh stiffness.
pub type Stiffness = Quantity<ISQ<Z0, P1, N2, Z0, Z0, Z0, Z0>, SI<f64>, f64>;
/// N·s/m (= kg/s), a road load's speed coefficient f1.
pub type MassRate = Quantity<ISQ<Z0, P1, N1, Z0, Z0, Z0, Z0>, SI<f64>, f64>;
/// N·s²/m² (= kg/m), a road load's square coefficient f2.
pub type MassPerLength = Quantity<ISQ<N1, P1, Z0, Z0, Z0, Z0, Z0>, SI<f64>, f64>;
/// W/K, the unit of a thermal conductance (a foundation, an oil cooler).
pub type ThermalConductance = Quantity<ISQ<P2, P1, N3, Z0, N1, Z0, Z0>, SI<f64>, f64>;

/// A value as the user gave it: the checked value, the text written and where.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Given<T> {
    pub value: T,
    pub written: String,
    pub span: Span,
}

/// One `.gear` scene after lowering.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Scene {
    pub title: String,
    pub gears: GearPair,
    pub lubricant: Option<Lubricant>,
    pub operating: Operating,
    pub friction: Vec<FrictionLawSpec>,
    pub dynamics: Option<DynamicsSpec>,
    /// Lubrication method, bearings and seals, for the loss budget beside the mesh.
    pub gearbox: Option<crate::losses::Gearbox>,
    /// The housing as a thermal node (`gearbox { housing { ... } }`).
    pub housing: Option<crate::thermal::Housing>,
    pub duty_cycle: Option<crate::thermal::DutyCycle>,
    pub analyses: Analyses,
    /// A scene written with `stage` blocks: its drive (then `gears` is the first stage's pair and
    /// `operating` holds the sweeps at the ends the drive names). None for a scene of one pair.
    pub drive: Option<SceneDrive>,
}

/// A drive of stages as the scene gives it: the checked layout and each stage's pair, in order.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SceneDrive {
    pub layout: crate::drive::Drive,
    /// Each stage's pair: a planetary stage's sun–planet pair (the sun as pinion).
    pub pairs: Vec<GearPair>,
    /// Each stage's meshes beyond its own pair, numbered 1, 2, … as its kind's `StageModel` numbers
    /// them (a planetary stage's planet–ring pair, internal, the planet as pinion); empty for a
    /// stage of one mesh.
    pub further_pairs: Vec<Vec<GearPair>>,
    /// A vehicle over a drive cycle, with the box as its drive.
    pub cycle: Option<DriveCycleSpec>,
    /// One pair (a `gears` block) as its one-stage drive, `pinion_torque` at the pinion gear (`scene/pair_stage.rs`).
    pub one_pair: bool,
    /// `oil_temperature = equilibrium`: each row of the sweep is evaluated at its own balance θ*
    /// (its records then hold θ* and the sump's status).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub oil_at_balance: bool,
    /// `analyses { thermal_balance }` with a housing at a given oil temperature: every row's
    /// balance θ*, what the housing gives off there and the speed's ratings in its records.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub balance_rows: bool,
}

/// A `vehicle` over a `drive_cycle` as the scene gives them.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DriveCycleSpec {
    pub vehicle_name: String,
    pub name: String,
    pub trace_file: String, // as written in the scene
    pub cycle: crate::vehicle::Cycle,
    /// Where the transient starts (K); None: the housing's ambient.
    pub start_temperature: Option<f64>,
    /// The vehicle as written: (what, value as written).
    pub written: Vec<(String, String)>,
    pub span: Span,
}

impl Scene {
    /// The scene at the `i`-th temperature of its `oil_temperature` sweep: the lubricant moved to
    /// that temperature (α too when it comes from the base oil), no sweep left. The scene itself
    /// when it has no sweep.
    pub fn at_oil_temperature(&self, i: usize) -> Scene {
        let Some(sweep) = &self.operating.oil_temperatures else {
            return self.clone();
        };
        let theta = Given { value: sweep.values[i], written: sweep.label(i), span: sweep.span };
        let mut scene = self.at_temperature(theta);
        scene.operating.oil_temperatures = None;
        scene
    }

    /// The scene with its lubricant moved to `theta` (α too when it comes from the base oil).
    pub fn at_temperature(&self, theta: Given<ThermodynamicTemperature>) -> Scene {
        let mut scene = self.clone();
        scene.lubricant = scene.lubricant.take().map(|l| l.at_temperature(&theta));
        scene.operating.oil_temperature = Some(theta);
        scene
    }

    /// At `oil_temperature = equilibrium` (written at `span`): the scene with its oil at `kelvin`,
    /// the balance of its first operating point, which its oil table states.
    pub(crate) fn at_balance_of_point_1(&self, kelvin: f64, span: Span) -> Scene {
        self.at_temperature(Given {
            value: ThermodynamicTemperature::new::<uom::si::thermodynamic_temperature::kelvin>(kelvin),
            written: format!("{:.2} degC (equilibrium of point 1)", kelvin - 273.15),
            span,
        })
    }

    /// The oil temperatures the scene runs at, as written (`90 degC`): one per run.
    pub fn oil_temperature_labels(&self) -> Vec<String> {
        match &self.operating.oil_temperatures {
            Some(s) => (0..s.values.len()).map(|i| s.label(i)).collect(),
            None => Vec::new(),
        }
    }
}

pub use crate::dynamics::spec::{DynamicModel, DynamicsSpec, FreeResponseSpec, Solver, StiffnessSpec};

#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadSharing {
    /// Share 1 in single contact, 1/n where n pairs are in contact.
    Equal,
    /// Every contact carries the whole load (He–Cho–Singh).
    None,
    /// By the compatibility of the teeth's deflections: pair j carries k_j max(0, δ − e_j) of the
    /// potential-energy stiffness k_j and tip relief e_j (README, "Mesh stiffness from the teeth").
    Stiffness,
}

/// How the module was given. For a helical pair `module` and `diametral_pitch` are normal values
/// (ISO 21771, AGMA), the `transverse_*` keys transverse ones: m_n = m_t cos β.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub enum ModuleSource {
    Module,
    /// `diametral_pitch = 10 1/in`: m = 1/P_d.
    DiametralPitch(Given<ReciprocalLength>),
    /// `transverse_module = 5 mm`: m_n = m_t cos β.
    TransverseModule(Given<Length>),
    /// `transverse_diametral_pitch = 8 1/in`: m_n = cos β / P_dt.
    TransverseDiametralPitch(Given<ReciprocalLength>),
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct GearPair {
    pub module: Given<Length>,
    pub module_source: ModuleSource,
    /// Normal pressure angle α_n (the pressure angle of a spur pair).
    pub pressure_angle: Given<Angle>,
    /// `transverse_pressure_angle` when it was given instead: tan α_n = tan α_t cos β.
    pub transverse_pressure_angle: Option<Given<Angle>>,
    /// Helix angle β at the reference circle; None for a spur pair.
    pub helix_angle: Option<Given<Angle>>,
    /// `hand = left | right`: accepted and reported; the models here do not depend on it.
    pub hand: Option<String>,
    pub center_distance: Option<Given<Length>>,
    pub face_width: Given<Length>,
    pub load_sharing: LoadSharing,
    pub pinion: Gear,
    pub wheel: Gear,
    /// `mesh = internal`: the wheel is a ring with its teeth inside (ISO 21771).
    pub internal: bool,
    /// Span of the `gears` block, for diagnostics about the pair as a whole.
    pub span: Span,
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct Gear {
    pub teeth: Given<u32>,
    pub profile_shift: Given<f64>,
    pub tip_diameter: Option<Given<Length>>,
    pub inertia: Option<Given<MomentOfInertia>>,
    /// The gear's mass with its shaft share, for the 6-DOF model.
    pub mass: Option<Given<Mass>>,
    pub material: Material,
    pub roughness_ra: Option<Given<Length>>,
    pub roughness_rq: Option<Given<Length>>,
    pub roughness_rz: Option<Given<Length>>,
    /// Root diameter d_f (default from the basic rack, h_fP = 1.25 m_n).
    pub root_diameter: Option<Given<Length>>,
    /// Bore diameter, the fillet foundation's inner boundary (default d_f/2).
    pub bore_diameter: Option<Given<Length>>,
    pub tip_relief: Option<TipReliefSpec>,
    pub span: Span,
}

/// `tip_relief { amount = 10 um  length = 1.8 mm  shape = linear }`.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TipReliefSpec {
    pub amount: Given<Length>,
    pub length: Given<Length>,
    pub shape: crate::geometry::teeth::load_sharing::ReliefShape,
    pub span: Span,
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct Material {
    pub name: String,
    pub youngs_modulus: Given<Pressure>,
    pub poisson_ratio: Given<f64>,
}

pub use crate::tribology::lubricant::BaseOil as LubricantType;

#[derive(Debug, Clone, serde::Serialize)]
pub struct Lubricant {
    pub name: String,
    pub dynamic_viscosity: Given<DynamicViscosity>,
    /// Given, or derived as η/ν when `kinematic_viscosity` is given instead.
    pub density: Option<Given<MassDensity>>,
    pub kinematic_viscosity: Option<Given<KinematicViscosity>>,
    pub pressure_viscosity: Option<Given<ReciprocalPressure>>,
    pub kind: Option<LubricantType>,
    pub temperature: Option<Given<ThermodynamicTemperature>>,
    /// ν40, ν100 and ρ15 when the oil was given by grade or measured values (the values above are
    /// then at the oil temperature).
    pub oil: Option<crate::tribology::lubricant::OilData>,
    /// Whether α comes from the base oil's α(ν) (and so moves with the temperature).
    pub alpha_from_oil: bool,
}

/// A swept or single operating variable: values in SI, plus how they were written.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Sweep<T> {
    pub values: Vec<T>,
    /// The unit the user wrote, for the summary (`rpm`).
    pub unit: String,
    /// SI per unit written (π/30 for rpm).
    pub factor: f64,
    /// The values in the user's unit.
    pub written_values: Vec<f64>,
    pub span: Span,
}

impl<T> Sweep<T> {
    /// Value `i` as written, with its unit (`90 degC`).
    pub fn label(&self, i: usize) -> String {
        format!("{} {}", self.written_values[i], crate::quantity::shown_written_unit(&self.unit))
    }

    /// Value `i` of an operating sweep as its points' labels show it (`2309.09 rpm`: a computed
    /// value to the digits that tell it from the values beside it, `crate::quantity::label_number`).
    pub fn point_label(&self, i: usize) -> String {
        let w = &self.written_values;
        let neighbours = [i.checked_sub(1).map(|j| w[j]), w.get(i + 1).copied()];
        let n: Vec<f64> = neighbours.into_iter().flatten().collect();
        format!("{} {}", crate::quantity::label_number(w[i], &n), crate::quantity::shown_written_unit(&self.unit))
    }
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct Operating {
    pub pinion_torque: Sweep<Torque>,
    pub pinion_speed: Sweep<AngularVelocity>,
    /// The oil (sump or injection) temperature, at which the lubricant's values are read.
    pub oil_temperature: Option<Given<ThermodynamicTemperature>>,
    /// `oil_temperature = [60, 90, 120] degC` (two values or more): the scene runs once at each
    /// ([`Scene::at_oil_temperature`]); `oil_temperature` is then the first of them.
    pub oil_temperatures: Option<Sweep<ThermodynamicTemperature>>,
    /// Operating points the scene asks to see in full (0-based; written 1-based as `detail_points`).
    pub detail_points: Vec<usize>,
    /// `oil_temperature = equilibrium`: where it was written (the efficiency records are then at each
    /// point's thermal balance).
    pub equilibrium: Option<Span>,
}

/// Most operating points a scene may ask for (the product of its sweeps).
pub const MAX_OPERATING_POINTS: usize = 10_000_000;

impl Operating {
    /// The number of operating points: the product of the sweeps.
    pub fn count(&self) -> usize {
        self.pinion_torque.values.len() * self.pinion_speed.values.len()
    }
}

/// What the scene asks to compute. Geometry and the contact state are always computed.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct Analyses {
    pub efficiency: Option<Vec<Formulation>>,
    /// The grid of `efficiency_map(pinion_torque = ..., pinion_speed = ...)`.
    pub efficiency_map: Option<(Sweep<Torque>, Sweep<AngularVelocity>)>,
    /// A drive's map: the ends its axes are given at (`efficiency_map(output_torque = …, …)`).
    pub map_ends: Option<crate::drive::DriveOperating>,
    pub friction_along_loa: bool,
    pub film: bool,
    /// Where `film` was asked for, for diagnostics.
    pub film_span: Option<Span>,
    pub dynamics: bool,
    /// Pinion speeds (rad/s) of the stability map, with the unit and values as written.
    pub stability_map: Option<Sweep<AngularVelocity>>,
    pub numerics: bool,
    /// Where `dynamics`, `stability_map` or `numerics` was asked for.
    pub dynamics_span: Option<Span>,
    /// Where `efficiency` or `friction_along_loa` was asked for (they need friction laws).
    pub friction_span: Option<Span>,
    /// `thermal_balance` and `duty_cycle`, with where they were asked for.
    pub thermal_balance: Option<Span>,
    pub duty_cycle: Option<Span>,
    /// A vehicle over a drive cycle (a drive's scene only), where it was asked for.
    pub drive_cycle: Option<Span>,
    /// `transmission_error(pinion_torque = [...] N*m)`: the torques.
    pub transmission_error: Option<Sweep<Torque>>,
    /// A drive's `stages = [first, second]`: the stages whose meshes the analyses of one pair
    /// (friction along the line of action, film, dynamics, …) run on, with where each is named;
    /// None: every stage.
    pub stages: Option<Vec<(String, Span)>>,
}
