//! # contact
//!
//! One job: the contact mechanics of two adhesive, viscoelastic bodies of one material, as
//! reviewed in Arakawa & Krijt (2021), Section 2, with the JKR thresholds of Sections 5.1 and 6.
//! This crate knows nothing about time integration or the crack law; every quantity is SI.
//!
//! ## Quick start
//! ```
//! use contact::{Contact, Geometry, Material};
//! // the paper's CO2 grains: two identical spheres of R1 = 60 um
//! let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! assert!((c.v_stick_jkr() - 1.66e-2).abs() < 5e-5); // Section 5.1: 1.66e-2 m/s
//! // a 60 um grain on a CO2 wall, or a 60 um grain meeting a 30 um one
//! let wall = Contact::new(Material::co2(), Geometry::wall(60e-6))?;
//! let pair = Contact::new(Material::co2(), Geometry::spheres(60e-6, 30e-6))?;
//! assert!(wall.v_stick_jkr() > c.v_stick_jkr() && pair.v_stick_jkr() > c.v_stick_jkr());
//! # Ok::<(), contact::ContactError>(())
//! ```
//!
//! ## Equations
//! With the reduced radius and mass of the [`Geometry`] (`R = R1 R2/(R1 + R2)`,
//! `m* = m1 m2/(m1 + m2)`; `R1/2` and `m1/2` for the paper's identical spheres, `R1` and `m1` on a
//! wall), `E* = E/(2(1 - nu^2))` and `gamma = 2 gamma_SV`:
//! ```text
//! a_eq     = (9 pi gamma R^2 / (2 E*))^(1/3)                     (Sec. 2.2)
//! delta_eq = (3 pi^2 R gamma^2 / (4 E*^2))^(1/3) = a_eq^2/(3R)   (Sec. 2.2)
//! mu       = (R gamma^2 / E*^2)^(1/3) / epsilon,  epsilon = 0.3 nm   (Tabor parameter, Sec. 2.2)
//! U_E      = E* a^3/(3R) [delta (3 delta R/a^2 - 1) - a^2/(5R) (5 delta R/a^2 - 3)]   (Sec. 2.1)
//! U_S      = -pi a^2 gamma                                         (Sec. 2.2)
//! G_eff    = E* (a^2 - delta R)^2 / (2 pi a R^2),  beta = G_eff/gamma   (Sec. 2.4)
//! F_E      = 2E*/(3R) (3 a delta R - a^3)                          (Sec. 2.5)
//! F_D      = 2 A E* a delta_dot,  A = T_vis / nu^2                 (Sec. 2.5)
//! a_dot    = v(k, beta) E* gamma / (sigma0^2 T_vis),  sigma0 = gamma/epsilon   (Sec. 2.3)
//! a(t=0)   = [2 pi R^2 (1 + eps) k gamma / E*]^(1/3)               (Sec. 4.1)
//! F_crit   = 3 pi gamma R / 2,  delta_crit = (9/16)^(1/3) delta_eq    (Sec. 6)
//! V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6)          (Sec. 5.1)
//! E_stick,JKR = m* V_stick,JKR^2 / 2 = 0.9355 F_crit delta_crit,  E_break,JKR = 1.54 F_crit delta_crit   (Sec. 6)
//! ```
//! Materials (Section 3): [`Material::co2`] (E and nu from sound speeds) and [`Material::h2o`], or
//! a JSON file with the fields `gamma_sv`, `young`, `poisson`, `density`.

pub mod dimensionless;
pub mod error;
pub mod geometry;
pub mod material;
pub mod pair;
pub mod warning;

pub use dimensionless::Dimensionless;
pub use error::ContactError;
pub use geometry::Geometry;
pub use material::{elastic_from_sound_speeds, Material, PRESETS};
pub use numerics::OutOfRange;
pub use pair::{Contact, JKR_QUANTITIES, SURFACE_FORCE_RANGE, TABOR_MIN};
pub use warning::{
    Warning, PLAUSIBLE_DENSITY, PLAUSIBLE_GAMMA_SV, PLAUSIBLE_RADIUS, PLAUSIBLE_SPEED_MAX,
    PLAUSIBLE_YOUNG,
};
