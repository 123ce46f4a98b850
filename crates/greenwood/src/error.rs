//! Typed errors of the crack law.

/// Everything that can go wrong when evaluating Greenwood's crack law.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GreenwoodError {
    /// The modulus ratio k (relaxed / instantaneous Young's modulus, dimensionless) is outside (0, 1).
    #[error("k = {k:?} is outside the allowed range 0 < k < 1 (ratio of relaxed to instantaneous modulus)")]
    KOutOfRange {
        /// The rejected value.
        k: f64,
    },
    /// The normalized apparent surface energy beta is outside (k, 1/k), where v(k, beta) is undefined.
    #[error("beta = {beta:?} is outside the allowed range {min:?} < beta < {max:?} (k = {k:?})")]
    BetaOutOfRange {
        /// The rejected value.
        beta: f64,
        /// The modulus ratio it was checked against.
        k: f64,
        /// Lower bound k.
        min: f64,
        /// Upper bound 1/k.
        max: f64,
    },
    /// The non-dimensional transit time alpha must be finite and > 0.
    #[error("alpha = {alpha:?} is outside the allowed range 0 < alpha < infinity")]
    AlphaOutOfRange {
        /// The rejected value.
        alpha: f64,
    },
}
