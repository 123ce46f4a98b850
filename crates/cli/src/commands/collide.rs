//! `stickiness collide`: one head-on collision.

use super::KArgs;
use crate::args::MaterialArgs;
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use dynamics::{Collider, SolverOptions};
use serde_json::Value;
use std::io::Write;
use std::path::PathBuf;

/// One head-on collision of two identical spheres (Arakawa & Krijt 2021, Sections 2.6 and 4).
#[derive(Debug, Args)]
pub struct CollideArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Viscoelastic relaxation time T_vis (s, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub t_vis: f64,
    /// Impact speed V_in (m/s, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub v_in: f64,
    #[command(flatten)]
    pub k: KArgs,
    /// Write the trajectory (t, a, delta, delta_dot, energy; SI) to this CSV file.
    #[arg(long)]
    pub trajectory: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: &CollideArgs) -> Result<Report, CliError> {
    let contact = args.material.contact()?;
    let law = args.k.crack_law()?;
    let opts = SolverOptions {
        record_trajectory: args.trajectory.is_some(),
        ..Default::default()
    };
    let collider = Collider::new(contact, &law, args.t_vis)?.with_options(opts)?;
    let c = collider.collide(args.v_in)?;
    if let Some(path) = &args.trajectory {
        write_trajectory(path, args, &c).map_err(|e| {
            CliError::Compute(format!("cannot write --trajectory {}: {e}", path.display()))
        })?;
    }
    let mut r = Report::new(format!(
        "Collision of two {} spheres, R1 = {:?} m, T_vis = {:?} s, V_in = {:?} m/s, k = {:?}",
        args.material.material, args.material.radius, args.t_vis, args.v_in, args.k.k
    ));
    r.warn_about(&contact);
    r.value("outcome", Value::from(c.outcome.as_str()), "");
    r.number("e", c.e, "")?;
    r.number("v_out", c.v_out, "m/s")?;
    match c.contact_time {
        Some(t) => r.number("contact_time", t, "s")?,
        None => r.value("contact_time", Value::Null, "(the contact never ends)"),
    }
    if let Some(crit) = c.sticking_criterion {
        let name = match crit {
            dynamics::StickingCriterion::EnergyBound => "energy_bound",
            dynamics::StickingCriterion::Oscillations => "oscillations",
        };
        r.value("sticking_criterion", Value::from(name), "");
    }
    r.number("v_stick_jkr", contact.v_stick_jkr(), "m/s")?;
    Ok(r)
}

fn write_trajectory(
    path: &PathBuf,
    args: &CollideArgs,
    c: &dynamics::Collision,
) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        f,
        "# trajectory of one head-on collision (stickiness collide)"
    )?;
    writeln!(
        f,
        "# material = {}, radius = {:?} m, t_vis = {:?} s, v_in = {:?} m/s, k = {:?}",
        args.material.material, args.material.radius, args.t_vis, args.v_in, args.k.k
    )?;
    writeln!(f, "# outcome = {}", c.outcome.as_str())?;
    writeln!(
        f,
        "# units: t [s], a [m], delta [m], delta_dot [m/s], energy [J]"
    )?;
    writeln!(f, "t,a,delta,delta_dot,energy")?;
    for p in &c.trajectory {
        writeln!(
            f,
            "{:e},{:e},{:e},{:e},{:e}",
            p.t, p.a, p.delta, p.delta_dot, p.energy
        )?;
    }
    f.flush()
}
