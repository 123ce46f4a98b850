//! V_stick and the onset of double collisions (Sections 4.4 and 5).
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing.
//! `V_double_onset` is the sticking -> double transition and `V_stick` the double -> bouncing
//! transition (the paper's threshold velocity for sticking). The double-collision window is narrow
//! (2.6 % of V_stick at T_vis = 1e-9 s, 4e-6 at 1e-14 s), so each transition is searched on its
//! own predicate ("not sticking", "bouncing") from one shared set of classified speeds.
//!
//! Collisions are integrated on a ladder of solver tolerances ([`LADDER`]): while a bracket is
//! wide, a coarse collision (a quarter to a third of the cost of one at the search's own
//! tolerance) classifies a speed as well as a tight one; the final brackets of both transitions
//! are made of collisions at the search's own tolerance only.
//!
//! The search has three stages:
//! 1. [`Search::bracket_stage`]: a sticking speed below and a bouncing speed above, on the
//!    coarsest rung, starting just below V_stick,JKR (V_stick >= V_stick,JKR) or around a hint
//!    from a neighbouring sweep point;
//! 2. [`Search::refine`]: V_out is continuous through V_stick (positive for double collisions,
//!    negative for bouncing), so V_stick is a root of V_out: coarse secant steps estimate it, and
//!    two pairs of full-tolerance collisions around the estimate close its bracket. The onset is a
//!    jump of the outcome (e from 0 to about -0.1), so it is trisected, on coarse rungs while
//!    the bracket is wide;
//! 3. [`Search::result`]: V_stick is the zero of V_out between the ends of its final bracket
//!    (accurate to the solver's tolerance, well inside the bracket), the onset the centre of its
//!    final bracket.
//!
//! A collision whose speed lies close to two collisions of the same rung (between them, or just
//! beyond, with an error of the line through them no larger than interpolating in a bracket of
//! relative width [`RESTART_MAX_WIDTH`] on the last rung, wider on coarse ones) starts at its
//! rebound, the state where delta returns to zero, interpolated or extrapolated from theirs
//! ([`dynamics::Rebound`]), instead of at first contact: the outcome is decided after the
//! rebound, and the part before it is a half to two thirds of the steps
//! ([`SearchOptions::restarts`]).
//!
//! Each round integrates two impact speeds, on two threads when asked; the speeds depend only on
//! the outcomes seen, so the result does not depend on the threads.

use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Collider, Method, Outcome, Rebound, SolverOptions};
use greenwood::CrackLaw;
use numerics::{format::number, OutOfRange};

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
/// First upper trial, in units of the first lower one (so 1.02 V_stick,JKR): V_stick is within
/// 2 % of V_stick,JKR for T_vis up to about 1e-12 s (CO2 60 um, Figure 4), where collisions are
/// stiff and dearest, and one round brackets it; above, the growth steps of [`UPPER_GROWTH`] find
/// bouncing in about as many rounds as a first trial of 1.6 did. Measured with
/// `v_stick_once` over T_vis = 1e-16..1e-8 s: 10-17 % fewer instructions at 1e-16..1e-12 s,
/// 1-3 % more at 1e-11..1e-8 s (`docs/performance.md`, item 17).
const FIRST_UPPER_OVER_LOWER: f64 = 1.03;
/// The [`Hint::spread`] of a hint from one neighbour, or where an extrapolation is doubtful: the
/// first round tries 10 % below the hinted onset and 10 % above the hinted V_stick, on the
/// coarsest rung, which brackets both transitions when the hint is a few per cent off.
pub const HINT_SPREAD_ONE: f64 = 0.1;
/// The spread of an extrapolated hint, per its step (the relative change from the nearer
/// neighbour's thresholds): over Figure-4-like sweeps (CO2 60 um, k = 0.01 and 0.02, 33 T_vis
/// from 1e-12 to 1e-8 s) the extrapolation of [`Hint::extrapolated`] was off by at most 0.34 of
/// its step (0.01-0.03 below T_vis = 1e-9 s, where the thresholds follow the power law closely),
/// on 11 T_vis per 4 decades by up to 0.75 of it at 1e-8 s (`docs/performance.md`, item 20).
const HINT_SPREAD_PER_STEP: f64 = 0.75;
/// The smallest spread of an extrapolated hint: just wide enough for the first round to run on
/// the second rung of the tolerance ladder (a spread above [`LADDER_MARGIN`] times its shift),
/// a third cheaper from first contact than the third. Over the sweeps of
/// [`HINT_SPREAD_PER_STEP`], floors of 1e-4 (first rounds on the third rung), 1e-3 and 2e-3
/// took 2-3 % more steps.
const HINT_SPREAD_MIN: f64 = 1.02 * LADDER_MARGIN * LADDER[1].1;
/// The spread of an extrapolated hint per miss of the same extrapolation one point earlier:
/// the misses grew by at most a factor 1.9 from one point to the next over the sweeps of
/// [`HINT_SPREAD_PER_STEP`] (`docs/performance.md`, item 20).
const HINT_SPREAD_PER_MISS: f64 = 3.0;
/// How many previous points of a sweep seed the hint of the next ([`Hint::extrapolated`]).
pub const HINT_NEIGHBOURS: usize = 3;
/// Growth of the upper trial per step while nothing bounces: 1.5 keeps the bracket of V_out
/// tight enough for the secant steps on V_out while reaching 1000 V_stick,JKR in 9 rounds.
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
    /// Start a collision at its rebound, interpolated between two collisions close by (or
    /// extrapolated from two just beside it), instead of at first contact, where that is
    /// accurate (a third to a half of the
    /// cost; [`dynamics::Collider::collide_from`]). It moves V_stick by less than 1e-7 relative
    /// and the onset of double collisions (the centre of its final bracket) by less than that
    /// bracket (`docs/performance.md`, "Rebound restarts" and "Accuracy"). Default on; off for a
    /// reference.
    pub restarts: bool,
}

/// Expected thresholds, from a neighbouring point of a sweep (m/s), and how far off they may be.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hint {
    /// Expected V_double_onset (m/s).
    pub v_double_onset: f64,
    /// Expected V_stick (m/s).
    pub v_stick: f64,
    /// How far off the two may be, relative (dimensionless, in (0, 1)): the first round of a
    /// search tries `(1 - spread) v_double_onset` and `(1 + spread) v_stick`, on the coarsest
    /// rung of the tolerance ladder that resolves that bracket. [`HINT_SPREAD_ONE`] (0.1) for
    /// the thresholds of one neighbour; [`Hint::extrapolated`] sets it from its step.
    pub spread: f64,
}

/// The most a hint extrapolated from two neighbours moves the excess of the thresholds over
/// their floor (a factor): the thresholds of neighbouring points of a sweep seldom differ by
/// more, and a wild extrapolation would cost more than no hint.
const HINT_EXTRAPOLATION_MAX: f64 = 2.0;

impl Hint {
    /// The thresholds of one neighbour as a hint, with spread [`HINT_SPREAD_ONE`].
    pub fn from_neighbour(v_double_onset: f64, v_stick: f64) -> Hint {
        Hint {
            v_double_onset,
            v_stick,
            spread: HINT_SPREAD_ONE,
        }
    }

    /// The hint for a search at `t_vis` (s) from the thresholds of the points before it in a
    /// sweep, `previous` (the last [`HINT_NEIGHBOURS`] or fewer, as `(t_vis, hint)` in sweep
    /// order), and `floor` (m/s), the value both thresholds tend to as T_vis -> 0 (V_stick,JKR
    /// of the contact; 0 if unknown).
    ///
    /// With two neighbours or more, each threshold's excess over `floor` is extrapolated from
    /// the nearest two as a power law in T_vis (it grows about like T_vis^0.9 for CO2 60 um
    /// below 1e-10 s; the change of the excess is capped at a factor
    /// [`HINT_EXTRAPOLATION_MAX`]). The spread is [`HINT_SPREAD_PER_STEP`] times the larger
    /// relative change from the nearest neighbour or, with a third neighbour, if smaller,
    /// [`HINT_SPREAD_PER_MISS`] times how far the same extrapolation one point earlier missed the
    /// nearest neighbour; within `[6.1e-4, 0.1]`. With one neighbour, its thresholds and spread
    /// 0.1.
    ///
    /// # Example
    /// ```
    /// use thresholds::Hint;
    /// // excesses over the floor of 1 m/s: 0.1 and 0.2 m/s a factor 10 in T_vis apart
    /// let a = (1e-11, Hint::from_neighbour(1.1, 1.1));
    /// let b = (1e-10, Hint::from_neighbour(1.2, 1.2));
    /// let h = Hint::extrapolated(1e-9, &[a, b], 1.0).unwrap();
    /// assert!((h.v_stick - 1.4).abs() < 1e-12); // the excess doubles again
    /// assert!((h.spread - 0.1).abs() < 1e-12); // 0.75 x (1.4 / 1.2 - 1), capped at 0.1
    /// // a third neighbour on the same power law: the extrapolation did not miss it, and the
    /// // spread is its floor
    /// let c = (1e-12, Hint::from_neighbour(1.05, 1.05));
    /// let h = Hint::extrapolated(1e-9, &[c, a, b], 1.0).unwrap();
    /// assert!(h.spread < 1e-3);
    /// ```
    pub fn extrapolated(t_vis: f64, previous: &[(f64, Hint)], floor: f64) -> Option<Hint> {
        let valid = |t0: f64, t1: f64, t: f64| t0 > 0.0 && t1 > 0.0 && t > 0.0 && t0 != t1;
        match previous {
            [] => None,
            [.., (t0, h0), (t1, h1)] if valid(*t0, *t1, t_vis) => {
                let (onset, stick) = extrapolate((*t0, h0), (*t1, h1), t_vis, floor);
                let off = |h: &Hint, onset: f64, stick: f64| {
                    (onset / h.v_double_onset - 1.0)
                        .abs()
                        .max((stick / h.v_stick - 1.0).abs())
                };
                let mut spread = HINT_SPREAD_PER_STEP * off(h1, onset, stick);
                if let [.., (tm, hm), _, _] = previous {
                    if valid(*tm, *t0, *t1) {
                        let (o, s) = extrapolate((*tm, hm), (*t0, h0), *t1, floor);
                        spread = spread.min(HINT_SPREAD_PER_MISS * off(h1, o, s));
                    }
                }
                let spread = spread.clamp(HINT_SPREAD_MIN, HINT_SPREAD_ONE);
                Some(Hint {
                    v_double_onset: onset,
                    v_stick: stick,
                    spread: if spread.is_finite() {
                        spread
                    } else {
                        HINT_SPREAD_ONE
                    },
                })
            }
            [.., (_, h)] => Some(Hint::from_neighbour(h.v_double_onset, h.v_stick)),
        }
    }
}

/// The two thresholds at `t_vis` (s) from those of two neighbours: each one's excess over
/// `floor` (m/s) as a power law in T_vis through theirs, its change capped at a factor
/// [`HINT_EXTRAPOLATION_MAX`] (the value itself where it is not above the floor).
fn extrapolate(
    (t0, h0): (f64, &Hint),
    (t1, h1): (f64, &Hint),
    t_vis: f64,
    floor: f64,
) -> (f64, f64) {
    let s = (t_vis / t1).ln() / (t1 / t0).ln();
    let step = |x1: f64, x0: f64| {
        let base = if x1 > floor && x0 > floor { floor } else { 0.0 };
        let f = ((x1 - base) / (x0 - base)).powf(s);
        if f.is_finite() {
            base + (x1 - base) * f.clamp(1.0 / HINT_EXTRAPOLATION_MAX, HINT_EXTRAPOLATION_MAX)
        } else {
            x1
        }
    };
    (
        step(h1.v_double_onset, h0.v_double_onset),
        step(h1.v_stick, h0.v_stick),
    )
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
            restarts: true,
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
        Some(Hint::from_neighbour(self.v_double_onset?, self.v_stick?))
    }

    /// The speed (m/s) up to which no collision bounced when there is no V_stick, else `None`.
    pub fn no_bouncing_below(&self) -> Option<f64> {
        self.v_stick.is_none().then_some(self.v_max)
    }
}

/// The coarse solver tolerances of a search, coarsest first: `(rtol, shift)`, where `shift`
/// bounds how far that tolerance moves the transitions (relative to V_in) from a tight reference.
/// The shifts measured over CO2 and H2O at T_vis = 1e-14..1e-8 s (`docs/performance.md`,
/// "Tolerance ladder") are 1.1e-3, 7.4e-5 and 1.4e-6; each bound here is 1.8 times that or more. The
/// last rung, the search's own solver settings, is exact by definition.
const LADDER: [(f64, f64); 3] = [(1e-4, 2e-3), (1e-5, 1.5e-4), (1e-7, 3e-6)];

/// A rung of [`LADDER`] classifies impact speeds only while the bracket it refines is wider
/// than this many times its shift: a misclassified speed then lies near the bracket's far end,
/// where the final check at full tolerance finds it.
const LADDER_MARGIN: f64 = 4.0;

/// The rung of the coarse secant steps on V_out once the bracket is narrower than the coarsest
/// rung allows ([`Search::rung_for`]): 1e-5, a third of the cost of full tolerance, and V_out
/// accurate to about 1e-5. While the bracket is wider, the coarsest rung trisects it.
const COARSE_SECANT_RUNG: usize = 1;
/// Coarse steps on V_out at most (trisection until a secant root falls inside the bracket, then
/// secant steps), before the full-tolerance pairs take over: trisecting a bracket of a factor 1.5
/// down to the first pair's width (3e-4) takes 7, and the rest leaves room for secant steps.
const MAX_COARSE_SECANT_STEPS: usize = 24;
/// A coarse secant estimate has settled when it moves by less than this (relative): the
/// transitions move by about 1e-5 on the coarse rung, so finer steps there are noise.
const SECANT_SETTLED: f64 = 3e-5;
/// Each coarse secant step also integrates a speed this much above its estimate (relative), so
/// that the next step has a secant through two close speeds.
const SECANT_PROBE: f64 = 1e-3;
/// Half-width (relative) of the first full-tolerance pair around a coarse estimate: twice the
/// largest shift of the coarse rung measured (7e-5), so that the pair straddles V_stick.
const TIGHT_PAIR_HALF_WIDTH: f64 = 1.5e-4;

/// Half-width of a closing pair of V_stick, relative to the search's `rel_tol`: a pair around a
/// root estimate that straddles V_stick is then a final bracket (narrower than `rel_tol`), and
/// it tolerates an estimate 0.45 `rel_tol` off (the secant through two full-tolerance collisions
/// 3e-4 apart was off by 4.6e-7 at T_vis = 1e-11 s, CO2 60 um).
const CLOSING_HALF_WIDTH: f64 = 0.45;
/// Newton steps on the parabola of [`Search::quadratic_root`], from the secant root: near the
/// root the parabola is close to its secant, and each step squares the relative error.
const QUADRATIC_NEWTON_STEPS: usize = 4;
/// [`Search::quadratic_root`] accepts a root where the parabola is below this fraction of
/// its slope times V_in (a relative error in V_in well below any bracket).
const QUADRATIC_SETTLED: f64 = 1e-12;

/// The rebound of a collision at the search tolerance is restarted from the line through two
/// full-tolerance collisions whose rebounds are at most as far off as interpolating at the middle
/// of a bracket of this relative width ([`Search::restart_from`]) instead of integrating it from
/// first contact ([`dynamics::Collider::collide_from`]). The interpolation error of the state is
/// about 0.36 |(v - v_a)(v - v_b)| / v^2 (0.09 w^2 at the middle of a bracket of relative width
/// w; measured near the thresholds of CO2 and H2O, `docs/performance.md`, "Rebound restarts"):
/// 1e-8 at this width, a twentieth of the solver's own error at the search tolerance (2e-7). A
/// coarse rung allows `sqrt(shift)`, where the interpolation error is a tenth of its shift
/// ([`restart_width`]).
const RESTART_MAX_WIDTH: f64 = 3.2e-4;

/// The bracket width (relative) whose interpolation error bounds the restarts on `rung`: see
/// [`RESTART_MAX_WIDTH`].
fn restart_width(rung: usize) -> f64 {
    LADDER
        .get(rung)
        .map_or(RESTART_MAX_WIDTH, |&(_, shift)| shift.sqrt())
}

/// Absolute tolerance of a rung, relative to its rtol (the states are of order one).
const ATOL_OVER_RTOL: f64 = 1e-3;

/// One classified impact speed.
#[derive(Debug, Clone, Copy)]
struct Seen {
    /// Impact speed (m/s).
    v: f64,
    outcome: Outcome,
    /// V_out (m/s).
    v_out: f64,
    /// The rung of the tolerance ladder it was integrated on ([`LADDER`]`.len()` is the
    /// search's own solver settings).
    rung: usize,
    /// Its state where delta first returned to zero, if it did.
    rebound: Option<Rebound>,
}

/// A transition between two classes of outcomes: the fastest speed below it and the slowest
/// above it seen so far.
type Bracket = (Option<Seen>, Option<Seen>);

fn sticks(o: Outcome) -> bool {
    o == Outcome::Sticking
}

fn not_sticking(o: Outcome) -> bool {
    o != Outcome::Sticking
}

fn bouncing(o: Outcome) -> bool {
    o == Outcome::Bouncing
}

/// One threshold search: colliders for each rung, its settings, and every classified speed.
struct Search<'a> {
    /// One collider a rung of [`LADDER`], then one with the search's own solver settings.
    colliders: Vec<Collider>,
    opts: &'a SearchOptions,
    v_jkr: f64,
    v_max: f64,
    seen: Vec<Seen>,
    /// The state of the V_stick search.
    stick: StickState,
}

/// The two speeds that cut `[lo, hi]` in thirds, on `rung`.
fn trisect(lo: f64, hi: f64, rung: usize) -> Vec<(f64, usize)> {
    let third = (hi - lo) / 3.0;
    vec![(lo + third, rung), (lo + 2.0 * third, rung)]
}

/// Where the V_stick search stands.
#[derive(Debug, Clone, Copy)]
struct StickState {
    /// The coarse estimate has stopped moving.
    settled: bool,
    /// The latest coarse estimate (m/s).
    estimate: Option<f64>,
    /// Coarse steps taken.
    coarse_steps: usize,
    /// Relative half-width of the next full-tolerance pair.
    half_width: f64,
}

impl Search<'_> {
    /// The finest rung.
    fn tight(&self) -> usize {
        LADDER.len()
    }

    /// The coarsest rung fit to classify speeds inside a bracket of relative width `width`.
    fn rung_for(&self, width: f64) -> usize {
        LADDER
            .iter()
            .position(|&(rtol, shift)| {
                width > LADDER_MARGIN * shift && rtol > self.opts.solver.rtol
            })
            .unwrap_or(self.tight())
    }

    /// The speeds seen, each by its finest classification, without the coarse ones that a finer
    /// one contradicts (outcomes come in the order sticking, double, bouncing along V_in).
    fn trusted(&self) -> Vec<Seen> {
        let rank = |o: Outcome| match o {
            Outcome::Sticking => 0,
            Outcome::DoubleCollision => 1,
            Outcome::Bouncing => 2,
        };
        self.seen
            .iter()
            .filter(|p| {
                !self.seen.iter().any(|q| {
                    q.rung > p.rung
                        && ((q.v == p.v)
                            || (q.v > p.v && rank(q.outcome) < rank(p.outcome))
                            || (q.v < p.v && rank(q.outcome) > rank(p.outcome)))
                })
            })
            .copied()
            .collect()
    }

    /// The bracket of the transition into the outcomes with `is_above`.
    fn bracket(&self, is_above: impl Fn(Outcome) -> bool) -> Bracket {
        self.bracket_from(0, is_above)
    }

    /// The bracket of the transition into the outcomes with `is_above`, from the speeds
    /// integrated on `rung` or finer.
    fn bracket_from(&self, rung: usize, is_above: impl Fn(Outcome) -> bool) -> Bracket {
        let mut trusted = self.trusted();
        trusted.retain(|p| p.rung >= rung);
        let hi = trusted
            .iter()
            .filter(|p| is_above(p.outcome))
            .min_by(|a, b| a.v.total_cmp(&b.v))
            .copied();
        let lo = trusted
            .iter()
            .filter(|p| !is_above(p.outcome) && hi.is_none_or(|h| p.v < h.v))
            .max_by(|a, b| a.v.total_cmp(&b.v))
            .copied();
        (lo, hi)
    }

    fn has(&self, outcome: impl Fn(Outcome) -> bool) -> bool {
        self.seen.iter().any(|p| outcome(p.outcome))
    }

    /// Integrates impact speeds, each on its rung, two at a time (concurrently when asked).
    fn round(&mut self, jobs: &[(f64, usize)]) -> Result<(), ThresholdsError> {
        let jobs: Vec<(f64, usize, Option<Rebound>)> = jobs
            .iter()
            .map(|&(v, rung)| (v, rung, self.restart_from(v, rung)))
            .collect();
        let one = |(v, rung, from): (f64, usize, Option<Rebound>)| {
            let collider = &self.colliders[rung];
            match from {
                Some(r) => collider.collide_from(v, &r),
                None => collider.collide(v),
            }
            .map(|c| (v, rung, c))
        };
        let results = match jobs.as_slice() {
            [a, b] if self.opts.parallel => {
                let (x, y) = rayon::join(|| one(*a), || one(*b));
                vec![x, y]
            }
            _ => jobs.iter().map(|j| one(*j)).collect(),
        };
        for r in results {
            let (v, rung, c) = r?;
            self.seen.push(Seen {
                v,
                outcome: c.outcome,
                v_out: c.v_out,
                rung,
                rebound: c.rebound,
            });
        }
        Ok(())
    }

    /// The rebound to start a collision at `v` on `rung` from: on the line through the
    /// rebounds of two collisions of that rung, `a` and `b`, whose error (about
    /// `0.36 |(v - v_a)(v - v_b)| / v^2` of the state, `docs/performance.md`, "Rebound
    /// restarts") is smallest and at most that of interpolating at the middle of a bracket of
    /// relative width [`restart_width`]. Between them, or beyond the nearer one by at most their
    /// spacing (further out, the solver's own noise in the two states would be amplified).
    /// `None` (integrate from first contact) otherwise.
    fn restart_from(&self, v: f64, rung: usize) -> Option<Rebound> {
        if !self.opts.restarts {
            return None;
        }
        let width = restart_width(rung) * v;
        let same: Vec<(f64, Rebound)> = self
            .seen
            .iter()
            .filter(|p| p.rung == rung && p.v != v)
            .filter_map(|p| Some((p.v, p.rebound?)))
            .collect();
        let mut best: Option<(f64, Rebound)> = None;
        for (i, &(va, ra)) in same.iter().enumerate() {
            for &(vb, rb) in &same[i + 1..] {
                let product = ((v - va) * (v - vb)).abs();
                let between = (v - va) * (v - vb) < 0.0;
                let beyond = (v - va).abs().min((v - vb).abs()) <= (va - vb).abs();
                if product <= 0.25 * width * width
                    && (between || beyond)
                    && best.as_ref().is_none_or(|(q, _)| product < *q)
                {
                    if let Some(r) = Rebound::through(&ra, &rb, v) {
                        best = Some((product, r));
                    }
                }
            }
        }
        best.map(|(_, r)| r)
    }

    /// Stage 1: a sticking speed below both transitions and, unless nothing bounces up to
    /// `v_max`, a bouncing speed above them, on the coarsest rung.
    fn bracket_stage(&mut self) -> Result<(), ThresholdsError> {
        let coarse = self.rung_for(f64::INFINITY);
        let mut v = (FIRST_LOWER_OVER_JKR * self.v_jkr).min(0.5 * self.v_max);
        let v_max = self.v_max;
        let hinted = self.opts.hint.filter(|h| {
            h.v_double_onset > 0.0
                && h.v_stick >= h.v_double_onset
                && h.spread > 0.0
                && h.spread < 1.0
                && h.v_stick * (1.0 + h.spread.max(HINT_SPREAD_ONE)) <= v_max
        });
        match hinted {
            Some(h) => {
                let (lo, hi) = (
                    (1.0 - h.spread) * h.v_double_onset,
                    (1.0 + h.spread) * h.v_stick,
                );
                // the coarsest rung that classifies speeds a spread away from a transition
                let rung = self.rung_for(h.spread);
                self.round(&[(lo, rung), (hi, rung)])?;
                // a narrow hint that missed a side: that side again, at the geometric mean of
                // the spread and 10 %, and 10 % out
                if h.spread < HINT_SPREAD_ONE {
                    let wide = HINT_SPREAD_ONE;
                    let mean = (h.spread * wide).sqrt();
                    let (far, up) = (1.0 - mean, 1.0 + mean);
                    match (self.has(sticks), self.has(bouncing)) {
                        (true, true) => {}
                        (false, true) => self.round(&[
                            (far * h.v_double_onset, coarse),
                            ((1.0 - wide) * h.v_double_onset, coarse),
                        ])?,
                        (true, false) => self.round(&[
                            (up * h.v_stick, coarse),
                            ((1.0 + wide) * h.v_stick, coarse),
                        ])?,
                        (false, false) => self.round(&[
                            ((1.0 - wide) * h.v_double_onset, coarse),
                            ((1.0 + wide) * h.v_stick, coarse),
                        ])?,
                    }
                }
            }
            None => self.round(&[
                (v, coarse),
                ((FIRST_UPPER_OVER_LOWER * v).min(v_max), coarse),
            ])?,
        }
        if hinted.is_some() && !self.has(sticks) {
            self.round(&[(v, coarse), (0.5 * v, coarse)])?;
            // the loop below continues from 0.5 v, already integrated: its first round is
            // 0.25 v and 0.125 v
            v *= 0.5;
        }
        while !self.has(sticks) {
            v *= LOWER_SHRINK;
            if v < V_FLOOR_OVER_JKR * self.v_jkr {
                return Err(ThresholdsError::NoSticking {
                    v_min: v,
                    t_vis: self.colliders[0].t_vis(),
                });
            }
            self.round(&[(2.0 * v, coarse), (v, coarse)])?;
        }
        let mut top = self.seen.iter().map(|p| p.v).fold(0.0, f64::max);
        while !self.has(bouncing) && top < v_max {
            let a = (UPPER_GROWTH * top).min(v_max);
            let b = (UPPER_GROWTH * a).min(v_max);
            self.round(&[(a, coarse), (b, coarse)])?;
            top = b;
        }
        Ok(())
    }

    /// Stage 2: V_stick, then the onset of double collisions, each to the tolerance on
    /// full-tolerance collisions, two speeds a round (both cores busy).
    fn refine(&mut self) -> Result<(), ThresholdsError> {
        loop {
            let jobs = self.stick_jobs()?;
            if jobs.is_empty() {
                break;
            }
            self.round(&jobs)?;
        }
        loop {
            let jobs = self.onset_jobs();
            if jobs.is_empty() {
                return Ok(());
            }
            self.round(&jobs)?;
        }
    }

    /// The next two speeds for V_stick; none when it is done.
    ///
    /// V_out(V_in) is continuous through V_stick (positive for double collisions, negative for
    /// bouncing), so V_stick is a root of V_out. Coarse collisions only estimate that root (a
    /// coarse collision near it may be misclassified, so their outcomes are not used for the
    /// result): secant steps on the coarse rung, safeguarded by trisection, until they move by less
    /// than [`SECANT_SETTLED`]. Then pairs of full-tolerance collisions: around the estimate,
    /// then a quarter of the tolerance either side of the secant root through them, which closes
    /// the bracket; wider pairs or trisection continue at full tolerance when a pair does not
    /// straddle V_stick.
    fn stick_jobs(&mut self) -> Result<Vec<(f64, usize)>, ThresholdsError> {
        if !self.has(bouncing) {
            return Ok(Vec::new());
        }
        let tight = self.tight();
        if !self.stick.settled {
            if let (Some(lo), Some(hi)) = self.bracket(bouncing) {
                // the coarsest rung the bracket allows, at most the secant rung
                let coarse = self.rung_for((hi.v - lo.v) / hi.v).min(COARSE_SECANT_RUNG);
                // ends from that rung or finer once they bracket V_stick: a coarser end may be
                // misclassified within its rung's shift, and would keep the secant root out
                let (lo, hi) = match self.bracket_from(coarse, bouncing) {
                    (Some(l), Some(h)) => (l, h),
                    _ => (lo, hi),
                };
                if hi.v - lo.v > TIGHT_PAIR_HALF_WIDTH * hi.v
                    && self.stick.coarse_steps < MAX_COARSE_SECANT_STEPS
                {
                    // the secant root when it falls inside the bracket of every speed seen,
                    // else the bracket's midpoint (before two speeds have a V_out, or when V_out
                    // curves)
                    // a neighbour's V_stick is the first estimate
                    let hinted = self
                        .opts
                        .hint
                        .map(|h| h.v_stick)
                        .filter(|_| self.stick.estimate.is_none());
                    let inside = |q: &f64| *q > lo.v && *q < hi.v;
                    let root = hinted
                        .filter(inside)
                        .or_else(|| self.v_out_root(coarse).filter(inside))
                        .or_else(|| self.v_out_root(0).filter(inside));
                    let Some(p) = root else {
                        self.stick.coarse_steps += 1;
                        return Ok(trisect(lo.v, hi.v, coarse));
                    };
                    let settled = root.is_some()
                        && self
                            .stick
                            .estimate
                            .is_some_and(|e| (e - p).abs() <= SECANT_SETTLED * p);
                    self.stick.estimate = Some(p);
                    if !settled {
                        self.stick.coarse_steps += 1;
                        // a second speed a little above: a local secant next round
                        return Ok(vec![(p, coarse), (p * (1.0 + SECANT_PROBE), coarse)]);
                    }
                } else {
                    // the bracket is narrow: the secant root inside it, else the last estimate
                    // if still inside (an earlier one may have been passed), else its midpoint
                    let inside = |q: &f64| *q > lo.v && *q < hi.v;
                    let estimate = self
                        .v_out_root(coarse)
                        .filter(inside)
                        .or(self.stick.estimate.filter(inside))
                        .unwrap_or(0.5 * (lo.v + hi.v));
                    self.stick.estimate = Some(estimate);
                }
            }
            self.stick.settled = true;
        }
        let (lo, hi) = self.tight_bracket(bouncing);
        let eps = 0.25 * self.opts.rel_tol;
        let half = &mut self.stick.half_width;
        let p = match (lo, hi) {
            (Some(lo), Some(hi)) => {
                if hi.v - lo.v <= self.opts.rel_tol * hi.v {
                    return Ok(Vec::new());
                }
                // V_out crosses zero smoothly from a double collision: the root of the parabola
                // through the three speeds nearest to it, and a closing pair around it
                let closing = CLOSING_HALF_WIDTH * self.opts.rel_tol;
                if let Some(q) = self
                    .quadratic_root(tight)
                    .filter(|q| lo.outcome == Outcome::DoubleCollision && *q > lo.v && *q < hi.v)
                {
                    let below = (q * (1.0 - closing)).max(0.5 * (lo.v + q));
                    let above = (q * (1.0 + closing)).min(0.5 * (q + hi.v));
                    return Ok(vec![(below, tight), (above, tight)]);
                }
                if let Some((a, b)) = self.bouncing_roots(tight) {
                    // just outside the two estimates, inside the bracket
                    let mut below = a * (1.0 - eps);
                    if below <= lo.v {
                        below = 0.5 * (lo.v + b.min(hi.v));
                    }
                    let mut above = b * (1.0 + eps);
                    if above >= hi.v {
                        above = 0.5 * (a.max(lo.v) + hi.v);
                    }
                    if below < above {
                        return Ok(vec![(below, tight), (above, tight)]);
                    }
                }
                let root = self.v_out_root(tight).filter(|q| *q > lo.v && *q < hi.v);
                match root {
                    Some(q) => {
                        self.stick.half_width = closing.min(0.25 * (hi.v - lo.v) / hi.v);
                        q
                    }
                    // no secant (V_out is steep near V_stick in the JKR limit, and a sticking
                    // lower end has none): trisect
                    None => return Ok(trisect(lo.v, hi.v, tight)),
                }
            }
            (Some(lo), None) => {
                // everything at full tolerance so far is below V_stick: go up, to v_max at most
                if lo.v >= self.v_max * (1.0 - self.opts.rel_tol) {
                    return Ok(Vec::new());
                }
                *half *= 2.0;
                lo.v * (1.0 + 2.0 * *half)
            }
            (None, Some(hi)) => {
                // everything at full tolerance so far bounces: follow V_out down to its root
                // (two bouncing speeds at full tolerance), or step down
                *half *= 2.0;
                let step = hi.v * (1.0 - 2.0 * *half);
                self.v_out_root(tight)
                    .filter(|q| *q < hi.v)
                    .map_or(step, |q| q.max(step))
            }
            (None, None) => match self.stick.estimate {
                Some(p) => p,
                None => match self.bracket(bouncing) {
                    (Some(lo), Some(hi)) => 0.5 * (lo.v + hi.v),
                    _ => return Ok(Vec::new()),
                },
            },
        };
        let half = self.stick.half_width;
        let p = p.min(self.v_max / (1.0 + half));
        Ok(vec![(p * (1.0 - half), tight), (p * (1.0 + half), tight)])
    }

    /// Two estimates of V_stick that bracket it, from the two bouncing speeds on `rung` nearest
    /// to it when no double collision is nearer: V_out falls to zero between linearly (the secant
    /// of V_out is exact) and like a square root of V_in - V_stick (the JKR limit, where
    /// V_out^2 = V_in^2 - V_stick^2 and the secant of V_out^2 is exact); for a shape in between,
    /// the first root lies below V_stick and the second above. `None` otherwise.
    fn bouncing_roots(&self, rung: usize) -> Option<(f64, f64)> {
        let (a, b) = self.nearest_to_v_out_zero(rung)?;
        if !(bouncing(a.outcome) && bouncing(b.outcome)) {
            return None;
        }
        let linear = a.v - a.v_out * (b.v - a.v) / (b.v_out - a.v_out);
        let (a2, b2) = (a.v_out * a.v_out, b.v_out * b.v_out);
        let square = a.v - a2 * (b.v - a.v) / (b2 - a2);
        let (lo, hi) = (linear.min(square), linear.max(square));
        (lo.is_finite() && hi.is_finite() && lo > 0.0 && hi < self.v_max).then_some((lo, hi))
    }

    /// The root of V_out(V_in) of the parabola through the three double or bouncing collisions
    /// on `rung` or finer with the smallest |V_out|, by Newton steps from the secant root of the
    /// nearest two; `None` without three such speeds or when the steps do not settle.
    fn quadratic_root(&self, rung: usize) -> Option<f64> {
        let pts = self.by_distance_to_v_out_zero(rung);
        let [a, b, c, ..] = pts.as_slice() else {
            return None;
        };
        // Newton's divided differences: p(v) = y_a + f_ab (v - v_a) + f_abc (v - v_a)(v - v_b)
        let f_ab = (b.v_out - a.v_out) / (b.v - a.v);
        let f_bc = (c.v_out - b.v_out) / (c.v - b.v);
        let f_abc = (f_bc - f_ab) / (c.v - a.v);
        let mut v = a.v - a.v_out / f_ab;
        for _ in 0..QUADRATIC_NEWTON_STEPS {
            let p = a.v_out + f_ab * (v - a.v) + f_abc * (v - a.v) * (v - b.v);
            let dp = f_ab + f_abc * (2.0 * v - a.v - b.v);
            v -= p / dp;
        }
        let p = a.v_out + f_ab * (v - a.v) + f_abc * (v - a.v) * (v - b.v);
        let settled = (p / (f_ab * v)).abs() < QUADRATIC_SETTLED;
        (v.is_finite() && v > 0.0 && settled).then_some(v)
    }

    /// The bracket of a transition from full-tolerance collisions only.
    fn tight_bracket(&self, is_above: impl Fn(Outcome) -> bool) -> Bracket {
        let tight = self.tight();
        let pts = || self.seen.iter().filter(|p| p.rung == tight);
        let hi = pts()
            .filter(|p| is_above(p.outcome))
            .min_by(|a, b| a.v.total_cmp(&b.v))
            .copied();
        let lo = pts()
            .filter(|p| !is_above(p.outcome) && hi.is_none_or(|h| p.v < h.v))
            .max_by(|a, b| a.v.total_cmp(&b.v))
            .copied();
        (lo, hi)
    }

    /// The root of V_out(V_in) by a secant through the two speeds with the smallest |V_out|
    /// among double collisions and bouncing integrated on `rung` or finer (extrapolated from
    /// the bouncing side while no double collision is known). `None` without two such speeds.
    fn v_out_root(&self, rung: usize) -> Option<f64> {
        let (a, b) = self.nearest_to_v_out_zero(rung)?;
        let p = a.v - a.v_out * (b.v - a.v) / (b.v_out - a.v_out);
        (p.is_finite() && p > 0.0 && p < self.v_max).then_some(p)
    }

    /// The two double collisions or bouncing ones integrated on `rung` or finer with the
    /// smallest |V_out|, nearest first; `None` without two such speeds of distinct V_in and
    /// V_out (no secant through them).
    fn nearest_to_v_out_zero(&self, rung: usize) -> Option<(Seen, Seen)> {
        match self.by_distance_to_v_out_zero(rung).as_slice() {
            [a, b, ..] if a.v != b.v && a.v_out != b.v_out => Some((*a, *b)),
            _ => None,
        }
    }

    /// The double collisions and bouncing ones integrated on `rung` or finer, by increasing
    /// |V_out| (the points of the V_out secants and parabola).
    fn by_distance_to_v_out_zero(&self, rung: usize) -> Vec<Seen> {
        let mut pts: Vec<Seen> = self
            .seen
            .iter()
            .filter(|p| not_sticking(p.outcome) && p.rung >= rung)
            .copied()
            .collect();
        pts.sort_by(|a, b| a.v_out.abs().total_cmp(&b.v_out.abs()));
        pts
    }

    /// The next speeds (one or two) for the onset of double collisions; none when it is done.
    ///
    /// The onset is a jump in the outcome: it is trisected on the coarsest rung the bracket's
    /// width allows. A coarse speed within its rung's shift of the onset may be misclassified:
    /// when both ends come from coarser rungs than the width now needs (the bracket has just
    /// narrowed past a rung), the new rung trisects it, which usually yields two new ends; an end
    /// still coarser after that is integrated again on the current rung, alongside the bracket's
    /// midpoint, and the final ends at full tolerance.
    fn onset_jobs(&self) -> Vec<(f64, usize)> {
        let (Some(lo), Some(hi)) = self.bracket(not_sticking) else {
            return Vec::new();
        };
        let width = (hi.v - lo.v) / hi.v;
        let rung = if width <= self.opts.rel_tol {
            self.tight()
        } else {
            self.rung_for(width)
        };
        let mut jobs: Vec<(f64, usize)> = [lo, hi]
            .iter()
            .filter(|end| end.rung < rung)
            .map(|end| (end.v, rung))
            .collect();
        if width > self.opts.rel_tol {
            match jobs.len() {
                1 => jobs.push((0.5 * (lo.v + hi.v), rung)),
                _ => jobs = trisect(lo.v, hi.v, rung),
            }
        }
        jobs
    }

    /// Stage 3: V_stick is the zero of V_out between the ends of its final bracket, the onset the
    /// centre of its final bracket; none where the outcome above it was never seen.
    fn result(&self) -> StickingThresholds {
        let center = |(lo, hi): Bracket| Some(0.5 * (lo?.v + hi?.v));
        // V_stick: where V_out crosses zero between the final bracket's ends (a double collision
        // and a bouncing one), else the bracket's centre
        let root = |(lo, hi): Bracket| -> Option<f64> {
            let (lo, hi) = (lo?, hi?);
            if lo.outcome != Outcome::DoubleCollision {
                return center((Some(lo), Some(hi)));
            }
            let p = lo.v - lo.v_out * (hi.v - lo.v) / (hi.v_out - lo.v_out);
            if p.is_finite() && p >= lo.v && p <= hi.v {
                Some(p)
            } else {
                center((Some(lo), Some(hi)))
            }
        };
        let v_stick = if self.has(bouncing) {
            root(self.tight_bracket(bouncing))
        } else {
            None
        };
        let v_double_onset = if self.has(not_sticking) {
            center(self.tight_bracket(not_sticking))
        } else {
            None
        };
        StickingThresholds {
            t_vis: self.colliders[0].t_vis(),
            v_stick,
            v_double_onset,
            v_stick_jkr: self.v_jkr,
            v_max: self.v_max,
            collisions: self.seen.len(),
        }
    }
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
    let mut colliders = Vec::with_capacity(LADDER.len() + 1);
    for (rtol, _) in LADDER {
        let solver = SolverOptions {
            rtol,
            atol: ATOL_OVER_RTOL * rtol,
            ..opts.solver
        };
        colliders.push(Collider::new(*contact, law, t_vis)?.with_options(solver)?);
    }
    colliders.push(Collider::new(*contact, law, t_vis)?.with_options(opts.solver)?);
    let mut search = Search {
        colliders,
        opts,
        v_jkr,
        v_max,
        seen: Vec::new(),
        stick: StickState {
            settled: false,
            estimate: None,
            coarse_steps: 0,
            half_width: TIGHT_PAIR_HALF_WIDTH,
        },
    };
    search.bracket_stage()?;
    search.refine()?;
    Ok(search.result())
}

/// The last [`HINT_NEIGHBOURS`] (or fewer) results of a sweep with both thresholds, as
/// `(t_vis, hint)` for [`Hint::extrapolated`] (none when the last has no hint).
pub fn neighbours(done: &[StickingThresholds]) -> Vec<(f64, Hint)> {
    let mut chain = HintChain::default();
    for th in done {
        chain.push(th.t_vis, th.as_hint());
    }
    chain.previous
}

/// The hints along a sweep: the thresholds of its last [`HINT_NEIGHBOURS`] points (fewer at
/// its start or after a point without both thresholds), extrapolated to the next T_vis.
///
/// # Example
/// ```
/// use thresholds::{Hint, HintChain};
/// let mut chain = HintChain::default();
/// assert_eq!(chain.next(1e-10, 0.0), None); // nothing to go by yet
/// chain.push(1e-11, Some(Hint::from_neighbour(0.02, 0.021)));
/// assert_eq!(chain.next(1e-10, 0.0).unwrap().v_stick, 0.021); // one neighbour: its thresholds
/// chain.push(1e-10, None); // no thresholds there: start again
/// assert_eq!(chain.next(1e-9, 0.0), None);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct HintChain {
    previous: Vec<(f64, Hint)>,
}

impl HintChain {
    /// A chain continuing from `previous` (`(t_vis, hint)` in sweep order, the last
    /// [`HINT_NEIGHBOURS`] are kept), for instance the rows of an interrupted sweep.
    pub fn new(previous: &[(f64, Hint)]) -> Self {
        let skip = previous.len().saturating_sub(HINT_NEIGHBOURS);
        Self {
            previous: previous[skip..].to_vec(),
        }
    }

    /// The hint for the next point, at `t_vis` (s), with thresholds tending to `floor` (m/s) as
    /// T_vis -> 0 ([`Hint::extrapolated`]); `None` without a previous point.
    pub fn next(&self, t_vis: f64, floor: f64) -> Option<Hint> {
        Hint::extrapolated(t_vis, &self.previous, floor)
    }

    /// Records the point at `t_vis` (s) with its thresholds as a hint (`None` without both,
    /// which empties the chain: the next point starts afresh).
    pub fn push(&mut self, t_vis: f64, hint: Option<Hint>) {
        match hint {
            Some(h) => {
                self.previous.push((t_vis, h));
                if self.previous.len() > HINT_NEIGHBOURS {
                    self.previous.remove(0);
                }
            }
            None => self.previous.clear(),
        }
    }
}

/// `sticking_thresholds` over a sequence of relaxation times (s), each search started from the
/// thresholds of the previous points (see [`SearchOptions::hint`], [`Hint::extrapolated`]). Use an increasing or decreasing
/// sequence: neighbours then have close thresholds.
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
