//! One k's table: rows every [`BuildConfig::y_step`] in y, each cell between two rows checked at
//! mid-y, at the distance to the end interpolated there, and a row added in its middle where the
//! check fails, down to [`BuildConfig::min_y_step`].

use super::row::build_row;
use super::{grid_k, rel_diff, BuildConfig, Cache};
use crate::master::ends::EndCurves;
use crate::master::format::{CellData, EndsData, PieceData, RowData, TableData, F_TOP};
use crate::master::interp::{lagrange, local_cubic, stencil_start};
use crate::ThresholdsError;
use greenwood::CrackLaw;
use numerics::format::number;
use numerics::OutOfRange;
use rayon::prelude::*;

/// The end curves' grid point of `y` at table `k_index` (an exact point of the grid: rows lie on
/// it), if computed.
fn row_ends(cfg: &BuildConfig, ends: &EndsData, k_index: usize, y: f64) -> Option<(f64, f64)> {
    let j = k_index * (cfg.ends_k.1 / cfg.table_k.1);
    let i = ((y - ends.y0) / ends.dy).round();
    if !(i >= 0.0 && (i as usize) < ends.ny && j < ends.nk) {
        return None;
    }
    let at = j * ends.ny + i as usize;
    let (s, o) = (ends.x_s[at], ends.x_on[at]);
    (s.is_finite() && o.is_finite()).then_some((s, o))
}

/// A piece's nodes as `(u, g = ln(ratio - 1))` for ratio `v`, u increasing.
fn curve(p: &PieceData, end: f64, v: usize) -> (Vec<f64>, Vec<f64>) {
    let u = p.x.iter().rev().map(|x| (end - x).ln()).collect();
    let r = if v == 0 { &p.f_stick } else { &p.f_onset };
    let g = r.iter().rev().map(|f| (f - 1.0).ln()).collect();
    (u, g)
}

pub use crate::master::format::SHEARED_REACH;

/// The last check point that passed before the first that failed, in the order given: `all`
/// when every one passed, `none` when the first failed.
pub fn last_passing(checks: &[(f64, bool)], all: f64, none: f64) -> f64 {
    match checks.iter().position(|q| !q.1) {
        None => all,
        Some(0) => none,
        Some(i) => checks[i - 1].0,
    }
}

/// Each of the sorted `points` (once) and whether the cubic in y through the stencil's rows at
/// it (`g(q, point)`: `g = ln(ratio - 1)` of row `q`, at `ys[q]`), evaluated at `y_mid`, is within
/// `tol` of the `exact` ratio there.
fn checked(
    mut points: Vec<f64>,
    ys: &[f64],
    y_mid: f64,
    tol: f64,
    g: impl Fn(usize, f64) -> f64 + Sync,
    exact: impl Fn(f64) -> Option<f64> + Sync,
) -> Vec<(f64, bool)> {
    points.dedup();
    points
        .par_iter()
        .map(|&p| {
            let g: Vec<f64> = (0..ys.len()).map(|q| g(q, p)).collect();
            let predicted = 1.0 + lagrange(ys, &g, y_mid).exp();
            (p, rel_diff(Some(predicted), exact(p)) <= tol)
        })
        .collect()
}

/// The body (`strip` false) or the strip of a row.
fn piece_of(r: &RowData, strip: bool) -> &PieceData {
    if strip {
        &r.strip
    } else {
        &r.body
    }
}

/// What a cell check needs besides the rows: the build's settings, the crack law of the
/// table's k, the nodes computed so far and the end curves.
#[derive(Clone, Copy)]
pub struct Checker<'a> {
    /// The build's settings.
    pub cfg: &'a BuildConfig,
    /// The crack law of the table's k.
    pub law: &'a CrackLaw,
    /// The nodes computed so far.
    pub cache: &'a Cache,
    /// The end curves (the end at a cell's mid-y).
    pub curves: &'a EndCurves,
}

/// The four rows whose cubic in y answers in the cell between `rows[j]` and `rows[j + 1]`
/// (shifted inward at the ends), their y, and the cell's mid-y; `None` with fewer than four rows.
fn cell_stencil(rows: &[RowData], j: usize) -> Option<(&[RowData], Vec<f64>, f64)> {
    let s = stencil_start(j, rows.len());
    let stencil = rows.get(s..s + 4)?;
    let ys = stencil.iter().map(|r| r.y).collect();
    Some((stencil, ys, 0.5 * (rows[j].y + rows[j + 1].y)))
}

/// The sheared check `c` (0: body F, 1: body F_on, 2: strip F_on) of the cell between
/// `rows[j]` and `rows[j + 1]`: at the distances to the end of `rows[j]`'s nodes with u = ln d in
/// `u_range` (and within [`SHEARED_REACH`] and every stencil row's nodes), in decreasing u, the
/// cubic in y through the stencil's rows against the exact ratio at mid-y (at that distance
/// to the end interpolated there). `None` where the end curves do not give the end at mid-y or
/// a row of the stencil has fewer than two nodes.
pub fn sheared_checks(
    on: &Checker,
    rows: &[RowData],
    j: usize,
    c: usize,
    u_range: (f64, f64),
) -> Option<Vec<(f64, bool)>> {
    let Checker {
        cfg,
        law,
        cache,
        curves,
    } = *on;
    let (stencil, ys, y_mid) = cell_stencil(rows, j)?;
    let e = curves.at(y_mid, law.k())?;
    let (strip, v) = (c == 2, usize::from(c != 0));
    let end = |r: &RowData| if strip { r.x_on } else { r.x_s };
    let end_mid = if strip { e.x_on } else { e.x_s };
    if stencil.iter().any(|r| piece_of(r, strip).x.len() < 2) {
        return None;
    }
    let of_rows: Vec<(Vec<f64>, Vec<f64>)> = stencil
        .iter()
        .map(|r| curve(piece_of(r, strip), end(r), v))
        .collect();
    let hi = of_rows
        .iter()
        .map(|(u, _)| u[u.len() - 1])
        .fold(SHEARED_REACH.ln(), f64::min)
        .min(u_range.1);
    let mut us: Vec<f64> = curve(piece_of(&rows[j], strip), end(&rows[j]), v)
        .0
        .into_iter()
        .filter(|&u| u >= u_range.0 && u <= hi)
        .collect();
    us.sort_by(|a, b| b.total_cmp(a));
    let exact = |u: f64| cache.node(cfg, law, end_mid - u.exp(), y_mid).ratio(v);
    Some(checked(
        us,
        &ys,
        y_mid,
        cfg.tol,
        |q, u| local_cubic(&of_rows[q].0, &of_rows[q].1, u),
        exact,
    ))
}

/// The limits of the cell between `rows[j]` and `rows[j + 1]` (checked at mid-y: in plain x at
/// the nodes of both rows, and at a fixed distance to the end interpolated there), and whether
/// every check inside the rows' vouched ranges passed (else a row is added in the middle).
fn check_cell(on: &Checker, rows: &[RowData], j: usize) -> (CellData, bool) {
    let Checker {
        cfg, law, cache, ..
    } = *on;
    let Some((stencil, ys, y_mid)) = cell_stencil(rows, j) else {
        return (CellData::NONE, false);
    };
    let mut cell = CellData::NONE;
    let mut ok = true;
    let exact = |x: f64, y: f64, v: usize| cache.node(cfg, law, x, y).ratio(v);
    // plain x
    let x_s_min = stencil.iter().map(|r| r.x_s).fold(f64::INFINITY, f64::min);
    for v in 0..2 {
        if stencil.iter().any(|r| r.body.x.len() < 2) {
            continue;
        }
        let of_rows: Vec<(Vec<f64>, Vec<f64>, f64)> = stencil
            .iter()
            .map(|r| {
                let (u, g) = curve(&r.body, r.x_s, v);
                (u, g, r.x_s)
            })
            .collect();
        let hi = stencil
            .iter()
            .map(|r| r.x_s - r.body.d_lo[v])
            .fold(f64::INFINITY, f64::min);
        // the nodes of the lower row (the upper row's are its next cell's)
        let mut xs: Vec<f64> = rows[j]
            .body
            .x
            .iter()
            .copied()
            .filter(|&x| x <= hi)
            .collect();
        xs.sort_by(f64::total_cmp);
        let checks = checked(
            xs,
            &ys,
            y_mid,
            cfg.tol,
            |q, x| {
                let (u, g, x_s) = &of_rows[q];
                local_cubic(u, g, (x_s - x).ln().min(u[u.len() - 1]))
            },
            |x| exact(x, y_mid, v),
        );
        cell.x_hi[v] = last_passing(&checks, hi, f64::NEG_INFINITY);
        // far from the end (where the sheared checks do not reach) plain x must hold
        ok &= checks
            .iter()
            .all(|q| q.1 || q.0 > x_s_min - SHEARED_REACH / 2.0);
    }
    // at a fixed distance to the end, where the end curves vouch for the end at mid-y
    for c in 0..3 {
        let lo = stencil
            .iter()
            .map(|r| piece_of(r, c == 2).d_lo[usize::from(c != 0)].ln())
            .fold(f64::NEG_INFINITY, f64::max);
        let Some(checks) = sheared_checks(on, rows, j, c, (lo, f64::INFINITY)) else {
            continue;
        };
        let all = if lo.is_finite() { lo } else { f64::INFINITY };
        cell.d_lo[c] = last_passing(&checks, all, f64::INFINITY).exp();
        ok &= checks.iter().all(|q| q.1);
    }
    (cell, ok)
}

/// The table of `k_index` (k = `grid_k` of the tables' grid) on the end curves `ends`;
/// `progress` is told what is done.
pub fn build_table(
    cfg: &BuildConfig,
    k_index: usize,
    ends: &EndsData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    extend_table(cfg, k_index, None, ends, progress)
}

/// The table of `k_index` grown from `committed` (the same k): its rows kept, rows added every
/// [`BuildConfig::y_step`] below its lowest down to `cfg.y_range.0`, and the cells whose stencil
/// changed (the new ones and the old first one, whose stencil, the four rows nearest, now
/// reaches into the new rows; the first only if it lies above `cfg.y_range.0`) checked and split
/// as in a build. The cells above keep their rows and limits: the restitution tables were built
/// on them (`cargo xtask restitution-table --check` recomputes them from the master tables to
/// 1e-7). Without `committed`, the whole table is built.
pub fn extend_table(
    cfg: &BuildConfig,
    k_index: usize,
    committed: Option<TableData>,
    ends: &EndsData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    let (k0, per, _) = cfg.table_k;
    let k = grid_k(k0, per, k_index);
    let law = CrackLaw::new(k)?;
    let curves = EndCurves::new(ends.clone());
    let cache = Cache::default();
    let row_at = |y: f64| -> Option<RowData> {
        let (x_s, x_on) = row_ends(cfg, ends, k_index, y)?;
        let r = build_row(cfg, &law, &cache, y, x_s, x_on);
        progress(&format!(
            "k = {k}, row y = {y}: {} + {} nodes, vouched to d = {} / {} / {}{}",
            r.body.x.len(),
            r.strip.x.len(),
            number(r.body.d_lo[0]),
            number(r.body.d_lo[1]),
            number(r.strip.d_lo[1]),
            if r.monotone { "" } else { ", not monotone" }
        ));
        Some(r)
    };
    let (y0, mut y1) = cfg.y_range;
    let (old_rows, old_cells) = match committed {
        Some(t) if (t.k / k - 1.0).abs() < 1e-9 && !t.rows.is_empty() => (t.rows, t.cells),
        Some(t) => {
            let allowed = format!("the table's k = {k}, with at least one row");
            return Err(OutOfRange::new("k", t.k, allowed, "dimensionless").into());
        }
        None => (Vec::new(), Vec::new()),
    };
    if let Some(first) = old_rows.first() {
        y1 = first.y - 0.5 * cfg.y_step;
    }
    // rounding must not drop the last row: (5.5 - (-6)) / 0.5 is 23, not 22.999...
    let n0 = ((y1 - y0) / cfg.y_step + 1e-9).floor().max(-1.0) as i64 + 1;
    let ys: Vec<f64> = (0..n0).map(|i| y0 + i as f64 * cfg.y_step).collect();
    let mut rows: Vec<RowData> = ys.par_iter().filter_map(|&y| row_at(y)).collect();
    let added = rows.len();
    let mut cells: Vec<Option<CellData>> = vec![None; added];
    cells.extend(old_cells.into_iter().map(Some));
    rows.extend(old_rows);
    cells.truncate(rows.len().saturating_sub(1));
    // the new cells and the old first one (its stencil changed; not below y0); every other
    // cell of the committed table keeps its rows and limits
    for (j, c) in cells.iter_mut().enumerate() {
        if j <= added && rows[j].y >= y0 {
            *c = None;
        }
    }
    refine(
        cfg, &law, &cache, &curves, &mut rows, &mut cells, &row_at, progress,
    );
    let header = vec![
        format!(
            "master table of F = V_stick/V_stick,JKR and F_on = V_double_onset/V_stick,JKR over x = log10 c_D, y = log10(c_D c_a), k = {k}"
        ),
        format!(
            "nodes: the exact search at rel_tol = {}, collisions at rtol = {}, c_a clamped at 1e{}; F up to {F_TOP} (x_s, x_on: the end curves)",
            number(cfg.rel_tol),
            number(cfg.solver.rtol),
            cfg.z_clamp
        ),
        format!(
            "interpolation: local cubics of ln(ratio - 1) in u = ln(x_s - x) (body) and w = ln(x_on - x) (strip), then in y in plain x (cell x_hi) or at a fixed distance to the end (cell d_lo); every midpoint checked to {}; the default search agrees with every vouched node to {} (ratios up to {}; {} above)",
            number(cfg.tol),
            number(cfg.agree),
            number(cfg.agree_up_to),
            number(cfg.agree_beyond)
        ),
        format!(
            "domain: x from {}, y in [{}, {}]; d_lo: vouched where the distance to the end is at least this",
            number(cfg.x_min),
            number(rows.first().map_or(y0, |r| r.y)),
            number(rows.last().map_or(y0, |r| r.y))
        ),
    ];
    Ok(TableData {
        k,
        header,
        cells: cells
            .into_iter()
            .map(|c| c.unwrap_or(CellData::NONE))
            .collect(),
        rows,
    })
}

/// Checks every cell not yet checked (`None`; a cell's stencil is the four rows around it,
/// shifted inward at the ends), and splits those that fail with a row in their middle, down to
/// [`BuildConfig::min_y_step`], until every cell is checked.
#[allow(clippy::too_many_arguments)]
fn refine(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    curves: &EndCurves,
    rows: &mut Vec<RowData>,
    cells: &mut Vec<Option<CellData>>,
    row_at: &(dyn Fn(f64) -> Option<RowData> + Sync),
    progress: &(dyn Fn(&str) + Sync),
) {
    let on = Checker {
        cfg,
        law,
        cache,
        curves,
    };
    let k = law.k();
    loop {
        let unchecked: Vec<usize> = (0..cells.len()).filter(|&j| cells[j].is_none()).collect();
        if unchecked.is_empty() {
            break;
        }
        let mut split = Vec::new();
        for &j in &unchecked {
            let (cell, ok) = check_cell(&on, rows, j);
            let can_split = rows[j + 1].y - rows[j].y > cfg.min_y_step * 1.5;
            if ok || !can_split {
                cells[j] = Some(cell);
            } else {
                split.push(j);
            }
            progress(&format!(
                "k = {k}, cell y = {} .. {}: plain to x = {} / {}, sheared to d = {} / {} / {}{}",
                rows[j].y,
                rows[j + 1].y,
                number(cell.x_hi[0]),
                number(cell.x_hi[1]),
                number(cell.d_lo[0]),
                number(cell.d_lo[1]),
                number(cell.d_lo[2]),
                if ok || !can_split { "" } else { ", split" }
            ));
        }
        let new_rows: Vec<RowData> = split
            .par_iter()
            .filter_map(|&j| row_at(0.5 * (rows[j].y + rows[j + 1].y)))
            .collect();
        if new_rows.is_empty() && !split.is_empty() {
            for j in split {
                cells[j] = Some(CellData::NONE);
            }
        }
        for r in new_rows {
            let at = rows.partition_point(|q| q.y < r.y);
            rows.insert(at, r);
            cells.insert(at, None);
            // the stencils around the new row changed
            for j in at.saturating_sub(2)..(at + 2).min(cells.len()) {
                cells[j] = None;
            }
        }
    }
}
