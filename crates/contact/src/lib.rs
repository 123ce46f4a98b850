//! # contact
//!
//! One job: the contact mechanics of two identical adhesive, viscoelastic spheres, as reviewed in
//! Arakawa & Krijt (2021), Section 2, with the JKR thresholds of Sections 5.1 and 6. This crate
//! knows nothing about time integration or the crack law; every quantity is SI.
//!
//! ## Equations
//! With `R = R1/2`, `E* = E/(2(1 - nu^2))`, `m* = m1/2`, `gamma = 2 gamma_SV`:
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

#![warn(missing_docs)]

pub mod error;
pub mod material;
pub mod sphere;

pub use error::ContactError;
pub use material::{elastic_from_sound_speeds, Material, PRESETS};
pub use sphere::{Contact, Warning, SURFACE_FORCE_RANGE, TABOR_MIN};
