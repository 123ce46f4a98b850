//! `stickiness crack-law`: Greenwood's v(k, beta).

use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

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

/// Runs the command: `v` from the tabulated law the model integrates with (as the Python
/// package's `crack_speed`), `alpha` and `v_quadrature` from the direct inversion by quadrature
/// (they agree to 1e-8).
pub fn run(args: &CrackLawArgs) -> Result<Report, CliError> {
    let law = greenwood::CrackLaw::new(args.k)?;
    let v = law.v(args.beta)?;
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
    // beta = 1: alpha = infinity, v = 0
    r.optional("alpha", point.map(|p| p.alpha), "", "infinite (beta = 1)")?;
    r.number("v", v, "")?;
    r.number("v_quadrature", point.map_or(0.0, |p| p.v), "")?;
    r.input(input);
    Ok(r)
}
