//! V_stick as the zero of V_out: the speeds of the V_stick stage.
//!
//! V_out(V_in) is continuous through V_stick (positive for double collisions, negative for
//! bouncing), so V_stick is a zero of V_out. Coarse collisions only estimate it (a coarse
//! collision near V_stick may be misclassified, so their outcomes are not used for the result):
//! secant steps on a coarse rung, safeguarded by trisection, until they move by less than
//! [`SECANT_SETTLED`] ([`Search::coarse_estimate`]). Then pairs of full-tolerance collisions:
//! around the estimate, then around the zero of the parabola through the three collisions
//! nearest to V_out = 0, which closes the bracket; wider pairs or trisection continue at full
//! tolerance when a pair does not straddle V_stick ([`Search::closing_jobs`]).

use super::ladder::LADDER;
use super::{trisect, Search, Seen, Transition};
use crate::ThresholdsError;
use dynamics::Outcome;

/// The rung of the coarse secant steps once the bracket is narrower than the coarsest rung
/// allows: rtol 1e-5, a third of the cost of full tolerance, with V_out accurate to about 1e-5,
/// matched to the first full-tolerance pair ([`TIGHT_PAIR_HALF_WIDTH`] is its shift). While the
/// bracket is wider, the coarsest rung trisects it. Letting the secant steps move on to the
/// next rung as the bracket narrows took 2 % more steps over five sweeps (CO2 and H2O, 25-41
/// T_vis each; `docs/performance.md`, "Search constants re-measured").
const SECANT_RUNG: usize = 1;
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
/// Half-width (relative) of the first full-tolerance pair around a coarse estimate: the shift
/// bound of the secant rung, twice the largest shift measured there (7e-5), so that the pair
/// straddles V_stick.
pub(crate) const TIGHT_PAIR_HALF_WIDTH: f64 = LADDER[SECANT_RUNG].shift;
/// Half-width of a closing pair of V_stick, relative to the search's `rel_tol`: a pair around a
/// root estimate that straddles V_stick is then a final bracket (narrower than `rel_tol`), and
/// it tolerates an estimate 0.45 `rel_tol` off (the secant through two full-tolerance collisions
/// 3e-4 apart was off by 4.6e-7 at T_vis = 1e-11 s, CO2 60 um).
const CLOSING_HALF_WIDTH: f64 = 0.45;
/// How far outside the two zeros of [`bouncing_zeros`] its pair lies, relative to `rel_tol`: a
/// quarter of the tolerance, so that the pair brackets V_stick and is a final bracket when the
/// two zeros are close.
const BOUNCING_PAIR_MARGIN: f64 = 0.25;
/// Factor by which a full-tolerance pair widens when it missed V_stick on one side.
const PAIR_GROWTH: f64 = 2.0;
/// The widest a pair grows (relative half-width): after a dozen misses (7e-5 doubled 12 times)
/// the pair spans 0.75-1.25 of its centre and a step down halves the speed, so no speed
/// reaches 0 (a search just below the no-bouncing cliff missed 20 times and asked V_in < 0).
const MAX_PAIR_HALF_WIDTH: f64 = 0.25;
/// The largest half-width of a pair around the secant zero of two full-tolerance collisions, as
/// a fraction of their bracket: the pair then lies inside the bracket.
const SECANT_PAIR_MAX_HALF_WIDTH: f64 = 0.25;

/// Where the V_stick stage stands.
#[derive(Debug, Clone, Copy)]
pub(crate) struct StickState {
    /// The coarse estimate has stopped moving.
    settled: bool,
    /// The latest coarse estimate (m/s).
    estimate: Option<f64>,
    /// Coarse steps taken.
    coarse_steps: usize,
    /// Relative half-width of the next full-tolerance pair.
    half_width: f64,
}

impl Default for StickState {
    fn default() -> Self {
        Self {
            settled: false,
            estimate: None,
            coarse_steps: 0,
            half_width: TIGHT_PAIR_HALF_WIDTH,
        }
    }
}

/// The zero of the line through `a` and `b` in the (V_in, V_out) plane.
fn secant_zero(a: &Seen, b: &Seen) -> f64 {
    a.v - a.v_out * (b.v - a.v) / (b.v_out - a.v_out)
}

/// The zero nearest to `a` of the parabola through `a`, `b` and `c` in the (V_in, V_out) plane;
/// `None` when it has no real zero. With `t = V_in - v_a`, the parabola is
/// `f_abc t^2 + (f_ab - f_abc (v_b - v_a)) t + V_out,a` (Newton's divided differences), and its
/// zero of smaller |t| is `-2c / (b + sign(b) sqrt(b^2 - 4ac))`, free of cancellation.
fn parabola_zero(a: &Seen, b: &Seen, c: &Seen) -> Option<f64> {
    let f_ab = (b.v_out - a.v_out) / (b.v - a.v);
    let f_bc = (c.v_out - b.v_out) / (c.v - b.v);
    let f_abc = (f_bc - f_ab) / (c.v - a.v);
    let (qa, qb, qc) = (f_abc, f_ab - f_abc * (b.v - a.v), a.v_out);
    if qc == 0.0 {
        return Some(a.v);
    }
    let discriminant = qb * qb - 4.0 * qa * qc;
    if discriminant.is_nan() || discriminant < 0.0 {
        return None;
    }
    let v = a.v - 2.0 * qc / (qb + qb.signum() * discriminant.sqrt());
    (v.is_finite() && v > 0.0).then_some(v)
}

/// Two estimates of V_stick from two bouncing collisions `a` and `b` above it: V_out falls to
/// zero between linearly (the secant of V_out is exact) and like a square root of
/// V_in - V_stick (the JKR limit, where V_out^2 = V_in^2 - V_stick^2 is nearly linear in V_in
/// and the secant of V_out^2 nearly exact); for a shape in between, the first zero lies below
/// V_stick and the second above. In increasing order.
fn bouncing_zeros(a: &Seen, b: &Seen) -> (f64, f64) {
    let linear = secant_zero(a, b);
    let (a2, b2) = (a.v_out * a.v_out, b.v_out * b.v_out);
    let square = a.v - a2 * (b.v - a.v) / (b2 - a2);
    (linear.min(square), linear.max(square))
}

impl Search<'_> {
    /// The next two speeds for V_stick; none when it is done.
    pub(crate) fn stick_jobs(&mut self) -> Result<Vec<(f64, usize)>, ThresholdsError> {
        if !self.has(Transition::Stick) {
            return Ok(Vec::new());
        }
        if !self.stick.settled {
            if let Some(jobs) = self.coarse_estimate() {
                return Ok(jobs);
            }
            self.stick.settled = true;
        }
        Ok(self.closing_jobs())
    }

    /// A coarse round towards the estimate of V_stick, or `None` once it has settled (or the
    /// bracket is narrow): secant steps on V_out on the coarsest rung the bracket allows (at most
    /// [`SECANT_RUNG`]), trisection while no secant root falls inside the bracket.
    fn coarse_estimate(&mut self) -> Option<Vec<(f64, usize)>> {
        let (Some(lo), Some(hi)) = self.bracket(Transition::Stick) else {
            return None;
        };
        let coarse = self
            .rung_for((hi.v - lo.v) / hi.v)
            .min(SECANT_RUNG)
            .max(super::min_rung(&self.seen));
        // ends from that rung or finer once they bracket V_stick: a coarser end may be
        // misclassified within its rung's shift, and would keep the secant root out
        let (lo, hi) = match self.bracket_from(coarse, Transition::Stick) {
            (Some(l), Some(h)) => (l, h),
            _ => (lo, hi),
        };
        let inside = |q: &f64| *q > lo.v && *q < hi.v;
        if hi.v - lo.v > TIGHT_PAIR_HALF_WIDTH * hi.v
            && self.stick.coarse_steps < MAX_COARSE_SECANT_STEPS
        {
            // a neighbour's V_stick is the first estimate, then the secant root when it falls
            // inside the bracket, else the bracket is trisected (before two speeds have a V_out,
            // or when V_out curves)
            let hinted = self
                .opts
                .hint
                .map(|h| h.v_stick)
                .filter(|_| self.stick.estimate.is_none());
            let root = hinted
                .filter(inside)
                .or_else(|| self.v_out_root(coarse).filter(inside))
                .or_else(|| self.v_out_root(0).filter(inside));
            let Some(p) = root else {
                self.stick.coarse_steps += 1;
                return Some(trisect(lo.v, hi.v, coarse));
            };
            let settled = self
                .stick
                .estimate
                .is_some_and(|e| (e - p).abs() <= SECANT_SETTLED * p);
            self.stick.estimate = Some(p);
            if settled {
                return None;
            }
            self.stick.coarse_steps += 1;
            // a second speed a little above: a local secant next round
            Some(vec![(p, coarse), (p * (1.0 + SECANT_PROBE), coarse)])
        } else {
            // the bracket is narrow: the secant root inside it, else the last estimate if still
            // inside (an earlier one may have been passed), else its midpoint
            let estimate = self
                .v_out_root(coarse)
                .filter(inside)
                .or(self.stick.estimate.filter(inside))
                .unwrap_or(0.5 * (lo.v + hi.v));
            self.stick.estimate = Some(estimate);
            None
        }
    }

    /// The next pair of full-tolerance collisions for V_stick; none once they bracket it to
    /// `rel_tol` (or nothing bounces up to `v_max`).
    fn closing_jobs(&mut self) -> Vec<(f64, usize)> {
        let tight = self.tight();
        let rel_tol = self.opts.rel_tol;
        let p = match self.tight_bracket(Transition::Stick) {
            (Some(lo), Some(hi)) => {
                if hi.v - lo.v <= rel_tol * hi.v {
                    return Vec::new();
                }
                // V_out crosses zero smoothly from a double collision: the zero of the parabola
                // through the three speeds nearest to it, and a closing pair around it
                let closing = CLOSING_HALF_WIDTH * rel_tol;
                if let Some(q) = self
                    .quadratic_root(tight)
                    .filter(|q| lo.outcome == Outcome::DoubleCollision && *q > lo.v && *q < hi.v)
                {
                    let below = (q * (1.0 - closing)).max(0.5 * (lo.v + q));
                    let above = (q * (1.0 + closing)).min(0.5 * (q + hi.v));
                    return vec![(below, tight), (above, tight)];
                }
                if let Some((a, b)) = self.bouncing_roots(tight) {
                    // just outside the two estimates, inside the bracket
                    let margin = BOUNCING_PAIR_MARGIN * rel_tol;
                    let mut below = a * (1.0 - margin);
                    if below <= lo.v {
                        below = 0.5 * (lo.v + b.min(hi.v));
                    }
                    let mut above = b * (1.0 + margin);
                    if above >= hi.v {
                        above = 0.5 * (a.max(lo.v) + hi.v);
                    }
                    // both inside the bracket, or the pair would not narrow it (the two zeros
                    // can both lie below a sticking lower end when V_out is steep there)
                    if lo.v < below && below < above && above < hi.v {
                        return vec![(below, tight), (above, tight)];
                    }
                }
                match self.v_out_root(tight).filter(|q| *q > lo.v && *q < hi.v) {
                    Some(q) => {
                        self.stick.half_width =
                            closing.min(SECANT_PAIR_MAX_HALF_WIDTH * (hi.v - lo.v) / hi.v);
                        q
                    }
                    // no secant (V_out is steep near V_stick in the JKR limit, and a sticking
                    // lower end has none): trisect
                    None => return trisect(lo.v, hi.v, tight),
                }
            }
            (Some(lo), None) => {
                // everything at full tolerance so far is below V_stick: go up, to v_max at most
                if lo.v >= self.v_max * (1.0 - rel_tol) {
                    return Vec::new();
                }
                self.stick.half_width =
                    (self.stick.half_width * PAIR_GROWTH).min(MAX_PAIR_HALF_WIDTH);
                lo.v * (1.0 + 2.0 * self.stick.half_width)
            }
            (None, Some(hi)) => {
                // everything at full tolerance so far bounces: follow V_out down to its root
                // (two bouncing speeds at full tolerance), or step down
                self.stick.half_width =
                    (self.stick.half_width * PAIR_GROWTH).min(MAX_PAIR_HALF_WIDTH);
                let step = hi.v * (1.0 - 2.0 * self.stick.half_width);
                self.v_out_root(tight)
                    .filter(|q| *q < hi.v)
                    .map_or(step, |q| q.max(step))
            }
            (None, None) => match self.stick.estimate {
                Some(p) => p,
                None => match self.bracket(Transition::Stick) {
                    (Some(lo), Some(hi)) => 0.5 * (lo.v + hi.v),
                    _ => return Vec::new(),
                },
            },
        };
        let half = self.stick.half_width;
        let p = p.min(self.v_max / (1.0 + half));
        vec![(p * (1.0 - half), tight), (p * (1.0 + half), tight)]
    }

    /// [`bouncing_zeros`] of the two collisions on `rung` or finer nearest to V_out = 0 when
    /// both bounce (no double collision is nearer); `None` otherwise or outside `(0, v_max)`.
    fn bouncing_roots(&self, rung: usize) -> Option<(f64, f64)> {
        let (a, b) = self.nearest_to_v_out_zero(rung)?;
        if !(a.outcome == Outcome::Bouncing && b.outcome == Outcome::Bouncing) {
            return None;
        }
        let (lo, hi) = bouncing_zeros(&a, &b);
        (lo.is_finite() && hi.is_finite() && lo > 0.0 && hi < self.v_max).then_some((lo, hi))
    }

    /// [`parabola_zero`] of the three double or bouncing collisions on `rung` or finer with the
    /// smallest |V_out|; `None` without three such speeds.
    fn quadratic_root(&self, rung: usize) -> Option<f64> {
        let pts = self.by_distance_to_v_out_zero(rung);
        let [a, b, c, ..] = pts.as_slice() else {
            return None;
        };
        parabola_zero(a, b, c)
    }

    /// The root of V_out(V_in) by a secant through the two speeds with the smallest |V_out|
    /// among double collisions and bouncing integrated on `rung` or finer (extrapolated from
    /// the bouncing side while no double collision is known). `None` without two such speeds.
    fn v_out_root(&self, rung: usize) -> Option<f64> {
        let (a, b) = self.nearest_to_v_out_zero(rung)?;
        let p = secant_zero(&a, &b);
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
            .filter(|p| p.outcome != Outcome::Sticking && p.rung >= rung)
            .copied()
            .collect();
        pts.sort_by(|a, b| a.v_out.abs().total_cmp(&b.v_out.abs()));
        pts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A full-tolerance collision at `v` whose `v_out` gives its outcome.
    fn at(v: f64, v_out: f64) -> Seen {
        let outcome = if v_out > 0.0 {
            Outcome::DoubleCollision
        } else {
            Outcome::Bouncing
        };
        Seen::at(v, outcome, v_out)
    }

    /// Closed forms: the line through (1, 1) and (3, -1) is zero at 2; the parabola
    /// V_out = (2 - V)(V + 1) through three of its points is zero at 2 (the zero nearest to the
    /// point with the smallest |V_out|, not -1), and a parabola without a real zero gives none.
    #[test]
    fn secant_and_parabola_zeros() {
        assert_eq!(secant_zero(&at(1.0, 1.0), &at(3.0, -1.0)), 2.0);
        let f = |v: f64| (2.0 - v) * (v + 1.0);
        let (a, b, c) = (at(1.9, f(1.9)), at(2.2, f(2.2)), at(1.5, f(1.5)));
        let zero = parabola_zero(&a, &b, &c).unwrap();
        assert!((zero - 2.0).abs() < 1e-14, "{zero}");
        let g = |v: f64| -(v - 2.0).powi(2) - 0.1;
        assert_eq!(
            parabola_zero(&at(1.9, g(1.9)), &at(2.2, g(2.2)), &at(1.5, g(1.5))),
            None
        );
    }

    /// Three shapes of V_out above V_stick = 1: the square root of the JKR limit, a power 3/4 in
    /// between, and a line; the two zeros bracket V_stick for each, and the linear zero is exact
    /// for the line.
    #[test]
    fn bouncing_zeros_bracket_v_stick() {
        let shapes: [fn(f64) -> f64; 3] = [
            |v| -(v * v - 1.0).sqrt(),
            |v| -(v - 1.0).powf(0.75),
            |v| -(v - 1.0),
        ];
        for shape in shapes {
            let (lo, hi) = bouncing_zeros(&at(1.01, shape(1.01)), &at(1.02, shape(1.02)));
            assert!(lo <= 1.0 + 1e-12 && hi >= 1.0 - 1e-12, "{lo} {hi}");
        }
        let line = |v: f64| -(v - 1.0);
        let (lo, _) = bouncing_zeros(&at(1.01, line(1.01)), &at(1.02, line(1.02)));
        assert!((lo - 1.0).abs() < 1e-12);
    }
}
