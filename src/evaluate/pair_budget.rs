//! A one-pair drive's point read as the pair's loss budget: the parts beside the mesh in the
//! budget's columns, and every bearing place of the pinion's shaft, then the wheel's, with the loads
//! and losses the drive's statics and bearing models gave it. A pair's efficiency map and its
//! losses at an oil temperature (thermal balance, ratings, duty cycle) are its one-stage drive's
//! walk read this way.

use crate::drive::DrivePoint;
use crate::losses::parts::LossColumn;
use crate::losses::{BearingLoads, BearingLoss, BudgetParts, LossBudget, Oil};
use crate::model::SceneDrive;

/// The power of each of `columns` (the parts the pair's gearbox describes, in column order) at the
/// drive's point `p` (W): the gears' no-load parts, the bearings' no-load and load parts, the seals.
pub(crate) fn parts_of(p: &DrivePoint, columns: &[LossColumn]) -> Vec<(LossColumn, f64)> {
    let l = &p.losses;
    columns
        .iter()
        .map(|c| {
            let power = match c {
                LossColumn::GearNoLoad => l.gear_no_load,
                LossColumn::BearingsNoLoad => l.bearings_no_load,
                LossColumn::BearingsLoad => l.bearings_load,
                LossColumn::Seals => l.seals,
            };
            (*c, power)
        })
        .collect()
}

/// The pair's budget beside the mesh at its one-stage drive's point `p` in `oil` (the oil the walk
/// read): the parts of `columns` and each bearing place's loads and losses, the pinion's shaft
/// first, each shaft's places as written. A place's load-dependent loss is absent (as a pair's
/// budget gives it) where its model has no load moment (a bearing without the C_0 its f_1 needs).
pub(crate) fn one_pair_budget(drive: &SceneDrive, p: &DrivePoint, oil: &Oil, columns: &[LossColumn]) -> LossBudget {
    let places = drive.layout.stages[0].places;
    let mut bearings = Vec::new();
    for (name, place) in ["pinion", "wheel"].into_iter().zip(places) {
        let (shaft, at) = (&drive.layout.shafts[place.shaft], &p.shafts[place.shaft]);
        let speed = at.speed.abs();
        for (b, point) in shaft.bearings.iter().zip(at.bearings.iter().filter(|b| b.is_shaft_place())) {
            let modelled = oil
                .nu
                .is_some_and(|nu| b.moments(point.radial_load, point.axial_load, nu, speed, oil.mineral).1.is_some());
            bearings.push(BearingLoss {
                shaft: name,
                kind: b.kind.name(),
                model: b.model_name(),
                count: b.count,
                position: b.position,
                loads: BearingLoads {
                    radial_load: point.radial_load,
                    axial_load: point.axial_load,
                    no_load: point.no_load,
                    load: modelled.then_some(point.load),
                },
            });
        }
    }
    LossBudget { parts: parts_of(p, columns), bearings }
}

/// A one-pair drive's point `p` as the pair's budget at input power `input` = T_1 ω_1 (W): the parts
/// `columns` the gearbox describes, the whole loss mesh + Σ parts and the pair's total efficiency
/// 1 − P_total/(T_1 ω_1), taken at the pinion gear (not the drive's P_out/P_in, whose input also
/// pays the pinion shaft's own losses). The map keeps no bearing loads. A point whose walk did not
/// settle (not seen: at a given pinion torque the bearing loads do not feed back into the torque
/// that loads them) has no whole loss and no total efficiency (NaN, which the report flags).
pub(crate) fn budget_of(p: &DrivePoint, input: f64, columns: &[LossColumn]) -> BudgetParts {
    let parts = parts_of(p, columns);
    let total = if p.settled() { p.stages[0].mesh_loss + parts.iter().map(|(_, p)| p).sum::<f64>() } else { f64::NAN };
    BudgetParts { parts, total_loss: total, total_efficiency: 1.0 - total / input, bearings: Vec::new() }
}

#[cfg(test)]
mod tests {
    use crate::efficiency::Formulation;
    use crate::evaluate::thermal::Losses;

    /// A pair's losses at an oil temperature are its own budget: for every scene of one pair among
    /// the specs and ok fixtures with a gearbox and an oil that can be moved, at its first three
    /// points, 40, 80 and 120 °C, every law and both formulations, the one-stage drive's walk read
    /// as the budget (`Losses::at`) gives the pair's mesh loss as its budget charges it (its law in
    /// the oil at θ, `efficiency::charged_mesh_loss`) and the pair's own loss budget in that oil
    /// (`losses::loss_budget`, the parts catalogue on the pair's statics): the mesh, every part
    /// and every bearing place's loads and losses to 1e-13 relative (the largest difference seen is
    /// 9e-15: the walk starts with the input at T_1 plus the pinion shaft's own losses, so the mesh
    /// has T_1 but for rounding).
    #[test]
    fn losses_at_an_oil_temperature_are_the_pairs_own_budget() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut files: Vec<_> = ["specs", "tests/specs/ok"]
            .iter()
            .flat_map(|d| std::fs::read_dir(root.join(d)).unwrap().map(|e| e.unwrap().path()))
            .filter(|p| p.extension().is_some_and(|e| e == "gear"))
            .collect();
        files.sort();
        let worst = std::cell::Cell::new(0.0f64);
        let close = |a: f64, b: f64| {
            let scale = a.abs().max(b.abs());
            if scale > 0.0 {
                worst.set(worst.get().max((a - b).abs() / scale));
            }
            (a - b).abs() <= 1e-13 * scale
        };
        let (mut scenes, mut compared, mut places) = (0, 0, 0);
        for path in files {
            let source = std::fs::read_to_string(&path).unwrap();
            let Ok(scene) = crate::scene::check::check(&path.display().to_string(), &source) else {
                continue;
            };
            let Some(g) = scene.gearbox.as_ref().filter(|_| scene.runs_as_pair()) else { continue };
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
                            let b = got.budget.expect("a budget");
                            assert_eq!(b.parts.len(), want_budget.parts.len(), "{name}");
                            for ((c, p), (wc, w)) in b.parts.iter().zip(&want_budget.parts) {
                                assert!(c == wc && close(*p, *w), "{name} {k} {celsius} °C: {c:?} {p} vs {w}");
                            }
                            assert_eq!(b.bearings.len(), want_budget.bearings.len(), "{name}");
                            for (x, w) in b.bearings.iter().zip(&want_budget.bearings) {
                                assert_eq!(
                                    (x.shaft, x.kind, x.model, x.count, x.position),
                                    (w.shaft, w.kind, w.model, w.count, w.position)
                                );
                                let (l, m) = (x.loads, w.loads);
                                for (a, e) in [
                                    (l.radial_load, m.radial_load),
                                    (l.axial_load, m.axial_load),
                                    (l.no_load, m.no_load),
                                ] {
                                    assert!(close(a, e), "{name} {k} {celsius} °C bearing: {a} vs {e}");
                                }
                                assert_eq!(l.load.is_some(), m.load.is_some());
                                assert!(
                                    close(l.load.unwrap_or(0.0), m.load.unwrap_or(0.0)),
                                    "{name}: {:?} vs {:?}",
                                    l.load,
                                    m.load
                                );
                                places += 1;
                            }
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
