//! `stickiness jkr`: the JKR equilibrium and thresholds of a contact.

use crate::args::MaterialArgs;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;

/// JKR contact of two identical spheres (Arakawa & Krijt 2021, Sections 2.2, 5.1, 6).
#[derive(Debug, Args)]
pub struct JkrArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
}

/// Runs the command.
pub fn run(args: &JkrArgs) -> Result<Report, CliError> {
    let c = args.material.contact()?;
    let mut r = Report::new(format!(
        "JKR contact of two {} spheres, R1 = {:?} m",
        args.material.material, args.material.radius
    ));
    r.warn_about(&c);
    r.number("a_eq", c.a_eq(), "m")?;
    r.number("delta_eq", c.delta_eq(), "m")?;
    r.number("tabor", c.tabor(), "")?;
    r.number("f_crit", c.f_crit(), "N")?;
    r.number("delta_crit", c.delta_crit(), "m")?;
    r.number("e_stick", c.e_stick_jkr(), "J")?;
    r.number("e_break", c.e_break_jkr(), "J")?;
    r.number("v_stick_jkr", c.v_stick_jkr(), "m/s")?;
    Ok(r)
}
