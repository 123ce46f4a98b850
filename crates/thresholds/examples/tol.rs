use contact::{Contact, Material};
use greenwood::CrackLaw;
use thresholds::*;
fn main() {
    let law = CrackLaw::new(0.01).unwrap();
    let c = Contact::new(Material::co2(), 60e-6).unwrap();
    let o = SearchOptions::default();
    let t = std::time::Instant::now();
    let mut n = 0;
    for _ in 0..10 {
        n += sticking_thresholds(&c, &law, 1e-9, &o).unwrap().collisions;
    }
    println!("{:?} per v-stick, {} collisions", t.elapsed() / 10, n / 10);
}
