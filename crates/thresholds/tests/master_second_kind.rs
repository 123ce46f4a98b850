//! The second kind of bouncing (soft, sticky, large grains past the kink of the cliff, where
//! sticking turns straight into bouncing: F_on = F), where the default search is less accurate
//! than elsewhere and the master tables give no value (`docs/model.md`, "The cliff";
//! `docs/performance.md`, "Master tables", "What is left" (15)). The reference of each check is
//! a converged search computed here: BDF at rtol 1e-12, brackets of 1e-10 (BDF at 1e-13 moved
//! it by at most 9e-7 at five points of the second kind).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use thresholds::master::build::{default_search, node, BuildConfig, Point};
use thresholds::{CrackLaw, MasterTables};

/// Points `(x, y, k)` of `examples/table_accuracy.rs`'s draw (seed 2026) that the tables
/// decline, of the second kind, F = 147-510 (below the default search limit of 1000
/// V_stick,JKR, so a value is needed), to nine digits (F changes by about 4e-6 for 1e-6 in k
/// there, and the default search's miss is scattered from point to point).
const SECOND_KIND: [(f64, f64, f64); 3] = [
    (-0.246572737, -4.739349370, 0.025820338),
    (0.561764988, -4.435981264, 0.041861864),
    (-0.055500943, -4.190480052, 0.046997715),
];

/// A point of the same draw of the first kind (F = 79.6, a window of double collisions below
/// it), next to the kink but short of the crossing, to nine digits.
const FIRST_KIND: (f64, f64, f64) = (-0.480429255, -4.275621428, 0.048556687);

/// `(F, F_on)` of a search that found both below its limit.
fn both(p: Point) -> (f64, f64) {
    match p {
        Point::Bounce { f_stick, f_onset } => (f_stick, f_onset),
        p => panic!("both thresholds expected, got {p:?}"),
    }
}

#[test]
fn in_the_second_kind_the_default_search_strays_and_the_tables_give_no_value() {
    let (cfg, reference) = (BuildConfig::standard(), BuildConfig::converged());
    let tables = MasterTables::standard();
    for (x, y, k) in SECOND_KIND {
        let law = CrackLaw::new(k).unwrap();
        let (f, f_on) = both(node(&reference, &law, x, y));
        // the second kind: no window of double collisions below V_stick
        assert!(
            (f_on / f - 1.0).abs() < 1e-9,
            "{x} {y} {k}: F {f}, F_on {f_on}"
        );
        assert!(f < 990.0, "{x} {y} {k}: F = {f} should need a value");
        // the default search misses it by more than the tables' promise of 1e-5 (a recorded
        // measurement at these points, where it scatters: a search tightened there fails the
        // lower bound, and this test and the docs then change), by less than the 5.4e-5 seen
        // over 1e5 random points
        let (f_default, _) = both(default_search(&cfg, &law, x, y));
        let miss = (f_default / f - 1.0).abs();
        assert!(
            miss > 1e-5 && miss <= 5.4e-5,
            "{x} {y} {k}: default search off by {miss:.1e}"
        );
        // no interpolation agrees with that search to 1e-5: the tables give no value
        let answer = tables.ratios_at(x, y, k, 1000.0);
        assert!(
            answer.is_none_or(|r| r.v_stick.is_none()),
            "{x} {y} {k}: the tables answered {answer:?}"
        );
    }
}

#[test]
fn in_the_first_kind_next_to_the_kink_the_default_search_is_within_its_accuracy() {
    let (x, y, k) = FIRST_KIND;
    let law = CrackLaw::new(k).unwrap();
    let (f, f_on) = both(node(&BuildConfig::converged(), &law, x, y));
    assert!(
        f_on < f * (1.0 - 1e-4),
        "the first kind: F {f}, F_on {f_on}"
    );
    let (f_default, _) = both(default_search(&BuildConfig::standard(), &law, x, y));
    // `docs/performance.md`, "Accuracy": the default search within 8e-8 of the reference on
    // its cases, within 6.2e-7 at the 60 first-kind points the tables decline in 1e5
    assert!(
        (f_default / f - 1.0).abs() < 1e-6,
        "F {f_default} against {f}"
    );
}
