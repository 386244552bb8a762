//! The outline of one tooth in its transverse section: the involute flank from the form circle to
//! the tip and, below it, the trochoid fillet that the generating rack's tip rounding cuts (Ma,
//! Song, Pang, Wen, "Time-varying mesh stiffness calculation of cracked spur gears", Engineering
//! Failure Analysis 44 (2014) 179–194, with the profile shift added; rack of ISO 53).
//!
//! Frame: the tooth's centreline is the y axis from the gear centre; `h` is the half-thickness.
//! The involute is parameterised by its roll length ℓ = √(r² − r_b²), the distance from the
//! gear's own tangency point T along the line of action, so that a contact at position s from A is
//! at ℓ₁ = T1A + s on the pinion and ℓ₂ = T1T2 − T1A − s on the wheel, and every integrand is
//! analytic in ℓ (in r it has a square-root branch at the base circle).

use std::f64::consts::FRAC_PI_2;

use crate::geometry::involute;

/// What one tooth's outline needs, SI (m, rad), transverse section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothInput {
    pub teeth: u32,
    /// Transverse module m_t (= m for a spur gear).
    pub transverse_module: f64,
    /// Normal module m_n: the rack's addendum is 1·m_n.
    pub normal_module: f64,
    /// Transverse pressure angle α_t of the generating rack.
    pub pressure_angle: f64,
    /// The profile shift x_n m_n (m).
    pub shift: f64,
    pub tip_radius: f64,
    pub root_radius: f64,
}

/// Why an outline cannot be built.
#[derive(Debug, Clone, PartialEq)]
pub enum OutlineProblem {
    /// The root circle is at or above the form circle, or at or above the tip.
    RootTooHigh { root: f64, limit: f64 },
    /// The rack's tip rounding cuts the involute away (undercut).
    Undercut,
    /// The rack dedendum is below its addendum: no tip rounding (h_fP ≤ h_aP).
    NoClearance { dedendum: f64, addendum: f64 },
    /// The rack dedendum reaches where its flanks meet (h_fP ≥ π m/(4 tan α)): no rack cuts it.
    PointedRack { dedendum: f64, limit: f64 },
}

/// One tooth's outline (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothOutline {
    pub input: ToothInput,
    pub pitch_radius: f64,
    pub base_radius: f64,
    /// The rack's dedendum h_fP = r − r_f + x m.
    pub rack_dedendum: f64,
    /// The rack's tip rounding radius ρ = (h_fP − h_aP)/(1 − sin α), at most the full round tip's
    /// (π m/4 − h_fP tan α) cos α/(1 − sin α).
    pub tip_rounding: f64,
    /// a1 = h_fP − x m − ρ: the rounding centre's distance inside the pitch circle.
    pub a1: f64,
    /// b1 = π m/4 + h_fP tan α + ρ (1 − sin α)/cos α.
    pub b1: f64,
    /// Radius where the fillet meets the involute.
    pub form_radius: f64,
    /// ψ at the pitch circle plus inv α: ψ(r) = this − inv α_r.
    psi0: f64,
}

/// A point of the outline: y from the centre, half-thickness h, and dy along the parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutlinePoint {
    pub y: f64,
    pub h: f64,
    pub dy: f64,
}

impl ToothOutline {
    /// The outline of a tooth cut by the ISO 53 rack with tip rounding, or why it cannot be cut.
    pub fn new(input: ToothInput) -> Result<Self, OutlineProblem> {
        let ToothInput { teeth, transverse_module: m, normal_module: m_n, pressure_angle: alpha, shift, .. } = input;
        let r = m * teeth as f64 / 2.0;
        let r_b = r * alpha.cos();
        let h_fp = r - input.root_radius + shift;
        let h_ap = m_n;
        if h_fp <= h_ap {
            return Err(OutlineProblem::NoClearance { dedendum: h_fp, addendum: h_ap });
        }
        // The rack tooth's half-width at its tip line, from its centreline: π m/4 − h_fP tan α.
        let half_tip = std::f64::consts::PI * m / 4.0 - h_fp * alpha.tan();
        if half_tip <= 0.0 {
            return Err(OutlineProblem::PointedRack {
                dedendum: h_fp,
                limit: std::f64::consts::PI * m / (4.0 * alpha.tan()),
            });
        }
        // The rounding tangent to the flank at the depth h_aP and to the tip line, unless the rack's
        // tip is too narrow for it: then the full round tip, the two roundings meeting on the rack
        // tooth's centreline (ISO 53's largest ρ_fP; 0.39 m for type D's h_fP = 1.4 m).
        let rho = ((h_fp - h_ap) / (1.0 - alpha.sin())).min(half_tip * alpha.cos() / (1.0 - alpha.sin()));
        let a1 = h_fp - shift - rho;
        let b1 = std::f64::consts::PI * m / 4.0 + h_fp * alpha.tan() + rho * (1.0 - alpha.sin()) / alpha.cos();
        // The rack's straight flank ends h_fP − x m − ρ(1 − sin α) inside the pitch circle.
        let flank_end = (h_fp - shift - rho * (1.0 - alpha.sin())) / alpha.sin();
        if r_b * alpha.tan() <= flank_end {
            return Err(OutlineProblem::Undercut);
        }
        let form_radius = r_b.hypot(r_b * alpha.tan() - flank_end);
        let limit = form_radius.min(input.tip_radius);
        if input.root_radius >= limit {
            return Err(OutlineProblem::RootTooHigh { root: input.root_radius, limit });
        }
        // Half the angular thickness at the pitch circle: (π m_t/2 + 2 x m tan α_t)/(2r).
        let psi_pitch = (std::f64::consts::PI * m / 2.0 + 2.0 * shift * alpha.tan()) / (2.0 * r);
        Ok(ToothOutline {
            input,
            pitch_radius: r,
            base_radius: r_b,
            rack_dedendum: h_fp,
            tip_rounding: rho,
            a1,
            b1,
            form_radius,
            psi0: psi_pitch + involute(alpha),
        })
    }

    /// Roll length ℓ = √(r² − r_b²) of a radius.
    pub fn roll_of(&self, r: f64) -> f64 {
        (r * r - self.base_radius * self.base_radius).max(0.0).sqrt()
    }

    /// ℓ at the form circle and at the tip: the involute's extent.
    pub fn involute_rolls(&self) -> [f64; 2] {
        [self.roll_of(self.form_radius), self.roll_of(self.input.tip_radius)]
    }

    /// ψ, the half angular thickness, at roll length ℓ: ψ(r) = π/(2z) + 2 x m tan α/(z m) + inv α − inv α_r.
    pub fn half_angle(&self, roll: f64) -> f64 {
        let t = roll / self.base_radius;
        self.psi0 - (t - t.atan())
    }

    /// The involute point at roll length ℓ, with dy/dℓ = (cos ψ + sin ψ tan α_r) ℓ/r.
    pub fn involute_point(&self, roll: f64) -> OutlinePoint {
        let r = self.base_radius.hypot(roll);
        let psi = self.half_angle(roll);
        let (s, c) = psi.sin_cos();
        let tan_ar = roll / self.base_radius;
        OutlinePoint { y: r * c, h: r * s, dy: (c + s * tan_ar) * roll / r }
    }

    /// The fillet point at the rack's rounding-normal angle γ ∈ [α, π/2] (γ = π/2 at the root
    /// circle, γ = α at the form circle): φ = (a1/tan γ + b1)/r, q = a1/sin γ + ρ,
    /// h = r sin φ − q cos(γ − φ), y = r cos φ − q sin(γ − φ), and dy/dγ.
    pub fn fillet_point(&self, gamma: f64) -> OutlinePoint {
        let r = self.pitch_radius;
        let (sg, cg) = gamma.sin_cos();
        let phi = (self.a1 * cg / sg + self.b1) / r;
        let q = self.a1 / sg + self.tip_rounding;
        let d_phi = -self.a1 / (r * sg * sg);
        let (sgp, cgp) = (gamma - phi).sin_cos();
        let h = r * phi.sin() - q * cgp;
        let y = r * phi.cos() - q * sgp;
        let dy = -r * phi.sin() * d_phi + self.a1 * cg * sgp / (sg * sg) - q * cgp * (1.0 - d_phi);
        OutlinePoint { y, h, dy }
    }

    /// The fillet's angle at the root circle, θ_f = b1/r, and y there (the foot of the tooth).
    pub fn root_angle(&self) -> f64 {
        self.b1 / self.pitch_radius
    }

    /// y of the root point, the origin of the tooth's integrals.
    pub fn root_y(&self) -> f64 {
        self.fillet_point(FRAC_PI_2).y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fzg_pinion() -> ToothOutline {
        let m = 4.5e-3;
        let r = m * 16.0 / 2.0;
        ToothOutline::new(ToothInput {
            teeth: 16,
            transverse_module: m,
            normal_module: m,
            pressure_angle: 20f64.to_radians(),
            shift: 0.1817 * m,
            tip_radius: 0.5 * 82.46e-3,
            root_radius: r - (1.25 * m - 0.1817 * m),
        })
        .unwrap()
    }

    /// The fillet meets the root circle at θ_f and the involute at the form circle, in position
    /// (1e-12 m) — the check that the rack's a1, b1 and ρ describe one continuous outline.
    #[test]
    fn fillet_meets_root_and_involute() {
        let t = fzg_pinion();
        let root = t.fillet_point(FRAC_PI_2);
        let rf = t.input.root_radius;
        assert!((root.y - rf * t.root_angle().cos()).abs() < 1e-12);
        assert!((root.h - rf * t.root_angle().sin()).abs() < 1e-12);
        let f = t.fillet_point(t.input.pressure_angle);
        let i = t.involute_point(t.involute_rolls()[0]);
        assert!((f.y - i.y).abs() < 1e-12 && (f.h - i.h).abs() < 1e-12, "{f:?} {i:?}");
        assert!((f.y.hypot(f.h) - t.form_radius).abs() < 1e-12);
    }

    /// dy along each parameter equals a central difference (1e-7 relative).
    #[test]
    fn slopes_match_differences() {
        let t = fzg_pinion();
        let d = 1e-6;
        for g in [0.5, 0.9, 1.3] {
            let fd = (t.fillet_point(g + d).y - t.fillet_point(g - d).y) / (2.0 * d);
            assert!((t.fillet_point(g).dy - fd).abs() < 1e-7 * fd.abs().max(1e-3), "γ {g}");
        }
        let [l0, l1] = t.involute_rolls();
        for l in [l0, 0.5 * (l0 + l1), l1] {
            let dd = 1e-9;
            let fd = (t.involute_point(l + dd).y - t.involute_point(l - dd).y) / (2.0 * dd);
            assert!((t.involute_point(l).dy - fd).abs() < 1e-6 * fd.abs(), "ℓ {l}");
        }
    }

    /// The rack's tip radius against ISO 53: h_fP = 1.25 m gives type A's ρ_fP = 0.38 m (0.25/(1 −
    /// sin 20°) = 0.37995 m); type D's h_fP = 1.4 m leaves too narrow a tip for 0.4/(1 − sin 20°), so
    /// the tip is full round, ρ_fP = (π/4 − 1.4 tan 20°) cos 20°/(1 − sin 20°) m = 0.39394 m (ISO 53
    /// prints 0.39), and its root point lies mid-space, θ_f = π/z (1e-12; z = 20, x = 0.145); the outline stays
    /// continuous. A dedendum past π m/(4 tan α) is refused.
    #[test]
    fn rack_tip_radius_of_iso_53_types_a_and_d() {
        let m = 8e-3;
        let tooth = |h_fp: f64| {
            let r = m * 20.0 / 2.0;
            ToothOutline::new(ToothInput {
                teeth: 20,
                transverse_module: m,
                normal_module: m,
                pressure_angle: 20f64.to_radians(),
                shift: 0.145 * m,
                tip_radius: r + 1.145 * m,
                root_radius: r - (h_fp - 0.145) * m,
            })
        };
        let a = tooth(1.25).unwrap();
        assert!((a.tip_rounding / m - 0.25 / (1.0 - 20f64.to_radians().sin())).abs() < 1e-12);
        assert!((a.tip_rounding / m - 0.37995).abs() < 1e-5);
        let d = tooth(1.4).unwrap();
        assert!((d.tip_rounding / m - 0.39394).abs() < 1e-5, "{}", d.tip_rounding / m);
        assert!((d.root_angle() - std::f64::consts::PI / 20.0).abs() < 1e-12);
        let (f, i) = (d.fillet_point(d.input.pressure_angle), d.involute_point(d.involute_rolls()[0]));
        assert!((f.y - i.y).abs() < 1e-12 && (f.h - i.h).abs() < 1e-12);
        assert!(matches!(tooth(2.2), Err(OutlineProblem::PointedRack { .. })));
    }

    /// The tip half-thickness equals the pair geometry's s_a/2 (ISO 21771) to 1e-12 m.
    #[test]
    fn tip_thickness_agrees_with_iso_21771() {
        let t = fzg_pinion();
        let tip = t.involute_point(t.involute_rolls()[1]);
        let alpha = t.input.pressure_angle;
        let ra = t.input.tip_radius;
        let aa = (t.base_radius / ra).acos();
        let sa = 2.0 * ra * ((FRAC_PI_2 + 2.0 * 0.1817 * alpha.tan()) / 16.0 + involute(alpha) - involute(aa));
        // h is the half chord at the tip: r sin(ψ), s_a/2 = r ψ.
        assert!((tip.h - ra * (sa / (2.0 * ra)).sin()).abs() < 1e-12);
    }
}
