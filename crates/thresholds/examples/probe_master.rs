#![allow(clippy::unwrap_used, missing_docs)]
use std::time::Instant;
use thresholds::{Contact, Geometry, MasterTables, Material};
fn main() {
    let m = MasterTables::standard();
    let mut s = 1u64;
    let mut next = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut pts = Vec::new();
    for _ in 0..1_000_000 {
        let r = 10f64.powf(-7.0 + 4.0 * next());
        let t = 10f64.powf(-14.0 + 8.0 * next());
        let c = Contact::new(Material::co2(), Geometry::identical(r)).unwrap();
        pts.push((
            c.drag_number(t).log10(),
            c.drag_crack_product().log10(),
            1000.0,
        ));
    }
    let _ = m.ratios_at(pts[0].0, pts[0].1, 0.01, 1000.0);
    for _ in 0..5 {
        let t0 = Instant::now();
        let mut a = 0usize;
        let mut sum = 0.0;
        for &(x, y, f) in &pts {
            if let Some(r) = m.ratios_at(x, y, 0.01, f) {
                a += 1;
                sum += r.v_stick.unwrap_or(0.0);
            }
        }
        println!("{:.3} us a point ({a}, {sum})", t0.elapsed().as_secs_f64());
    }
}
