//! `cargo xtask master-table [--check]`: build the master tables of V_stick / V_stick,JKR with
//! the exact search and write them to `crates/thresholds/data/master_k<k>.csv`, or recompute a
//! sample of their nodes and fail if the model no longer gives them.

use crate::figures::Error;
use numerics::format::number;
use std::path::Path;
use std::time::Instant;
use thresholds::master::build::{build, check_nodes, BuildConfig};
use thresholds::master::STANDARD_K;
use thresholds::MasterTable;

/// `--check` recomputes every this-many-th node (about 350 of each table's 15 000): a change of
/// the model moves them all, so a sample finds it, in seconds.
pub const CHECK_EVERY: usize = 40;

/// A recomputed node must equal the committed one to this relative tolerance: a node is the
/// search without a hint, which is deterministic, so any change comes from the model or its
/// numerics (the file keeps 13 significant figures).
pub const CHECK_REL_TOL: f64 = 1e-11;

/// The file of the table of `k` under `root`.
pub fn table_path(root: &Path, k: f64) -> std::path::PathBuf {
    root.join("crates/thresholds/data")
        .join(format!("master_k{}.csv", number(k)))
}

/// The commit the table is built at (with `-dirty` for uncommitted changes), for its header.
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

/// Builds both standard tables and writes them.
pub fn run_build(root: &Path) -> Result<(), Error> {
    let start = Instant::now();
    let commit = commit(root);
    for k in STANDARD_K {
        let progress = |s: &str| eprintln!("k = {k}, {:.0} s: {s}", start.elapsed().as_secs_f64());
        let mut table = build(&BuildConfig::standard(k), &progress)?;
        table.prepend_header(&[
            "command: cargo xtask master-table".to_string(),
            format!("commit: {commit}"),
        ]);
        let path = table_path(root, k);
        std::fs::write(&path, table.to_text())?;
        eprintln!(
            "wrote {} in {:.0} s",
            path.display(),
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// Recomputes a sample of the committed tables' nodes; an error naming the first that moved.
pub fn run_check() -> Result<(), Error> {
    for k in STANDARD_K {
        let table = MasterTable::standard(k).ok_or(format!("no committed table for k = {k}"))?;
        let checked = check_nodes(table, CHECK_EVERY)?;
        if let Some(&(x, y, f, again)) = checked.iter().find(|(_, _, f, again)| {
            (again / f - 1.0).abs().is_nan() || (again / f - 1.0).abs() > CHECK_REL_TOL
        }) {
            return Err(format!(
                "the master table of k = {k} is stale: at x = log10 c_D = {x}, y = log10(c_D c_a) = {y} it holds F = {f}, the model now gives {again}; run `cargo xtask master-table`"
            )
            .into());
        }
        eprintln!(
            "master-table --check: k = {k}: {} nodes recomputed, all within {}",
            checked.len(),
            number(CHECK_REL_TOL)
        );
    }
    Ok(())
}
