//! `stickiness fit-t-vis`: the relaxation time that reproduces a measured V_stick.

use super::{KArgs, SearchArgs};
use crate::args::MaterialArgs;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;

/// T_vis for a measured V_stick, with the range for its uncertainty (Sections 5.1-5.2).
#[derive(Debug, Args)]
pub struct FitTVisArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Measured threshold velocity for sticking V_stick (m/s, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub v_stick: f64,
    /// Uncertainty of the measured V_stick (m/s, 0 <= dV < V_stick).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub v_stick_err: f64,
    #[command(flatten)]
    pub k: KArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &FitTVisArgs) -> Result<Report, CliError> {
    let contact = args.material.contact()?;
    let law = args.k.crack_law()?;
    let fit = thresholds::fit_t_vis(
        &contact,
        &law,
        args.v_stick,
        args.v_stick_err,
        &args.search.options(),
    )?;
    let mut r = Report::new(format!(
        "Relaxation time for V_stick = {:?} ± {:?} m/s, two {} spheres, R1 = {:?} m, k = {:?}",
        args.v_stick, args.v_stick_err, args.material.material, args.material.radius, args.k.k
    ));
    r.warn_about(&contact);
    r.number("t_vis", fit.t_vis, "s")?;
    r.number("t_vis_min", fit.t_vis_min, "s")?;
    r.number("t_vis_max", fit.t_vis_max, "s")?;
    r.number("v_stick_jkr", fit.v_stick_jkr, "m/s")?;
    Ok(r)
}
