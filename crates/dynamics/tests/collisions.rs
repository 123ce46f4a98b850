//! Collisions of two identical spheres (Arakawa & Krijt 2021, Sections 2.5 and 4).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use dynamics::model::{self, end_energy_bound, Params};
use dynamics::{Backend, Collider, Method, Outcome, Rebound, SolverOptions, StickingCriterion};
use greenwood::CrackLaw;

fn co2_60um() -> Contact {
    Contact::new(Material::co2(), Geometry::identical(60e-6)).unwrap()
}

fn law() -> CrackLaw {
    CrackLaw::new(0.01).unwrap()
}

/// A collider of two CO2 spheres of 60 um at `t_vis` (s) with solver settings `opts`.
fn co2_collider(law: &CrackLaw, t_vis: f64, opts: SolverOptions) -> Collider {
    Collider::new(co2_60um(), law, t_vis)
        .unwrap()
        .with_options(opts)
        .unwrap()
}

/// Section 4 / Figure 2: CO2, R1 = 60 um, T_vis = 1e-9 s: V_in = 3.5, 4.05, 4.5 cm/s give
/// sticking, a double collision and bouncing.
#[test]
fn section_4_three_outcomes() {
    let law = law();
    let col = Collider::new(co2_60um(), &law, 1e-9).unwrap();
    let stick = col.collide(0.035).unwrap();
    assert_eq!(stick.outcome, Outcome::Sticking);
    assert_eq!((stick.e, stick.v_out, stick.contact_time), (0.0, 0.0, None));
    let double = col.collide(0.0405).unwrap();
    assert_eq!(double.outcome, Outcome::DoubleCollision);
    assert!(double.e < 0.0 && double.v_out > 0.0);
    let bounce = col.collide(0.045).unwrap();
    assert_eq!(bounce.outcome, Outcome::Bouncing);
    assert!(bounce.e > 0.0 && bounce.e < 1.0 && bounce.v_out < 0.0);
    assert!(bounce.contact_time.unwrap() > 0.0);
}

/// The nondimensional right-hand side is Section 2's physics: delta_ddot = -(F_E + F_D)/m* and
/// a_dot = v(k, beta) E* gamma / (sigma0^2 T_vis), evaluated in SI with the contact crate.
#[test]
fn nondimensional_rhs_is_the_physical_model() {
    let law = law();
    let c = co2_60um();
    let t_vis = 1e-9;
    let col = Collider::new(c, &law, t_vis).unwrap();
    let s = *col.scales();
    let params = Params {
        speed_cap: f64::INFINITY, // plain time: g = 1
        ..*col.params()
    };
    for (a, delta, delta_dot) in [
        (0.5e-6, 2e-9, 0.01),
        (0.8e-6, -3e-9, -0.02),
        (0.3e-6, 1e-9, 0.03),
    ] {
        let u = [a / s.a_eq, delta / s.delta_eq, delta_dot / s.v0, 0.0];
        let mut f = [0.0; 4];
        model::rhs(&params, &law, &u, &mut f);
        let acc = -(c.f_e(a, delta) + c.f_d(a, delta_dot, t_vis)) / c.m_star();
        let a_dot = law.v(c.beta(a, delta)).unwrap() * c.crack_speed_unit(t_vis);
        assert!((f[2] * s.v0 / s.t0 - acc).abs() < 1e-12 * acc.abs());
        assert!((f[0] * s.a_eq / s.t0 - a_dot).abs() < 1e-12 * a_dot.abs());
        assert!((f[1] * s.delta_eq / s.t0 - delta_dot).abs() < 1e-12 * delta_dot.abs());
        assert_eq!(f[3], 1.0);
        let e = model::energy(u[0], u[1], u[2]) * s.e0;
        assert!(
            (e - c.total_energy(a, delta, delta_dot)).abs() < 1e-12 * e.abs().max(c.e_stick_jkr())
        );
        assert!((model::beta(u[0], u[1]) - c.beta(a, delta)).abs() < 1e-12);
    }
}

/// The analytic Jacobian agrees with central differences of the right-hand side.
#[test]
fn jacobian_matches_finite_differences() {
    let law = law();
    for lambda in [1.3, 1.3e5] {
        let p = Params {
            lambda,
            c_d: 0.05,
            speed_cap: model::SPEED_CAP,
        };
        for u in [
            [0.7, 0.2, 0.3, 1.0],
            [0.3, -0.5, -0.2, 1.0],
            [1.04, 1.2, -1.1, 4.4],
            [0.2, 0.0, 2.0, 0.0],
        ] {
            for j in 0..4 {
                let h = 1e-6 * (1.0 + f64::abs(u[j]));
                let (mut up, mut um) = (u, u);
                up[j] += h;
                um[j] -= h;
                let (mut fp, mut fm, mut jw, mut w) = ([0.0; 4], [0.0; 4], [0.0; 4], [0.0; 4]);
                model::rhs(&p, &law, &up, &mut fp);
                model::rhs(&p, &law, &um, &mut fm);
                w[j] = 1.0;
                model::jac_mul(&p, &law, &u, &w, &mut jw);
                for i in 0..4 {
                    let fd = (fp[i] - fm[i]) / (2.0 * h);
                    let scale = 1e-3 * (1.0 + fd.abs().max(jw[i].abs()));
                    assert!(
                        (fd - jw[i]).abs() < scale,
                        "lambda {lambda} u {u:?} J[{i}][{j}]: {fd} vs {}",
                        jw[i]
                    );
                }
            }
        }
    }
}

/// The end-state energy bound: brute-force minimum of U_E - pi a^2 gamma over states with
/// beta = beta_end (both branches y = 3x^2 ± 2 sqrt(beta_end x)) against the closed form.
#[test]
fn end_energy_bound_matches_brute_force() {
    for beta_end in [99.0, 49.5, 5.0, 3.0, 2.5, 1.5, 1.1] {
        let mut brute = f64::INFINITY;
        for i in 1..200_000 {
            let x = i as f64 * 1e-5;
            for sign in [-1.0, 1.0] {
                let y = 3.0 * x * x + sign * 2.0 * (beta_end * x).sqrt();
                brute = brute.min(model::energy(x, y, 0.0));
            }
        }
        let bound = end_energy_bound(beta_end);
        if beta_end >= 3.0 {
            assert_eq!(bound, 0.0);
            assert!(brute > -1e-9, "{beta_end}: {brute}");
        } else {
            assert!(bound < 0.0);
            assert!(
                (bound - brute).abs() < 1e-6 * brute.abs(),
                "{beta_end}: {bound} vs {brute}"
            );
        }
    }
}

/// The total energy never increases along a trajectory (beyond the integration tolerance):
/// F_D dissipates and v(k, beta) has the sign of 1 - beta (Sections 2.3-2.5).
#[test]
fn energy_never_increases() {
    let law = law();
    for t_vis in [1e-9, 1e-11, 1e-14] {
        let col = Collider::new(co2_60um(), &law, t_vis).unwrap();
        for v_in in [0.03, 0.0405, 0.1, 1.0] {
            let r = col.collide(v_in).unwrap();
            let e_in = 0.5 * col.contact().m_star() * v_in * v_in;
            assert!(
                r.max_energy_increase <= 1e-8 * e_in,
                "T_vis {t_vis}, V_in {v_in}: {:e} of {:e}",
                r.max_energy_increase,
                e_in
            );
        }
    }
}

/// BDF and ESDIRK34 agree, and e moves by less than 1e-7 relative when the tolerance is
/// tightened tenfold.
#[test]
fn solvers_agree_and_converge() {
    let law = law();
    for t_vis in [1e-9, 1e-13] {
        for v_in in [0.045, 0.2] {
            let e = |method: Method, rtol: f64| {
                let opts = SolverOptions::at_rtol(rtol).with_method(method);
                co2_collider(&law, t_vis, opts).collide(v_in).unwrap().e
            };
            let base = e(Method::Bdf, 1e-9);
            let tight = e(Method::Bdf, 1e-10);
            let esdirk = e(Method::Esdirk34, 1e-9);
            assert!(
                ((tight - base) / base).abs() < 1e-7,
                "T_vis {t_vis} V {v_in}: {base} vs {tight}"
            );
            assert!(
                ((esdirk - base) / base).abs() < 1e-6,
                "T_vis {t_vis} V {v_in}: {base} vs {esdirk}"
            );
        }
    }
}

/// `Method::Auto` integrates non-stiff collisions (small lambda) with Tsit45 and stiff ones with
/// BDF, and agrees with BDF (an independent integrator) to its tolerance: e within 1e-6
/// relative at rtol 1e-9. A fast impact too stiff for Tsit45 falls back to BDF.
#[test]
fn auto_method_picks_the_integrator_and_agrees_with_bdf() {
    let law = law();
    let run = |t_vis: f64, v_in: f64, method: Method| {
        let opts = SolverOptions {
            method,
            ..Default::default()
        };
        co2_collider(&law, t_vis, opts).collide(v_in).unwrap()
    };
    // (T_vis, V_in, integrator expected): lambda = 1.3 and 13 (explicit), 1.3e5 (stiff); and
    // 100 m/s at T_vis = 1e-9 s, about 6000 V_stick,JKR, where the contact itself is stiff
    for (t_vis, v_in, expected) in [
        (1e-9, 0.035, Method::Tsit45),
        (1e-9, 0.045, Method::Tsit45),
        (1e-10, 0.03, Method::Tsit45),
        (1e-14, 0.02, Method::Bdf),
        (1e-9, 100.0, Method::Bdf),
    ] {
        let auto = run(t_vis, v_in, Method::Auto);
        let bdf = run(t_vis, v_in, Method::Bdf);
        assert_eq!(auto.method, expected, "T_vis {t_vis} V {v_in}");
        assert_eq!(bdf.method, Method::Bdf);
        assert_eq!(auto.outcome, bdf.outcome, "T_vis {t_vis} V {v_in}");
        assert!(
            (auto.e - bdf.e).abs() <= 1e-6 * bdf.e.abs(),
            "T_vis {t_vis} V {v_in}: {} vs {}",
            auto.e,
            bdf.e
        );
    }
}

/// The collision ODE (Section 2.5) is autonomous: continued from its state where delta returns
/// to zero (its rebound), a collision ends as it does integrated from first contact. The
/// reference is the full integration at a tenfold tighter tolerance; the continuation from the
/// rebound of the same collision and from one interpolated halfway between collisions 1e-4
/// apart (error of order 1e-4^2) agree with it as the full integration at the working tolerance
/// does: e within 1e-6 relative. Tsit45 at T_vis = 1e-9 s and BDF at 1e-14 s; the rebound lies
/// after the deepest compression.
#[test]
fn continuing_from_the_rebound_reproduces_the_collision() {
    let law = law();
    for (t_vis, v_in) in [(1e-9, 0.045), (1e-9, 0.0405), (1e-14, 0.025)] {
        let collider = |rtol: f64| {
            let opts = SolverOptions::at_rtol(rtol);
            co2_collider(&law, t_vis, opts)
        };
        let (col, tight) = (collider(1e-9), collider(1e-10));
        let reference = tight.collide(v_in).unwrap();
        let full = col.collide(v_in).unwrap();
        let own = full
            .rebound
            .expect("a bouncing or double collision rebounds");
        let (lo, hi) = (
            col.collide(v_in * (1.0 - 5e-5)),
            col.collide(v_in * (1.0 + 5e-5)),
        );
        let lo = lo.unwrap().rebound.unwrap();
        let between = Rebound::between(&lo, &hi.unwrap().rebound.unwrap(), v_in).unwrap();
        // from two speeds below, extrapolated by their spacing
        let lower = col.collide(v_in * (1.0 - 1e-4)).unwrap().rebound.unwrap();
        let beyond = Rebound::through(&lower, &lo, v_in).unwrap();
        assert!(own.time(col.scales()) < full.contact_time.unwrap());
        for (what, c) in [
            ("full", full.clone()),
            ("own rebound", col.collide_from(v_in, &own).unwrap()),
            ("interpolated", col.collide_from(v_in, &between).unwrap()),
            ("extrapolated", col.collide_from(v_in, &beyond).unwrap()),
        ] {
            assert_eq!(c.outcome, reference.outcome, "T_vis {t_vis} {what}");
            assert!(
                (c.e / reference.e - 1.0).abs() < 1e-6,
                "T_vis {t_vis} {what}: e {} vs {}",
                c.e,
                reference.e
            );
        }
        // a continuation costs the steps after the rebound only
        let continued = col.collide_from(v_in, &own).unwrap();
        assert!(
            continued.steps < full.steps,
            "{} vs {}",
            continued.steps,
            full.steps
        );
    }
    // outside the two speeds, or across different oscillation counts, nothing is interpolated
    let col = Collider::new(co2_60um(), &law, 1e-9).unwrap();
    let (a, b) = (col.collide(0.045).unwrap(), col.collide(0.046).unwrap());
    let (ra, rb) = (a.rebound.unwrap(), b.rebound.unwrap());
    assert_eq!(Rebound::between(&ra, &rb, 0.047), None);
    assert_eq!(Rebound::between(&ra, &rb, 0.045), None);
    assert!(Rebound::between(&rb, &ra, 0.0455).is_some());
    // the line through two rebounds reaches beyond them, and reproduces each at its own speed
    assert!(Rebound::through(&ra, &rb, 0.047).is_some());
    assert_eq!(
        Rebound::through(&ra, &rb, 0.045).unwrap().state(),
        ra.state()
    );
    assert_eq!(Rebound::through(&ra, &ra, 0.047), None);
}

/// Sticking is proved by the energy bound when damping is strong; for weak damping the
/// oscillation criterion decides.
#[test]
fn sticking_criteria() {
    let law = law();
    let strong = Collider::new(co2_60um(), &law, 1e-9)
        .unwrap()
        .collide(0.03)
        .unwrap();
    assert_eq!(
        strong.sticking_criterion,
        Some(StickingCriterion::EnergyBound)
    );
    let weak = Collider::new(co2_60um(), &law, 1e-14)
        .unwrap()
        .collide(0.0165)
        .unwrap();
    assert_eq!(weak.outcome, Outcome::Sticking);
    assert_eq!(
        weak.sticking_criterion,
        Some(StickingCriterion::Oscillations)
    );
}

/// The oscillation criterion decides as soon as the spheres approach again with the crack
/// advancing (beta < 1), before the next maximum of delta: from there the contact cannot end
/// before that maximum. Checked by integrating on: with the decision held back to three times
/// its time (`decide_after`), collisions just below the onset of double collisions (where the
/// contact comes closest to ending) decided early as sticking still stick. The onset is found
/// here by bisection on the outcome (sticking below it, not above: Section 4.4's order of the
/// outcomes along V_in), from 0.5 to 10 V_stick,JKR down to 1e-7 relative, and each collision
/// taken 1e-7 and 2e-5 relative below it.
#[test]
fn early_oscillation_decision_is_the_outcome() {
    let law = law();
    for t_vis in [1e-9, 1e-12, 1e-14] {
        let col = Collider::new(co2_60um(), &law, t_vis).unwrap();
        let sticks = |v: f64| col.collide(v).unwrap().outcome == Outcome::Sticking;
        let jkr = co2_60um().v_stick_jkr();
        let (mut lo, mut hi) = (0.5 * jkr, 10.0 * jkr);
        assert!(
            sticks(lo) && !sticks(hi),
            "T_vis {t_vis}: no onset in the bracket"
        );
        while hi / lo - 1.0 > 1e-7 {
            let mid = 0.5 * (lo + hi);
            if sticks(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        for v_in in [lo, hi * (1.0 - 2e-5)] {
            let early = col.collide(v_in).unwrap();
            assert_eq!(early.outcome, Outcome::Sticking, "T_vis {t_vis} V {v_in}");
            assert_eq!(
                early.sticking_criterion,
                Some(StickingCriterion::Oscillations),
                "T_vis {t_vis} V {v_in}"
            );
            let opts = SolverOptions {
                decide_after: 3.0 * early.decided_at,
                ..Default::default()
            };
            let late = col
                .clone()
                .with_options(opts)
                .unwrap()
                .collide(v_in)
                .unwrap();
            assert_eq!(late.outcome, Outcome::Sticking, "T_vis {t_vis} V {v_in}");
            assert!(late.decided_at >= opts.decide_after);
        }
    }
}

/// Section 2.5: the trajectory starts at delta = 0, delta_dot = V_in, beta = (1 + eps) k and a
/// bouncing one ends at beta = (1 - eps)/k.
#[test]
fn trajectory_initial_and_final_states() {
    let law = law();
    let c = co2_60um();
    let opts = SolverOptions {
        record_trajectory: true,
        ..Default::default()
    };
    let r = Collider::new(c, &law, 1e-9)
        .unwrap()
        .with_options(opts)
        .unwrap()
        .collide(0.045)
        .unwrap();
    let first = r.trajectory[0];
    assert_eq!((first.t, first.delta, first.delta_dot), (0.0, 0.0, 0.045));
    assert!((c.beta(first.a, 0.0) / (1.01 * 0.01) - 1.0).abs() < 1e-12);
    let last = *r.trajectory.last().unwrap();
    assert!((c.beta(last.a, last.delta) / 99.0 - 1.0).abs() < 1e-6);
    assert_eq!(Some(last.t), r.contact_time);
    assert_eq!(last.delta_dot, r.v_out);
}

/// The nalgebra and faer linear-algebra backends give the same collision.
#[test]
fn backends_agree() {
    let law = law();
    for v_in in [0.035, 0.0405, 0.045] {
        let run = |backend: Backend| {
            let opts = SolverOptions {
                backend,
                ..Default::default()
            };
            co2_collider(&law, 1e-9, opts).collide(v_in).unwrap()
        };
        let (a, b) = (run(Backend::Nalgebra), run(Backend::Faer));
        assert_eq!(a.outcome, b.outcome);
        assert!(
            (a.e - b.e).abs() <= 1e-9 * a.e.abs().max(1e-3),
            "{v_in}: {} vs {}",
            a.e,
            b.e
        );
    }
}

/// A coarse step can jump past the end of contact to a vanished contact radius (a < 0, where
/// beta is negative although it grows without bound as a -> 0+). Two CO2 grains of 2.18 um at
/// T_vis = 3.4e-10 s and 55 m/s, beyond the no-bouncing cliff (c_D = 0.82), at rtol 1e-4: the
/// solver crept on at a < 0 for 2e6 steps. Truth: the same collision at rtol 1e-9, a double
/// collision with e = -1.1337e-3; at 1e-4 it must end the same way, to the coarse tolerance.
#[test]
fn a_step_past_the_vanishing_contact_ends_it() {
    let c = Contact::new(Material::co2(), Geometry::identical(2.1828606522255834e-6)).unwrap();
    let (law, t_vis, v_in) = (law(), 3.4295490173049875e-10, 54.99992174913366);
    let run = |rtol: f64| {
        let opts = SolverOptions {
            max_steps: 20_000,
            ..SolverOptions::at_rtol(rtol)
        };
        let col = Collider::new(c, &law, t_vis).unwrap().with_options(opts);
        col.unwrap().collide(v_in).unwrap()
    };
    let fine = run(1e-9);
    assert_eq!(fine.outcome, Outcome::DoubleCollision);
    for rtol in [1e-3, 1e-4, 1e-5] {
        let coarse = run(rtol);
        assert_eq!(coarse.outcome, Outcome::DoubleCollision, "rtol {rtol}");
        assert!(
            (coarse.e / fine.e - 1.0).abs() < 0.2,
            "rtol {rtol}: {} vs {}",
            coarse.e,
            fine.e
        );
    }
}
