//! `stickiness collide`: one head-on collision.

use crate::args::{PointArgs, Setup};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use contact::Warning;
use dynamics::{SolverOptions, StickingCriterion};
use numerics::format::number;
use std::io::Write;
use std::path::PathBuf;

/// Arguments of `collide` (its help text is on `Command::Collide`).
#[derive(Debug, Args)]
pub struct CollideArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Impact speed V_in (m/s, > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub v_in: f64,
    /// Write the trajectory (t, a, delta, delta_dot, energy, beta; SI) to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub trajectory: Option<PathBuf>,
    /// Keep integrating a sticking collision up to this time (s) before deciding that it sticks,
    /// to record the whole spiral towards the JKR equilibrium (Figure 2) in --trajectory.
    #[arg(long, allow_hyphen_values = true)]
    pub t_end: Option<f64>,
    /// ode (default): integrate the collision; table: the outcome, e and V_out from the
    /// restitution tables (within 1e-4 of the ODE in e, microseconds) where they vouch for them,
    /// the ODE elsewhere (with BDF where the tables cover k: e within 1.3e-6 of --method ode)
    /// and with --trajectory or --t-end ("method" in the output says which; a table answer has
    /// no contact time).
    #[arg(long, value_enum, ignore_case = true, default_value = "ode")]
    pub method: CollideMethod,
}

/// The values of `collide --method`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CollideMethod {
    /// Integrate the collision.
    Ode,
    /// The restitution tables, the ODE where they do not vouch.
    Table,
}

/// Runs the command.
pub fn run(args: &CollideArgs) -> Result<Report, CliError> {
    let (mut setup, t_vis, law) = args.point.resolve(None)?;
    setup.with_input("v_in", args.v_in);
    setup.with_input("k", law.k());
    let opts = SolverOptions {
        record_trajectory: args.trajectory.is_some(),
        decide_after: args.t_end.unwrap_or(0.0),
        ..Default::default()
    };
    if let Some(t) = args.t_end {
        setup.with_input("t_end", t);
    }
    opts.validate()?;
    let method = match args.method {
        CollideMethod::Ode => thresholds::ThresholdMethod::Search,
        CollideMethod::Table => thresholds::ThresholdMethod::Table,
    };
    let cannot_write = |path: &std::path::Path, e: std::io::Error| {
        CliError::Usage(format!(
            "--trajectory {}: cannot write the file: {e}",
            path.display()
        ))
    };
    // a path that cannot be written is bad input, found before the collision; the file is
    // written (and an existing one replaced) only once the collision is done, so that bad
    // input (T_vis or V_in out of range) leaves it as it was
    if let Some(path) = &args.trajectory {
        writable(path).map_err(|e| cannot_write(path, e))?;
    }
    let found =
        thresholds::restitution::collision(&setup.contact, &law, t_vis, args.v_in, &opts, method);
    let (c, answered) = setup.or_warned(found)?;
    if let Some(path) = &args.trajectory {
        let file = std::fs::File::create(path).map_err(|e| cannot_write(path, e))?;
        write_trajectory(file, &setup, &c).map_err(|e| {
            CliError::Usage(format!(
                "--trajectory {}: cannot write the file: {e}",
                path.display()
            ))
        })?;
    }
    let mut r = Report::new(format!(
        "Collision of {}, T_vis = {} s, V_in = {} m/s, k = {}",
        setup.describe(),
        number(t_vis),
        number(args.v_in),
        number(law.k())
    ));
    r.warn(setup.warnings());
    r.warn(Warning::for_speed("v_in", args.v_in));
    r.text("outcome", c.outcome.as_str());
    r.number("e", c.e, "")?;
    // e as an experiment observes it: 0 for sticking and double collisions (Section 4.4)
    r.number("e_observed", c.observed_e(), "")?;
    r.number("v_out", c.v_out, "m/s")?;
    if answered == thresholds::ThresholdMethod::Table {
        r.optional(
            "contact_time",
            None,
            "s",
            "not from the tables (use --method ode)",
        )?;
    } else {
        r.optional(
            "contact_time",
            c.contact_time,
            "s",
            "none (the contact never ends)",
        )?;
    }
    if let Some(crit) = c.sticking_criterion {
        let name = match crit {
            StickingCriterion::EnergyBound => "energy_bound",
            StickingCriterion::Oscillations => "oscillations",
        };
        r.text("sticking_criterion", name);
    }
    r.number("v_stick_jkr", setup.contact.v_stick_jkr(), "m/s")?;
    r.text(
        "method",
        match answered {
            thresholds::ThresholdMethod::Table => "table",
            thresholds::ThresholdMethod::Search => "ode",
        },
    );
    setup.with_input(
        "method",
        match args.method {
            CollideMethod::Ode => "ode",
            CollideMethod::Table => "table",
        },
    );
    r.input(setup.input);
    Ok(r)
}

/// Whether `path` can be written, without changing it: opened for appending (created if it does
/// not exist, and then removed again).
fn writable(path: &std::path::Path) -> std::io::Result<()> {
    let existed = path.exists();
    std::fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(path)?;
    if !existed {
        std::fs::remove_file(path)?;
    }
    Ok(())
}

fn write_trajectory(
    file: std::fs::File,
    setup: &Setup,
    c: &dynamics::Collision,
) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(file);
    writeln!(
        f,
        "# trajectory of one head-on collision (stickiness collide): {}",
        setup.describe()
    )?;
    let inputs: Vec<String> = setup
        .input
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect();
    writeln!(f, "# {}", inputs.join(", "))?;
    writeln!(f, "# outcome = {}", c.outcome.as_str())?;
    writeln!(
        f,
        "# units: t [s], a [m], delta [m], delta_dot [m/s], energy [J], beta [dimensionless]"
    )?;
    writeln!(f, "t,a,delta,delta_dot,energy,beta")?;
    for p in &c.trajectory {
        writeln!(
            f,
            "{},{},{},{},{},{}",
            number(p.t),
            number(p.a),
            number(p.delta),
            number(p.delta_dot),
            number(p.energy),
            number(p.beta)
        )?;
    }
    f.flush()
}
