//! Building the master tables with the exact search (`cargo xtask master-table`), and checking
//! committed ones against it (`--check`).
//!
//! 1. **End curves** ([`ends`]): on a grid of y (every 1/64) and k (12 an octave), x_s, the x
//!    where one collision at [`F_TOP`] V_stick,JKR stops bouncing (there F = F_TOP; a root of
//!    V_out in x, continuous through the double-collision side), and x_on, where it starts to
//!    stick (F_on = F_TOP; bisection), both to 1e-10 in x.
//! 2. **Rows** ([`row`]): for each table k (k = 0.005 2^(i/3)) and each y, nodes from x = -17
//!    every 0.5 up to one decade of c_D from x_s, then every 0.5 in u = ln(x_s - x) down to
//!    x_s - 1e-5; every interval is checked at its midpoint in u against the local cubic and
//!    halved where the two differ by more than [`BuildConfig::tol`]; the default search must
//!    agree with each node to [`BuildConfig::agree`]. The strip (x_s to x_on) likewise in
//!    w = ln(x_on - x), for F_on.
//! 3. **Cells** ([`cells`]): rows every 0.5 in y; each cell is checked at mid-y on the nodes of
//!    its two rows (at the distance to the interpolated end) and a row added in its middle where
//!    the check fails, down to 1/64.
//! 4. **k intervals** ([`kcheck`]): between tables of neighbouring k, the quintic in ln k is
//!    checked at the middle k in every eighth of y (`BuildConfig::kcheck_dy`); in plain x past
//!    a first miss on while it holds at nine points around each check node
//!    (`BuildConfig::kcheck_spread_tol`).
//!
//! A node is the exact search ([`crate::sticking_thresholds`]) at a synthetic contact whose
//! dimensionless numbers are the node's ([`synthetic`]), at `rel_tol` 1e-8 with collisions at
//! rtol 1e-10: the search's own error (up to a few 1e-6 of V_stick within 1e-3 of the cliff
//! at the default rtol 1e-8) stays out of the nodes.

pub mod beyond;
pub mod cells;
pub mod check;
pub mod ends;
pub mod kcheck;
pub mod midpoints;
pub mod revouch;
pub mod row;

use super::format::F_TOP;
use crate::{sticking_thresholds, SearchOptions, ThresholdsError};
use contact::{Contact, Geometry, Material};
use dynamics::SolverOptions;
use greenwood::CrackLaw;
use std::collections::HashMap;
use std::sync::Mutex;

/// The settings of a build.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildConfig {
    /// Relative width of the final brackets of each node's search: 1e-8.
    pub rel_tol: f64,
    /// The collisions of a node's search: rtol 1e-10 (atol 1e-13), a hundredth of the default
    /// search's, so that a node is the search's limit rather than one of its approximations.
    pub solver: SolverOptions,
    /// The largest interpolation error a check accepts, relative to the ratio: 2e-6, a fifth of
    /// the 1e-5 the tables promise, for the error between checks and of the k interpolation.
    pub tol: f64,
    /// The default search must agree with a node to this (relative) where the node's ratio is
    /// at most [`BuildConfig::agree_up_to`]: 8e-6, so that with the interpolation's
    /// [`BuildConfig::tol`] the tables stay within the 1e-5 they promise against it. Near the
    /// cliff the default search's own error grows (V_out is nearly flat in V_in there: up to
    /// 5.4e-6 from the reference search 1e-4 to 1e-3 in x from x_s, where the rows are within
    /// 1.3e-6 of it, and up to 7.4e-6 from the nodes at F of 900-1000; [`revouch`]); where it
    /// exceeds this, the tables stop vouching and the search answers (the band at the ends).
    /// The tables built before `revouch` used 4e-6.
    pub agree: f64,
    /// The largest ratio held to [`BuildConfig::agree`]: 1000, the default search limit
    /// ([`crate::DEFAULT_V_MAX_OVER_JKR`]), beyond which a default search says "no bouncing
    /// below v_max" and the tables' verdict is all it is compared on.
    pub agree_up_to: f64,
    /// Above [`BuildConfig::agree_up_to`] the default search must agree with a node to this
    /// only: 1e-4. There (F of 1000 to 2200 within 1e-4 of the cliff, CO2-like rows) the
    /// default search scatters by up to 3.5e-5 around the nodes while the rows' midpoints lie
    /// within 1e-6 of new nodes: the scatter is the default search's, and the tables are held
    /// to the nodes (the search at rel_tol 1e-8, collisions at rtol 1e-10); the looser check
    /// still catches a default search that found another root.
    pub agree_beyond: f64,
    /// Where the tables serve as lower bounds only (`--part bounds`, [`revouch::Pass::Bounds`]),
    /// the default search must lie within this (relative) of a node, and beyond the limit find
    /// at least the ratio at it less this: 1e-3, seven times the 1.4e-4 it strays by near the
    /// cliff of CO2-like rows, a tenth of the margin an answer from a lower bound keeps from
    /// the search limit ([`crate::master::BOUND_MARGIN`], 1e-2), so that the
    /// verdict "above the search limit" is the default search's. It still catches a default
    /// search that found another root.
    pub bound_agree: f64,
    /// Nodes with both ratios below this are not compared with the default search: there (far
    /// from the cliff) the two agree to 1e-7 (`docs/performance.md`, "Accuracy").
    pub agree_from: f64,
    /// The smallest x = log10 c_D of a row: -17, below T_vis = 1e-16 s for every grain of the
    /// domain (the JKR limit, where F has converged to 1e-9).
    pub x_min: f64,
    /// The first spacing of the nodes in x, more than a decade of c_D from the end.
    pub x_step: f64,
    /// The first spacing of the nodes in u = ln(distance to the end), within a decade.
    pub u_step: f64,
    /// The closest node to an end (in x): 1e-5, where the default search's own error near the
    /// cliff reaches 1e-5 (CO2-like rows, y ~ 0).
    pub d_min: f64,
    /// The finest spacing of nodes in x.
    pub min_x_step: f64,
    /// The finest spacing of nodes in u.
    pub min_u_step: f64,
    /// The range of y = log10(c_D c_a): the domain's -5.8 to 5.1 (gamma_SV 0.01-0.3 J/m^2,
    /// E 0.5-200 GPa, nu 0.1-0.45, reduced radius 5 nm - 1 cm; 99.99 % of its points lie in
    /// -5.5 .. 4.5) and a row or more beyond.
    pub y_range: (f64, f64),
    /// The first spacing of the rows.
    pub y_step: f64,
    /// The finest spacing of the rows (the end curves' grid step).
    pub min_y_step: f64,
    /// The largest log10 c_a of a node (see the module documentation of `master`).
    pub z_clamp: f64,
    /// The tables' k: `k0 2^(i / per_octave)`, `i < count`.
    pub table_k: (f64, usize, usize),
    /// The end curves' k grid, likewise (a refinement of the tables').
    pub ends_k: (f64, usize, usize),
    /// The y bins of the k checks (their width). Each bin is checked at its middle y and
    /// vouched for from it: 0.125 (2026-11-27, seventh sitting) against 0.25 before put every
    /// point within 1/16 in y of a check and answered 14 more of 1e5 random points of the whole
    /// domain (one fewer elsewhere), each within 2.4e-6 of the reference search; 0.0625 answered
    /// fewer than 0.25 (a finer bin meets more of the narrow failures near the kink).
    pub kcheck_dy: f64,
    /// Past the first check point of a k check in plain x that misses by more than
    /// [`BuildConfig::tol`], the interval is still vouched for, check point by check point,
    /// while the polynomial in ln k stays within this (relative) of the exact nodes at nine
    /// points around it (the bin's middle and edges in y, a quarter, half and three quarters
    /// of the interval in ln k) and within [`BuildConfig::kcheck_default_agree`] of the
    /// default search at the middle: 4e-6. Near the kink of the cliff the tables' own
    /// interpolation (in x between nodes, in y between rows) scatters by 1-4e-6 around the
    /// nodes without growing, and the first check above 2e-6 had stopped whole bins there
    /// (`docs/performance.md`, "The k checks past their first miss").
    pub kcheck_spread_tol: f64,
    /// The default search must lie within this (relative) of the polynomial in ln k at each
    /// check point that [`BuildConfig::kcheck_spread_tol`] vouches for: 5e-6, so that with the
    /// interpolation between check points the answers stay within the 1e-5 the tables promise
    /// against it.
    pub kcheck_default_agree: f64,
}

impl BuildConfig {
    /// The settings of the committed tables.
    pub fn standard() -> Self {
        Self {
            rel_tol: 1e-8,
            solver: SolverOptions {
                rtol: 1e-10,
                atol: 1e-13,
                ..SearchOptions::default_solver()
            },
            tol: 2e-6,
            agree: 8e-6,
            agree_up_to: crate::DEFAULT_V_MAX_OVER_JKR,
            agree_beyond: 1e-4,
            bound_agree: 1e-3,
            agree_from: 5.0,
            x_min: -17.0,
            x_step: 0.5,
            u_step: 0.5,
            d_min: 1e-5,
            min_x_step: 1.0 / 64.0,
            min_u_step: 1.0 / 64.0,
            y_range: (-6.0, 5.5),
            y_step: 0.5,
            min_y_step: 1.0 / 64.0,
            z_clamp: 8.0,
            table_k: (0.005, 3, 11),
            ends_k: (0.005, 12, 41),
            kcheck_dy: 0.125,
            kcheck_spread_tol: 4e-6,
            kcheck_default_agree: 5e-6,
        }
    }

    /// A converged search, against which the nodes and the default search are measured where
    /// they are least accurate (the second kind of bouncing, `docs/performance.md`, "Master
    /// tables", (15)): the standard settings with brackets of 1e-10 and BDF collisions at rtol
    /// 1e-12 (absolute 1e-15), a hundredth of a node's each. BDF at rtol 1e-13 moved its F by at
    /// most 9e-7 there; the default search and the nodes by up to 5.4e-5 and 8.2e-6. A few
    /// times a node's cost.
    ///
    /// # Example
    /// ```
    /// use thresholds::master::build::BuildConfig;
    /// use thresholds::Method;
    /// let c = BuildConfig::converged();
    /// assert_eq!((c.rel_tol, c.solver.rtol, c.solver.method), (1e-10, 1e-12, Method::Bdf));
    /// ```
    pub fn converged() -> Self {
        let mut cfg = Self::standard();
        cfg.rel_tol = 1e-10;
        cfg.solver.method = crate::Method::Bdf;
        cfg.solver.rtol = 1e-12;
        cfg.solver.atol = 1e-15;
        cfg
    }

    /// The k of the tables.
    pub fn table_ks(&self) -> Vec<f64> {
        let (k0, per, n) = self.table_k;
        (0..n).map(|i| grid_k(k0, per, i)).collect()
    }
}

/// The commit that built (or last grew) `table`, from its header: the nodes' provenance, which
/// a pass over a committed table records before the caller stamps its own commit.
pub fn built_at(table: &crate::master::format::TableData) -> &str {
    table
        .header
        .iter()
        .find_map(|h| h.strip_prefix("commit: "))
        .unwrap_or("an unknown commit")
}

/// `k0 2^(i / per_octave)`, exact at whole octaves.
pub fn grid_k(k0: f64, per_octave: usize, i: usize) -> f64 {
    let (whole, part) = (i / per_octave, i % per_octave);
    k0 * 2f64.powi(whole as i32) * 2f64.powf(part as f64 / per_octave as f64)
}

/// V_stick,JKR of the synthetic contacts (m/s): that of 60 um CO2 grains, so that every search
/// runs at ordinary speeds whatever the point (F_TOP V_stick,JKR = 200 m/s).
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

/// Density factors of the synthetic contacts tried in turn when a computation fails: the same
/// dimensionless problem, rounded differently.
pub const RETRY_DENSITY: [f64; 3] = [1.0, 1.37, 0.61];

/// The exact search at one point (ratios to V_stick,JKR).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Point {
    /// Both thresholds below the search limit.
    Bounce {
        /// F = V_stick / V_stick,JKR.
        f_stick: f64,
        /// F_on = V_double_onset / V_stick,JKR.
        f_onset: f64,
    },
    /// No bouncing below the limit, but double collisions from F_on on.
    OnsetOnly {
        /// F_on.
        f_onset: f64,
    },
    /// Every collision below the limit sticks.
    NoBounce,
    /// The search failed for every synthetic contact tried.
    Failed,
}

impl Point {
    /// F, where there is one.
    pub fn stick(self) -> Option<f64> {
        match self {
            Point::Bounce { f_stick, .. } => Some(f_stick),
            _ => None,
        }
    }

    /// F_on, where there is one.
    pub fn onset(self) -> Option<f64> {
        match self {
            Point::Bounce { f_onset, .. } | Point::OnsetOnly { f_onset } => Some(f_onset),
            _ => None,
        }
    }

    /// Ratio `v` (0: F, 1: F_on), where there is one.
    pub fn ratio(self, v: usize) -> Option<f64> {
        if v == 0 {
            self.stick()
        } else {
            self.onset()
        }
    }

    /// Whether this default search's ratio `v` is at least `floor`, or lies above its search
    /// limit (no value): what a lower bound claims of the stretch closer to the end than its
    /// limit (`revouch::Pass::Bounds`, the k checks). A search that failed proves nothing.
    pub fn at_least(self, v: usize, floor: f64) -> bool {
        match self {
            Point::Failed => false,
            p => p.ratio(v).is_none_or(|r| r >= floor),
        }
    }
}

/// The search at `(x, y)` (c_a clamped at `10^z_clamp`) with `opts` (its `v_max` set to
/// `f_max` V_stick,JKR), without a hint, so that a node can be recomputed to the bit.
pub fn search(
    cfg: &BuildConfig,
    law: &CrackLaw,
    x: f64,
    y: f64,
    f_max: f64,
    opts: &SearchOptions,
) -> Point {
    let y = y.min(x + cfg.z_clamp);
    for factor in RETRY_DENSITY {
        let Ok((contact, t_vis)) = synthetic(x, y, factor) else {
            return Point::Failed;
        };
        let jkr = contact.v_stick_jkr();
        let o = SearchOptions {
            v_max: Some(f_max * jkr),
            method: crate::ThresholdMethod::Search,
            ..*opts
        };
        if let Ok(th) = sticking_thresholds(&contact, law, t_vis, &o) {
            return match (th.v_stick, th.v_double_onset) {
                (Some(s), Some(o)) => Point::Bounce {
                    f_stick: s / jkr,
                    f_onset: o / jkr,
                },
                (None, Some(o)) => Point::OnsetOnly { f_onset: o / jkr },
                _ => Point::NoBounce,
            };
        }
    }
    Point::Failed
}

/// A node: the exact search of the build (`rel_tol` 1e-8, collisions at rtol 1e-10) up to
/// twice [`F_TOP`] V_stick,JKR.
pub fn node(cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Point {
    let opts = SearchOptions {
        rel_tol: cfg.rel_tol,
        solver: cfg.solver,
        ..SearchOptions::exact()
    };
    search(cfg, law, x, y, 2.0 * F_TOP, &opts)
}

/// The default search (what a user's `method="search"` runs) at the same point and limit.
pub fn default_search(cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Point {
    search(cfg, law, x, y, 2.0 * F_TOP, &SearchOptions::exact())
}

/// Whether the default search at each of the points `xs` (at `y`) finds ratio `v` at least
/// `floor`, or nothing below its search limit ([`Point::at_least`]): what a lower bound claims
/// of the stretch beyond its limit (`revouch::Pass::Bounds`, the k checks). `first` is the
/// default search already made at the first point, if it was (where the limit stopped).
pub fn default_search_at_least(
    cfg: &BuildConfig,
    law: &CrackLaw,
    y: f64,
    v: usize,
    floor: f64,
    xs: impl IntoIterator<Item = f64>,
    first: Option<Point>,
) -> bool {
    xs.into_iter().enumerate().all(|(j, x)| {
        let theirs = match first {
            Some(p) if j == 0 => p,
            _ => default_search(cfg, law, x, y),
        };
        theirs.at_least(v, floor)
    })
}

/// Nodes computed so far in one table's build, keyed by `(x, y)` to 1e-12: rows and cell checks
/// share them.
#[derive(Default)]
pub struct Cache(Mutex<HashMap<(i64, i64), Point>>);

impl Cache {
    fn key(x: f64, y: f64) -> (i64, i64) {
        ((x * 1e12).round() as i64, (y * 1e12).round() as i64)
    }

    /// The node at `(x, y)`, computed once.
    pub fn node(&self, cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Point {
        let key = Self::key(x, y);
        if let Some(p) = self.0.lock().ok().and_then(|m| m.get(&key).copied()) {
            return p;
        }
        let p = node(cfg, law, x, y);
        if let Ok(mut m) = self.0.lock() {
            m.insert(key, p);
        }
        p
    }
}

/// Whether the default search's ratio `theirs` agrees with a node's `ours`: to
/// [`BuildConfig::agree`] up to [`BuildConfig::agree_up_to`], to [`BuildConfig::agree_beyond`]
/// above it.
pub fn agrees(cfg: &BuildConfig, theirs: Option<f64>, ours: f64) -> bool {
    let tol = if ours <= cfg.agree_up_to {
        cfg.agree
    } else {
        cfg.agree_beyond
    };
    rel_diff(theirs, Some(ours)) <= tol
}

/// Two limits closer than this (relative) are the same: the limits are node distances, which
/// the text form keeps to the bit (a cell's limit equal to its rows' old one had every check
/// pass down to it; a node at a piece's limit is inside its vouched range).
pub(super) const SAME_LIMIT: f64 = 1e-12;

/// The relative difference of two ratios (infinite when either is missing).
pub fn rel_diff(a: Option<f64>, b: Option<f64>) -> f64 {
    match (a, b) {
        (Some(a), Some(b)) => (a / b - 1.0).abs(),
        _ => f64::INFINITY,
    }
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

    /// The grid's k are exact at whole octaves: 0.01 and 0.02 are tables of their own.
    #[test]
    fn grid_k_is_exact_at_octaves() {
        assert_eq!(grid_k(0.005, 3, 3), 0.01);
        assert_eq!(grid_k(0.005, 3, 6), 0.02);
        assert_eq!(grid_k(0.005, 12, 12), 0.01);
        assert!((grid_k(0.005, 3, 10) / 0.0504 - 1.0).abs() < 1e-3);
    }
}
