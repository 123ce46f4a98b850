//! The master tables between tables of k, where the checks between neighbouring tables (the
//! `kcheck` bins of `master_ends.csv`) vouch for the polynomial in ln k: points those checks
//! once refused, against the exact search (`SearchOptions::exact()`, the truth the tables are
//! built from), and next to the search limit, where that search's verdict is wrong, against the
//! reference search (`SearchOptions::reference()`).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;
use common::agree::checked_table_answer;
use greenwood::CrackLaw;
use thresholds::{sticking_thresholds, SearchOptions, ThresholdMethod};

/// What answers a point the k checks once refused.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Since {
    /// In the first and the last interval of k the sextic through seven tables answers
    /// (`K_STENCIL_EDGE`), where the quintic through six missed the exact search by up to 2.6e-6
    /// (so the k checks refused it). The points: those `examples/table_accuracy.rs` listed as
    /// declined before (2026-11-27), F = 17 to 720.
    Sextic,
    /// The k checks in y bins of 0.125 (`BuildConfig::kcheck_dy`, 0.25 before 2026-11-27, seventh
    /// sitting): each bin is checked at its middle y, so every point lies within 1/16 in y of a
    /// check. The points: those the finer bins answer and those of 0.25 declined in five draws of
    /// 2e4 random points of the whole domain (`examples/table_accuracy.rs`; the first three
    /// beyond the cliff, F_on on the strip within 1e-3 of x_s; their coordinates rounded), but for
    /// the one of the next test.
    FinerBins,
    /// In plain x the k checks go on past their first miss while the polynomial stays within
    /// 4e-6 of the exact nodes at nine points around each check point and within 5e-6 of the
    /// default search (`BuildConfig::kcheck_spread_tol`, 2026-11-28, fifteenth sitting): next
    /// to the kink the tables' own interpolation scatters by 1-4e-6 around the nodes, and the
    /// first check point above 2e-6 had ended whole bins. The points: those it answers of the
    /// declined in three draws of 2e4 random points of the whole domain (`TABLE_SEED` 2026, 7
    /// and 99 of `examples/table_accuracy.rs`), F = 20 to 640.
    PastFirstMiss,
}

/// The points `(x, y, k)`, each with what answers it now.
const REFUSED: [(f64, f64, f64, Since); 30] = [
    (-1.094788, -4.095806, 0.046104, Since::Sextic),
    (-1.099735, -3.959702, 0.047059, Since::Sextic),
    (-1.383768, -4.348049, 0.049542, Since::Sextic),
    (-1.067420, -3.850801, 0.044004, Since::Sextic),
    (-0.742408, -4.014833, 0.005686, Since::Sextic),
    (-0.351498, -2.810375, 0.005560, Since::Sextic),
    (-0.068662, -0.043688, 0.016689, Since::FinerBins),
    (-0.069894, -0.057077, 0.008979, Since::FinerBins),
    (-0.084134, -0.273428, 0.024138, Since::FinerBins),
    (-0.620700, -3.710300, 0.047753, Since::FinerBins),
    (-1.222958, -3.676451, 0.044537, Since::FinerBins),
    (-0.5214, -4.1431, 0.0238, Since::FinerBins),
    (-1.0366, -4.7607, 0.0329, Since::FinerBins),
    (-1.0278, -3.8001, 0.0411, Since::FinerBins),
    (-1.2660, -3.7084, 0.0452, Since::FinerBins),
    (-0.5121, -3.6239, 0.0053, Since::FinerBins),
    (-0.4892, -3.5879, 0.0379, Since::FinerBins),
    (-0.5072, -3.6732, 0.0425, Since::FinerBins),
    (-0.9612, -3.6270, 0.0467, Since::FinerBins),
    (-1.019367, -3.532402, 0.046929, Since::PastFirstMiss),
    (-1.074927, -3.565232, 0.045415, Since::PastFirstMiss),
    (-0.449222, -3.072365, 0.040044, Since::PastFirstMiss),
    (-0.483153, -3.821676, 0.005722, Since::PastFirstMiss),
    (-0.696664, -3.814771, 0.045537, Since::PastFirstMiss),
    (-0.428873, -3.249564, 0.043559, Since::PastFirstMiss),
    (-0.464657, -3.042640, 0.046782, Since::PastFirstMiss),
    (-0.389304, -3.100377, 0.041120, Since::PastFirstMiss),
    (-0.749070, -3.913193, 0.046978, Since::PastFirstMiss),
    (-0.405532, -3.146082, 0.044646, Since::PastFirstMiss),
    (-0.432744, -3.043999, 0.049131, Since::PastFirstMiss),
];

/// At the points the k checks once refused ([`REFUSED`]) the tables answer, each answer within
/// 1e-5 of the exact search ([`checked_table_answer`]).
#[test]
fn where_the_k_checks_once_refused_the_tables_agree_with_the_search() {
    for since in [Since::Sextic, Since::FinerBins, Since::PastFirstMiss] {
        let points: Vec<_> = REFUSED.iter().filter(|p| p.3 == since).collect();
        let answered = points
            .iter()
            .filter(|&&&(x, y, k, _)| checked_table_answer(x, y, k).is_some())
            .count();
        // every one: a point that is declined again is a change of the checks to look at
        assert!(
            answered == points.len(),
            "{since:?}: answered {answered} of {}",
            points.len()
        );
    }
}

/// A fourteenth point the finer bins answer, (x, y, k) = (-0.244, -2.5279, 0.0387), lies 0.26 %
/// below the search limit of 1000 V_stick,JKR (F = 997.38): there the default search says
/// "no bouncing below v_max" (its verdict rests on the collision at v_max, integrated on the
/// coarsest rung of its tolerance ladder only, `search/bracket.rs`), while the same search with
/// a higher limit and the reference search (BDF at rtol 1e-11) both find F = 997.382. The
/// tables follow the reference search: F and F_on within 2e-6 of it, and a value, not the
/// default search's verdict.
#[test]
fn next_to_the_search_limit_the_tables_follow_the_reference_search() {
    let (x, y, k) = (-0.244, -2.5279, 0.0387);
    let (c, t_vis) = thresholds::master::build::synthetic(x, y, 1.0).unwrap();
    let law = CrackLaw::new(k).unwrap();
    let table = sticking_thresholds(&c, &law, t_vis, &SearchOptions::default()).unwrap();
    assert_eq!(table.method, ThresholdMethod::Table);
    let reference = SearchOptions {
        v_max: Some(2.0 * table.v_max),
        ..SearchOptions::reference()
    };
    let r = sticking_thresholds(&c, &law, t_vis, &reference).unwrap();
    for (t, r) in [
        (table.v_stick, r.v_stick),
        (table.v_double_onset, r.v_double_onset),
    ] {
        let (t, r) = (t.unwrap(), r.unwrap());
        assert!((t / r - 1.0).abs() < 2e-6, "table {t} vs reference {r}");
    }
    // below the default limit, by more than the tables' margin there
    assert!(r.v_stick.unwrap() < table.v_max * (1.0 - 2e-3));
}
