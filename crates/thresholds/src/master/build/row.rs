//! One row of constant y: its body (F and F_on against u = ln(x_s - x)) and its strip (F_on
//! against w = ln(x_on - x)), each refined until the local cubic matches the exact search at
//! every interval's midpoint, and vouched for only where it does and the default search agrees
//! with the nodes.

use super::{agrees, default_search, rel_diff, search, BuildConfig, Cache, Point};
use crate::master::format::{increasing_up_to, PieceData, RowData, F_TOP};
use crate::master::interp::local_cubic;
use crate::SearchOptions;
use greenwood::CrackLaw;

/// The narrowest strip tabulated (in x): it must hold a few nodes between 2 strip widths and
/// [`BuildConfig::d_min`] from its end; narrower strips (y above about 2.5) are answered by the
/// search.
pub const STRIP_MIN: f64 = 2.5e-5;

/// Beyond x_s (and x_on) a row is checked for no bouncing (no double collision) up to F_TOP at
/// these distances, so that "beyond the end the ratio exceeds F_TOP" is an answer.
const BEYOND: [f64; 3] = [1e-3, 0.1, 1.0];

/// Which ratios a piece holds: the body both (F, F_on), the strip F_on only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// The body: F and F_on.
    Body,
    /// The strip: F_on.
    Strip,
}

impl Kind {
    fn values(self) -> &'static [usize] {
        match self {
            Kind::Body => &[0, 1],
            Kind::Strip => &[1],
        }
    }
}

/// A node's ratios as a piece of `kind` takes them: a body node needs both (`None` otherwise).
pub(super) fn ratios(p: Point, kind: Kind) -> Option<[f64; 2]> {
    match (kind, p) {
        (Kind::Body, Point::Bounce { f_stick, f_onset }) => Some([f_stick, f_onset]),
        (Kind::Strip, p) => p.onset().map(|o| [f64::NAN, o]),
        _ => None,
    }
}

/// Whether the interval `[a, b]` (x) of a piece ending at `end` is still halved: while either
/// coordinate is coarse, far from the end x ([`BuildConfig::min_x_step`]), near it u
/// ([`BuildConfig::min_u_step`]); else it is of the finest width.
pub(super) fn splittable(cfg: &BuildConfig, end: f64, a: f64, b: f64) -> bool {
    let u = |x: f64| (end - x).ln();
    b - a > cfg.min_x_step * 1.5 || u(a) - u(b) > cfg.min_u_step * 1.5
}

/// The nodes of a piece: `(x, [F, F_on])`, increasing in x.
type Nodes = Vec<(f64, [f64; 2])>;

/// The ratio `v` interpolated at u from `nodes` (x increasing) of a piece ending at `end`: the
/// local cubic in u = ln(end - x) of ln(ratio - 1).
pub fn interpolate(nodes: &[(f64, [f64; 2])], end: f64, v: usize, u: f64) -> f64 {
    let us: Vec<f64> = nodes.iter().rev().map(|n| (end - n.0).ln()).collect();
    let gs: Vec<f64> = nodes.iter().rev().map(|n| (n.1[v] - 1.0).ln()).collect();
    1.0 + local_cubic(&us, &gs, u).exp()
}

/// A piece ending at `end` with first nodes `xs`, refined and vouched for (see the module
/// documentation).
fn piece(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    y: f64,
    end: f64,
    xs: &[f64],
    kind: Kind,
) -> PieceData {
    let u = |x: f64| (end - x).ln();
    let eval = |x: f64| ratios(cache.node(cfg, law, x, y), kind);
    let mut nodes: Nodes = xs.iter().filter_map(|&x| eval(x).map(|r| (x, r))).collect();
    // vouched for up to here (in x), for each ratio
    // where each ratio failed a check that no further node can mend: nothing beyond the
    // farther of the two is vouched for, so nothing beyond it is refined (where F jumps to the
    // hyper-speed bouncing of soft grains, or its nodes are fuzzy, halving would go on to the
    // finest step for nothing)
    let mut beyond_repair = [f64::INFINITY; 2];
    let mut x_hi = loop {
        let mut added = Vec::new();
        let mut failed = [f64::INFINITY; 2];
        let blocked = kind
            .values()
            .iter()
            .map(|&v| beyond_repair[v])
            .fold(f64::NEG_INFINITY, f64::max);
        for w in nodes.windows(2) {
            let (a, b) = (w[0].0, w[1].0);
            if a >= blocked {
                break;
            }
            let u_mid = 0.5 * (u(a) + u(b));
            let mid = end - u_mid.exp();
            let exact = eval(mid);
            let mut bad = [false; 2];
            for &v in kind.values() {
                let good = exact.is_some_and(|e| {
                    rel_diff(Some(interpolate(&nodes, end, v, u_mid)), Some(e[v])) <= cfg.tol
                });
                if !good {
                    bad[v] = true;
                    failed[v] = failed[v].min(a);
                }
            }
            let ok = !bad[0] && !bad[1];
            match exact {
                Some(e) if !ok && splittable(cfg, end, a, b) => added.push((mid, e)),
                _ if !ok => {
                    for v in 0..2 {
                        if bad[v] {
                            beyond_repair[v] = beyond_repair[v].min(a);
                        }
                    }
                }
                _ => {}
            }
        }
        if added.is_empty() {
            break failed;
        }
        nodes.extend(added);
        nodes.sort_by(|a, b| a.0.total_cmp(&b.0));
    };
    // a failure no node could mend, met in an earlier round, ends the range too (the last
    // round skips it; until 2026-11-28 it was lost there: `midpoints.rs`)
    for (hi, stop) in x_hi.iter_mut().zip(beyond_repair) {
        *hi = hi.min(stop);
    }
    // the default search must agree with every node up to the vouched end
    let last = nodes.last().map_or(f64::NEG_INFINITY, |n| n.0);
    for (v, hi) in x_hi.iter_mut().enumerate() {
        *hi = if kind.values().contains(&v) {
            hi.min(last)
        } else {
            f64::NEG_INFINITY
        };
    }
    for i in 0..nodes.len() {
        let (x, r) = nodes[i];
        if x > x_hi[0].max(x_hi[1]) {
            break;
        }
        if !(r[0] >= cfg.agree_from || r[1] >= cfg.agree_from) {
            continue;
        }
        let d = default_search(cfg, law, x, y);
        for (v, theirs) in [(0, d.stick()), (1, d.onset())] {
            if x <= x_hi[v] && !agrees(cfg, theirs, r[v]) {
                x_hi[v] = if i == 0 {
                    f64::NEG_INFINITY
                } else {
                    nodes[i - 1].0
                };
            }
        }
    }
    PieceData {
        x: nodes.iter().map(|n| n.0).collect(),
        f_stick: nodes.iter().map(|n| n.1[0]).collect(),
        f_onset: nodes.iter().map(|n| n.1[1]).collect(),
        // vouched where the distance to the end is at least this
        d_lo: x_hi.map(|h| end - h),
        d_lb: None,
    }
}

/// The first nodes of a piece ending at `end`, from `x_start`: every `x_step` while more than a
/// decade from the end (`d > 1`), then every `u_step` in u = ln(end - x) down to `d_min`.
fn first_nodes(cfg: &BuildConfig, x_start: f64, end: f64) -> Vec<f64> {
    let mut xs = Vec::new();
    let mut x = x_start;
    while x < end - 1.0 {
        xs.push(x);
        x += cfg.x_step;
    }
    let mut u = (end - x_start).ln().min(0.0);
    while u >= cfg.d_min.ln() - 1e-9 {
        xs.push(end - u.exp());
        u -= cfg.u_step;
    }
    xs
}

/// Whether nothing bounces (double-collides, for the onset) below `f_top` V_stick,JKR beyond
/// `end` (at the distances [`BEYOND`]).
pub(super) fn none_beyond(
    cfg: &BuildConfig,
    law: &CrackLaw,
    y: f64,
    end: f64,
    onset: bool,
    f_top: f64,
) -> bool {
    let opts = SearchOptions {
        rel_tol: cfg.rel_tol,
        solver: cfg.solver,
        ..SearchOptions::exact()
    };
    BEYOND.iter().all(|&d| {
        let p = search(cfg, law, end + d, y, f_top, &opts);
        if onset {
            p == Point::NoBounce
        } else {
            matches!(p, Point::NoBounce | Point::OnsetOnly { .. })
        }
    })
}

/// The ratios increase with x along the nodes (to the nodes' noise, [`crate::master::format::NODE_NOISE`]).
fn increasing(p: &PieceData) -> bool {
    increasing_up_to(&p.f_stick) == f64::INFINITY && increasing_up_to(&p.f_onset) == f64::INFINITY
}

/// The row at `y` with ends `x_s`, `x_on` (from the end curves).
pub fn build_row(
    cfg: &BuildConfig,
    law: &CrackLaw,
    cache: &Cache,
    y: f64,
    x_s: f64,
    x_on: f64,
) -> RowData {
    let body = piece(
        cfg,
        law,
        cache,
        y,
        x_s,
        &first_nodes(cfg, cfg.x_min, x_s),
        Kind::Body,
    );
    let width = x_on - x_s;
    let strip = if width >= STRIP_MIN {
        let xs: Vec<f64> = first_nodes(cfg, x_s - width, x_on);
        piece(cfg, law, cache, y, x_on, &xs, Kind::Strip)
    } else {
        PieceData {
            d_lo: [f64::INFINITY; 2],
            ..PieceData::default()
        }
    };
    let clear =
        none_beyond(cfg, law, y, x_s, false, F_TOP) && none_beyond(cfg, law, y, x_on, true, F_TOP);
    RowData {
        y,
        x_s,
        x_on,
        monotone: increasing(&body) && increasing(&strip) && clear,
        none_beyond: if clear { F_TOP } else { 0.0 },
        body,
        strip,
    }
}
