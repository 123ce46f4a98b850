//! Typed errors of the threshold searches, layered over the collision errors.

use dynamics::DynamicsError;

/// Everything that can go wrong in a threshold search.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ThresholdsError {
    /// A collision failed.
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// A parameter is outside its allowed range.
    #[error("{field} = {value:?} is outside the allowed range {allowed} ({unit})")]
    OutOfRange {
        /// Parameter name.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range.
        allowed: &'static str,
        /// SI unit.
        unit: &'static str,
    },
    /// A bug: an invariant of the search did not hold.
    #[error("internal error: {0}")]
    Internal(String),
    /// No sticking collision was found down to the lower end of the search.
    #[error(
        "no sticking collision at or above {v_min:?} m/s (T_vis = {t_vis:?} s): the grains never stick"
    )]
    NoSticking {
        /// Lowest impact speed tried (m/s).
        v_min: f64,
        /// Relaxation time (s).
        t_vis: f64,
    },
}

impl From<contact::ContactError> for ThresholdsError {
    fn from(e: contact::ContactError) -> Self {
        ThresholdsError::Dynamics(e.into())
    }
}

impl From<greenwood::GreenwoodError> for ThresholdsError {
    fn from(e: greenwood::GreenwoodError) -> Self {
        ThresholdsError::Dynamics(e.into())
    }
}
