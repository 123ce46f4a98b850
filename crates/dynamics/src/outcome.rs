//! What a collision gives: its [`Outcome`] (Section 4), how sticking was decided
//! ([`StickingCriterion`]), the result [`Collision`] and the recorded [`TrajectoryPoint`]s (SI).

use crate::Method;
use crate::Rebound;

/// Outcome of one collision (Section 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Outcome {
    /// The contact never ends (e = 0).
    Sticking,
    /// The contact ends with `delta_dot > 0`: the spheres meet again at once (e < 0 computed).
    DoubleCollision,
    /// The contact ends with `delta_dot < 0`: the spheres fly apart (0 < e < 1).
    Bouncing,
}

impl Outcome {
    /// The coefficient of restitution an experiment observes for a collision of this outcome
    /// whose first contact gives `e = -V_out/V_in`: `e` for bouncing; 0 for sticking and for a
    /// double collision, whose second contact follows at once and sticks (Section 4.4).
    ///
    /// ```
    /// use dynamics::Outcome;
    /// assert_eq!(Outcome::Bouncing.observed_e(0.3), 0.3);
    /// assert_eq!(Outcome::DoubleCollision.observed_e(-0.1), 0.0);
    /// ```
    pub fn observed_e(self, e: f64) -> f64 {
        if self == Outcome::Bouncing {
            e
        } else {
            0.0
        }
    }

    /// `sticking`, `double` or `bouncing`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Outcome::Sticking => "sticking",
            Outcome::DoubleCollision => "double",
            Outcome::Bouncing => "bouncing",
        }
    }
}

/// How a sticking outcome was decided.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StickingCriterion {
    /// The energy fell below the end-of-contact bound (rigorous).
    EnergyBound,
    /// The contact completed the allowed number of oscillations, or is bound to complete the
    /// last of them (approaching with the crack advancing).
    Oscillations,
}

/// One recorded state (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrajectoryPoint {
    /// Time since first contact (s).
    pub t: f64,
    /// Contact radius a (m).
    pub a: f64,
    /// Mutual approach delta (m).
    pub delta: f64,
    /// Approach speed delta_dot (m/s).
    pub delta_dot: f64,
    /// Total energy (J).
    pub energy: f64,
    /// Normalized apparent surface energy beta = G_eff/gamma (dimensionless).
    pub beta: f64,
}

/// Result of one collision (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct Collision {
    /// Outcome.
    pub outcome: Outcome,
    /// Coefficient of restitution `e = -V_out/V_in` (0 for sticking; negative for double collisions).
    pub e: f64,
    /// Approach speed at the end of contact V_out (m/s; 0 for sticking).
    pub v_out: f64,
    /// Duration of the contact (s); `None` for sticking, and for an answer of the restitution
    /// tables ([`Collision::from_rebound`]: no trajectory was integrated).
    pub contact_time: Option<f64>,
    /// How sticking was decided; `None` otherwise (and for an answer of the restitution tables).
    pub sticking_criterion: Option<StickingCriterion>,
    /// Time at which the outcome was decided (s; NaN for an answer of the restitution tables).
    pub decided_at: f64,
    /// Largest increase of the total energy between consecutive steps (J): an integration error
    /// diagnostic, since the exact energy never increases (0 for an answer of the restitution
    /// tables: nothing was integrated).
    pub max_energy_increase: f64,
    /// Largest beta reached at a solver step (dimensionless): for a sticking collision, how close the
    /// contact came to its end at beta = (1 - eps)/k (NaN for an answer of the restitution
    /// tables).
    pub beta_max: f64,
    /// Solver steps taken (by `method`; 0 for an answer of the restitution tables).
    pub steps: usize,
    /// The integrator that decided the outcome ([`Method::Auto`] resolved: Tsit45 or BDF), or
    /// [`Method::Auto`] itself where nothing was integrated (an answer of the restitution
    /// tables, [`Collision::from_rebound`]).
    pub method: Method,
    /// Trajectory, when [`crate::SolverOptions::record_trajectory`] is set.
    pub trajectory: Vec<TrajectoryPoint>,
    /// Where the collision first crossed delta = 0 on its way out, if it did: the state
    /// [`crate::Collider::collide_from`] continues a collision of a nearby impact speed from.
    pub rebound: Option<Rebound>,
}

impl Collision {
    /// A collision known only by its rebound (outcome, e, V_out in m/s), as the restitution
    /// tables of `thresholds` give it: no contact time, trajectory or solver statistics (NaN,
    /// empty, zero).
    pub fn from_rebound(outcome: Outcome, e: f64, v_out: f64) -> Self {
        Self {
            outcome,
            e,
            v_out,
            contact_time: None,
            sticking_criterion: None,
            decided_at: f64::NAN,
            max_energy_increase: 0.0,
            beta_max: f64::NAN,
            steps: 0,
            method: Method::Auto,
            trajectory: Vec::new(),
            rebound: None,
        }
    }

    /// The coefficient of restitution an experiment observes ([`Outcome::observed_e`]): `e` for
    /// bouncing, 0 for sticking and double collisions (Section 4.4).
    pub fn observed_e(&self) -> f64 {
        self.outcome.observed_e(self.e)
    }
}
