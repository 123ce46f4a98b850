use contact::{Contact, Material};
use dynamics::*;
use greenwood::CrackLaw;
use thresholds::*;
fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let c = Contact::new(Material::co2(), 60e-6).unwrap();
    let h = Contact::new(Material::h2o(), 90e-6).unwrap();
    let so = SearchOptions::default_solver();
    for (name, cc, tv) in [
        ("co2", c, 1e-9),
        ("co2", c, 1e-11),
        ("co2", c, 1e-12),
        ("co2", c, 1e-13),
        ("co2", c, 1e-14),
        ("co2", c, 1e-16),
        ("h2o", h, 1e-9),
        ("h2o", h, 1e-7),
    ] {
        let col = Collider::new(cc, &law, tv)
            .unwrap()
            .with_options(so)
            .unwrap();
        let steps: Vec<String> = [0.5, 0.9, 1.0, 1.1, 3.0]
            .iter()
            .map(
                |f| match col.collide(f * cc.v_stick_jkr() * if tv > 1e-10 { 2.5 } else { 1.0 }) {
                    Ok(r) => format!("{}:{}", &format!("{:?}", r.outcome)[..2], r.steps),
                    Err(e) => format!("ERR {}", &e.to_string()[..40]),
                },
            )
            .collect();
        let t = std::time::Instant::now();
        let th = sticking_thresholds(&cc, &law, tv, &SearchOptions::default());
        let el = t.elapsed();
        match th {
            Ok(th) => println!(
                "{name} {tv:e}: {steps:?} vs={:?} vd={:?} n={} {el:?}",
                th.v_stick, th.v_double_onset, th.collisions
            ),
            Err(e) => println!("{name} {tv:e}: {steps:?} ERR {e}"),
        }
    }
}
