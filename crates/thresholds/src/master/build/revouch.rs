//! `cargo xtask master-table --part revouch`: a committed table vouched closer to its ends,
//! without new nodes or rows.
//!
//! A row stops vouching at the first node the default search disagrees with by more than
//! [`BuildConfig::agree`]. Near the cliff the default search is the less accurate of the two:
//! measured at 24 CO2 points 1e-4 to 1e-3 in x from x_s (k = 0.01), the default search lay up to
//! 5.4e-6 from the reference search (`SearchOptions::reference()`), the rows' interpolation
//! (unvouched there) within 1.3e-6 of it; closer still (F of 1000 to 2200) the default search
//! scatters by up to 3.5e-5 around the nodes while the rows' midpoints stay within 1e-6 of new
//! nodes. Tables built with the earlier rule (4e-6 at every ratio) stopped there, and the
//! search answered that band (6-20 ms a point). This pass takes each piece's nodes beyond its
//! vouched end in turn, checks the local cubic at the interval's midpoint against a new node
//! (as a build does, to [`BuildConfig::tol`]) and the default search at the node ([`agrees`]:
//! to `agree` up to the default search limit, to `agree_beyond` above), and extends the
//! vouched range while both pass; then each cell whose checks had all passed down to its rows'
//! old limit is checked on down to the new one, as a build checks it. Nothing else changes:
//! the nodes, rows, plain-x limits and the k checks (which `--part kcheck` recomputes).
//!
//! `cargo xtask master-table --part bounds` ([`Pass::Bounds`]) goes on the same way from there,
//! node after node, while the midpoint check passes and the default search lies within
//! [`BuildConfig::bound_agree`] of the node, and writes the result as each piece's and cell's
//! `d_lb`: where the tables are within their tolerance of the exact nodes, but the default
//! search strays from them by more than the tables promise against it, so that they serve only
//! as lower bounds, for the verdict "above the search limit" (`master::answer`,
//! `BOUND_MARGIN`); a cell only where its checks reached below its old limit, and a piece only
//! where the default search at every node beyond the new limit finds at least the ratio there
//! (what an answer claims of that stretch). Measured on the CO2-like rows near the cliff
//! (k = 0.01, y about -0.5 to 0.7): the default search strays by 1.2e-5 to 1.4e-4 there, the
//! rows' midpoints stay within 1e-6 of new nodes down to 1e-5 from the ends.

use super::cells::{last_passing, sheared_checks, Checker};
use super::row::interpolate;
use super::{
    agrees, default_search, default_search_at_least, rel_diff, BuildConfig, Cache, Point,
    SAME_LIMIT,
};
use crate::master::ends::EndCurves;
use crate::master::format::{CellData, EndsData, PieceData, RowData, TableData};
use crate::master::interp::stencil_start;
use crate::ThresholdsError;
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// Which limit a pass moves towards the ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pass {
    /// `d_lo` (values): the midpoint checks pass and the default search agrees with the nodes
    /// as the tables promise ([`agrees`]).
    Revouch,
    /// `d_lb` (lower bounds): the midpoint checks pass and the default search lies within
    /// [`BuildConfig::bound_agree`] of the nodes.
    Bounds,
}

impl Pass {
    /// Whether the default search's ratio `theirs` passes against the node's `ours`.
    fn agrees(self, cfg: &BuildConfig, theirs: Option<f64>, ours: f64) -> bool {
        match self {
            Pass::Revouch => agrees(cfg, theirs, ours),
            Pass::Bounds => rel_diff(theirs, Some(ours)) <= cfg.bound_agree,
        }
    }
}

/// `piece` (ending at `end`) with ratio `v` vouched on past its `d_lo[v]`, node after node,
/// while the midpoint check and the default search pass (`pass`'s rule); the new limit. A
/// lower bound serves all the way to the end (the value at the limit, where the rows increase
/// towards it): [`Pass::Bounds`] keeps its limit only where the default search at every node
/// beyond it finds the ratio at least the limit's, to [`BuildConfig::bound_agree`] (or
/// nothing below its search limit), and keeps `d_lo` otherwise.
fn extend_piece(on: &Checker, pass: Pass, y: f64, end: f64, piece: &PieceData, v: usize) -> f64 {
    let Checker {
        cfg, law, cache, ..
    } = *on;
    let d_lo = piece.d_lo[v];
    let n = piece.x.len();
    if !d_lo.is_finite() || n < 2 {
        return d_lo;
    }
    let nodes = piece.nodes();
    // the last vouched node (x increasing: the distance to the end decreasing)
    let Some(first) = nodes
        .iter()
        .rposition(|n| end - n.0 >= d_lo * (1.0 - SAME_LIMIT))
    else {
        return d_lo;
    };
    let (mut vouched, mut last) = (d_lo, first);
    // the default search at the node where the limit stopped, where it was made
    let mut searched: Option<Point> = None;
    for i in first + 1..n {
        let (a, b) = (nodes[i - 1].0, nodes[i].0);
        let u_mid = 0.5 * ((end - a).ln() + (end - b).ln());
        let exact = cache.node(cfg, law, end - u_mid.exp(), y).ratio(v);
        if rel_diff(Some(interpolate(&nodes, end, v, u_mid)), exact) > cfg.tol {
            break;
        }
        // nodes far from the cliff are not compared (`BuildConfig::agree_from`; a node's ratios
        // are finite, the reader refuses others)
        if nodes[i].1[v] >= cfg.agree_from {
            let theirs = default_search(cfg, law, b, y);
            if !pass.agrees(cfg, theirs.ratio(v), nodes[i].1[v]) {
                searched = Some(theirs);
                break;
            }
        }
        (vouched, last) = (end - b, i);
    }
    if pass == Pass::Bounds && last > first {
        // beyond the limit the answer claims "at least the ratio at the limit": the default
        // search must not find less there
        let floor = nodes[last].1[v] * (1.0 - cfg.bound_agree);
        let beyond = nodes[last + 1..].iter().map(|node| node.0);
        if !default_search_at_least(cfg, law, y, v, floor, beyond, searched) {
            return d_lo;
        }
    }
    vouched
}

/// The row with its pieces vouched (`pass`: as values or as lower bounds) as close to their
/// ends as the checks allow.
fn revouch_row(on: &Checker, pass: Pass, row: &RowData) -> RowData {
    let mut r = row.clone();
    let extend = |end: f64, p: &PieceData, v: usize| extend_piece(on, pass, row.y, end, p, v);
    let body = [0, 1].map(|v| extend(row.x_s, &row.body, v));
    let strip = [f64::INFINITY, extend(row.x_on, &row.strip, 1)];
    match pass {
        Pass::Revouch => {
            (r.body.d_lo, r.strip.d_lo) = (body, strip);
            // lower bounds reached from the old limits are computed anew (`--part bounds`)
            (r.body.d_lb, r.strip.d_lb) = (None, None);
        }
        Pass::Bounds => {
            r.body.d_lb = (body != row.body.d_lo).then_some(body);
            r.strip.d_lb = (strip[1] != row.strip.d_lo[1]).then_some(strip);
        }
    }
    r
}

/// The sheared limit `c` (0: body F, 1: body F_on, 2: strip F_on) of the pieces of the rows
/// `s..s + 4` (the largest of their `d_lo`, or of their lower-bound limits with `bounds`, as a
/// cell check takes it).
fn rows_limit(rows: &[RowData], s: usize, c: usize, bounds: bool) -> f64 {
    rows[s..s + 4]
        .iter()
        .map(|r| {
            let (p, v) = if c == 2 { (&r.strip, 1) } else { (&r.body, c) };
            if bounds {
                p.bound_limit(v)
            } else {
                p.d_lo[v]
            }
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The `pass` over `table` (of k, on the end curves `ends`): vouched closer to its ends as
/// values or as lower bounds (see the module documentation); `progress` is told what is done.
pub fn revouch_table(
    pass: Pass,
    cfg: &BuildConfig,
    table: &TableData,
    ends: &EndsData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let curves = EndCurves::new(ends.clone());
    let cache = Cache::default();
    let on = Checker {
        cfg,
        law: &law,
        cache: &cache,
        curves: &curves,
    };
    let rows: Vec<RowData> = table
        .rows
        .par_iter()
        .map(|row| {
            let r = revouch_row(&on, pass, row);
            let to = |p: &PieceData, v: usize| match pass {
                Pass::Revouch => number(p.d_lo[v]),
                Pass::Bounds => number(p.bound_limit(v)),
            };
            progress(&format!(
                "k = {}, row y = {}: {pass:?} to d = {} / {} / {} (vouched {} / {} / {})",
                table.k,
                r.y,
                to(&r.body, 0),
                to(&r.body, 1),
                to(&r.strip, 1),
                number(row.body.d_lo[0]),
                number(row.body.d_lo[1]),
                number(row.strip.d_lo[1]),
            ));
            r
        })
        .collect();
    let n = rows.len();
    let cells: Vec<CellData> = (0..table.cells.len())
        .into_par_iter()
        .map(|j| {
            let mut cell = table.cells[j];
            if n < 4 {
                return cell;
            }
            let s = stencil_start(j, n);
            let bounds = pass == Pass::Bounds;
            let mut moved = cell.d_lo;
            for (c, moved) in moved.iter_mut().enumerate() {
                let old = rows_limit(&table.rows, s, c, false);
                let new = rows_limit(&rows, s, c, bounds);
                let passed_to_old = (cell.d_lo[c] / old - 1.0).abs() <= SAME_LIMIT;
                if old.is_finite() && passed_to_old && new < old {
                    // the points between the new limit and the old (those at the old passed)
                    let range = (new.ln(), old.ln() - SAME_LIMIT);
                    // where nothing moves, the cell's own limit, to the bit (equal to its rows'
                    // old one to SAME_LIMIT only: not a new limit)
                    let kept = cell.d_lo[c];
                    *moved = match sheared_checks(&on, &rows, j, c, range) {
                        // a lower bound needs a check below the old limit (values keep the
                        // rule they were vouched by: the rows' limit where none lies between)
                        Some(checks) if bounds && checks.is_empty() => kept,
                        Some(checks) => match last_passing(&checks, new.ln(), old.ln()) {
                            // no check passed below the old limit (or only next to it; the
                            // exp of a log may lie an ulp above it)
                            u if u.exp() >= old * (1.0 - SAME_LIMIT) => kept,
                            u => u.exp(),
                        },
                        None => kept,
                    };
                }
            }
            match pass {
                Pass::Revouch => (cell.d_lo, cell.d_lb) = (moved, None),
                Pass::Bounds => cell.d_lb = (moved != cell.d_lo).then_some(moved),
            }
            let d = [0, 1, 2].map(|c| number(cell.bound_limit(c).min(cell.d_lo[c])));
            progress(&format!(
                "k = {}, cell y = {} .. {}: {pass:?}, sheared to d = {} / {} / {}",
                table.k,
                rows[j].y,
                rows[(j + 1).min(n - 1)].y,
                d[0],
                d[1],
                d[2]
            ));
            cell
        })
        .collect();
    let built = super::built_at(table);
    let mut header = table.header.clone();
    if pass == Pass::Bounds {
        header.retain(|h| !h.starts_with("bounds:"));
        header.push(format!(
            "bounds: d_lb, lower bounds only, where the midpoint checks pass to {} and the default search lies within {} of the nodes (cargo xtask master-table --part bounds, on the table of commit {built})",
            number(cfg.tol),
            number(cfg.bound_agree)
        ));
        return Ok(TableData {
            k: table.k,
            header,
            rows,
            cells,
        });
    }
    header.retain(|h| !h.starts_with("bounds:"));
    header.push(format!(
        "revouched: the pieces and cells vouched on towards the ends while the midpoint checks pass to {} and the default search agrees to {} up to ratios of {}, to {} above (cargo xtask master-table --part revouch, on the table of commit {built})",
        number(cfg.tol),
        number(cfg.agree),
        number(cfg.agree_up_to),
        number(cfg.agree_beyond)
    ));
    Ok(TableData {
        k: table.k,
        header,
        rows,
        cells,
    })
}
