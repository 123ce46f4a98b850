//! Hints: the thresholds a search expects, from the points before it in a sweep.
//!
//! Along a sweep in T_vis neighbouring points have close thresholds. A search given a [`Hint`]
//! starts with one round around it instead of bracketing from V_stick,JKR
//! ([`crate::SearchOptions::hint`]); a wrong hint costs a round, never the result.
//! [`Hint::extrapolated`] extrapolates the last points' thresholds to the next T_vis, with a
//! `spread` that says how far off it may be; [`HintChain`] keeps those points along a sweep.

use crate::search::ladder::{LADDER, LADDER_MARGIN};

/// The [`Hint::spread`] of a hint from one neighbour, or where an extrapolation is doubtful: the
/// first round tries 10 % below the hinted onset and 10 % above the hinted V_stick, on the
/// coarsest rung, which brackets both transitions when the hint is a few per cent off.
pub const HINT_SPREAD_ONE: f64 = 0.1;
/// The spread of an extrapolated hint, per its step (the relative change from the nearer
/// neighbour's thresholds): over Figure-4-like sweeps (CO2 60 um, k = 0.01 and 0.02, 33 T_vis
/// from 1e-12 to 1e-8 s) the extrapolation of [`Hint::extrapolated`] was off by at most 0.34 of
/// its step (0.01-0.03 below T_vis = 1e-9 s, where the thresholds follow the power law closely),
/// on 11 T_vis per 4 decades by up to 0.75 of it at 1e-8 s (`docs/performance.md`, item 20).
/// Re-measured over five sweeps (CO2 k = 0.01, 0.02 and on a wall, H2O at two gamma_SV): the
/// three spread constants together save 8 % of the steps against a spread of 0.1 for every
/// hint (`docs/performance.md`, "Search constants re-measured").
const HINT_SPREAD_PER_STEP: f64 = 0.75;
/// The smallest spread of an extrapolated hint: just wide enough for the first round to run on
/// the second rung of the tolerance ladder (a spread above [`LADDER_MARGIN`] times its shift),
/// a third cheaper from first contact than the third. Over the sweeps of
/// [`HINT_SPREAD_PER_STEP`], floors of 1e-4 (first rounds on the third rung), 1e-3 and 2e-3
/// took 2-3 % more steps; re-measured over five sweeps, 1e-4 took 2 % more.
const HINT_SPREAD_MIN: f64 = 1.02 * LADDER_MARGIN * LADDER[1].shift;
/// The spread of an extrapolated hint per miss of the same extrapolation one point earlier:
/// the misses grew by at most a factor 1.9 from one point to the next over the sweeps of
/// [`HINT_SPREAD_PER_STEP`] (`docs/performance.md`, item 20). Without it (the spread from the
/// step alone) five sweeps took 4 % more steps.
const HINT_SPREAD_PER_MISS: f64 = 3.0;
/// How many previous points of a sweep seed the hint of the next ([`Hint::extrapolated`]).
pub const HINT_NEIGHBOURS: usize = 3;

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

    /// The thresholds of one neighbour (m/s) as a hint, when it has both.
    pub fn from_thresholds(v_double_onset: Option<f64>, v_stick: Option<f64>) -> Option<Hint> {
        Some(Hint::from_neighbour(v_double_onset?, v_stick?))
    }

    /// The hint for a search at `t_vis` (s) from the thresholds of the points before it in a
    /// sweep, `previous` (the last [`HINT_NEIGHBOURS`] or fewer, as `(t_vis, hint)` in sweep
    /// order), and `floor` (m/s), the value both thresholds tend to as T_vis -> 0 (V_stick,JKR
    /// of the contact; 0 if unknown).
    ///
    /// With two neighbours or more, each threshold's excess over `floor` is extrapolated from
    /// the nearest two as a power law in T_vis (it grows about like T_vis^0.9 for CO2 60 um
    /// below 1e-10 s; the change of the excess is capped at a factor
    /// `HINT_EXTRAPOLATION_MAX`). The spread is `HINT_SPREAD_PER_STEP` times the larger
    /// relative change from the nearest neighbour or, with a third neighbour, if smaller,
    /// `HINT_SPREAD_PER_MISS` times how far the same extrapolation one point earlier missed the
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
