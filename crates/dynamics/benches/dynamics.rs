//! One collision of two 60 um CO2 grains (T_vis = 1e-9 s and 1e-14 s) at the threshold-search
//! tolerance: sticking, double collision and bouncing. `cargo bench -p dynamics`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use criterion::{criterion_group, criterion_main, Criterion};
use dynamics::{Collider, SolverOptions};
use greenwood::CrackLaw;
use std::hint::black_box;

fn collisions(c: &mut Criterion) {
    let law = CrackLaw::new(0.01).expect("k in range");
    let contact = Contact::new(Material::co2(), Geometry::identical(60e-6)).expect("valid");
    let opts = SolverOptions {
        rtol: 1e-8,
        atol: 1e-11,
        ..Default::default()
    };
    let mut group = c.benchmark_group("collision");
    group.sample_size(30);
    for (t_vis, cases) in [
        (
            1e-9,
            [("stick", 0.035), ("double", 0.0405), ("bounce", 0.045)],
        ),
        (
            1e-14,
            [("stick", 0.0165), ("double", 0.01659745), ("bounce", 0.017)],
        ),
    ] {
        let col = Collider::new(contact, &law, t_vis)
            .and_then(|c| c.with_options(opts))
            .expect("valid");
        for (name, v) in cases {
            group.bench_function(format!("T_vis={t_vis:e}/{name}"), |b| {
                b.iter(|| col.collide(black_box(v)))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, collisions);
criterion_main!(benches);
