//! `stickiness v-frag`: the fragmentation velocity of aggregates, V_frag = 10 V_stick.

use super::{check_t_vis, v_stick::optional, KArgs, SearchArgs};
use crate::args::MaterialArgs;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use serde_json::Value;
use thresholds::TVisLaw;

/// V_frag = 10 V_stick for aggregates of monomers of radius R1 (Arakawa & Krijt 2021, Section 6).
#[derive(Debug, Args)]
pub struct VFragArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Viscoelastic relaxation time T_vis (s, >= 0; 0, the default, is the JKR limit).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "t_vis_law")]
    pub t_vis: Option<f64>,
    /// Size law for T_vis(R1) (Section 5.3): co2 = 1e-11 s (R1/1 um)^1.11, h2o = 1e-10 s (R1/1.5 um)^1.11.
    #[arg(long, value_parser = ["co2", "h2o"])]
    pub t_vis_law: Option<String>,
    #[command(flatten)]
    pub k: KArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &VFragArgs) -> Result<Report, CliError> {
    let contact = args.material.contact()?;
    let t_vis = match (&args.t_vis, &args.t_vis_law) {
        (Some(t), _) => *t,
        (None, Some(name)) => TVisLaw::from_name(name)
            .ok_or_else(|| {
                CliError::Usage(format!(
                    "--t-vis-law = {name} is not one of the allowed laws co2, h2o"
                ))
            })?
            .t_vis(contact.r1()),
        (None, None) => 0.0,
    };
    check_t_vis(t_vis)?;
    let law = args.k.crack_law()?;
    let th = thresholds::sticking_thresholds(&contact, &law, t_vis, &args.search.options())?;
    let mut r = Report::new(format!(
        "Fragmentation velocity of aggregates of {} monomers, R1 = {:?} m, T_vis = {t_vis:?} s, k = {:?}",
        args.material.material, args.material.radius, args.k.k
    ));
    r.warn_about(&contact);
    match th.v_stick {
        Some(v) => r.number("v_frag", thresholds::v_frag(v), "m/s")?,
        None => r.value(
            "v_frag",
            Value::Null,
            "(no bouncing below no_bouncing_below)",
        ),
    }
    optional(&mut r, "v_stick", th.v_stick)?;
    r.number("t_vis", t_vis, "s")?;
    r.number("v_frag_jkr", thresholds::v_frag(th.v_stick_jkr), "m/s")?;
    r.number("v_stick_jkr", th.v_stick_jkr, "m/s")?;
    match th.v_stick {
        Some(_) => r.value("no_bouncing_below", Value::Null, ""),
        None => r.number("no_bouncing_below", th.v_max, "m/s")?,
    }
    Ok(r)
}
