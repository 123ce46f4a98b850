//! Building a master table with the exact search (`cargo xtask master-table`), and checking a
//! committed one against it (`--check`).
//!
//! A node at `(x, y)` is the exact search for a synthetic contact whose dimensionless numbers
//! are `c_D = 10^x` and `c_a = min(10^(y - x), 10^z_clamp)` ([`synthetic`]). Each row of
//! constant y starts from nodes every [`BuildConfig::x_step`] up to the cliff, which it then
//! brackets by bisection; every interval between two nodes is checked at its midpoint against
//! the local cubic through the nodes around it and halved where the two differ by more than
//! [`BuildConfig::tol`] of F, down to [`BuildConfig::min_x_step`]. Rows start every
//! [`BuildConfig::y_step`]; each cell between two rows is checked at mid-y on the nodes of both
//! rows and a row is added in its middle where the check fails, down to
//! [`BuildConfig::min_y_step`]. What still fails at the finest steps (near the cliff) is not
//! vouched for.

use super::interp::{lagrange, local_cubic, stencil_start};
use super::{MasterTable, Row};
use crate::{sticking_thresholds, SearchOptions, ThresholdsError};
use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::Mutex;

/// The settings of a table build.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildConfig {
    /// The modulus ratio k.
    pub k: f64,
    /// Relative width of the final brackets of each node's search: 1e-8, so that a node's
    /// error (the solver's, about 2e-7) stays far below [`BuildConfig::tol`].
    pub rel_tol: f64,
    /// The largest interpolation error a check accepts, relative to F: 2e-6, a fifth of the
    /// 1e-5 the table promises, for the error between checks and the noise of the nodes.
    pub tol: f64,
    /// The range of x = log10 c_D: down to T_vis = 1e-16 s for every grain of the domain
    /// (-12.7) and up beyond the cliff.
    pub x_range: (f64, f64),
    /// The range of y = log10(c_D c_a): the domain's -5.8 to 5.1 and a row or more beyond.
    pub y_range: (f64, f64),
    /// The first spacing of the nodes of a row (decades of c_D).
    pub x_step: f64,
    /// The finest spacing of the nodes of a row.
    pub min_x_step: f64,
    /// The first spacing of the rows (decades of c_D c_a).
    pub y_step: f64,
    /// The finest spacing of the rows.
    pub min_y_step: f64,
    /// The largest log10 c_a of a node (see the module documentation of `master`).
    pub z_clamp: f64,
    /// The cliff of a row is where no collision bounces up to this many V_stick,JKR (the
    /// default search limit of [`SearchOptions::v_max`]).
    pub f_max: f64,
    /// The nodes of a row end where F exceeds this: just before the cliff F climbs steeply
    /// (from 10 to several hundred within a few hundredths of a decade of c_D), where a table
    /// would need a node every 1/128 decade; the exact search answers there.
    pub f_vouch: f64,
}

impl BuildConfig {
    /// The settings of the committed tables, for `k`.
    pub fn standard(k: f64) -> Self {
        Self {
            k,
            rel_tol: 1e-8,
            tol: 2e-6,
            x_range: (-13.0, 1.5),
            y_range: (-6.5, 6.0),
            x_step: 0.5,
            min_x_step: 1.0 / 128.0,
            y_step: 0.5,
            min_y_step: 1.0 / 64.0,
            z_clamp: 8.0,
            f_max: crate::DEFAULT_V_MAX_OVER_JKR,
            f_vouch: 100.0,
        }
    }
}

/// The exact search at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Point {
    /// F = V_stick / V_stick,JKR and F_on = V_double_onset / V_stick,JKR.
    Bounce {
        /// V_stick / V_stick,JKR.
        f_stick: f64,
        /// V_double_onset / V_stick,JKR.
        f_onset: f64,
    },
    /// No collision bounces up to [`BuildConfig::f_max`] V_stick,JKR.
    NoBounce,
    /// The search failed (the solver, or no convergence) for every synthetic contact tried.
    Failed,
}

/// V_stick,JKR of the synthetic contacts (m/s): that of 60 um CO2 grains, so that every search
/// runs at ordinary speeds whatever the point.
const SYNTHETIC_V_STICK_JKR: f64 = 0.02;

/// A contact and a relaxation time (s) whose dimensionless numbers are `c_D = 10^x` and
/// `c_D c_a = 10^y`: two identical spheres with CO2's elastic constants, the radius that gives y
/// (y goes as R^(-2/3)), the density that gives V_stick,JKR = 0.02 m/s times `density_factor`
/// (y does not depend on it), and the T_vis that gives x.
pub fn synthetic(x: f64, y: f64, density_factor: f64) -> Result<(Contact, f64), ThresholdsError> {
    let co2 = Material::co2();
    let reference = Contact::new(co2, Geometry::identical(60e-6))?;
    let d = reference.dimensionless(1.0);
    let radius = 60e-6 * 10f64.powf(-1.5 * (y - (d.c_d * d.c_a).log10()));
    let sized = Contact::new(co2, Geometry::identical(radius))?;
    let density =
        co2.density * (sized.v_stick_jkr() / SYNTHETIC_V_STICK_JKR).powi(2) * density_factor;
    let contact = Contact::new(Material { density, ..co2 }, Geometry::identical(radius))?;
    let t_vis = 10f64.powf(x) / contact.dimensionless(1.0).c_d;
    Ok((contact, t_vis))
}

/// Density factors of the synthetic contacts tried in turn when a search fails: the same
/// dimensionless problem, rounded differently.
const RETRY_DENSITY: [f64; 3] = [1.0, 1.37, 0.61];

/// The exact search at `(x, y)` (c_a clamped at `10^z_clamp`), without a hint, so that a
/// node can be recomputed to the bit (`cargo xtask master-table --check`).
pub fn evaluate(cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Point {
    let y = y.min(x + cfg.z_clamp);
    for factor in RETRY_DENSITY {
        let Ok((contact, t_vis)) = synthetic(x, y, factor) else {
            return Point::Failed;
        };
        let jkr = contact.v_stick_jkr();
        let opts = SearchOptions {
            rel_tol: cfg.rel_tol,
            v_max: Some(cfg.f_max * jkr),
            ..SearchOptions::default()
        };
        if let Ok(th) = sticking_thresholds(&contact, law, t_vis, &opts) {
            return match (th.v_stick, th.v_double_onset) {
                (Some(s), Some(o)) => Point::Bounce {
                    f_stick: s / jkr,
                    f_onset: o / jkr,
                },
                _ => Point::NoBounce,
            };
        }
    }
    Point::Failed
}

/// Evaluations shared by the rows and the cell checks of one build, keyed by `(x, y)` to 1e-9.
struct Cache(Mutex<HashMap<(i64, i64), Point>>);

impl Cache {
    fn key(x: f64, y: f64) -> (i64, i64) {
        ((x * 1e9).round() as i64, (y * 1e9).round() as i64)
    }

    fn get(&self, cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Point {
        let key = Self::key(x, y);
        if let Some(p) = self.0.lock().ok().and_then(|m| m.get(&key).copied()) {
            return p;
        }
        let p = evaluate(cfg, law, x, y);
        if let Ok(mut m) = self.0.lock() {
            m.insert(key, p);
        }
        p
    }
}

/// `(F, F_on)` where the table holds a node: bouncing with F up to [`BuildConfig::f_vouch`].
fn bounces(p: Point, cfg: &BuildConfig) -> Option<(f64, f64)> {
    match p {
        Point::Bounce { f_stick, f_onset }
            if f_stick <= cfg.f_vouch && f_stick > 1.0 && f_onset > 1.0 =>
        {
            Some((f_stick, f_onset))
        }
        _ => None,
    }
}

/// The relative difference of two `(F, F_on)`, the larger of the two.
fn rel_error(a: (f64, f64), b: (f64, f64)) -> f64 {
    ((a.0 - b.0) / b.0).abs().max(((a.1 - b.1) / b.1).abs())
}

/// `(F, F_on)` from the nodes `(x, F, F_on)` at `x` through the local cubic in ln(F - 1).
fn interpolate(nodes: &[(f64, f64, f64)], x: f64) -> (f64, f64) {
    let xs: Vec<f64> = nodes.iter().map(|n| n.0).collect();
    let gs: Vec<f64> = nodes.iter().map(|n| (n.1 - 1.0).ln()).collect();
    let go: Vec<f64> = nodes.iter().map(|n| (n.2 - 1.0).ln()).collect();
    (
        1.0 + local_cubic(&xs, &gs, x).exp(),
        1.0 + local_cubic(&xs, &go, x).exp(),
    )
}

/// One row of constant `y` (see the module documentation).
fn build_row(cfg: &BuildConfig, law: &CrackLaw, cache: &Cache, y: f64) -> Row {
    let (x0, x1) = cfg.x_range;
    let mut nodes: Vec<(f64, f64, f64)> = Vec::new();
    // coarse nodes up to F = f_vouch (or the cliff)
    let mut top = f64::INFINITY;
    let mut x = x0;
    while x <= x1 + 1e-12 {
        let p = cache.get(cfg, law, x, y);
        match bounces(p, cfg) {
            Some((s, o)) => nodes.push((x, s, o)),
            // a search that failed is no end of the row: its interval stays unchecked
            None if p == Point::Failed => {}
            None => {
                top = x;
                break;
            }
        }
        x += cfg.x_step;
    }
    // that end bracketed to the finest step
    if let Some(&(mut lo, ..)) = nodes.last().filter(|_| top.is_finite()) {
        while top - lo > cfg.min_x_step * 1.5 {
            let mid = 0.5 * (lo + top);
            match bounces(cache.get(cfg, law, mid, y), cfg) {
                Some((s, o)) => {
                    nodes.push((mid, s, o));
                    lo = mid;
                }
                None => top = mid,
            }
        }
    }
    // the cliff beyond, for the record: the first x without bouncing, to the finest step
    let mut cliff = f64::INFINITY;
    if top.is_finite() {
        let no_bounce = |x: f64| cache.get(cfg, law, x, y) == Point::NoBounce;
        let step = 8.0 * cfg.min_x_step;
        let mut lo = top - cfg.min_x_step;
        let mut x = top;
        while x <= x1 + 1e-12 {
            if no_bounce(x) {
                cliff = x;
                break;
            }
            lo = x;
            x += step;
        }
        while cliff.is_finite() && cliff - lo > cfg.min_x_step * 1.5 {
            let mid = 0.5 * (lo + cliff);
            if no_bounce(mid) {
                cliff = mid;
            } else {
                lo = mid;
            }
        }
    }
    // intervals checked at their midpoints, halved where the cubic misses
    let failed_at = loop {
        let mut added = Vec::new();
        let mut failed_at = f64::INFINITY;
        for w in nodes.windows(2) {
            let (a, b) = (w[0].0, w[1].0);
            let mid = 0.5 * (a + b);
            let ok = match bounces(cache.get(cfg, law, mid, y), cfg) {
                Some(exact) => rel_error(interpolate(&nodes, mid), exact) <= cfg.tol,
                None => false,
            };
            if !ok {
                if b - a > cfg.min_x_step * 1.5 {
                    if let Some((s, o)) = bounces(cache.get(cfg, law, mid, y), cfg) {
                        added.push((mid, s, o));
                        continue;
                    }
                }
                failed_at = failed_at.min(a);
            }
        }
        if added.is_empty() {
            break failed_at;
        }
        nodes.extend(added);
        nodes.sort_by(|a, b| a.0.total_cmp(&b.0));
    };
    let x_hi = failed_at.min(nodes.last().map_or(x0, |n| n.0));
    Row {
        y,
        x: nodes.iter().map(|n| n.0).collect(),
        g_stick: nodes.iter().map(|n| (n.1 - 1.0).ln()).collect(),
        g_onset: nodes.iter().map(|n| (n.2 - 1.0).ln()).collect(),
        x_hi,
        cliff,
    }
}

/// The largest x up to which the y-interpolation of the cell between `rows[j]` and
/// `rows[j + 1]` matches the exact search at mid-y on the nodes of both rows (`None` when a
/// check fails below the rows' vouched ends).
fn check_cell(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    rows: &[Row],
    j: usize,
) -> (f64, bool) {
    let n = rows.len();
    let s = stencil_start(j, n);
    let stencil = &rows[s..(s + 4).min(n)];
    let ys: Vec<f64> = stencil.iter().map(|r| r.y).collect();
    let y_mid = 0.5 * (rows[j].y + rows[j + 1].y);
    let x_lo = stencil
        .iter()
        .map(|r| r.x[0])
        .fold(f64::NEG_INFINITY, f64::max);
    let x_hi = stencil.iter().map(|r| r.x_hi).fold(f64::INFINITY, f64::min);
    let mut xs: Vec<f64> = rows[j]
        .x
        .iter()
        .chain(&rows[j + 1].x)
        .copied()
        .filter(|&x| x >= x_lo && x <= x_hi)
        .collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let results: Vec<(f64, bool)> = xs
        .par_iter()
        .map(|&x| {
            let (gs, go): (Vec<f64>, Vec<f64>) = stencil.iter().map(|r| r.at(x)).unzip();
            let predicted = (
                1.0 + lagrange(&ys, &gs, y_mid).exp(),
                1.0 + lagrange(&ys, &go, y_mid).exp(),
            );
            let ok = bounces(cache.get(cfg, law, x, y_mid), cfg)
                .is_some_and(|exact| rel_error(predicted, exact) <= cfg.tol);
            (x, ok)
        })
        .collect();
    match results.iter().position(|r| !r.1) {
        None => (x_hi, true),
        Some(0) => (x_lo, false),
        Some(i) => (results[i - 1].0, false),
    }
}

/// Builds the table of `cfg.k` (see the module documentation); `progress` is told what is done.
pub fn build(
    cfg: &BuildConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<MasterTable, ThresholdsError> {
    let law = CrackLaw::new(cfg.k)?;
    let cache = Cache(Mutex::new(HashMap::new()));
    let (y0, y1) = cfg.y_range;
    let n0 = ((y1 - y0) / cfg.y_step).round() as usize + 1;
    let ys: Vec<f64> = (0..n0).map(|i| y0 + i as f64 * cfg.y_step).collect();
    let mut rows: Vec<Row> = ys
        .par_iter()
        .map(|&y| {
            let r = build_row(cfg, &law, &cache, y);
            progress(&format!(
                "row y = {y}: {} nodes, cliff at x = {}",
                r.x.len(),
                r.cliff
            ));
            r
        })
        .collect();
    // cells: x_hi and whether checked, for each pair of rows
    let mut cells: Vec<Option<f64>> = vec![None; rows.len() - 1];
    loop {
        let unchecked: Vec<usize> = (1..rows.len().saturating_sub(2))
            .filter(|&j| cells[j].is_none())
            .collect();
        if unchecked.is_empty() {
            break;
        }
        let mut split = Vec::new();
        for &j in &unchecked {
            let (x_hi, ok) = check_cell(cfg, &law, &cache, &rows, j);
            let can_split = rows[j + 1].y - rows[j].y > cfg.min_y_step * 1.5;
            if ok || !can_split {
                cells[j] = Some(x_hi);
            } else {
                split.push(j);
            }
            progress(&format!(
                "cell y = {} .. {}: vouched up to x = {x_hi}{}",
                rows[j].y,
                rows[j + 1].y,
                if ok || !can_split { "" } else { ", split" }
            ));
        }
        let new_rows: Vec<Row> = split
            .par_iter()
            .map(|&j| build_row(cfg, &law, &cache, 0.5 * (rows[j].y + rows[j + 1].y)))
            .collect();
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
    let end = |c: Option<f64>| c.unwrap_or(f64::NEG_INFINITY);
    let header = vec![
            format!(
                "master table of F = V_stick/V_stick,JKR and F_on = V_double_onset/V_stick,JKR over x = log10 c_D, y = log10(c_D c_a), k = {}",
                cfg.k
            ),
            format!(
                "nodes: the exact search at rel_tol = {}, c_a clamped at 1e{}; interpolation (local cubics in ln(F - 1)) checked at every midpoint to {} of F; rows end at F = {}",
                number(cfg.rel_tol),
                cfg.z_clamp,
                number(cfg.tol),
                number(cfg.f_vouch)
            ),
            format!(
                "domain: x in [{}, {}], y in [{}, {}]; vouched where the checks passed (row: up to x_hi; cell: up to its x_hi); the cliff: no bouncing up to {} V_stick,JKR",
                number(cfg.x_range.0),
                number(cfg.x_range.1),
                number(cfg.y_range.0),
                number(cfg.y_range.1),
                number(cfg.f_max)
            ),
    ];
    let cells = cells.into_iter().map(end).collect();
    Ok(MasterTable::new(cfg.k, header, rows, cells))
}

/// A node of `table` recomputed by the exact search: `(x, y, stored F, recomputed F)`, for
/// every `every`-th node; a changed model shows as a difference (the search is deterministic).
pub fn check_nodes(
    table: &MasterTable,
    every: usize,
) -> Result<Vec<(f64, f64, f64, f64)>, ThresholdsError> {
    let cfg = BuildConfig::standard(table.k);
    let law = CrackLaw::new(table.k)?;
    let nodes: Vec<(f64, f64, f64)> = table
        .rows
        .iter()
        .flat_map(|r| {
            r.x.iter()
                .zip(&r.g_stick)
                .map(move |(&x, &g)| (x, r.y, 1.0 + g.exp()))
        })
        .step_by(every.max(1))
        .collect();
    Ok(nodes
        .par_iter()
        .map(|&(x, y, f)| {
            let again = match evaluate(&cfg, &law, x, y) {
                Point::Bounce { f_stick, .. } => f_stick,
                _ => f64::NAN,
            };
            (x, y, f, again)
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The synthetic contact has the dimensionless numbers asked for, and V_stick,JKR = 0.02 m/s.
    #[test]
    fn synthetic_contacts_hit_their_point() {
        for (x, y) in [(-3.0, -1.0), (-0.5, 4.0), (-10.0, -5.5)] {
            let (c, t) = synthetic(x, y, 1.0).unwrap();
            let d = c.dimensionless(t);
            assert!(
                (d.c_d.log10() - x).abs() < 1e-12 && ((d.c_d * d.c_a).log10() - y).abs() < 1e-12
            );
            assert!((c.v_stick_jkr() / SYNTHETIC_V_STICK_JKR - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn interpolation_of_nodes_uses_ln_f_minus_one() {
        // F - 1 = e^(2x) is linear in ln(F - 1): exact
        let nodes: Vec<(f64, f64, f64)> = (0..5)
            .map(|i| {
                let x = i as f64;
                (x, 1.0 + (2.0 * x).exp(), 1.0 + x.exp())
            })
            .collect();
        let (s, o) = interpolate(&nodes, 1.5);
        assert!((s - (1.0 + 3f64.exp())).abs() < 1e-9 && (o - (1.0 + 1.5f64.exp())).abs() < 1e-12);
    }
}
