//! Bad input to a collision, refused by name with the range it must lie in (typed errors, never
//! a panic): k, T_vis, the impact speed, the crack-speed number's bound, the Poisson ratio.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, DynamicsError};
use greenwood::CrackLaw;

fn co2_60um() -> Contact {
    Contact::new(Material::co2(), Geometry::identical(60e-6)).unwrap()
}

fn law() -> CrackLaw {
    CrackLaw::new(0.01).unwrap()
}

/// k above K_MAX = 0.9 is refused by name: there the window of beta a contact crosses,
/// (1 + eps) k to (1 - eps)/k, has closed so far that V_stick fell below V_stick,JKR at
/// k = 0.98 (the JKR limit is a lower bound of V_stick for every T_vis > 0, Section 5.1).
#[test]
fn k_above_the_closing_window_is_refused_by_name() {
    for k in [0.95, 0.98, 0.99, 0.995] {
        let err = Collider::new(co2_60um(), CrackLaw::new(k).unwrap(), 1e-9).unwrap_err();
        assert!(
            matches!(
                err,
                DynamicsError::OutOfRange(numerics::OutOfRange { field: "k", .. })
            ),
            "{err}"
        );
        assert!(err
            .to_string()
            .starts_with(&format!("k = {k}: must be 0 < k <= 0.9")));
    }
    assert!(Collider::new(co2_60um(), CrackLaw::new(dynamics::K_MAX).unwrap(), 1e-9).is_ok());
    // the range the messages state is K_MAX's
    let stated = format!("0 < k <= {}", dynamics::K_MAX);
    assert!(
        dynamics::K_RANGE.starts_with(&stated),
        "{}",
        dynamics::K_RANGE
    );
}

#[test]
fn bad_inputs_are_typed_errors() {
    let law = law();
    let err = Collider::new(co2_60um(), &law, 0.0).unwrap_err();
    assert!(matches!(
        err,
        DynamicsError::OutOfRange(numerics::OutOfRange { field: "t_vis", .. })
    ));
    assert!(err.to_string().contains("JKR"));
    // a T_vis whose drag number overflows is named as too large, not as too small
    let err = Collider::new(co2_60um(), &law, 1e300).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("t_vis = 1e+300: must be small enough that the drag number c_D"),
        "{err}"
    );
    let col = Collider::new(co2_60um(), &law, 1e-9).unwrap();
    for v in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            col.collide(v),
            Err(DynamicsError::OutOfRange(numerics::OutOfRange {
                field: "v_in",
                ..
            }))
        ));
    }
}

/// Below the T_vis where the crack-speed number exceeds MAX_CRACK_SPEED_NUMBER (1 cm grains of
/// a stiff ice at 1e-16 s: c_a = 1.5e11) a collision cannot be integrated within the step
/// budget; the collider refuses it as bad input naming t_vis and the smallest T_vis it takes,
/// and takes that one.
#[test]
fn crack_speeds_beyond_the_limit_are_refused() {
    let m = Material {
        gamma_sv: 0.01,
        young: 2e11,
        poisson: 0.45,
        density: 1e4,
    };
    let c = Contact::new(m, Geometry::wall(1e-2)).unwrap();
    let law = CrackLaw::new(0.01).unwrap();
    let e = Collider::new(c, &law, 1e-16).unwrap_err();
    let bad = e.out_of_range().expect("bad input").clone();
    assert_eq!(bad.field, "t_vis");
    let t_min = 1e-16 * c.dimensionless(1e-16).c_a / dynamics::MAX_CRACK_SPEED_NUMBER;
    assert!(Collider::new(c, &law, t_min * 1.001).is_ok());
}

/// The refusal's message names the material's constants and how the bound moves with them:
/// c_a = E* gamma t0/(sigma0^2 T_vis a_eq) (docs/model.md) with a_eq ~ (gamma R^2/E*)^(1/3),
/// t0 = sqrt(m* delta_eq/(3 pi gamma R)) ~ sqrt(m*/gamma) a_eq/R and sigma0 ~ gamma makes the
/// smallest T_vis grow as E* = E/(1 - nu^2), as sqrt(m*)/R (sqrt(rho R1) at one shape of the
/// pair: identical spheres, a wall) and as gamma^(-3/2): a Young's modulus of 1e30 Pa (a slip of
/// units) is then visible as the cause.
#[test]
fn the_crack_speed_bound_names_the_constants_it_grows_with() {
    let t_min = |m: Material, g: Geometry| {
        let c = Contact::new(m, g).unwrap();
        1e-9 * c.dimensionless(1e-9).c_a / dynamics::MAX_CRACK_SPEED_NUMBER
    };
    let base = Material::co2();
    let g0 = Geometry::identical(60e-6);
    let t0 = t_min(base, g0);
    // sqrt(m*)/R of a geometry against the base pair's
    let shape = |g: Geometry| {
        let m = |g: Geometry| g.reduced_mass(base.density).sqrt() / g.reduced_radius();
        m(g) / m(g0)
    };
    let cases = [
        (
            Material {
                young: 10.0 * base.young,
                ..base
            },
            g0,
            10.0,
        ),
        (
            Material {
                poisson: 0.4,
                ..base
            },
            g0,
            (1.0 - base.poisson.powi(2)) / 0.84,
        ),
        (
            Material {
                density: 4.0 * base.density,
                ..base
            },
            g0,
            2.0,
        ),
        (base, Geometry::identical(240e-6), 2.0),
        (
            Material {
                gamma_sv: 4.0 * base.gamma_sv,
                ..base
            },
            g0,
            0.125,
        ),
        // a larger partner raises R and lowers the bound; a wall alike
        (
            base,
            Geometry::spheres(60e-6, 1e-3),
            shape(Geometry::spheres(60e-6, 1e-3)),
        ),
        (base, Geometry::wall(60e-6), shape(Geometry::wall(60e-6))),
    ];
    for (m, g, ratio) in cases {
        let got = t_min(m, g) / t0;
        assert!(
            (got / ratio - 1.0).abs() < 1e-12,
            "{m:?} {g:?}: {got} against {ratio}"
        );
    }
    assert!(shape(Geometry::wall(60e-6)) < 1.0);
    let huge = Material {
        young: 1e30,
        ..base
    };
    let err = Collider::new(Contact::new(huge, g0).unwrap(), law(), 1e-9)
        .unwrap_err()
        .to_string();
    assert!(err.contains("young = 1e+30 Pa"), "{err}");
    assert!(
        err.contains("young/(1 - poisson^2), as sqrt(m*)/R"),
        "{err}"
    );
}

/// A Poisson ratio of 0 is a valid elastic material (its JKR quantities exist) but no collision:
/// the drag A = T_vis/nu^2 of Section 2.5 is infinite, so c_D is too at every T_vis. The
/// collider names poisson, not t_vis (which it blamed before, as too large); nu = -0.2 and
/// |nu| = 1e-3 (a finite, huge c_D) are collisions.
#[test]
fn a_poisson_ratio_of_zero_is_named_for_a_collision() {
    let with_nu = |poisson: f64| {
        let m = Material {
            poisson,
            ..Material::co2()
        };
        Contact::new(m, Geometry::identical(60e-6)).unwrap()
    };
    for nu in [0.0, -0.0, 1e-300, -1e-200] {
        let c = with_nu(nu);
        assert!(c.v_stick_jkr().is_finite(), "JKR quantities at nu = {nu}");
        let err = Collider::new(c, law(), 1e-9).unwrap_err();
        let bad = err.out_of_range().expect("bad input");
        assert_eq!(bad.field, "poisson", "{err}");
        assert!(err.to_string().contains("nonzero for a collision"), "{err}");
    }
    for nu in [1e-3, -0.2] {
        assert!(Collider::new(with_nu(nu), law(), 1e-9).is_ok(), "nu = {nu}");
    }
}

/// Solver options that cannot decide a collision are refused by name: no step at all, or no
/// oscillation to prove sticking by.
#[test]
fn options_that_decide_nothing_are_refused_by_name() {
    use dynamics::SolverOptions;
    let steps = SolverOptions {
        max_steps: 0,
        ..SolverOptions::DEFAULT
    };
    assert_eq!(steps.validate().unwrap_err().field, "max_steps");
    let oscillations = SolverOptions {
        max_oscillations: 0,
        ..SolverOptions::DEFAULT
    };
    assert_eq!(
        oscillations.validate().unwrap_err().field,
        "max_oscillations"
    );
    assert!(SolverOptions::DEFAULT.validate().is_ok());
}
