//! [`Collider`]: one head-on collision, from first contact to separation or to a proof of
//! sticking (Sections 2.5 and 4).
//!
//! Section 2.5 of Arakawa & Krijt (2021): start at `delta = 0`, `delta_dot = V_in`,
//! `beta = (1 + eps) k`; end when `beta = (1 - eps)/k`, where the spheres separate with
//! `V_out = delta_dot`. Outcomes (Section 4): bouncing (`V_out < 0`, `e = -V_out/V_in > 0`),
//! double collision (`V_out > 0`, `e < 0`), sticking (the contact never ends, `e = 0`; how it
//! is proved: [`crate::sticking`]). The integration itself is in the private module `integrate`.

use crate::integrate::Start;
use crate::model::{self, Params, NSTATES};
use crate::scales::Scales;
use crate::{Collision, DynamicsError, Rebound, SolverOptions, TrajectoryPoint, H0};
use contact::Contact;
use greenwood::CrackLaw;
use numerics::OutOfRange;

/// The fiducial eps = 0.01 of Section 2.5 (start at beta = (1 + eps) k, end at (1 - eps)/k).
pub const EPS: f64 = 0.01;

/// The largest modulus ratio k a collision is integrated for. A contact starts at
/// beta = (1 + eps) k and ends at (1 - eps)/k ([`EPS`]): the regularisation eps must stay small
/// against the window 1/k - k of beta it is cut from (1.5 at k = 0.5, 0.21 at 0.9). As k -> 1
/// that window closes and the regularised ends take over: V_stick falls below V_stick,JKR at
/// k = 0.98 (CO2, 60 um, T_vis = 1e-8 s), and at 0.99 the search finds nothing that sticks
/// (measured 2026-11-27). Ice and dust have k of 0.005-0.05 (Figure 4).
pub const K_MAX: f64 = 0.9;

/// The allowed range of k of a collision, as error messages state it ([`K_MAX`]).
pub const K_RANGE: &str =
    "0 < k <= 0.9 for a collision (the window 1/k - k of beta a contact crosses closes as k -> 1)";

/// `k` (dimensionless) if a collision is integrated for it, 0 < k <= [`K_MAX`]; else the error
/// stating [`K_RANGE`] (also for k that Greenwood's crack law alone would take, up to 1).
///
/// # Example
/// ```
/// assert_eq!(dynamics::collision_k(0.01), Ok(0.01));
/// assert!(dynamics::collision_k(1.5).unwrap_err().to_string().contains("0 < k <= 0.9"));
/// ```
pub fn collision_k(k: f64) -> Result<f64, OutOfRange> {
    if k > 0.0 && k <= K_MAX {
        Ok(k)
    } else {
        Err(OutOfRange::new("k", k, K_RANGE, "dimensionless"))
    }
}

/// What a collision needs of the Poisson ratio besides the material's -1 < nu < 0.5: the
/// viscoelastic drag's A = T_vis/nu^2 (Section 2.5) is infinite at nu = 0, so the drag number
/// c_D is too (an elastic material of nu = 0 still has its JKR quantities); 1/nu^2 overflows
/// below |nu| = 7.5e-155.
const POISSON_FOR_DRAG: &str = "-1 < poisson < 0.5 and nonzero for a collision (the drag's \
     A = T_vis/nu^2 of Section 2.5 is infinite at nu = 0; |nu| above about 1e-154)";

/// The Poisson ratio `nu` (dimensionless) if a collision is integrated for it: 1/nu^2 finite,
/// so that the drag A = T_vis/nu^2 is; else the error naming `poisson` with that range. The
/// material's own range, -1 < nu < 0.5, is [`contact::Material::validate`]'s.
///
/// # Example
/// ```
/// assert_eq!(dynamics::collision_poisson(0.25), Ok(0.25));
/// assert!(dynamics::collision_poisson(0.0).unwrap_err().to_string().contains("nonzero"));
/// ```
pub fn collision_poisson(nu: f64) -> Result<f64, OutOfRange> {
    if (1.0 / (nu * nu)).is_finite() {
        Ok(nu)
    } else {
        Err(OutOfRange::new(
            "poisson",
            nu,
            POISSON_FOR_DRAG,
            "dimensionless",
        ))
    }
}

/// The largest crack-speed number c_a (lambda) a collision is integrated at: at 1.5e10 a
/// collision of 1 cm grains takes 2e5 steps, at 1.5e11 it does not end within the step budget
/// of 2e6 (the crack must follow beta = 1 to 1e-11); V_stick has converged there to its
/// T_vis -> 0 limit within 2e-7 (`thresholds::MasterTables` clamps c_a at 1e8).
pub const MAX_CRACK_SPEED_NUMBER: f64 = 3e10;

/// Integrates collisions of one contact at one relaxation time.
///
/// It owns its crack law: build the [`CrackLaw`] once per k and pass it (or a reference: the
/// table is shared, never copied) to every collider.
#[derive(Debug, Clone)]
pub struct Collider {
    pub(crate) contact: Contact,
    pub(crate) law: CrackLaw,
    pub(crate) t_vis: f64,
    pub(crate) eps: f64,
    pub(crate) scales: Scales,
    pub(crate) params: Params,
    pub(crate) beta_end: f64,
    pub(crate) energy_bound: f64,
    pub(crate) options: SolverOptions,
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
        let law: CrackLaw = law.into();
        collision_k(law.k())?;
        collision_poisson(contact.material().poisson)?;
        let scales = Scales::new(&contact);
        let params = scales.params(&contact, t_vis);
        if !params.c_d.is_finite() {
            // c_D grows as T_vis: T_vis too large for f64 (far beyond the no-bouncing cliff,
            // where every collision sticks)
            let per_second = scales.params(&contact, 1.0).c_d;
            return Err(OutOfRange::new(
                "t_vis",
                t_vis,
                format!(
                    "small enough that the drag number c_D = {} x T_vis/(1 s) is finite",
                    numerics::format::number(per_second)
                ),
                "s",
            )
            .into());
        }
        if params.lambda > MAX_CRACK_SPEED_NUMBER || params.lambda.is_nan() {
            // the smallest T_vis these grains can be integrated at (c_a ~ 1/T_vis)
            let t_min = t_vis * params.lambda / MAX_CRACK_SPEED_NUMBER;
            let m = contact.material();
            return Err(OutOfRange::new(
                "t_vis",
                t_vis,
                format!(
                    ">= {} s for these grains ({}, gamma_sv = {} J/m^2, young = {} Pa, poisson = {}, density = {} kg/m^3; the bound grows as young/(1 - poisson^2), as sqrt(m*)/R with the reduced mass m* and radius R (as sqrt(density R1) for one shape of the pair) and as gamma_sv^(-3/2)): below it the crack-speed number c_a exceeds {:e} and the collision cannot be integrated (V_stick has reached its T_vis -> 0 limit there to about 1e-6; the master tables give it where they cover these grains and their k: V_stick by default, a collision's e and V_out with the table method)",
                    numerics::format::number(t_min),
                    contact.geometry().as_arguments(),
                    numerics::format::number(m.gamma_sv),
                    numerics::format::number(m.young),
                    numerics::format::number(m.poisson),
                    numerics::format::number(m.density),
                    MAX_CRACK_SPEED_NUMBER
                ),
                "s",
            )
            .into());
        }
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
    pub(crate) fn initial_state(&self, v_in: f64) -> [f64; NSTATES] {
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

    /// A solver failure at the initial state of `v_in` (m/s).
    pub(crate) fn solver_error(&self, v_in: f64, e: impl std::fmt::Display) -> DynamicsError {
        self.solver_error_at(v_in, &self.initial_state(v_in), e)
    }

    /// A solver failure at state `u` of the collision at `v_in` (m/s), with the message `e`.
    pub(crate) fn solver_error_at(
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
            // diffsol writes tiny times in full decimals: the workspace's number form instead;
            // its time is the pseudo-time of the integration, not the t in seconds above
            message: numerics::format::shorten_numbers(&e.to_string()).replace(
                "at time = ",
                "at the solver's pseudo-time (dimensionless) = ",
            ),
        }
    }

    /// State `u` in SI.
    pub(crate) fn point(&self, u: &[f64; NSTATES]) -> TrajectoryPoint {
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
}
