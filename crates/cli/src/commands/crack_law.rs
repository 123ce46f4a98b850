//! `stickiness crack-law`: Greenwood's v(k, beta) by direct inversion.

use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use greenwood::format::number;

/// Normalized crack speed v(k, beta) (Arakawa & Krijt 2021, Appendix A).
#[derive(Debug, Args)]
pub struct CrackLawArgs {
    /// Ratio of relaxed to instantaneous modulus k (dimensionless, 0 < k < 1).
    #[arg(long, default_value = "0.01", allow_hyphen_values = true)]
    pub k: f64,
    /// Normalized apparent surface energy beta = G_eff/gamma (dimensionless, k < beta < 1/k).
    #[arg(long, allow_hyphen_values = true)]
    pub beta: f64,
}

/// Runs the command.
pub fn run(args: &CrackLawArgs) -> Result<Report, CliError> {
    let point = greenwood::alpha_of_beta(args.k, args.beta)?;
    let mut input = serde_json::Map::new();
    input.insert("k".into(), args.k.into());
    input.insert("beta".into(), args.beta.into());
    let mut r = Report::new(format!(
        "Greenwood crack law at k = {}, beta = {}",
        number(args.k),
        number(args.beta)
    ));
    r.number("k", args.k, "")?;
    r.number("beta", args.beta, "")?;
    match point {
        Some(p) => {
            r.number("alpha", p.alpha, "")?;
            r.number("v", p.v, "")?;
        }
        None => {
            // beta = 1: alpha = infinity, v = 0
            r.optional("alpha", None, "", "infinite (beta = 1)")?;
            r.number("v", 0.0, "")?;
        }
    }
    r.input(input);
    Ok(r)
}
