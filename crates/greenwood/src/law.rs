//! Greenwood's crack law on both branches, parametrised by alpha, and its direct inversion.
//!
//! Appendix A of Arakawa & Krijt (2021), with `I1 = k + (1-k) J1`, `I2 = k + (1-k) J2`,
//! `I3 = 1 - (1-k) J3`:
//! ```text
//! opening (beta > 1, v < 0):  beta = 1 / I1,       v = -(pi/4) / (alpha I1)
//! closing (beta < 1, v > 0):  beta = I3^2 / I2,    v = +(pi/4) / (alpha I2)
//! ```
//! alpha -> 0 gives beta -> 1/k (opening) or beta -> k (closing) with |v| -> infinity;
//! alpha -> infinity gives beta -> 1 and v -> 0 on both branches.
//!
//! The distances of beta to 1 and to its limit (k or 1/k) are computed from the complements
//! `1 - J1 = J3 + K`, `1 - J3` (see [`crate::integrals`]) in closed algebraic forms that have no
//! cancellation:
//! ```text
//! opening: beta - 1 = (1-k)(J3 + K) / I1,            1/k - beta = (1-k) J1 / (k I1)
//! closing: 1 - beta = (1-k)(J3 I3 + K) / I2,         beta - k   = (1-k)(k J1 + (1-k)(1-J3)^2) / I2
//! ```

use crate::{GreenwoodError, JIntegrals};
use numerics::roots::{illinois, Illinois};
use numerics::OutOfRange;
use std::f64::consts::FRAC_PI_4;

/// Which branch of the crack law: the crack closes (contact grows) or opens (contact shrinks).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    /// beta < 1, v > 0: the contact radius grows (bonding).
    Closing,
    /// beta > 1, v < 0: the contact radius shrinks (cracking).
    Opening,
}

/// One point (alpha, beta, v) of the crack law, with beta's distances to its bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrackPoint {
    /// Branch of the point.
    pub branch: Branch,
    /// Non-dimensional transit time (dimensionless).
    pub alpha: f64,
    /// Normalized apparent surface energy `beta = G_eff / gamma` (dimensionless).
    pub beta: f64,
    /// Normalized crack speed `v = sigma0^2 T_vis a_dot / (E* gamma)` (dimensionless).
    pub v: f64,
    /// `|beta - 1|` without cancellation (dimensionless).
    pub distance_to_one: f64,
    /// Distance of beta to the end of its branch: `beta - k` (closing) or `1/k - beta` (opening).
    pub distance_to_limit: f64,
}

pub(crate) fn check_k(k: f64) -> Result<(), GreenwoodError> {
    if k.is_finite() && k > 0.0 && k < 1.0 {
        Ok(())
    } else {
        Err(OutOfRange::new("k", k, "0 < k < 1", "dimensionless").into())
    }
}

impl CrackPoint {
    /// The crack-law point at modulus ratio `k` (0 < k < 1) and integrals `j` on `branch`.
    pub fn from_integrals(k: f64, j: &JIntegrals, branch: Branch) -> Result<Self, GreenwoodError> {
        check_k(k)?;
        let c = 1.0 - k;
        let alpha = j.alpha;
        Ok(match branch {
            Branch::Opening => {
                let i1 = k + c * j.j1;
                Self {
                    branch,
                    alpha,
                    beta: 1.0 / i1,
                    v: -FRAC_PI_4 / (alpha * i1),
                    distance_to_one: c * j.one_minus_j1() / i1,
                    distance_to_limit: c * j.j1 / (k * i1),
                }
            }
            Branch::Closing => {
                let i2 = k + c * j.j2;
                let i3 = k + c * j.one_minus_j3;
                Self {
                    branch,
                    alpha,
                    beta: i3 * i3 / i2,
                    v: FRAC_PI_4 / (alpha * i2),
                    distance_to_one: c * (j.j3 * i3 + j.k_log) / i2,
                    distance_to_limit: c * (k * j.j1 + c * j.one_minus_j3 * j.one_minus_j3) / i2,
                }
            }
        })
    }

    /// The crack-law point at modulus ratio `k` (0 < k < 1) and transit time `alpha` (> 0).
    pub fn new(k: f64, alpha: f64, branch: Branch) -> Result<Self, GreenwoodError> {
        check_k(k)?;
        Self::from_integrals(k, &JIntegrals::new(alpha)?, branch)
    }

    /// `zeta = ln(distance to 1) - ln(distance to limit)`: the coordinate in which the table of
    /// [`crate::CrackLaw`] is laid out. It runs from -infinity (beta -> 1) to +infinity (beta at
    /// its limit) and is close to `±ln(alpha)` at both ends.
    pub fn zeta(&self) -> f64 {
        self.distance_to_one.ln() - self.distance_to_limit.ln()
    }
}

/// Beta bounds check: `k < beta < 1/k`, beta finite.
pub(crate) fn check_beta(k: f64, beta: f64) -> Result<(), GreenwoodError> {
    check_k(k)?;
    if beta.is_finite() && beta > k && beta < 1.0 / k {
        Ok(())
    } else {
        Err(OutOfRange::new(
            "beta",
            beta,
            format!(
                "{} < beta < {} (k < beta < 1/k)",
                numerics::format::number(k),
                numerics::format::number(1.0 / k)
            ),
            "dimensionless",
        )
        .into())
    }
}

/// The table coordinate `zeta` of a given beta (see [`CrackPoint::zeta`]); beta must be within
/// `(k, 1/k)` and not 1.
pub(crate) fn zeta_of_beta(k: f64, beta: f64) -> (Branch, f64) {
    if beta < 1.0 {
        (Branch::Closing, ((1.0 - beta) / (beta - k)).ln())
    } else {
        (Branch::Opening, ((beta - 1.0) / (1.0 / k - beta)).ln())
    }
}

/// Bracket of the inversion in `ln alpha`: alpha in `[1e-60, 1e60]` contains every beta
/// representable in f64 strictly inside `(k, 1/k)`.
const LN_ALPHA_BRACKET: f64 = 60.0 * std::f64::consts::LN_10;

/// Direct inversion: the alpha at which the crack law passes through `beta` (k < beta < 1/k).
///
/// Returns `None` for `beta == 1`, which corresponds to alpha = infinity (v = 0). Solves
/// `zeta(alpha) = zeta(beta)` with [`numerics::roots::illinois`] in `ln alpha` over
/// `[-LN_ALPHA_BRACKET, LN_ALPHA_BRACKET]`.
///
/// # Example
/// ```
/// // v(k, beta) is positive below beta = 1 (the contact grows) and negative above (Figure 1)
/// let p = greenwood::alpha_of_beta(0.01, 0.5).unwrap().unwrap();
/// assert!(p.v > 0.0 && (p.beta - 0.5).abs() < 1e-12);
/// assert!(greenwood::alpha_of_beta(0.01, 1.0).unwrap().is_none());
/// ```
pub fn alpha_of_beta(k: f64, beta: f64) -> Result<Option<CrackPoint>, GreenwoodError> {
    check_beta(k, beta)?;
    if beta == 1.0 {
        return Ok(None);
    }
    let (branch, target) = zeta_of_beta(k, beta);
    // zeta decreases with alpha on both branches (from +inf at alpha -> 0 to -inf at alpha -> inf)
    let f = |u: f64| -> Result<f64, GreenwoodError> {
        Ok(CrackPoint::new(k, u.exp(), branch)?.zeta() - target)
    };
    let (lo, hi) = (-LN_ALPHA_BRACKET, LN_ALPHA_BRACKET);
    let (f_lo, f_hi) = (f(lo)?, f(hi)?);
    let u = if f_lo <= 0.0 {
        lo
    } else if f_hi >= 0.0 {
        hi
    } else {
        let opts = Illinois {
            // ln alpha to 1e-14 of its bracket's width (about 1.4e-12 absolute): alpha to about
            // 1.4e-12 relative
            x_tol: 1e-14 * LN_ALPHA_BRACKET,
            ..Illinois::default()
        };
        illinois(f, (lo, f_lo), (hi, f_hi), &opts)?.best
    };
    Ok(Some(CrackPoint::new(k, u.exp(), branch)?))
}

/// v(k, beta) by direct inversion (slow: several quadratures; use [`crate::CrackLaw`] in loops).
///
/// `k` in (0, 1), `beta` in (k, 1/k); returns the dimensionless crack speed, 0 at beta = 1.
pub fn v_direct(k: f64, beta: f64) -> Result<f64, GreenwoodError> {
    Ok(alpha_of_beta(k, beta)?.map_or(0.0, |p| p.v))
}
