//! `cargo xtask figures [--check]`: regenerate (or check) the paper's figures.

use std::io::{IsTerminal, Write};
use std::process::ExitCode;
use std::sync::Mutex;
use std::time::Instant;
use xtask::figures::{self, Resolution};
use xtask::{compare_with_committed, plot, workspace_root, CHECK_REL_TOL, CSV_DIGITS};

const USAGE: &str = "usage: cargo xtask figures [--check]
  figures          compute Figures 1-7, write data/fig*.csv and docs/figures/fig*.svg
  figures --check  recompute and compare with the committed data/fig*.csv (relative tolerance 1e-4)";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = match args
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>()
        .as_slice()
    {
        ["figures"] => false,
        ["figures", "--check"] => true,
        _ => {
            eprintln!("{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(check) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(check: bool) -> Result<(), figures::Error> {
    let start = Instant::now();
    // On a terminal one line is rewritten; in a log, a line at 0, 50 and 100 % of each figure.
    let terminal = std::io::stderr().is_terminal();
    let last = Mutex::new(String::new());
    let progress = |name: &str, done: usize, total: usize| {
        let Ok(mut l) = last.lock() else { return };
        let line = format!("{name}: {done}/{total}");
        let elapsed = start.elapsed().as_secs_f64();
        if terminal {
            if *l != line {
                eprint!("\r{line:<24} ({elapsed:.1} s)");
                let _ = std::io::stderr().flush();
            }
        } else if done == 0 || done == total || 2 * done == total || 2 * done == total + 1 {
            eprintln!("{line:<24} ({elapsed:.1} s)");
        }
        *l = line;
    };
    let figs = figures::all(Resolution::Full, &progress)?;
    eprintln!();
    let root = workspace_root();
    let data = root.join("data");
    if check {
        let diffs = compare_with_committed(&figs, &data)?;
        if !diffs.is_empty() {
            return Err(format!(
                "the recomputed figure data differ from data/ beyond the relative tolerance {CHECK_REL_TOL}:\n  {}\nrun `cargo xtask figures` and review the change",
                diffs.join("\n  ")
            )
            .into());
        }
        eprintln!(
            "figures --check: all figure data agree with data/ (relative tolerance {CHECK_REL_TOL}) in {:.1} s",
            start.elapsed().as_secs_f64()
        );
        return Ok(());
    }
    std::fs::create_dir_all(&data)?;
    for table in figs.iter().flat_map(|(_, t)| t) {
        std::fs::write(data.join(&table.file), table.to_csv(CSV_DIGITS))?;
    }
    plot::draw_all(&figs, &root.join("docs").join("figures"))?;
    eprintln!(
        "wrote data/fig*.csv and docs/figures/fig*.svg in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
