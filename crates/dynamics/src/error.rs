//! Typed errors of the collision integrator, layered over the lower crates' errors.

use contact::{ContactError, Geometry};
use greenwood::GreenwoodError;
use numerics::format::number;
use numerics::OutOfRange;

/// Everything that can go wrong when integrating a collision.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// Invalid contact or material parameters.
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// Invalid crack-law parameters.
    #[error(transparent)]
    Greenwood(#[from] GreenwoodError),
    /// A collision parameter is outside its allowed range (`t_vis`, `v_in`, `eps`, `rtol`, ...).
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// The ODE solver failed.
    #[error("ODE solver failed for {geometry}, T_vis = {} s, V_in = {} m/s, after t = {} s with a = {} m, delta = {} m, delta_dot = {} m/s, beta = {}: {message}", number(*t_vis), number(*v_in), number(*t), number(*a), number(*delta), number(*delta_dot), number(*beta))]
    Solver {
        /// The colliding bodies (radii in m).
        geometry: Geometry,
        /// Relaxation time (s).
        t_vis: f64,
        /// Impact speed (m/s).
        v_in: f64,
        /// Time of the last accepted step (s).
        t: f64,
        /// Contact radius at the last accepted step (m).
        a: f64,
        /// Mutual approach at the last accepted step (m).
        delta: f64,
        /// Approach speed at the last accepted step (m/s).
        delta_dot: f64,
        /// beta at the last accepted step.
        beta: f64,
        /// The solver's message.
        message: String,
    },
    /// Neither the end of contact nor a sticking criterion was reached within the step budget.
    #[error("no outcome after {steps} solver steps for {geometry}, T_vis = {} s, V_in = {} m/s (raise max_steps)", number(*t_vis), number(*v_in))]
    Undecided {
        /// The colliding bodies (radii in m).
        geometry: Geometry,
        /// Relaxation time (s).
        t_vis: f64,
        /// Impact speed (m/s).
        v_in: f64,
        /// Steps taken.
        steps: usize,
    },
}

impl DynamicsError {
    /// The input out of range behind this error, wherever it was caught (contact, crack law or
    /// collision); `None` for failures of the computation.
    pub fn out_of_range(&self) -> Option<&OutOfRange> {
        match self {
            DynamicsError::OutOfRange(o)
            | DynamicsError::Contact(ContactError::OutOfRange(o))
            | DynamicsError::Greenwood(GreenwoodError::OutOfRange(o)) => Some(o),
            _ => None,
        }
    }
}
