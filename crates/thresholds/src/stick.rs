//! V_stick and the onset of double collisions by bracketing and bisection (Sections 4.4 and 5).
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing.
//! `V_double_onset` is the sticking -> double transition and `V_stick` the double -> bouncing
//! transition (the paper's threshold velocity for sticking). The double-collision window is narrow
//! (2.6 % of V_stick at T_vis = 1e-9 s, 4e-6 at 1e-14 s), so each transition is searched on its
//! own predicate ("not sticking", "bouncing") from one shared bracket, reusing every collision.
//!
//! V_out is continuous through V_stick (positive for double collisions, negative for bouncing),
//! so V_stick is found by the Illinois variant of regula falsi on V_out(V_in) inside the bracket
//! (a bisection step whenever the lower end is not yet a double collision). The onset is a
//! discontinuity (e jumps from 0 to about -0.1), so it is bisected.

use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Collider, Outcome, SolverOptions};
use greenwood::CrackLaw;

/// Settings of a threshold search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchOptions {
    /// Relative width of the final bisection bracket (dimensionless).
    pub rel_tol: f64,
    /// Highest impact speed tried (m/s); `None` means 1000 V_stick,JKR. Without bouncing below it the
    /// result says so instead of returning a number.
    pub v_max: Option<f64>,
    /// Settings of each collision; the default is [`SearchOptions::default_solver`].
    pub solver: SolverOptions,
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
        if !(v.is_finite() && v > 0.0) {
            return Err(ThresholdsError::OutOfRange {
                field: "v_max",
                value: v,
                allowed: "> 0 and finite",
                unit: "m/s",
            });
        }
    }
    Ok(())
}

/// V_stick and V_double_onset of `contact` at relaxation time `t_vis` (s, >= 0) with the crack
/// law `law` (its k). `t_vis = 0` is the JKR limit: both equal V_stick,JKR.
pub fn sticking_thresholds(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    opts: &SearchOptions,
) -> Result<StickingThresholds, ThresholdsError> {
    check_options(opts)?;
    let v_jkr = contact.v_stick_jkr();
    let v_max = opts.v_max.unwrap_or(1000.0 * v_jkr);
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
    let mut classify = |v: f64, seen: &mut Seen| -> Result<Outcome, ThresholdsError> {
        let c = collider.collide(v)?;
        seen.record(v, c.outcome, c.v_out);
        Ok(c.outcome)
    };

    // Lower bracket: a sticking collision. V_stick >= V_stick,JKR, so start just below it.
    let v_floor = 1e-6 * v_jkr;
    let mut v = (0.99 * v_jkr).min(0.5 * v_max);
    while classify(v, &mut seen)? != Outcome::Sticking {
        v *= 0.5;
        if v < v_floor {
            return Err(ThresholdsError::NoSticking { v_min: v, t_vis });
        }
    }
    // Upper bracket: a bouncing collision, growing by 1.5 up to v_max.
    while !seen.has(bouncing) {
        if v >= v_max {
            break;
        }
        v = (1.5 * v).min(v_max);
        classify(v, &mut seen)?;
    }
    if !seen.has(bouncing) {
        // No bouncing up to v_max; maybe not even a double collision.
        let v_double_onset = if seen.has(not_sticking) {
            Some(bisect(
                &mut seen,
                opts.rel_tol,
                &mut classify,
                not_sticking,
            )?)
        } else {
            None
        };
        return Ok(StickingThresholds {
            t_vis,
            v_stick: None,
            v_double_onset,
            v_stick_jkr: v_jkr,
            v_max,
            collisions: seen.points.len(),
        });
    }
    let v_stick = regula_falsi_v_out(&mut seen, opts.rel_tol, &mut classify)?;
    let v_double_onset = bisect(&mut seen, opts.rel_tol, &mut classify, not_sticking)?;
    Ok(StickingThresholds {
        t_vis,
        v_stick: Some(v_stick),
        v_double_onset: Some(v_double_onset),
        v_stick_jkr: v_jkr,
        v_max,
        collisions: seen.points.len(),
    })
}

/// Bisects the transition to `is_above` inside the bracket of what `seen` holds.
fn bisect(
    seen: &mut Seen,
    rel_tol: f64,
    classify: &mut impl FnMut(f64, &mut Seen) -> Result<Outcome, ThresholdsError>,
    is_above: fn(Outcome) -> bool,
) -> Result<f64, ThresholdsError> {
    loop {
        let (Some(lo), Some(hi)) = seen.bracket(is_above) else {
            return Err(ThresholdsError::Internal(
                "bisection started without a bracket".into(),
            ));
        };
        if hi - lo <= rel_tol * hi {
            return Ok(0.5 * (lo + hi));
        }
        classify(0.5 * (lo + hi), seen)?;
    }
}

/// V_stick by the Illinois variant of regula falsi on V_out inside the bracket of "bouncing";
/// bisection while the lower end is not a double collision (V_out undefined for sticking).
fn regula_falsi_v_out(
    seen: &mut Seen,
    rel_tol: f64,
    classify: &mut impl FnMut(f64, &mut Seen) -> Result<Outcome, ThresholdsError>,
) -> Result<f64, ThresholdsError> {
    // Illinois: halve the weight of an end that stays for two steps in a row.
    let mut weight_lo = 1.0;
    let mut weight_hi = 1.0;
    let mut last_moved: Option<bool> = None; // Some(true): the lower end moved last
    loop {
        let (Some(lo), Some(hi)) = seen.bracket(bouncing) else {
            return Err(ThresholdsError::Internal(
                "regula falsi started without a bracket".into(),
            ));
        };
        if hi - lo <= rel_tol * hi {
            return Ok(0.5 * (lo + hi));
        }
        let f_lo = seen.v_out_at(lo).unwrap_or(0.0);
        let f_hi = seen.v_out_at(hi).unwrap_or(0.0);
        let lo_is_double = f_lo > 0.0;
        let mut v = if lo_is_double && f_hi < 0.0 {
            let (a, b) = (weight_lo * f_lo, weight_hi * f_hi);
            (lo * b - hi * a) / (b - a)
        } else {
            0.5 * (lo + hi)
        };
        // keep the new point strictly inside, at least a quarter tolerance from either end
        let margin = 0.25 * rel_tol * hi;
        v = v.clamp(lo + margin, hi - margin);
        let moved_lo = classify(v, seen)? != Outcome::Bouncing;
        if lo_is_double {
            match (last_moved, moved_lo) {
                (Some(true), true) => weight_hi *= 0.5,
                (Some(false), false) => weight_lo *= 0.5,
                _ => {
                    weight_lo = 1.0;
                    weight_hi = 1.0;
                }
            }
            last_moved = Some(moved_lo);
        }
    }
}
