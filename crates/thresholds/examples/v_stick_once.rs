//! One V_stick search, serial, for instruction counts (`docs/performance.md`):
//!
//! ```sh
//! cargo build --release -p thresholds --example v_stick_once
//! valgrind --tool=callgrind target/release/examples/v_stick_once co2 1e-9
//! ```
//! Arguments: `co2` (R1 = 60 um) or `h2o` (R1 = 90 um), then T_vis (s). Prints V_stick,
//! V_double_onset (m/s) and the number of collisions.

use thresholds::{sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions};

const USAGE: &str = "usage: v_stick_once [co2|h2o] [T_VIS in s, > 0; default 1e-9]";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let (material, radius) = match args.get(1).map(String::as_str) {
        None | Some("co2") => (Material::co2(), 60e-6),
        Some("h2o") => (Material::h2o(), 90e-6),
        Some(other) => return Err(format!("unknown case '{other}'; {USAGE}").into()),
    };
    let t_vis: f64 = match args.get(2) {
        None => 1e-9,
        Some(t) => t
            .parse()
            .map_err(|e| format!("T_vis = '{t}': {e}; {USAGE}"))?,
    };
    let law = CrackLaw::new(0.01)?;
    let contact = Contact::new(material, Geometry::identical(radius))?;
    let opts = SearchOptions {
        parallel: false,
        ..SearchOptions::exact()
    };
    let th = sticking_thresholds(&contact, &law, t_vis, &opts)?;
    println!(
        "V_stick = {:?} m/s, V_double_onset = {:?} m/s, {} collisions",
        th.v_stick, th.v_double_onset, th.collisions
    );
    Ok(())
}
