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
    for ((key, unit), value) in contact::JKR_QUANTITIES.iter().zip(c.jkr_values()) {
        r.number(key, value, unit)?;
    }
    r.input(setup.input);
    Ok(r)
}
