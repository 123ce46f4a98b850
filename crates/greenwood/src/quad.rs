//! The quadrature kernels of J1-J3 and the alpha grid of the crack-law table.
//!
//! This file has no dependency on the rest of the crate: `build.rs` includes it to tabulate
//! J3, 1 - J3 and K at the table's nodes once, at build time (they do not depend on k), and
//! [`crate::integrals`] wraps it with checks. See [`crate::integrals`] for the method.

/// Half-width point of the split: `xi = 1/2`, i.e. `s = 1/sqrt(2)` in both substitutions.
pub(crate) const S_HALF: f64 = std::f64::consts::FRAC_1_SQRT_2;
/// Truncation of the Gaussian boundary layer in the scaled variable `u` (weight `exp(-49)`).
pub(crate) const U_MAX: f64 = 7.0;
/// Below this alpha, `1 - J3` is integrated directly (with `expm1`) instead of subtracted.
pub(crate) const ALPHA_SUBTRACT: f64 = 1.0;

/// Smallest tabulated alpha of the crack-law table (dimensionless).
pub const ALPHA_MIN: f64 = 1e-9;
/// Largest tabulated alpha (dimensionless).
pub const ALPHA_MAX: f64 = 1e11;
/// Node spacing of the table in `ln alpha`.
pub const LN_ALPHA_STEP: f64 = 0.02;

/// Number of table nodes.
#[cfg_attr(not(test), allow(dead_code))]
pub fn node_count() -> usize {
    ((ALPHA_MAX.ln() - ALPHA_MIN.ln()) / LN_ALPHA_STEP).ceil() as usize + 1
}

/// alpha at table node `i` (tabulated by `build.rs` with the nodes' integrals).
#[cfg_attr(not(test), allow(dead_code))]
pub fn node_alpha(i: usize) -> f64 {
    (ALPHA_MIN.ln() + i as f64 * LN_ALPHA_STEP).exp()
}

/// `(J3, 1 - J3, K)` at `alpha` (finite, > 0; unchecked).
pub fn j3_complement_log_term(alpha: f64) -> (f64, f64, f64) {
    let j3 = j3_unchecked(alpha);
    let one_minus_j3 = if alpha <= ALPHA_SUBTRACT {
        one_minus_j3_quadrature(alpha)
    } else {
        1.0 - j3
    };
    (j3, one_minus_j3, log_term_unchecked(alpha))
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

pub(crate) fn j3_unchecked(alpha: f64) -> f64 {
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

pub(crate) fn one_minus_j3_quadrature(alpha: f64) -> f64 {
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

pub(crate) fn log_term_unchecked(alpha: f64) -> f64 {
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

pub(crate) fn sqrt_moment_unchecked(alpha: f64) -> f64 {
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
