//! `stickiness v-frag`: the fragmentation velocity of aggregates, V_frag = 10 V_stick.

use super::{no_bouncing_below, v_stick_rows};
use crate::args::{GeometryArgs, KArgs, MaterialArgs, SearchArgs, Setup, TVisArgs};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

/// V_frag = 10 V_stick for aggregates of monomers of radius R1 (Arakawa & Krijt 2021, Section 6).
#[derive(Debug, Args)]
pub struct VFragArgs {
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
pub fn run(args: &VFragArgs) -> Result<Report, CliError> {
    let mut setup = Setup::new(&args.material, &args.geometry)?;
    let t_vis = args.t_vis.resolve(&mut setup, Some(0.0))?;
    setup.with_input("k", args.k.k);
    let opts = args.search.options(&mut setup);
    let law = args.k.crack_law()?;
    let f = thresholds::fragmentation(&setup.contact, &law, t_vis, &opts)?;
    let v_max = f.no_bouncing_below.unwrap_or(opts.v_max_for(f.v_stick_jkr));
    setup.with_input("v_max", v_max);
    let mut r = Report::new(format!(
        "Fragmentation velocity of aggregates of {} monomers, T_vis = {} s, k = {}",
        setup.describe(),
        number(t_vis),
        number(args.k.k)
    ));
    r.warn(setup.contact.warnings());
    v_stick_rows(&mut r, "v_frag", f.v_frag, v_max)?;
    v_stick_rows(&mut r, "v_stick", f.v_stick, v_max)?;
    r.number("t_vis", t_vis, "s")?;
    r.number("v_frag_jkr", f.v_frag_jkr, "m/s")?;
    r.number("v_stick_jkr", f.v_stick_jkr, "m/s")?;
    no_bouncing_below(&mut r, f.v_stick, v_max);
    r.input(setup.input);
    Ok(r)
}
