//! `stickiness`: do two colliding ice or dust grains stick or bounce?
//!
//! A thin layer over the `greenwood`, `contact`, `dynamics` and `thresholds` crates: it parses
//! arguments, calls them, and prints SI results as text or, with `--json`, as one JSON object.
//! It holds no physics.

mod args;
mod commands;
mod error;
mod hyphen;
mod not_a_number;
mod output;
mod progress;
mod usage_line;

use clap::{CommandFactory, Parser, Subcommand};
use std::process::ExitCode;

/// Sticking, bouncing and fragmentation of colliding viscoelastic grains: two spheres (equal or
/// not) or a sphere on a wall (Krijt et al. 2013; Arakawa & Krijt 2021). All quantities are SI.
#[derive(Debug, Parser)]
#[command(name = "stickiness", version, about, long_about = None)]
struct Cli {
    /// Print one JSON object on stdout instead of text.
    #[arg(long, global = true)]
    json: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Greenwood's normalized crack speed v(k, beta).
    CrackLaw(commands::crack_law::CrackLawArgs),
    /// The four constants of a material (preset or JSON file), after overrides.
    Material(commands::material::MaterialArgs),
    /// JKR equilibrium, pull-off force, sticking energy and V_stick,JKR.
    Jkr(commands::jkr::JkrArgs),
    /// One head-on collision: outcome, coefficient of restitution, contact time.
    ///
    /// The outcome is sticking (the contact never ends, e = 0), a double collision or bouncing.
    /// The sign of v_out, the approach speed d(delta)/dt when the contact ends, tells the two
    /// others apart: v_out < 0, the grains separate (bouncing, e = -v_out/v_in > 0); v_out > 0,
    /// the contact ended while the grains approach again, so a second contact follows (double
    /// collision, e < 0). Sections 2.5 and 4 of Arakawa & Krijt (2021).
    #[command(mut_arg("t_vis", |a| a.help(args::COLLIDE_T_VIS_HELP)))]
    Collide(commands::collide::CollideArgs),
    /// Threshold velocity for sticking V_stick and the onset of double collisions.
    VStick(commands::v_stick::VStickArgs),
    /// The relaxation time T_vis that reproduces a measured V_stick.
    ///
    /// V_stick exceeds V_stick,JKR for every T_vis > 0, so a measured value at or below
    /// V_stick,JKR is refused; one within the model's T_vis -> 0 limit of V_stick (1.55e-4 above
    /// V_stick,JKR, whose 14.18 is rounded) gives T_vis = 0, the JKR limit, with a warning; a
    /// range whose lower end is below that limit starts at t_vis_min = 0.
    #[command(mut_arg("v_max", |a| a.help(args::FIT_V_MAX_HELP)))]
    FitTVis(commands::fit_t_vis::FitTVisArgs),
    /// Fragmentation velocity of aggregates V_frag = 10 V_stick.
    ///
    /// Without --t-vis or --t-vis-law, T_vis = 0: the JKR limit V_frag,JKR. V_stick is that of
    /// two monomers (Section 6: identical spheres of radius --radius); with --radius2 or --wall
    /// it is 10 V_stick of that pair instead, an extrapolation of the factor 10 that Wada et
    /// al. (2013) found for aggregates of identical monomers.
    #[command(
        mut_arg("radius", |a| a.help(args::V_FRAG_RADIUS_HELP)),
        mut_arg("t_vis", |a| a.help(args::V_FRAG_T_VIS_HELP))
    )]
    VFrag(commands::v_frag::VFragArgs),
    /// V_stick, V_double_onset, V_stick,JKR and V_frag over a grid, into a file that survives
    /// being killed.
    ///
    /// Every axis takes a comma list or START:STOP:N (N log-spaced values, both ends included);
    /// the grid is their product in the order material, gamma_sv, radius, radius2, t_vis, k
    /// (outermost first). Rows are computed on all cores (--jobs) and written in grid order as
    /// soon as they and all before them are done; --resume keeps the complete rows of an
    /// interrupted file and computes the rest, giving the same bytes as an uninterrupted run.
    Sweep(commands::sweep::SweepArgs),
}

fn main() -> ExitCode {
    let argv: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let cli = match Cli::try_parse_from(&argv) {
        Ok(cli) => cli,
        Err(e) => {
            // a flag taken as the value of the option before it explains a failure better
            let e = match hyphen::flag_as_value(&mut Cli::command(), &argv) {
                Some(flag) => flag,
                None => {
                    // a value that is not a number, in one line as all other bad input
                    if let Some(line) = not_a_number::message(&Cli::command(), &argv, &e) {
                        eprintln!("error: {line}");
                        return ExitCode::from(2);
                    }
                    e
                }
            };
            // every other usage error in one line too; help and version as clap prints them
            match usage_line::line(&e) {
                Some(line) => {
                    eprintln!("{line}");
                    return ExitCode::from(2);
                }
                None => e.exit(),
            }
        }
    };
    let result = match &cli.command {
        Command::CrackLaw(a) => commands::crack_law::run(a),
        Command::Material(a) => commands::material::run(a),
        Command::Jkr(a) => commands::jkr::run(a),
        Command::Collide(a) => commands::collide::run(a),
        Command::VStick(a) => commands::v_stick::run(a),
        Command::FitTVis(a) => commands::fit_t_vis::run(a),
        Command::VFrag(a) => commands::v_frag::run(a),
        Command::Sweep(a) => commands::sweep::run(a),
    };
    match result {
        Ok(report) => {
            report.print(cli.json);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::CommandFactory;

    /// clap's own consistency checks of every subcommand (unique names, conflicts that exist).
    #[test]
    fn commands_are_well_formed() {
        super::Cli::command().debug_assert();
    }
}
