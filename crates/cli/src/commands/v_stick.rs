//! `stickiness v-stick`: the threshold velocity for sticking and the onset of double collisions.

use super::{no_bouncing_below, point_report, v_stick_rows};
use crate::args::{PointArgs, SearchArgs};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

/// V_stick (double collision -> bouncing) and V_double_onset (sticking -> double collision)
/// (Arakawa & Krijt 2021, Sections 4.4 and 5).
#[derive(Debug, Args)]
pub struct VStickArgs {
    #[command(flatten)]
    pub point: PointArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &VStickArgs) -> Result<Report, CliError> {
    let (mut setup, t_vis, law) = args.point.resolve(None)?;
    setup.with_input("k", law.k());
    let opts = args.search.options(&mut setup);
    let found = thresholds::sticking_thresholds(&setup.contact, &law, t_vis, &opts);
    let th = setup.or_warned(found)?;
    setup.with_input("v_max", th.v_max);
    let what = format!("Sticking thresholds of {}", setup.describe());
    let mut r = point_report(what, &setup, t_vis, law.k());
    r.warn(opts.v_max_warning(th.v_stick_jkr, "--v-max "));
    v_stick_rows(&mut r, "v_stick", th.v_stick, th.v_max)?;
    r.optional(
        "v_double_onset",
        th.v_double_onset,
        "m/s",
        format!("every collision sticks up to {} m/s", number(th.v_max)),
    )?;
    r.number("v_stick_jkr", th.v_stick_jkr, "m/s")?;
    no_bouncing_below(&mut r, th.v_stick, th.v_max);
    r.text("method", th.method.name());
    r.input(setup.input);
    Ok(r)
}
