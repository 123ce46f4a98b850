//! One head-on collision: integrate from first contact to separation or to a proof of sticking.
//!
//! Section 2.6 of Arakawa & Krijt (2021): start at `delta = 0`, `delta_dot = V_in`,
//! `beta = (1 + eps) k`; end when `beta = (1 - eps)/k`, where the spheres separate with
//! `V_out = delta_dot`. Outcomes (Section 4): bouncing (`V_out < 0`, `e = -V_out/V_in > 0`),
//! double collision (`V_out > 0`, `e < 0`), sticking (the contact never ends, `e = 0`).
//!
//! # Deciding "sticking"
//! 1. **Energy bound (rigorous).** The total energy `m* delta_dot^2/2 + U_E - pi a^2 gamma` never
//!    increases (F_D dissipates; the crack speed has the sign of `1 - beta`), and no state with
//!    `beta = (1 - eps)/k` has energy below [`crate::model::end_energy_bound`] (0 for k < 0.33).
//!    Once the energy is below that bound by a margin larger than the integration error, the
//!    contact can never end.
//! 2. **Oscillations (weak damping).** For T_vis below about 1e-11 s the energy can stay above the
//!    bound for thousands of oscillations. A contact that has completed
//!    [`SolverOptions::max_oscillations`] full oscillations after the first compression (maxima of
//!    delta while still in contact) has already failed to separate on an outward swing with more
//!    energy than any later one has; it is declared sticking. The tests show that the transitions
//!    do not move when this number is changed. The decision comes as soon as the last of these
//!    oscillations is certain: once the spheres approach again with the crack advancing
//!    (beta < 1), beta cannot reach 1 before the maximum of delta (at beta = 1 the crack stops
//!    and the approach lowers beta), so the contact cannot end before it.
//!
//! # Continuing from the rebound
//! The equations are autonomous, so a collision is determined by its state at any point. Each
//! collision records its state where delta first returns to zero on the way out
//! ([`Collision::rebound`]); [`Collider::collide_from`] continues a collision from such a state,
//! for instance one interpolated by [`Rebound::between`] from two collisions at nearby speeds:
//! every outcome is decided after the rebound, so a scan over impact speeds can skip the
//! compression of most of its collisions.

use crate::model::{self, Params, NSTATES};
use crate::scales::Scales;
use crate::DynamicsError;
use contact::Contact;
use diffsol::{
    FaerLU, FaerMat, NalgebraLU, NalgebraMat, OdeBuilder, OdeEquations, OdeSolverMethod, Vector,
};
use greenwood::CrackLaw;
use numerics::roots::{illinois, Illinois};
use numerics::OutOfRange;

/// The fiducial eps = 0.01 of Section 2.6 (start at beta = (1 + eps) k, end at (1 - eps)/k).
pub const EPS: f64 = 0.01;

/// First step of the integration, in pseudo-time units of t0. diffsol's default (1.0) is a whole
/// compression; 1e-6 resolves the initial growth of the crack, and step control enlarges it
/// within a few steps.
pub const H0: f64 = 1e-6;

/// Which integrator of diffsol to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The explicit [`Method::Tsit45`] where the collision is not stiff, BDF where it is: Tsit45
    /// first when lambda <= [`AUTO_EXPLICIT_LAMBDA_MAX`] and no trajectory is recorded, started
    /// again with BDF if it takes more than [`auto_explicit_step_budget`] steps or fails. The
    /// outcome is the collision's at the tolerance asked for either way (`docs/performance.md`,
    /// "Integrator").
    #[default]
    Auto,
    /// Variable-order BDF (NDF) method (stiff).
    Bdf,
    /// ESDIRK34 singly-diagonally-implicit Runge-Kutta method (stiff).
    Esdirk34,
    /// Tsitouras 5(4) explicit Runge-Kutta method: fewest steps where the crack moves slowly
    /// (lambda up to about 30), and very many where it is stiff (small T_vis, fast impacts).
    Tsit45,
}

/// [`Method::Auto`] tries the explicit Tsit45 first when lambda (the crack-speed ratio, see
/// [`crate::model`]) is at most this. Measured near the thresholds (CO2 and H2O, T_vis =
/// 1e-12..1e-8 s): Tsit45 takes 0.3-0.75 of BDF's steps for lambda <= 60 at about 1.3 times
/// BDF's cost a step, and more steps than BDF from lambda of about 100 on.
pub const AUTO_EXPLICIT_LAMBDA_MAX: f64 = 30.0;

/// Steps after which [`Method::Auto`] abandons Tsit45 for BDF when Tsit45 runs at rtol = 1e-8;
/// [`auto_explicit_step_budget`] scales it to the tolerance Tsit45 actually runs at (a tenth of
/// the one asked for): 629 when rtol 1e-8 is asked for, about 1.85 times the most Tsit45 takes
/// then for collisions near V_stick where [`AUTO_EXPLICIT_LAMBDA_MAX`] lets it run (340), so
/// that a collision too stiff for it (a fast impact) wastes less than one BDF collision.
pub const AUTO_EXPLICIT_STEPS_AT_RTOL_1E8: f64 = 500.0;

/// [`Method::Auto`] runs Tsit45 at this fraction of the tolerance asked for, so that it is about
/// as accurate as BDF at that tolerance: for a bouncing collision just above V_stick (CO2 60 um
/// and H2O 90 um, T_vis = 1e-9 s) the error of V_out against BDF at rtol 1e-12 is 4.1e-8 and
/// 6.5e-8 of V_in for BDF at rtol 1e-8, 8.0e-8 and 2.7e-7 for Tsit45 at 1e-8, and 4.3e-8 and
/// 1.0e-7 for Tsit45 at 1e-9, which still takes half of BDF's steps (`cargo run --release -p
/// dynamics --example integrators`, `docs/performance.md`, "Integrator").
pub const AUTO_EXPLICIT_RTOL_FACTOR: f64 = 0.1;

/// The step budget of the explicit attempt of [`Method::Auto`] at relative tolerance `rtol`:
/// [`AUTO_EXPLICIT_STEPS_AT_RTOL_1E8`] scaled as the steps of a fifth-order method,
/// `rtol^(-1/5)`, and at least 50.
pub fn auto_explicit_step_budget(rtol: f64) -> usize {
    // float -> usize saturates; the value is finite and positive for valid rtol
    (AUTO_EXPLICIT_STEPS_AT_RTOL_1E8 * (1e-8 / rtol).powf(0.2)).max(50.0) as usize
}

/// Which dense linear algebra diffsol uses for the 4 x 4 Newton systems.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Backend {
    /// nalgebra: measured twice as fast as faer on this 4 x 4 system (`docs/performance.md`).
    #[default]
    Nalgebra,
    /// faer.
    Faer,
}

/// Numerical settings of a collision integration (dimensionless unless stated).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Integrator. Default [`Method::Auto`]: explicit where the collision is not stiff, BDF
    /// where it is (BDF measured faster than ESDIRK34 here; all agree to the tolerance).
    pub method: Method,
    /// Linear algebra of the Newton iterations. Default nalgebra: twice as fast as faer on a
    /// 4 x 4 system (`docs/performance.md`).
    pub backend: Backend,
    /// Relative tolerance of the state. Default 1e-9: V_out to about 1e-8 for single collisions
    /// (threshold searches use 1e-8, see `thresholds::SearchOptions::default_solver`).
    pub rtol: f64,
    /// Absolute tolerance of the nondimensional state (states are O(1)). Default 1e-12.
    pub atol: f64,
    /// Step budget; exceeding it is an [`DynamicsError::Undecided`] error, never a silent answer.
    /// Default 2e6: over 1000 times the steps of the longest collision measured.
    pub max_steps: usize,
    /// Full oscillations in contact after which the collision is declared sticking (>= 1).
    /// Default 1: the transitions do not move with 2 or 6 (`thresholds` tests).
    pub max_oscillations: usize,
    /// Margin below the end-state energy bound, relative to `max(1, initial energy)` in units of
    /// E0. Default 1e-4: far above the integration error of the energy (about rtol).
    pub energy_margin: f64,
    /// Record the trajectory at every solver step. Default off.
    pub record_trajectory: bool,
    /// Apply the sticking criteria only after this time (s); a later decision shows more of a
    /// sticking trajectory (Figure 2) and changes no outcome. Default 0.
    pub decide_after: f64,
}

impl SolverOptions {
    /// Checks every field: `0 < rtol < 1`, `atol > 0`, `decide_after >= 0` (all finite) and
    /// `max_oscillations >= 1`.
    pub fn validate(&self) -> Result<(), OutOfRange> {
        if !(self.rtol.is_finite() && self.rtol > 0.0 && self.rtol < 1.0) {
            return Err(OutOfRange::new(
                "rtol",
                self.rtol,
                "0 < rtol < 1",
                "dimensionless",
            ));
        }
        numerics::positive("atol", self.atol, "dimensionless")?;
        if !(self.decide_after.is_finite() && self.decide_after >= 0.0) {
            return Err(OutOfRange::new(
                "decide_after",
                self.decide_after,
                ">= 0 and finite",
                "s",
            ));
        }
        if self.max_oscillations == 0 {
            return Err(OutOfRange::new(
                "max_oscillations",
                0.0,
                ">= 1",
                "dimensionless",
            ));
        }
        Ok(())
    }
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            method: Method::Auto,
            backend: Backend::Nalgebra,
            rtol: 1e-9,
            atol: 1e-12,
            max_steps: 2_000_000,
            max_oscillations: 1,
            energy_margin: 1e-4,
            record_trajectory: false,
            decide_after: 0.0,
        }
    }
}

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
    /// Duration of the contact (s); `None` for sticking.
    pub contact_time: Option<f64>,
    /// How sticking was decided; `None` otherwise.
    pub sticking_criterion: Option<StickingCriterion>,
    /// Time at which the outcome was decided (s).
    pub decided_at: f64,
    /// Largest increase of the total energy between consecutive steps (J): an integration error
    /// diagnostic, since the exact energy never increases.
    pub max_energy_increase: f64,
    /// Largest beta reached at a solver step (dimensionless): for a sticking collision, how close the
    /// contact came to its end at beta = (1 - eps)/k.
    pub beta_max: f64,
    /// Solver steps taken (by `method`).
    pub steps: usize,
    /// The integrator that decided the outcome ([`Method::Auto`] resolved: Tsit45 or BDF).
    pub method: Method,
    /// Trajectory, when [`SolverOptions::record_trajectory`] is set.
    pub trajectory: Vec<TrajectoryPoint>,
    /// Where the collision first crossed delta = 0 on its way out, if it did: the state
    /// [`Collider::collide_from`] continues a collision of a nearby impact speed from.
    pub rebound: Option<Rebound>,
}

/// The state of a collision where delta first returns to zero on its way out (the rebound,
/// `delta_dot < 0`), from which [`Collider::collide_from`] continues it.
///
/// The system is autonomous, so the rest of a collision depends only on this state. Between two
/// impact speeds close together the rebound state is a smooth function of the speed: for a speed
/// in between, [`Rebound::between`] interpolates it linearly, with an error of order
/// `(relative width)^2 / 8` of the state (`docs/performance.md`, "Rebound restarts").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rebound {
    /// Impact speed of the collision (m/s).
    v_in: f64,
    /// Nondimensional state `(x, y, p, tau)` at the crossing (`y = 0`).
    u: [f64; NSTATES],
    /// The solver's step size there (pseudo-time units), the first step of a continuation.
    h: f64,
    /// Maxima of delta before the crossing (oscillations counted by the sticking criterion).
    maxima: usize,
    /// Largest beta at a step before the crossing.
    beta_max: f64,
    /// Largest increase of the energy between steps before the crossing (units of E0).
    max_increase: f64,
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

/// Where an integration starts: first contact, or a rebound.
#[derive(Debug, Clone, Copy)]
struct Start {
    u: [f64; NSTATES],
    h0: f64,
    maxima: usize,
    beta_max: f64,
    max_increase: f64,
    /// The rebound it starts from (kept in the result), if any.
    rebound: Option<Rebound>,
}

/// Whether a contact in state `u` is bound to stay in contact up to the next maximum of delta:
/// the spheres approach (`p > 0`) and the crack advances (`beta < 1`, with `q = 3x^2 - y > 0`).
/// Along such a state beta cannot reach 1 before p does 0: at beta = 1 the crack stops (v = 0)
/// and `d beta/dtau = (d beta/dy) p = -q p / (2x) < 0`. So beta stays below 1, far from the end
/// of contact at beta_end, until the maximum of delta, where the oscillation criterion decides
/// sticking anyway; deciding here gives the same outcome, earlier.
fn bound_to_next_maximum(u: &[f64; NSTATES]) -> bool {
    let (x, y, p) = (u[0], u[1], u[2]);
    let q = 3.0 * x * x - y;
    p > 0.0 && x > 0.0 && q > 0.0 && model::beta(x, y) < 1.0
}

/// Evaluations of the dense output that place the end of contact (beta = beta_end) or the
/// rebound (delta = 0) inside the step that crossed it: Illinois converges superlinearly, so 12
/// reach the last bits of the pseudo-time.
const CROSSING_ITERATIONS: usize = 12;
/// The crossing's bracket in pseudo-time is narrowed down to this many units in the last place.
const CROSSING_ULPS: f64 = 4.0;

/// Integrates collisions of one contact at one relaxation time.
///
/// It owns its crack law: build the [`CrackLaw`] once per k and pass it (or a reference: the
/// table is shared, never copied) to every collider.
#[derive(Debug, Clone)]
pub struct Collider {
    contact: Contact,
    law: CrackLaw,
    t_vis: f64,
    eps: f64,
    scales: Scales,
    params: Params,
    beta_end: f64,
    energy_bound: f64,
    options: SolverOptions,
}

impl Collider {
    /// Collisions of `contact` with the crack law `law` (a [`CrackLaw`] or a reference to one;
    /// its k) and relaxation time `t_vis` (s, finite, > 0; the limit T_vis -> 0 is JKR theory,
    /// see `contact::Contact::v_stick_jkr`).
    pub fn new(
        contact: Contact,
        law: impl Into<CrackLaw>,
        t_vis: f64,
    ) -> Result<Self, DynamicsError> {
        if !(t_vis.is_finite() && t_vis > 0.0) {
            return Err(OutOfRange::new(
                "t_vis",
                t_vis,
                "> 0 and finite (T_vis -> 0 is the JKR limit: use V_stick,JKR)",
                "s",
            )
            .into());
        }
        let law = law.into();
        let scales = Scales::new(&contact);
        let params = scales.params(&contact, t_vis);
        let mut c = Self {
            contact,
            law,
            t_vis,
            eps: EPS,
            scales,
            params,
            beta_end: 0.0,
            energy_bound: 0.0,
            options: SolverOptions::default(),
        };
        c.set_eps(EPS)?;
        Ok(c)
    }

    fn set_eps(&mut self, eps: f64) -> Result<(), DynamicsError> {
        let k = self.law.k();
        if !(eps.is_finite() && eps > 0.0 && eps < 1.0 && (1.0 + eps) * k < (1.0 - eps) / k) {
            return Err(OutOfRange::new(
                "eps",
                eps,
                "0 < eps < 1 with (1 + eps) k < (1 - eps)/k",
                "dimensionless",
            )
            .into());
        }
        self.eps = eps;
        self.beta_end = (1.0 - eps) / k;
        self.energy_bound = model::end_energy_bound(self.beta_end);
        Ok(())
    }

    /// The same collider with another eps (start at beta = (1 + eps) k, end at (1 - eps)/k).
    pub fn with_eps(mut self, eps: f64) -> Result<Self, DynamicsError> {
        self.set_eps(eps)?;
        Ok(self)
    }

    /// The same collider with other solver settings.
    pub fn with_options(mut self, options: SolverOptions) -> Result<Self, DynamicsError> {
        options.validate()?;
        self.options = options;
        Ok(self)
    }

    /// The contact (SI).
    pub fn contact(&self) -> &Contact {
        &self.contact
    }

    /// The crack law (its k).
    pub fn law(&self) -> &CrackLaw {
        &self.law
    }

    /// Relaxation time T_vis (s).
    pub fn t_vis(&self) -> f64 {
        self.t_vis
    }

    /// The nondimensional units.
    pub fn scales(&self) -> &Scales {
        &self.scales
    }

    /// The nondimensional parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// Solver settings.
    pub fn options(&self) -> &SolverOptions {
        &self.options
    }

    /// beta at which the contact ends, (1 - eps)/k (dimensionless).
    pub fn beta_end(&self) -> f64 {
        self.beta_end
    }

    /// Smallest energy any end-of-contact state can have (J).
    pub fn end_energy_bound(&self) -> f64 {
        self.energy_bound * self.scales.e0
    }

    /// Nondimensional initial state for impact speed `v_in` (m/s).
    fn initial_state(&self, v_in: f64) -> [f64; NSTATES] {
        let x0 = self.contact.initial_contact_radius(self.law.k(), self.eps) / self.scales.a_eq;
        [x0, 0.0, v_in / self.scales.v0, 0.0]
    }

    /// Integrates one collision at impact speed `v_in` (m/s, finite, > 0).
    ///
    /// # Example
    /// ```
    /// use contact::{Contact, Geometry, Material};
    /// use dynamics::{Collider, Outcome};
    /// use greenwood::CrackLaw;
    /// // Section 4 (Figure 2): CO2, R1 = 60 um, T_vis = 1e-9 s, k = 0.01
    /// let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    /// let collider = Collider::new(contact, CrackLaw::new(0.01)?, 1e-9)?;
    /// assert_eq!(collider.collide(0.035)?.outcome, Outcome::Sticking); // 3.5 cm/s
    /// assert_eq!(collider.collide(0.0405)?.outcome, Outcome::DoubleCollision); // 4.05 cm/s
    /// let bounce = collider.collide(0.045)?; // 4.5 cm/s
    /// assert_eq!(bounce.outcome, Outcome::Bouncing);
    /// assert!(bounce.v_out < 0.0 && bounce.e > 0.0 && bounce.e < 1.0);
    /// # Ok::<(), dynamics::DynamicsError>(())
    /// ```
    pub fn collide(&self, v_in: f64) -> Result<Collision, DynamicsError> {
        if !(v_in.is_finite() && v_in > 0.0) {
            return Err(OutOfRange::new("v_in", v_in, "> 0 and finite", "m/s").into());
        }
        let u = self.initial_state(v_in);
        self.integrate(
            v_in,
            Start {
                u,
                h0: H0,
                maxima: 0,
                beta_max: model::beta(u[0], u[1]),
                max_increase: 0.0,
                rebound: None,
            },
        )
    }

    /// Continues a collision at impact speed `v_in` (m/s) from its `rebound` (for instance one
    /// interpolated by [`Rebound::between`] from two collisions at nearby speeds): the same
    /// outcome as [`Collider::collide`] for the part after the rebound, at a fraction of the
    /// cost. The result's `steps` count the steps after the rebound; its trajectory starts there.
    ///
    /// # Example
    /// ```
    /// use contact::{Contact, Geometry, Material};
    /// use dynamics::{Collider, Rebound};
    /// use greenwood::CrackLaw;
    /// let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    /// let collider = Collider::new(contact, CrackLaw::new(0.01)?, 1e-9)?;
    /// // 4.500 and 4.504 cm/s bounce; their rebounds, interpolated, start one at 4.502 cm/s
    /// let (a, b) = (collider.collide(0.04500)?, collider.collide(0.04504)?);
    /// let rebound = Rebound::between(&a.rebound.unwrap(), &b.rebound.unwrap(), 0.04502).unwrap();
    /// let full = collider.collide(0.04502)?;
    /// let continued = collider.collide_from(0.04502, &rebound)?;
    /// assert_eq!(full.outcome, continued.outcome);
    /// assert!((full.v_out / continued.v_out - 1.0).abs() < 1e-6);
    /// assert!(continued.steps < full.steps / 2);
    /// # Ok::<(), dynamics::DynamicsError>(())
    /// ```
    pub fn collide_from(&self, v_in: f64, rebound: &Rebound) -> Result<Collision, DynamicsError> {
        if !(v_in.is_finite() && v_in > 0.0) {
            return Err(OutOfRange::new("v_in", v_in, "> 0 and finite", "m/s").into());
        }
        let rebound = Rebound { v_in, ..*rebound };
        self.integrate(
            v_in,
            Start {
                u: rebound.u,
                h0: rebound.h,
                maxima: rebound.maxima,
                beta_max: rebound.beta_max,
                max_increase: rebound.max_increase,
                rebound: Some(rebound),
            },
        )
    }

    fn integrate(&self, v_in: f64, start: Start) -> Result<Collision, DynamicsError> {
        let u0 = start.u;
        let params = self.params;
        let law: &CrackLaw = &self.law;
        let opts = &self.options;
        // The same problem for either linear-algebra backend.
        macro_rules! integrate {
            ($mat:ty, $lu:ty) => {{
                // `coloring`: the Jacobian through diffsol's coloring path, which assembles it in
                // preallocated scratch vectors (the default path allocates two vectors per
                // Jacobian evaluation); it probes the sparsity when the problem is built, which
                // an explicit method, needing no Jacobian, is spared (3 % of a search at 1e-9 s)
                let problem = |coloring: bool, rtol: f64, atol: f64| {
                    let mut problem = OdeBuilder::<$mat>::new()
                        .rtol(rtol)
                        .atol([atol; NSTATES])
                        .h0(start.h0)
                        .use_coloring(coloring)
                        .rhs_implicit(
                            move |u: &[f64], _p: &[f64], _s: f64, out: &mut [f64]| {
                                model::rhs(&params, law, u, out)
                            },
                            move |u: &[f64], _p: &[f64], _s: f64, w: &[f64], out: &mut [f64]| {
                                model::jac_mul(&params, law, u, w, out)
                            },
                        )
                        .init(
                            move |_p: &[f64], _s: f64, y: &mut [f64]| y.copy_from_slice(&u0),
                            NSTATES,
                        )
                        .build()
                        .map_err(|e| self.solver_error(v_in, e))?;
                    // diffsol's BDF counts Newton failures over the whole integration, not per
                    // step: a long contact (many oscillations) with a few recovered failures at
                    // each graze of the JKR fold would abort after 50. Recovered failures are
                    // normal; the step budget bounds the work.
                    problem.ode_options.max_nonlinear_solver_failures = opts.max_steps;
                    Ok::<_, DynamicsError>(problem)
                };
                if opts.method == Method::Auto
                    && self.params.lambda <= AUTO_EXPLICIT_LAMBDA_MAX
                    && !opts.record_trajectory
                {
                    let rtol = AUTO_EXPLICIT_RTOL_FACTOR * opts.rtol;
                    let explicit = problem(false, rtol, AUTO_EXPLICIT_RTOL_FACTOR * opts.atol)?;
                    let solver = explicit.tsit45();
                    if let Ok(mut solver) = solver {
                        let budget = auto_explicit_step_budget(rtol).min(opts.max_steps);
                        // within budget: done; over budget or failed: stiff here, BDF below
                        let run = self.run(&mut solver, v_in, &start, budget, Method::Tsit45);
                        if let Ok(c) = run {
                            return Ok(c);
                        }
                    }
                }
                let method = match opts.method {
                    Method::Auto => Method::Bdf,
                    m => m,
                };
                let problem = problem(method != Method::Tsit45, opts.rtol, opts.atol)?;
                match method {
                    Method::Esdirk34 => {
                        let mut solver = problem
                            .esdirk34::<$lu>()
                            .map_err(|e| self.solver_error(v_in, e))?;
                        self.run(&mut solver, v_in, &start, opts.max_steps, method)
                    }
                    Method::Tsit45 => {
                        let mut solver =
                            problem.tsit45().map_err(|e| self.solver_error(v_in, e))?;
                        self.run(&mut solver, v_in, &start, opts.max_steps, method)
                    }
                    Method::Auto | Method::Bdf => {
                        let mut solver = problem
                            .bdf::<$lu>()
                            .map_err(|e| self.solver_error(v_in, e))?;
                        self.run(&mut solver, v_in, &start, opts.max_steps, Method::Bdf)
                    }
                }
            }};
        }
        match opts.backend {
            Backend::Nalgebra => integrate!(NalgebraMat<f64>, NalgebraLU<f64>),
            Backend::Faer => integrate!(FaerMat<f64>, FaerLU<f64>),
        }
    }

    /// The state where `g` crosses zero inside the last step, from `(s0, g0)` to `(s1, g1)`
    /// (values of opposite signs, or `g1 = 0`), from the solver's dense output, by the
    /// workspace's root finder ([`numerics::roots::illinois`]). `None` if the dense output
    /// fails.
    fn crossing<'s, Eqn, S>(
        &self,
        solver: &S,
        g: impl Fn(&[f64; NSTATES]) -> f64,
        (s0, g0): (f64, f64),
        (s1, g1): (f64, f64),
    ) -> Option<[f64; NSTATES]>
    where
        Eqn: OdeEquations<T = f64> + 's,
        S: OdeSolverMethod<'s, Eqn>,
    {
        let state = |s: f64| -> Option<[f64; NSTATES]> {
            let v = solver.interpolate(s).ok()?;
            let mut u = [0.0; NSTATES];
            for (i, ui) in u.iter_mut().enumerate() {
                *ui = v.get_index(i);
            }
            Some(u)
        };
        let opts = Illinois {
            x_tol: CROSSING_ULPS * f64::EPSILON * s1.abs(),
            max_iter: CROSSING_ITERATIONS,
            guard: 0.0,
        };
        let root = illinois(
            |s| state(s).map(|u| g(&u)).ok_or(()),
            (s0, g0),
            (s1, g1),
            &opts,
        );
        state(root.ok()?.best)
    }

    fn solver_error(&self, v_in: f64, e: impl std::fmt::Display) -> DynamicsError {
        self.solver_error_at(v_in, &self.initial_state(v_in), e)
    }

    fn solver_error_at(
        &self,
        v_in: f64,
        u: &[f64; NSTATES],
        e: impl std::fmt::Display,
    ) -> DynamicsError {
        let p = self.point(u);
        DynamicsError::Solver {
            geometry: *self.contact.geometry(),
            t_vis: self.t_vis,
            v_in,
            t: p.t,
            a: p.a,
            delta: p.delta,
            delta_dot: p.delta_dot,
            beta: model::beta(u[0], u[1]),
            message: e.to_string(),
        }
    }

    fn point(&self, u: &[f64; NSTATES]) -> TrajectoryPoint {
        let s = &self.scales;
        TrajectoryPoint {
            t: u[3] * s.t0,
            a: u[0] * s.a_eq,
            delta: u[1] * s.delta_eq,
            delta_dot: u[2] * s.v0,
            energy: model::energy(u[0], u[1], u[2]) * s.e0,
            beta: model::beta(u[0], u[1]),
        }
    }

    /// Steps `solver` (of kind `method`) until the outcome is decided, at most `max_steps` steps.
    fn run<'s, Eqn, S>(
        &self,
        solver: &mut S,
        v_in: f64,
        start: &Start,
        max_steps: usize,
        method: Method,
    ) -> Result<Collision, DynamicsError>
    where
        Eqn: OdeEquations<T = f64> + 's,
        S: OdeSolverMethod<'s, Eqn>,
    {
        let opts = &self.options;
        let read = |v: &Eqn::V| -> [f64; NSTATES] {
            [
                v.get_index(0),
                v.get_index(1),
                v.get_index(2),
                v.get_index(3),
            ]
        };
        let mut u = read(solver.state().y);
        // the margin is relative to the energy at first contact, also when starting at a rebound
        let first = self.initial_state(v_in);
        let e_initial = model::energy(first[0], first[1], first[2]);
        let threshold = self.energy_bound - opts.energy_margin * e_initial.abs().max(1.0);
        let mut e_prev = model::energy(u[0], u[1], u[2]);
        let mut max_increase: f64 = start.max_increase;
        let mut maxima = start.maxima;
        let mut beta_max = start.beta_max;
        let mut p_prev = u[2];
        let mut rebound = start.rebound;
        let mut s_prev = solver.state().t;
        let decide_after = opts.decide_after / self.scales.t0;
        let mut trajectory = Vec::new();
        if opts.record_trajectory {
            trajectory.push(self.point(&u));
        }
        let mut beta_prev = model::beta(u[0], u[1]);
        for step in 1..=max_steps {
            solver
                .step()
                .map_err(|e| self.solver_error_at(v_in, &u, e))?;
            let y_prev = u[1];
            let u_step = read(solver.state().y);
            let s_now = solver.state().t;
            let beta_now = model::beta(u_step[0], u_step[1]);
            if beta_now >= self.beta_end {
                // the contact ended inside this step: where beta = beta_end, from the dense output
                let g = |v: &[f64; NSTATES]| model::beta(v[0], v[1]) - self.beta_end;
                let end = self
                    .crossing(
                        solver,
                        g,
                        (s_prev, beta_prev - self.beta_end),
                        (s_now, beta_now - self.beta_end),
                    )
                    .ok_or_else(|| {
                        self.solver_error_at(v_in, &u, "dense output failed at the end of contact")
                    })?;
                let e_end = model::energy(end[0], end[1], end[2]);
                max_increase = max_increase.max(e_end - e_prev);
                let end_point = self.point(&end);
                if opts.record_trajectory {
                    trajectory.push(end_point);
                }
                let v_out = end_point.delta_dot;
                let outcome = if v_out > 0.0 {
                    Outcome::DoubleCollision
                } else {
                    Outcome::Bouncing
                };
                return Ok(Collision {
                    outcome,
                    e: -v_out / v_in,
                    v_out,
                    contact_time: Some(end_point.t),
                    sticking_criterion: None,
                    decided_at: end_point.t,
                    max_energy_increase: max_increase * self.scales.e0,
                    beta_max: self.beta_end,
                    steps: step,
                    method,
                    trajectory,
                    rebound,
                });
            }
            beta_prev = beta_now;
            u = u_step;
            beta_max = beta_max.max(beta_now);
            let energy = model::energy(u[0], u[1], u[2]);
            max_increase = max_increase.max(energy - e_prev);
            e_prev = energy;
            if opts.record_trajectory {
                trajectory.push(self.point(&u));
            }
            if p_prev > 0.0 && u[2] <= 0.0 {
                maxima += 1;
            }
            p_prev = u[2];
            if rebound.is_none() && y_prev > 0.0 && u[1] <= 0.0 && u[2] < 0.0 {
                rebound = self
                    .crossing(solver, |v| v[1], (s_prev, y_prev), (s_now, u[1]))
                    .map(|u| Rebound {
                        v_in,
                        u,
                        h: solver.state().h,
                        maxima: 0,
                        beta_max: 0.0,
                        max_increase: 0.0,
                    });
                if let Some(r) = rebound.as_mut() {
                    r.maxima = maxima;
                    r.beta_max = beta_max;
                    r.max_increase = max_increase;
                }
            }
            s_prev = s_now;
            let criterion = if u[3] < decide_after {
                None
            } else if energy < threshold {
                Some(StickingCriterion::EnergyBound)
            } else if maxima > opts.max_oscillations
                || (maxima == opts.max_oscillations && bound_to_next_maximum(&u))
            {
                Some(StickingCriterion::Oscillations)
            } else {
                None
            };
            if let Some(criterion) = criterion {
                return Ok(Collision {
                    outcome: Outcome::Sticking,
                    e: 0.0,
                    v_out: 0.0,
                    contact_time: None,
                    sticking_criterion: Some(criterion),
                    decided_at: u[3] * self.scales.t0,
                    max_energy_increase: max_increase * self.scales.e0,
                    beta_max,
                    steps: step,
                    method,
                    trajectory,
                    rebound,
                });
            }
        }
        Err(DynamicsError::Undecided {
            geometry: *self.contact.geometry(),
            t_vis: self.t_vis,
            v_in,
            steps: max_steps,
        })
    }
}
