//! Tests of [`super`]: the short way far inside the plain region against the full answer.

use super::*;

/// A uniform number in [0, 1) from a 64-bit LCG (Knuth's constants).
fn uniform(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// Far inside the region vouched in plain x the answer without the end curves
/// ([`MasterTables::plain_inside`]) is the full answer's, bit for bit: 4e4 random points of
/// the tables' domain (x from -17 to 3, y from -6 to 5.5, k log-uniform over the tables' range
/// and at the tables' own k, f_max from 2 to 2e4), a third of them taking the short way.
#[test]
fn far_inside_the_plain_region_the_answer_needs_no_ends() {
    let t = MasterTables::standard();
    let (k0, k1) = t.k_range();
    let mut state = 7;
    let (mut inside, n) = (0, 40_000);
    for i in 0..n {
        let x = -17.0 + 20.0 * uniform(&mut state);
        let y = -6.0 + 11.5 * uniform(&mut state);
        let k = if i % 4 == 0 {
            t.table_k()[i / 4 % t.table_k().len()]
        } else {
            k0 * (k1 / k0).powf(uniform(&mut state))
        };
        let f_max = 2.0 * 1e4f64.powf(uniform(&mut state));
        let Some(ks) = t.k_stencil(k, y) else {
            continue;
        };
        let (stick, onset) = t.sides_with_ends(&ks, x, y, k, f_max);
        let full = both(stick, onset);
        // a stencil of its own: nothing kept from the full answer's evaluation
        let fresh = t.k_stencil(k, y).expect("as above");
        if let Some(short) = t.plain_inside(&fresh, x, y, f_max) {
            inside += 1;
            assert_eq!(
                Some(short),
                full,
                "x = {x}, y = {y}, k = {k}, f_max = {f_max}"
            );
        }
        assert_eq!(t.interpolate(x, y, k, f_max), full);
    }
    assert!(inside * 3 >= n, "{inside} of {n} inside");
}

/// The strips between x_s and x_on are narrow on the whole grid of the end curves (at most
/// 0.003 in x), so that [`PLAIN_INSIDE`] keeps a point far inside the plain region more than
/// half a strip below x_s, where the full answer reads F_on on the body.
#[test]
fn the_strips_are_narrow() {
    let ends = MasterTables::standard().ends().expect("embedded");
    let d = ends.data();
    let widest = d
        .x_s
        .iter()
        .zip(d.x_on.iter())
        .map(|(s, o)| o - s)
        .filter(|w| w.is_finite())
        .fold(0.0, f64::max);
    assert!(widest < 0.004 && 0.5 * widest < PLAIN_INSIDE, "{widest}");
}
