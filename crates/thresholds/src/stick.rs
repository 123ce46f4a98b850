//! V_stick and the onset of double collisions by bracketing and bisection (Sections 4.4 and 5).
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing.
//! `V_double_onset` is the sticking -> double transition and `V_stick` the double -> bouncing
//! transition (the paper's threshold velocity for sticking). The double-collision window is narrow
//! (2.6 % of V_stick at T_vis = 1e-9 s, 4e-6 at 1e-14 s), so each transition is searched on its
//! own predicate ("not sticking", "bouncing") from one shared bracket, reusing every collision.
//!
//! V_out is continuous through V_stick (positive for double collisions, negative for bouncing),
//! so V_stick is found by regula falsi on V_out(V_in) inside its bracket (the midpoint whenever
//! the lower end is not yet a double collision). The onset is a discontinuity (e jumps from 0 to
//! about -0.1), so it is bisected. Each round integrates two speeds: one for each transition
//! while both are open, then two for the remaining one (regula falsi and midpoint for V_stick,
//! trisection for the onset).

use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Collider, Outcome, SolverOptions};
use greenwood::CrackLaw;

/// Highest impact speed any search integrates (m/s): 10 km/s is far above the collision speeds
/// of dust and ice grains (tens of m/s) and far beyond where contact mechanics applies.
pub const V_SEARCH_LIMIT: f64 = 1e4;

/// Settings of a threshold search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchOptions {
    /// Relative width of the final bisection bracket (dimensionless).
    pub rel_tol: f64,
    /// Highest impact speed tried (m/s, at most [`V_SEARCH_LIMIT`]); `None` means 1000 V_stick,JKR
    /// (at most [`V_SEARCH_LIMIT`]). Without bouncing below it the result says so instead of
    /// returning a number.
    pub v_max: Option<f64>,
    /// Settings of each collision; the default is [`SearchOptions::default_solver`].
    pub solver: SolverOptions,
    /// Integrate the two collisions of each round on two threads (the result is the same).
    pub parallel: bool,
    /// Thresholds expected from a neighbouring point of a sweep (m/s): the first round tries
    /// just below `v_double_onset` and just above `v_stick` instead of bracketing from
    /// V_stick,JKR. A wrong hint costs one round, never the result.
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

impl StickingThresholds {
    /// This result as the hint for a neighbouring point (`None` without both thresholds).
    pub fn as_hint(&self) -> Option<Hint> {
        Some(Hint {
            v_double_onset: self.v_double_onset?,
            v_stick: self.v_stick?,
        })
    }
}

impl SearchOptions {
    /// Collision settings for threshold searches: relative tolerance 1e-8 (absolute 1e-11), which
    /// moves V_stick and V_double_onset by less than 5e-8 relative from a 1e-11 reference
    /// (`docs/performance.md`), well inside the bisection tolerance of 1e-6.
    pub fn default_solver() -> SolverOptions {
        SolverOptions {
            rtol: 1e-8,
            atol: 1e-11,
            ..SolverOptions::default()
        }
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

/// Every classified impact speed with its outcome and V_out, for the two searches.
#[derive(Debug, Default)]
struct Seen {
    points: Vec<(f64, Outcome)>,
    v_out: Vec<f64>,
}

impl Seen {
    fn record(&mut self, v: f64, outcome: Outcome, v_out: f64) {
        self.points.push((v, outcome));
        self.v_out.push(v_out);
    }

    /// V_out at a recorded speed.
    fn v_out_at(&self, v: f64) -> Option<f64> {
        self.points
            .iter()
            .position(|p| p.0 == v)
            .map(|i| self.v_out[i])
    }

    /// Smallest speed with `is_above`, and the largest speed below it without.
    fn bracket(&self, is_above: impl Fn(Outcome) -> bool) -> (Option<f64>, Option<f64>) {
        let hi = self
            .points
            .iter()
            .filter(|(_, o)| is_above(*o))
            .map(|p| p.0)
            .reduce(f64::min);
        let lo = self
            .points
            .iter()
            .filter(|(v, o)| !is_above(*o) && hi.is_none_or(|h| *v < h))
            .map(|p| p.0)
            .reduce(f64::max);
        (lo, hi)
    }

    fn has(&self, outcome: impl Fn(Outcome) -> bool) -> bool {
        self.points.iter().any(|(_, o)| outcome(*o))
    }
}

fn not_sticking(o: Outcome) -> bool {
    o != Outcome::Sticking
}

fn bouncing(o: Outcome) -> bool {
    o == Outcome::Bouncing
}

fn check_options(opts: &SearchOptions) -> Result<(), ThresholdsError> {
    if !(opts.rel_tol.is_finite() && opts.rel_tol > 1e-15 && opts.rel_tol < 0.5) {
        return Err(ThresholdsError::OutOfRange {
            field: "rel_tol",
            value: opts.rel_tol,
            allowed: "1e-15 < rel_tol < 0.5",
            unit: "dimensionless",
        });
    }
    if let Some(v) = opts.v_max {
        if !(v > 0.0 && v <= V_SEARCH_LIMIT) {
            return Err(ThresholdsError::OutOfRange {
                field: "v_max",
                value: v,
                allowed: "0 < v_max <= 1e4",
                unit: "m/s",
            });
        }
    }
    Ok(())
}

/// V_stick and V_double_onset of `contact` at relaxation time `t_vis` (s, >= 0) with the crack
/// law `law` (its k). `t_vis = 0` is the JKR limit: both equal V_stick,JKR.
///
/// Every round integrates two impact speeds, concurrently when [`SearchOptions::parallel`] is set
/// (two cores halve the wall time); the speeds chosen depend only on the outcomes seen, so the
/// result is the same either way.
pub fn sticking_thresholds(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    opts: &SearchOptions,
) -> Result<StickingThresholds, ThresholdsError> {
    check_options(opts)?;
    let v_jkr = contact.v_stick_jkr();
    let v_max = opts.v_max.unwrap_or((1000.0 * v_jkr).min(V_SEARCH_LIMIT));
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
    let collider = Collider::new(*contact, law, t_vis)?.with_options(opts.solver)?;
    let mut seen = Seen::default();
    let round = |speeds: [f64; 2], seen: &mut Seen| -> Result<(), ThresholdsError> {
        let one = |v: f64| collider.collide(v);
        let (a, b) = if opts.parallel {
            rayon::join(|| one(speeds[0]), || one(speeds[1]))
        } else {
            (one(speeds[0]), one(speeds[1]))
        };
        for (v, c) in speeds.into_iter().zip([a?, b?]) {
            seen.record(v, c.outcome, c.v_out);
        }
        Ok(())
    };
    let tol = opts.rel_tol;
    let v_floor = 1e-6 * v_jkr;

    // Lower bracket: a sticking collision. V_stick >= V_stick,JKR, so start just below it (and
    // try 1.6 V_stick,JKR towards the upper bracket in the same round), or around a hint.
    let mut v = (0.99 * v_jkr).min(0.5 * v_max);
    let hinted = opts.hint.filter(|h| {
        h.v_double_onset > 0.0 && h.v_stick >= h.v_double_onset && h.v_stick * 1.02 <= v_max
    });
    match hinted {
        Some(h) => round([0.98 * h.v_double_onset, 1.02 * h.v_stick], &mut seen)?,
        None => round([v, (1.6 * v).min(v_max)], &mut seen)?,
    }
    if hinted.is_some() && !seen.has(|o| o == Outcome::Sticking) {
        round([v, 0.5 * v], &mut seen)?;
    }
    while !seen.has(|o| o == Outcome::Sticking) {
        v *= 0.25;
        if v < v_floor {
            return Err(ThresholdsError::NoSticking { v_min: v, t_vis });
        }
        round([2.0 * v, v], &mut seen)?;
    }
    // Upper bracket: a bouncing collision, growing by 1.5 a step up to v_max.
    let mut top = seen.points.iter().map(|p| p.0).fold(0.0, f64::max);
    while !seen.has(bouncing) && top < v_max {
        let a = (1.5 * top).min(v_max);
        let b = (1.5 * a).min(v_max);
        round([a, b], &mut seen)?;
        top = b;
    }

    // Both transitions, two speeds a round.
    let converged = |(lo, hi): (Option<f64>, Option<f64>)| match (lo, hi) {
        (Some(lo), Some(hi)) => hi - lo <= tol * hi,
        _ => true, // nothing to search (for example no bouncing below v_max)
    };
    loop {
        let stick_bracket = seen.bracket(bouncing);
        let onset_bracket = seen.bracket(not_sticking);
        let (stick_done, onset_done) = (converged(stick_bracket), converged(onset_bracket));
        let speeds = match (stick_done, onset_done) {
            (true, true) => break,
            (false, false) => {
                let p = regula_falsi_point(&seen, stick_bracket, tol);
                let q = midpoint(onset_bracket);
                if (p - q).abs() > tol * p {
                    [p, q]
                } else {
                    // one bracket for both: trisect it
                    let (lo, hi) = (
                        onset_bracket.0.unwrap_or(0.0),
                        stick_bracket.1.unwrap_or(0.0),
                    );
                    [lo + (hi - lo) / 3.0, lo + 2.0 * (hi - lo) / 3.0]
                }
            }
            (false, true) => {
                let p = regula_falsi_point(&seen, stick_bracket, tol);
                [p, midpoint(stick_bracket)]
            }
            (true, false) => {
                let (lo, hi) = (
                    onset_bracket.0.unwrap_or(0.0),
                    onset_bracket.1.unwrap_or(0.0),
                );
                [lo + (hi - lo) / 3.0, lo + 2.0 * (hi - lo) / 3.0]
            }
        };
        round(speeds, &mut seen)?;
    }
    let center = |(lo, hi): (Option<f64>, Option<f64>)| match (lo, hi) {
        (Some(lo), Some(hi)) => Some(0.5 * (lo + hi)),
        _ => None,
    };
    let v_stick = if seen.has(bouncing) {
        center(seen.bracket(bouncing))
    } else {
        None
    };
    let v_double_onset = if seen.has(not_sticking) {
        center(seen.bracket(not_sticking))
    } else {
        None
    };
    Ok(StickingThresholds {
        t_vis,
        v_stick,
        v_double_onset,
        v_stick_jkr: v_jkr,
        v_max,
        collisions: seen.points.len(),
    })
}

fn midpoint((lo, hi): (Option<f64>, Option<f64>)) -> f64 {
    0.5 * (lo.unwrap_or(0.0) + hi.unwrap_or(0.0))
}

/// The regula falsi point of V_out(V_in) in the V_stick bracket when its lower end is a double
/// collision (V_out > 0 there, < 0 at the bouncing end), else the midpoint; kept a quarter of the
/// tolerance inside the bracket.
fn regula_falsi_point(seen: &Seen, (lo, hi): (Option<f64>, Option<f64>), tol: f64) -> f64 {
    let (lo, hi) = (lo.unwrap_or(0.0), hi.unwrap_or(0.0));
    let f_lo = seen.v_out_at(lo).unwrap_or(0.0);
    let f_hi = seen.v_out_at(hi).unwrap_or(0.0);
    let v = if f_lo > 0.0 && f_hi < 0.0 {
        (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
    } else {
        0.5 * (lo + hi)
    };
    let margin = 0.25 * tol * hi;
    v.clamp(lo + margin, hi - margin)
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
