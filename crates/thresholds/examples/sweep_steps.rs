//! The cost of the search over five sweeps in T_vis, in solver steps (repeatable, unlike
//! seconds): the measurement behind the search's tuning constants (`docs/performance.md`,
//! "Search constants re-measured").
//!
//! ```sh
//! cargo run --release -p thresholds --example sweep_steps
//! ```
//! CO2 60 um at k = 0.01 and 0.02 (33 T_vis from 1e-12 to 1e-8 s, Figure 4), H2O 90 um at
//! gamma_SV = 0.02 and 0.19 J/m^2 (25 T_vis from 1e-12 to 3e-8 s, Figure 5) and CO2 60 um on a
//! wall (41 T_vis from 1e-13 to 1e-8 s), each search seeded by its neighbours, serial.
use thresholds::{
    sweep::geomspace, sweep_t_vis, Contact, CrackLaw, Geometry, Material, SearchOptions,
};
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let opts = SearchOptions {
        parallel: false,
        ..SearchOptions::exact()
    };
    let mut cases: Vec<(String, Contact, f64, Vec<f64>)> = Vec::new();
    let co2 = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    for k in [0.01, 0.02] {
        cases.push((
            format!("co2 fig4 k={k}"),
            co2,
            k,
            geomspace(1e-12, 1e-8, 33),
        ));
    }
    for g in [0.02, 0.19] {
        let h = Contact::new(
            Material {
                gamma_sv: g,
                ..Material::h2o()
            },
            Geometry::identical(90e-6),
        )?;
        cases.push((
            format!("h2o fig5 g={g}"),
            h,
            0.01,
            geomspace(1e-12, 3e-8, 25),
        ));
    }
    let wall = Contact::new(Material::co2(), Geometry::wall(60e-6))?;
    cases.push(("co2 wall".into(), wall, 0.01, geomspace(1e-13, 1e-8, 41)));
    let mut total = 0;
    for (name, c, k, t) in cases {
        let law = CrackLaw::new(k)?;
        let r = sweep_t_vis(&c, &law, &t, &opts)?;
        let steps: usize = r.iter().map(|x| x.steps).sum();
        let coll: usize = r.iter().map(|x| x.collisions).sum();
        total += steps;
        println!("{name}: {steps} steps, {coll} collisions");
    }
    println!("total {total}");
    Ok(())
}
