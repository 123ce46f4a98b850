//! # dynamics
//!
//! One job: integrate a head-on collision of two identical viscoelastic adhesive spheres and
//! report its outcome (Arakawa & Krijt 2021, Sections 2.5, 2.6 and 4). It uses `contact` for
//! the forces and units and `greenwood` for the crack law; it knows nothing of thresholds.
//!
//! ## Equations
//! ```text
//! delta_ddot = -(F_E + F_D) / m*                                  (Sec. 2.5, Eq. d_dt)
//! a_dot      = v(k, beta) E* gamma / (sigma0^2 T_vis),  beta = G_eff(a, delta)/gamma   (Sec. 2.3-2.4)
//! t = 0: delta = 0, delta_dot = V_in, beta = (1 + eps) k;  end: beta = (1 - eps)/k, eps = 0.01   (Sec. 2.6)
//! e = -V_out / V_in                                                (Sec. 4.4)
//! ```
//! integrated with diffsol's stiff solvers (BDF or ESDIRK34, analytic Jacobian) in the
//! nondimensional variables and pseudo-time described in [`model`]. Sticking is decided by the
//! energy bound and oscillation criteria described in [`collision`].

#![warn(missing_docs)]

pub mod collision;
pub mod error;
pub mod model;
pub mod scales;

pub use collision::{
    Backend, Collider, Collision, Method, Outcome, SolverOptions, StickingCriterion,
    TrajectoryPoint, EPS,
};
pub use error::DynamicsError;
pub use scales::Scales;
