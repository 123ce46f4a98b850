//! The last verdict where the interpolation declines: "nothing below v_max" from the nodes
//! alone, a floor under F and F_on that holds across the kink where the two kinds of bouncing
//! meet (`docs/model.md`, "The two kinds of bouncing").
//!
//! Next to the kink F = min(F1, F2) of two smooth thresholds, and no polynomial through nodes
//! on both sides of the crossing is within 1e-5 there (`docs/performance.md`, "What is left").
//! But a lower bound needs no polynomial, only that each kind of bouncing be monotone in each
//! coordinate between neighbouring nodes: then the least of min(F1, F2) over an interval lies at
//! one of its ends. At a query (x, y, k):
//! 1. **k.** The smaller of the floors of the two tables around k (at a table's own k, its
//!    floor). At a fixed (x, y) both ratios fall as k grows on every committed row sampled
//!    (y = -5.5 to -3.5: more hysteresis, more dissipated), so the floor is mostly that of
//!    the table above;
//! 2. **y.** In each of those tables, the smaller of the floors of its two rows around y (1/16
//!    to 1/2 apart);
//! 3. **x.** On a row, the least of its nodes from the last node at or below x to the row's
//!    end (each kind of bouncing climbs towards the cliff; the least node, not the nearest,
//!    because a row falls where the second kind takes over); past the row's end, the row's
//!    `beyond` level (what the build checked for no bouncing beyond the ends).
//!
//! The floor answers only "nothing below v_max" (it says no value), where it exceeds f_max by
//! [`BOUND_MARGIN`] (the nodes are reference searches; the default search strays from them by
//! up to 1.4e-4 near the cliff). The monotony is not proven but checked: at 2000 random points
//! (around the kink and over the whole domain) the floor lies below the reference search, and
//! where the interpolation declines its verdicts are the default search's
//! (`tests/master_floor.rs`; `examples/node_floor.rs` for the full count).

use super::answer::SAME_K;
use super::binary::{Piece, Row, Table};
use super::verdict::{side, Eval, Side, BOUND_MARGIN};
use super::MasterTables;

/// `g = ln(ratio - 1)` of the least node of `piece` (ratio `v`: 0 F, 1 F_on) from the last node
/// at or below `x` to the piece's `end`; `None` where `x` lies below every node.
fn piece_floor(piece: &Piece, v: usize, end: f64, x: f64) -> Option<f64> {
    // nodes in decreasing x (increasing u = ln(end - x)): those at or below x have u >= u_x
    let u_x = (end - x).ln();
    let last = piece.u.iter().position(|&u| u >= u_x)?;
    piece.g[v][..=last]
        .iter()
        .copied()
        .filter(|g| g.is_finite())
        .reduce(f64::min)
}

/// The floor of ratio `v` (0: F, 1: F_on) on row `r` at `x`, as `g = ln(ratio - 1)`.
fn row_floor(r: &Row, v: usize, x: f64) -> Option<f64> {
    let end = if v == 0 { r.x_s } else { r.x_on };
    if x >= end {
        // past the end: nothing below the level the build checked (0 where it did not)
        return (r.beyond > 1.0).then(|| (r.beyond - 1.0).ln());
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
    /// there (y outside the rows, x below their nodes).
    pub fn node_floor(&self, x: f64, y: f64) -> [Option<f64>; 2] {
        let Some(j) = self.ys.windows(2).position(|w| w[0] <= y && y <= w[1]) else {
            return [None, None];
        };
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
        // within rounding, SAME_K)
        let same = |t: f64| (k - t).abs() < SAME_K * t;
        let below = ks.iter().rposition(|&t| t <= k || same(t));
        let above = ks.iter().position(|&t| t >= k || same(t));
        let floor = |i: Option<usize>| match i.and_then(|i| self.table(i)) {
            Some(t) => t.node_floor(x, y),
            None => [None, None],
        };
        let (a, b) = (floor(below), floor(above));
        [0, 1].map(|v| Some(1.0 + a[v]?.min(b[v]?).exp()))
    }

    /// "Nothing below the search limit" for both ratios at (x, y, k), where both floors
    /// ([`MasterTables::node_floor`]) exceed `f_max` by [`BOUND_MARGIN`].
    pub(super) fn node_verdict(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<()> {
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
        (above(f) && above(f_on)).then_some(())
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

    /// On a row: the least node from the last one at or below x to the end (a row that falls
    /// towards its end counts its fall), the checked level past the end, nothing below the
    /// first node or past an unchecked end; between two rows, the smaller.
    #[test]
    fn the_least_node_towards_the_end_and_the_smaller_row() {
        let r = row(0.0, [10.0, 30.0, 20.0, 100.0], 9990.0);
        let at = |x: f64| ratio(row_floor(&r, 0, x)).map(|f| (f * 1e9).round() / 1e9);
        assert_eq!(at(-0.5), Some(10.0));
        assert_eq!(at(0.2), Some(20.0)); // node 30 at x = 0, but 20 at x = 0.5 nearer the end
        assert_eq!(at(0.7), Some(20.0));
        assert_eq!(at(0.95), Some(100.0));
        assert_eq!(at(1.5), Some(9990.0));
        assert_eq!(at(-2.0), None);
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
        assert!((f.unwrap() - 20.0).abs() < 1e-9 && (f_on.unwrap() - 20.0).abs() < 1e-9);
        assert!((ratio(t.node_floor(0.6, 0.4)[0]).unwrap() - 20.0).abs() < 1e-9);
        assert!((ratio(t.node_floor(-0.5, 0.1)[0]).unwrap() - 5.0).abs() < 1e-9);
        assert_eq!(t.node_floor(0.2, 0.6), [None, None]);
    }
}
