//! The integrals J1, J2, J3 of Greenwood (2004), Arakawa & Krijt (2021) Appendix A.
//!
//! ```text
//! J1(alpha) = alpha/2 ∫_0^1 exp[-alpha (1 - xi)] F(xi) dxi
//! J2(alpha) = alpha/2 ∫_0^1 exp[-alpha (1 - xi)] A(xi) dxi
//! J3(alpha) = 1/2     ∫_0^1 exp[-alpha (1 - xi)] xi^(-1/2) dxi
//! F(xi) = 2 sqrt(xi) - (1 - xi) L(xi),   A(xi) = 2 sqrt(xi) + (1 - xi) L(xi),
//! L(xi) = log[(1 + sqrt(xi)) / (1 - sqrt(xi))]
//! ```
//!
//! # Numerical method
//! The `quadrature` crate's tanh-sinh rule replaces non-finite integrand values by zero and its error
//! estimate is not a bound, so every integrand handed to it here is finite and smooth (or has only a
//! bounded `s^3 log s` endpoint term):
//! - `[0, 1/2]` uses `xi = s^2`, which removes the `xi^(-1/2)` singularity;
//! - `[1/2, 1]` uses `1 - xi = t = u^2 / alpha`, which removes the logarithmic singularity of `L` and
//!   rescales the boundary layer `exp(-alpha t)` of width `1/alpha` to width one. The Gaussian
//!   tail beyond `u = 7` (relative weight `exp(-49) ~ 5e-22`) is dropped.
//! - `L` is evaluated as `2 log(1 + sqrt(1 - t)) - log t` with `log t = 2 log u - log alpha`, which
//!   has no cancellation as `xi -> 1`.
//!
//! Integrating by parts gives the exact identity `J1 + J2 = 2 alpha ∫ e^{-alpha(1-xi)} sqrt(xi) dxi
//! = 2 (1 - J3)`, so `J1 = (1 - J3) - K` and `J2 = (1 - J3) + K` with the log term
//! `K = (J2 - J1)/2 = alpha/2 ∫ e^{-alpha(1-xi)} (1 - xi) L(xi) dxi`. [`JIntegrals`] uses that form
//! because it gives `1 - J1 = J3 + K` and `1 - J3` without cancellation at both ends of alpha;
//! [`j1`] and [`j2`] integrate Appendix A's F and A directly, and the tests check one against the other.
//! `J3` also has the closed form `J3 = D(sqrt(alpha)) / sqrt(alpha)` with Dawson's integral `D`.

use crate::quad::{
    j3_complement_log_term, j3_unchecked, log_term_unchecked, sqrt_moment_unchecked,
};
use crate::GreenwoodError;
use numerics::OutOfRange;

/// Values of Appendix A's integrals at one alpha, with the complements needed by the crack law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JIntegrals {
    /// Non-dimensional transit time alpha (dimensionless).
    pub alpha: f64,
    /// J1(alpha) (dimensionless), from the identity `J1 = (1 - J3) - K`.
    pub j1: f64,
    /// J2(alpha) (dimensionless), from the identity `J2 = (1 - J3) + K`.
    pub j2: f64,
    /// J3(alpha) (dimensionless).
    pub j3: f64,
    /// `1 - J3(alpha)`, computed without cancellation (dimensionless).
    pub one_minus_j3: f64,
    /// The log term `K = (J2 - J1) / 2` (dimensionless).
    pub k_log: f64,
}

impl JIntegrals {
    /// Evaluates J1, J2, J3, `1 - J3` and `K` at `alpha` (dimensionless, finite, > 0).
    pub fn new(alpha: f64) -> Result<Self, GreenwoodError> {
        check_alpha(alpha)?;
        let (j3, one_minus_j3, k_log) = j3_complement_log_term(alpha);
        Ok(Self::from_parts(alpha, j3, one_minus_j3, k_log))
    }

    /// Assembles the values from `J3`, `1 - J3` and `K` at `alpha` (all dimensionless), with
    /// `J1 = (1 - J3) - K` and `J2 = (1 - J3) + K`.
    pub fn from_parts(alpha: f64, j3: f64, one_minus_j3: f64, k_log: f64) -> Self {
        Self {
            alpha,
            j1: one_minus_j3 - k_log,
            j2: one_minus_j3 + k_log,
            j3,
            one_minus_j3,
            k_log,
        }
    }

    /// `1 - J1 = J3 + K`, without cancellation for large alpha (dimensionless).
    pub fn one_minus_j1(&self) -> f64 {
        self.j3 + self.k_log
    }

    /// `1 - J2 = J3 - K` (dimensionless).
    pub fn one_minus_j2(&self) -> f64 {
        self.j3 - self.k_log
    }
}

fn check_alpha(alpha: f64) -> Result<(), GreenwoodError> {
    if alpha.is_finite() && alpha > 0.0 {
        Ok(())
    } else {
        Err(OutOfRange::new("alpha", alpha, "> 0 and finite", "dimensionless").into())
    }
}

/// J1(alpha) by direct quadrature of Appendix A's integrand `F` (dimensionless; alpha finite, > 0).
pub fn j1(alpha: f64) -> Result<f64, GreenwoodError> {
    check_alpha(alpha)?;
    Ok(alpha * sqrt_moment_unchecked(alpha) - log_term_unchecked(alpha))
}

/// J2(alpha) by direct quadrature of Appendix A's integrand `A` (dimensionless; alpha finite, > 0).
pub fn j2(alpha: f64) -> Result<f64, GreenwoodError> {
    check_alpha(alpha)?;
    Ok(alpha * sqrt_moment_unchecked(alpha) + log_term_unchecked(alpha))
}

/// J3(alpha) by quadrature (dimensionless; alpha finite, > 0).
pub fn j3(alpha: f64) -> Result<f64, GreenwoodError> {
    check_alpha(alpha)?;
    Ok(j3_unchecked(alpha))
}

/// The log term `K(alpha) = (J2 - J1)/2` by quadrature (dimensionless; alpha finite, > 0).
pub fn log_term(alpha: f64) -> Result<f64, GreenwoodError> {
    check_alpha(alpha)?;
    Ok(log_term_unchecked(alpha))
}
