//! The numerical settings of a collision: which of diffsol's integrators runs it
//! ([`Method`], with the constants of [`Method::Auto`]'s choice), its linear algebra
//! ([`Backend`]), and the tolerances and budgets of one integration ([`SolverOptions`]).
//! Everything here is dimensionless unless its doc says otherwise.

use numerics::OutOfRange;

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
/// the one asked for, [`AUTO_EXPLICIT_RTOL_FACTOR`]): 792 steps when a search asks for rtol 1e-8
/// (Tsit45 at 1e-9), about 2.3 times the most Tsit45 takes then for collisions near V_stick
/// where [`AUTO_EXPLICIT_LAMBDA_MAX`] lets it run (340), so that a collision too stiff for it (a
/// fast impact) wastes less than one BDF collision.
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
    /// Step budget; exceeding it is an [`crate::DynamicsError::Undecided`] error, never a silent answer.
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

/// Absolute tolerance per unit of relative tolerance of [`SolverOptions::at_rtol`]: the
/// nondimensional states are of order one, so a thousandth keeps the absolute test below the
/// relative one, as in the default settings (1e-12 at 1e-9).
pub const ATOL_PER_RTOL: f64 = 1e-3;

impl SolverOptions {
    /// The default settings at relative tolerance `rtol`, with absolute tolerance
    /// [`ATOL_PER_RTOL`] `rtol`.
    ///
    /// ```
    /// use dynamics::SolverOptions;
    /// let o = SolverOptions::at_rtol(1e-6);
    /// assert_eq!((o.rtol, o.atol), (1e-6, 1e-3 * 1e-6));
    /// ```
    pub const fn at_rtol(rtol: f64) -> Self {
        let mut o = Self::DEFAULT;
        o.rtol = rtol;
        o.atol = ATOL_PER_RTOL * rtol;
        o
    }

    /// These settings with the integrator `method`.
    ///
    /// ```
    /// use dynamics::{Method, SolverOptions};
    /// let o = SolverOptions::at_rtol(1e-8).with_method(Method::Bdf);
    /// assert_eq!((o.method, o.rtol), (Method::Bdf, 1e-8));
    /// ```
    pub const fn with_method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }

    /// Checks every field: `0 < rtol < 1`, `atol > 0`, `decide_after >= 0` (all finite),
    /// `max_steps >= 1` and `max_oscillations >= 1`.
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
        if self.max_steps == 0 {
            // no step decides anything: every collision would end undecided
            return Err(OutOfRange::new("max_steps", 0.0, ">= 1", "steps"));
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

impl SolverOptions {
    /// The defaults, as a constant: [`Method::Auto`], nalgebra, rtol 1e-9, atol 1e-12, a budget
    /// of 2e6 steps, one oscillation, an energy margin of 1e-4, no trajectory, decided at once.
    pub const DEFAULT: SolverOptions = SolverOptions {
        method: Method::Auto,
        backend: Backend::Nalgebra,
        rtol: 1e-9,
        atol: 1e-12,
        max_steps: 2_000_000,
        max_oscillations: 1,
        energy_margin: 1e-4,
        record_trajectory: false,
        decide_after: 0.0,
    };
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}
