//! Regression guards over the figure data at reduced resolution, rounded to 6 significant
//! figures. A snapshot only says that the numbers did not change; the physics is validated by
//! the tests of the `greenwood`, `contact`, `dynamics` and `thresholds` crates.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use xtask::figures::{
    Error, Figure1, Figure2, Figure3, Figure4, Figure5, Figure6, Figure7, FigureWall, Progress,
    Resolution,
};
use xtask::table::Table;

fn quiet(_: &str, _: usize, _: usize) {}

fn snapshot<F>(
    compute: fn(Resolution, Progress) -> Result<F, Error>,
    tables: fn(&F) -> Vec<Table>,
) {
    let figure = compute(Resolution::Reduced, &quiet).expect("figure computes");
    for t in tables(&figure) {
        insta::assert_snapshot!(t.file.clone(), t.to_csv(6));
    }
}

#[test]
fn figure1() {
    snapshot(Figure1::compute, Figure1::to_tables);
}

#[test]
fn figure2() {
    snapshot(Figure2::compute, Figure2::to_tables);
}

#[test]
fn figure3() {
    snapshot(Figure3::compute, Figure3::to_tables);
}

#[test]
fn figure4() {
    snapshot(Figure4::compute, Figure4::to_tables);
}

#[test]
fn figure5() {
    snapshot(Figure5::compute, Figure5::to_tables);
}

#[test]
fn figure6() {
    snapshot(Figure6::compute, Figure6::to_tables);
}

#[test]
fn figure7() {
    snapshot(Figure7::compute, Figure7::to_tables);
}

#[test]
fn figure_wall() {
    snapshot(FigureWall::compute, FigureWall::to_tables);
}
