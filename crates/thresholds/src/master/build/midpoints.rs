//! `cargo xtask master-table --part midpoints`: the rows' finest intervals checked again, and
//! each piece's vouched range ended at the first that fails.
//!
//! A row's build halves each interval until the local cubic matches a new exact node at its
//! midpoint to [`BuildConfig::tol`], down to [`BuildConfig::min_x_step`] and
//! [`BuildConfig::min_u_step`]; an interval that still fails there cannot be mended, and its
//! piece is vouched for up to its start only. Until 2026-11-28 a failure met in an earlier
//! round of halving (while other intervals were still being halved) was not counted when the
//! last round ended the loop (`row.rs` kept only the last round's failures), so the piece was
//! vouched to its end across it. That happened where the two kinds of bouncing cross (F has a
//! kink there, which no cubic follows): on 252 committed rows (240 for F) vouched past a change
//! of kind of their nodes, the rows' interpolation next to the crossing missed the exact search
//! by 1.4e-3 to 0.33, and the tables answered at their own k with errors up to 2.2e-3 (k =
//! 0.0252, x = -0.402, y = -4.096; `docs/performance.md`, "Master tables").
//!
//! This pass needs no new rows: for every interval of the finest width inside a piece's vouched
//! range (the ones whose failure the build dropped), the midpoint check once more with the
//! committed nodes, and the vouched range ended at the start of the first that fails. It does
//! not redo the build: a wider interval below the first such failure passed the last round's
//! check with the final nodes (or it would have been halved), but one beyond it may have been
//! halved in an earlier round and never checked again; the range ends before those as long as
//! the finest failure still fails with the final nodes (every committed row vouched past a
//! change of kind of its nodes did: `tests/master_own_k.rs`), and a failure the build met with
//! earlier nodes but that passes with the final ones is not counted here. Where a limit moves,
//! the piece's lower-bound limit (`d_lb`, which `--part bounds` reached from the old limit) is
//! dropped. The cells and the k checks keep theirs: an answer takes the smallest of the rows',
//! the cell's and the k check's limits, so a row's new limit bounds them all.

use super::row::{interpolate, ratios, splittable, Kind};
use super::{rel_diff, BuildConfig, Cache, SAME_LIMIT};
use crate::master::format::{PieceData, RowData, TableData};
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// The vouched limit (`d_lo`) of ratio `v` of `piece` (ending at `end`, on the row at `y`) once
/// its finest intervals inside the vouched range are checked again: the distance to the end of
/// the start of the first that fails, or the old limit.
pub(super) fn recheck_piece(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    y: f64,
    end: f64,
    (piece, kind): (&PieceData, Kind),
    v: usize,
) -> f64 {
    let d_lo = piece.d_lo[v];
    let n = piece.x.len();
    if !d_lo.is_finite() || n < 2 {
        return d_lo;
    }
    let nodes = piece.nodes();
    for i in 1..n {
        let (a, b) = (nodes[i - 1].0, nodes[i].0);
        if end - b < d_lo * (1.0 - SAME_LIMIT) {
            break;
        }
        if splittable(cfg, end, a, b) {
            continue;
        }
        let u_mid = 0.5 * ((end - a).ln() + (end - b).ln());
        // as the build takes a node: a body's midpoint needs both ratios
        let exact = ratios(cache.node(cfg, law, end - u_mid.exp(), y), kind).map(|r| r[v]);
        if rel_diff(Some(interpolate(&nodes, end, v, u_mid)), exact) > cfg.tol {
            return end - a;
        }
    }
    d_lo
}

/// `row` with each piece's limits after [`recheck_piece`], and its lower-bound limits dropped
/// where a limit moved; whether one moved.
fn recheck_row(cfg: &BuildConfig, law: &CrackLaw, cache: &Cache, row: &RowData) -> (RowData, bool) {
    let mut r = row.clone();
    let body =
        [0, 1].map(|v| recheck_piece(cfg, law, cache, row.y, row.x_s, (&row.body, Kind::Body), v));
    let strip = [
        row.strip.d_lo[0],
        recheck_piece(
            cfg,
            law,
            cache,
            row.y,
            row.x_on,
            (&row.strip, Kind::Strip),
            1,
        ),
    ];
    let moved = [body != row.body.d_lo, strip != row.strip.d_lo];
    if moved[0] {
        (r.body.d_lo, r.body.d_lb) = (body, None);
    }
    if moved[1] {
        (r.strip.d_lo, r.strip.d_lb) = (strip, None);
    }
    (r, moved[0] || moved[1])
}

/// `table` (of `law`'s k) with every row's finest intervals checked again (see the module
/// documentation); `progress` is told of every row whose limits moved.
pub fn recheck_table(
    cfg: &BuildConfig,
    law: &CrackLaw,
    table: &TableData,
    progress: &(dyn Fn(&str) + Sync),
) -> TableData {
    let cache = Cache::default();
    let rows: Vec<RowData> = table
        .rows
        .par_iter()
        .map(|row| {
            let (r, moved) = recheck_row(cfg, law, &cache, row);
            if moved {
                progress(&format!(
                    "k = {}, row y = {}: vouched to x = {} / {} / strip d = {} (was {} / {} / {})",
                    table.k,
                    r.y,
                    number(r.x_s - r.body.d_lo[0]),
                    number(r.x_s - r.body.d_lo[1]),
                    number(r.strip.d_lo[1]),
                    number(row.x_s - row.body.d_lo[0]),
                    number(row.x_s - row.body.d_lo[1]),
                    number(row.strip.d_lo[1]),
                ));
            }
            r
        })
        .collect();
    let built = super::built_at(table);
    let mut header = table.header.clone();
    header.retain(|h| !h.starts_with("midpoints:"));
    header.push(format!(
        "midpoints: every finest interval inside a piece's vouched range checked again at its midpoint to {}, the range ended at the first that fails (cargo xtask master-table --part midpoints, on the table of commit {built})",
        number(cfg.tol)
    ));
    TableData {
        k: table.k,
        header,
        rows,
        cells: table.cells.clone(),
    }
}
