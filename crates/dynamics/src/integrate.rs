//! The integration of one collision with diffsol: the choice of integrator and linear algebra
//! ([`crate::Method`], [`crate::Backend`]), the step loop, and the crossings placed inside a
//! step from the dense output: the end of contact (beta = beta_end) and the rebound (delta = 0).

use crate::model::{self, NSTATES};
use crate::sticking::StickingWatch;
use crate::{
    auto_explicit_step_budget, Backend, Collider, Collision, DynamicsError, Method, Outcome,
    Rebound, AUTO_EXPLICIT_LAMBDA_MAX, AUTO_EXPLICIT_RTOL_FACTOR,
};
use diffsol::{
    FaerLU, FaerMat, NalgebraLU, NalgebraMat, OdeBuilder, OdeEquations, OdeSolverMethod, Vector,
};
use greenwood::CrackLaw;
use numerics::roots::{illinois, Illinois};

/// Where an integration starts: first contact, or a rebound.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Start {
    pub(crate) u: [f64; NSTATES],
    pub(crate) h0: f64,
    pub(crate) maxima: usize,
    pub(crate) beta_max: f64,
    pub(crate) max_increase: f64,
    /// The rebound it starts from (kept in the result), if any.
    pub(crate) rebound: Option<Rebound>,
}

/// Rejected tries of one step before diffsol gives up (its default is 40): see `integrate`.
const MAX_ERROR_TEST_FAILURES: usize = 400;

/// Evaluations of the dense output that place the end of contact (beta = beta_end) or the
/// rebound (delta = 0) inside the step that crossed it: Illinois converges superlinearly, so 12
/// reach the last bits of the pseudo-time.
const CROSSING_ITERATIONS: usize = 12;
/// The crossing's bracket in pseudo-time is narrowed down to this many units in the last place.
const CROSSING_ULPS: f64 = 4.0;

impl Collider {
    /// Integrates the collision at `v_in` (m/s) from `start`.
    pub(crate) fn integrate(&self, v_in: f64, start: Start) -> Result<Collision, DynamicsError> {
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
                    // and it gives up a step after 40 rejected tries in a row (its default): at
                    // crack speeds of 1e8 (T_vis near 1e-15 s for nanometre grains) a step in the
                    // fast oscillations at beta = 1 - 1e-8 can need more, and the collision then
                    // failed where it had barely started; the step budget bounds the work
                    problem.ode_options.max_error_test_failures = MAX_ERROR_TEST_FAILURES;
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
            ..Illinois::default()
        };
        let root = illinois(
            |s| state(s).map(|u| g(&u)).ok_or(()),
            (s0, g0),
            (s1, g1),
            &opts,
        );
        state(root.ok()?.best)
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
        let mut sticking = StickingWatch::new(
            self.energy_bound,
            opts.energy_margin,
            model::energy(first[0], first[1], first[2]),
            opts.decide_after / self.scales.t0,
            opts.max_oscillations,
            start.maxima,
            &u,
        );
        let mut e_prev = model::energy(u[0], u[1], u[2]);
        let mut max_increase: f64 = start.max_increase;
        let mut beta_max = start.beta_max;
        let mut rebound = start.rebound;
        let mut s_prev = solver.state().t;
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
            // a step can jump past the end of contact to a vanished contact radius, a <= 0,
            // where beta (which grows without bound as a -> 0+) is negative: at coarse
            // tolerances near the no-bouncing cliff (2 um CO2 at 3.4e-10 s, 55 m/s, rtol 1e-4)
            // the solver then crept on at a < 0 for millions of steps
            let collapsed = beta_now < self.beta_end && u_step[0] <= 0.0;
            if beta_now >= self.beta_end || collapsed {
                // the contact ended inside this step: where beta = beta_end, from the dense output
                let end = if collapsed {
                    let g = |v: &[f64; NSTATES]| model::end_gap(v[0], v[1], self.beta_end);
                    self.crossing(solver, g, (s_prev, g(&u)), (s_now, g(&u_step)))
                } else {
                    let g = |v: &[f64; NSTATES]| model::beta(v[0], v[1]) - self.beta_end;
                    self.crossing(
                        solver,
                        g,
                        (s_prev, beta_prev - self.beta_end),
                        (s_now, beta_now - self.beta_end),
                    )
                };
                let end = end.ok_or_else(|| {
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
            sticking.count_maximum(&u);
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
                    r.maxima = sticking.maxima();
                    r.beta_max = beta_max;
                    r.max_increase = max_increase;
                }
            }
            s_prev = s_now;
            if let Some(criterion) = sticking.decide(&u, energy) {
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
