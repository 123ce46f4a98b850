//! `stickiness v-stick`: the threshold velocity for sticking and the onset of double collisions.

use super::{no_bouncing_below, v_stick_rows};
use crate::args::{GeometryArgs, KArgs, MaterialArgs, SearchArgs, Setup, TVisArgs};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

/// V_stick (double collision -> bouncing) and V_double_onset (sticking -> double collision)
/// (Arakawa & Krijt 2021, Sections 4.4 and 5).
#[derive(Debug, Args)]
pub struct VStickArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    #[command(flatten)]
    pub geometry: GeometryArgs,
    #[command(flatten)]
    pub t_vis: TVisArgs,
    #[command(flatten)]
    pub k: KArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &VStickArgs) -> Result<Report, CliError> {
    let mut setup = Setup::new(&args.material, &args.geometry)?;
    let t_vis = args.t_vis.resolve(&mut setup, None)?;
    setup.with_input("k", args.k.k);
    let opts = args.search.options(&mut setup);
    let law = args.k.crack_law()?;
    let th = thresholds::sticking_thresholds(&setup.contact, &law, t_vis, &opts)?;
    setup.with_input("v_max", th.v_max);
    let mut r = Report::new(format!(
        "Sticking thresholds of {}, T_vis = {} s, k = {}",
        setup.describe(),
        number(t_vis),
        number(args.k.k)
    ));
    r.warn(setup.contact.warnings());
    v_stick_rows(&mut r, "v_stick", th.v_stick, th.v_max)?;
    r.optional(
        "v_double_onset",
        th.v_double_onset,
        "m/s",
        format!("every collision sticks up to {} m/s", number(th.v_max)),
    )?;
    r.number("v_stick_jkr", th.v_stick_jkr, "m/s")?;
    no_bouncing_below(&mut r, th.v_stick, th.v_max);
    r.input(setup.input);
    Ok(r)
}
