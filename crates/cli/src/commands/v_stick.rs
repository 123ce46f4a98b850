//! `stickiness v-stick`: the threshold velocity for sticking and the onset of double collisions.

use super::{check_t_vis, KArgs, SearchArgs};
use crate::args::MaterialArgs;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use serde_json::Value;

/// V_stick and V_double_onset (Arakawa & Krijt 2021, Sections 4.4 and 5).
#[derive(Debug, Args)]
pub struct VStickArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Viscoelastic relaxation time T_vis (s, >= 0; 0 is the JKR limit).
    #[arg(long, allow_hyphen_values = true)]
    pub t_vis: f64,
    #[command(flatten)]
    pub k: KArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &VStickArgs) -> Result<Report, CliError> {
    check_t_vis(args.t_vis)?;
    let contact = args.material.contact()?;
    let law = args.k.crack_law()?;
    let th = thresholds::sticking_thresholds(&contact, &law, args.t_vis, &args.search.options())?;
    let mut r = Report::new(format!(
        "Sticking thresholds of two {} spheres, R1 = {:?} m, T_vis = {:?} s, k = {:?}",
        args.material.material, args.material.radius, args.t_vis, args.k.k
    ));
    r.warn_about(&contact);
    optional(&mut r, "v_stick", th.v_stick)?;
    optional(&mut r, "v_double_onset", th.v_double_onset)?;
    r.number("v_stick_jkr", th.v_stick_jkr, "m/s")?;
    match th.v_stick {
        Some(_) => r.value("no_bouncing_below", Value::Null, ""),
        None => r.number("no_bouncing_below", th.v_max, "m/s")?,
    }
    Ok(r)
}

/// A threshold that may be beyond the search: `null` in JSON and a sentence in text.
pub fn optional(r: &mut Report, key: &str, v: Option<f64>) -> Result<(), CliError> {
    match v {
        Some(v) => r.number(key, v, "m/s"),
        None => {
            r.value(
                key,
                Value::Null,
                if key == "v_stick" {
                    "(no bouncing below no_bouncing_below)"
                } else {
                    "(every collision sticks below no_bouncing_below)"
                },
            );
            Ok(())
        }
    }
}
