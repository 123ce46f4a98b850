//! The last verdict where the interpolation declines: "nothing below v_max" from the nodes
//! alone, a floor under F and F_on that holds across the kink where the two kinds of bouncing
//! meet (`docs/model.md`, "The cliff" and "How they answer").
//!
//! Next to the kink F = min(F1, F2) of two smooth thresholds, and no polynomial through nodes
//! on both sides of the crossing is within 1e-5 there (`docs/performance.md`, "What is left").
//! But a lower bound needs no polynomial, only that each kind of bouncing be monotone between
//! neighbouring nodes in y and k, and in x monotone or U-shaped: then the least of min(F1, F2)
//! over an interval lies at one of its ends or at the U's dip. At a query (x, y, k):
//! 1. **k.** The smaller of the floors of the two tables around k (at a table's own k, its
//!    floor). At a fixed (x, y) both ratios fall as k grows on every committed row sampled
//!    (y = -5.5 to -3.5: more hysteresis, more dissipated), so the floor is mostly that of
//!    the table above;
//! 2. **y.** In each of those tables, the smaller of the floors of its two rows around y (1/64
//!    to 1/2 apart);
//! 3. **x.** On a row, the least from the last node at or below x to the row's end: the first
//!    kind climbs towards its cliff, the second falls where it takes over and then climbs (a
//!    U: at a node below both neighbours, the dip of the parabola through the three counts,
//!    up to 0.41 % below the node on the committed rows); past the row's end, the row's
//!    `beyond` level (what the build checked for no bouncing beyond the ends).
//!
//! The floor answers only "nothing below v_max" (it says no value), where the interpolation
//! puts neither ratio below the limit, both floors exceed f_max by [`BOUND_MARGIN`] (the nodes
//! are reference searches; the default search strays from them near the cliff), and f_max is
//! at most [`FLOOR_F_MAX`]. That is next to the kink, and in the band at the cliff where the
//! default search strays from the nodes and the interpolation declines. The monotony is not
//! proven but checked: at 2574 random points (around the kink and over the whole domain, 1688
//! of them with floors read off nodes; `examples/node_floor.rs`) the floor lies below the
//! reference search, and its verdicts are the exact search's at the 14 points of 2e4 of the
//! whole domain it answers and at 590 points of the band at the cliff (`tests/master_floor.rs`,
//! `tests/master_bounds.rs`).

use super::binary::{Piece, Row, Table};
use super::format::F_TOP;
use super::interp::interval;
use super::verdict::{side, Eval, Side, BOUND_MARGIN};
use super::MasterTables;
use crate::k_axis::same_k;

/// The floor answers for search limits up to this ratio (f_max = v_max / V_stick,JKR): the
/// range over which its verdicts were checked against the default search (100-3000,
/// `tests/master_bounds.rs`; the default limit is 1000). Beyond the cliff, near F_TOP, the
/// default search finds spurious bouncing now and then (F = 8256 and 9607 where the reference
/// search finds none up to 2e4), so a floor there could disagree with it.
pub const FLOOR_F_MAX: f64 = 3000.0;

/// The least ratio of a row's second kind between its nodes: at a node below both neighbours
/// (the second kind is U-shaped in x: it falls where it takes over, then climbs towards the
/// cliff), the vertex of the parabola through the three nodes, else the node's ratio. On the
/// committed rows (315 with a minimum rising by more than 1e-6 to both sides) the vertex lies
/// up to 0.41 % below the node (k = 0.005, y = -5.6875, x = -0.346), more than 0.1 % at 2.
fn least_near(x: [f64; 3], r: [f64; 3]) -> f64 {
    if !(r[1] <= r[0] && r[1] <= r[2]) {
        return r[1];
    }
    // p(s) = r1 + b s + a s^2 with s = x - x1, through the three nodes
    let (s0, s2) = (x[0] - x[1], x[2] - x[1]);
    let (d0, d2) = ((r[0] - r[1]) / s0, (r[2] - r[1]) / s2);
    let a = (d2 - d0) / (s2 - s0);
    let b = d2 - a * s2;
    if a > 0.0 {
        r[1].min(r[1] - b * b / (4.0 * a))
    } else {
        r[1]
    }
}

/// `g = ln(ratio - 1)` of the least of `piece` (ratio `v`: 0 F, 1 F_on) from the last node at
/// or below `x` to the piece's `end` (each node, or the vertex of a minimum: [`least_near`]);
/// `None` where `x` lies below every node or a node has no ratio.
fn piece_floor(piece: &Piece, v: usize, end: f64, x: f64) -> Option<f64> {
    let u_x = (end - x).ln();
    // nodes in decreasing x (increasing u = ln(end - x)): those at or below x have u >= u_x
    let (u, g) = (&piece.u, &piece.g[v]);
    let last = u.partition_point(|&u| u < u_x);
    if last >= u.len() || !g.iter().all(|g| g.is_finite()) {
        return None;
    }
    let node = |q: usize| (end - u[q].exp(), 1.0 + g[q].exp());
    let least = (0..=last)
        .map(|q| match (q.checked_sub(1), q + 1 < u.len()) {
            (Some(p), true) => {
                let ((x0, r0), (x1, r1), (x2, r2)) = (node(p), node(q), node(q + 1));
                least_near([x0, x1, x2], [r0, r1, r2])
            }
            _ => node(q).1,
        })
        .fold(f64::INFINITY, f64::min);
    (least > 1.0).then(|| (least - 1.0).ln())
}

/// The floor of ratio `v` (0: F, 1: F_on) on row `r` at `x`, as `g = ln(ratio - 1)`.
fn row_floor(r: &Row, v: usize, x: f64) -> Option<f64> {
    let end = if v == 0 { r.x_s } else { r.x_on };
    if x >= end {
        // past the end: nothing below the level the build checked (0 where it did not), at
        // most F_TOP
        let level = r.beyond.min(F_TOP);
        return (level > 1.0).then(|| (level - 1.0).ln());
    }
    if x >= r.x_s {
        // F_on between x_s and x_on: the strip's nodes (none where the strip is too narrow)
        return piece_floor(&r.strip, 1, r.x_on, x);
    }
    piece_floor(&r.body, v, r.x_s, x)
}

impl Table {
    /// Lower bounds `[g F, g F_on]` (g = ln(ratio - 1)) at (x, y) from the nodes of the two rows
    /// around y (steps 2 and 3 of [`super::floor`]); `None` for a ratio the rows cannot bound
    /// there (y outside the rows, x below their nodes or not finite).
    pub fn node_floor(&self, x: f64, y: f64) -> [Option<f64>; 2] {
        let n = self.ys.len();
        if n < 2 || !x.is_finite() || !(y >= self.ys[0] && y <= self.ys[n - 1]) {
            return [None, None];
        }
        let j = interval(&self.ys, y);
        let (a, b) = (&self.rows[j], &self.rows[j + 1]);
        [0, 1].map(|v| Some(row_floor(a, v, x)?.min(row_floor(b, v, x)?)))
    }
}

impl MasterTables {
    /// Lower bounds `[F, F_on]` at x = log10 c_D, y = log10(c_D c_a) and k from the nodes of the
    /// tables around k (step 1 of [`super::floor`]); `None` for a ratio they cannot
    /// bound (k outside the tables, y outside their rows, x below their nodes).
    pub fn node_floor(&self, x: f64, y: f64, k: f64) -> [Option<f64>; 2] {
        let ks = self.table_k();
        // the last table at or below k and the first at or above (one table at its own k, to
        // within rounding, `k_axis::SAME_K`)
        let below = ks.iter().rposition(|&t| t <= k || same_k(k, t));
        let above = ks.iter().position(|&t| t >= k || same_k(k, t));
        let floor = |i: Option<usize>| match i.and_then(|i| self.table(i)) {
            Some(t) => t.node_floor(x, y),
            None => [None, None],
        };
        let (a, b) = (floor(below), floor(above));
        [0, 1].map(|v| Some(1.0 + a[v]?.min(b[v]?).exp()))
    }

    /// "Nothing below the search limit" for both ratios at (x, y, k): whether both floors
    /// ([`MasterTables::node_floor`]) exceed `f_max` (> 0) by [`BOUND_MARGIN`].
    pub(super) fn node_verdict(&self, x: f64, y: f64, k: f64, f_max: f64) -> bool {
        if !(f_max > 0.0 && f_max <= FLOOR_F_MAX) {
            return false;
        }
        let above = |floor: Option<f64>| {
            floor.is_some_and(|r| {
                let at_least = Eval::AtLeast {
                    g: (r - 1.0).ln(),
                    margin: BOUND_MARGIN,
                };
                side(at_least, f_max) == Side::Above
            })
        };
        let [f, f_on] = self.node_floor(x, y, k);
        above(f) && above(f_on)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row ending at x_s = 1 (x_on = 1.002) with body nodes at x = -1, 0, 0.5, 0.9 and F =
    /// F_on = `f` there, nothing bouncing beyond the ends below `beyond`.
    fn row(y: f64, f: [f64; 4], beyond: f64) -> Row {
        let (x_s, xs): (f64, [f64; 4]) = (1.0, [-1.0, 0.0, 0.5, 0.9]);
        // nodes in decreasing x: u = ln(x_s - x) increasing
        let u: Vec<f64> = xs.iter().rev().map(|x| (x_s - x).ln()).collect();
        let g: Vec<f64> = f.iter().rev().map(|f| (f - 1.0).ln()).collect();
        Row {
            y,
            x_s,
            x_on: 1.002,
            monotone: false,
            mono: 20.0,
            beyond,
            body: Piece {
                u: u.into(),
                g: [g.clone().into(), g.into()],
                ..Piece::default()
            },
            strip: Piece::default(),
        }
    }

    fn ratio(g: Option<f64>) -> Option<f64> {
        g.map(|g| 1.0 + g.exp())
    }

    /// The least of the parabola through (0, 30), (0.5, 20), (0.9, 25), found on a fine grid
    /// of its Lagrange form (not from its vertex): 19.9738...
    fn dip() -> f64 {
        let (x, r) = ([0.0, 0.5, 0.9], [30.0, 20.0, 25.0]);
        let p = |t: f64| {
            (0..3)
                .map(|i| {
                    let w: f64 = (0..3)
                        .filter(|&j| j != i)
                        .map(|j| (t - x[j]) / (x[i] - x[j]))
                        .product();
                    w * r[i]
                })
                .sum::<f64>()
        };
        (0..=90_000)
            .map(|i| p(i as f64 * 1e-5))
            .fold(f64::INFINITY, f64::min)
    }

    /// On a row: the least from the last node at or below x to the end, the dip of the
    /// second kind's U between nodes included; the checked level past the end; nothing below
    /// the first node or past an unchecked end; between two rows, the smaller.
    #[test]
    fn the_least_towards_the_end_and_the_smaller_row() {
        let r = row(0.0, [10.0, 30.0, 20.0, 25.0], 9990.0);
        let at = |x: f64| ratio(row_floor(&r, 0, x)).unwrap();
        let dip = dip();
        assert!(dip < 20.0 - 0.02, "{dip}");
        assert!((at(-0.5) - 10.0).abs() < 1e-9);
        assert!((at(0.2) - dip).abs() < 1e-6, "{} vs {dip}", at(0.2));
        assert!((at(0.7) - dip).abs() < 1e-6);
        assert!((at(0.95) - 25.0).abs() < 1e-9);
        assert!((at(1.5) - 9990.0).abs() < 1e-6);
        assert_eq!(row_floor(&r, 0, -2.0), None);
        assert_eq!(row_floor(&row(0.0, [10.0; 4], 0.0), 0, 1.5), None);
        // F_on between x_s and x_on: the strip, empty here
        assert_eq!(row_floor(&r, 1, 1.001), None);
        let t = Table {
            k: 0.01,
            ys: vec![0.0, 0.5],
            rows: vec![r.clone(), row(0.5, [5.0, 50.0, 60.0, 70.0], 9990.0)],
            cells: Vec::new(),
            y_bins: Vec::new(),
        };
        let [f, f_on] = t.node_floor(0.2, 0.25).map(ratio);
        assert!((f.unwrap() - dip).abs() < 1e-6 && (f_on.unwrap() - dip).abs() < 1e-6);
        assert!((ratio(t.node_floor(-0.5, 0.1)[0]).unwrap() - 5.0).abs() < 1e-9);
        assert_eq!(t.node_floor(0.2, 0.6), [None, None]);
        assert_eq!(t.node_floor(f64::NAN, 0.25), [None, None]);
    }

    /// The tables around k: at a table's own k (to within [`crate::k_axis::SAME_K`]) that
    /// table's floor alone; between two tables the smaller of theirs; nothing outside the
    /// tables' k.
    #[test]
    fn the_tables_around_k() {
        let t = MasterTables::standard();
        let ks = t.table_k().to_vec();
        let (x, y) = (-0.42, -4.1266);
        let own = |i: usize| t.table(i).unwrap().node_floor(x, y).map(ratio);
        for i in [3, 9] {
            for k in [ks[i], ks[i] * (1.0 + 1e-13), ks[i] * (1.0 - 1e-13)] {
                assert_eq!(t.node_floor(x, y, k), own(i), "k = {k}");
            }
        }
        let between = t.node_floor(x, y, (ks[9] * ks[10]).sqrt());
        let (a, b) = (own(9), own(10));
        for v in 0..2 {
            assert_eq!(between[v], Some(a[v].unwrap().min(b[v].unwrap())));
        }
        assert_eq!(t.node_floor(x, y, 0.004), [None, None]);
        assert_eq!(t.node_floor(x, y, 0.06), [None, None]);
    }
}
