//! One V_stick search, serial, for instruction counts (`docs/performance.md`):
//!
//! ```sh
//! cargo build --release -p thresholds --example v_stick_once
//! valgrind --tool=callgrind target/release/examples/v_stick_once co2 1e-9
//! ```
//! Arguments: `co2` (R1 = 60 um) or `h2o` (R1 = 90 um), then T_vis (s). Prints V_stick,
//! V_double_onset (m/s) and the number of collisions.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use thresholds::{sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (material, radius) = match args.get(1).map(String::as_str) {
        Some("h2o") => (Material::h2o(), 90e-6),
        _ => (Material::co2(), 60e-6),
    };
    let t_vis: f64 = args.get(2).map_or(1e-9, |t| t.parse().expect("T_vis in s"));
    let law = CrackLaw::new(0.01).unwrap();
    let contact = Contact::new(material, Geometry::identical(radius)).unwrap();
    let opts = SearchOptions {
        parallel: false,
        ..SearchOptions::default()
    };
    let th = sticking_thresholds(&contact, &law, t_vis, &opts).unwrap();
    println!(
        "V_stick = {:?} m/s, V_double_onset = {:?} m/s, {} collisions",
        th.v_stick, th.v_double_onset, th.collisions
    );
}
