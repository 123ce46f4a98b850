//! `stickiness material`: the four constants of a material, after overrides.

use crate::args::Overrides;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;

/// The constants of a preset or a material file, after overrides (SI).
#[derive(Debug, Args)]
pub struct MaterialArgs {
    /// A preset (co2, h2o; any case) or a path to a JSON file with gamma_sv, young, poisson,
    /// density (SI).
    #[arg(value_name = "NAME|PATH")]
    pub name: String,
    #[command(flatten)]
    pub overrides: Overrides,
}

/// Runs the command.
pub fn run(args: &MaterialArgs) -> Result<Report, CliError> {
    let named = args.overrides.resolve(&args.name, "")?;
    let m = &named.material;
    let mut r = Report::new(format!("Material {}", named.short));
    r.text("material", &named.given);
    r.number("gamma_sv", m.gamma_sv, "J/m^2")?;
    r.number("young", m.young, "Pa")?;
    r.number("poisson", m.poisson, "")?;
    r.number("density", m.density, "kg/m^3")?;
    Ok(r)
}
