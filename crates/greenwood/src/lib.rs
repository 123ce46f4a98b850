//! # greenwood
//!
//! One job: Greenwood's (2004) viscoelastic crack law, the normalized crack speed `v(k, beta)`
//! that Krijt et al. (2013) and Arakawa & Krijt (2021) use for the contact edge of colliding grains.
//! This crate knows nothing about spheres, forces or time.
//!
//! ## Equations (Arakawa & Krijt 2021, Section 2.3 and Appendix A)
//! - `beta = G_eff / gamma` (normalized apparent surface energy) and
//!   `v = sigma0^2 T_vis a_dot / (E* gamma)` (normalized crack speed) are both functions of the
//!   modulus ratio `k` (relaxed / instantaneous modulus, 0 < k < 1) and an auxiliary non-dimensional
//!   transit time `alpha`:
//! ```text
//! opening (beta > 1, v < 0):  beta = 1 / I1,      v = -(pi/4) / (alpha I1)
//! closing (beta < 1, v > 0):  beta = I3^2 / I2,   v = +(pi/4) / (alpha I2)
//! I1 = k + (1-k) J1,  I2 = k + (1-k) J2,  I3 = 1 - (1-k) J3
//! J1 = alpha/2 ∫_0^1 e^{-alpha(1-xi)} F(xi) dxi,  J2 = alpha/2 ∫_0^1 e^{-alpha(1-xi)} A(xi) dxi,
//! J3 = 1/2 ∫_0^1 e^{-alpha(1-xi)} xi^{-1/2} dxi,
//! F, A = 2 sqrt(xi) ∓ (1 - xi) ln[(1 + sqrt xi)/(1 - sqrt xi)]
//! ```
//! - v is defined for `k < beta < 1/k`, with `v(k, 1) = 0`.
//!
//! ## Quick start
//! ```
//! use greenwood::CrackLaw;
//! // build the table once per k (the paper's fiducial k = 0.01), then evaluate in ~30 ns
//! let law = CrackLaw::new(0.01)?;
//! assert_eq!(law.v(1.0)?, 0.0); // v(k, 1) = 0: the crack is at rest at beta = 1 (Figure 1)
//! assert!(law.v(0.5)? > 0.0 && law.v(2.0)? < 0.0); // closing below 1, opening above
//! # Ok::<(), greenwood::GreenwoodError>(())
//! ```
//!
//! ## Map
//! - [`integrals`]: J1, J2, J3 by tanh-sinh quadrature after substitutions that remove the endpoint
//!   singularities; the identity `J1 + J2 = 2 (1 - J3)`; `J3 = D(sqrt alpha)/sqrt alpha`.
//! - [`law`]: `(beta, v)` at given alpha on both branches ([`CrackPoint`]) and the direct inversion
//!   [`v_direct`] for a given beta.
//! - [`table`]: [`CrackLaw`], built once per k, evaluates `v` and `dv/dbeta` in well under a
//!   microsecond with a relative error below 1e-8 over alpha in [1e-6, 1e8].
//! - [`error`]: [`GreenwoodError`], over `numerics`' [`OutOfRange`] (the workspace's one bad-input
//!   error, its one number format and its one root finder live in the `numerics` crate below).
//!
//! Everything here is dimensionless.

pub mod error;
pub mod integrals;
pub mod law;
mod quad;
pub mod table;

pub use error::GreenwoodError;
pub use integrals::{j1, j2, j3, log_term, JIntegrals};
pub use law::{alpha_of_beta, v_direct, Branch, CrackPoint};
pub use numerics::OutOfRange;
pub use table::{CrackLaw, CrackSpeed};
