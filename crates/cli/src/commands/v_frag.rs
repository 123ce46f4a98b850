//! `stickiness v-frag`: the fragmentation velocity of aggregates, V_frag = 10 V_stick.

use super::{no_bouncing_below, point_report, v_stick_rows};
use crate::args::{PointArgs, SearchArgs};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

/// V_frag = 10 V_stick for aggregates of monomers of radius R1 (Arakawa & Krijt 2021, Section 6).
#[derive(Debug, Args)]
pub struct VFragArgs {
    #[command(flatten)]
    pub point: PointArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &VFragArgs) -> Result<Report, CliError> {
    let (mut setup, t_vis, law) = args.point.resolve(Some(0.0))?;
    setup.with_input("k", law.k());
    let opts = args.search.options(&mut setup);
    let found = thresholds::fragmentation(&setup.contact, &law, t_vis, &opts);
    let f = setup.or_warned(found)?;
    let v_max = f.no_bouncing_below.unwrap_or(opts.v_max_for(f.v_stick_jkr));
    setup.with_input("v_max", v_max);
    // the monomers' pair, whose V_stick sets V_frag (Section 6)
    let what = format!(
        "Fragmentation velocity of aggregates, V_frag = 10 V_stick of {}",
        setup.describe()
    );
    let mut r = point_report(what, &setup, t_vis, law.k());
    r.warn(opts.v_max_warning(f.v_stick_jkr, "--v-max "));
    // without bouncing up to v_max, V_frag = 10 V_stick lies above 10 v_max
    r.optional(
        "v_frag",
        f.v_frag,
        "m/s",
        format!(
            "above {} m/s (no bouncing up to {} m/s)",
            number(thresholds::v_frag(v_max)),
            number(v_max)
        ),
    )?;
    v_stick_rows(&mut r, "v_stick", f.v_stick, v_max)?;
    r.number("t_vis", t_vis, "s")?;
    r.number("v_frag_jkr", f.v_frag_jkr, "m/s")?;
    r.number("v_stick_jkr", f.v_stick_jkr, "m/s")?;
    no_bouncing_below(&mut r, f.v_stick, v_max);
    r.text("method", f.method.name());
    r.input(setup.input);
    Ok(r)
}
