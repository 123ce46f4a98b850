//! Deciding "sticking": when a contact can be proved never to end.
//!
//! 1. **Energy bound (rigorous).** The total energy `m* delta_dot^2/2 + U_E - pi a^2 gamma` never
//!    increases (F_D dissipates; the crack speed has the sign of `1 - beta`), and no state with
//!    `beta = (1 - eps)/k` has energy below [`crate::model::end_energy_bound`] (0 for k < 0.33).
//!    Once the energy is below that bound by a margin larger than the integration error, the
//!    contact can never end.
//! 2. **Oscillations (weak damping).** For T_vis below about 1e-11 s the energy can stay above the
//!    bound for thousands of oscillations. A contact that has completed
//!    [`crate::SolverOptions::max_oscillations`] full oscillations after the first compression
//!    (maxima of delta while still in contact) has already failed to separate on an outward swing
//!    with more energy than any later one has; it is declared sticking. The tests show that the
//!    transitions do not move when this number is changed. The decision comes as soon as the last
//!    of these oscillations is certain: once the spheres approach again with the crack advancing
//!    (beta < 1), beta cannot reach 1 before the maximum of delta (at beta = 1 the crack stops
//!    and the approach lowers beta), so the contact cannot end before it
//!    (`bound_to_next_maximum`).

use crate::model::{self, NSTATES};
use crate::StickingCriterion;

/// The two criteria along one integration, in the nondimensional state `(x, y, p, tau)` and
/// energy of [`crate::model`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct StickingWatch {
    /// Energy below which the contact can never end: the end-state bound minus the margin.
    threshold: f64,
    /// Pseudo-time units of t0 before which nothing is decided.
    decide_after: f64,
    /// Full oscillations after which the contact sticks.
    max_oscillations: usize,
    /// Maxima of delta counted so far.
    maxima: usize,
    /// p at the previous step.
    p_prev: f64,
}

impl StickingWatch {
    /// A watch for an integration from `u0` with `maxima` maxima of delta already behind it
    /// (non-zero when it starts at a rebound). `energy_bound` is the smallest energy of an end
    /// state, `energy_margin` the margin below it relative to `max(1, |e_initial|)` (the energy at
    /// first contact), `decide_after` in units of t0.
    pub(crate) fn new(
        energy_bound: f64,
        energy_margin: f64,
        e_initial: f64,
        decide_after: f64,
        max_oscillations: usize,
        maxima: usize,
        u0: &[f64; NSTATES],
    ) -> Self {
        Self {
            threshold: energy_bound - energy_margin * e_initial.abs().max(1.0),
            decide_after,
            max_oscillations,
            maxima,
            p_prev: u0[2],
        }
    }

    /// Counts a maximum of delta if p changed sign from + to - over the step that ended at `u`.
    pub(crate) fn count_maximum(&mut self, u: &[f64; NSTATES]) {
        if self.p_prev > 0.0 && u[2] <= 0.0 {
            self.maxima += 1;
        }
        self.p_prev = u[2];
    }

    /// Maxima of delta counted so far.
    pub(crate) fn maxima(&self) -> usize {
        self.maxima
    }

    /// Whether the contact at `u` with `energy` (units of E0) has been proved to stick, and how.
    pub(crate) fn decide(&self, u: &[f64; NSTATES], energy: f64) -> Option<StickingCriterion> {
        if u[3] < self.decide_after {
            None
        } else if energy < self.threshold {
            Some(StickingCriterion::EnergyBound)
        } else if self.maxima > self.max_oscillations
            || (self.maxima == self.max_oscillations && bound_to_next_maximum(u))
        {
            Some(StickingCriterion::Oscillations)
        } else {
            None
        }
    }
}

/// Whether a contact in state `u` is bound to stay in contact up to the next maximum of delta:
/// the spheres approach (`p > 0`) and the crack advances (`beta < 1`, with `q = 3x^2 - y > 0`).
/// Along such a state beta cannot reach 1 before p does 0: at beta = 1 the crack stops (v = 0)
/// and `d beta/dtau = (d beta/dy) p = -q p / (2x) < 0`. So beta stays below 1, far from the end
/// of contact at beta_end, until the maximum of delta, where the oscillation criterion decides
/// sticking anyway; deciding here gives the same outcome, earlier.
pub(crate) fn bound_to_next_maximum(u: &[f64; NSTATES]) -> bool {
    let (x, y, p) = (u[0], u[1], u[2]);
    let q = 3.0 * x * x - y;
    p > 0.0 && x > 0.0 && q > 0.0 && model::beta(x, y) < 1.0
}
