//! `stickiness jkr`: the JKR equilibrium and thresholds of a contact.

use crate::args::{GeometryArgs, MaterialArgs, Setup};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;

/// JKR contact: equilibrium, pull-off force, sticking and breaking energies, V_stick,JKR
/// (Arakawa & Krijt 2021, Sections 2.2, 5.1, 6).
#[derive(Debug, Args)]
pub struct JkrArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    #[command(flatten)]
    pub geometry: GeometryArgs,
}

/// Runs the command.
pub fn run(args: &JkrArgs) -> Result<Report, CliError> {
    let setup = Setup::new(&args.material, &args.geometry)?;
    let c = &setup.contact;
    let mut r = Report::new(format!("JKR contact of {}", setup.describe()));
    r.warn(c.warnings());
    r.number("a_eq", c.a_eq(), "m")?;
    r.number("delta_eq", c.delta_eq(), "m")?;
    r.number("tabor", c.tabor(), "")?;
    r.number("f_crit", c.f_crit(), "N")?;
    r.number("delta_crit", c.delta_crit(), "m")?;
    r.number("e_stick", c.e_stick_jkr(), "J")?;
    r.number("e_break", c.e_break_jkr(), "J")?;
    r.number("v_stick_jkr", c.v_stick_jkr(), "m/s")?;
    r.input(setup.input);
    Ok(r)
}
