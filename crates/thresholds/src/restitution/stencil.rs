//! The answer of one restitution table at a point: the four rows around y, the four nodes
//! around u = ln(x_s - x) on each, the channels around the impact speed's coordinate (local
//! cubics along each, then across), and the cell checks that vouch for it.

use super::format::{self, Table};
use super::{Side, CLIFF_MARGIN};
use crate::master::interp::{
    interval, lagrange, lagrange_weight, local_cubic, stencil_start, weights4,
};

/// Where an answer lies along a table's channels: the (at most) four channels around its
/// coordinate, as an offset into a node's h values, and their Lagrange weights. The same for
/// every node of the table, so found once an answer instead of once a node (sixteen nodes a
/// table: a fifth of an answer).
struct Channels {
    /// The first channel's index among a node's values (bouncing channels first).
    first: usize,
    /// How many channels (four, fewer only on a grid of fewer).
    len: usize,
    /// Their weights at the coordinate ([`lagrange`]'s).
    weights: [f64; 4],
}

impl Channels {
    /// The channels of `t` around `coord` (ln sigma + sigma or logit nu) on `side`; `None`
    /// outside the channels.
    fn around(t: &Table, side: Side, coord: f64) -> Option<Channels> {
        let (grid, offset) = match side {
            Side::Bouncing => (&t.sigma, 0),
            Side::Double => (&t.nu, t.sigma.len()),
        };
        if !(coord >= grid[0] && coord <= grid[grid.len() - 1]) {
            return None;
        }
        let s = stencil_start(interval(grid, coord), grid.len());
        let e = (s + 4).min(grid.len());
        let mut weights = [0.0; 4];
        if e - s == 4 {
            weights = weights4(&grid[s..e], coord);
        } else {
            for (j, w) in weights.iter_mut().enumerate().take(e - s) {
                *w = lagrange_weight(&grid[s..e], j, coord);
            }
        }
        Some(Channels {
            first: offset + s,
            len: e - s,
            weights,
        })
    }

    /// h of node `node` of `row` of `t` at the coordinate (the local cubic along the channels).
    fn h(&self, t: &Table, row: &format::Row, node: usize) -> Option<f64> {
        let at = node * (t.sigma.len() + t.nu.len()) + self.first;
        let v = row.h.get(at..at + self.len)?;
        if v.iter().any(|h| !h.is_finite()) {
            return None;
        }
        Some(v.iter().zip(&self.weights).map(|(h, w)| w * h).sum())
    }
}

/// Where one table's answer at `(x, y)` reads: the four rows around y (from `first_row`), on
/// each the four nodes around u = ln(x_s - x) (from `first_node`), and the channels around the
/// coordinate. Found for every table of an answer before any value is read, so that the
/// sixty-four nodes' values (scattered over 6 MB a table) are fetched together and not one
/// after the other.
pub(super) struct Stencil<'a> {
    table: &'a Table,
    first_row: usize,
    first_node: [usize; 4],
    u: [f64; 4],
    channels: Channels,
}

impl<'a> Stencil<'a> {
    /// The stencil of `t` at `(x, y)` on `side` at `coord`; `None` outside the rows or the
    /// channels, or (`checked`) where the cell holding x (and `k_checked`, its k cell) was not
    /// vouched for.
    pub(super) fn new(
        t: &'a Table,
        x: f64,
        y: f64,
        side: Side,
        coord: f64,
        checked: bool,
        k_checked: bool,
    ) -> Option<Self> {
        let n = t.rows.len();
        if n < 4 || !(y >= t.ys[1] && y <= t.ys[n - 2]) {
            return None;
        }
        let j = interval(&t.ys, y);
        if checked {
            // the cell of row j (to row j + 1) that holds x, at least the margin from the end
            // of both its rows (below the kink the end moves by up to 0.5 in x a row step)
            let r = &t.rows[j];
            if r.x_s.min(t.rows[j + 1].x_s) - x < CLIFF_MARGIN {
                return None;
            }
            let u = (r.x_s - x).ln().min(r.u[r.u.len() - 1]);
            if u.is_nan() || u < r.u[0] {
                return None;
            }
            let i = interval(&r.u, u);
            // bouncing needs its own channels vouched; a double collision every channel
            let (cells, kcells) = r.cells.side(side == Side::Bouncing);
            if !cells.get(i).copied().unwrap_or(false)
                || (k_checked && !kcells.get(i).copied().unwrap_or(false))
            {
                return None;
            }
        }
        let channels = Channels::around(t, side, coord)?;
        let first_row = stencil_start(j, n);
        let (mut first_node, mut us) = ([0; 4], [0.0; 4]);
        for (q, r) in t.rows[first_row..first_row + 4].iter().enumerate() {
            let u = (r.x_s - x).ln().min(r.u[r.u.len() - 1]);
            if u.is_nan() || u < r.u[0] || r.u.len() < 4 {
                return None;
            }
            first_node[q] = stencil_start(interval(&r.u, u), r.u.len());
            us[q] = u;
        }
        Some(Stencil {
            table: t,
            first_row,
            first_node,
            u: us,
            channels,
        })
    }

    /// Reads the first and the last of the channels' values of each of the sixteen nodes and
    /// returns their sum: called for every table of an answer before [`Stencil::h`], it sends
    /// the sixty-four nodes' cache misses out together (a prefetch without `unsafe`). Random
    /// collisions between tables: 3.6 -> 2.6 us an answer (`examples/restitution_accuracy.rs`),
    /// 5.3 -> 4.2 us with the stencils found first but no prefetch.
    pub(super) fn prefetch(&self) -> f64 {
        let t = self.table;
        let per = t.sigma.len() + t.nu.len();
        let mut sum = 0.0;
        for (q, r) in t.rows[self.first_row..self.first_row + 4]
            .iter()
            .enumerate()
        {
            for node in self.first_node[q]..self.first_node[q] + 4 {
                let at = node * per + self.channels.first;
                sum += r.h.get(at).copied().unwrap_or(0.0);
                sum += r.h.get(at + self.channels.len - 1).copied().unwrap_or(0.0);
            }
        }
        sum
    }

    /// h at the stencil's point: the local cubic along the channels at each node, along each
    /// row, across the rows.
    pub(super) fn h(&self, y: f64) -> Option<f64> {
        let t = self.table;
        let rows = &t.rows[self.first_row..self.first_row + 4];
        let mut across = [0.0; 4];
        for (q, r) in rows.iter().enumerate() {
            let a = self.first_node[q];
            let mut along = [0.0; 4];
            for (p, node) in (a..a + 4).enumerate() {
                along[p] = self.channels.h(t, r, node)?;
            }
            across[q] = local_cubic(&r.u[a..a + 4], &along, self.u[q]);
        }
        let h = lagrange(&t.ys[self.first_row..self.first_row + 4], &across, y);
        h.is_finite().then_some(h)
    }
}
