//! The default V_stick search against a tight reference: the accuracy claim of
//! `docs/performance.md` ("Accuracy").
//!
//! ```sh
//! cargo run --release -p thresholds --example tight_reference
//! ```
//! For each case, V_stick and V_double_onset with `SearchOptions::exact()` (relative
//! tolerance 1e-6) and with a reference search (`SearchOptions::reference()`: BDF at rtol 1e-11, bracket 1e-9); prints the
//! relative differences and the number of collisions of the default search, then the same
//! search without rebound restarts (`SearchOptions::restarts`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

#[path = "common/mod.rs"]
mod common;

use thresholds::{sticking_thresholds, CrackLaw, SearchOptions};

fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let reference = SearchOptions::reference();
    println!(
        "case | V_stick - ref | V_double_onset - ref | collisions | without restarts: V_stick - ref | V_double_onset - ref"
    );
    for (name, contact, t_vis) in common::cases(common::REFERENCE) {
        let r = sticking_thresholds(&contact, &law, t_vis, &reference).unwrap();
        let d = sticking_thresholds(&contact, &law, t_vis, &SearchOptions::exact()).unwrap();
        let no_restarts = SearchOptions {
            restarts: false,
            ..SearchOptions::exact()
        };
        let n = sticking_thresholds(&contact, &law, t_vis, &no_restarts).unwrap();
        let rel = |a: Option<f64>, b: Option<f64>| a.unwrap() / b.unwrap() - 1.0;
        println!(
            "{name} | {:+.1e} | {:+.1e} | {} | {:+.1e} | {:+.1e}",
            rel(d.v_stick, r.v_stick),
            rel(d.v_double_onset, r.v_double_onset),
            d.collisions,
            rel(n.v_stick, r.v_stick),
            rel(n.v_double_onset, r.v_double_onset),
        );
    }
}
