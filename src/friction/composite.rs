//! Composite friction, Model V (He–Cho–Singh eq 20–21): the regime follows the film parameter Λ at
//! each contact — Λ < 1 boundary → smoothed Coulomb (Model IV), 1 ≤ Λ < 4 mixed → Benedict–Kelley
//! eq 14 (Model II), Λ ≥ 4 full film → Xu (Model III). Λ = h_c/R_comp · sqrt(L_x/(2 b_H)) with the
//! Dowson–Toyoda central film ([`crate::tribology::film`]). Model IV's magnitude is the mean |μ_BK|
//! over A–E at the operating point unless `mu` is given (He–Cho–Singh §3.5, their ref [4]).

use super::benedict_kelley::BenedictKelley;
use super::smoothed_coulomb::SmoothedCoulomb;
use super::xu::Xu;
use super::{FrictionLaw, LawContext, Parameter, Regime};
use crate::geometry::ContactPoint;
use crate::numerics::quadrature::integrate_singular;
use crate::tribology::FilmInputs;

/// Λ thresholds between boundary/mixed and mixed/full film.
pub const MIXED_FROM: f64 = 1.0;
pub const FULL_FILM_FROM: f64 = 4.0;

#[derive(Debug, Clone)]
pub struct Composite {
    pub filter_cutoff: f64,
    pub rq_composite: f64,
    pub film: FilmInputs,
    pub boundary: SmoothedCoulomb,
    pub mixed: BenedictKelley,
    pub full_film: Xu,
    /// True when Model IV's magnitude was derived as the mean |μ_BK| over A–E.
    pub mu_from_benedict_kelley: bool,
    switches: Vec<f64>,
    mixed_at_pitch: bool,
}

impl Composite {
    pub fn new(ctx: &LawContext, filter_cutoff: f64, mu: f64, phi: f64) -> Self {
        let t = &ctx.tribology;
        let mixed = BenedictKelley::new(t);
        let p = ctx.geometry.points;
        let (mu, derived) = if mu.is_finite() {
            (mu, false)
        } else {
            let mean = integrate_singular(
                |u, d| {
                    mixed.magnitude(&if d.is_finite() { ctx.contact_at_offset(d) } else { ctx.contact_at(u) }).max(0.0)
                },
                &[p.a, p.b, p.p, p.d, p.e],
                &[p.p],
                1e-10,
            );
            (mean.value / (p.e - p.a), true)
        };
        let mut law = Composite {
            filter_cutoff,
            rq_composite: t.rq_composite.unwrap_or(f64::NAN),
            film: FilmInputs {
                dynamic_viscosity: t.dynamic_viscosity,
                pressure_viscosity: t.pressure_viscosity.unwrap_or(f64::NAN),
                reduced_modulus: t.reduced_modulus,
            },
            boundary: SmoothedCoulomb { mu, phi },
            mixed,
            full_film: Xu::new(t),
            mu_from_benedict_kelley: derived,
            switches: Vec::new(),
            mixed_at_pitch: false,
        };
        law.switches = law.find_switches(ctx);
        law.mixed_at_pitch = Self::regime_of(law.lambda(&ctx.contact_at(p.p))) == Regime::Mixed;
        law
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

    /// Positions where the regime changes, by bisection between samples of different regime.
    fn find_switches(&self, ctx: &LawContext) -> Vec<f64> {
        let p = ctx.geometry.points;
        let n = 60;
        let at = |u: f64| Self::regime_of(self.lambda(&ctx.contact_at(u)));
        let mut out = Vec::new();
        let mut prev_u = p.a;
        let mut prev = at(p.a);
        for i in 1..=n {
            let u = p.a + (p.e - p.a) * i as f64 / n as f64;
            let r = at(u);
            if r != prev {
                let (mut lo, mut hi) = (prev_u, u);
                for _ in 0..64 {
                    let mid = 0.5 * (lo + hi);
                    if at(mid) == prev {
                        lo = mid
                    } else {
                        hi = mid
                    }
                }
                out.push(0.5 * (lo + hi));
            }
            prev = r;
            prev_u = u;
        }
        out
    }
}

impl FrictionLaw for Composite {
    fn id(&self) -> &'static str {
        "composite"
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
            "composite: regimes by Λ (Dowson–Toyoda central film, L_x = {:.3} mm): Λ < 1 smoothed Coulomb, 1 ≤ Λ < 4 Benedict–Kelley eq 14, Λ ≥ 4 Xu",
            self.filter_cutoff * 1e3
        )];
        if self.mu_from_benedict_kelley {
            v.push(format!("composite: Model IV magnitude μ = {:.5}, the mean |μ_BK| over A–E", self.boundary.mu));
        }
        v
    }
}
