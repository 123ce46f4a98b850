//! The rebound: a collision's state where delta first returns to zero on its way out.
//!
//! The equations are autonomous, so a collision is determined by its state at any point. Each
//! collision records its state where delta first returns to zero on the way out
//! ([`crate::Collision::rebound`]); [`crate::Collider::collide_from`] continues a collision from
//! such a state, for instance one interpolated by [`Rebound::between`] from two collisions at
//! nearby speeds: every outcome is decided after the rebound, so a scan over impact speeds can
//! skip the compression of most of its collisions.

use crate::model::NSTATES;
use crate::scales::Scales;

/// The state of a collision where delta first returns to zero on its way out (the rebound,
/// `delta_dot < 0`), from which [`crate::Collider::collide_from`] continues it.
///
/// The system is autonomous, so the rest of a collision depends only on this state. Between two
/// impact speeds close together the rebound state is a smooth function of the speed: for a speed
/// in between, [`Rebound::between`] interpolates it linearly, with an error of order
/// `(relative width)^2 / 8` of the state (`docs/performance.md`, "Rebound restarts").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rebound {
    /// Impact speed of the collision (m/s).
    pub(crate) v_in: f64,
    /// Nondimensional state `(x, y, p, tau)` at the crossing (`y = 0`).
    pub(crate) u: [f64; NSTATES],
    /// The solver's step size there (pseudo-time units), the first step of a continuation.
    pub(crate) h: f64,
    /// Maxima of delta before the crossing (oscillations counted by the sticking criterion).
    pub(crate) maxima: usize,
    /// Largest beta at a step before the crossing.
    pub(crate) beta_max: f64,
    /// Largest increase of the energy between steps before the crossing (units of E0).
    pub(crate) max_increase: f64,
}

impl Rebound {
    /// Impact speed of the collision this rebound belongs to (m/s).
    pub fn v_in(&self) -> f64 {
        self.v_in
    }

    /// The nondimensional state `(x, y, p, tau)` at the rebound (`y = 0`; see [`crate::model`]).
    pub fn state(&self) -> [f64; NSTATES] {
        self.u
    }

    /// Time from first contact to the rebound (s), given the collider's scales.
    pub fn time(&self, scales: &Scales) -> f64 {
        self.u[3] * scales.t0
    }

    /// The rebound of a collision at `v_in` (m/s), strictly between the impact speeds of `a` and
    /// `b`, by linear interpolation of their states in the impact speed. `None` when `v_in` is
    /// not between them or they counted different oscillations before their rebound.
    pub fn between(a: &Rebound, b: &Rebound, v_in: f64) -> Option<Rebound> {
        let (lo, hi) = (a.v_in.min(b.v_in), a.v_in.max(b.v_in));
        if !(v_in > lo && v_in < hi) {
            return None;
        }
        Rebound::through(a, b, v_in)
    }

    /// The rebound of a collision at `v_in` (m/s) on the line through the states of `a` and `b`
    /// in the impact speed: interpolated between them or extrapolated beyond either. The error
    /// is about `C |(v_in - v_a)(v_in - v_b)| / v_in^2` of the state, with C measured below 0.5
    /// near the thresholds for interpolation and extrapolation alike (`docs/performance.md`,
    /// "Rebound restarts"). `None` when `a` and `b` have the same speed or counted different
    /// oscillations before their rebound.
    pub fn through(a: &Rebound, b: &Rebound, v_in: f64) -> Option<Rebound> {
        if a.v_in == b.v_in || a.maxima != b.maxima || !v_in.is_finite() {
            return None;
        }
        let w = (v_in - a.v_in) / (b.v_in - a.v_in);
        let lerp = |x: f64, y: f64| x + w * (y - x);
        let mut u = [0.0; NSTATES];
        for (i, ui) in u.iter_mut().enumerate() {
            *ui = lerp(a.u[i], b.u[i]);
        }
        Some(Rebound {
            v_in,
            u,
            h: a.h.min(b.h),
            maxima: a.maxima,
            beta_max: a.beta_max.max(b.beta_max),
            max_increase: a.max_increase.max(b.max_increase),
        })
    }
}
