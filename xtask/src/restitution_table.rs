//! `cargo xtask restitution-table [--check | --only I,.. | --k-cells | --refine --only I,.. |
//! --recheck [--only I,..] | --quarters [--only I,..] | --refill [--only I,..]]`:
//! build the restitution tables (V_out and e of single collisions over the dimensionless numbers, k and the impact speed) from the ODE and
//! write them to `crates/thresholds/data/restitution_k<k>.csv`, or recompute a sample of their
//! values and fail if the model no longer gives them. They stand on the committed master
//! tables (V_stick and V_double_onset at every node), so build those first. `--refine` adds
//! rows to committed tables where their cells fail between rows
//! ([`thresholds::restitution::refine`]), `--refill` rebuilds the rows built without thresholds
//! where the master tables now have them; run `--k-cells` after either.

use crate::figures::Error;
use crate::master_table::{committed_ends, data_dir};
use numerics::format::number;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::time::Instant;
use thresholds::master::build::{grid_k, node, rel_diff, BuildConfig as MasterConfig};
use thresholds::restitution::build::{build_table, ratios, BuildConfig};
use thresholds::restitution::check::{check_quarters, k_cells};
use thresholds::restitution::format::{parse, TableData};
use thresholds::restitution::refine::{recheck_table, refill_table, refine_table};
use thresholds::restitution::to_text;
use thresholds::{CrackLaw, MasterTables};

/// `--check` recomputes one channel value of every `CHECK_EVERY / channels`-th node (1616 of the
/// k = 0.01 table's 750 000, 1.3 s).
pub const CHECK_EVERY: usize = 397;

/// A recomputed value must equal the committed one to this (the file keeps 8 significant
/// figures; a collision is deterministic).
pub const CHECK_TOL: f64 = 1e-7;

/// The file of the table of `k`.
pub fn table_path(root: &Path, k: f64) -> PathBuf {
    data_dir(root).join(format!("restitution_k{k:.5}.csv"))
}

/// The committed restitution tables, in increasing k: one for each master table that has one
/// (they are built one k at a time).
pub fn committed(root: &Path) -> Result<Vec<TableData>, Error> {
    let paths: Vec<PathBuf> = MasterTables::standard()
        .table_k()
        .iter()
        .map(|&k| table_path(root, k))
        .filter(|path| path.exists())
        .collect();
    // parsed at once (10 MB of text a table); the first error in k order is reported
    let parsed: Vec<Result<TableData, Error>> = paths
        .par_iter()
        .map(|path| {
            let text =
                std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
            parse(&text)
                .map_err(|e| format!("{}, line {}: {}", path.display(), e.line, e.problem).into())
        })
        .collect();
    parsed.into_iter().collect()
}

/// Builds every table (or `only` these indices) and their k cells, and writes them.
pub fn run_build(root: &Path, only: &[usize]) -> Result<(), Error> {
    let start = Instant::now();
    let cfg = BuildConfig::standard();
    let ends = committed_ends(root)?;
    let masters = MasterTables::standard();
    let progress = |s: &str| eprintln!("{:.0} s: {s}", start.elapsed().as_secs_f64());
    require_masters(masters)?;
    // the indices of the standard k grid (k = 0.005 2^(i/3)) that have a master table
    let has_master = |i: usize| {
        let k = grid_k(ends.k0, 3, i);
        masters
            .table_k()
            .iter()
            .any(|&t| (t / k - 1.0).abs() < 1e-9)
    };
    for i in 0..BuildConfig::TABLES {
        if !has_master(i) || (!only.is_empty() && !only.contains(&i)) {
            continue;
        }
        let t = build_table(&cfg, i, &ends, masters, &progress)?;
        std::fs::write(table_path(root, t.k), to_text(&t))?;
        progress(&format!("wrote {}", table_path(root, t.k).display()));
    }
    if only.is_empty() {
        write_k_cells(root, &cfg, &progress)?;
    }
    Ok(())
}

/// Refines the committed tables of these indices (k = 0.005 2^(i/3)) in y where their cells
/// fail, and writes them; their k cells are cleared (run `--k-cells` after).
pub fn run_refine(root: &Path, only: &[usize]) -> Result<(), Error> {
    /// Two passes: the first halves the rows' spacing where cells fail (0.25 -> 0.125), the
    /// second where they still fail.
    const PASSES: usize = 2;
    let start = Instant::now();
    let progress = |s: &str| eprintln!("{:.0} s: {s}", start.elapsed().as_secs_f64());
    if only.is_empty() {
        return Err("--refine needs --only I,..: the tables to refine (an hour of collisions for all eleven)".into());
    }
    let (cfg, ends, masters) = (
        BuildConfig::standard(),
        committed_ends(root)?,
        MasterTables::standard(),
    );
    require_masters(masters)?;
    let mut tables = committed(root)?;
    for &i in only {
        let k = grid_k(ends.k0, 3, i);
        let Some(t) = tables.iter_mut().find(|t| (t.k / k - 1.0).abs() < 1e-9) else {
            return Err(format!("no committed restitution table of k = {k} (index {i}): build it first (--only {i})").into());
        };
        let added = refine_table(&cfg, t, i, &ends, masters, PASSES, &progress)?;
        std::fs::write(table_path(root, t.k), to_text(t))?;
        progress(&format!(
            "k = {k}: {added} rows added; wrote {}",
            table_path(root, t.k).display()
        ));
    }
    Ok(())
}

/// A table-wide step of the build tools. `step(cfg, table, masters, progress)` changes a
/// committed table in place and says what it did (`None`: nothing, the file is left as it is).
type Step = dyn Fn(
    &BuildConfig,
    &mut TableData,
    &MasterTables,
    &(dyn Fn(&str) + Sync),
) -> Result<Option<String>, Error>;

/// Runs `step` on each committed table (or `only` these indices, k = 0.005 2^(i/3)) and writes
/// the tables it changed.
fn each_committed(root: &Path, only: &[usize], step: &Step) -> Result<(), Error> {
    let start = Instant::now();
    let progress = |s: &str| eprintln!("{:.0} s: {s}", start.elapsed().as_secs_f64());
    let (cfg, ends, masters) = (
        BuildConfig::standard(),
        committed_ends(root)?,
        MasterTables::standard(),
    );
    require_masters(masters)?;
    let tables = committed(root)?;
    let index = |t: &TableData| {
        (0..BuildConfig::TABLES).find(|&i| (grid_k(ends.k0, 3, i) / t.k - 1.0).abs() < 1e-9)
    };
    if let Some(i) = only
        .iter()
        .find(|&&i| !tables.iter().any(|t| index(t) == Some(i)))
    {
        return Err(format!(
            "--only {i}: no committed restitution table of that index (k = 0.005 2^(i/3), i = 0..{})",
            BuildConfig::TABLES - 1
        )
        .into());
    }
    for mut t in tables {
        if !only.is_empty() && !index(&t).is_some_and(|i| only.contains(&i)) {
            continue;
        }
        let what = step(&cfg, &mut t, masters, &progress)?;
        let path = table_path(root, t.k);
        match what {
            Some(what) => {
                std::fs::write(&path, to_text(&t))?;
                progress(&format!("k = {}: {what}; wrote {}", t.k, path.display()));
            }
            None => progress(&format!("k = {}: nothing to do", t.k)),
        }
    }
    Ok(())
}

/// Rebuilds the rows of the committed tables (or `only` these indices) whose nodes had no
/// thresholds where the master tables now vouch for them, and writes them; their k cells are
/// cleared (run `--k-cells` after).
pub fn run_refill(root: &Path, only: &[usize]) -> Result<(), Error> {
    each_committed(root, only, &|cfg, t, masters, progress| {
        let rows = refill_table(cfg, t, masters, progress)?;
        Ok((rows > 0).then(|| format!("{rows} rows rebuilt")))
    })
}

/// Checks every cell of the committed tables (or `only` these indices) again, the bouncing
/// cells apart, and writes them (their k cells kept).
pub fn run_recheck(root: &Path, only: &[usize]) -> Result<(), Error> {
    each_committed(root, only, &|cfg, t, masters, progress| {
        recheck_table(cfg, t, masters, progress)?;
        Ok(Some("cells checked again".into()))
    })
}

/// Checks every vouched cell of the committed tables (or `only` these indices) again at a
/// quarter, half and three quarters of its interval at both speed sets (what a build now
/// checks), and writes them (their k cells kept).
pub fn run_quarters(root: &Path, only: &[usize]) -> Result<(), Error> {
    each_committed(root, only, &|cfg, t, masters, progress| {
        let law = CrackLaw::new(t.k)?;
        let lost = check_quarters((cfg, &law), t, masters, progress);
        // written even where nothing moved: the header says the quarters were checked
        Ok(Some(format!("{lost} cell flags fewer at the quarters")))
    })
}

/// Fills the k cells of the committed tables and writes them (`--k-cells`: the tables
/// themselves untouched).
pub fn run_k_cells(root: &Path) -> Result<(), Error> {
    let start = Instant::now();
    let progress = |s: &str| eprintln!("{:.0} s: {s}", start.elapsed().as_secs_f64());
    write_k_cells(root, &BuildConfig::standard(), &progress)
}

/// The restitution tables stand on the master tables (V_stick and the onset at every node).
fn require_masters(masters: &MasterTables) -> Result<(), Error> {
    if masters.table_k().is_empty() {
        return Err(
            "the master tables are not embedded: build them first (cargo xtask master-table)"
                .into(),
        );
    }
    Ok(())
}

/// The k cells of the committed tables, computed and written.
fn write_k_cells(
    root: &Path,
    cfg: &BuildConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(), Error> {
    require_masters(MasterTables::standard())?;
    let mut tables = committed(root)?;
    // the cubic in ln k through four tables: fewer give no k cells to check
    if tables.len() < 4 {
        return Err(format!(
            "the k cells need at least four committed restitution tables, found {}: build them first (cargo xtask restitution-table --only I)",
            tables.len()
        )
        .into());
    }
    k_cells(cfg, &mut tables, MasterTables::standard(), progress)?;
    for t in &tables {
        std::fs::write(table_path(root, t.k), to_text(t))?;
    }
    progress("wrote the k cells");
    Ok(())
}

/// Recomputes a sample of the committed values; an error naming the first that moved.
pub fn run_check(root: &Path, say: &mut dyn FnMut(String)) -> Result<(), Error> {
    let tables = committed(root)?;
    // every table at once (one table's values are recomputed in turn), each reported in order
    let results: Vec<Result<(usize, usize), String>> = tables.par_iter().map(check_table).collect();
    for (t, result) in tables.iter().zip(results) {
        let (recomputed, exact) = result?;
        say(format!(
            "restitution-table --check: k = {}: {recomputed} values recomputed, all within {}; {exact} nodes' thresholds (the master tables no longer vouch there) within {} of the exact search",
            number(t.k),
            number(CHECK_TOL),
            number(MasterConfig::standard().tol)
        ));
    }
    Ok(())
}

/// `--check` of one table: how many values were recomputed, or what is stale.
fn check_table(t: &TableData) -> Result<(usize, usize), String> {
    let cfg = BuildConfig::standard();
    let masters = MasterTables::standard();
    let law = CrackLaw::new(t.k).map_err(|e| e.to_string())?;
    let master = MasterConfig::standard();
    // (values recomputed, nodes checked against the exact search)
    let mut checked = (0, 0);
    let channels = cfg.sigma.len() + cfg.nu.len();
    let all = t
        .rows
        .iter()
        .flat_map(|r| r.nodes.iter().map(move |p| (r.y, p)));
    for (n, (y, p)) in all.enumerate() {
        if !p.f.is_finite() {
            continue;
        }
        let c = n * 7 % channels;
        if n % (CHECK_EVERY / channels).max(1) != 0 || !p.h[c].is_finite() {
            continue;
        }
        let bouncing = c < cfg.sigma.len();
        let q = if bouncing {
            cfg.sigma[c]
        } else {
            cfg.nu[c - cfg.sigma.len()]
        };
        // the thresholds as the build had them (the file rounds them); where the master
        // tables no longer vouch for the node (a row's range ended at a kink of the two kinds
        // of bouncing since, `cargo xtask master-table --part midpoints`: 81 nodes of the
        // eleven tables, their thresholds within 1.1e-6 of it), the file's thresholds are
        // checked against the exact search instead, to the master tables' own tolerance (its h
        // cannot be recomputed to the bit without the build's thresholds)
        let Some((f, f_on)) = ratios(masters, p.x, y, t.k) else {
            let exact = node(&master, &law, p.x, y);
            let off = rel_diff(exact.stick(), Some(p.f)).max(rel_diff(exact.onset(), Some(p.f_on)));
            if off > master.tol {
                return Err(format!(
                    "the restitution table of k = {} is stale: the master tables no longer vouch for x = {}, y = {y}, and its thresholds there are {off:.1e} from the exact search's",
                    t.k, p.x
                ));
            }
            checked.1 += 1;
            continue;
        };
        let now =
            thresholds::restitution::build::node_channel(&cfg, &law, p.x, y, f, f_on, bouncing, q);
        let within = (now - p.h[c]).abs() <= CHECK_TOL * p.h[c].abs().max(1e-6);
        if !within {
            return Err(format!(
                "the restitution table of k = {} is stale: h at x = {}, y = {y}, {} = {q} is {}, the model now gives {now}; run `cargo xtask restitution-table`",
                t.k, p.x, if bouncing { "sigma" } else { "nu" }, p.h[c]
            ));
        }
        checked.0 += 1;
    }
    Ok(checked)
}
