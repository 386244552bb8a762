//! The lubricant at an oil temperature: an oil given by grade or by ν40, ν100 and ρ15 read at θ
//! (ν by ASTM D341, ρ by thermal expansion, η = ρν, α from the base oil unless given), and ν of
//! any lubricant.

use crate::diagnostics::Span;
use crate::model::{DynamicViscosity, Given, Lubricant, MassDensity, ReciprocalPressure, ThermodynamicTemperature};

impl Lubricant {
    /// The lubricant's values read at `kelvin` (a temperature the run found, not one the scene
    /// wrote: a balance's every trial temperature): [`Self::at_temperature`]'s numbers, without its
    /// name and the values written out as text (nothing reads them there).
    pub(crate) fn at_kelvin(&self, kelvin: f64) -> Lubricant {
        let theta = Given {
            value: ThermodynamicTemperature::new::<uom::si::thermodynamic_temperature::kelvin>(kelvin),
            written: String::new(),
            span: Default::default(),
        };
        match &self.oil {
            Some(oil) => {
                let given = self.pressure_viscosity.as_ref().filter(|_| !self.alpha_from_oil);
                let alpha = given.map(|a| Given { value: a.value, written: String::new(), span: a.span });
                let span = self.dynamic_viscosity.span;
                Lubricant::of_oil_written(String::new(), oil.clone(), alpha, (span, &theta), false)
            }
            None => self.clone().moved_to(&theta, false),
        }
    }

    /// The lubricant at oil temperature θ: an oil given by grade or by ν40, ν100 and ρ15 moved
    /// there ([`Lubricant::of_oil`]); one given by its viscosity as it is (α kept unless it came from
    /// the base oil).
    pub fn at_temperature(self, theta: &Given<ThermodynamicTemperature>) -> Lubricant {
        self.moved_to(theta, true)
    }

    fn moved_to(self, theta: &Given<ThermodynamicTemperature>, write: bool) -> Lubricant {
        let alpha = if self.alpha_from_oil { None } else { self.pressure_viscosity };
        let span = self.dynamic_viscosity.span;
        match self.oil {
            Some(oil) => Lubricant::of_oil_written(self.name, oil, alpha, (span, theta), write),
            None => Lubricant { pressure_viscosity: alpha, ..self },
        }
    }

    /// An oil given by grade or by ν40, ν100 and ρ15, at the oil temperature θ: ν by ASTM D341, ρ by
    /// thermal expansion, η = ρν, α from the base oil unless `alpha` is given
    /// ([`crate::tribology::lubricant::OilData::at`]).
    pub fn of_oil(
        name: String,
        oil: crate::tribology::lubricant::OilData,
        alpha: Option<Given<ReciprocalPressure>>,
        span: Span,
        theta: &Given<ThermodynamicTemperature>,
    ) -> Lubricant {
        Lubricant::of_oil_written(name, oil, alpha, (span, theta), true)
    }

    /// [`Self::of_oil`], its values written out as text where `write`.
    fn of_oil_written(
        name: String,
        oil: crate::tribology::lubricant::OilData,
        alpha: Option<Given<ReciprocalPressure>>,
        (span, theta): (Span, &Given<ThermodynamicTemperature>),
        write: bool,
    ) -> Lubricant {
        use uom::si::dynamic_viscosity::pascal_second;
        use uom::si::mass_density::kilogram_per_cubic_meter;
        use uom::si::thermodynamic_temperature::kelvin;
        let at = oil.at(theta.value.get::<kelvin>());
        // Not written by the user: read from the oil's data at θ, and said so beside the value.
        let at_theta = format!("the oil's at {}", theta.written);
        let written = |x: f64, unit: &str, scale: f64| {
            if write {
                format!("{:.6} {unit} ({at_theta})", x * scale)
            } else {
                String::new()
            }
        };
        let alpha_from_oil = alpha.is_none() && at.pressure_viscosity.is_some();
        let alpha = alpha.or_else(|| {
            at.pressure_viscosity.map(|a| Given {
                value: ReciprocalPressure {
                    dimension: std::marker::PhantomData,
                    units: std::marker::PhantomData,
                    value: a,
                },
                written: if write {
                    format!("{a:.4e} 1/Pa (the base oil's at {})", theta.written)
                } else {
                    String::new()
                },
                span,
            })
        });
        Lubricant {
            name,
            dynamic_viscosity: Given {
                value: DynamicViscosity::new::<pascal_second>(at.dynamic_viscosity),
                written: written(at.dynamic_viscosity, "mPa*s", 1e3),
                span,
            },
            density: Some(Given {
                value: MassDensity::new::<kilogram_per_cubic_meter>(at.density),
                written: written(at.density, "kg/m^3", 1.0),
                span,
            }),
            kinematic_viscosity: None,
            pressure_viscosity: alpha,
            kind: Some(oil.base),
            temperature: Some(theta.clone()),
            oil: Some(oil),
            alpha_from_oil,
        }
    }
}

impl Lubricant {
    /// ν = η/ρ in m²/s, from whichever of density and kinematic viscosity was given.
    pub fn kinematic_viscosity_si(&self) -> Option<f64> {
        use uom::si::diffusion_coefficient::square_meter_per_second;
        use uom::si::dynamic_viscosity::pascal_second;
        use uom::si::mass_density::kilogram_per_cubic_meter;
        if let Some(nu) = &self.kinematic_viscosity {
            return Some(nu.value.get::<square_meter_per_second>());
        }
        self.density.as_ref().map(|rho| {
            self.dynamic_viscosity.value.get::<pascal_second>() / rho.value.get::<kilogram_per_cubic_meter>()
        })
    }
}
