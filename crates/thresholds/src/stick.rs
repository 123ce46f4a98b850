//! V_stick and the onset of double collisions (Sections 4.4 and 5).
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing.
//! `V_double_onset` is the sticking -> double transition and `V_stick` the double -> bouncing
//! transition (the paper's threshold velocity for sticking). The double-collision window is narrow
//! (2.6 % of V_stick at T_vis = 1e-9 s, 4e-6 at 1e-14 s), so each transition is searched on its
//! own predicate ("not sticking", "bouncing") from one shared set of classified speeds.
//!
//! The search has three stages:
//! 1. [`Search::bracket`]: a sticking speed below and a bouncing speed above, starting just below
//!    V_stick,JKR (V_stick >= V_stick,JKR) or around a hint from a neighbouring sweep point;
//! 2. [`Search::refine`]: V_out is continuous through V_stick (positive for double collisions,
//!    negative for bouncing), so V_stick is found by regula falsi on V_out(V_in); the onset is a
//!    jump of the outcome (e from 0 to about -0.1), so it is bisected;
//! 3. [`Search::result`]: each threshold is the centre of its final bracket.
//!
//! Each round integrates two impact speeds, on two threads when asked; the speeds depend only on
//! the outcomes seen, so the result does not depend on the threads.

use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Collider, Outcome, SolverOptions};
use greenwood::{CrackLaw, OutOfRange};

/// Highest impact speed any search integrates (m/s): 10 km/s is far above the collision speeds
/// of dust and ice grains (tens of m/s) and far beyond where contact mechanics applies.
pub const V_SEARCH_LIMIT: f64 = 1e4;

/// Default highest impact speed searched, in units of V_stick,JKR (capped at
/// [`V_SEARCH_LIMIT`]): where bouncing exists at all in Figures 4-5, V_stick is below
/// 60 V_stick,JKR; beyond 1000 the drag makes every collision stick.
pub const DEFAULT_V_MAX_OVER_JKR: f64 = 1e3;

/// First lower trial, in units of V_stick,JKR: V_stick >= V_stick,JKR for every T_vis > 0, so a
/// speed just below it almost always sticks.
const FIRST_LOWER_OVER_JKR: f64 = 0.99;
/// First upper trial, in units of the first lower one: V_stick is within 1.6 V_stick,JKR for
/// T_vis up to about 1e-10 s (Figure 4), so one round often brackets it.
const FIRST_UPPER_OVER_LOWER: f64 = 1.6;
/// A hinted search first tries 2 % below the neighbour's onset and 2 % above its V_stick:
/// neighbours of a sweep grid of 8 points a decade differ by less.
const HINT_BELOW: f64 = 0.98;
/// See [`HINT_BELOW`].
const HINT_ABOVE: f64 = 1.02;
/// Growth of the upper trial per step while nothing bounces: 1.5 keeps the bracket of V_out
/// tight enough for regula falsi while reaching 1000 V_stick,JKR in 9 rounds.
const UPPER_GROWTH: f64 = 1.5;
/// Shrink factor of the lower trial while nothing sticks (rare: a wrong hint, extreme inputs).
const LOWER_SHRINK: f64 = 0.25;
/// Lowest speed tried, in units of V_stick,JKR, before declaring that nothing sticks.
const V_FLOOR_OVER_JKR: f64 = 1e-6;

/// Settings of a threshold search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchOptions {
    /// Relative width of the final brackets (dimensionless). Default 1e-6.
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
}

/// Expected thresholds, from a neighbouring point of a sweep (m/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hint {
    /// Expected V_double_onset (m/s).
    pub v_double_onset: f64,
    /// Expected V_stick (m/s).
    pub v_stick: f64,
}

impl SearchOptions {
    /// Collision settings for threshold searches: relative tolerance 1e-8 (absolute 1e-11), which
    /// moves V_stick and V_double_onset by less than 5e-8 relative from a 1e-11 reference
    /// (`docs/performance.md`), well inside the bracket tolerance of 1e-6.
    pub fn default_solver() -> SolverOptions {
        SolverOptions {
            rtol: 1e-8,
            atol: 1e-11,
            ..SolverOptions::default()
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
                return Err(OutOfRange::new("v_max", v, "0 < v_max <= 10000.0", "m/s"));
            }
        }
        self.solver.validate()
    }

    /// The highest speed searched for a contact with JKR threshold `v_stick_jkr` (m/s).
    pub fn v_max_for(&self, v_stick_jkr: f64) -> f64 {
        self.v_max
            .unwrap_or((DEFAULT_V_MAX_OVER_JKR * v_stick_jkr).min(V_SEARCH_LIMIT))
    }
}

impl Default for SearchOptions {
    fn default() -> Self {
        Self {
            rel_tol: 1e-6,
            v_max: None,
            solver: Self::default_solver(),
            parallel: true,
            hint: None,
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
}

impl StickingThresholds {
    /// This result as the hint for a neighbouring point (`None` without both thresholds).
    pub fn as_hint(&self) -> Option<Hint> {
        Some(Hint {
            v_double_onset: self.v_double_onset?,
            v_stick: self.v_stick?,
        })
    }

    /// The speed (m/s) up to which no collision bounced when there is no V_stick, else `None`.
    pub fn no_bouncing_below(&self) -> Option<f64> {
        self.v_stick.is_none().then_some(self.v_max)
    }
}

/// Every classified impact speed with its outcome and V_out.
#[derive(Debug, Default)]
struct Seen {
    points: Vec<(f64, Outcome, f64)>,
}

/// A transition between two classes of outcomes: the fastest speed below it and the slowest
/// above it seen so far (m/s).
type Bracket = (Option<f64>, Option<f64>);

impl Seen {
    fn record(&mut self, v: f64, outcome: Outcome, v_out: f64) {
        self.points.push((v, outcome, v_out));
    }

    /// V_out at a recorded speed.
    fn v_out_at(&self, v: f64) -> Option<f64> {
        self.points.iter().find(|p| p.0 == v).map(|p| p.2)
    }

    /// Smallest speed with `is_above`, and the largest speed below it without.
    fn bracket(&self, is_above: impl Fn(Outcome) -> bool) -> Bracket {
        let hi = self
            .points
            .iter()
            .filter(|p| is_above(p.1))
            .map(|p| p.0)
            .reduce(f64::min);
        let lo = self
            .points
            .iter()
            .filter(|p| !is_above(p.1) && hi.is_none_or(|h| p.0 < h))
            .map(|p| p.0)
            .reduce(f64::max);
        (lo, hi)
    }

    fn has(&self, outcome: impl Fn(Outcome) -> bool) -> bool {
        self.points.iter().any(|p| outcome(p.1))
    }

    fn fastest(&self) -> f64 {
        self.points.iter().map(|p| p.0).fold(0.0, f64::max)
    }
}

fn sticks(o: Outcome) -> bool {
    o == Outcome::Sticking
}

fn not_sticking(o: Outcome) -> bool {
    o != Outcome::Sticking
}

fn bouncing(o: Outcome) -> bool {
    o == Outcome::Bouncing
}

/// One threshold search: the collider, its settings, and every speed classified so far.
struct Search<'a> {
    collider: Collider,
    opts: &'a SearchOptions,
    v_jkr: f64,
    v_max: f64,
    seen: Seen,
}

impl Search<'_> {
    /// Integrates two impact speeds (concurrently when asked) and records their outcomes.
    fn round(&mut self, speeds: [f64; 2]) -> Result<(), ThresholdsError> {
        let one = |v: f64| self.collider.collide(v);
        let (a, b) = if self.opts.parallel {
            rayon::join(|| one(speeds[0]), || one(speeds[1]))
        } else {
            (one(speeds[0]), one(speeds[1]))
        };
        for (v, c) in speeds.into_iter().zip([a?, b?]) {
            self.seen.record(v, c.outcome, c.v_out);
        }
        Ok(())
    }

    /// Stage 1: a sticking speed below both transitions and, unless nothing bounces up to
    /// `v_max`, a bouncing speed above them.
    fn bracket(&mut self) -> Result<(), ThresholdsError> {
        let mut v = (FIRST_LOWER_OVER_JKR * self.v_jkr).min(0.5 * self.v_max);
        let v_max = self.v_max;
        let hinted = self.opts.hint.filter(|h| {
            h.v_double_onset > 0.0
                && h.v_stick >= h.v_double_onset
                && h.v_stick * HINT_ABOVE <= v_max
        });
        match hinted {
            Some(h) => self.round([HINT_BELOW * h.v_double_onset, HINT_ABOVE * h.v_stick])?,
            None => self.round([v, (FIRST_UPPER_OVER_LOWER * v).min(v_max)])?,
        }
        if hinted.is_some() && !self.seen.has(sticks) {
            self.round([v, 0.5 * v])?;
        }
        while !self.seen.has(sticks) {
            v *= LOWER_SHRINK;
            if v < V_FLOOR_OVER_JKR * self.v_jkr {
                return Err(ThresholdsError::NoSticking {
                    v_min: v,
                    t_vis: self.collider.t_vis(),
                });
            }
            self.round([2.0 * v, v])?;
        }
        let mut top = self.seen.fastest();
        while !self.seen.has(bouncing) && top < v_max {
            let a = (UPPER_GROWTH * top).min(v_max);
            let b = (UPPER_GROWTH * a).min(v_max);
            self.round([a, b])?;
            top = b;
        }
        Ok(())
    }

    /// Whether a transition's bracket is narrower than the tolerance (or there is nothing to
    /// search, for example no bouncing below `v_max`).
    fn converged(&self, (lo, hi): Bracket) -> bool {
        match (lo, hi) {
            (Some(lo), Some(hi)) => hi - lo <= self.opts.rel_tol * hi,
            _ => true,
        }
    }

    /// Stage 2: both transitions to the tolerance, two speeds a round.
    fn refine(&mut self) -> Result<(), ThresholdsError> {
        let tol = self.opts.rel_tol;
        loop {
            let stick = self.seen.bracket(bouncing);
            let onset = self.seen.bracket(not_sticking);
            let speeds = match (self.converged(stick), self.converged(onset)) {
                (true, true) => return Ok(()),
                (false, false) => {
                    let p = self.regula_falsi_point(stick);
                    let q = midpoint(onset);
                    if (p - q).abs() > tol * p {
                        [p, q]
                    } else {
                        // one bracket for both: trisect it
                        trisect(onset.0, stick.1)
                    }
                }
                (false, true) => [self.regula_falsi_point(stick), midpoint(stick)],
                (true, false) => trisect(onset.0, onset.1),
            };
            self.round(speeds)?;
        }
    }

    /// The regula falsi point of V_out(V_in) in the V_stick bracket when its lower end is a double
    /// collision (V_out > 0 there, < 0 at the bouncing end), else the midpoint; kept a quarter of
    /// the tolerance inside the bracket.
    fn regula_falsi_point(&self, (lo, hi): Bracket) -> f64 {
        let (lo, hi) = (lo.unwrap_or(0.0), hi.unwrap_or(0.0));
        let f_lo = self.seen.v_out_at(lo).unwrap_or(0.0);
        let f_hi = self.seen.v_out_at(hi).unwrap_or(0.0);
        let v = if f_lo > 0.0 && f_hi < 0.0 {
            (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        } else {
            0.5 * (lo + hi)
        };
        let margin = 0.25 * self.opts.rel_tol * hi;
        v.clamp(lo + margin, hi - margin)
    }

    /// Stage 3: each threshold is the centre of its final bracket; none where the outcome above
    /// it was never seen.
    fn result(&self) -> StickingThresholds {
        let center = |(lo, hi): Bracket| Some(0.5 * (lo? + hi?));
        let v_stick = if self.seen.has(bouncing) {
            center(self.seen.bracket(bouncing))
        } else {
            None
        };
        let v_double_onset = if self.seen.has(not_sticking) {
            center(self.seen.bracket(not_sticking))
        } else {
            None
        };
        StickingThresholds {
            t_vis: self.collider.t_vis(),
            v_stick,
            v_double_onset,
            v_stick_jkr: self.v_jkr,
            v_max: self.v_max,
            collisions: self.seen.points.len(),
        }
    }
}

fn midpoint((lo, hi): Bracket) -> f64 {
    0.5 * (lo.unwrap_or(0.0) + hi.unwrap_or(0.0))
}

/// The two points that cut `[lo, hi]` in thirds.
fn trisect(lo: Option<f64>, hi: Option<f64>) -> [f64; 2] {
    let (lo, hi) = (lo.unwrap_or(0.0), hi.unwrap_or(0.0));
    [lo + (hi - lo) / 3.0, lo + 2.0 * (hi - lo) / 3.0]
}

/// V_stick and V_double_onset of `contact` at relaxation time `t_vis` (s, >= 0) with the crack
/// law `law` (its k). `t_vis = 0` is the JKR limit: both equal V_stick,JKR.
///
/// Every round integrates two impact speeds, concurrently when [`SearchOptions::parallel`] is set
/// (two cores halve the wall time); the speeds chosen depend only on the outcomes seen, so the
/// result is the same either way.
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
    let v_max = opts.v_max_for(v_jkr);
    if t_vis == 0.0 {
        return Ok(StickingThresholds {
            t_vis,
            v_stick: Some(v_jkr),
            v_double_onset: Some(v_jkr),
            v_stick_jkr: v_jkr,
            v_max,
            collisions: 0,
        });
    }
    let mut search = Search {
        collider: Collider::new(*contact, law, t_vis)?.with_options(opts.solver)?,
        opts,
        v_jkr,
        v_max,
        seen: Seen::default(),
    };
    search.bracket()?;
    search.refine()?;
    Ok(search.result())
}

/// `sticking_thresholds` over a sequence of relaxation times (s), each search started from the
/// previous point's thresholds (see [`SearchOptions::hint`]). Use an increasing or decreasing
/// sequence: neighbours then have close thresholds.
pub fn sweep_t_vis(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: &[f64],
    opts: &SearchOptions,
) -> Result<Vec<StickingThresholds>, ThresholdsError> {
    let mut out: Vec<StickingThresholds> = Vec::with_capacity(t_vis.len());
    for &t in t_vis {
        let hint = out.last().and_then(StickingThresholds::as_hint);
        let o = SearchOptions {
            hint: hint.or(opts.hint),
            ..*opts
        };
        out.push(sticking_thresholds(contact, law, t, &o)?);
    }
    Ok(out)
}
