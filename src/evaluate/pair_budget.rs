//! A one-pair drive read as the pair's loss budget: the parts beside the mesh in the budget's
//! columns, and every bearing place of the pinion's shaft, then the wheel's, with the loads and
//! losses the drive's statics and bearing models give it. A pair's budget at each point of its
//! sweep and at an oil temperature (thermal balance, ratings, duty cycle) is its one-stage drive's
//! loss parts at the given pinion torque (`parts_budget`).

use crate::drive::forces::MeshForceSizes;
use crate::drive::shaft_beam::PreparedBeam;
use crate::drive::walk::{parts_at, DriveModel};
use crate::drive::EndValue;
use crate::geometry::{OperatingState, PairGeometry};
use crate::losses::parts::{LossColumn, PartLosses};
use crate::losses::{BearingLoss, LossBudget, Oil};
use crate::model::{Scene, SceneDrive};

/// What a pair's budget beside the mesh reads at each point of its sweep: its one-stage drive's
/// sizes, shaft beams and oil, and the columns its gearbox fills. The budget at a point is the
/// loss-part catalogue on the drive's shafts at the given pinion torque and speed
/// ([`crate::drive::walk::parts_at`]: the bearing loads the mesh force at that torque puts on the
/// drive's statics), read as the pair's budget.
#[derive(Debug, Clone)]
pub(crate) struct PairParts {
    sizes: [MeshForceSizes; 1],
    beams: Vec<Option<PreparedBeam>>,
    oil: Oil,
    columns: Vec<LossColumn>,
}

impl PairParts {
    /// For a scene of one pair with a gearbox (and its one-stage drive), with its pair's geometry
    /// `g` and the budget's oil `oil`.
    pub(crate) fn new(scene: &Scene, g: &PairGeometry, oil: Oil) -> Option<PairParts> {
        let (gearbox, drive) = (scene.gearbox.as_ref()?, scene.drive.as_ref().filter(|d| d.one_pair)?);
        let sizes = [MeshForceSizes::of(g)];
        let beams = crate::drive::shaft_bending::prepared_beams(&drive.layout);
        Some(PairParts { sizes, beams, oil, columns: gearbox.columns() })
    }

    /// The budget beside the mesh at `state` on `drive` (the scene's one-stage drive).
    pub(crate) fn at(&self, drive: &SceneDrive, state: &OperatingState) -> LossBudget {
        let model = DriveModel { drive: &drive.layout, sizes: &self.sizes, oil: &self.oil, beams: &self.beams };
        let speed = EndValue { at: drive.layout.operating.speed_at, value: state.pinion_speed };
        let parts = parts_at(&model, speed, &[state.pinion_torque]);
        parts_budget(drive, &parts, &self.columns)
    }
}

/// The catalogue's parts `[load-independent, load-dependent]` on a one-pair drive read as the pair's
/// budget: the power of each of `columns` over both shafts, and each bearing place of the pinion's
/// shaft, then the wheel's, as written.
pub(crate) fn parts_budget(
    drive: &SceneDrive,
    [fixed, loaded]: &[PartLosses; 2],
    columns: &[LossColumn],
) -> LossBudget {
    let parts = columns.iter().map(|&c| (c, fixed.column(c) + loaded.column(c))).collect();
    let places = drive.layout.stages[0].places;
    let kept = loaded.places.as_deref().unwrap_or_default();
    let mut bearings = Vec::new();
    for (name, place) in ["pinion", "wheel"].into_iter().zip(places) {
        let shaft = &drive.layout.shafts[place.shaft];
        for (b, loads) in shaft.bearings.iter().zip(kept.get(place.shaft).into_iter().flatten()) {
            bearings.push(BearingLoss {
                shaft: name,
                kind: b.kind.name(),
                model: b.model_name(),
                count: b.count,
                position: b.position,
                loads: *loads,
            });
        }
    }
    LossBudget { parts, bearings }
}

#[cfg(test)]
mod tests {
    use crate::efficiency::Formulation;
    use crate::evaluate::thermal::Losses;
    use crate::losses::LossBudget;

    /// Every scene of one pair with a gearbox among the specs and the ok fixtures, checked.
    fn pair_scenes_with_a_gearbox() -> Vec<(std::path::PathBuf, crate::model::Scene)> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut files: Vec<_> = ["specs", "tests/specs/ok"]
            .iter()
            .flat_map(|d| std::fs::read_dir(root.join(d)).unwrap().map(|e| e.unwrap().path()))
            .filter(|p| p.extension().is_some_and(|e| e == "gear"))
            .collect();
        files.sort();
        files
            .into_iter()
            .filter_map(|path| {
                let source = std::fs::read_to_string(&path).unwrap();
                let scene = crate::scene::check::check(&path.display().to_string(), &source).ok()?;
                (scene.gearbox.is_some() && scene.drive.as_ref().is_some_and(|d| d.one_pair && d.cycle.is_none()))
                    .then_some((path, scene))
            })
            .collect()
    }

    /// Asserts `got` is `want` (`close` on every number), naming `at`; the number of bearing places.
    fn assert_same_budget(got: &LossBudget, want: &LossBudget, close: &dyn Fn(f64, f64) -> bool, at: &str) -> usize {
        assert_eq!(got.parts.len(), want.parts.len(), "{at}");
        for ((c, p), (wc, w)) in got.parts.iter().zip(&want.parts) {
            assert!(c == wc && close(*p, *w), "{at}: {c:?} {p} vs {w}");
        }
        assert_eq!(got.bearings.len(), want.bearings.len(), "{at}");
        for (x, w) in got.bearings.iter().zip(&want.bearings) {
            assert_eq!(
                (x.shaft, x.kind, x.model, x.count, x.position),
                (w.shaft, w.kind, w.model, w.count, w.position)
            );
            let (l, m) = (x.loads, w.loads);
            for (a, e) in [(l.radial_load, m.radial_load), (l.axial_load, m.axial_load), (l.no_load, m.no_load)] {
                assert!(close(a, e), "{at} bearing: {a} vs {e}");
            }
            assert_eq!(l.load.is_some(), m.load.is_some(), "{at}");
            assert!(close(l.load.unwrap_or(0.0), m.load.unwrap_or(0.0)), "{at}: {:?} vs {:?}", l.load, m.load);
        }
        got.bearings.len()
    }

    /// A pair's budget at each point of its sweep (`Setup::loss_budget`: the parts catalogue on its
    /// one-stage drive's shafts and statics at the given pinion torque, `PairParts`) is the budget of
    /// its gearbox on the pair's own two shafts and statics (`losses::loss_budget`,
    /// `losses::pair_statics`: F_bt = T_1/r_b1 shared by the places, or the two-place beam): every
    /// column and every bearing place's loads and losses to 1e-14 relative (the largest difference
    /// seen is 6e-16), at the first 12 points of every such scene (9 scenes, 33 budgets, 68 places).
    #[test]
    fn a_pairs_budget_is_its_drives_parts_at_the_pinion_torque() {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * a.abs().max(b.abs());
        let (mut scenes, mut compared, mut places) = (0, 0, 0);
        for (path, scene) in pair_scenes_with_a_gearbox() {
            let plan = crate::evaluate::Plan::new(&scene.operating, None, &[]);
            let eval = crate::evaluate::prepare(&scene, &plan);
            let oil = scene.mesh().budget_oil(&eval.tribology);
            let gearbox = scene.gearbox.as_ref().unwrap();
            scenes += 1;
            for k in 0..scene.operating.count().min(12) {
                let state = crate::evaluate::state_at(&scene.operating, k);
                let got = eval.loss_budget(&scene, &state).expect("a budget");
                let want =
                    crate::losses::loss_budget(gearbox, &eval.geometry, state.pinion_torque, state.pinion_speed, &oil);
                places += assert_same_budget(&got, &want, &close, &format!("{} point {k}", path.display()));
                compared += 1;
            }
        }
        assert!(scenes >= 9 && compared >= 33 && places >= 68, "{scenes} scenes, {compared} budgets, {places} places");
    }

    /// A pair's losses at an oil temperature are its own budget: for every scene of one pair among
    /// the specs and ok fixtures with a gearbox and an oil that can be moved, at its first three
    /// points, 40, 80 and 120 °C, every law and both formulations, the one-stage drive's walk read
    /// as the budget (`Losses::at`) gives the pair's mesh loss as its budget charges it (its law in
    /// the oil at θ, `efficiency::charged_mesh_loss`) and the pair's own loss budget in that oil
    /// (`losses::loss_budget`, the parts catalogue on the pair's statics): the mesh, every part
    /// and every bearing place's loads and losses to 1e-13 relative (the largest difference seen is
    /// 9e-15: the walk starts with the input at T_1 plus the pinion shaft's own losses, so the mesh
    /// has T_1 but for rounding); and the total P_V the balance reads (`Losses::total`, the walk's
    /// one pass without its point) is the mesh loss plus that budget to 1e-13.
    #[test]
    fn losses_at_an_oil_temperature_are_the_pairs_own_budget() {
        let worst = std::cell::Cell::new(0.0f64);
        let close = |a: f64, b: f64| {
            let scale = a.abs().max(b.abs());
            if scale > 0.0 {
                worst.set(worst.get().max((a - b).abs() / scale));
            }
            (a - b).abs() <= 1e-13 * scale
        };
        let (mut scenes, mut compared, mut places) = (0, 0, 0);
        for (path, scene) in pair_scenes_with_a_gearbox() {
            let g = scene.gearbox.as_ref().expect("a gearbox");
            let plan = crate::evaluate::Plan::new(&scene.operating, None, &[]);
            let eval = crate::evaluate::prepare(&scene, &plan);
            let Some(losses) = Losses::new(&scene, &eval) else { continue };
            scenes += 1;
            for k in 0..scene.operating.count().min(3) {
                let state = crate::evaluate::state_at(&scene.operating, k);
                for celsius in [40.0, 80.0, 120.0] {
                    let t = celsius + 273.15;
                    let tribology = losses.tribology_at(t);
                    let oil = scene.mesh().budget_oil(&tribology);
                    let want_budget =
                        crate::losses::loss_budget(g, &eval.geometry, state.pinion_torque, state.pinion_speed, &oil);
                    for spec in &scene.friction {
                        for f in [Formulation::External, Formulation::Internal] {
                            let ctx = crate::friction::LawContext {
                                geometry: &eval.geometry,
                                state,
                                tribology,
                                sharing: eval.sharing(),
                            };
                            let law = crate::evaluate::setup::law_at(spec, &ctx);
                            let mesh =
                                crate::efficiency::charged_mesh_loss(&ctx, law.as_ref(), f, eval.ohlendorf_loss_factor);
                            let got = losses.at(spec, f, state, t);
                            let name = path.display();
                            assert!(close(got.mesh, mesh), "{name} {k} {celsius} °C: mesh {} vs {mesh}", got.mesh);
                            // P_V as the balance reads it, from the walk's one pass without its point.
                            let total = losses.total(spec, f, state, t);
                            let want_total = mesh + want_budget.beside_mesh();
                            assert!(close(total, want_total), "{name} {k} {celsius} °C: P_V {total} vs {want_total}");
                            let b = got.budget.expect("a budget");
                            places += assert_same_budget(&b, &want_budget, &close, &format!("{name} {k} {celsius} °C"));
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert!(
            scenes >= 8 && compared >= 150 && places >= 300,
            "{scenes} scenes, {compared} losses, {places} places (largest difference {:.1e})",
            worst.get()
        );
    }
}
