//! `stickiness fit-t-vis`: the relaxation time that reproduces a measured V_stick.

use crate::args::{GeometryArgs, KArgs, MaterialArgs, SearchArgs, Setup};
use crate::error::CliError;
use crate::output::Report;
use clap::Args;
use numerics::format::number;

/// T_vis for a measured V_stick, with the range for its uncertainty (Sections 5.1-5.2).
#[derive(Debug, Args)]
pub struct FitTVisArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    #[command(flatten)]
    pub geometry: GeometryArgs,
    /// Measured threshold velocity for sticking V_stick (m/s, above V_stick,JKR; V_stick + dV at
    /// most 5000.0: each trial T_vis is searched up to twice the target, within the 10000.0 m/s
    /// search limit).
    #[arg(long, allow_hyphen_values = true)]
    pub v_stick: f64,
    /// Uncertainty of the measured V_stick (m/s, 0 <= dV < V_stick).
    #[arg(long, default_value = "0.0", allow_hyphen_values = true)]
    pub v_stick_err: f64,
    #[command(flatten)]
    pub k: KArgs,
    #[command(flatten)]
    pub search: SearchArgs,
}

/// Runs the command.
pub fn run(args: &FitTVisArgs) -> Result<Report, CliError> {
    let mut setup = Setup::new(&args.material, &args.geometry)?;
    setup.with_input("v_stick", args.v_stick);
    setup.with_input("v_stick_err", args.v_stick_err);
    setup.with_input("k", args.k.k);
    let opts = args.search.options(&mut setup);
    // each trial T_vis is searched up to twice its target, or to --v-max if higher: null when
    // not given
    setup.with_input("v_max", args.search.v_max);
    let law = args.k.crack_law()?;
    let found = thresholds::fit_t_vis(&setup.contact, &law, args.v_stick, args.v_stick_err, &opts);
    let fit = setup.or_warned(found)?;
    // without an uncertainty the title gives the value alone
    let err = if args.v_stick_err > 0.0 {
        format!(" ± {}", number(args.v_stick_err))
    } else {
        String::new()
    };
    let mut r = Report::new(format!(
        "Relaxation time for V_stick = {}{err} m/s, {}, k = {}",
        number(args.v_stick),
        setup.describe(),
        number(args.k.k)
    ));
    r.warn(setup.warnings());
    r.warn(fit.warnings().iter().map(|w| w.message_for("--v-max ")));
    r.number("t_vis", fit.t_vis, "s")?;
    r.number("t_vis_min", fit.t_vis_min, "s")?;
    r.number("t_vis_max", fit.t_vis_max, "s")?;
    r.number("v_stick_jkr", fit.v_stick_jkr, "m/s")?;
    r.text("method", fit.method.name());
    r.input(setup.input);
    Ok(r)
}
