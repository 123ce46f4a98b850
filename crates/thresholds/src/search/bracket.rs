//! The first bracket: a sticking speed below both transitions and a bouncing one above them.
//!
//! Without a hint the search starts just below V_stick,JKR (V_stick >= V_stick,JKR for every
//! T_vis > 0) and grows the upper trial by [`UPPER_GROWTH`] until something bounces, up to
//! `v_max`; with a hint from a neighbouring point of a sweep ([`crate::Hint`]) it starts around
//! the hinted thresholds, a `spread` away, on the coarsest rung that resolves that spread.

use super::{Search, Transition};
use crate::search::hints::HINT_SPREAD_ONE;
use crate::ThresholdsError;

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
/// Growth of the upper trial per step while nothing bounces: 1.5 keeps the bracket of V_out
/// tight enough for the secant steps on V_out while reaching 1000 V_stick,JKR in 9 rounds.
const UPPER_GROWTH: f64 = 1.5;
/// Shrink factor of the lower trial while nothing sticks (rare: a wrong hint, extreme inputs).
const LOWER_SHRINK: f64 = 0.25;
/// Lowest speed tried, in units of V_stick,JKR, before declaring that nothing sticks.
const V_FLOOR_OVER_JKR: f64 = 1e-6;
/// The first lower trial is at most this fraction of `v_max`, so that the first upper one
/// ([`FIRST_UPPER_OVER_LOWER`] times it) still lies below `v_max`.
const FIRST_LOWER_MAX_OVER_V_MAX: f64 = 0.5;
/// When nothing stuck in the rounds around a hint, the next round tries the unhinted first lower
/// trial and this fraction of it, before the shrinking steps of [`LOWER_SHRINK`].
const HINT_MISS_LOWER: f64 = 0.5;

impl Search<'_> {
    /// Stage 1: a sticking speed below both transitions and, unless nothing bounces up to
    /// `v_max`, a bouncing speed above them, on the coarsest rung.
    pub(crate) fn bracket_stage(&mut self) -> Result<(), ThresholdsError> {
        let coarse = self.rung_for(f64::INFINITY);
        let mut v =
            (FIRST_LOWER_OVER_JKR * self.v_jkr).min(FIRST_LOWER_MAX_OVER_V_MAX * self.v_max);
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
                    match (self.has_sticking(), self.has(Transition::Stick)) {
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
        if hinted.is_some() && !self.has_sticking() {
            self.round(&[(v, coarse), (HINT_MISS_LOWER * v, coarse)])?;
            // the loop below continues below there (already integrated): its first round is
            // 2 LOWER_SHRINK and LOWER_SHRINK times it
            v *= HINT_MISS_LOWER;
        }
        while !self.has_sticking() {
            v *= LOWER_SHRINK;
            if v < V_FLOOR_OVER_JKR * self.v_jkr {
                return Err(ThresholdsError::NoSticking {
                    v_min: v,
                    t_vis: self.colliders[0].t_vis(),
                });
            }
            // the speed shrunk once, and twice that (between it and the last one)
            self.round(&[(2.0 * v, coarse), (v, coarse)])?;
        }
        let mut top = self.seen.iter().map(|p| p.v).fold(0.0, f64::max);
        while !self.has(Transition::Stick) && top < v_max {
            let a = (UPPER_GROWTH * top).min(v_max);
            let b = (UPPER_GROWTH * a).min(v_max);
            self.round(&[(a, coarse), (b, coarse)])?;
            top = b;
        }
        Ok(())
    }
}
