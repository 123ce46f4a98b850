//! The committed `data/fig*.csv` are what the code computes now (the check of
//! `cargo xtask figures --check`), and they are readable as numpy/pandas CSV.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use xtask::figures::{Figures, Resolution};
use xtask::table::Table;
use xtask::{compare_with_committed, workspace_root};

fn quiet(_: &str, _: usize, _: usize) {}

#[test]
fn committed_figure_data_is_current() {
    let figs = Figures::compute(Resolution::Full, &quiet).expect("figures compute");
    let diffs = compare_with_committed(&figs.tables(), &workspace_root().join("data"))
        .expect("data readable");
    assert!(
        diffs.is_empty(),
        "data/ differs from a recomputation; run `cargo xtask figures`:\n{}",
        diffs.join("\n")
    );
}

/// Every CSV: `#` comment lines first (figure, units), one header row of snake_case names, then
/// rows with as many fields as the header.
#[test]
fn csv_files_are_plain() {
    let dir = workspace_root().join("data");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).expect("data/ exists") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("csv") {
            continue;
        }
        n += 1;
        let text = std::fs::read_to_string(&path).expect("readable");
        assert!(
            text.starts_with("# Figure")
                || text.starts_with("# Sphere on a wall")
                || text.starts_with("# Master figure"),
            "{}",
            path.display()
        );
        assert!(
            text.lines()
                .any(|l| l.starts_with("# units") || l.contains("units:")),
            "{}",
            path.display()
        );
        let t = Table::from_csv(&path.display().to_string(), &text).expect("parses");
        for c in &t.columns {
            assert!(
                c.chars()
                    .all(|ch| ch.is_ascii_lowercase() || ch.is_ascii_digit() || ch == '_'),
                "{c}"
            );
        }
        assert!(!t.rows.is_empty());
    }
    assert_eq!(n, 11, "eleven figure files");
}
