//! The checks between tables of neighbouring k: in each k interval, at its middle k (a point of
//! the end curves' grid), in each bin of y, the quintic in ln k through the six tables around it
//! (the sextic through seven in the first and the last interval) is compared with the exact
//! search along the nodes of the nearest row, from far from the end towards it; the interval is
//! vouched for in that bin down to the last distance that passed. In plain x a check point that
//! misses by more than the build's tolerance does not end the walk at once: from there on each
//! check point is vouched for while the polynomial stays within
//! [`BuildConfig::kcheck_spread_tol`] of the nodes at nine points around it and within
//! [`BuildConfig::kcheck_default_agree`] of the default search. Closer to the end, where the
//! tables serve as lower bounds only (their `d_lb`), the same check goes on and gives the
//! interval's lower-bound limit (`bound_limit`).

use super::cells::SHEARED_REACH;
use super::{default_search, default_search_at_least, rel_diff, BuildConfig, Cache, Point};
use crate::master::binary::Table;
use crate::master::ends::EndCurves;
use crate::master::format::{CellData, EndsData, TableData};
use crate::master::{Curve, MasterTables, K_STENCIL, K_STENCIL_EDGE};
use crate::ThresholdsError;
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// Every this-many-th node of the nearest row is a check point (they lie a few hundredths to a
/// few tenths apart in u; the k interpolation error varies slowly along them).
const CHECK_EVERY: usize = 2;

/// `ends` with the k checks of `tables` filled in; `progress` is told of each interval.
pub fn k_checks(
    cfg: &BuildConfig,
    tables: &[TableData],
    ends: &EndsData,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<EndsData, ThresholdsError> {
    // the bins of this build's width (`BuildConfig::kcheck_dy`) over the span of y the end
    // curves set for them
    let (y0, dy0, ny0) = ends.kcheck_y;
    let dy = cfg.kcheck_dy;
    let ny = (dy0 * ny0 as f64 / dy - 1e-9).ceil().max(0.0) as usize;
    let mut open = ends.clone();
    open.kcheck_y = (y0, dy, ny);
    // no restriction while checking
    let everywhere = CellData {
        x_hi: [f64::INFINITY; 2],
        d_lo: [0.0; 3],
        d_lb: None,
    };
    open.kcheck = vec![everywhere; tables.len().saturating_sub(1) * ny];
    let curves = EndCurves::new(open.clone());
    let all = MasterTables::from_parts(
        tables.iter().map(Table::from_data).collect(),
        EndCurves::new(open.clone()),
    );
    let mut out = open;
    for i in 0..tables.len().saturating_sub(1) {
        // the middle in ln k (on the standard grid, a point of the end curves' grid)
        let k_mid = (tables[i].k * tables[i + 1].k).sqrt();
        let law = CrackLaw::new(k_mid)?;
        let cache = Cache::default();
        // a quarter and three quarters of the interval in ln k, for the checks past the first
        // miss ([`BuildConfig::kcheck_spread_tol`])
        let (k_lo, k_hi) = (tables[i].k, tables[i + 1].k);
        let spread_laws = [
            CrackLaw::new(k_lo.powf(0.75) * k_hi.powf(0.25))?,
            CrackLaw::new(k_lo.powf(0.25) * k_hi.powf(0.75))?,
        ];
        let spread_caches = [Cache::default(), Cache::default()];
        let spread = Spread {
            laws: [&spread_laws[0], &law, &spread_laws[1]],
            caches: [&spread_caches[0], &cache, &spread_caches[1]],
            dy,
        };
        let bins: Vec<CellData> = (0..ny)
            .into_par_iter()
            .map(|b| {
                let y = y0 + (b as f64 + 0.5) * dy;
                check_bin(cfg, &spread, &all, &curves, &tables[i], y)
            })
            .collect();
        let plain = bins.iter().filter(|c| c.x_hi[0].is_finite()).count();
        let sheared = bins.iter().filter(|c| c.d_lo[0].is_finite()).count();
        progress(&format!(
            "k checks between k = {} and {} (at {k_mid}): {plain} of {ny} bins in plain x, {sheared} at a fixed distance",
            number(tables[i].k),
            number(tables[i + 1].k),
        ));
        out.kcheck[i * ny..(i + 1) * ny].copy_from_slice(&bins);
    }
    // this check's description replaces an earlier one's
    out.header.retain(|h| !h.starts_with("k checks:"));
    out.header.push(format!(
        "k checks: the polynomial in ln k through {K_STENCIL} tables ({K_STENCIL_EDGE} in the first and last interval), in each interval of k at its middle k, in y bins of {}, along every {CHECK_EVERY}nd node of the nearest row, to {}; in plain x past the first miss on while within {} of the nodes at the bin's middle and edges in y and a quarter, half and three quarters of the interval in ln k, and within {} of the default search at the middle; then on through the tables' lower bounds with the default search within {} (d_lb)",
        number(dy),
        number(cfg.tol),
        number(cfg.kcheck_spread_tol),
        number(cfg.kcheck_default_agree),
        number(cfg.bound_agree)
    ));
    Ok(out)
}

/// The three k of an interval where a k check looks past its first miss (a quarter, half and
/// three quarters of it in ln k, each with its crack law and nodes; the middle one is the
/// check's own), and the width of the y bins.
struct Spread<'a> {
    laws: [&'a CrackLaw; 3],
    caches: [&'a Cache; 3],
    dy: f64,
}

impl Spread<'_> {
    /// Whether the polynomial in ln k of `curve` (ratio `v`) at `x` is within
    /// [`BuildConfig::kcheck_spread_tol`] of the exact nodes at the bin's middle `y` and edges,
    /// at each of the three k, and within [`BuildConfig::kcheck_default_agree`] of the default
    /// search at the middle.
    fn holds(
        &self,
        cfg: &BuildConfig,
        all: &MasterTables,
        curve: Curve,
        v: usize,
        x: f64,
        y: f64,
    ) -> bool {
        // the polynomial's ratio at (x, y_at) for k
        let ratio = |y_at: f64, k: f64| {
            all.g_plain_between_tables(curve, y_at, x, k)
                .map(|g| 1.0 + g.exp())
        };
        // the bin's middle and its two edges
        for y_at in [y, y - 0.5 * self.dy, y + 0.5 * self.dy] {
            for (law, cache) in self.laws.iter().zip(&self.caches) {
                let exact = cache.node(cfg, law, x, y_at).ratio(v);
                if rel_diff(ratio(y_at, law.k()), exact) > cfg.kcheck_spread_tol {
                    return false;
                }
            }
        }
        let law = self.laws[1];
        let theirs = default_search(cfg, law, x, y).ratio(v);
        rel_diff(ratio(y, law.k()), theirs) <= cfg.kcheck_default_agree
    }
}

/// The limits of the polynomial in ln k at `y` (as a cell's).
fn check_bin(
    cfg: &BuildConfig,
    spread: &Spread,
    all: &MasterTables,
    curves: &EndCurves,
    lower: &TableData,
    y: f64,
) -> CellData {
    let (law, cache) = (spread.laws[1], spread.caches[1]);
    let Some(row) = lower
        .rows
        .iter()
        .min_by(|a, b| (a.y - y).abs().total_cmp(&(b.y - y).abs()))
    else {
        return CellData::NONE;
    };
    let exact = |x: f64, v: usize| cache.node(cfg, law, x, y).ratio(v);
    let mut cell = CellData::NONE;
    let mut lb = cell.d_lo;
    // plain x, from far from the end towards it; past the first miss on while the
    // polynomial holds around the check point (`Spread::holds`)
    for (v, curve) in [(0, Curve::Stick), (1, Curve::OnsetBody)] {
        let mut last_ok = f64::NEG_INFINITY;
        let mut missed = false;
        for &x in row.body.x.iter().step_by(CHECK_EVERY) {
            let Some(g) = all.g_plain_between_tables(curve, y, x, law.k()) else {
                break;
            };
            let ok = if missed {
                spread.holds(cfg, all, curve, v, x, y)
            } else if rel_diff(Some(1.0 + g.exp()), exact(x, v)) > cfg.tol {
                missed = true;
                spread.holds(cfg, all, curve, v, x, y)
            } else {
                true
            };
            if !ok {
                break;
            }
            last_ok = x;
        }
        cell.x_hi[v] = last_ok;
    }
    // at a fixed distance to the end, within SHEARED_REACH of it
    let Some(e) = curves.at(y, law.k()) else {
        return cell;
    };
    for (c, curve, v) in [
        (0, Curve::Stick, 0),
        (1, Curve::OnsetBody, 1),
        (2, Curve::OnsetStrip, 1),
    ] {
        let (piece, end_row, end) = match curve {
            Curve::OnsetStrip => (&row.strip, row.x_on, e.x_on),
            _ => (&row.body, row.x_s, e.x_s),
        };
        let us: Vec<f64> = piece
            .x
            .iter()
            .step_by(CHECK_EVERY)
            .map(|x| (end_row - x).ln())
            .filter(|&u| u <= SHEARED_REACH.ln())
            .collect();
        let mut last_ok = f64::INFINITY;
        for &u in &us {
            let Some(g) = all.g_between_tables(curve, y, u, law.k()) else {
                continue;
            };
            if rel_diff(Some(1.0 + g.exp()), exact(end - u.exp(), v)) > cfg.tol {
                break;
            }
            last_ok = u.exp();
        }
        cell.d_lo[c] = last_ok;
        let band = Band {
            curve,
            v,
            y,
            end,
            lo: last_ok,
        };
        lb[c] = bound_limit(cfg, law, cache, all, &band, &us);
    }
    cell.d_lb = (lb != cell.d_lo).then_some(lb);
    cell
}

/// One sheared limit of a k check, as [`bound_limit`] continues it: the curve and its ratio
/// (0: F, 1: F_on), the y and the end at the interval's middle k, and the vouched limit (a
/// distance to the end).
struct Band {
    curve: Curve,
    v: usize,
    y: f64,
    end: f64,
    lo: f64,
}

/// How close to the end the polynomial in ln k through the tables' lower bounds
/// ([`MasterTables::g_bound_between_tables`]) holds at the check points `us` (u = ln of the
/// distance, decreasing) beyond the vouched limit: to the build's tolerance against the exact
/// search, with the default search within [`BuildConfig::bound_agree`] of it, from the limit on
/// until one fails (as `--part bounds` vouches a row); kept only where the default search at every check
/// point beyond finds at least the ratio there, less [`BuildConfig::bound_agree`] (what an
/// answer claims of that stretch, as `--part bounds` asks of a table's rows). The vouched limit
/// where not.
fn bound_limit(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    all: &MasterTables,
    band: &Band,
    us: &[f64],
) -> f64 {
    let Band {
        curve,
        v,
        y,
        end,
        lo,
    } = *band;
    if !lo.is_finite() {
        return lo;
    }
    let beyond: Vec<f64> = us.iter().copied().filter(|&u| u < lo.ln()).collect();
    // the last check point that passed: its index, distance and ratio; and the default search
    // at the point where the limit stopped, where it was made
    let mut last: Option<(usize, f64, f64)> = None;
    let mut searched: Option<Point> = None;
    for (i, &u) in beyond.iter().enumerate() {
        let Some(g) = all.g_bound_between_tables(curve, y, u, law.k()) else {
            break;
        };
        let x = end - u.exp();
        let node = cache.node(cfg, law, x, y).ratio(v);
        if rel_diff(Some(1.0 + g.exp()), node) > cfg.tol {
            break;
        }
        // the default search near the node, as `--part bounds` asks at a row's nodes (a
        // search that failed is not near)
        if !node.is_some_and(|f| f < cfg.agree_from) {
            let theirs = default_search(cfg, law, x, y);
            let near =
                theirs != Point::Failed && rel_diff(theirs.ratio(v), node) <= cfg.bound_agree;
            if !near {
                searched = Some(theirs);
                break;
            }
        }
        last = Some((i, u.exp(), 1.0 + g.exp()));
    }
    let Some((i, lb, at_lb)) = last else {
        return lo;
    };
    let floor = at_lb * (1.0 - cfg.bound_agree);
    let xs = beyond[i + 1..].iter().map(|&u| end - u.exp());
    if default_search_at_least(cfg, law, y, v, floor, xs, searched) {
        lb
    } else {
        lo
    }
}
