//! The tests of [`super`]: the fast cells against the table and the old whole-octave fill,
//! the table built from its nodes as they come, the build-time nodes.

use super::{
    BranchTable, CrackLaw, FAST_BITS, FAST_BLOCK, FAST_BLOCKS_PER_OCTAVE, FAST_BLOCK_BITS,
    FAST_MAX_EXP, FAST_MIN_EXP, J_NODES,
};
use crate::integrals::JIntegrals;
use crate::law::{Branch, CrackPoint};
use crate::quad::{j3_complement_log_term, node_alpha, node_count};

/// The fast representation reproduces the table it interpolates: |v| within 1e-9 relative
/// and d|v|/dr within 1e-5 (the table's own slope accuracy) over every octave it covers (cubic Hermite error, about
/// (cell width in zeta)^4 / 384 times the curvature), sampled off the cell edges; within
/// 1e-8 in the cells across the table's end nodes, where its slope jumps.
#[test]
fn fast_cells_reproduce_the_table() {
    for k in [0.005, 0.01, 0.3] {
        let law = CrackLaw::new(k).unwrap();
        let t = law.tables();
        for (table, fast) in [(&t.closing, &t.closing_fast), (&t.opening, &t.opening_fast)] {
            let (mut worst, mut worst_slope) = (0.0f64, 0.0f64);
            for e in FAST_MIN_EXP..FAST_MAX_EXP {
                for i in 0..(3 << FAST_BITS) {
                    let r = 2f64.powi(e) * (1.0 + (i as f64 + 0.37) / (3 << FAST_BITS) as f64);
                    let (f, df) = fast.eval(r, table).unwrap();
                    let (w, dw) = table.eval(r.ln());
                    let (g, dg) = (w.exp(), w.exp() * dw / r);
                    // the table's first and last nodes are kinks (linear extrapolation
                    // beyond them); a cell across one is held to the table's own 1e-8
                    let h = 2f64.powi(e - FAST_BITS as i32);
                    let ends = [table.zeta[0], table.zeta[table.zeta.len() - 1]];
                    let kink = ends.iter().any(|z| (z.exp() - r).abs() < h);
                    let err = (f / g - 1.0).abs();
                    assert!(err < 1e-8, "k = {k}, r = {r:e}: {err:e}");
                    if !kink {
                        worst = worst.max(err);
                    }
                    worst_slope = worst_slope.max(((df - dg) / dg).abs());
                }
            }
            assert!(worst < 1e-9, "k = {k}: {worst:e}");
            assert!(worst_slope < 1e-5, "k = {k}: slope {worst_slope:e}");
        }
        // outside the octaves covered, the table itself answers
        assert!(t
            .closing_fast
            .eval(2f64.powi(FAST_MAX_EXP), &t.closing)
            .is_none());
        assert!(t
            .closing_fast
            .eval(2f64.powi(FAST_MIN_EXP - 1), &t.closing)
            .is_none());
    }
}

/// The nodes of one branch in increasing alpha, as `Tables::new` once collected them.
fn nodes_in_increasing_alpha(k: f64, branch: Branch) -> Vec<(f64, f64)> {
    J_NODES
        .iter()
        .filter_map(|&[alpha, j3, m, k_log]| {
            let j = JIntegrals::from_parts(alpha, j3, m, k_log);
            let p = CrackPoint::from_integrals(k, &j, branch).ok()?;
            Some((p.zeta(), p.v.abs().ln()))
        })
        .collect()
}

/// `Tables::new` takes the nodes as they come (in decreasing alpha, already sorted by zeta)
/// and builds the very tables that sorting the nodes in increasing alpha builds, bit for bit,
/// on both branches and across k; on nodes that do not come sorted (ties, signed zeros, out of
/// order) `from_nodes` sorts them as `from_points` does.
#[test]
fn nodes_as_they_come_build_the_sorted_table() {
    // Debug prints each float's shortest round trip: equal text, equal bits
    let text = |t: &BranchTable| format!("{t:?}");
    for k in [0.005, 0.01, 0.02, 0.05, 0.3, 0.9] {
        let law = CrackLaw::new(k).unwrap();
        let t = law.tables();
        for (branch, built) in [(Branch::Closing, &t.closing), (Branch::Opening, &t.opening)] {
            let sorted = BranchTable::from_points(nodes_in_increasing_alpha(k, branch));
            assert_eq!(text(built), text(&sorted), "k = {k}, {branch:?}");
        }
    }
    // nodes given in decreasing alpha that are not sorted by zeta: a tie (two w), a signed
    // zero and a node out of order
    let zeta = [-3.0, -1.0, -0.0, 0.0, 2.0, 1.5, 4.0, 4.0, 5.0, 6.0, 7.0];
    let w: Vec<f64> = (0..zeta.len()).map(|i| 0.1 * i as f64 - 0.3).collect();
    let given = BranchTable::from_nodes(zeta.to_vec(), w.clone());
    let increasing_alpha: Vec<(f64, f64)> = zeta.into_iter().zip(w).rev().collect();
    assert_eq!(
        text(&given),
        text(&BranchTable::from_points(increasing_alpha))
    );
}

/// The cells filled eight at a time are the cells the whole octave's fill made before
/// (the edges of all 129 at once, then each cell from its two), bit for bit, in every
/// octave of both branches.
#[test]
fn blocks_hold_the_cells_of_the_whole_octave() {
    // the fill of one whole octave as it was (docs/performance.md, "The crack law of each k")
    fn octave(biased: i64, table: &BranchTable) -> Vec<[f64; 4]> {
        let n = 1usize << FAST_BITS;
        let base = f64::from_bits((biased as u64) << 52);
        let h = base / n as f64;
        let edges: Vec<(f64, f64)> = (0..=n)
            .map(|j| {
                let r = base + j as f64 * h;
                let (w, dw) = table.eval(r.ln());
                let f = w.exp();
                (f, f * dw / r * h)
            })
            .collect();
        edges
            .windows(2)
            .map(|e| {
                let ((f0, d0), (f1, d1)) = (e[0], e[1]);
                [
                    f0,
                    d0,
                    3.0 * (f1 - f0) - 2.0 * d0 - d1,
                    2.0 * (f0 - f1) + d0 + d1,
                ]
            })
            .collect()
    }
    let law = CrackLaw::new(0.01).unwrap();
    let t = law.tables();
    for (table, fast) in [(&t.closing, &t.closing_fast), (&t.opening, &t.opening_fast)] {
        for e in FAST_MIN_EXP..FAST_MAX_EXP {
            let biased = i64::from(e) + 1023;
            let whole = octave(biased, table);
            for (j, cell) in whole.iter().enumerate() {
                // r at the cell's left edge: its value is c0, and the cell is filled there
                let r = 2f64.powi(e) * (1.0 + j as f64 / (1 << FAST_BITS) as f64);
                let (f, _) = fast.eval(r, table).unwrap();
                assert_eq!(f.to_bits(), cell[0].to_bits(), "2^{e}, cell {j}");
                let b = j >> FAST_BLOCK_BITS;
                let octave = usize::try_from(e - FAST_MIN_EXP).unwrap();
                let blocks = &fast.blocks[octave * FAST_BLOCKS_PER_OCTAVE + b];
                let filled = blocks.get().unwrap()[j & (FAST_BLOCK - 1)];
                assert_eq!(
                    filled.map(f64::to_bits),
                    cell.map(f64::to_bits),
                    "2^{e}, {j}"
                );
            }
        }
    }
}

/// Outside the octaves covered (and for r that is not finite and positive) the fast cells
/// answer nothing, so that the table itself does.
#[test]
fn fast_cells_answer_only_inside_their_octaves() {
    let law = CrackLaw::new(0.01).unwrap();
    let t = law.tables();
    let (table, fast) = (&t.closing, &t.closing_fast);
    let outside = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        -1.0,
        f64::MIN_POSITIVE / 2.0,
        2f64.powi(FAST_MIN_EXP) * (1.0 - f64::EPSILON),
        2f64.powi(FAST_MAX_EXP),
        1e300,
    ];
    for r in outside {
        assert!(fast.eval(r, table).is_none(), "r = {r:e}");
    }
    for r in [
        2f64.powi(FAST_MIN_EXP),
        1.0,
        2f64.powi(FAST_MAX_EXP) * (1.0 - f64::EPSILON),
    ] {
        assert!(fast.eval(r, table).is_some(), "r = {r:e}");
    }
}

/// The build-time table holds exactly what the quadrature gives now. A guard of the build (the
/// build script runs the same `quad.rs`, so this holds by construction while both agree): the
/// integrals themselves are checked against Dawson's function, their identity and asymptotics
/// in `tests/`.
#[test]
fn build_time_nodes_equal_the_quadrature() {
    assert_eq!(J_NODES.len(), node_count());
    for i in (0..J_NODES.len()).step_by(97) {
        let alpha = node_alpha(i);
        let (j3, m, k) = j3_complement_log_term(alpha);
        assert_eq!(J_NODES[i], [alpha, j3, m, k], "node {i}");
    }
}
