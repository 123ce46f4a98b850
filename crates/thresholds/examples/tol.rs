use contact::{Contact, Material};
use greenwood::CrackLaw;
use thresholds::*;
fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let c = Contact::new(Material::co2(), 60e-6).unwrap();
    for parallel in [false, true, false, true] {
        let o = SearchOptions {
            parallel,
            ..Default::default()
        };
        let t = std::time::Instant::now();
        let mut n = 0;
        for _ in 0..20 {
            n += sticking_thresholds(&c, &law, 1e-9, &o).unwrap().collisions;
        }
        println!(
            "parallel {parallel}: {:?} per v-stick, {} collisions",
            t.elapsed() / 20,
            n / 20
        );
    }
    let col = dynamics::Collider::new(c, &law, 1e-9)
        .unwrap()
        .with_options(SearchOptions::default_solver())
        .unwrap();
    for v in [0.035, 0.0405, 0.045] {
        let t = std::time::Instant::now();
        for _ in 0..20 {
            col.collide(v).unwrap();
        }
        println!("v {v}: {:?} per collision", t.elapsed() / 20);
    }
}
