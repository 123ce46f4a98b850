//! Crack-law evaluation: the table lookup the ODE calls at every right-hand side, the table
//! build, and one direct inversion for comparison. `cargo bench -p greenwood`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use criterion::{criterion_group, criterion_main, Criterion};
use greenwood::{v_direct, CrackLaw};
use std::hint::black_box;

fn crack_law(c: &mut Criterion) {
    let law = CrackLaw::new(0.01).expect("k in range");
    let betas: Vec<f64> = (0..1024)
        .map(|i| 0.011 * (99.0f64 / 0.011).powf(i as f64 / 1023.0))
        .collect();
    c.bench_function("crack_law/speed (v and dv/dbeta), per call", |b| {
        let mut i = 0;
        b.iter(|| {
            i = (i + 1) & 1023;
            black_box(law.speed_unchecked(black_box(betas[i])))
        })
    });
    // the law and its table, built on the first evaluation
    c.bench_function("crack_law/CrackLaw::new(k) and its table", |b| {
        b.iter(|| {
            let law = CrackLaw::new(black_box(0.01)).expect("k in range");
            black_box(law.speed_unchecked(0.5))
        })
    });
    c.bench_function("crack_law/v_direct (quadrature inversion)", |b| {
        b.iter(|| v_direct(black_box(0.01), black_box(2.0)))
    });
}

criterion_group!(benches, crack_law);
criterion_main!(benches);
