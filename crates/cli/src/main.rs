//! `stickiness`: do two colliding ice or dust grains stick or bounce?
//!
//! A thin layer over the `greenwood`, `contact`, `dynamics` and `thresholds` crates: it parses
//! arguments, calls them, and prints SI results as text or, with `--json`, as one JSON object.
//! It holds no physics.

mod args;
mod commands;
mod error;
mod output;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Sticking, bouncing and fragmentation of colliding viscoelastic grains
/// (Krijt et al. 2013; Arakawa & Krijt 2021). All quantities are SI.
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
    /// JKR equilibrium, pull-off force, sticking energy and V_stick,JKR.
    Jkr(commands::jkr::JkrArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::CrackLaw(a) => commands::crack_law::run(a),
        Command::Jkr(a) => commands::jkr::run(a),
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
