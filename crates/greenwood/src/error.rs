//! Typed errors of the crack law, layered over [`OutOfRange`] (from `numerics`, the workspace's
//! one "bad input" error).

use numerics::OutOfRange;

/// Everything that can go wrong when evaluating Greenwood's crack law: an input out of range
/// (`k` outside (0, 1), `beta` outside (k, 1/k), `alpha` not finite and > 0).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GreenwoodError {
    /// An input outside its allowed range.
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
}
