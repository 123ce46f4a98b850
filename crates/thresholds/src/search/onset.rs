//! The onset of double collisions: the speeds of the onset stage.
//!
//! The onset is a jump in the outcome (e from 0 to about -0.1), so it is trisected, on coarse
//! rungs of the tolerance ladder while the bracket is wide, and closed at full tolerance.

use super::{trisect, Search, Transition};

impl Search<'_> {
    /// The next speeds (one or two) for the onset of double collisions; none when it is done.
    ///
    /// The onset is a jump in the outcome: it is trisected on the coarsest rung the bracket's
    /// width allows. A coarse speed within its rung's shift of the onset may be misclassified:
    /// when both ends come from coarser rungs than the width now needs (the bracket has just
    /// narrowed past a rung), the new rung trisects it, which usually yields two new ends; an end
    /// still coarser after that is integrated again on the current rung, alongside the bracket's
    /// midpoint, and the final ends at full tolerance.
    pub(crate) fn onset_jobs(&self) -> Vec<(f64, usize)> {
        let (Some(lo), Some(hi)) = self.bracket(Transition::DoubleOnset) else {
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
}
