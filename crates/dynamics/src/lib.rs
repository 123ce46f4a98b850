//! # dynamics
//!
//! One job: integrate a head-on collision of two viscoelastic adhesive bodies (two spheres or a
//! sphere on a wall, `contact::Geometry`) and report its outcome (Arakawa & Krijt 2021,
//! Sections 2.5 and 4). It uses `contact` for the forces and units and `greenwood` for the
//! crack law; it knows nothing of thresholds.
//!
//! ## Quick start
//! ```
//! use contact::{Contact, Geometry, Material};
//! use dynamics::{Collider, Outcome};
//! use greenwood::CrackLaw;
//! // Section 4: CO2 grains of 60 um at T_vis = 1e-9 s bounce at 4.5 cm/s
//! let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! let collider = Collider::new(contact, CrackLaw::new(0.01)?, 1e-9)?;
//! let c = collider.collide(0.045)?;
//! assert_eq!(c.outcome, Outcome::Bouncing);
//! if let Some(t) = c.contact_time {
//!     println!("e = {}, contact time = {t} s", c.e);
//! }
//! # Ok::<(), dynamics::DynamicsError>(())
//! ```
//!
//! ## Equations
//! ```text
//! delta_ddot = -(F_E + F_D) / m*                                  (Sec. 2.5, Eq. d_dt)
//! a_dot      = v(k, beta) E* gamma / (sigma0^2 T_vis),  beta = G_eff(a, delta)/gamma   (Sec. 2.3-2.4)
//! t = 0: delta = 0, delta_dot = V_in, beta = (1 + eps) k;  end: beta = (1 - eps)/k, eps = 0.01   (Sec. 2.5)
//! e = -V_out / V_in                                                (Sec. 4.4)
//! ```
//! integrated with diffsol (by default its explicit Tsit45 where the collision is not stiff and
//! its BDF method, with the analytic Jacobian, where it is: [`Method::Auto`]) in the
//! nondimensional variables and pseudo-time described in [`model`]. Sticking is decided by the
//! energy bound and oscillation criteria described in [`sticking`].
//!
//! ## Map
//! - [`collider`]: [`Collider`], the public entry point: [`Collider::collide`] from first
//!   contact, [`Collider::collide_from`] from a [`Rebound`].
//! - [`outcome`]: what a collision gives: [`Outcome`], [`Collision`], [`TrajectoryPoint`].
//! - [`options`]: [`SolverOptions`], [`Method`] (and how [`Method::Auto`] chooses), [`Backend`].
//! - [`sticking`]: how a contact is proved never to end.
//! - [`rebound`]: the state where delta first returns to zero, to continue a collision from.
//! - `integrate` (private): diffsol's integrators, the step loop, the end of contact and the rebound
//!   placed inside a step.
//! - [`model`] and [`scales`]: the ODE in JKR units and the conversion to SI.

pub mod collider;
pub mod error;
mod integrate;
pub mod model;
pub mod options;
pub mod outcome;
pub mod rebound;
pub mod scales;
pub mod sticking;

pub use collider::{
    collision_k, collision_poisson, Collider, EPS, K_MAX, K_RANGE, MAX_CRACK_SPEED_NUMBER,
};
pub use error::DynamicsError;
pub use options::{
    auto_explicit_step_budget, Backend, Method, SolverOptions, ATOL_PER_RTOL,
    AUTO_EXPLICIT_LAMBDA_MAX, AUTO_EXPLICIT_RTOL_FACTOR, AUTO_EXPLICIT_STEPS_AT_RTOL_1E8, H0,
};
pub use outcome::{Collision, Outcome, StickingCriterion, TrajectoryPoint};
pub use rebound::Rebound;
pub use scales::Scales;
