//! The measurements and constants the paper compares with, stated once: the laboratory
//! thresholds of Musiolik et al. (2016a, b) and Gundlach et al. (2015), the surface energies of
//! H2O ice, the density of Section 5.4 and the collision speeds of Section 6 (Arakawa & Krijt
//! 2021). The figures (`cargo xtask figures`), the tests and the examples take them from here.
//!
//! # Example
//! ```
//! use thresholds::paper::MUSIOLIK_2016A;
//! assert_eq!((MUSIOLIK_2016A.v_stick, MUSIOLIK_2016A.v_stick_err), (0.04, 0.02)); // m/s
//! assert_eq!(MUSIOLIK_2016A.radius, 60e-6); // m, the typical grain
//! ```

/// A measured threshold velocity for sticking, with the grains it was measured on (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Where it is reported, as cited by the paper.
    pub source: &'static str,
    /// The grains' material: `co2` or `h2o` (a preset name).
    pub material: &'static str,
    /// Measured V_stick (m/s).
    pub v_stick: f64,
    /// Its 1-sigma uncertainty (m/s); 0 where none is given.
    pub v_stick_err: f64,
    /// Typical grain radius R1 (m).
    pub radius: f64,
    /// The radii R1 (m) between which 80 % of the grains lie, where reported.
    pub radius_80_percent: Option<(f64, f64)>,
    /// Whether the grains hit a flat target of the same ice (a sphere on a wall) rather than
    /// each other.
    pub on_wall: bool,
}

/// Musiolik et al. (2016a), Section 5.1: CO2 ice grains of R1 about 60 um (80 % of them within
/// 40-120 um, their Figure 4), shot at a CO2-covered target at 80 K, stick below
/// V_stick = 0.04 ± 0.02 m/s. The paper models them as two identical spheres; the experiment
/// is a sphere on a wall.
pub const MUSIOLIK_2016A: Measurement = Measurement {
    source: "Musiolik et al. (2016a)",
    material: "co2",
    v_stick: 0.04,
    v_stick_err: 0.02,
    radius: 60e-6,
    radius_80_percent: Some((40e-6, 120e-6)),
    on_wall: true,
};

/// Musiolik et al. (2016b), Section 5.2: H2O ice grains of R1 about 90 um at 80 K stick below
/// V_stick ~ 0.73 m/s (no uncertainty given).
pub const MUSIOLIK_2016B: Measurement = Measurement {
    source: "Musiolik et al. (2016b)",
    material: "h2o",
    v_stick: 0.73,
    v_stick_err: 0.0,
    radius: 90e-6,
    radius_80_percent: None,
    on_wall: true,
};

/// Gundlach & Blum (2015), cited as Gundlach et al. (2015), Section 5.3: H2O ice grains of
/// R1 = 1.5 um stick below V_stick = 9.6 ± 0.3 m/s (modelled, as the paper does, as two
/// identical spheres).
pub const GUNDLACH_2015: Measurement = Measurement {
    source: "Gundlach & Blum (2015)",
    material: "h2o",
    v_stick: 9.6,
    v_stick_err: 0.3,
    radius: 1.5e-6,
    radius_80_percent: None,
    on_wall: false,
};

/// Gundlach et al. (2015), Section 5.3: T_vis = 1e-10 s reproduces [`GUNDLACH_2015`] for
/// H2O grains of R1 = 1.5 um: `(R1 (m), T_vis (s))`, the anchor of the H2O size law.
pub const GUNDLACH_2015_T_VIS: (f64, f64) = (1.5e-6, 1e-10);

/// The surface free energy gamma_SV of H2O ice (J/m^2), Section 5.2: 0.02 from tensile strength
/// below 150 K (Gundlach et al. 2018) to 0.19 from rolling friction (Gundlach et al. 2011).
pub const H2O_GAMMA_SV_RANGE: (f64, f64) = (0.02, 0.19);

/// The CO2 density of Section 5.4 (kg/m^3); Section 2.5 states 1560, which reproduces the
/// paper's V_stick,JKR and is the preset's (`contact::Material::co2`).
pub const CO2_DENSITY_SECTION_5_4: f64 = 1650.0;

/// The maximum collision speeds of dust aggregates in weakly turbulent discs (m/s), Section 6:
/// 25-50 m/s (Adachi et al. 1976; Blum 2008; Wada et al. 2013).
pub const V_COL_MAX: (f64, f64) = (25.0, 50.0);
