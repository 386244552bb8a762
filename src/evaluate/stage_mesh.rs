//! One stage's mesh as the drive's walk evaluates it: its pair's geometry as each member driving
//! sees it (the wheel's in the pinion's place in coast; a stage's model says which, `mesh_states`), its
//! tribology, its load sharing and Ohlendorf's H_V; a planetary stage's planet–ring mesh; and the
//! meshes of a drive under one law and formulation (or passing their power whole, with no law).

use super::setup::law_at;
use crate::drive::{Member, MeshEfficiency, MeshForceSizes};
use crate::efficiency::{charged_mesh_losses, ohlendorf_loss_factor, Formulation};
use crate::friction::LawContext;
use crate::geometry::sharing::Sharing;
use crate::geometry::teeth::load_sharing::LoadSharing as TeethSharing;
use crate::geometry::{OperatingState, PairGeometry};
use crate::model::{FrictionLawSpec, LoadSharing, Lubricant, SceneDrive};
use crate::tribology::Tribology;

/// A contact table's positions along the line of action from T1 (m), each with its name where it
/// is a named point (`B`).
pub(crate) type TablePositions = Vec<(Option<&'static str>, f64)>;

/// One stage's mesh as each member driving sees it.
pub(crate) struct StageMesh {
    /// [pinion driving, wheel driving]: the pair with the driving member as its pinion (shared by
    /// the setups of one drive at several oil temperatures).
    pub(super) geometry: std::sync::Arc<[PairGeometry; 2]>,
    /// The contacts along A–E at which a law's validity is read, for each geometry
    /// ([`super::setup::curve_positions`], computed once).
    pub(super) positions: std::sync::Arc<[Vec<f64>; 2]>,
    /// The contact table's positions, named where a point is (`super::cases::table_positions`), for each
    /// geometry: where a drive's contacts are checked for plausibility.
    pub(super) table: std::sync::Arc<[TablePositions; 2]>,
    pub(super) h_v: [f64; 2],
    pub(super) tribology: Tribology,
    pub(super) whole: bool,
    /// `load_sharing = stiffness`: the pair's stiffness and reliefs as each member driving sees it
    /// (the same model the pair alone reads, [`super::setup::Setup::sharing`]).
    pub(super) stiffness: std::sync::Arc<[Option<TeethSharing>; 2]>,
    /// A planetary stage's planet–ring mesh (internal, the planet as pinion).
    pub(super) ring: Option<RingMesh>,
}

/// A planetary stage's planet–ring mesh.
pub(crate) struct RingMesh {
    pub(super) geometry: std::sync::Arc<PairGeometry>,
    /// [`super::setup::curve_positions`] of the geometry.
    pub(super) positions: Vec<f64>,
    pub(super) table: TablePositions,
    pub(super) h_v: f64,
    pub(super) tribology: Tribology,
}

impl RingMesh {
    pub(super) fn of(
        drive: &SceneDrive,
        k: usize,
        lubricant: Option<&Lubricant>,
        geometry: Option<std::sync::Arc<PairGeometry>>,
    ) -> Option<RingMesh> {
        let mesh = drive.further_mesh(k, 1, lubricant)?;
        let tribology = mesh.tribology(mesh.reduced_modulus());
        let geometry = geometry.unwrap_or_else(|| std::sync::Arc::new(mesh.geometry()));
        let positions = super::setup::curve_positions(&geometry);
        let table = super::cases::table_positions(&geometry);
        let mut out = RingMesh { geometry, positions, table, h_v: 0.0, tribology };
        out.h_v = ohlendorf_loss_factor(&out.context(1.0, 1.0));
        Some(out)
    }

    fn context(&self, torque: f64, speed: f64) -> LawContext<'_> {
        LawContext {
            geometry: &self.geometry,
            state: OperatingState { pinion_torque: torque, pinion_speed: speed },
            tribology: self.tribology,
            sharing: Sharing::Equal,
        }
    }
}

impl StageMesh {
    /// Stage `k`'s mesh in `lubricant` (the scene's oil at its temperature).
    pub(super) fn of(drive: &SceneDrive, k: usize, lubricant: Option<&Lubricant>) -> StageMesh {
        let mesh = drive.mesh(k, lubricant);
        let e_r = mesh.reduced_modulus();
        let tribology = mesh.tribology(e_r);
        // A ring is no pinion: an internal pair is evaluated with its pinion in the pinion's place
        // whichever gear drives (the internal stage's model puts it there, `mesh_states`).
        let geometry = std::sync::Arc::new([
            mesh.geometry(),
            match drive.pairs[k].internal {
                true => mesh.geometry(),
                false => drive.pairs[k].swapped().geometry().expect("a pair's geometry holds with the roles swapped"),
            },
        ]);
        let whole = drive.pairs[k].load_sharing == LoadSharing::None;
        let stiffness = std::sync::Arc::new([drive.pairs[k].clone(), drive.pairs[k].swapped()].map(|pair| {
            (pair.load_sharing == LoadSharing::Stiffness).then(|| TeethSharing {
                stiffness: pair.pair_stiffness().expect("lowering has built the teeth both ways (lower_stage.rs)"),
                reliefs: pair.reliefs(),
            })
        }));
        let ring = RingMesh::of(drive, k, lubricant, None);
        let positions = std::sync::Arc::new([0, 1].map(|d| super::setup::curve_positions(&geometry[d])));
        let table = std::sync::Arc::new([0, 1].map(|d| super::cases::table_positions(&geometry[d])));
        let mut out = StageMesh { h_v: [0.0; 2], geometry, positions, table, tribology, whole, stiffness, ring };
        for d in 0..2 {
            out.h_v[d] = ohlendorf_loss_factor(&out.context(d, 1.0, 1.0));
        }
        out
    }

    fn context(&self, d: usize, torque: f64, speed: f64) -> LawContext<'_> {
        LawContext {
            geometry: &self.geometry[d],
            state: OperatingState { pinion_torque: torque, pinion_speed: speed },
            tribology: self.tribology,
            sharing: match (self.whole, &self.stiffness[d]) {
                (true, _) => Sharing::Whole,
                (false, Some(model)) => Sharing::Stiffness(model),
                (false, None) => Sharing::Equal,
            },
        }
    }

    /// Mesh `mesh` (0 the stage's own pair, 1 its second) with the gear on place `driving` in the
    /// pinion's place at its torque and speed, and that pair's loss factor H_V.
    pub(super) fn law_context(&self, mesh: usize, driving: Member, torque: f64, speed: f64) -> (LawContext<'_>, f64) {
        match mesh {
            0 => {
                let d = driving.index();
                (self.context(d, torque, speed), self.h_v[d])
            }
            _ => {
                let second = self.ring.as_ref().expect("a stage of two meshes has its second");
                (second.context(torque, speed), second.h_v)
            }
        }
    }

    /// The contacts along A–E at which a law's validity is read on mesh `mesh` with the gear on
    /// place `driving` in the pinion's place (as [`Self::law_context`] picks its geometry).
    pub(super) fn validity_positions(&self, mesh: usize, driving: Member) -> &[f64] {
        match mesh {
            0 => &self.positions[driving.index()],
            _ => &self.ring.as_ref().expect("a stage of two meshes has its second").positions,
        }
    }

    /// The contact table's positions on mesh `mesh` with the gear on place `driving` in the
    /// pinion's place (as [`Self::law_context`] picks its geometry).
    pub(super) fn table_positions(&self, mesh: usize, driving: Member) -> &TablePositions {
        match mesh {
            0 => &self.table[driving.index()],
            _ => &self.ring.as_ref().expect("a stage of two meshes has its second").table,
        }
    }

    /// The sizes the mesh forces read (pinion and wheel as the stage names them).
    pub(super) fn sizes(&self) -> MeshForceSizes {
        MeshForceSizes::of(&self.geometry[0])
    }
}

/// The meshes of every stage under one law and formulation.
pub(super) struct LawMeshes<'a> {
    pub(super) stages: &'a [StageMesh],
    pub(super) spec: &'a FrictionLawSpec,
    pub(super) formulation: Formulation,
    memo: &'a MeshMemo,
}

/// The meshes' η already found under one law at one point, by mesh and its exact state, in both
/// formulations: a pass of the fixed point that puts a mesh at a state met before (a one-pair
/// drive's mesh at its given pinion torque, each pass), or the walk of the point's other
/// formulation there, reads it back instead of integrating the same mesh cycle again (the line
/// integral gives both formulations at once). The same numbers either way.
#[derive(Default)]
pub(crate) struct MeshMemo(std::cell::RefCell<Vec<(MeshState, [f64; 2])>>);

/// A mesh's exact state in a walk: stage, mesh, driving member, T and ω as bits.
type MeshState = (usize, usize, Member, u64, u64);

impl<'a> LawMeshes<'a> {
    /// The meshes of `stages` under law `spec` and `formulation`, reading and filling `memo` (one
    /// memo serves one law at one point).
    pub(super) fn new(
        stages: &'a [StageMesh],
        spec: &'a FrictionLawSpec,
        formulation: Formulation,
        memo: &'a MeshMemo,
    ) -> LawMeshes<'a> {
        LawMeshes { stages, spec, formulation, memo }
    }

    /// η = 1 − P_mesh/(T ω) of the law on one mesh at the context's point (its pinion's T and ω), in
    /// both formulations.
    fn of(&self, ctx: &LawContext, h_v: f64) -> [f64; 2] {
        let law = law_at(self.spec, ctx);
        charged_mesh_losses(ctx, &*law, h_v).map(|p| 1.0 - p / (ctx.state.pinion_torque * ctx.state.pinion_speed))
    }
}

impl MeshEfficiency for LawMeshes<'_> {
    fn efficiency(&self, stage: usize, mesh: usize, driving: Member, torque: f64, speed: f64) -> f64 {
        let key = (stage, mesh, driving, torque.to_bits(), speed.to_bits());
        let f = self.formulation.index();
        if let Some((_, eta)) = self.memo.0.borrow().iter().find(|(k, _)| *k == key) {
            return eta[f];
        }
        let (ctx, h_v) = self.stages[stage].law_context(mesh, driving, torque, speed);
        let eta = self.of(&ctx, h_v);
        self.memo.0.borrow_mut().push((key, eta));
        eta[f]
    }
}

/// The meshes of a drive whose scene lists no friction law (it asks only for analyses of one
/// pair): each passes its power whole, the bearings, seals and gears' no-load parts still charged.
pub(super) struct WholeMeshes;

impl MeshEfficiency for WholeMeshes {
    fn efficiency(&self, _: usize, _: usize, _: Member, _: f64, _: f64) -> f64 {
        1.0
    }
}
