//! `cargo xtask master-table [--part ends|tables|kcheck|revouch|bounds|beyond|midpoints] [--check]`: build the master tables of
//! V_stick / V_stick,JKR with the exact search and write them to `crates/thresholds/data/`
//! (`master_ends.csv`, the end curves and the checks between tables of neighbouring k;
//! `master_k<k>.csv`, one table a k), or recompute a sample of their nodes and end points and
//! fail if the model no longer gives them.

use crate::figures::Error;
use numerics::format::number;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::time::Instant;
use thresholds::master::build::beyond::{check_beyond_table, check_levels};
use thresholds::master::build::cells::extend_table;
use thresholds::master::build::check::{
    check_ends, check_nodes, END_TOL, ILL_CONDITIONED_BELOW_Y, ILL_CONDITIONED_TOL, NODE_REL_TOL,
};
use thresholds::master::build::ends::{build_ends, repair_ends};
use thresholds::master::build::kcheck::k_checks;
use thresholds::master::build::midpoints::recheck_table;
use thresholds::master::build::revouch::{revouch_table, Pass};
use thresholds::master::build::BuildConfig;
use thresholds::master::format::{parse_ends, parse_table, EndsData, TableData};
use thresholds::master::{ends_to_text, table_to_text};
use thresholds::CrackLaw;

/// `--check` recomputes every this-many-th node of each table (95-135 of its 48 000-67 000
/// values): a change of the model moves them all, so a sample finds it. 250 (190-270 a table)
/// took 60 s of the 147 s of `--check` once the tables had grown; this and
/// [`CHECK_LEVELS_EVERY`] keep the checks, which `cargo xtask test` runs beside its other steps
/// at a lower priority, within what those leave idle (`docs/performance.md`, "Build time").
pub const CHECK_EVERY: usize = 500;

/// `--check` checks beyond their ends every this-many-th row that is not monotone in each table,
/// from the middle of the first stride (21 of the 340 rows of the eleven tables, 12 searches
/// each, up to F = F_TOP: the costly ones, 63 s on one thread; every 4th, 85 rows, took 85 s on
/// two; [`check_levels`]).
pub const CHECK_LEVELS_EVERY: usize = 16;

/// `--check` recomputes every this-many-th point of the end curves (about 40 of 33 000).
pub const CHECK_ENDS_EVERY: usize = 800;

/// Which part to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Part {
    /// Everything, in order.
    All,
    /// The end curves (`master_ends.csv`, without the k checks).
    Ends,
    /// The end curves' missing points only, keeping the committed ones.
    EndsRepair,
    /// The tables of every k on the committed end curves.
    Tables,
    /// The checks between tables of neighbouring k, into `master_ends.csv`.
    Kcheck,
    /// The committed tables vouched closer to their ends (no new nodes; then `kcheck`).
    Revouch,
    /// The committed tables' lower-bound limits closer to their ends, checked against the exact
    /// nodes where the default search strays from them (no new nodes; after `revouch`, then
    /// `kcheck`, whose checks between tables go on into them).
    Bounds,
    /// The committed tables' rows that are not monotone checked for no bouncing beyond their
    /// ends up to where their ratios stop increasing (no new nodes).
    Beyond,
    /// The committed tables' rows with their finest intervals checked again at the midpoints,
    /// each piece's vouched range ended at the first that fails (no new rows).
    Midpoints,
}

/// How `--part tables` treats the committed tables.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Extend {
    /// Grow the committed tables instead of building them anew.
    pub extend: bool,
    /// Check the cells never checked once, without adding rows.
    pub no_split: bool,
    /// Split failing cells only down to this spacing of rows in y.
    pub min_y_step: Option<f64>,
}

/// The directory of the committed tables.
pub fn data_dir(root: &Path) -> PathBuf {
    root.join("crates/thresholds/data")
}

/// The file of the table of `k` under `root`.
pub fn table_path(root: &Path, k: f64) -> PathBuf {
    data_dir(root).join(format!("master_k{k:.5}.csv"))
}

/// The file of the end curves under `root`.
pub fn ends_path(root: &Path) -> PathBuf {
    data_dir(root).join("master_ends.csv")
}

/// The commit the tables are built at (with `-dirty` for uncommitted changes), for the headers.
fn commit(root: &Path) -> String {
    let git = |args: &[&str]| {
        std::process::Command::new("git")
            .args(args)
            .current_dir(root)
            .output()
            .ok()
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let head = git(&["rev-parse", "--short", "HEAD"]).unwrap_or_else(|| "unknown".into());
    let dirty =
        git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty());
    if dirty {
        format!("{head}-dirty")
    } else {
        head
    }
}

fn read(path: &Path) -> Result<String, Error> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()).into())
}

/// The committed end curves.
pub fn committed_ends(root: &Path) -> Result<EndsData, Error> {
    let path = ends_path(root);
    parse_ends(&read(&path)?)
        .map_err(|e| format!("{}, line {}: {}", path.display(), e.line, e.problem).into())
}

/// The committed tables, in increasing k: those of the standard grid that exist (the tables are
/// built one k at a time; the k axis answers between the tables present).
pub fn committed_tables(root: &Path) -> Result<Vec<TableData>, Error> {
    let cfg = BuildConfig::standard();
    cfg.table_ks()
        .iter()
        .map(|&k| table_path(root, k))
        .filter(|path| path.exists())
        .map(|path| {
            parse_table(&read(&path)?)
                .map_err(|e| format!("{}, line {}: {}", path.display(), e.line, e.problem).into())
        })
        .collect()
}

/// Builds `part` (and `only` these table indices, if given; tables from the row `y_min` up, if
/// given; with `extend`, each table grown from the committed one: its rows kept, rows added
/// below down to `y_min`, its cells never checked checked) and writes it.
pub fn run_build(
    root: &Path,
    part: Part,
    only: &[usize],
    y_min: Option<f64>,
    how: Extend,
) -> Result<(), Error> {
    let Extend {
        extend,
        no_split,
        min_y_step,
    } = how;
    let start = Instant::now();
    let mut cfg = BuildConfig::standard();
    if no_split {
        // no cell is split: each keeps the limits its checks pass with the rows it has
        cfg.min_y_step = f64::INFINITY;
    }
    if let Some(step) = min_y_step {
        if !(step >= cfg.min_y_step && step <= cfg.y_step) {
            return Err(format!(
                "--min-y-step = {step}: must be from {} to {}",
                cfg.min_y_step, cfg.y_step
            )
            .into());
        }
        cfg.min_y_step = step;
    }
    if let Some(y) = y_min {
        if !(y >= cfg.y_range.0 && y < cfg.y_range.1 && (y * 2.0).fract() == 0.0) {
            return Err(format!(
                "--y-min = {y}: must be a multiple of 0.5 from {} to below {}",
                cfg.y_range.0, cfg.y_range.1
            )
            .into());
        }
        cfg.y_range.0 = y;
    }
    let stamp = |header: &mut Vec<String>| stamp(header, root);
    let progress = |s: &str| eprintln!("{:.0} s: {s}", start.elapsed().as_secs_f64());
    if matches!(part, Part::All | Part::Ends) {
        let mut ends = build_ends(&cfg, &progress);
        stamp(&mut ends.header);
        std::fs::write(ends_path(root), ends_to_text(&ends))?;
        progress(&format!("wrote {}", ends_path(root).display()));
    }
    if part == Part::EndsRepair {
        let previous = committed_ends(root)?;
        let mut ends = repair_ends(&cfg, Some(&previous), &progress);
        stamp(&mut ends.header);
        std::fs::write(ends_path(root), ends_to_text(&ends))?;
        progress(&format!("wrote {}", ends_path(root).display()));
    }
    if matches!(part, Part::All | Part::Tables) {
        let ends = committed_ends(root)?;
        let mut committed = if extend {
            committed_tables(root)?
        } else {
            Vec::new()
        };
        for i in 0..cfg.table_k.2 {
            if !only.is_empty() && !only.contains(&i) {
                continue;
            }
            let k = thresholds::master::build::grid_k(cfg.table_k.0, cfg.table_k.1, i);
            let from = match committed.iter().position(|t| (t.k / k - 1.0).abs() < 1e-9) {
                Some(at) => Some(committed.swap_remove(at)),
                None if extend => {
                    return Err(format!("--extend: no committed table of k = {k}").into())
                }
                None => None,
            };
            let kept = from.as_ref().map(|t| {
                let was = |key: &str| t.header.iter().find(|h| h.starts_with(key)).cloned();
                format!(
                    "extended: the rows from y = {} kept from the table of {}",
                    t.rows.first().map_or(f64::NAN, |r| r.y),
                    was("commit: ").map_or("an unknown commit".into(), |c| c.replace(": ", " "))
                )
            });
            // the passes run on the committed table since it was built say so still
            let passes: Vec<String> = from.as_ref().map_or(Vec::new(), |t| {
                t.header
                    .iter()
                    .filter(|h| {
                        ["revouched:", "bounds:", "beyond:", "midpoints:"]
                            .iter()
                            .any(|p| h.starts_with(p))
                    })
                    .cloned()
                    .collect()
            });
            let mut t = extend_table(&cfg, i, from, &ends, &progress)?;
            t.header.extend(kept);
            t.header.extend(passes);
            if no_split {
                t.header.push(
                    "no split: the cells never checked were checked once with the rows there, without adding rows (--extend --no-split)".into(),
                );
            }
            if let Some(step) = min_y_step {
                t.header.push(format!(
                    "split: the cells never checked split down to rows {} apart in y (--extend --min-y-step)",
                    number(step)
                ));
            }
            stamp(&mut t.header);
            write_table(root, &t, &progress)?;
        }
    }
    if matches!(
        part,
        Part::Revouch | Part::Bounds | Part::Beyond | Part::Midpoints
    ) {
        let ends = committed_ends(root)?;
        for t in committed_tables(root)? {
            let i = cfg
                .table_ks()
                .iter()
                .position(|k| (t.k / k - 1.0).abs() < 1e-9);
            if !only.is_empty() && !i.is_some_and(|i| only.contains(&i)) {
                continue;
            }
            let mut t = match part {
                Part::Revouch => revouch_table(Pass::Revouch, &cfg, &t, &ends, &progress)?,
                Part::Bounds => revouch_table(Pass::Bounds, &cfg, &t, &ends, &progress)?,
                Part::Midpoints => recheck_table(&cfg, &CrackLaw::new(t.k)?, &t, &progress),
                _ => check_beyond_table(&cfg, &t, &progress)?,
            };
            stamp(&mut t.header);
            write_table(root, &t, &progress)?;
        }
    }
    if matches!(part, Part::All | Part::Kcheck) {
        let ends = committed_ends(root)?;
        let tables = committed_tables(root)?;
        let mut checked = k_checks(&cfg, &tables, &ends, &progress)?;
        stamp(&mut checked.header);
        std::fs::write(ends_path(root), ends_to_text(&checked))?;
        progress(&format!(
            "wrote {} with the k checks",
            ends_path(root).display()
        ));
    }
    Ok(())
}

/// Puts the command that writes a file and the commit it runs at first in its `header`, in
/// place of those of an earlier run (what else the header says of earlier runs stays).
fn stamp(header: &mut Vec<String>, root: &Path) {
    header.retain(|h| !h.starts_with("commit:") && !h.starts_with("command:"));
    let command: Vec<String> = std::iter::once("cargo xtask".to_string())
        .chain(std::env::args().skip(1))
        .collect();
    header.splice(
        0..0,
        [
            format!("command: {}", command.join(" ")),
            format!("commit: {}", commit(root)),
        ],
    );
}

/// Writes the table `t` to its file under `root`, and says so.
fn write_table(root: &Path, t: &TableData, progress: &dyn Fn(&str)) -> Result<(), Error> {
    let path = table_path(root, t.k);
    std::fs::write(&path, table_to_text(t))?;
    progress(&format!("wrote {}", path.display()));
    Ok(())
}

/// Recomputes a sample of the committed tables' nodes and end points; an error naming the first
/// that moved. Each line of the report goes to `say`.
pub fn run_check(root: &Path, say: &mut dyn FnMut(String)) -> Result<(), Error> {
    let ends = committed_ends(root)?;
    let checked = check_ends(&ends, CHECK_ENDS_EVERY)?;
    if let Some(r) = checked.iter().find(|r| r.moved()) {
        return Err(format!(
            "the master tables' end curves are stale: {} is {}, the model now gives {}; run `cargo xtask master-table`",
            r.what, r.stored, r.now
        )
        .into());
    }
    say(format!(
        "master-table --check: {} end points recomputed, all within {} ({} below y = {}, where the roots are ill-conditioned)",
        checked.len(),
        number(END_TOL),
        number(ILL_CONDITIONED_TOL),
        number(ILL_CONDITIONED_BELOW_Y)
    ));
    let tables = committed_tables(root)?;
    let intervals = ends.kcheck.len() / ends.kcheck_y.2.max(1);
    if intervals != tables.len().saturating_sub(1) {
        say(format!(
            "master-table --check: the k checks cover {intervals} intervals, the {} tables make {}: \
             only the tables' own k are answered until `cargo xtask master-table --part kcheck`",
            tables.len(),
            tables.len().saturating_sub(1)
        ));
    }
    // every table at once (a table's few rows beyond the ends would leave a core idle), then
    // each reported in order
    let results: Vec<_> = tables
        .par_iter()
        .map(|t| {
            let nodes = check_nodes(t, CHECK_EVERY)?;
            let levels = check_levels(&BuildConfig::standard(), t, CHECK_LEVELS_EVERY)?;
            Ok::<_, thresholds::ThresholdsError>((nodes, levels))
        })
        .collect();
    for (t, result) in tables.iter().zip(results) {
        let (checked, (moved, rows)) = result?;
        if let Some(r) = checked.iter().find(|r| r.moved()) {
            return Err(format!(
                "the master table of k = {} is stale: {} is {}, the model now gives {}; run `cargo xtask master-table`",
                t.k, r.what, r.stored, r.now
            )
            .into());
        }
        if let Some(y) = moved {
            return Err(format!(
                "the master table of k = {} is stale: beyond the ends of its row y = {y} something now bounces below the row's level; run `cargo xtask master-table --part beyond`",
                t.k
            )
            .into());
        }
        say(format!(
            "master-table --check: k = {}: {} values recomputed, all within {}; the levels of {rows} rows checked beyond their ends",
            t.k,
            checked.len(),
            number(NODE_REL_TOL)
        ));
    }
    Ok(())
}
