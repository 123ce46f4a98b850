//! One module per subcommand; each turns parsed arguments into a [`crate::output::Report`].

pub mod collide;
pub mod crack_law;
pub mod fit_t_vis;
pub mod jkr;
pub mod v_frag;
pub mod v_stick;

use crate::error::CliError;
use clap::Args;

/// The crack-law parameter shared by every collision command.
#[derive(Debug, Clone, Args)]
pub struct KArgs {
    /// Ratio of relaxed to instantaneous modulus k (dimensionless, 0 < k < 1).
    #[arg(long, default_value_t = 0.01, allow_hyphen_values = true)]
    pub k: f64,
}

impl KArgs {
    /// Greenwood's crack law tabulated for this k.
    pub fn crack_law(&self) -> Result<greenwood::CrackLaw, CliError> {
        Ok(greenwood::CrackLaw::new(self.k)?)
    }
}

/// The threshold-search settings shared by v-stick, fit-t-vis and v-frag.
#[derive(Debug, Clone, Args)]
pub struct SearchArgs {
    /// Relative tolerance of the bisections (dimensionless).
    #[arg(long, default_value_t = 1e-6, allow_hyphen_values = true)]
    pub rel_tol: f64,
    /// Highest impact speed searched for bouncing (m/s; default 1000 V_stick,JKR; at most 1e4).
    #[arg(long, allow_hyphen_values = true)]
    pub v_max: Option<f64>,
}

impl SearchArgs {
    /// The library's search options.
    pub fn options(&self) -> thresholds::SearchOptions {
        thresholds::SearchOptions {
            rel_tol: self.rel_tol,
            v_max: self.v_max,
            ..Default::default()
        }
    }
}

/// Relaxation time flag check: finite and >= 0.
pub fn check_t_vis(t_vis: f64) -> Result<(), CliError> {
    if t_vis.is_finite() && t_vis >= 0.0 {
        Ok(())
    } else {
        Err(CliError::Usage(format!(
            "--t-vis = {t_vis} is outside the allowed range >= 0 and finite (s)"
        )))
    }
}
