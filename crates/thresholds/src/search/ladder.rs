//! The tolerance ladder: coarse solver tolerances for the early rounds of a search.
//!
//! While a bracket is wide, a coarse collision (a quarter to a third of the cost of one at the
//! search's own tolerance) classifies a speed as well as a tight one. Each rung of [`LADDER`] is
//! used only while the bracket it refines is wider than [`LADDER_MARGIN`] times the rung's
//! `shift`; the final brackets of both transitions are made of collisions at the search's own
//! tolerance only (the rung after the ladder, [`Search::tight`]).

use super::Search;
use crate::ThresholdsError;
use contact::Contact;
use dynamics::{Collider, SolverOptions};
use greenwood::CrackLaw;

/// One rung: a solver tolerance and how far it moves the transitions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rung {
    /// Relative tolerance of the collisions on this rung.
    pub(crate) rtol: f64,
    /// Absolute tolerance of the nondimensional state: [`dynamics::ATOL_PER_RTOL`] `rtol`, the
    /// ratio of the search's own settings ([`crate::SearchOptions::default_solver`]: 1e-11 at
    /// 1e-8).
    pub(crate) atol: f64,
    /// A bound on how far this tolerance moves the transitions (relative to V_in) from a tight
    /// reference.
    pub(crate) shift: f64,
}

impl Rung {
    /// The rung of relative tolerance `rtol` with the bound `shift`.
    const fn new(rtol: f64, shift: f64) -> Self {
        Self {
            rtol,
            atol: dynamics::ATOL_PER_RTOL * rtol,
            shift,
        }
    }
}

/// The coarse rungs, coarsest first. The shifts measured over CO2 and H2O at
/// T_vis = 1e-14..1e-8 s (`docs/performance.md`, "Tolerance ladder") are 1.1e-3, 7.4e-5 and
/// 1.4e-6; each bound here is 1.8 times that or more. The last rung, the search's own solver
/// settings, is exact by definition.
pub(crate) const LADDER: [Rung; 3] = [
    Rung::new(1e-4, 2e-3),
    Rung::new(1e-5, 1.5e-4),
    Rung::new(1e-7, 3e-6),
];

/// A rung of [`LADDER`] classifies impact speeds only while the bracket it refines is wider
/// than this many times its shift: a misclassified speed then lies near the bracket's far end,
/// where the final check at full tolerance finds it.
pub(crate) const LADDER_MARGIN: f64 = 4.0;

/// One collider a rung of [`LADDER`], then one with the search's own settings `solver`.
pub(crate) fn colliders(
    contact: &Contact,
    law: &CrackLaw,
    t_vis: f64,
    solver: &SolverOptions,
) -> Result<Vec<Collider>, ThresholdsError> {
    let mut colliders = Vec::with_capacity(LADDER.len() + 1);
    for rung in LADDER {
        let options = SolverOptions {
            rtol: rung.rtol,
            atol: rung.atol,
            ..*solver
        };
        colliders.push(Collider::new(*contact, law, t_vis)?.with_options(options)?);
    }
    colliders.push(Collider::new(*contact, law, t_vis)?.with_options(*solver)?);
    Ok(colliders)
}

impl Search<'_> {
    /// The finest rung: the search's own solver settings.
    pub(crate) fn tight(&self) -> usize {
        LADDER.len()
    }

    /// The coarsest rung fit to classify speeds inside a bracket of relative width `width`:
    /// one whose shift is below `width` by [`LADDER_MARGIN`] and whose tolerance is coarser
    /// than the search's own; the search's own otherwise.
    /// Never a rung this search found unreliable ([`super::min_rung`]).
    pub(crate) fn rung_for(&self, width: f64) -> usize {
        rung_for(width, self.opts.solver.rtol).max(super::min_rung(&self.seen))
    }
}

/// [`Search::rung_for`] for a search at solver tolerance `rtol`.
fn rung_for(width: f64, rtol: f64) -> usize {
    LADDER
        .iter()
        .position(|r| width > LADDER_MARGIN * r.shift && r.rtol > rtol)
        .unwrap_or(LADDER.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bracket of a factor 1.5 is classified on the coarsest rung; one of 1e-3 (between 4
    /// times the second shift, 6e-4, and 4 times the first, 8e-3) on the second; one of 1e-6,
    /// below every margin, at full tolerance; and a search asking for rtol 1e-5 never uses a
    /// rung as fine as its own.
    #[test]
    fn the_rung_follows_the_width_of_the_bracket() {
        assert_eq!(rung_for(0.5, 1e-8), 0);
        assert_eq!(rung_for(1e-3, 1e-8), 1);
        assert_eq!(rung_for(1e-4, 1e-8), 2);
        assert_eq!(rung_for(1e-6, 1e-8), 3);
        assert_eq!(rung_for(1e-3, 1e-5), 3);
    }

    /// `rung_for` takes the first rung that fits, which is the coarsest only if the ladder runs
    /// from coarse to fine.
    #[test]
    fn the_ladder_runs_from_coarse_to_fine() {
        for w in LADDER.windows(2) {
            assert!(w[0].rtol > w[1].rtol && w[0].shift > w[1].shift);
        }
    }
}
