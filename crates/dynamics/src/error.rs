//! Typed errors of the collision integrator, layered over the lower crates' errors.

use contact::ContactError;
use greenwood::GreenwoodError;

/// Everything that can go wrong when integrating a collision.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// Invalid contact or material parameters.
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// Invalid crack-law parameters.
    #[error(transparent)]
    Greenwood(#[from] GreenwoodError),
    /// A collision parameter is outside its allowed range.
    #[error("{field} = {value:?} is outside the allowed range {allowed} ({unit})")]
    OutOfRange {
        /// Parameter name (`t_vis`, `v_in`, `eps`, `rtol`, ...).
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range.
        allowed: &'static str,
        /// SI unit.
        unit: &'static str,
    },
    /// The ODE solver failed.
    #[error("ODE solver failed at R1 = {r1:?} m, T_vis = {t_vis:?} s, V_in = {v_in:?} m/s, after t = {t:?} s with a = {a:?} m, delta = {delta:?} m, delta_dot = {delta_dot:?} m/s, beta = {beta:?}: {message}")]
    Solver {
        /// Particle radius (m).
        r1: f64,
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
    #[error("no outcome after {steps} solver steps at R1 = {r1:?} m, T_vis = {t_vis:?} s, V_in = {v_in:?} m/s (raise max_steps)")]
    Undecided {
        /// Particle radius (m).
        r1: f64,
        /// Relaxation time (s).
        t_vis: f64,
        /// Impact speed (m/s).
        v_in: f64,
        /// Steps taken.
        steps: usize,
    },
}
