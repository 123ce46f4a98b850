//! Warnings: inputs that are valid but likely a slip (a radius in micrometres, a constant in cgs
//! units), and contacts outside JKR theory's validity. Each [`Warning`]'s [`std::fmt::Display`]
//! form is the sentence shown to the user.

use crate::pair::TABOR_MIN;
use crate::Material;
use numerics::format::number;

/// Plausible grain radii R1 (m): 10 nm (below, the Tabor parameter of ices falls under 1) to
/// 1 cm (beyond, "grains" are pebbles). Outside, a result comes with a warning, since a radius
/// given in the wrong unit (60 for 60 um) is the likeliest slip.
pub const PLAUSIBLE_RADIUS: (f64, f64) = (1e-8, 1e-2);

/// Impact speeds above this (m/s) come with a warning: 1 km/s is far above grain collision
/// speeds in discs (tens of m/s), where contact mechanics no longer describes the impact.
pub const PLAUSIBLE_SPEED_MAX: f64 = 1e3;

/// Plausible surface free energies gamma_SV (J/m^2): 1 mJ/m^2 (below van der Waals solids) to
/// 5 J/m^2 (above the metals' 1-2.5). Ices and silicates lie at 0.02-0.2 (Section 3); a value
/// in erg/cm^2 (cgs: 80 for CO2's 0.08) is the likeliest slip.
pub const PLAUSIBLE_GAMMA_SV: (f64, f64) = (1e-3, 5.0);
/// Plausible Young's moduli E (Pa): 10 MPa (soft polymers) to 1.2 TPa (diamond). Ices lie at
/// 1e9-1e10 Pa (Section 3); a value in GPa (10.7 for CO2) is the likeliest slip. A value in
/// dyn/cm^2 (ten times the Pa value: 1.07e11 for CO2) lies within the range of stiff solids
/// (silicates, iron: 1e11-2e11 Pa) and is not caught.
pub const PLAUSIBLE_YOUNG: (f64, f64) = (1e7, 1.2e12);
/// Plausible material densities rho (kg/m^3) of a grain's material: 100 (below any solid but
/// aerogels) to 25 000 (above osmium's 22 600). Ices lie near 1000-1600; a value in g/cm^3
/// (1.56 for CO2) is the likeliest slip.
pub const PLAUSIBLE_DENSITY: (f64, f64) = (100.0, 2.5e4);

/// A material constant [`Warning::for_material`] checks.
struct Check {
    /// The field of [`Material`].
    field: &'static str,
    /// Its SI unit.
    unit: &'static str,
    /// Its plausible range (SI).
    range: (f64, f64),
    /// The unit slips it suggests: the factor from that unit to SI, and the unit's name.
    slips: &'static [(f64, &'static str)],
}

const MATERIAL_CHECKS: [Check; 3] = [
    Check {
        field: "gamma_sv",
        unit: "J/m^2",
        range: PLAUSIBLE_GAMMA_SV,
        slips: &[(1e-3, "erg/cm^2 (mJ/m^2)")],
    },
    Check {
        field: "young",
        unit: "Pa",
        range: PLAUSIBLE_YOUNG,
        slips: &[(1e9, "GPa"), (1e6, "MPa")],
    },
    Check {
        field: "density",
        unit: "kg/m^3",
        range: PLAUSIBLE_DENSITY,
        slips: &[(1e3, "g/cm^3")],
    },
];

impl Check {
    fn implausible(&self, value: f64) -> bool {
        value < self.range.0 || value > self.range.1
    }
}

/// A condition under which the model's results should be read with care; its
/// [`std::fmt::Display`] form is the sentence shown to the user.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Warning {
    /// The Tabor parameter is below [`TABOR_MIN`]: surface forces act outside the contact and JKR
    /// theory, on which the model stands, does not apply (Section 2.2).
    JkrOutsideValidity {
        /// The Tabor parameter mu (dimensionless).
        tabor: f64,
    },
    /// A radius outside [`PLAUSIBLE_RADIUS`] (valid, but likely given in the wrong unit).
    ImplausibleRadius {
        /// The input (`radius`).
        field: &'static str,
        /// Its value (m).
        value: f64,
    },
    /// A material constant outside its plausible range ([`PLAUSIBLE_GAMMA_SV`],
    /// [`PLAUSIBLE_YOUNG`], [`PLAUSIBLE_DENSITY`]): valid, but likely in the wrong unit.
    ImplausibleMaterial {
        /// The constant (`gamma_sv`, `young` or `density`, the fields of [`Material`]).
        field: &'static str,
        /// Its value (SI).
        value: f64,
    },
    /// A speed above [`PLAUSIBLE_SPEED_MAX`].
    ImplausibleSpeed {
        /// The input (`v_in`).
        field: &'static str,
        /// Its value (m/s).
        value: f64,
    },
}

impl Warning {
    /// A warning for an impact speed `value` (m/s) of the input `field` above
    /// [`PLAUSIBLE_SPEED_MAX`], else `None`.
    pub fn for_speed(field: &'static str, value: f64) -> Option<Self> {
        (value > PLAUSIBLE_SPEED_MAX).then_some(Self::ImplausibleSpeed { field, value })
    }

    /// The warnings for the constants of `material` outside their plausible ranges.
    pub fn for_material(material: &Material) -> impl Iterator<Item = Self> {
        let values = [material.gamma_sv, material.young, material.density];
        MATERIAL_CHECKS
            .iter()
            .zip(values)
            .filter(|(check, value)| check.implausible(*value))
            .map(|(check, value)| Self::ImplausibleMaterial {
                field: check.field,
                value,
            })
    }

    /// Whether any constant of `material` is outside its plausible range.
    pub fn any_for_material(material: &Material) -> bool {
        let values = [material.gamma_sv, material.young, material.density];
        MATERIAL_CHECKS
            .iter()
            .zip(values)
            .any(|(check, value)| check.implausible(value))
    }

    /// A warning for a radius `value` (m) of the input `field` outside [`PLAUSIBLE_RADIUS`],
    /// else `None`.
    pub fn for_radius(field: &'static str, value: f64) -> Option<Self> {
        let (lo, hi) = PLAUSIBLE_RADIUS;
        (value < lo || value > hi).then_some(Self::ImplausibleRadius { field, value })
    }
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Warning::JkrOutsideValidity { tabor } => write!(
                f,
                "Tabor parameter mu = {} < {}: JKR theory (mu >> 1) is outside its validity for these grains (Arakawa & Krijt 2021, Section 2.2)",
                number(tabor),
                number(TABOR_MIN)
            ),
            Warning::ImplausibleRadius { field, value } => {
                let (lo, hi) = PLAUSIBLE_RADIUS;
                write!(
                    f,
                    "{field} = {} m is outside the plausible range {} - {} m of dust and ice grains",
                    number(value),
                    number(lo),
                    number(hi)
                )?;
                // a value read as micrometres that lands inside the range: suggest it
                let micro = value * 1e-6;
                if value > hi && (lo..=hi).contains(&micro) {
                    let digits = number(value);
                    write!(f, "; did you mean {}e-6 m?", digits.trim_end_matches(".0"))?;
                }
                Ok(())
            }
            Warning::ImplausibleMaterial { field, value } => {
                let Some(check) = MATERIAL_CHECKS.iter().find(|c| c.field == field) else {
                    return write!(f, "{field} = {} is implausible", number(value));
                };
                let (unit, (lo, hi)) = (check.unit, check.range);
                write!(
                    f,
                    "{field} = {} {unit} is outside the plausible range {} - {} {unit} of dust and ice grains",
                    number(value),
                    number(lo),
                    number(hi)
                )?;
                // a unit slip that lands inside the range: suggest it
                if let Some((factor, name)) = check
                    .slips
                    .iter()
                    .find(|(factor, _)| !check.implausible(value * factor))
                {
                    write!(
                        f,
                        "; given in {name}? that is {} {unit}",
                        numerics::format::derived(value * factor)
                    )?;
                }
                Ok(())
            }
            Warning::ImplausibleSpeed { field, value } => write!(
                f,
                "{field} = {} m/s is above {} m/s, far beyond grain collision speeds in discs, where contact mechanics no longer applies",
                number(value),
                number(PLAUSIBLE_SPEED_MAX)
            ),
        }
    }
}
