//! How the restitution tables do next to the no-bouncing cliff, where the rebound just above
//! V_stick changes fast with x = log10 c_D: random collisions within 0.05 in x of the cliff
//! (the master tables' end curve x_s at their (y, k)), by distance to it, answered by the
//! tables (closer than [`CLIFF_MARGIN`] they decline, the ODE answers) and against the ODE.
//!
//! ```sh
//! cargo run --release -p thresholds --example cliff_margin -- 20000 wide     # V_stick/2 - 100 V_stick
//! cargo run --release -p thresholds --example cliff_margin -- 20000 near     # sigma 1e-4 - 1
//! cargo run --release -p thresholds --example cliff_margin -- 20000 double own
//! ```
//! Speeds: `wide` log-uniform from V_stick/2 to 100 V_stick (an experiment's), `near` just above
//! V_stick (sigma = ln(V_in / V_stick) log-uniform from 1e-4 to 1), `double` half bouncing, half
//! double collisions (`domain::impact_speed`); k log-uniform over the tables' range, or with
//! `own` one of the tables' own k (no check between tables stands behind those). `CLIFF_SEED`
//! draws other collisions.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::restitution::{RestitutionTables, CLIFF_MARGIN};
use thresholds::{Collider, CrackLaw, Outcome};

#[path = "common/domain.rs"]
#[allow(dead_code)] // the example of the master tables reads the rest
mod domain;

use domain::{draw, Rng};

/// The bands of distance to the cliff (in x) reported, up to the margin of the restitution
/// tables before their cells were checked at their quarters (0.05).
const BANDS: [f64; 6] = [0.0, 0.005, 0.01, 0.02, 0.03, domain::OLD_CLIFF_MARGIN];

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(20000, |s| s.parse().unwrap());
    let rest: Vec<String> = args.collect();
    let mode = rest.first().cloned().unwrap_or_else(|| "wide".into());
    let own = rest.iter().any(|a| a == "own");
    let seed = std::env::var("CLIFF_SEED").map_or(4242, |s| s.parse().unwrap());
    let tables = RestitutionTables::standard();
    let mut rng = Rng(seed);
    // (point, k, V_in, distance to the cliff in x, V_stick)
    let mut cases = Vec::with_capacity(n);
    while cases.len() < n {
        let p = draw(&mut rng, false);
        let k = if own {
            rng.pick(tables.table_k())
        } else {
            rng.restitution_k()
        };
        let Some(dist) = p.below_cliff(k) else {
            continue;
        };
        if !(dist > 0.0 && dist < BANDS[BANDS.len() - 1]) {
            continue;
        }
        let law = CrackLaw::new(k).unwrap();
        let Some((vs, von, v_max)) = p.bouncing_thresholds(&law) else {
            continue;
        };
        let v_in = match mode.as_str() {
            "near" => domain::just_above(&mut rng, vs),
            "double" => domain::impact_speed(&mut rng, vs, von, v_max),
            _ => rng.log_uniform(0.5 * vs, (100.0 * vs).min(v_max)),
        };
        if v_in < v_max {
            cases.push((p, k, v_in, dist, vs));
        }
    }
    // per band: how many collisions, the tables' answers (None: the ODE answers) and, of
    // those the ODE can integrate, (|e - e_ODE|, the same outcome)
    struct Band {
        collisions: usize,
        answered: usize,
        not_sticking: usize,
        compared: Vec<(f64, bool)>,
    }
    let bands: Vec<Band> = BANDS
        .windows(2)
        .map(|b| {
            let inside: Vec<_> = cases
                .iter()
                .filter(|c| c.3 >= b[0] && c.3 < b[1])
                .collect();
            let answers: Vec<_> = inside
                .par_iter()
                .filter_map(|&(p, k, v_in, dist, vs)| {
                    let a = tables.rebound(&p.contact, *k, p.t_vis, *v_in)?;
                    let law = CrackLaw::new(*k).unwrap();
                    // below the collider's T_vis bound the tables answer with their
                    // converged value and the ODE refuses: nothing to compare
                    let Ok(collider) = Collider::new(p.contact, &law, p.t_vis) else {
                        return Some((a.outcome, None));
                    };
                    let ode = collider.collide(*v_in).unwrap();
                    let miss = (a.e - ode.e).abs();
                    if miss > 1e-4 {
                        eprintln!(
                            "  |e - e_ODE| = {miss:.1e} at {dist:.4} from the cliff, k = {k:.5}, sigma = {:.4}, e = {:.5} (ODE {:.5})",
                            (v_in / vs).ln(),
                            a.e,
                            ode.e
                        );
                    }
                    Some((a.outcome, Some((miss, a.outcome == ode.outcome))))
                })
                .collect();
            Band {
                collisions: inside.len(),
                answered: answers.len(),
                not_sticking: answers
                    .iter()
                    .filter(|a| a.0 != Outcome::Sticking)
                    .count(),
                compared: answers.iter().filter_map(|a| a.1).collect(),
            }
        })
        .collect();
    println!(
        "{n} collisions within {} of the cliff ({mode} speeds, k {}), CLIFF_MARGIN = {CLIFF_MARGIN}:",
        BANDS[BANDS.len() - 1],
        if own { "the tables' own" } else { "log-uniform" }
    );
    for (b, band) in BANDS.windows(2).zip(bands) {
        let c = &band.compared;
        let worst = c.iter().map(|m| m.0).fold(0.0, f64::max);
        let over = c.iter().filter(|m| m.0 > 1e-4).count();
        let differ = c.iter().filter(|m| !m.1).count();
        println!(
            "  {:.3}-{:.3}: {} collisions, the tables answered {} ({} not sticking); against the ODE on {}: largest |e - e_ODE| {worst:.2e} ({over} above 1e-4), {differ} outcomes differ",
            b[0],
            b[1],
            band.collisions,
            band.answered,
            band.not_sticking,
            c.len()
        );
    }
}
