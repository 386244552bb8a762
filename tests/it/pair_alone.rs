//! References for a scene of one pair run as its one-stage drive, computed without the drive's
//! walk: the mesh loss the pair's budget charges (`efficiency::charged_mesh_loss`, its law built at
//! the point) and its gearbox's losses beside the mesh on the pair's own two shafts and statics
//! (`losses::loss_budget`: F_bt = T_1/r_b1 shared by the places, or the two-place beam); and the
//! drive's rows as drive_records.csv writes them, to hold against those.

use gearloss::efficiency::Formulation;
use gearloss::geometry::OperatingState;

/// A scene of one pair prepared for [`PairAlone::losses`].
pub(crate) struct PairAlone<'a> {
    pair: &'a gearloss::Scene,
    eval: gearloss::Evaluation,
}

impl<'a> PairAlone<'a> {
    pub(crate) fn new(pair: &'a gearloss::Scene) -> PairAlone<'a> {
        let plan = gearloss::evaluate::Plan::new(&pair.operating, None, &[]);
        PairAlone { pair, eval: gearloss::evaluate::prepare(&pair.pair_alone().unwrap(), &plan) }
    }

    /// The pair's own losses at pinion torque `t` (N·m) and speed `w` (rad/s) in its oil (its
    /// lubricant at its oil temperature): `[mesh, beside the mesh]` (W), the mesh loss under law `law`
    /// (index in the scene) and formulation `f` as the budget charges it (ISO/TR 14179-2's
    /// P_in μ_mZ H_V on a helical pair under that law, else the contact-line integral), none at zero
    /// torque or speed; beside it the gearbox's budget (none without a gearbox, and at zero speed).
    pub(crate) fn losses(&self, (law, f): (usize, Formulation), (t, w): (f64, f64)) -> [f64; 2] {
        let setup = &self.eval.setup;
        let mesh = if t > 0.0 && w > 0.0 {
            let ctx = setup.law_context(OperatingState { pinion_torque: t, pinion_speed: w });
            let built = self.pair.friction[law].build(&ctx).unwrap_or_else(|e| panic!("{e:?}"));
            gearloss::efficiency::charged_mesh_loss(&ctx, built.as_ref(), f, setup.ohlendorf_loss_factor)
        } else {
            0.0
        };
        let oil = self.pair.mesh().budget_oil(&setup.tribology);
        let beside = self
            .pair
            .gearbox
            .as_ref()
            .filter(|_| w > 0.0)
            .map_or(0.0, |g| gearloss::losses::loss_budget(g, &setup.geometry, t, w, &oil).beside_mesh());
        [mesh, beside]
    }
}

/// The pair with its oil moved to `kelvin`.
pub(crate) fn at_kelvin(pair: &gearloss::Scene, kelvin: f64) -> gearloss::Scene {
    use uom::si::thermodynamic_temperature::kelvin as k;
    pair.at_temperature(gearloss::model::Given {
        value: uom::si::f64::ThermodynamicTemperature::new::<k>(kelvin),
        written: format!("{kelvin} K"),
        span: Default::default(),
    })
}

/// A drive's rows as drive_records.csv writes them.
pub(crate) struct DriveRows {
    head: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl DriveRows {
    /// The rows of `scene`'s drive (every point, law and formulation).
    pub(crate) fn of(scene: &gearloss::Scene) -> DriveRows {
        let mut csv = Vec::new();
        gearloss::evaluate::evaluate_drive_into(scene, scene.drive.as_ref().unwrap(), &mut csv).unwrap();
        DriveRows::parse(&String::from_utf8(csv).unwrap())
    }

    /// The rows of a drive_records.csv.
    pub(crate) fn parse(csv: &str) -> DriveRows {
        let mut lines = csv.lines();
        let head = lines.next().unwrap().split(',').map(str::to_string).collect();
        DriveRows { head, rows: lines.map(|l| l.split(',').map(str::to_string).collect()).collect() }
    }

    pub(crate) fn len(&self) -> usize {
        self.rows.len()
    }

    /// The column `name`'s index.
    fn col(&self, name: &str) -> usize {
        self.head.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"))
    }

    /// Row `k`'s cell in column `name`, as written.
    pub(crate) fn cell(&self, k: usize, name: &str) -> &str {
        &self.rows[k][self.col(name)]
    }

    /// Row `k`'s number in column `name`.
    pub(crate) fn value(&self, k: usize, name: &str) -> f64 {
        let cell = self.cell(k, name);
        cell.parse().unwrap_or_else(|_| panic!("{name} = {cell:?}"))
    }

    /// The row of point (torque index, speed index), law index and formulation.
    pub(crate) fn find(&self, (t, s): (usize, usize), law: usize, f: Formulation) -> usize {
        let key = [t.to_string(), s.to_string(), law.to_string(), f.name().to_string()];
        (0..self.rows.len())
            .find(|k| {
                ["torque_index", "speed_index", "law_index", "formulation"]
                    .iter()
                    .zip(&key)
                    .all(|(c, v)| self.cell(*k, c) == v)
            })
            .unwrap_or_else(|| panic!("no drive row {key:?}"))
    }
}
