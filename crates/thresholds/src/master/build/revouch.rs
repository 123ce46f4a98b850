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

use super::cells::{last_passing, sheared_checks, Checker};
use super::row::interpolate;
use super::{agrees, default_search, rel_diff, BuildConfig, Cache};
use crate::master::ends::EndCurves;
use crate::master::format::{CellData, EndsData, PieceData, RowData, TableData};
use crate::master::interp::stencil_start;
use crate::ThresholdsError;
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// Two limits closer than this (relative) are the same: a cell's limit equal to its rows' old
/// one had every check pass down to it (the text form keeps limits to the bit).
const SAME_LIMIT: f64 = 1e-12;

/// `piece` (ending at `end`) with ratio `v` vouched on past its `d_lo[v]`, node after node,
/// while the midpoint check and the default search pass; the new `d_lo[v]`.
fn extend_piece(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    y: f64,
    end: f64,
    piece: &PieceData,
    v: usize,
) -> f64 {
    let d_lo = piece.d_lo[v];
    let n = piece.x.len();
    if !d_lo.is_finite() || n < 2 {
        return d_lo;
    }
    let nodes: Vec<(f64, [f64; 2])> = (0..n)
        .map(|i| (piece.x[i], [piece.f_stick[i], piece.f_onset[i]]))
        .collect();
    // the last vouched node (x increasing: the distance to the end decreasing)
    let Some(first) = nodes
        .iter()
        .rposition(|n| end - n.0 >= d_lo * (1.0 - SAME_LIMIT))
    else {
        return d_lo;
    };
    let mut vouched = d_lo;
    for i in first + 1..n {
        let (a, b) = (nodes[i - 1].0, nodes[i].0);
        let u_mid = 0.5 * ((end - a).ln() + (end - b).ln());
        let exact = cache.node(cfg, law, end - u_mid.exp(), y);
        let ratio = |p: super::Point| if v == 0 { p.stick() } else { p.onset() };
        let midpoint_ok =
            rel_diff(Some(interpolate(&nodes, end, v, u_mid)), ratio(exact)) <= cfg.tol;
        let agrees = nodes[i].1[v] < cfg.agree_from
            || agrees(cfg, ratio(default_search(cfg, law, b, y)), nodes[i].1[v]);
        if !(midpoint_ok && agrees) {
            break;
        }
        vouched = end - b;
    }
    vouched
}

/// The row with its pieces vouched as close to their ends as the checks allow.
fn revouch_row(cfg: &BuildConfig, law: &CrackLaw, cache: &Cache, row: &RowData) -> RowData {
    let mut r = row.clone();
    for v in 0..2 {
        r.body.d_lo[v] = extend_piece(cfg, law, cache, row.y, row.x_s, &row.body, v);
    }
    r.strip.d_lo[1] = extend_piece(cfg, law, cache, row.y, row.x_on, &row.strip, 1);
    r
}

/// The sheared limit `c` (0: body F, 1: body F_on, 2: strip F_on) of the pieces of the rows
/// `s..s + 4` (the largest of their `d_lo`, as a cell check takes it).
fn rows_limit(rows: &[RowData], s: usize, c: usize) -> f64 {
    rows[s..s + 4]
        .iter()
        .map(|r| {
            if c == 2 {
                r.strip.d_lo[1]
            } else {
                r.body.d_lo[c]
            }
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// `table` (of k, on the end curves `ends`) vouched closer to its ends (see the module
/// documentation); `progress` is told what is done.
pub fn revouch_table(
    cfg: &BuildConfig,
    table: &TableData,
    ends: &EndsData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    let law = CrackLaw::new(table.k)?;
    let curves = EndCurves::new(ends.clone());
    let cache = Cache::default();
    let rows: Vec<RowData> = table
        .rows
        .par_iter()
        .map(|row| {
            let r = revouch_row(cfg, &law, &cache, row);
            progress(&format!(
                "k = {}, row y = {}: vouched to d = {} / {} / {} (was {} / {} / {})",
                table.k,
                r.y,
                number(r.body.d_lo[0]),
                number(r.body.d_lo[1]),
                number(r.strip.d_lo[1]),
                number(row.body.d_lo[0]),
                number(row.body.d_lo[1]),
                number(row.strip.d_lo[1]),
            ));
            r
        })
        .collect();
    let n = rows.len();
    let on = Checker {
        cfg,
        law: &law,
        cache: &cache,
        curves: &curves,
    };
    let cells: Vec<CellData> = (0..table.cells.len())
        .into_par_iter()
        .map(|j| {
            let mut cell = table.cells[j];
            if n < 4 {
                return cell;
            }
            let s = stencil_start(j, n);
            for c in 0..3 {
                let (old, new) = (rows_limit(&table.rows, s, c), rows_limit(&rows, s, c));
                let passed_to_old = (cell.d_lo[c] / old - 1.0).abs() <= SAME_LIMIT;
                if old.is_finite() && passed_to_old && new < old {
                    // the points between the new limit and the old (those at the old passed)
                    let range = (new.ln(), old.ln() - SAME_LIMIT);
                    cell.d_lo[c] = sheared_checks(&on, &rows, j, c, range).map_or(old, |checks| {
                        last_passing(&checks, new.ln(), old.ln()).exp()
                    });
                }
            }
            progress(&format!(
                "k = {}, cell y = {} .. {}: sheared to d = {} / {} / {}",
                table.k,
                rows[j].y,
                rows[(j + 1).min(n - 1)].y,
                number(cell.d_lo[0]),
                number(cell.d_lo[1]),
                number(cell.d_lo[2])
            ));
            cell
        })
        .collect();
    let built = super::built_at(table);
    let mut header = table.header.clone();
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
