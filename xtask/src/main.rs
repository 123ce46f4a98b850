//! `cargo xtask figures [--check]`: regenerate (or check) the paper's figures.
//! `cargo xtask test`: every test, Rust and Python (and the documentation build).
//! `cargo xtask docs`: the documentation site into target/site/.

use clap::{Parser, Subcommand};
use numerics::format::number;
use std::io::{IsTerminal, Write};
use std::process::ExitCode;
use std::sync::Mutex;
use std::time::Instant;
use xtask::figures::{self, Figures, Resolution};
use xtask::{compare_with_committed, workspace_root, CHECK_REL_TOL, CSV_DIGITS};

/// Project automation for the stickiness workspace.
#[derive(Debug, Parser)]
#[command(name = "cargo xtask")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Compute Figures 1-7, the sphere-on-wall figure and the master figure; write
    /// data/fig*.csv and docs/figures/fig*.svg.
    Figures {
        /// Recompute and compare with the committed data/fig*.csv (relative tolerance 1e-4)
        /// instead of writing.
        #[arg(long)]
        check: bool,
    },
    /// Build the master tables of V_stick / V_stick,JKR over the two dimensionless numbers and k
    /// with the exact search (hours on 2 cores) and write crates/thresholds/data/master_*.csv.
    MasterTable {
        /// Recompute a sample of the committed tables' nodes and end points instead, and fail if
        /// the model no longer gives them.
        #[arg(long)]
        check: bool,
        /// Build only this part: the end curves, the tables (on the committed end curves), the
        /// checks between tables of neighbouring k, the committed tables vouched closer to
        /// their ends (`revouch`, no new nodes; then `kcheck`), their lower-bound limits
        /// closer still (`bounds`, no new nodes: where the default search strays from the
        /// nodes, for the verdict "above the search limit"; then `kcheck`), or their rows that
        /// are not monotone checked for no bouncing beyond their ends (`beyond`, no new nodes).
        #[arg(long, value_enum, default_value = "all")]
        part: xtask::master_table::Part,
        /// With `--part tables`, `revouch`, `bounds` or `beyond`: only the tables of these indices (k = 0.005 2^(i/3)).
        #[arg(long, value_delimiter = ',')]
        only: Vec<usize>,
        /// With `--part tables`: the lowest row, instead of y = -6 (log10 c_D c_a). Below -4.5
        /// lies the second kind of bouncing, whose rows cost one to three times the rest of a
        /// table; the tables answer with the search there until it is built.
        #[arg(long, allow_hyphen_values = true)]
        y_min: Option<f64>,
        /// With `--part tables`: grow the committed tables instead of building them anew: their
        /// rows kept, rows added below down to `--y-min`, and the cells whose stencil changed
        /// (the new ones and the old first one) checked; every other cell is kept as it is (the
        /// restitution tables were built on it).
        #[arg(long)]
        extend: bool,
        /// With `--extend`: check the cells never checked once with the rows there, keeping the
        /// limits their checks pass, instead of adding rows where they fail (minutes instead of
        /// hours where the second kind of bouncing makes the rows disagree).
        #[arg(long, requires = "extend", conflicts_with = "min_y_step")]
        no_split: bool,
        /// With `--extend`: split failing cells only down to this spacing of rows in y (the
        /// build's 1/64 by default), so that a cell where the rows disagree gets a row or two,
        /// not dozens.
        #[arg(long, requires = "extend")]
        min_y_step: Option<f64>,
    },
    /// Build the restitution tables (V_out and e of single collisions over the two
    /// dimensionless numbers, k and the impact speed) with the ODE, on the committed master
    /// tables, and write crates/thresholds/data/restitution_k*.csv.
    RestitutionTable {
        /// Recompute a sample of the committed values instead, and fail if the model no longer
        /// gives them.
        #[arg(long)]
        check: bool,
        /// Only the tables of these indices (k = 0.005 2^(i/3)), without the k cells.
        #[arg(long, value_delimiter = ',')]
        only: Vec<usize>,
        /// Only the k cells (the checks between tables of neighbouring k), on the committed
        /// tables: what a table built with `--only` leaves to do.
        #[arg(long, conflicts_with_all = ["only", "check"])]
        k_cells: bool,
        /// With `--only`: refine those committed tables in y where their cells fail between
        /// rows (a row halfway, the cells around it checked again); run `--k-cells` after.
        #[arg(long, conflicts_with_all = ["check", "k_cells"], requires = "only")]
        refine: bool,
        /// Check every cell of the committed tables (or those of `--only`) again, the bouncing
        /// cells apart (a double-collision miss next to the onset no longer refuses bouncing).
        #[arg(long, conflicts_with_all = ["check", "k_cells", "refine"])]
        recheck: bool,
        /// Check every vouched cell of the committed tables (or those of `--only`) again at a
        /// quarter, half and three quarters of its interval, at the centre's speeds and denser
        /// ones (what a build now checks); a cell that misses there is vouched no longer.
        #[arg(long, conflicts_with_all = ["check", "k_cells", "refine", "recheck"])]
        quarters: bool,
        /// Rebuild the rows of the committed tables (or those of `--only`) holding a node that
        /// was built without thresholds where the master tables now vouch for them (most of
        /// them below y = -4.5); run `--k-cells` after.
        #[arg(long, conflicts_with_all = ["check", "k_cells", "refine", "recheck", "quarters"])]
        refill: bool,
    },
    /// Build the Python package's wheel (maturin, PyO3's stable ABI: one wheel for every
    /// CPython 3.9 or newer on this platform, checked for manylinux compliance) into
    /// target/wheels/ and print its path.
    Wheel {
        /// The cargo profile: release (for distribution) or dev (opt-level 3, shares the build).
        #[arg(long, default_value = "release")]
        profile: String,
    },
    /// Run every test: `cargo test --workspace`, then the Python package in a virtual
    /// environment under target/venv (built from crates/python) with pytest, then the
    /// documentation build with warnings as errors.
    Test {
        /// Only the Rust tests.
        #[arg(long, conflicts_with = "python_only")]
        rust_only: bool,
        /// Only the Python package and its tests.
        #[arg(long)]
        python_only: bool,
    },
    /// Build the documentation site (Sphinx: user guide, Python and CLI references, the
    /// notebook; the Rust API by rustdoc against the test build's libraries, as `cargo doc`
    /// makes it) into target/site/, warnings as errors.
    Docs,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Figures { check } => run_figures(check),
        Command::Wheel { profile } => xtask::wheel::build(&workspace_root(), &profile).map(|w| {
            println!("{}", w.display());
        }),
        Command::RestitutionTable { check: true, .. } => {
            xtask::restitution_table::run_check(&workspace_root(), &mut |s| eprintln!("{s}"))
        }
        Command::RestitutionTable {
            refine: true, only, ..
        } => xtask::restitution_table::run_refine(&workspace_root(), &only),
        Command::RestitutionTable {
            refill: true, only, ..
        } => xtask::restitution_table::run_refill(&workspace_root(), &only),
        Command::RestitutionTable {
            recheck: true,
            only,
            ..
        } => xtask::restitution_table::run_recheck(&workspace_root(), &only),
        Command::RestitutionTable {
            quarters: true,
            only,
            ..
        } => xtask::restitution_table::run_quarters(&workspace_root(), &only),
        Command::RestitutionTable { k_cells: true, .. } => {
            xtask::restitution_table::run_k_cells(&workspace_root())
        }
        Command::RestitutionTable { only, .. } => {
            xtask::restitution_table::run_build(&workspace_root(), &only)
        }
        Command::MasterTable { check: true, .. } => {
            xtask::master_table::run_check(&workspace_root(), &mut |s| eprintln!("{s}"))
        }
        Command::MasterTable {
            part,
            only,
            y_min,
            extend,
            no_split,
            min_y_step,
            ..
        } => xtask::master_table::run_build(
            &workspace_root(),
            part,
            &only,
            y_min,
            xtask::master_table::Extend {
                extend,
                no_split,
                min_y_step,
            },
        ),
        Command::Docs => {
            xtask::docs::build(&workspace_root(), xtask::docs::Package::Install, None).map(|_| ())
        }
        Command::Test {
            rust_only,
            python_only,
        } => {
            let start = Instant::now();
            let parts = xtask::test::Parts {
                rust: !python_only,
                python: !rust_only,
            };
            // one closing line, after the interleaved logs of the parts run side by side
            xtask::test::run_tests(&workspace_root(), parts).map(|()| {
                eprintln!(
                    "cargo xtask test: all green ({}) in {:.0} s",
                    parts.described(),
                    start.elapsed().as_secs_f64()
                )
            })
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run_figures(check: bool) -> Result<(), figures::Error> {
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
    let figs = Figures::compute(Resolution::Full, &progress)?;
    let tables = figs.tables();
    eprintln!();
    let root = workspace_root();
    let data = root.join("data");
    if check {
        let diffs = compare_with_committed(&tables, &data)?;
        if !diffs.is_empty() {
            return Err(format!(
                "the recomputed figure data differ from data/ beyond the relative tolerance {}:\n  {}\nrun `cargo xtask figures` and review the change",
                number(CHECK_REL_TOL),
                diffs.join("\n  ")
            )
            .into());
        }
        eprintln!(
            "figures --check: all figure data agree with data/ (relative tolerance {}) in {:.1} s",
            number(CHECK_REL_TOL),
            start.elapsed().as_secs_f64()
        );
        return Ok(());
    }
    std::fs::create_dir_all(&data)?;
    for table in &tables {
        std::fs::write(data.join(&table.file), table.to_csv(CSV_DIGITS))?;
    }
    figs.draw_all(&root.join("docs").join("figures"))?;
    eprintln!(
        "wrote data/fig*.csv and docs/figures/fig*.svg in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
