//! Typed errors of the threshold searches, layered over the collision errors.

use contact::Geometry;
use dynamics::DynamicsError;
use numerics::format::number;
use numerics::OutOfRange;

/// Everything that can go wrong in a threshold search.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ThresholdsError {
    /// A collision failed, or its inputs were invalid.
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// A parameter of the search is outside its allowed range (an input out of range caught
    /// deeper arrives as [`ThresholdsError::Dynamics`]: [`ThresholdsError::out_of_range`] finds
    /// it wherever it was caught).
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// A sweep's axis that cannot be read ([`crate::sweep::parse_axis`]).
    #[error(transparent)]
    Axis(#[from] crate::sweep::AxisError),
    /// A sweep's grid refused before any work ([`crate::sweep::Grid::validate`]).
    #[error(transparent)]
    Grid(#[from] crate::sweep::GridError),
    /// No sticking collision was found down to the lower end of the search.
    #[error(
        "no sticking collision at or above {} m/s (T_vis = {} s): the grains never stick",
        number(*v_min),
        number(*t_vis)
    )]
    NoSticking {
        /// Lowest impact speed tried (m/s).
        v_min: f64,
        /// Relaxation time (s).
        t_vis: f64,
    },
    /// The search did not close its brackets within [`crate::search::MAX_COLLISIONS`]
    /// collisions (a safeguard: searches take 20-100).
    #[error(
        "the threshold search at T_vis = {} s did not converge within {collisions} collisions",
        number(*t_vis)
    )]
    NotConverged {
        /// Relaxation time (s).
        t_vis: f64,
        /// Collisions integrated.
        collisions: usize,
    },
    /// A measured V_stick at or below V_stick,JKR: no relaxation time reproduces it, since
    /// V_stick > V_stick,JKR for every T_vis > 0 (Section 5.1).
    #[error(
        "v_stick = {} m/s is at or below V_stick,JKR = {} m/s, which every T_vis > 0 exceeds: no relaxation time reproduces it (the JKR limit T_vis -> 0 is the closest)",
        number(*v_stick),
        number(*v_stick_jkr)
    )]
    BelowJkr {
        /// The measured value (m/s).
        v_stick: f64,
        /// V_stick,JKR of the contact (m/s).
        v_stick_jkr: f64,
        /// The two bodies (radii in m): V_stick,JKR scales as R^(-5/6) with the reduced radius.
        geometry: Geometry,
    },
    /// A measured V_stick above what any relaxation time up to `t_vis_max` gives.
    #[error(
        "v_stick = {} m/s is not reached for T_vis up to {} s by these grains ({}; the T_vis of a given V_stick grows roughly as R^(7/6), the drag number c_D being proportional to T_vis R^(-7/6))",
        number(*v_stick),
        number(*t_vis_max),
        geometry.as_arguments()
    )]
    Unreachable {
        /// The measured value (m/s).
        v_stick: f64,
        /// Largest relaxation time tried (s).
        t_vis_max: f64,
        /// The two bodies (radii in m).
        geometry: Geometry,
    },
}

impl ThresholdsError {
    /// The input out of range behind this error, wherever it was caught; a measured V_stick at or
    /// below V_stick,JKR reads as `v_stick` out of range, with V_stick,JKR in the allowed range.
    /// `None` for failures of the computation (and for an unreachable V_stick).
    pub fn out_of_range(&self) -> Option<OutOfRange> {
        match self {
            ThresholdsError::OutOfRange(o) => Some(o.clone()),
            ThresholdsError::Grid(crate::sweep::GridError::OutOfRange(o)) => Some(o.clone()),
            ThresholdsError::Dynamics(d) => d.out_of_range().cloned(),
            ThresholdsError::BelowJkr {
                v_stick,
                v_stick_jkr,
                geometry,
            } => Some(OutOfRange::new(
                "v_stick",
                *v_stick,
                format!(
                    "> V_stick,JKR = {} of these grains ({}; V_stick,JKR scales as R^(-5/6)), which V_stick exceeds for every T_vis > 0",
                    number(*v_stick_jkr),
                    geometry.as_arguments()
                ),
                "m/s",
            )),
            _ => None,
        }
    }
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
