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

use crate::GreenwoodError;

/// Half-width point of the split: `xi = 1/2`, i.e. `s = 1/sqrt(2)` in both substitutions.
const S_HALF: f64 = std::f64::consts::FRAC_1_SQRT_2;
/// Truncation of the Gaussian boundary layer in the scaled variable `u` (weight `exp(-49)`).
const U_MAX: f64 = 7.0;
/// Below this alpha, `1 - J3` is integrated directly (with `expm1`) instead of subtracted.
const ALPHA_SUBTRACT: f64 = 1.0;

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
        let j3 = j3_unchecked(alpha);
        let one_minus_j3 = if alpha <= ALPHA_SUBTRACT {
            one_minus_j3_quadrature(alpha)
        } else {
            1.0 - j3
        };
        let k_log = log_term_unchecked(alpha);
        Ok(Self {
            alpha,
            j1: one_minus_j3 - k_log,
            j2: one_minus_j3 + k_log,
            j3,
            one_minus_j3,
            k_log,
        })
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
        Err(GreenwoodError::AlphaOutOfRange { alpha })
    }
}

/// Tanh-sinh over `[a, b]`, run to its last level (about 350 evaluations): every integrand here is
/// smooth after substitution, so the rule converges to rounding level.
fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    quadrature::double_exponential::integrate(f, a, b, 0.0).integral
}

/// Upper limit of the scaled variable `u` on `[1/2, 1]`: `u^2 / alpha = 1 - xi <= 1/2`.
fn u_top(alpha: f64) -> f64 {
    (0.5 * alpha).sqrt().min(U_MAX)
}

/// `L(xi)` for `xi = 1 - t`, `t = u^2 / alpha`, without cancellation.
fn log_ratio_near_one(u: f64, alpha: f64) -> f64 {
    let t = u * u / alpha;
    2.0 * (1.0 + (1.0 - t).sqrt()).ln() - (2.0 * u.ln() - alpha.ln())
}

/// `∫_0^1 exp(-alpha (1 - xi)) g(xi) dxi` split at `xi = 1/2`, with `left(s)` the integrand in
/// `xi = s^2` *including* the Jacobian, and `right(u)` the integrand in `1 - xi = u^2/alpha`
/// including the Jacobian and the weight.
fn split(alpha: f64, left: impl Fn(f64) -> f64, right: impl Fn(f64) -> f64) -> f64 {
    integrate(left, 0.0, S_HALF) + integrate(right, 0.0, u_top(alpha))
}

fn j3_unchecked(alpha: f64) -> f64 {
    // J3 = 1/2 ∫ e^{-alpha(1-xi)} xi^{-1/2} dxi
    // left:  xi = s^2: 1/2 * e * (1/s) * 2s = e
    // right: 1 - xi = u^2/alpha: 1/2 * e^{-u^2} (1 - t)^{-1/2} * 2u/alpha
    split(
        alpha,
        |s| (-alpha * (1.0 - s * s)).exp(),
        |u| {
            let t = u * u / alpha;
            (-u * u).exp() * u / ((1.0 - t).sqrt() * alpha)
        },
    )
}

fn one_minus_j3_quadrature(alpha: f64) -> f64 {
    // 1 - J3 = 1/2 ∫ (1 - e^{-alpha(1-xi)}) xi^{-1/2} dxi (the u-range covers all of [1/2, 1]
    // because this is used only for alpha <= 1, where u_top = sqrt(alpha/2) < U_MAX).
    split(
        alpha,
        |s| -(-alpha * (1.0 - s * s)).exp_m1(),
        |u| {
            let t = u * u / alpha;
            -(-u * u).exp_m1() * u / ((1.0 - t).sqrt() * alpha)
        },
    )
}

fn log_term_unchecked(alpha: f64) -> f64 {
    // K = alpha/2 ∫ e^{-alpha(1-xi)} (1 - xi) L(xi) dxi
    // left:  xi = s^2, L = 2 atanh(s): alpha/2 * e * (1 - s^2) * 2 atanh(s) * 2s
    // right: alpha/2 * e^{-u^2} * t * L * 2u/alpha = e^{-u^2} t L u
    split(
        alpha,
        |s| 2.0 * alpha * (-alpha * (1.0 - s * s)).exp() * (1.0 - s * s) * s.atanh() * s,
        |u| {
            let t = u * u / alpha;
            (-u * u).exp() * t * log_ratio_near_one(u, alpha) * u
        },
    )
}

fn sqrt_moment_unchecked(alpha: f64) -> f64 {
    // ∫ e^{-alpha(1-xi)} sqrt(xi) dxi
    split(
        alpha,
        |s| (-alpha * (1.0 - s * s)).exp() * 2.0 * s * s,
        |u| {
            let t = u * u / alpha;
            (-u * u).exp() * (1.0 - t).sqrt() * 2.0 * u / alpha
        },
    )
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
