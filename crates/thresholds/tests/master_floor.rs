//! The nodes' floor (`thresholds::master::floor`): where the interpolation declines next to the
//! kink of the cliff, a lower bound of F and F_on from the nodes of the tables around k answers
//! "nothing below v_max". The floor lies below the reference search (the truth the nodes are),
//! and its verdicts are the exact search's (`SearchOptions::exact()`, what `method="search"`
//! runs).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use greenwood::CrackLaw;
use rayon::prelude::*;
use thresholds::master::build::{node, BuildConfig, Point};
use thresholds::master::MasterTables;
use thresholds::{sticking_thresholds, SearchOptions, ThresholdMethod};

// the random numbers and the domain's points
#[allow(dead_code)]
#[path = "../examples/common/domain.rs"]
mod domain;

use domain::{draw, Rng};

/// At random points around the kink (x from -1.5 to 2.3, y from -5.6 to -3, k log-uniform
/// 0.005-0.05 or a table's own: where the interpolation declines most) whose floor of both
/// ratios lies between 500 and 9000 (read off nodes, not a row's level beyond its end), the
/// reference search of the nodes (`master::build::node`: rel_tol 1e-8, collisions at rtol
/// 1e-10) finds both ratios at least the floor. (`examples/node_floor.rs`: none above at 2800
/// points, 1000 around the kink and 1000 over the whole domain with any floor, 400 and 400
/// with a floor of at least 500.)
#[test]
fn the_node_floor_is_below_the_reference_search() {
    let tables = MasterTables::standard();
    let mut rng = Rng(4242);
    let ks = tables.table_k().to_vec();
    let points: Vec<[f64; 3]> = std::iter::repeat_with(|| {
        let x = -1.5 + 3.8 * rng.next();
        let y = -5.6 + 2.6 * rng.next();
        let k = if rng.next() < 0.5 {
            rng.pick(&ks)
        } else {
            rng.log_uniform(0.005, 0.05)
        };
        [x, y, k]
    })
    .filter(|&[x, y, k]| {
        let [f, f_on] = tables.node_floor(x, y, k);
        f.zip(f_on)
            .is_some_and(|(f, o)| f.min(o) >= 500.0 && f.max(o) <= 9000.0)
    })
    .take(16)
    .collect();
    let cfg = BuildConfig::standard();
    points.par_iter().for_each(|&[x, y, k]| {
        let [f, f_on] = tables.node_floor(x, y, k);
        let (f, f_on) = (f.unwrap(), f_on.unwrap());
        let what = format!("x = {x}, y = {y}, k = {k}: floor {f}, {f_on}");
        match node(&cfg, &CrackLaw::new(k).unwrap(), x, y) {
            Point::Bounce { f_stick, f_onset } => {
                assert!(f <= f_stick * (1.0 + 1e-6), "{what}: F = {f_stick}");
                assert!(f_on <= f_onset * (1.0 + 1e-6), "{what}: F_on = {f_onset}");
            }
            Point::OnsetOnly { f_onset } => {
                assert!(f_on <= f_onset * (1.0 + 1e-6), "{what}: F_on = {f_onset}")
            }
            Point::NoBounce => {}
            Point::Failed => panic!("{what}: the reference search failed"),
        }
    });
}

/// The points of the whole domain (the draw of `examples/table_accuracy.rs`, seed 2026: random
/// materials, reduced radii 5 nm - 1 cm, T_vis 1e-16 - 1e-3 s, k log-uniform 0.005-0.05) where
/// the interpolation declines and the floor answers: the exact search with the default v_max
/// finds no bouncing and no double collision below it either. (Measured: 14 of the 42 points
/// the interpolation declines since the k checks' bins of 0.125, of 47 before; all alike.)
#[test]
fn the_floors_verdicts_are_the_searchs() {
    let tables = MasterTables::standard();
    let mut rng = Rng(2026);
    let floors: Vec<domain::Point> = (0..20000)
        .map(|_| draw(&mut rng, false))
        .filter(|p| {
            let (x, y, f_max) = p.table_coordinates();
            tables.interpolated_at(x, y, p.k, f_max).is_none()
                && tables.ratios_at(x, y, p.k, f_max).is_some()
        })
        .collect();
    assert!(floors.len() >= 10, "the floor answers {}", floors.len());
    floors.par_iter().for_each(|p| {
        let law = CrackLaw::new(p.k).unwrap();
        let with = |o: SearchOptions| sticking_thresholds(&p.contact, &law, p.t_vis, &o).unwrap();
        let (t, s) = (with(SearchOptions::default()), with(SearchOptions::exact()));
        let what = format!("k = {}, t_vis = {}: {t:?} vs {s:?}", p.k, p.t_vis);
        assert_eq!(t.method, ThresholdMethod::Table, "{what}");
        assert_eq!((t.v_stick, t.v_double_onset), (None, None), "{what}");
        assert_eq!((s.v_stick, s.v_double_onset), (None, None), "{what}");
    });
}
