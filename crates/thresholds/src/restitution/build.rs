//! Building the restitution tables from single collisions (`cargo xtask restitution-table`).
//!
//! For each table k of the master tables and each row y (every [`BuildConfig::y_step`]), nodes
//! every [`BuildConfig::x_step`] from x = [`BuildConfig::x_min`] (the JKR plateau: the rebound
//! no longer changes with c_D below it) up to one decade of c_D from the row's end, then every
//! [`BuildConfig::u_step`] in u = ln(x_s - x) down to [`BuildConfig::d_min`]; each interval is
//! halved while the cubic along the row misses e at its midpoint ([`BuildConfig::min_u_step`]).
//! At each node the master tables give V_stick and V_double_onset, and one collision (rtol
//! 1e-9) is integrated at every channel. Each cell between two rows is then checked at its
//! centre at a few speeds between the channels against the ODE ([`BuildConfig::tol_e`]), and
//! each interval between tables of neighbouring k at its middle k.
//!
//! The cells are checked in [`super::check`]; where the bouncing cells fail between rows,
//! [`super::refine`] adds rows. The pilot at k = 0.01 (2026-11-25) converged along the rows
//! (130-170 nodes a row) while its cells, rows 0.5 apart, vouched for 10-75 % only: the rows
//! went to 0.25 apart, the channels to even steps in ln sigma + sigma and logit nu.

use super::format::{channel_at, channel_coordinate, CellFlags, NodeData, RowData, TableData};
use super::MIN_WINDOW;
use crate::master::build::{grid_k, synthetic};
use crate::master::format::EndsData;
use crate::master::{MasterTables, F_TOP};
use crate::{Collider, Outcome, SolverOptions, ThresholdsError};
use greenwood::CrackLaw;
use numerics::format::number;
use rayon::prelude::*;

/// The settings of a build.
#[derive(Debug, Clone, PartialEq)]
pub struct BuildConfig {
    /// The bouncing channels, sigma = ln(V_in / V_stick), evenly in ln sigma + sigma
    /// ([`CHANNEL_STEP`], [`channel_coordinate`]) from [`SIGMA_MIN`] to 9.5 (V_in up to 1.3e4 V_stick; the rebound
    /// saturates far above V_stick). A pilot at k = 0.01 with channels evenly in sigma (every
    /// 0.05 from 0) and h = -e^2 missed e by up to 8e-3 just above V_stick, where |V_out| changes
    /// from linear in the distance to V_stick to its square root within the first step.
    pub sigma: Vec<f64>,
    /// The double-collision channels, nu in (0, 1) (nu = 1 is the onset, where the outcome
    /// jumps), evenly in logit nu = ln(nu / (1 - nu)) from [`SIGMA_MIN`] to [`NU_MAX`]: towards
    /// the onset |V_out| rises about as ln(1/(1 - nu)) (by 0.0104 V_stick from 1 - nu = 1e-2 to
    /// 1e-4 at x = -0.52, y = 1.5, k = 0.01), which channels evenly in ln nu missed by 2.6 %.
    pub nu: Vec<f64>,
    /// Row spacing in y.
    pub y_step: f64,
    /// The y range.
    pub y_range: (f64, f64),
    /// The first node of a row: -12 (at smaller c_D the rebound is that of the JKR limit).
    pub x_min: f64,
    /// Node spacing in x, more than a decade of c_D from the end.
    pub x_step: f64,
    /// Node spacing in u = ln(x_s - x) within a decade of the end.
    pub u_step: f64,
    /// The closest node to the end (in x).
    pub d_min: f64,
    /// Intervals of a row are halved (in u = ln(x_s - x)) down to this where the cubic along the
    /// row misses e at their midpoint by more than `tol_e`.
    pub min_u_step: f64,
    /// The collisions: rtol 1e-9 (e to about 1e-8).
    pub solver: SolverOptions,
    /// A cell is vouched for where the interpolated e is within this of the ODE's at its centre:
    /// 5e-5, half the 1e-4 promised.
    pub tol_e: f64,
    /// The bouncing speeds a cell is checked at (between channels).
    pub check_sigma: Vec<f64>,
    /// The double-collision speeds a cell is checked at.
    pub check_nu: Vec<f64>,
    /// The speeds a cell is also checked at, at its quarters (`check::QUARTERS`): `(sigma,
    /// nu)`, between every fourth pair of channels (21 bouncing, 16 double-collision). The
    /// cell of k = 0.02 at y = -4.3125 to -4.25, x about -0.94, passed at
    /// [`BuildConfig::check_sigma`] and missed e by 1.6e-4 at 15 V_stick, between two of them
    /// (a scan at its middle y). Every fourth, not every second: the check of the eleven
    /// tables took 26 min so.
    pub quarter_speeds: (Vec<f64>, Vec<f64>),
}

impl BuildConfig {
    /// The tables of the standard k grid, k = 0.005 2^(i/3), i = 0..10 (the master tables').
    pub const TABLES: usize = 11;

    /// The settings of the committed tables.
    pub fn standard() -> Self {
        // channels evenly in the interpolation coordinate, from lo to hi
        let even = |bouncing: bool, lo: f64, hi: f64| -> Vec<f64> {
            let (a, b) = (
                channel_coordinate(bouncing, lo),
                channel_coordinate(bouncing, hi),
            );
            let n = ((b - a) / CHANNEL_STEP).ceil() as usize;
            (0..=n)
                .map(|i| channel_at(bouncing, a + (b - a) * i as f64 / n as f64))
                .collect()
        };
        let (sigma, nu) = (even(true, SIGMA_MIN, 9.5), even(false, SIGMA_MIN, NU_MAX));
        // between channels, where the cubic along them misses most, spread over the range
        let mid = |b: bool, g: &[f64], i: usize| {
            let z = 0.5 * (channel_coordinate(b, g[i]) + channel_coordinate(b, g[i + 1]));
            channel_at(b, z)
        };
        let check_sigma = [3, 12, 24, 36, 50, 64, 76]
            .map(|i| mid(true, &sigma, i))
            .to_vec();
        let check_nu = [3, 15, 30, 45, 55, 62].map(|i| mid(false, &nu, i)).to_vec();
        // `--quarters`: between every fourth pair of channels
        let dense = |b: bool, g: &[f64]| -> Vec<f64> {
            (1..g.len() - 1).step_by(4).map(|i| mid(b, g, i)).collect()
        };
        let quarter_speeds = (dense(true, &sigma), dense(false, &nu));
        Self {
            sigma,
            nu,
            y_step: 0.25,
            y_range: (-6.5, 6.0),
            x_min: -12.0,
            x_step: 0.5,
            u_step: 0.5,
            d_min: 1e-3,
            min_u_step: 1.0 / 32.0,
            solver: SolverOptions::default(),
            tol_e: 5e-5,
            check_sigma,
            check_nu,
            quarter_speeds,
        }
    }
}

/// The channels' spacing in their coordinates (ln sigma + sigma, logit nu): 0.25.
pub const CHANNEL_STEP: f64 = 0.25;

/// The first channel of each side, sigma (nu) = 1e-4: closer to V_stick the tables decline and
/// the ODE answers (the master tables' V_stick is good to 2e-6, a fiftieth of it).
pub const SIGMA_MIN: f64 = 1e-4;

/// The last double-collision channel, nu = 0.999: closer to the onset the ODE answers.
pub const NU_MAX: f64 = 0.999;

/// `(outcome, V_out / V_stick,JKR)` of one collision at `(x, y)` for `law`, at `s` V_stick,JKR.
pub(super) fn collide(
    cfg: &BuildConfig,
    law: &CrackLaw,
    x: f64,
    y: f64,
    s: f64,
) -> Option<(Outcome, f64)> {
    let (contact, t_vis) = synthetic(x, y.min(x + 8.0), 1.0).ok()?;
    let jkr = contact.v_stick_jkr();
    let c = Collider::new(contact, law, t_vis)
        .ok()?
        .with_options(cfg.solver)
        .ok()?;
    let r = c.collide(s * jkr).ok()?;
    Some((r.outcome, r.v_out / jkr))
}

/// The channel value of the collision at channel `q` (sigma when `bouncing`, else nu) of the
/// node at `(x, y)` with ratios `f`, `f_on` ([`super::format`]: `h = ln(|V_out| / V_stick)`);
/// NaN where it cannot be had (V_out of the wrong sign: the ODE answers there).
#[allow(clippy::too_many_arguments)]
pub fn node_channel(
    cfg: &BuildConfig,
    law: &CrackLaw,
    x: f64,
    y: f64,
    f: f64,
    f_on: f64,
    bouncing: bool,
    q: f64,
) -> f64 {
    let window = (f / f_on).ln();
    let s = if bouncing {
        f * q.exp()
    } else if window >= MIN_WINDOW {
        f * (-q * window).exp()
    } else {
        return f64::NAN;
    };
    // channels a little beyond the search limit, so that the cubic along them reaches it
    if s > F_TOP * 2.0 {
        return f64::NAN;
    }
    match collide(cfg, law, x, y, s) {
        Some((Outcome::Sticking, _)) | None => f64::NAN,
        Some((_, v_out)) => {
            // V_out < 0 above V_stick (bouncing), > 0 below (double collision)
            let w = if bouncing { -v_out / f } else { v_out / f };
            if w > 0.0 {
                w.ln()
            } else {
                f64::NAN
            }
        }
    }
}

/// The master tables' F and F_on at a point (both below F_TOP), if they vouch for them: the
/// thresholds a node's channels are placed by (its file keeps them to 8 figures only, too few
/// to place the channels of a narrow double-collision window again).
pub fn ratios(masters: &MasterTables, x: f64, y: f64, k: f64) -> Option<(f64, f64)> {
    let r = masters.ratios_at(x, y, k, F_TOP * (1.0 - 1e-3))?;
    Some((r.v_stick?, r.v_double_onset?))
}

/// e = -V_out / V_in from the channel value `h` at `s` V_stick,JKR with V_stick = `f`
/// V_stick,JKR.
pub(super) fn e_of(h: f64, f: f64, s: f64, bouncing: bool) -> f64 {
    let e = h.exp() * f / s;
    if bouncing {
        e
    } else {
        -e
    }
}

/// The node at `(x, y)`: the master tables' ratios and the channel values (NaN where the master
/// tables do not vouch).
fn node(cfg: &BuildConfig, law: &CrackLaw, masters: &MasterTables, x: f64, y: f64) -> NodeData {
    let (f, f_on) = ratios(masters, x, y, law.k()).unwrap_or((f64::NAN, f64::NAN));
    let mut h = Vec::with_capacity(cfg.sigma.len() + cfg.nu.len());
    for (bouncing, grid) in [(true, &cfg.sigma), (false, &cfg.nu)] {
        for &q in grid {
            h.push(if f.is_finite() {
                node_channel(cfg, law, x, y, f, f_on, bouncing, q)
            } else {
                f64::NAN
            });
        }
    }
    NodeData { x, f, f_on, h }
}

/// The largest miss in e, over the channels, of the local cubic along `nodes` (increasing x,
/// at least four) at `mid`, over the channels where both have a value.
fn row_miss(cfg: &BuildConfig, nodes: &[NodeData], x_s: f64, mid: &NodeData) -> f64 {
    let u: Vec<f64> = nodes.iter().rev().map(|p| (x_s - p.x).ln()).collect();
    let um = (x_s - mid.x).ln();
    let n = u.len();
    let a = crate::master::interp::stencil_start(crate::master::interp::interval(&u, um), n);
    let window = (mid.f / mid.f_on).ln();
    let mut worst = 0.0f64;
    for (c, &exact) in mid.h.iter().enumerate() {
        let bouncing = c < cfg.sigma.len();
        let q = if bouncing {
            cfg.sigma[c]
        } else {
            cfg.nu[c - cfg.sigma.len()]
        };
        let vals: Vec<f64> = (a..a + 4).map(|i| nodes[n - 1 - i].h[c]).collect();
        let interp = crate::master::interp::lagrange(&u[a..a + 4], &vals, um);
        // where a side has no value (beyond the search limit, or a node the master tables do
        // not vouch for) the table answers nothing there: no claim to check
        if !exact.is_finite() || !interp.is_finite() {
            continue;
        }
        let s = if bouncing {
            mid.f * q.exp()
        } else {
            mid.f * (-q * window).exp()
        };
        let miss = (e_of(interp, mid.f, s, bouncing) - e_of(exact, mid.f, s, bouncing)).abs();
        worst = worst.max(miss);
    }
    worst
}

/// `nodes` with every interval halved in u = ln(x_s - x) whose midpoint the cubic along the row
/// misses by more than `tol_e` in e, down to `min_u_step`; each midpoint computed to check it
/// becomes a node either way.
fn refine_row(
    cfg: &BuildConfig,
    law: &CrackLaw,
    masters: &MasterTables,
    y: f64,
    x_s: f64,
    mut nodes: Vec<NodeData>,
) -> Vec<NodeData> {
    let u = |x: f64| (x_s - x).ln();
    // intervals (by their left node's x) still to check
    let mut open: Vec<f64> = nodes[..nodes.len().saturating_sub(1)]
        .iter()
        .map(|p| p.x)
        .collect();
    while !open.is_empty() && nodes.len() >= 4 {
        let mids: Vec<(f64, NodeData, bool)> = open
            .par_iter()
            .filter_map(|&xa| {
                let i = nodes.iter().position(|p| p.x == xa)?;
                let xb = nodes.get(i + 1)?.x;
                let (ua, ub) = (u(xa), u(xb));
                if (ua - ub).abs() < 2.0 * cfg.min_u_step {
                    return None;
                }
                let xm = x_s - (0.5 * (ua + ub)).exp();
                let mid = node(cfg, law, masters, xm, y);
                let ok = row_miss(cfg, &nodes, x_s, &mid) <= cfg.tol_e;
                Some((xa, mid, ok))
            })
            .collect();
        open.clear();
        for (xa, mid, ok) in mids {
            if !ok {
                open.push(xa);
                open.push(mid.x);
            }
            nodes.push(mid);
        }
        nodes.sort_by(|a, b| a.x.total_cmp(&b.x));
    }
    nodes
}

/// One row of the table of `law`'s k at `y` ending at `x_s`.
pub(super) fn build_row(
    cfg: &BuildConfig,
    law: &CrackLaw,
    masters: &MasterTables,
    y: f64,
    x_s: f64,
) -> RowData {
    let mut xs = Vec::new();
    let mut x = cfg.x_min;
    while x < x_s - 1.0 {
        xs.push(x);
        x += cfg.x_step;
    }
    let mut u = (x_s - cfg.x_min).ln().min(0.0);
    while u >= cfg.d_min.ln() - 1e-9 {
        xs.push(x_s - u.exp());
        u -= cfg.u_step;
    }
    let nodes: Vec<NodeData> = xs
        .par_iter()
        .map(|&x| node(cfg, law, masters, x, y))
        .collect();
    let nodes = refine_row(cfg, law, masters, y, x_s, nodes);
    let cells = CellFlags::none(nodes.len().saturating_sub(1));
    RowData {
        y,
        x_s,
        nodes,
        cells,
    }
}

/// The table of the master tables' `k_index`-th k, on their end curves `ends`.
pub fn build_table(
    cfg: &BuildConfig,
    k_index: usize,
    ends: &EndsData,
    masters: &MasterTables,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<TableData, ThresholdsError> {
    let per = ends.per_octave / 3;
    let k = grid_k(ends.k0, 3, k_index);
    let law = CrackLaw::new(k)?;
    let (y0, y1) = cfg.y_range;
    let n = ((y1 - y0) / cfg.y_step).round() as usize + 1;
    let rows: Vec<RowData> = (0..n)
        .filter_map(|i| {
            let y = y0 + i as f64 * cfg.y_step;
            let at = (k_index * per) * ends.ny + ((y - ends.y0) / ends.dy).round() as usize;
            let x_s = *ends.x_s.get(at)?;
            x_s.is_finite().then(|| {
                let r = build_row(cfg, &law, masters, y, x_s);
                progress(&format!(
                    "restitution k = {k}, row y = {y}: {} nodes",
                    r.nodes.len()
                ));
                r
            })
        })
        .collect();
    let mut table = TableData {
        k,
        header: vec![
            format!("restitution table: h = ln(|V_out|/V_stick) (V_out < 0 bouncing, > 0 double collisions), over x = log10 c_D, y = log10(c_D c_a), k = {k}, at channels sigma = ln(V_in/V_stick) (bouncing) and nu = ln(V_stick/V_in)/ln(F/F_on) (double collisions), evenly in ln sigma + sigma and logit nu; V_stick and V_on from the master tables"),
            format!("nodes: one collision at rtol {} per channel; cells checked at their centres and quarters against the ODE to {} in e", number(cfg.solver.rtol), number(cfg.tol_e)),
        ],
        sigma: cfg.sigma.clone(),
        nu: cfg.nu.clone(),
        rows,
    };
    let all = vec![true; table.rows.len()];
    super::check::check_cells(cfg, &law, &mut table, masters, &all, progress);
    Ok(table)
}
