//! ISO/TR 14179-2 (Niemann–Schlenk) mean coefficient of friction, used along the line of action as a
//! Coulomb law with the sign of the sliding direction (physics notes, "Beyond the papers"):
//!
//! μ_mZ = 0.048 · ((F_bt/b)/(v_ΣC ρ_redC))^0.2 · η_oil^−0.05 · Ra^0.25 · X_L,
//!
//! F_bt in N (transverse load at the base circle), b in mm, v_ΣC = 2 v_t sin α_wt in m/s (v_t at the
//! operating pitch circle), ρ_redC = u/(1+u)² · a sin α_wt / cos β_b in mm, η_oil in mPa·s, Ra the
//! mean Ra in µm. F_bt/b below 150 N/mm is raised to 150; v_ΣC above 50 m/s is evaluated at 50; below
//! 1 m/s μ is underestimated, which is flagged. X_L is the lubricant's (ISO/TR 14179-2's table by
//! base oil) unless the law is given `x_l`.

use super::friction_law::{signed, FrictionLaw, Parameter};
use super::law_context::LawContext;
use super::needs::Needs;
use crate::geometry::ContactPoint;
use crate::tribology::units;

#[derive(Debug, Clone)]
pub struct Iso14179_2 {
    pub mu_mz: f64,
    pub load_per_width_n_per_mm: f64,
    pub sum_velocity: f64,
    pub reduced_radius_mm: f64,
    pub lubricant_factor: f64,
    notes: Vec<String>,
}

impl Iso14179_2 {
    /// `x_l`, when given, overrides the lubricant's X_L.
    pub fn new(ctx: &LawContext, x_l: Option<f64>) -> Result<Self, Needs> {
        let g = ctx.geometry;
        let t = &ctx.tribology;
        let u = g.gear_ratio;
        let alpha_wt = g.operating_pressure_angle;
        // F_bt: the transverse force at the base circle, T_p / r_b1 (= F_bn for a spur pair).
        let fbt_per_b = ctx.state.pinion_torque / g.base_radius[0] / (g.face_width * units::MM_PER_M);
        let vt = ctx.state.pinion_speed * g.working_pitch_radius[0];
        let v_sum = 2.0 * vt * alpha_wt.sin();
        let rho = u / (1.0 + u).powi(2) * g.signed_center_distance() * units::MM_PER_M * alpha_wt.sin();
        // ρ_redC = u/(1+u)² · a sin α_wt / cos β_b (helical pairs; cos β_b = 1 for spur); u and a
        // negative for an internal pair (ISO 21771), where it is ρ1ρ2/(ρ2 − ρ1).
        let rho = if g.is_helical() { rho / g.base_helix_angle.cos() } else { rho };
        let eta = t.dynamic_viscosity * units::CP_PER_PA_S;
        let ra = Needs::RoughnessRa.of(t.ra_mean)? * units::UM_PER_M;
        let mut notes = Vec::new();
        let load = if fbt_per_b < 150.0 {
            notes.push(format!("iso_14179_2: F_bt/b = {fbt_per_b:.1} N/mm is below 150 N/mm; evaluated at 150 N/mm"));
            150.0
        } else {
            fbt_per_b
        };
        let v = if v_sum > 50.0 {
            notes.push(format!("iso_14179_2: v_ΣC = {v_sum:.2} m/s is above 50 m/s; evaluated at 50 m/s"));
            50.0
        } else {
            if v_sum < 1.0 {
                notes.push(format!("iso_14179_2: v_ΣC = {v_sum:.3} m/s is below 1 m/s; μ_mZ is underestimated there"));
            }
            v_sum
        };
        let lubricant_factor = x_l.unwrap_or(t.lubricant_factor);
        if x_l.is_none() && t.lubricant_family == "mineral (default)" {
            notes.push("iso_14179_2: no lubricant `type` given; X_L = 1.0 (mineral oil)".into());
        }
        let mu_mz = 0.048 * (load / (v * rho)).powf(0.2) * eta.powf(-0.05) * ra.powf(0.25) * lubricant_factor;
        Ok(Iso14179_2 {
            mu_mz,
            load_per_width_n_per_mm: load,
            sum_velocity: v,
            reduced_radius_mm: rho,
            lubricant_factor,
            notes,
        })
    }
}

impl FrictionLaw for Iso14179_2 {
    fn constant_magnitude(&self) -> bool {
        true
    }
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Iso14179_2
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        signed(self.mu_mz, c.s)
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "mu_mz", value: self.mu_mz, unit: "1" },
            Parameter { name: "load_per_width", value: self.load_per_width_n_per_mm * 1e3, unit: "N/m" },
            Parameter { name: "sum_velocity_at_pitch_point", value: self.sum_velocity, unit: "m/s" },
            Parameter {
                name: "reduced_radius_at_pitch_point",
                value: self.reduced_radius_mm / units::MM_PER_M,
                unit: "m",
            },
            Parameter { name: "lubricant_factor", value: self.lubricant_factor, unit: "1" },
        ]
    }
    fn notes(&self) -> Vec<String> {
        self.notes.clone()
    }
}
