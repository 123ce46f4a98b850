//! Regression guards over the figure data at reduced resolution, rounded to 6 significant
//! figures. A snapshot only says that the numbers did not change; the physics is validated by
//! the tests of the `greenwood`, `contact`, `dynamics` and `thresholds` crates.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use xtask::figures::{Figures, Resolution};

fn quiet(_: &str, _: usize, _: usize) {}

/// Every table of every figure (`fig1.csv` ... `fig_wall.csv`), each its own snapshot.
#[test]
fn figure_tables() {
    let figures = Figures::compute(Resolution::Reduced, &quiet).expect("figures compute");
    for t in figures.tables() {
        insta::assert_snapshot!(t.file.clone(), t.to_csv(6));
    }
}
