//! How much of the restitution the tables answer, how fast and how well: random collisions of
//! the "Instant everywhere" domain (random materials, sizes, geometries, T_vis) with bouncing
//! below the search limit, k log-uniform over the committed restitution tables' range (once
//! their k cells are built; else one of their own k), impact speeds on both sides of V_stick
//! (`examples/common/domain.rs`).
//!
//! ```sh
//! cargo run --release -p thresholds --example restitution_accuracy -- 100000 2000
//! cargo run --release -p thresholds --example restitution_accuracy -- 100000 2000 wide
//! cargo run --release -p thresholds --example restitution_accuracy -- 100000 100000 wide own
//! ```
//! (`own`: k drawn from the tables' own k instead, where no check between tables stands behind
//! an answer.)
//! prints the share the tables answer, the time of those answers (one thread), and against the
//! ODE on the first `sample` of them the largest difference in e and whether every outcome
//! agrees. The impact speeds are half bouncing, half double collisions (between V_on and
//! V_stick: where that window is narrower than 1e-3 of V_stick, as for most grains, nearly all
//! of them lie within `ONSET_MARGIN` (3e-4) of the onset, where the ODE decides); with `wide`,
//! log-uniform from V_stick/2 to 100 V_stick (or the search limit), as an experiment's speeds
//! would be; then also the time of all of them answered as `collision(..,
//! ThresholdMethod::Table)` answers them (the tables, else the ODE) on every thread
//! (`RAYON_NUM_THREADS`).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Instant;
use thresholds::restitution::RestitutionTables;
use thresholds::{
    sticking_thresholds, Collider, CrackLaw, SearchOptions, SolverOptions, ThresholdMethod,
};

#[path = "common/domain.rs"]
#[allow(dead_code)] // the example of the master tables reads the rest
mod domain;

use domain::{draw, Rng};

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(100_000, |s| s.parse().unwrap());
    let sample: usize = args.next().map_or(2000, |s| s.parse().unwrap());
    let rest: Vec<String> = args.collect();
    let wide = rest.iter().any(|a| a == "wide");
    // the tables' own k only, where no check between tables stands behind an answer
    let own = rest.iter().any(|a| a == "own");
    let tables = RestitutionTables::standard();
    let ks = tables.table_k().to_vec();
    assert!(!ks.is_empty(), "no restitution table is embedded");
    // collisions with bouncing below the search limit: (point, k, V_in); the thresholds come
    // from the master tables, a few from the search (not timed)
    let mut rng = Rng(2030);
    let mut cases = Vec::with_capacity(n);
    while cases.len() < n {
        let p = draw(&mut rng, false);
        let k = if own {
            rng.pick(&ks)
        } else {
            rng.restitution_k()
        };
        let law = CrackLaw::new(k).unwrap();
        let Some((vs, von, v_max)) = p.bouncing_thresholds(&law) else {
            continue;
        };
        let v_in = if wide {
            rng.log_uniform(0.5 * vs, (100.0 * vs).min(v_max))
        } else {
            domain::impact_speed(&mut rng, vs, von, v_max)
        };
        cases.push((p, k, v_in));
    }
    let start = Instant::now();
    let answers: Vec<_> = cases
        .iter()
        .map(|(p, k, v_in)| tables.rebound(&p.contact, *k, p.t_vis, *v_in))
        .collect();
    let elapsed = start.elapsed().as_secs_f64();
    let answered = answers.iter().filter(|a| a.is_some()).count();
    let ks = if own {
        format!("the tables' own {ks:?}")
    } else if tables.k_checked() {
        format!("log-uniform over {} - {}", ks[0], ks[ks.len() - 1])
    } else {
        format!("{ks:?}")
    };
    println!(
        "{n} random collisions (k {ks}): the tables answered {answered} ({:.2} %) in {elapsed:.3} s, one thread ({:.2} us each)",
        100.0 * answered as f64 / n as f64,
        1e6 * elapsed / n as f64
    );
    if wide {
        use rayon::prelude::*;
        let solver = SolverOptions::default();
        let start = Instant::now();
        let by_ode: usize = cases
            .par_iter()
            .map(|(p, k, v_in)| {
                let law = CrackLaw::new(*k).unwrap();
                let (_, by) = thresholds::restitution::collision(
                    &p.contact,
                    &law,
                    p.t_vis,
                    *v_in,
                    &solver,
                    ThresholdMethod::Table,
                )
                .unwrap();
                usize::from(by == ThresholdMethod::Search)
            })
            .sum();
        println!(
            "all {n}, the tables or else the ODE ({by_ode} by the ODE), {} threads: {:.3} s",
            rayon::current_num_threads(),
            start.elapsed().as_secs_f64()
        );
    }
    let (mut worst, mut same, mut compared, mut over, mut refused) = (0.0f64, 0, 0, 0, 0);
    for ((p, k, v_in), a) in cases.iter().zip(&answers).take(sample) {
        let Some(a) = a else { continue };
        let law = CrackLaw::new(*k).unwrap();
        // below the collider's T_vis bound (c_a > 3e10) the tables answer with their
        // converged value and the ODE refuses: nothing to compare
        let Ok(collider) = Collider::new(p.contact, &law, p.t_vis) else {
            refused += 1;
            continue;
        };
        let ode = collider.collide(*v_in).unwrap();
        let miss = (a.e - ode.e).abs();
        worst = worst.max(miss);
        if miss > 1e-4 {
            over += 1;
            let d = p.contact.dimensionless(p.t_vis);
            let th =
                sticking_thresholds(&p.contact, &law, p.t_vis, &SearchOptions::default()).unwrap();
            eprintln!(
                "  |e - e_ODE| = {miss:.1e}: x = {:.3}, y = {:.3}, k = {k:.5}, V_in / V_stick = {:.6}, V_on / V_stick = {:.6}, e = {:.5} (ODE {:.5})",
                d.c_d.log10(),
                (d.c_d * d.c_a).log10(),
                v_in / th.v_stick.unwrap(),
                th.v_double_onset.unwrap() / th.v_stick.unwrap(),
                a.e,
                ode.e
            );
        }
        same += usize::from(a.outcome == ode.outcome);
        compared += 1;
    }
    println!(
        "against the ODE on {compared} of them: largest |e - e_ODE| = {worst:.2e} ({over} above 1e-4), the same outcome {same} of {compared} ({refused} below the collider's T_vis bound, not compared)"
    );
}
