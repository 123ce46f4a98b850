//! The tables' answer at a point: both ratios, or "beyond the search limit", or nothing where
//! the tables cannot vouch (the caller then searches).
//!
//! For a query (x, y, k) and the search limit f_max = v_max / V_stick,JKR:
//! 1. the end curves give x_s and x_on at (y, k) ([`super::ends`]); next to the kink where the
//!    cliff changes regime, where they are not interpolated, only upper bounds of them, which
//!    tell "beyond the end" (step 2) and nothing else;
//! 2. F: for x >= x_s it exceeds [`F_TOP`](super::format::F_TOP); else each table of the k
//!    stencil (the table of k itself, or the [`K_STENCIL`] tables around it in ln k,
//!    [`K_STENCIL_EDGE`] in the end intervals) gives g = ln(F - 1) at (y, u = ln(x_s - x))
//!    where vouched, and the polynomial in ln k through them (quintic; sextic in the end
//!    intervals) combines them; closer to x_s than vouched, F is at least its value at the
//!    closest vouched distance (the rows' ratios increase towards the end), or, where the
//!    table was checked against its exact nodes closer still (its `d_lb`: there the default
//!    search strays from them by more than the tables promise), at least its value there,
//!    which says "above the search limit" only with the wider [`BOUND_MARGIN`];
//! 3. F_on likewise, on the strip (w = ln(x_on - x)) for x within half a strip of x_s, on the
//!    body elsewhere;
//! 4. each ratio is compared with f_max: clearly below (an answer), clearly above (no
//!    bouncing / no double collision below v_max), or within [`V_MAX_MARGIN`] of it (the search
//!    decides);
//! 5. where steps 1-4 decline and put neither ratio below the limit, a floor of both ratios from
//!    the nodes of the two tables around k may still say "nothing below v_max"
//!    ([`super::floor`]).

use super::binary::Table;
use super::format::{CELL_LIMITS, LOWER_BOUND_OFFSET, SHEARED_REACH};
use super::interp::lagrange_weight;
use super::table::{Curve, Levels, RowsAt};
use super::verdict::{both, side, Eval, Side, BOUND_MARGIN, V_MAX_MARGIN};
use super::MasterTables;
use crate::k_axis;

/// How many tables of neighbouring k answer a k between tables: six, the quintic in ln k
/// through them. Measured at the middle of the k intervals (tables 2^(1/3) apart in k): the cubic
/// through four misses F by up to 1e-5 at a fixed distance to the cliff for y = log10(c_D c_a)
/// from -4 to -1.5 (so the k checks, to 2e-6, refused it there), the quintic by at most 1.2e-6.
/// Fewer committed tables (at least four) give a lower degree.
pub const K_STENCIL: usize = 6;

/// How many tables answer a k in the first or the last interval of k, where [`K_STENCIL`]
/// tables lie four on one side and two on the other, and the polynomial is as far from its
/// middle as it gets: one more, the sextic. Measured at 12 points between k = 0.0403 and
/// 0.0495 and between 0.0056 and 0.0063 (y = -4.6 to -2.8, F = 17 to 2700, against the exact
/// search): the quintic through the last (first) six tables misses F by up to 2.6e-6 (so the k
/// checks, to 2e-6, refused it there), the sextic through seven by at most 1.9e-6 and mostly
/// below 8e-7.
pub const K_STENCIL_EDGE: usize = 7;

/// The tables' answer: `(F, F_on)`, `None` for a ratio above the search limit.
pub(crate) type Answer = (Option<f64>, Option<f64>);

/// A plain pair kept: `((y, x), [g F, g F_on])`.
type PlainPair = ((f64, f64), Option<[f64; 2]>);

/// The tables that answer at (k, y): one (k is a table's own) or [`K_STENCIL`] around k in ln k
/// ([`K_STENCIL_EDGE`] in the first and the last interval),
/// with the interval of k between two tables (for the k checks), the Lagrange weights of k and
/// each table's four rows around y (found once an answer). Fixed arrays: no allocation per
/// answer.
struct KStencil<'a> {
    /// The last plain pair asked for: F and F_on are asked at the same point, and one search
    /// along each row serves both.
    plain: std::cell::Cell<Option<PlainPair>>,
    tables: [&'a Table; K_STENCIL_EDGE],
    /// Each table's rows around the asked y.
    at: [RowsAt; K_STENCIL_EDGE],
    /// What every table's rows around y promise towards and beyond their ends
    /// ([`Table::levels_in`]).
    levels: Levels,
    /// How many of `tables` (and `weights`) are used: 1, or 4 to [`K_STENCIL_EDGE`].
    n: usize,
    /// The Lagrange weights of the tables at the asked k (the polynomial in ln k).
    weights: [f64; K_STENCIL_EDGE],
    /// The k interval (between tables i and i + 1), `None` at a table's own k.
    interval: Option<usize>,
}

impl KStencil<'_> {
    /// The tables with their rows around y.
    fn tables_at(&self) -> impl Iterator<Item = (&Table, RowsAt)> {
        self.tables[..self.n]
            .iter()
            .zip(&self.at)
            .map(|(t, &at)| (*t, at))
    }

    /// The values of the stencil's tables (`None` if any is missing) combined at the asked k.
    fn combine(&self, mut g: impl FnMut(&Table, RowsAt) -> Option<f64>) -> Option<f64> {
        let mut sum = 0.0;
        for ((t, at), w) in self.tables_at().zip(&self.weights) {
            sum += w * g(t, at)?;
        }
        Some(sum)
    }

    /// `[g F, g F_on]` in plain x at (x, y), combined at the asked k (kept for the next call).
    fn plain_both(&self, y: f64, x: f64) -> Option<[f64; 2]> {
        if let Some((at, g)) = self.plain.get() {
            if at == (y, x) {
                return g;
            }
        }
        let mut g = Some([0.0; 2]);
        for ((t, at), w) in self.tables_at().zip(&self.weights) {
            match (t.g_plain_both_in(at, y, x), g.as_mut()) {
                (Some([a, b]), Some(sum)) => {
                    sum[0] += w * a;
                    sum[1] += w * b;
                }
                _ => g = None,
            }
        }
        self.plain.set(Some(((y, x), g)));
        g
    }
}

impl MasterTables {
    /// The tables around k with their rows around y; `None` where a table has no four rows
    /// around y (nothing is vouched for there).
    fn k_stencil(&self, k: f64, y: f64) -> Option<KStencil<'_>> {
        let ks = self.table_k();
        if let Some(i) = k_axis::own_table(ks, k) {
            let t = self.table(i)?;
            let at = t.rows_at(y)?;
            let mut weights = [0.0; K_STENCIL_EDGE];
            weights[0] = 1.0;
            return Some(KStencil {
                plain: Default::default(),
                tables: [t; K_STENCIL_EDGE],
                at: [at; K_STENCIL_EDGE],
                levels: t.levels_in(at),
                n: 1,
                weights,
                interval: None,
            });
        }
        let n = ks.len();
        if !k_axis::between_tables(ks, k) {
            return None;
        }
        let i = (1..n).find(|&i| ks[i] > k).map_or(n - 2, |i| i - 1);
        // the interval i in the middle of the stencil, shifted inward at the ends, one table
        // more in the end intervals
        let edge = i == 0 || i == n - 2;
        let width = n.min(if edge { K_STENCIL_EDGE } else { K_STENCIL });
        let s = (i + 1).saturating_sub(width / 2).min(n - width);
        let first = self.table(s)?;
        let mut tables = [first; K_STENCIL_EDGE];
        let mut at = [first.rows_at(y)?; K_STENCIL_EDGE];
        let mut levels = Levels::UNBOUNDED;
        let mut ln_k = [0.0; K_STENCIL_EDGE];
        for q in 0..width {
            tables[q] = self.table(s + q)?;
            at[q] = tables[q].rows_at(y)?;
            levels = levels.min(tables[q].levels_in(at[q]));
            ln_k[q] = ks[s + q].ln();
        }
        let mut weights = [0.0; K_STENCIL_EDGE];
        for (q, w) in weights.iter_mut().enumerate().take(width) {
            *w = lagrange_weight(&ln_k[..width], q, k.ln());
        }
        Some(KStencil {
            plain: Default::default(),
            tables,
            at,
            levels,
            n: width,
            weights,
            interval: Some(i),
        })
    }

    /// The k check of the stencil's interval at `y` (`Some(None)` at a table's own k), `None`
    /// where the interval was not checked there.
    fn check_of(&self, ks: &KStencil, y: f64) -> Option<Option<[f64; CELL_LIMITS]>> {
        match ks.interval {
            Some(i) => self.k_check(i, y).map(Some),
            None => Some(None),
        }
    }

    /// Both ratios far inside the region vouched in plain x (by [`PLAIN_INSIDE`] in x), without
    /// the end curves: the full answer ([`MasterTables::answer`]) gives the same there, bit for
    /// bit (`far_inside_the_plain_region_the_answer_needs_no_ends`), and the end curves' bicubic
    /// is a sixth of an answer that changes y at every point.
    fn plain_inside(
        &self,
        ks: &KStencil,
        x: f64,
        y: f64,
        f_max: f64,
    ) -> Option<(Option<f64>, Option<f64>)> {
        let check = self.check_of(ks, y)?;
        let hi = plain_limit(ks, check, Curve::Stick)?;
        let hi = hi.min(plain_limit(ks, check, Curve::OnsetBody)?);
        if hi.is_nan() || x + PLAIN_INSIDE > hi {
            return None;
        }
        let [s, o] = ks.plain_both(y, x)?;
        both(side(Eval::Value(s), f_max), side(Eval::Value(o), f_max))
    }

    /// `curve` at (x, y, k) from the stencil ([`super::table`]): plain where every table (and
    /// the k check) vouches for it at x, else sheared at the distance to the end where they do
    /// (this needs the end at (y, k)); closer to the end than vouched, at least the value at the
    /// closest vouched point, where the rows' ratios increase towards the end, or, down to the
    /// tables' lower-bound limits (`d_lb`), at least the value there, with [`BOUND_MARGIN`].
    fn eval(&self, ks: &KStencil, curve: Curve, x: f64, y: f64, end: Option<f64>) -> Eval {
        let Some(check) = self.check_of(ks, y) else {
            return Eval::Unknown;
        };
        // towards the end a ratio is at least its value at a point farther from it, up to the
        // level where the rows stop increasing
        let bound = |g: f64, margin: f64| Eval::AtLeast {
            g: g.min((ks.levels.mono - 1.0).ln()),
            margin,
        };
        let at_least = |g: f64| bound(g, V_MAX_MARGIN);
        // plain: vouched up to x_hi
        let plain = plain_limit(ks, check, curve);
        let g_plain = |x: f64| {
            let v = usize::from(curve != Curve::Stick);
            ks.plain_both(y, x).map(|g| g[v])
        };
        if let Some(hi) = plain {
            if x <= hi {
                return g_plain(x).map_or(Eval::Unknown, Eval::Value);
            }
        }
        // sheared: vouched down to u_lo
        if let Some(end) = end {
            let u = (end - x).max(f64::MIN_POSITIVE).ln();
            let c = match curve {
                Curve::Stick => 2,
                Curve::OnsetBody => 3,
                Curve::OnsetStrip => 4,
            };
            let (mut lo, mut hi) = (check.map_or(f64::NEG_INFINITY, |k| k[c]), f64::INFINITY);
            // the k check's limit for lower bounds (its `lo` where it has none deeper)
            let mut lb = check.map_or(f64::NEG_INFINITY, |k| k[c + LOWER_BOUND_OFFSET]);
            let mut vouched = true;
            for (t, at) in ks.tables_at() {
                match t.vouched_in(at, curve) {
                    Some((l, h)) => {
                        lo = lo.max(l);
                        hi = hi.min(h);
                        lb = lb.max(t.bound_in(at, curve));
                    }
                    None => vouched = false,
                }
            }
            // the checks at a fixed distance reach SHEARED_REACH from the end: farther, only
            // plain x was checked (below)
            let reach = SHEARED_REACH.ln();
            if vouched && lo <= hi.min(reach) && u <= reach {
                let at = |u: f64| ks.combine(|t, rows| t.g_at_in(rows, curve, y, u));
                // a strip holds nothing beyond its farthest node
                if curve == Curve::OnsetStrip && u > hi {
                    return Eval::Unknown;
                }
                let u = u.min(hi);
                if u >= lo {
                    return at(u).map_or(Eval::Unknown, Eval::Value);
                }
                // closer to the end than vouched: at least the value at the closest vouched
                // point; where the rows and cells were checked against the exact nodes closer
                // still (down to lb), at least the value at u or lb, with the wider margin
                let near = lo.is_finite().then(|| at(lo)).flatten().map(at_least);
                let deep = (lb < lo).then(|| at(u.max(lb))).flatten();
                let deep = deep.map(|g| bound(g, BOUND_MARGIN));
                match (near, deep) {
                    (Some(a), Some(b)) => return a.stronger(b),
                    (Some(e), None) | (None, Some(e)) => return e,
                    (None, None) => {}
                }
            }
        }
        // beyond the plain limit without the end: at least the value there
        match plain {
            Some(hi) if x > hi && hi.is_finite() => g_plain(hi).map_or(Eval::Unknown, at_least),
            _ => Eval::Unknown,
        }
    }

    /// `g = ln(ratio - 1)` of `curve` at `y`, at `u` (the log of the distance to the curve's
    /// end) and `k`, from the tables around k where each of them vouches for it, without the
    /// checks between tables (which the build computes with it).
    pub fn g_between_tables(&self, curve: Curve, y: f64, u: f64, k: f64) -> Option<f64> {
        let ks = self.k_stencil(k, y)?;
        ks.combine(|t, at| {
            let (lo, hi) = t.vouched_in(at, curve)?;
            (u >= lo && u <= hi).then_some(())?;
            t.g_at_in(at, curve, y, u)
        })
    }

    /// [`MasterTables::g_between_tables`] where each table serves as a lower bound (down to its
    /// `d_lb`, closer to the end than it vouches for values), without the checks between tables.
    pub fn g_bound_between_tables(&self, curve: Curve, y: f64, u: f64, k: f64) -> Option<f64> {
        let ks = self.k_stencil(k, y)?;
        ks.combine(|t, at| {
            let (_, hi) = t.vouched_in(at, curve)?;
            (u >= t.bound_in(at, curve) && u <= hi).then_some(())?;
            t.g_at_in(at, curve, y, u)
        })
    }

    /// [`MasterTables::g_between_tables`] in plain x: every table at the same x, where each
    /// vouches for it.
    pub fn g_plain_between_tables(&self, curve: Curve, y: f64, x: f64, k: f64) -> Option<f64> {
        let ks = self.k_stencil(k, y)?;
        ks.combine(|t, at| {
            (x <= t.plain_limit_in(at, curve)?).then_some(())?;
            t.g_plain(curve, y, x)
        })
    }

    /// Both ratios at x = log10 c_D, y = log10(c_D c_a), k, with the search limit `f_max`
    /// (= v_max / V_stick,JKR): `Some((F, F_on))` with `None` for a ratio above `f_max`, or
    /// `None` where the tables do not vouch for the answer.
    pub(crate) fn answer(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<Answer> {
        if let Some((stick, onset)) = self.sides(x, y, k, f_max) {
            if let Some(answer) = both(stick, onset) {
                return Some(answer);
            }
            // a ratio the interpolation puts below the limit is not overruled by a floor
            if matches!(stick, Side::Below(_)) || matches!(onset, Side::Below(_)) {
                return None;
            }
        }
        // where the interpolation declines (next to the kink), the nodes' floor may still say
        // "nothing below v_max" ([`super::floor`])
        self.node_verdict(x, y, k, f_max).then_some((None, None))
    }

    /// [`MasterTables::answer`] without the nodes' floor (steps 1-4).
    pub(crate) fn interpolate(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<Answer> {
        let (stick, onset) = self.sides(x, y, k, f_max)?;
        both(stick, onset)
    }

    /// What the interpolation says of each ratio (steps 1-4): far inside the plain region
    /// without the end curves, else with them; `None` without a stencil of tables at (k, y)
    /// or for a point or limit that is not finite and positive.
    fn sides(&self, x: f64, y: f64, k: f64, f_max: f64) -> Option<(Side, Side)> {
        if !(x.is_finite() && y.is_finite() && f_max > 0.0) {
            return None;
        }
        let ks = self.k_stencil(k, y)?;
        if let Some((stick, onset)) = self.plain_inside(&ks, x, y, f_max) {
            let side = |r: Option<f64>| r.map_or(Side::Above, Side::Below);
            return Some((side(stick), side(onset)));
        }
        Some(self.sides_with_ends(&ks, x, y, k, f_max))
    }

    /// What the end curves at (y, k) and the stencil say of each ratio, wherever x lies.
    fn sides_with_ends(&self, ks: &KStencil, x: f64, y: f64, k: f64, f_max: f64) -> (Side, Side) {
        let ends = self.ends().and_then(|e| e.at(y, k));
        let beyond = |end: Option<f64>| {
            // past its end a ratio exceeds the level up to which the rows were checked for no
            // bouncing beyond their ends (F_TOP for monotone rows); whether the rows increase
            // towards their ends does not matter there
            let level = ks.levels.beyond;
            match end {
                Some(end) if x >= end => {
                    if level > f_max * (1.0 + V_MAX_MARGIN) {
                        Some(Side::Above)
                    } else if ks.levels == Levels::UNBOUNDED {
                        Some(Side::Unknown)
                    } else {
                        None
                    }
                }
                _ => None,
            }
        };
        // next to the kink of the end curves, only "beyond the end" is known, from a bound
        let bound = match ends {
            None => self.ends().and_then(|e| e.upper_bound(y, k)),
            Some(_) => None,
        };
        let x_s = ends.map(|e| e.x_s);
        let stick = beyond(x_s.or(bound.map(|b| b.x_s)))
            .unwrap_or_else(|| side(self.eval(ks, Curve::Stick, x, y, x_s), f_max));
        let onset = beyond(ends.or(bound).map(|e| e.x_on)).unwrap_or_else(|| {
            let on_strip = ends
                .filter(|e| x > e.x_s - 0.5 * (e.x_on - e.x_s))
                .map(|e| self.eval(ks, Curve::OnsetStrip, x, y, Some(e.x_on)))
                .filter(|e| *e != Eval::Unknown);
            let e = on_strip.unwrap_or_else(|| self.eval(ks, Curve::OnsetBody, x, y, x_s));
            side(e, f_max)
        });
        (stick, onset)
    }
}

/// Far inside the region vouched in plain x by this much (in x), the end curves are not needed:
/// x lies below the end there (the vouched F is below F_TOP) by more than half the widest strip
/// between x_s and x_on on the end curves' grid (x_on - x_s is at most 0.003:
/// `the_strips_are_narrow`), so F_on is read on the body, as the full answer reads it.
const PLAIN_INSIDE: f64 = 0.01;

/// The plain limit of `curve` over the stencil's tables and the k check (x vouched up to it);
/// `None` where a table has none (and for the strip, which has no plain form).
fn plain_limit(ks: &KStencil, check: Option<[f64; CELL_LIMITS]>, curve: Curve) -> Option<f64> {
    if curve == Curve::OnsetStrip {
        return None;
    }
    let v = usize::from(curve != Curve::Stick);
    let mut hi = check.map_or(f64::INFINITY, |c| c[v]);
    for (t, at) in ks.tables_at() {
        hi = hi.min(t.plain_limit_in(at, curve)?);
    }
    Some(hi)
}

/// The relative accuracy the tables promise against the exact search (V_stick and
/// V_double_onset): a search asked for a tighter `rel_tol` than this (other than the default
/// [`crate::DEFAULT_REL_TOL`]) is not answered from the tables.
pub const TABLE_REL_TOL: f64 = 1e-5;

/// The thresholds of `contact` at `t_vis` (s, > 0) from the master tables for `law`'s k, or
/// `None` where they do not vouch for them (the caller then searches). Where a threshold lies
/// beyond the search limit `opts.v_max`, the answer is "none below v_max", as the search would
/// say.
pub(crate) fn from_table(
    contact: &contact::Contact,
    law: &greenwood::CrackLaw,
    t_vis: f64,
    opts: &crate::SearchOptions,
) -> Option<crate::StickingThresholds> {
    if opts.rel_tol < TABLE_REL_TOL && opts.rel_tol != crate::DEFAULT_REL_TOL {
        return None;
    }
    let c_d = contact.drag_number(t_vis);
    let v_jkr = contact.v_stick_jkr();
    let v_max = opts.v_max_for(v_jkr);
    // y from the product c_D c_a, not from c_D and c_a: the same bits at every T_vis of the
    // contact, so that the end curves at (y, k) of an array at one radius are found once
    let (x, y) = (c_d.log10(), contact.drag_crack_product().log10());
    let r = MasterTables::standard().ratios_at(x, y, law.k(), v_max / v_jkr)?;
    Some(crate::StickingThresholds {
        t_vis,
        v_stick: r.v_stick.map(|f| f * v_jkr),
        v_double_onset: r.v_double_onset.map(|f| f * v_jkr),
        v_stick_jkr: v_jkr,
        v_max,
        collisions: 0,
        steps: 0,
        method: crate::ThresholdMethod::Table,
    })
}

#[cfg(test)]
#[path = "answer_tests.rs"]
mod tests;
