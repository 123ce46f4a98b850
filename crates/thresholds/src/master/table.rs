//! One k's table: a ratio at a point, where the table vouches for it.
//!
//! Each row of constant y holds two pieces ([`binary::Piece`]): the *body* (x below x_s, F and
//! F_on, interpolated in u = ln(x_s - x)) and the *strip* (x between x_s and x_on, F_on only, in
//! w = ln(x_on - x)). Each row is interpolated by the local cubic in its own coordinate, then
//! the four rows around y by the cubic in y, in one of two ways:
//!
//! - *plain*: every row at the query's x ([`Table::g_plain`]): no end curve needed; good where
//!   the ratios are smooth in x and y, far from the cliff (and all the way to x_s where F rises
//!   as a power of c_D instead of diverging);
//! - *sheared*: every row at the query's distance to its own end, u ([`Table::g_at`]): near the
//!   cliff, where F is steep in x but smooth in u; it needs the end at the query's y.
//!
//! Each is vouched for where every row and the cell between the two middle rows were checked:
//! plain up to an x, sheared down to a distance to the end.

use super::binary::{self, Piece, Table};
use super::format::{F_TOP, LOWER_BOUND_OFFSET};
use super::interp::{
    interval, intervals4, lagrange, local_cubic, local_cubic_both, stencil_start, weights4,
};

/// Which piece of the rows, and which ratio.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Curve {
    /// F = V_stick / V_stick,JKR on the body (u = ln(x_s - x)).
    Stick,
    /// F_on = V_double_onset / V_stick,JKR on the body (u = ln(x_s - x)).
    OnsetBody,
    /// F_on on the strip (w = ln(x_on - x)).
    OnsetStrip,
}

impl Curve {
    /// The piece's ratio index (0: F, 1: F_on) and the index of its sheared limit in a cell.
    fn indices(self) -> (usize, usize) {
        match self {
            Curve::Stick => (0, 2),
            Curve::OnsetBody => (1, 3),
            Curve::OnsetStrip => (1, 4),
        }
    }

    fn piece(self, row: &binary::Row) -> &Piece {
        match self {
            Curve::OnsetStrip => &row.strip,
            _ => &row.body,
        }
    }
}

/// The body's coordinate u = ln(x_s - x) of `row` at `x`, far from the end the row's first
/// node's (where plain interpolation takes the value there); `None` at or beyond x_s.
fn plain_u(row: &binary::Row, x: f64) -> Option<f64> {
    let far = *row.body.u.last()?;
    let u = (row.x_s - x).ln().min(far);
    u.is_finite().then_some(u)
}

/// The four rows around a y and their cell: what every question to a table at that y starts
/// from, found once an answer ([`Table::rows_at`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct RowsAt {
    /// The first of the four rows.
    s: usize,
    /// The cell (between rows `j` and `j + 1`) that holds y.
    j: usize,
}

impl Table {
    /// The four rows around `y` (the first index, shifted inward in the two end cells, as the
    /// build checked them), with their cell; `None` outside the rows or with fewer than four.
    pub(crate) fn rows_at(&self, y: f64) -> Option<RowsAt> {
        let n = self.rows.len();
        if n < 4 || !(y >= self.ys[0] && y <= self.ys[n - 1]) {
            return None;
        }
        // the bin's cell (no search), checked; a search where the rows are off the bins' grid
        let bin = ((y - self.ys[0]) * binary::Y_BINS) as usize;
        let j = match self.y_bins.get(bin) {
            Some(&j) if self.ys[j as usize] <= y && y <= self.ys[j as usize + 1] => j as usize,
            _ => interval(&self.ys, y),
        };
        Some(RowsAt {
            s: stencil_start(j, n),
            j,
        })
    }

    /// The smallest u at which `curve` is vouched for at `y` (the largest of the rows' and the
    /// cell's limits), and the largest u the rows hold (their first node, far from the end).
    pub fn vouched(&self, curve: Curve, y: f64) -> Option<(f64, f64)> {
        self.vouched_in(self.rows_at(y)?, curve)
    }

    /// [`Table::vouched`] on the rows found.
    pub(crate) fn vouched_in(&self, at: RowsAt, curve: Curve) -> Option<(f64, f64)> {
        let RowsAt { s, j } = at;
        let (v, c) = curve.indices();
        let mut lo = self.cells[j][c];
        let mut hi = f64::INFINITY;
        for row in &self.rows[s..s + 4] {
            let p = curve.piece(row);
            if p.u.len() < 2 {
                return None;
            }
            lo = lo.max(p.u_lo[v]);
            hi = hi.min(p.u[p.u.len() - 1]);
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// The smallest u at which `curve` on the rows found is a lower bound of the ratio (the
    /// largest of the rows' and the cell's `u_lb`: checked against the exact nodes, not against
    /// the default search; [`super::format::PieceData::d_lb`]); at most their `u_lo`.
    pub(crate) fn bound_in(&self, at: RowsAt, curve: Curve) -> f64 {
        let RowsAt { s, j } = at;
        let (v, c) = curve.indices();
        self.rows[s..s + 4]
            .iter()
            .map(|row| curve.piece(row).u_lb[v])
            .fold(self.cells[j][c + LOWER_BOUND_OFFSET], f64::max)
    }

    /// `g = ln(ratio - 1)` of `curve` at `y` and `u` (the log of the distance to the curve's end),
    /// interpolated without asking whether it is vouched for.
    pub fn g_at(&self, curve: Curve, y: f64, u: f64) -> Option<f64> {
        self.g_at_in(self.rows_at(y)?, curve, y, u)
    }

    /// [`Table::g_at`] on the rows found.
    pub(crate) fn g_at_in(&self, at: RowsAt, curve: Curve, y: f64, u: f64) -> Option<f64> {
        let s = at.s;
        let (v, _) = curve.indices();
        let mut g = [0.0; 4];
        for (q, row) in self.rows[s..s + 4].iter().enumerate() {
            let p = curve.piece(row);
            g[q] = local_cubic(&p.u, &p.g[v], u);
        }
        let g = lagrange(&self.ys[s..s + 4], &g, y);
        g.is_finite().then_some(g)
    }

    /// The largest x up to which the body's ratio of `curve` interpolated in plain x at `y` is
    /// vouched for (every row vouched for at that x, and the cell checked up to it).
    pub fn plain_limit(&self, curve: Curve, y: f64) -> Option<f64> {
        self.plain_limit_in(self.rows_at(y)?, curve)
    }

    /// [`Table::plain_limit`] on the rows found.
    pub(crate) fn plain_limit_in(&self, at: RowsAt, curve: Curve) -> Option<f64> {
        let RowsAt { s, j } = at;
        let (v, _) = curve.indices();
        if curve == Curve::OnsetStrip {
            return None;
        }
        let mut hi = self.cells[j][v];
        for row in &self.rows[s..s + 4] {
            if row.body.u.len() < 2 {
                return None;
            }
            hi = hi.min(row.body.x_hi[v]);
        }
        hi.is_finite().then_some(hi)
    }

    /// `g = ln(ratio - 1)` of the body's `curve` at `y` and `x`, every row at that x (far from
    /// the end: beyond the rows' first node, the value there), without asking whether it is
    /// vouched for.
    pub fn g_plain(&self, curve: Curve, y: f64, x: f64) -> Option<f64> {
        let s = self.rows_at(y)?.s;
        let (v, _) = curve.indices();
        let mut g = [0.0; 4];
        for (q, row) in self.rows[s..s + 4].iter().enumerate() {
            let u = plain_u(row, x)?;
            g[q] = local_cubic(&row.body.u, &row.body.g[v], u);
        }
        let g = lagrange(&self.ys[s..s + 4], &g, y);
        g.is_finite().then_some(g)
    }

    /// [`Table::g_plain`] of F and F_on together (one search along each row): `[g F, g F_on]`.
    pub fn g_plain_both(&self, y: f64, x: f64) -> Option<[f64; 2]> {
        self.g_plain_both_in(self.rows_at(y)?, y, x)
    }

    /// [`Table::g_plain_both`] on the rows found.
    pub(crate) fn g_plain_both_in(&self, at: RowsAt, y: f64, x: f64) -> Option<[f64; 2]> {
        let s = at.s;
        let rows = &self.rows[s..s + 4];
        let mut u = [0.0; 4];
        for (u, row) in u.iter_mut().zip(rows) {
            *u = plain_u(row, x)?;
        }
        // the four rows' intervals found together (their nodes lie far apart in memory)
        let found = intervals4(std::array::from_fn(|q| &rows[q].body.u[..]), u);
        let mut g = [[0.0; 4]; 2];
        for (q, row) in rows.iter().enumerate() {
            let p = &row.body;
            let [a, b] = local_cubic_both(&p.u, [&p.g[0], &p.g[1]], u[q], found[q]);
            (g[0][q], g[1][q]) = (a, b);
        }
        // the weights of the four rows at y once for both ratios (lagrange's sum, term for term)
        let w = weights4(&self.ys[s..s + 4], y);
        let at_y = |g: &[f64; 4]| w[0] * g[0] + w[1] * g[1] + w[2] * g[2] + w[3] * g[3];
        let both = [at_y(&g[0]), at_y(&g[1])];
        both.iter().all(|g| g.is_finite()).then_some(both)
    }

    /// Whether every row of the stencil at `y` has ratios that increase towards the end (and
    /// was found without bouncing beyond it up to [`super::F_TOP`]).
    pub fn monotone(&self, y: f64) -> bool {
        self.rows_at(y).is_some_and(|at| self.monotone_in(at))
    }

    /// [`Table::monotone`] on the rows found.
    pub(crate) fn monotone_in(&self, at: RowsAt) -> bool {
        self.rows[at.s..at.s + 4].iter().all(|r| r.monotone)
    }

    /// Of the rows found: the ratio up to which all of them increase towards their ends
    /// ([`super::binary::Row::mono`]) and the ratio below which nothing bounces beyond their ends
    /// ([`super::binary::Row::beyond`]).
    pub(crate) fn levels_in(&self, at: RowsAt) -> Levels {
        self.rows[at.s..at.s + 4]
            .iter()
            .fold(Levels::UNBOUNDED, |l, r| Levels {
                mono: l.mono.min(r.mono),
                beyond: l.beyond.min(r.beyond),
            })
    }
}

/// What rows promise towards and beyond their ends, as ratios (see [`Table::levels_in`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Levels {
    /// The ratios increase towards the ends up to this ratio.
    pub mono: f64,
    /// Nothing bounces (double-collides) beyond the ends below this ratio.
    pub beyond: f64,
}

impl Levels {
    /// Rows that increase throughout with nothing below [`F_TOP`] beyond their ends.
    pub const UNBOUNDED: Levels = Levels {
        mono: f64::INFINITY,
        beyond: F_TOP,
    };

    /// The lower of each.
    pub fn min(self, o: Levels) -> Levels {
        Levels {
            mono: self.mono.min(o.mono),
            beyond: self.beyond.min(o.beyond),
        }
    }
}
