//! A pair's losses at an oil temperature and the balance and ratings of each point of its sweep;
//! the speeds' ratings, the heat-balance curve and a duty cycle over any P_V, which a drive's
//! thermal balance reads (`super::drive_thermal`; [`crate::thermal`] holds the housing and the
//! solvers).
//!
//! P_V(θ) is the scene's one-stage drive walked with its oil read at θ (ν by ASTM D341, ρ by thermal
//! expansion, η = ρν, α from the base oil where the scene does not give it;
//! `DriveSetup::at_oil_temperature`) at the pinion's torque, at the pinion gear, and speed, as a
//! drive's thermal balance walks its rows, its one pass added up (`DriveSetup::one_pair_losses`),
//! and read as the pair's budget (`super::pair_budget`): the mesh loss of one law and formulation
//! as the budget charges it plus the parts beside the mesh. At zero speed nothing turns and
//! nothing is lost; at zero torque the mesh carries nothing and only the no-load losses remain (no
//! law is read without a load).

use super::drive_setup::DriveSetup;
use super::setup::Setup;
use crate::efficiency::Formulation;
use crate::friction::catalog::FrictionLawSpec;
use crate::geometry::OperatingState;
use crate::losses::LossBudget;
use crate::model::Scene;
use crate::thermal::{self, Balance, DutyCycle, Housing, Ratings};
use crate::tribology::lubricant::OilData;
use crate::tribology::Tribology;

use super::thermal_row::ThermalRow;

/// The scene's losses as a function of the oil temperature.
pub struct Losses<'a> {
    scene: &'a Scene,
    setup: &'a Setup,
    /// The scene's one-stage drive, walked at each temperature.
    drive: DriveSetup<'a>,
    /// The budget's columns the gearbox fills (None without a gearbox).
    columns: Option<Vec<crate::losses::parts::LossColumn>>,
    oil: OilData,
    /// α given in the scene (kept at every temperature), or `None` to take the base oil's.
    alpha: Option<f64>,
}

/// The losses at one oil temperature (W).
#[derive(Debug, Clone, PartialEq)]
pub struct LossesAt {
    pub mesh: f64,
    pub budget: Option<LossBudget>,
}

impl LossesAt {
    pub fn total(&self) -> f64 {
        self.mesh + self.budget.as_ref().map_or(0.0, LossBudget::beside_mesh)
    }
}

impl<'a> Losses<'a> {
    /// `None` when the lubricant cannot be read at other temperatures (lowering refuses the thermal
    /// analyses then), or the scene carries no one-stage drive (a stage's pair analysed alone).
    pub fn new(scene: &'a Scene, setup: &'a Setup) -> Option<Losses<'a>> {
        let l = scene.lubricant.as_ref()?;
        let oil = l.oil.clone()?;
        let alpha = if l.alpha_from_oil { None } else { setup.tribology.pressure_viscosity };
        let drive = DriveSetup::new(scene, scene.drive.as_ref()?);
        let columns = scene.gearbox.as_ref().map(crate::losses::Gearbox::columns);
        Some(Losses { scene, setup, drive, columns, oil, alpha })
    }

    /// The tribology of the setup with the oil at `t` (K).
    pub fn tribology_at(&self, t: f64) -> Tribology {
        let at = self.oil.at(t);
        Tribology {
            dynamic_viscosity: at.dynamic_viscosity,
            kinematic_viscosity: Some(at.kinematic_viscosity),
            pressure_viscosity: self.alpha.or(at.pressure_viscosity),
            ..self.setup.tribology
        }
    }

    /// The setup with the oil at `t` (K) and only `formulations` (for a law evaluated at its balance).
    pub fn setup_at(&self, t: f64, formulations: &[Formulation]) -> Setup {
        Setup { tribology: self.tribology_at(t), formulations: formulations.to_vec(), ..self.setup.clone() }
    }

    /// P_V at oil temperature `t` (K) of law `spec` (one of the scene's) and formulation `f` at
    /// `state`: the one-stage drive's walk at `state` with its oil at `t` ([`Self::total`]'s mesh
    /// loss), and the pair's budget beside the mesh the same walk charges, with every bearing place
    /// (the loss parts on the drive's shafts at the pinion torque, `pair_budget::parts_budget`).
    pub fn at(&self, spec: &FrictionLawSpec, f: Formulation, state: OperatingState, t: f64) -> LossesAt {
        if state.pinion_speed <= 0.0 {
            return LossesAt { mesh: 0.0, budget: self.scene.gearbox.as_ref().map(|_| LossBudget::default()) };
        }
        let (torque, speed) = end_values(&self.drive, (state.pinion_torque, state.pinion_speed));
        let setup = self.drive.at_oil_temperature(t);
        let [mesh, _] = setup.one_pair_losses(self.law(spec), f, torque, speed);
        let budget = self.columns.as_ref().map(|columns| {
            let drive = self.scene.drive.as_ref().expect("Losses::new took the scene's drive");
            super::pair_budget::parts_budget(drive, &setup.one_pair_parts(torque, speed), columns)
        });
        LossesAt { mesh: Self::mesh_or_none(mesh, state), budget }
    }

    /// [`Self::at`]'s total P_V (W), what each point's balance and its speed's ratings
    /// read: the same walk's losses added up, from its one pass without building its point
    /// (`DriveSetup::one_pair_losses`; the bearings at the loads the pinion torque fixes).
    pub fn total(&self, spec: &FrictionLawSpec, f: Formulation, state: OperatingState, t: f64) -> f64 {
        if state.pinion_speed <= 0.0 {
            return 0.0;
        }
        let [mesh, beside] =
            one_pair_losses_at(&self.drive, (self.law(spec), f), (state.pinion_torque, state.pinion_speed), t);
        Self::mesh_or_none(mesh, state) + beside
    }

    /// The index of the scene's law `spec`.
    fn law(&self, spec: &FrictionLawSpec) -> usize {
        self.scene.friction.iter().position(|s| s == spec).expect("a law of the scene")
    }

    /// The mesh loss: none at zero torque (no law is read without a load).
    fn mesh_or_none(mesh: f64, state: OperatingState) -> f64 {
        if state.pinion_torque > 0.0 {
            mesh
        } else {
            0.0
        }
    }
}

/// A torque and a speed at the ends `drive`'s operating block names (a one-pair drive's: the
/// pinion's).
fn end_values(drive: &DriveSetup, (torque, speed): (f64, f64)) -> (crate::drive::EndValue, crate::drive::EndValue) {
    let ends = drive.operating_ends();
    let at = |at, value| crate::drive::EndValue { at, value };
    (at(ends.torque_at, torque), at(ends.speed_at, speed))
}

/// A one-pair drive's [mesh loss, every loss beside it] (W) under (law, formulation) at `torque`
/// and `speed` (the pinion's) with its oil at `theta` (K): its walk's first pass
/// (`DriveSetup::one_pair_losses`), without building the point. A pair's P_V(θ) ([`Losses::total`])
/// and a scene of one pair's drive rows' (`drive_thermal`) read it.
pub(crate) fn one_pair_losses_at(
    drive: &DriveSetup,
    (law, f): (usize, Formulation),
    torque_speed: (f64, f64),
    theta: f64,
) -> [f64; 2] {
    let (torque, speed) = end_values(drive, torque_speed);
    drive.at_oil_temperature(theta).one_pair_losses(law, f, torque, speed)
}

/// The balance of one operating point, law and formulation, with what it rests on.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ThermalPoint {
    pub balance: Balance,
    /// At θ* (or at the search's end without a balance).
    pub dissipation: thermal::Dissipation,
    pub heat_transfer_coefficient: f64,
    /// The losses at θ*.
    pub losses: LossesAt,
    /// Pinion torque (N·m) at which θ* is the limit, and at which it is 95 °C.
    pub rating: Option<f64>,
    pub rating_95: Option<f64>,
}

impl ThermalPoint {
    /// The balance as the record files carry it.
    pub(crate) fn row(&self) -> ThermalRow {
        let p = self;
        let d = &p.dissipation;
        ThermalRow {
            oil_temperature: p.balance.temperature,
            thermal_status: p.balance.status,
            loss_at_balance: p.losses.total(),
            convection: d.convection,
            radiation: d.radiation,
            foundation: d.foundation,
            cooler: d.cooler,
            dissipation: d.total,
            heat_transfer_coefficient: p.heat_transfer_coefficient,
            rating: p.rating,
            rating_95: p.rating_95,
        }
    }
}

/// The balance and the losses at it of law `spec`, formulation `f` at `state`, with the two ratings
/// of its speed ([`ratings`]).
pub(crate) fn thermal_point(
    losses: &Losses,
    housing: &Housing,
    spec: &FrictionLawSpec,
    f: Formulation,
    state: OperatingState,
    ratings: Ratings,
) -> ThermalPoint {
    let balance = thermal::balance(|t: f64| losses.total(spec, f, state, t), housing);
    let t = balance.temperature.unwrap_or(thermal::balance::SEARCH_LIMIT);
    ThermalPoint {
        balance,
        dissipation: housing.dissipation(t),
        heat_transfer_coefficient: housing.heat_transfer_coefficient(t),
        losses: losses.at(spec, f, state, t),
        rating: ratings.at_limit,
        rating_95: ratings.at_95,
    }
}

/// Each speed's ratings of a sweep, computed by the first point that asks (a 200 × 200 sweep
/// locates 200 speeds' ratings, not 40 000 points'): they depend on the speed alone, not on the
/// point's torque. Keyed by law, formulation and speed index; every speed's bracket starts at the
/// sweep's largest torque, so that a speed's ratings are one number whichever point asks first. A
/// pair's sweep and a drive's rows read it alike, each with its own P_V(torque, θ).
pub(crate) struct RatingTable {
    slots: Vec<std::sync::OnceLock<Ratings>>,
    speeds: usize,
    /// The bracket's start for every speed: the sweep's largest torque (at least 1 N·m).
    guess: f64,
}

impl RatingTable {
    /// The table of `scene`'s sweep: its laws, both formulations and its speeds.
    pub(crate) fn new(scene: &Scene) -> RatingTable {
        let speeds = scene.operating.pinion_speed.values.len();
        let guess = scene.operating.pinion_torque.values.iter().map(|v| v.value).fold(1.0, f64::max);
        let slots = (0..scene.friction.len() * 2 * speeds).map(|_| std::sync::OnceLock::new()).collect();
        RatingTable { slots, speeds, guess }
    }

    /// The ratings of law `law` (index in the scene), formulation `f` at speed index `speed_index`,
    /// located on `p_v(torque, θ)` (W) the first time they are asked for
    /// ([`crate::thermal::ratings`]).
    pub(crate) fn get(
        &self,
        (law, f, speed_index): (usize, Formulation, usize),
        housing: &Housing,
        p_v: impl Fn(f64, f64) -> f64 + Copy,
    ) -> Ratings {
        *self.slots[(law * 2 + f.index()) * self.speeds + speed_index]
            .get_or_init(|| thermal::ratings(p_v, housing, self.guess))
    }
}

/// The ratings of law `spec`, formulation `f` at pinion speed `speed` (rad/s): the pinion torques
/// (N·m) that put the balance on the oil's limit and on 95 °C ([`crate::thermal::ratings`]); `guess`
/// (N·m) starts the bracket. They depend on the speed alone, not on an operating point's torque.
pub fn ratings(
    losses: &Losses,
    housing: &Housing,
    spec: &FrictionLawSpec,
    f: Formulation,
    speed: f64,
    guess: f64,
) -> Ratings {
    thermal::ratings(loss_at_torque(losses, spec, f, speed), housing, guess.max(1.0))
}

/// P_V(torque, θ) of law `spec` and formulation `f` at pinion speed `speed` (rad/s): what a speed's
/// ratings are located on.
pub(crate) fn loss_at_torque<'l>(
    losses: &'l Losses,
    spec: &'l FrictionLawSpec,
    f: Formulation,
    speed: f64,
) -> impl Fn(f64, f64) -> f64 + Copy + 'l {
    move |torque: f64, t: f64| losses.total(spec, f, OperatingState { pinion_torque: torque, pinion_speed: speed }, t)
}

/// A duty cycle evaluated at the scene's fixed oil temperature and, with a heat capacity, as a
/// transient from ambient.
#[derive(Debug, Clone, PartialEq)]
pub struct DutyCycleResult {
    /// The law (index in the scene's list) and formulation the losses are read with.
    pub law_index: usize,
    pub formulation: Formulation,
    /// P_V of each step at the fixed temperature (W), when the scene has one.
    pub fixed: Option<Vec<f64>>,
    pub transient: Option<Result<thermal::Transient, String>>,
}

/// A duty cycle on `p_v(step, θ)` (W) under the scene's first law and formulation `f`: each step's
/// P_V at the fixed oil temperature, when there is one, and with a heat capacity the sump's
/// transient from ambient ([`crate::thermal::transient`]); a drive's (`drive_thermal::drive_duty`).
pub(crate) fn duty_cycle_of(
    p_v: impl Fn(usize, f64) -> f64 + Copy,
    housing: &Housing,
    cycle: &DutyCycle,
    (fixed, f): (Option<f64>, Formulation),
) -> DutyCycleResult {
    let durations: Vec<f64> = cycle.steps.iter().map(|s| s.duration).collect();
    DutyCycleResult {
        law_index: 0,
        formulation: f,
        fixed: fixed.map(|t| (0..cycle.steps.len()).map(|k| p_v(k, t)).collect()),
        transient: housing.heat_capacity.map(|c| thermal::transient(p_v, housing, c, &durations)),
    }
}

/// Temperatures of the heat-balance curve.
pub(crate) const CURVE_POINTS: usize = 120;

/// P_V(θ) and P_Q(θ) of one operating point, law and formulation from ambient to 200 °C, for the
/// heat-balance plot (the balance itself is located, not read from these).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatBalanceCurve {
    pub case: usize,
    pub law_index: usize,
    pub formulation: Formulation,
    pub temperatures: Vec<f64>,
    pub losses: Vec<f64>,
    pub dissipation: Vec<f64>,
    pub balance: Balance,
}

/// The curve of `p_v` (W at θ in K) against what `housing` gives off, from ambient to the balance
/// search's limit, at (operating point, law index, formulation): a drive's first row.
pub(crate) fn heat_balance_curve(
    p_v: impl Fn(f64) -> f64,
    housing: &Housing,
    (case, law_index, formulation): (usize, usize, Formulation),
) -> HeatBalanceCurve {
    let top = thermal::balance::SEARCH_LIMIT;
    let temperatures: Vec<f64> = (0..CURVE_POINTS)
        .map(|i| housing.ambient + (top - housing.ambient) * i as f64 / (CURVE_POINTS - 1) as f64)
        .collect();
    HeatBalanceCurve {
        case,
        law_index,
        formulation,
        losses: temperatures.iter().map(|t| p_v(*t)).collect(),
        dissipation: temperatures.iter().map(|t| housing.dissipation(*t).total).collect(),
        temperatures,
        balance: thermal::balance(p_v, housing),
    }
}
