//! V_stick and the onset of double collisions (Sections 4.4 and 5): the public API and the rule
//! that turns the collisions of a search into the two thresholds.
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing.
//! `V_double_onset` is the sticking -> double transition and `V_stick` the double -> bouncing
//! transition (the paper's threshold velocity for sticking). Both are found from the collisions
//! a search integrates ([`crate::search`]): it ends with, for each transition, a *final bracket*
//! of two collisions at the search's own solver tolerance, one on each side, at most `rel_tol`
//! apart (relative). Then (`thresholds_from`):
//!
//! - **V_stick** is where V_out, the approach speed when the contact ends, crosses zero: V_out
//!   is continuous through V_stick (positive for a double collision, the spheres still
//!   approaching; negative for bouncing). Between a double collision `(v_lo, V_out,lo > 0)` and a
//!   bouncing one `(v_hi, V_out,hi < 0)` it is the zero of the line through them,
//!   `v_lo - V_out,lo (v_hi - v_lo)/(V_out,hi - V_out,lo)`, accurate to the solver's tolerance
//!   (well inside the bracket). Where the lower end sticks (no V_out), the bracket's centre.
//! - **V_double_onset** is the centre of its final bracket: the outcome jumps there (e from 0 to
//!   about -0.1), so no line interpolates it.
//! - Without any bouncing collision up to `v_max`, `v_stick` is `None` (and
//!   [`StickingThresholds::no_bouncing_below`] says how far was searched); without any collision
//!   that does not stick, `v_double_onset` is `None` too.
//! - `t_vis = 0` is the JKR limit: both are V_stick,JKR, without a collision.
//!
//! The double-collision window is narrow (2.6 % of V_stick at T_vis = 1e-9 s, 4e-6 at 1e-14 s),
//! so each transition has its own final bracket, from one shared set of classified speeds.

use crate::search::{Search, Seen, Transition};
use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Method, Outcome, SolverOptions};
use greenwood::CrackLaw;
use numerics::{format::number, OutOfRange};

pub use crate::search::hints::{Hint, HintChain, HINT_NEIGHBOURS, HINT_SPREAD_ONE};

/// The result rule: the thresholds from the final brackets of a finished search (see the
/// module documentation).
fn thresholds_from(search: &Search) -> StickingThresholds {
    let v_stick = search.final_bracket(Transition::Stick).map(v_out_zero);
    let v_double_onset = search
        .final_bracket(Transition::DoubleOnset)
        .map(|(lo, hi)| 0.5 * (lo.v + hi.v));
    StickingThresholds {
        t_vis: search.t_vis(),
        v_stick,
        v_double_onset,
        v_stick_jkr: search.v_jkr,
        v_max: search.v_max,
        collisions: search.seen.len(),
        steps: search.steps,
        method: ThresholdMethod::Search,
    }
}

/// Where V_out crosses zero between the ends of V_stick's final bracket (a double collision
/// below, a bouncing one above): the zero of the line through them; the bracket's centre when
/// the lower end sticks (no V_out) or the line's zero falls outside.
fn v_out_zero((lo, hi): (Seen, Seen)) -> f64 {
    let center = 0.5 * (lo.v + hi.v);
    if lo.outcome != Outcome::DoubleCollision {
        return center;
    }
    let p = lo.v - lo.v_out * (hi.v - lo.v) / (hi.v_out - lo.v_out);
    if p.is_finite() && p >= lo.v && p <= hi.v {
        p
    } else {
        center
    }
}

/// Highest impact speed any search integrates (m/s): 10 km/s is far above the collision speeds
/// of dust and ice grains (tens of m/s) and far beyond where contact mechanics applies.
pub const V_SEARCH_LIMIT: f64 = 1e4;

/// Default highest impact speed searched, in units of V_stick,JKR (capped at
/// [`V_SEARCH_LIMIT`]): where bouncing exists at all in Figures 4-5, V_stick is below
/// 60 V_stick,JKR; beyond 1000 the drag makes every collision stick.
pub const DEFAULT_V_MAX_OVER_JKR: f64 = 1e3;

/// Default relative width of the final brackets ([`SearchOptions::rel_tol`]), as the CLI's
/// `--rel-tol` and Python's `rel_tol`.
pub const DEFAULT_REL_TOL: f64 = 1e-6;

/// How a threshold is answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ThresholdMethod {
    /// The exact search: 20-100 collisions, milliseconds.
    Search,
    /// The master tables ([`crate::MasterTables`], the default): about a microsecond, within
    /// 1e-5 of the search where they vouch for their accuracy; elsewhere (a thin band at the
    /// cliff, k outside 0.005-0.05, a `rel_tol` below [`crate::master::TABLE_REL_TOL`] other
    /// than the default [`crate::DEFAULT_REL_TOL`]) the exact search answers, and the result
    /// says so.
    #[default]
    Table,
}

impl ThresholdMethod {
    /// `search` or `table`.
    pub fn name(&self) -> &'static str {
        match self {
            ThresholdMethod::Search => "search",
            ThresholdMethod::Table => "table",
        }
    }

    /// The method by name: `search` or `table` (any case).
    pub fn from_name(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "search" => Some(ThresholdMethod::Search),
            "table" => Some(ThresholdMethod::Table),
            _ => None,
        }
    }
}

/// Settings of a threshold search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchOptions {
    /// Relative width of the final brackets (dimensionless). Default [`DEFAULT_REL_TOL`] (1e-6).
    pub rel_tol: f64,
    /// Highest impact speed tried (m/s, at most [`V_SEARCH_LIMIT`]); `None` means
    /// [`DEFAULT_V_MAX_OVER_JKR`] V_stick,JKR. Without bouncing below it the result says so
    /// instead of returning a number.
    pub v_max: Option<f64>,
    /// Settings of each collision; the default is [`SearchOptions::default_solver`].
    pub solver: SolverOptions,
    /// Integrate the two collisions of each round on two threads (the result is the same).
    /// Default on.
    pub parallel: bool,
    /// Thresholds expected from a neighbouring point of a sweep (m/s): the first round tries
    /// just below `v_double_onset` and just above `v_stick` instead of bracketing from
    /// V_stick,JKR. A wrong hint costs one round, never the result. Default none.
    pub hint: Option<Hint>,
    /// Start a collision at its rebound, interpolated between two collisions close by (or
    /// extrapolated from two just beside it), instead of at first contact, where that is
    /// accurate (a third to a half of the cost; [`dynamics::Collider::collide_from`]). It moves
    /// V_stick by less than 1e-7 relative and the onset of double collisions (the centre of its
    /// final bracket) by less than that bracket (`docs/performance.md`, "Rebound restarts" and
    /// "Accuracy"). Default on; off for a reference.
    pub restarts: bool,
    /// How to answer: the master tables where they vouch for their accuracy (the default) or
    /// the exact search ([`ThresholdMethod`]).
    pub method: ThresholdMethod,
}

impl SearchOptions {
    /// Collision settings for threshold searches: relative tolerance 1e-8 (absolute 1e-11), which
    /// moves V_stick and V_double_onset by at most 2e-7 relative from a BDF reference at rtol
    /// 1e-11 (CO2 and H2O, T_vis = 1e-14..1e-8 s; `docs/performance.md`, "Tolerance ladder"),
    /// inside the bracket tolerance of 1e-6.
    pub fn default_solver() -> SolverOptions {
        SolverOptions {
            rtol: 1e-8,
            atol: 1e-11,
            ..SolverOptions::default()
        }
    }

    /// A reference search, against which the defaults are measured (`docs/performance.md`,
    /// "Accuracy" and "Tolerance ladder"): brackets of relative width 1e-9, BDF at rtol 1e-11
    /// (absolute 1e-14), every collision from first contact (no rebound restarts). About 20
    /// times the cost of the default.
    ///
    /// # Example
    /// ```
    /// use thresholds::{Method, SearchOptions};
    /// let r = SearchOptions::reference();
    /// assert_eq!((r.rel_tol, r.solver.rtol, r.solver.method, r.restarts), (1e-9, 1e-11, Method::Bdf, false));
    /// ```
    pub fn reference() -> SearchOptions {
        SearchOptions {
            rel_tol: 1e-9,
            solver: SolverOptions {
                method: Method::Bdf,
                rtol: 1e-11,
                atol: 1e-14,
                ..SolverOptions::default()
            },
            restarts: false,
            ..SearchOptions::exact()
        }
    }

    /// The default settings with the exact search for every threshold
    /// ([`ThresholdMethod::Search`]), as `--method search` and `method="search"`.
    ///
    /// # Example
    /// ```
    /// use thresholds::{SearchOptions, ThresholdMethod};
    /// assert_eq!(SearchOptions::exact().method, ThresholdMethod::Search);
    /// assert_eq!(SearchOptions::default().method, ThresholdMethod::Table);
    /// ```
    pub fn exact() -> SearchOptions {
        SearchOptions {
            method: ThresholdMethod::Search,
            ..SearchOptions::default()
        }
    }

    /// Checks every field: `1e-15 < rel_tol < 0.5`, `0 < v_max <= 1e4` m/s, valid solver settings.
    pub fn validate(&self) -> Result<(), OutOfRange> {
        if !(self.rel_tol.is_finite() && self.rel_tol > 1e-15 && self.rel_tol < 0.5) {
            return Err(OutOfRange::new(
                "rel_tol",
                self.rel_tol,
                "1e-15 < rel_tol < 0.5",
                "dimensionless",
            ));
        }
        if let Some(v) = self.v_max {
            if !(v > 0.0 && v <= V_SEARCH_LIMIT) {
                return Err(OutOfRange::new(
                    "v_max",
                    v,
                    format!("0 < v_max <= {}", number(V_SEARCH_LIMIT)),
                    "m/s",
                ));
            }
        }
        self.solver.validate()
    }

    /// The highest speed searched (m/s) for a contact with JKR threshold `v_stick_jkr` (m/s).
    pub fn v_max_for(&self, v_stick_jkr: f64) -> f64 {
        self.v_max
            .unwrap_or((DEFAULT_V_MAX_OVER_JKR * v_stick_jkr).min(V_SEARCH_LIMIT))
    }

    /// A warning where a `v_max` given lies below `v_stick_jkr` (m/s), the least V_stick at any
    /// T_vis (Section 5.1: V_stick grows from V_stick,JKR as T_vis grows): no collision bounces
    /// below it, so "no bouncing below v_max" says nothing of the grains (often a slip of
    /// units). `v_max_as` names the limit as the user gave it (`"--v-max "`, `"v_max="`).
    /// `None` for the default limit, which lies far above.
    ///
    /// ```
    /// # use thresholds::SearchOptions;
    /// let opts = SearchOptions { v_max: Some(0.01), ..SearchOptions::default() };
    /// let w = opts.v_max_warning(0.0166, "v_max=").unwrap();
    /// assert!(w.starts_with("v_max=0.01 m/s is below V_stick,JKR = 0.0166 m/s"));
    /// assert!(SearchOptions::default().v_max_warning(0.0166, "v_max=").is_none());
    /// ```
    pub fn v_max_warning(&self, v_stick_jkr: f64, v_max_as: &str) -> Option<String> {
        let v_max = self.v_max.filter(|&v| v < v_stick_jkr)?;
        Some(format!(
            "{v_max_as}{} m/s is below V_stick,JKR = {} m/s, the least V_stick at any T_vis: no collision bounces below it",
            number(v_max),
            number(v_stick_jkr)
        ))
    }
}

impl Default for SearchOptions {
    fn default() -> Self {
        Self {
            rel_tol: DEFAULT_REL_TOL,
            v_max: None,
            solver: Self::default_solver(),
            parallel: true,
            hint: None,
            restarts: true,
            method: ThresholdMethod::Table,
        }
    }
}

/// The sticking thresholds of one contact at one relaxation time (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StickingThresholds {
    /// Relaxation time T_vis (s).
    pub t_vis: f64,
    /// Threshold velocity for sticking V_stick: double collision -> bouncing (m/s); `None` when no
    /// collision bounces below [`StickingThresholds::v_max`].
    pub v_stick: Option<f64>,
    /// Sticking -> double-collision transition (m/s); `None` when every collision below `v_max` sticks.
    pub v_double_onset: Option<f64>,
    /// JKR threshold V_stick,JKR (Section 5.1), the T_vis -> 0 limit (m/s).
    pub v_stick_jkr: f64,
    /// Highest impact speed searched (m/s).
    pub v_max: f64,
    /// Number of collisions integrated.
    pub collisions: usize,
    /// Solver steps over all collisions (the cost of the search).
    pub steps: usize,
    /// Which answered: the exact search or the master table. At T_vis = 0 (the JKR limit,
    /// answered in closed form by neither) the method that was asked for.
    pub method: ThresholdMethod,
}

impl StickingThresholds {
    /// This result as the hint for a neighbouring point (`None` without both thresholds).
    pub fn as_hint(&self) -> Option<Hint> {
        Hint::from_thresholds(self.v_double_onset, self.v_stick)
    }

    /// The speed (m/s) up to which no collision bounced when there is no V_stick, else `None`.
    pub fn no_bouncing_below(&self) -> Option<f64> {
        self.v_stick.is_none().then_some(self.v_max)
    }
}

/// V_stick and V_double_onset of `contact` at relaxation time `t_vis` (s, >= 0) with the crack
/// law `law` (its k). `t_vis = 0` is the JKR limit: both equal V_stick,JKR.
///
/// Every round integrates two impact speeds, concurrently when [`SearchOptions::parallel`] is set
/// (two cores halve the wall time); the speeds chosen depend only on the outcomes seen, so the
/// result is the same either way. How the speeds are chosen: [`crate::search`]. With
/// [`SearchOptions::method`] = [`ThresholdMethod::Table`] the master table answers where it
/// vouches for its accuracy (the result's `method` says which answered).
///
/// # Example
/// ```
/// use thresholds::{sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions};
/// // Section 4.4: CO2, R1 = 60 um, T_vis = 1e-9 s, k = 0.01: V_stick = 4.14 cm/s (the first
/// // bouncing speed on the paper's 0.01 cm/s grid), onset of double collisions 4.04 cm/s
/// let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
/// let th = sticking_thresholds(&contact, &CrackLaw::new(0.01)?, 1e-9, &SearchOptions::default())?;
/// let v_stick = th.v_stick.expect("bounces below the search limit");
/// assert!(v_stick > 0.0413 && v_stick <= 0.0414);
/// assert!(th.v_double_onset.unwrap() > 0.0403 && th.v_double_onset.unwrap() <= 0.0404);
/// # Ok::<(), thresholds::ThresholdsError>(())
/// ```
#[doc(alias = "v_stick")]
#[doc(alias = "V_stick")]
#[doc(alias = "threshold velocity for sticking")]
pub fn sticking_thresholds(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    opts: &SearchOptions,
) -> Result<StickingThresholds, ThresholdsError> {
    opts.validate()?;
    if !(t_vis.is_finite() && t_vis >= 0.0) {
        return Err(
            OutOfRange::new("t_vis", t_vis, ">= 0 and finite (0 is the JKR limit)", "s").into(),
        );
    }
    let v_jkr = contact.v_stick_jkr();
    if t_vis == 0.0 {
        return Ok(StickingThresholds {
            t_vis,
            v_stick: Some(v_jkr),
            v_double_onset: Some(v_jkr),
            v_stick_jkr: v_jkr,
            v_max: opts.v_max_for(v_jkr),
            collisions: 0,
            steps: 0,
            method: opts.method,
        });
    }
    if opts.method == ThresholdMethod::Table {
        if let Some(th) = crate::master::from_table(contact, law, t_vis, opts) {
            return Ok(th);
        }
    }
    let mut search = Search::new(contact, law, t_vis, opts)?;
    search.run()?;
    Ok(thresholds_from(&search))
}

/// `sticking_thresholds` over a sequence of relaxation times (s), each search started from the
/// thresholds of the previous points (see [`SearchOptions::hint`], [`Hint::extrapolated`]). Use
/// an increasing or decreasing sequence: neighbours then have close thresholds.
pub fn sweep_t_vis(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: &[f64],
    opts: &SearchOptions,
) -> Result<Vec<StickingThresholds>, ThresholdsError> {
    let mut out: Vec<StickingThresholds> = Vec::with_capacity(t_vis.len());
    let mut chain = HintChain::default();
    for &t in t_vis {
        let o = SearchOptions {
            hint: chain.next(t, contact.v_stick_jkr()).or(opts.hint),
            ..*opts
        };
        let th = sticking_thresholds(contact, law, t, &o)?;
        chain.push(t, th.as_hint());
        out.push(th);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The zero of the line through (1, 0.1) and (2, -0.3) is 1.25; a sticking lower end has no
    /// V_out, so the centre; a line whose zero falls outside (both ends bounce) gives the centre.
    #[test]
    fn v_stick_is_the_zero_of_v_out_between_the_ends() {
        let double = Seen::at(1.0, Outcome::DoubleCollision, 0.1);
        let bounce = Seen::at(2.0, Outcome::Bouncing, -0.3);
        assert!((v_out_zero((double, bounce)) - 1.25).abs() < 1e-15);
        let stick = Seen::at(1.0, Outcome::Sticking, 0.0);
        assert_eq!(v_out_zero((stick, bounce)), 1.5);
        let far = Seen::at(1.0, Outcome::DoubleCollision, -0.1);
        assert_eq!(v_out_zero((far, bounce)), 1.5);
    }
}
