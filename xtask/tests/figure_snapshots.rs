//! Regression guards over the figure data at reduced resolution, rounded to 6 significant
//! figures. A snapshot only says that the numbers did not change; the physics is validated by
//! the tests of the `greenwood`, `contact`, `dynamics` and `thresholds` crates.

use xtask::figures::{self, Error, Progress, Resolution};
use xtask::table::Table;

fn quiet(_: &str, _: usize, _: usize) {}

fn snapshot(f: fn(Resolution, Progress) -> Result<Vec<Table>, Error>) {
    for t in f(Resolution::Reduced, &quiet).expect("figure computes") {
        insta::assert_snapshot!(t.file.clone(), t.to_csv(6));
    }
}

#[test]
fn figure1() {
    snapshot(figures::figure1);
}

#[test]
fn figure2() {
    snapshot(figures::figure2);
}

#[test]
fn figure3() {
    snapshot(figures::figure3);
}

#[test]
fn figure4() {
    snapshot(figures::figure4);
}

#[test]
fn figure5() {
    snapshot(figures::figure5);
}

#[test]
fn figure6() {
    snapshot(figures::figure6);
}

#[test]
fn figure7() {
    snapshot(figures::figure7);
}
