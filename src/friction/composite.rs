//! Composite friction, Model V (He–Cho–Singh eq 20–21): the regime follows the film parameter Λ at
//! each contact — Λ < 1 boundary → smoothed Coulomb (Model IV), 1 ≤ Λ < 4 mixed → Benedict–Kelley
//! eq 14 (Model II), Λ ≥ 4 full film → Xu (Model III). Λ = h_c/R_comp · sqrt(L_x/(2 b_H)) with the
//! Dowson–Toyoda central film (`crate::tribology::film`). Model IV's magnitude is the mean |μ_BK|
//! over A–E at the operating point unless `mu` is given (He–Cho–Singh §3.5, their ref \[4\]).

use super::benedict_kelley::BenedictKelley;
use super::friction_law::{FrictionLaw, Parameter, Regime};
use super::law_context::LawContext;
use super::needs::Needs;
use super::smoothed_coulomb::SmoothedCoulomb;
use super::xu::Xu;
use crate::geometry::ContactPoint;
use crate::numerics::quadrature::integrate_singular;
use crate::numerics::roots::{bracketed_roots, brent};
use crate::tribology::FilmInputs;

/// Λ thresholds between boundary/mixed and mixed/full film.
pub(super) const MIXED_FROM: f64 = 1.0;
pub(super) const FULL_FILM_FROM: f64 = 4.0;

#[derive(Debug, Clone)]
pub struct Composite {
    pub filter_cutoff: f64,
    pub rq_composite: f64,
    pub film: FilmInputs,
    pub boundary: SmoothedCoulomb,
    pub mixed: BenedictKelley,
    /// Xu without its own film check: Model V uses it only where its Λ ≥ 4.
    pub full_film: Xu,
    /// True when Model IV's magnitude was derived as the mean |μ_BK| over A–E.
    pub mu_from_benedict_kelley: bool,
    switches: Vec<f64>,
    mixed_at_pitch: bool,
}

impl Composite {
    pub fn new(ctx: &LawContext, filter_cutoff: f64, mu: Option<f64>, phi: f64) -> Result<Self, Needs> {
        let t = &ctx.tribology;
        let mixed = BenedictKelley::new(t)?;
        let p = ctx.geometry.points;
        let (mu, derived) = if let Some(mu) = mu {
            (mu, false)
        } else {
            let mean = integrate_singular(
                |u, d| mixed.magnitude(&d.map_or_else(|| ctx.contact_at(u), |d| ctx.contact_at_offset(d))).max(0.0),
                &[
                    [p.a, p.p, p.e].as_slice(),
                    &ctx.geometry.pair_change_points().iter().map(|(_, u)| *u).collect::<Vec<_>>(),
                ]
                .concat(),
                &[p.p],
                1e-10,
            );
            (mean.value / (p.e - p.a), true)
        };
        let mut law = Composite {
            filter_cutoff,
            rq_composite: Needs::RoughnessRq.of(t.rq_composite)?,
            film: FilmInputs {
                dynamic_viscosity: t.dynamic_viscosity,
                pressure_viscosity: Needs::PressureViscosity.of(t.pressure_viscosity)?,
                reduced_modulus: t.reduced_modulus,
            },
            boundary: SmoothedCoulomb { mu, phi },
            mixed,
            full_film: Xu::from_units(
                t.dynamic_viscosity * crate::tribology::units::CP_PER_PA_S,
                Needs::RoughnessRa.of(t.ra_mean)? * crate::tribology::units::UM_PER_M,
            ),
            mu_from_benedict_kelley: derived,
            switches: Vec::new(),
            mixed_at_pitch: false,
        };
        law.switches = law.find_switches(ctx);
        law.mixed_at_pitch = Self::regime_of(law.lambda(&ctx.contact_at(p.p))) == Regime::Mixed;
        Ok(law)
    }

    /// Λ at a contact.
    pub fn lambda(&self, c: &ContactPoint) -> f64 {
        self.film.lambda(c, self.rq_composite, self.filter_cutoff)
    }

    pub fn regime_of(lambda: f64) -> Regime {
        if lambda < MIXED_FROM {
            Regime::Boundary
        } else if lambda < FULL_FILM_FROM {
            Regime::Mixed
        } else {
            Regime::FullFilm
        }
    }

    /// Positions where the regime changes, located, never read off a grid: A–E is split where Λ may
    /// jump (every point where the number of pairs and so the load changes); on each smooth piece the
    /// critical points of Λ(u) (roots of a central-difference dΛ/du bracketed on 60 nodes, Brent)
    /// split it further into stretches where Λ is monotone, and on each of those Λ(u) − 1 and
    /// Λ(u) − 4 have at most one root, found by Brent's method to 1e-12 of A–E. A jump across a level
    /// at B or D is a switch there. So a band narrower than the grid is found as long as it contains a
    /// critical point of Λ between two nodes of opposite slope.
    fn find_switches(&self, ctx: &LawContext) -> Vec<f64> {
        let p = ctx.geometry.points;
        let span = p.e - p.a;
        let xtol = 1e-12 * span;
        let nudge = 1e-12 * span;
        let lambda = |u: f64| self.lambda(&ctx.contact_at(u));
        let mut cuts = vec![p.a];
        cuts.extend(
            ctx.geometry.pair_change_points().iter().map(|(_, u)| *u).filter(|u| *u > p.a + nudge && *u < p.e - nudge),
        );
        cuts.push(p.e);
        cuts.sort_by(f64::total_cmp);
        let mut out = Vec::new();
        let mut last_regime: Option<Regime> = None;
        for w in cuts.windows(2) {
            let (a, b) = (w[0] + nudge, w[1] - nudge);
            if b <= a {
                continue;
            }
            let h = 1e-7 * (b - a);
            let slope = |u: f64| lambda((u + h).min(b)) - lambda((u - h).max(a));
            let n = 60;
            let grid: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
            let mut knots = vec![a];
            knots.extend(bracketed_roots(slope, &grid, xtol));
            knots.push(b);
            let start = Self::regime_of(lambda(a));
            if last_regime.is_some_and(|r| r != start) {
                out.push(w[0]);
            }
            for k in knots.windows(2) {
                let (l0, l1) = (lambda(k[0]), lambda(k[1]));
                let mut roots: Vec<f64> = [MIXED_FROM, FULL_FILM_FROM]
                    .into_iter()
                    .filter(|level| (l0 < *level) != (l1 < *level))
                    .map(|level| brent(|u| lambda(u) - level, k[0], k[1], xtol))
                    .collect();
                roots.sort_by(f64::total_cmp);
                out.extend(roots);
            }
            last_regime = Some(Self::regime_of(lambda(b)));
        }
        out
    }
}

impl FrictionLaw for Composite {
    fn id(&self) -> super::law_id::LawId {
        super::law_id::LawId::Composite
    }
    fn mu(&self, c: &ContactPoint) -> f64 {
        match Self::regime_of(self.lambda(c)) {
            Regime::Boundary => self.boundary.mu(c),
            Regime::Mixed => self.mixed.mu(c),
            Regime::FullFilm => self.full_film.mu(c),
        }
    }
    fn validity(&self, c: &ContactPoint) -> Result<(), &'static str> {
        match Self::regime_of(self.lambda(c)) {
            Regime::Boundary => Ok(()),
            Regime::Mixed => self.mixed.validity(c),
            Regime::FullFilm => self.full_film.validity(c),
        }
    }
    /// Only where the mixed regime (Benedict–Kelley) holds at the pitch point.
    fn diverges_at_pitch(&self) -> bool {
        self.mixed_at_pitch
    }
    fn regime(&self, c: &ContactPoint) -> Option<Regime> {
        Some(Self::regime_of(self.lambda(c)))
    }
    fn switch_points(&self) -> Vec<f64> {
        self.switches.clone()
    }
    fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter { name: "filter_cutoff", value: self.filter_cutoff, unit: "m" },
            Parameter { name: "mu_boundary", value: self.boundary.mu, unit: "1" },
            Parameter { name: "phi", value: self.boundary.phi, unit: "1/m" },
            Parameter { name: "rq_composite", value: self.rq_composite, unit: "m" },
        ]
    }
    fn notes(&self) -> Vec<String> {
        let mut v = vec![format!(
            "composite: regimes by He–Cho–Singh's Λ_HCS (Dowson–Toyoda central film, L_x = {:.3} mm; film table): Λ_HCS < 1 smoothed Coulomb, 1 ≤ Λ_HCS < 4 Benedict–Kelley eq 14, Λ_HCS ≥ 4 Xu",
            self.filter_cutoff * 1e3
        )];
        if self.mu_from_benedict_kelley {
            v.push(format!("composite: Model IV magnitude μ = {:.5}, the mean |μ_BK| over A–E", self.boundary.mu));
        }
        v
    }
}
