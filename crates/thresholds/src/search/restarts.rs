//! Rebound restarts: a collision that starts at its rebound, interpolated from two collisions
//! close by, instead of at first contact.
//!
//! A collision whose speed lies close to two collisions of the same rung (between them, or just
//! beyond, with an error of the line through them no larger than interpolating in a bracket of
//! relative width [`RESTART_MAX_WIDTH`] on the last rung, wider on coarse ones) starts at its
//! rebound, the state where delta returns to zero, interpolated or extrapolated from theirs
//! ([`dynamics::Rebound`]): the outcome is decided after the rebound, and the part before it is
//! a half to two thirds of the steps ([`crate::SearchOptions::restarts`]).

use super::ladder::LADDER;
use super::Search;
use dynamics::Rebound;

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
        .map_or(RESTART_MAX_WIDTH, |r| r.shift.sqrt())
}

/// Of the speeds `speeds` (m/s), the pair `(i, j)`, `i < j`, whose line is the best start for a
/// collision at `v`: the smallest `|(v - v_i)(v - v_j)|`, at most that of the middle of a
/// bracket of absolute width `width` (`width^2/4`), with `v` between them or beyond the nearer
/// by at most their spacing (further out, the solver's own noise in the two states would be
/// amplified), among the pairs that are `usable`.
fn best_pair(
    v: f64,
    width: f64,
    speeds: &[f64],
    usable: impl Fn(usize, usize) -> bool,
) -> Option<(usize, usize)> {
    let mut best: Option<(f64, (usize, usize))> = None;
    for (i, &va) in speeds.iter().enumerate() {
        for (j, &vb) in speeds.iter().enumerate().skip(i + 1) {
            let product = ((v - va) * (v - vb)).abs();
            let between = (v - va) * (v - vb) < 0.0;
            let beyond = (v - va).abs().min((v - vb).abs()) <= (va - vb).abs();
            if product <= 0.25 * width * width
                && (between || beyond)
                && best.as_ref().is_none_or(|(q, _)| product < *q)
                && usable(i, j)
            {
                best = Some((product, (i, j)));
            }
        }
    }
    best.map(|(_, pair)| pair)
}

impl Search<'_> {
    /// The rebound to start a collision at `v` on `rung` from: on the line through the
    /// rebounds of two collisions of that rung, `a` and `b`, whose error (about
    /// `0.36 |(v - v_a)(v - v_b)| / v^2` of the state, `docs/performance.md`, "Rebound
    /// restarts") is smallest and at most that of interpolating at the middle of a bracket of
    /// relative width [`restart_width`] ([`best_pair`]). `None` (integrate from first contact)
    /// otherwise, or when restarts are off.
    pub(crate) fn restart_from(&self, v: f64, rung: usize) -> Option<Rebound> {
        if !self.opts.restarts {
            return None;
        }
        let same: Vec<(f64, Rebound)> = self
            .seen
            .iter()
            .filter(|p| p.rung == rung && p.v != v)
            .filter_map(|p| Some((p.v, p.rebound?)))
            .collect();
        let speeds: Vec<f64> = same.iter().map(|s| s.0).collect();
        let line = |i: usize, j: usize| Rebound::through(&same[i].1, &same[j].1, v);
        let (i, j) = best_pair(v, restart_width(rung) * v, &speeds, |i, j| {
            line(i, j).is_some()
        })?;
        line(i, j)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Between 1.0 and 1.2 a speed of 1.1 has the smallest product (0.01) among 1.0, 1.2, 1.5;
    /// 1.3 lies beyond 1.2 by less than the spacing of (1.0, 1.2) but the pair (1.2, 1.5) around
    /// it is better; 2.0 is too far from all; an unusable pair is skipped for the next best
    /// (at 1.05: (1.0, 1.2) 0.0075, then (1.0, 1.5) 0.0225, then (1.2, 1.5) 0.0675).
    #[test]
    fn the_closest_usable_pair_is_chosen() {
        let speeds = [1.0, 1.2, 1.5];
        let all = |_: usize, _: usize| true;
        assert_eq!(best_pair(1.1, 1.0, &speeds, all), Some((0, 1)));
        assert_eq!(best_pair(1.3, 1.0, &speeds, all), Some((1, 2)));
        assert_eq!(best_pair(2.0, 0.5, &speeds, all), None);
        assert_eq!(
            best_pair(1.05, 1.0, &speeds, |i, j| (i, j) != (0, 1)),
            Some((0, 2))
        );
        // beyond the nearer end by more than the pair's spacing: none
        assert_eq!(best_pair(1.25, 10.0, &[1.0, 1.01], all), None);
    }

    /// A coarse rung allows restarts over sqrt(shift), the search's own rung over 3.2e-4.
    #[test]
    fn coarse_rungs_allow_wider_lines() {
        assert_eq!(restart_width(LADDER.len()), RESTART_MAX_WIDTH);
        assert!(restart_width(0) > restart_width(1) && restart_width(1) > RESTART_MAX_WIDTH);
    }
}
