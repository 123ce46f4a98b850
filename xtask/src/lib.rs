//! # xtask
//!
//! Project automation. `cargo xtask figures` regenerates the data of Figures 1-7 of Arakawa &
//! Krijt (2021) into `data/fig*.csv` and draws `docs/figures/fig*.svg`; `cargo xtask figures
//! --check` recomputes and compares with the committed data; `cargo xtask test` runs every test;
//! `cargo xtask docs` builds the documentation site into `target/site/`. No physics lives here: only the
//! parameter grids of each figure, the CSV format and the pictures.

pub mod docs;
pub mod figures;
pub mod master_table;
pub mod python;
pub mod restitution_table;
pub mod rustdoc;
pub mod table;
pub mod test;
pub mod wheel;

/// Significant figures written to the CSV files.
pub const CSV_DIGITS: usize = 10;

/// Relative tolerance of `cargo xtask figures --check`. The bisections stop at 1e-6 and the
/// collisions are integrated to 1e-8..1e-9, so a recomputation on another machine or with another
/// linear-algebra backend agrees to about 1e-5 (e near the double-collision onset is the most
/// sensitive); physics that drifted moves the numbers by far more.
pub const CHECK_REL_TOL: f64 = 1e-4;

/// Compares freshly computed figure tables with the committed files in `data_dir`, at the
/// precision they are written ([`CSV_DIGITS`]) and within [`CHECK_REL_TOL`]. Returns the
/// differences found (empty when the data are current).
pub fn compare_with_committed(
    tables: &[table::Table],
    data_dir: &std::path::Path,
) -> Result<Vec<String>, figures::Error> {
    let mut diffs = Vec::new();
    for t in tables {
        let path = data_dir.join(&t.file);
        let text = std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read committed {}: {e}", path.display()))?;
        let committed = table::Table::from_csv(&t.file, &text)?;
        let computed = table::Table::from_csv(&t.file, &t.to_csv(CSV_DIGITS))?;
        diffs.extend(computed.compare(&committed, CHECK_REL_TOL));
    }
    Ok(diffs)
}

/// The workspace root (the parent of this crate's directory).
pub fn workspace_root() -> std::path::PathBuf {
    let here = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    here.parent()
        .map_or(here.clone(), std::path::Path::to_path_buf)
}
