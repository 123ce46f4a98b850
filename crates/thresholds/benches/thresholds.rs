//! V_stick searches (both transitions, relative tolerance 1e-6) for the three reference cases of
//! the Speed issue, one of them with its crack-law table (as a Python call does), and a
//! Figure-4-like sweep (2 k x 11 T_vis, each search seeded by its neighbour); and the same
//! thresholds from the master tables (`v_stick_table/*`, the default method), at a table's own
//! k and between tables, near the cliff, beyond it, with and without building the contact.
//! `cargo bench -p thresholds`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use criterion::{criterion_group, criterion_main, Criterion};
use greenwood::CrackLaw;
use std::hint::black_box;
use thresholds::{sticking_thresholds, sweep_t_vis, MasterTables, SearchOptions};

fn v_stick(c: &mut Criterion) {
    let law = CrackLaw::new(0.01).expect("k in range");
    let co2 = Contact::new(Material::co2(), Geometry::identical(60e-6)).expect("valid");
    let h2o = Contact::new(Material::h2o(), Geometry::identical(90e-6)).expect("valid");
    let opts = SearchOptions::exact();
    let mut group = c.benchmark_group("v_stick");
    group.sample_size(20);
    for (name, contact, t_vis) in [
        ("co2_60um_1e-9", co2, 1e-9),
        ("co2_60um_1e-14", co2, 1e-14),
        ("h2o_90um_1e-9", h2o, 1e-9),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| sticking_thresholds(&contact, &law, black_box(t_vis), &opts))
        });
    }
    // what one call from Python does: its own crack-law table, then the search (the Python
    // overhead in docs/performance.md is measured against this)
    group.bench_function("co2_60um_1e-9_with_table", |b| {
        b.iter(|| {
            let law = CrackLaw::new(0.01).expect("k in range");
            sticking_thresholds(&co2, &law, black_box(1e-9), &opts)
        })
    });
    group.sample_size(10);
    let t_vis: Vec<f64> = (0..11)
        .map(|i| 1e-12 * 10f64.powf(i as f64 * 0.4))
        .collect();
    group.bench_function("sweep_2k_x_11t_vis", |b| {
        b.iter(|| {
            for k in [0.01, 0.02] {
                let law = CrackLaw::new(k).expect("k in range");
                black_box(sweep_t_vis(&co2, &law, &t_vis, &opts).ok());
            }
        })
    });
    group.finish();
}

fn v_stick_table(c: &mut Criterion) {
    let law = CrackLaw::new(0.01).expect("k in range");
    let between = CrackLaw::new(0.0137).expect("k in range");
    let co2 = Contact::new(Material::co2(), Geometry::identical(60e-6)).expect("valid");
    let h2o = Contact::new(Material::h2o(), Geometry::wall(90e-6)).expect("valid");
    let opts = SearchOptions::default();
    // read the embedded tables before timing
    let tables = MasterTables::standard();
    for i in 0..tables.table_k().len() {
        assert!(tables.table(i).is_some());
    }
    assert!(tables.ends().is_some());
    let mut group = c.benchmark_group("v_stick_table");
    for (name, contact, law, t_vis) in [
        ("co2_60um_1e-9", co2, &law, 1e-9),
        ("co2_60um_1e-14", co2, &law, 1e-14),
        ("h2o_90um_wall_1e-9", h2o, &law, 1e-9),
        ("co2_60um_1e-9_k0.0137", co2, &between, 1e-9),
        // within 1 % of the cliff in c_D (V_stick = 250 V_stick,JKR)
        ("co2_60um_near_cliff", co2, &law, 1.35e-8),
        // beyond it: no bouncing
        ("co2_60um_1e-6", co2, &law, 1e-6),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| sticking_thresholds(&contact, law, black_box(t_vis), &opts))
        });
    }
    // what an array element from Python does: the contact of its radius, then the table
    group.bench_function("co2_with_contact", |b| {
        b.iter(|| {
            let c = Contact::new(Material::co2(), Geometry::identical(black_box(60e-6)));
            sticking_thresholds(&c.expect("valid"), &law, black_box(1e-9), &opts)
        })
    });
    group.finish();
}

criterion_group!(benches, v_stick, v_stick_table);
criterion_main!(benches);
