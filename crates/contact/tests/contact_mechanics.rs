//! Closed-form consistency of the contact model (Arakawa & Krijt 2021, Section 2).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, ContactError, Geometry, Material, OutOfRange};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn co2() -> Contact {
    Contact::new(Material::co2(), Geometry::identical(60e-6)).unwrap()
}

/// Section 2.2: both expressions of delta_eq agree, and at (a_eq, delta_eq) F_E = 0 and beta = 1.
#[test]
fn jkr_equilibrium() {
    let c = co2();
    let (a, d, r) = (c.a_eq(), c.delta_eq(), c.reduced_radius());
    let other = a * a / r - (2.0 * PI * c.gamma() * a / c.e_star()).sqrt();
    assert!(rel(d, other) < 1e-13);
    assert!(c.f_e(a, d).abs() < 1e-12 * c.f_crit());
    assert!((c.beta(a, d) - 1.0).abs() < 1e-13);
}

/// Section 2.1: U_E as printed in the paper; dU_E/ddelta = F_E; dU_E/da = 2 pi a G_eff (Section 2.4).
#[test]
fn strain_energy_derivatives() {
    let c = co2();
    let r = c.reduced_radius();
    let e = c.e_star();
    for (a, d) in [(0.3e-6f64, 2e-9f64), (0.7e-6, 1e-9), (1.2e-6, -2e-9)] {
        let paper = e * a.powi(3) / (3.0 * r)
            * (d * (3.0 * d * r / (a * a) - 1.0)
                - a * a / (5.0 * r) * (5.0 * d * r / (a * a) - 3.0));
        assert!(rel(c.u_e(a, d), paper) < 1e-12);
        let h = 1e-6;
        let du_dd = (c.u_e(a, d * (1.0 + h)) - c.u_e(a, d * (1.0 - h))) / (2.0 * h * d);
        assert!(rel(du_dd, c.f_e(a, d)) < 1e-7);
        let du_da = (c.u_e(a * (1.0 + h), d) - c.u_e(a * (1.0 - h), d)) / (2.0 * h * a);
        assert!(rel(du_da, 2.0 * PI * a * c.g_eff(a, d)) < 1e-7);
    }
}

/// Section 2.5: F_D = ∫ 2 pi r A dp/ddelta delta_dot dr = 2 A E* a delta_dot with A = T_vis/nu^2.
#[test]
fn drag_force() {
    let c = co2();
    let nu = c.material().poisson;
    let f = c.f_d(0.5e-6, 0.01, 1e-9);
    assert!(rel(f, 2.0 * 1e-9 / (nu * nu) * c.e_star() * 0.5e-6 * 0.01) < 1e-14);
}

/// Section 4.1: at the initial radius, delta = 0 and beta = (1 + eps) k.
#[test]
fn initial_radius_gives_initial_beta() {
    let c = co2();
    let a0 = c.initial_contact_radius(0.01, 0.01);
    assert!(rel(c.beta(a0, 0.0), 1.01 * 0.01) < 1e-13);
}

#[test]
fn bad_inputs_name_the_field() {
    let err = Contact::new(Material::co2(), Geometry::identical(-1.0)).unwrap_err();
    assert!(matches!(
        err,
        ContactError::OutOfRange(OutOfRange {
            field: "radius",
            ..
        })
    ));
    assert_eq!(err.to_string(), "radius = -1.0: must be > 0 and finite (m)");
    let err = Contact::new(Material::co2(), Geometry::spheres(1e-6, f64::NAN)).unwrap_err();
    assert_eq!(err.to_string(), "radius2 = nan: must be > 0 and finite (m)");
    let bad = Material {
        poisson: 0.5,
        ..Material::co2()
    };
    assert!(matches!(
        bad.validate(),
        Err(OutOfRange {
            field: "poisson",
            ..
        })
    ));
    let bad = Material {
        young: f64::NAN,
        ..Material::co2()
    };
    assert!(matches!(
        bad.validate(),
        Err(OutOfRange { field: "young", .. })
    ));
}

/// Valid constants whose contact has no finite units in f64 (a mass or a JKR unit of 0 or
/// infinity) are refused naming the constant at fault, in the shortest form of each number.
#[test]
fn constants_too_far_out_for_f64_name_the_one_at_fault() {
    let field = |m: Material, g: Geometry| match Contact::new(m, g) {
        Err(ContactError::OutOfRange(bad)) => (bad.field, bad.to_string()),
        other => panic!("{other:?}"),
    };
    let co2 = Material::co2();
    let grains = Geometry::identical(60e-6);
    // 1e300 J/m^2 makes a_eq^3 overflow at any radius: the surface energy, not the radius
    let (name, message) = field(
        Material {
            gamma_sv: 1e300,
            ..co2
        },
        grains,
    );
    assert_eq!(name, "gamma_sv", "{message}");
    assert!(
        message.starts_with("gamma_sv = 1e+300: must be such that"),
        "{message}"
    );
    assert!(message.len() < 300, "{message}");
    assert_eq!(
        field(
            Material {
                young: 1e300,
                ..co2
            },
            grains
        )
        .0,
        "young"
    );
    assert_eq!(
        field(
            Material {
                density: 1e-300,
                ..co2
            },
            grains
        )
        .0,
        "density"
    );
    // a radius of 1e300 m has an infinite mass: the radius (R2 where R1 alone is fine)
    assert_eq!(field(co2, Geometry::identical(1e300)).0, "radius");
    assert_eq!(field(co2, Geometry::spheres(60e-6, 1e-300)).0, "radius2");
}

#[test]
fn json_material_files() {
    let m = Material::from_json_str(
        r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930}"#,
    )
    .unwrap();
    assert_eq!(m, Material::h2o());
    let missing = Material::from_json_str(r#"{"gamma_sv": 0.1, "poisson": 0.25, "density": 930}"#)
        .unwrap_err();
    assert!(missing.to_string().contains("young"), "{missing}");
    let unknown = Material::from_json_str(
        r#"{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930, "colour": 1}"#,
    )
    .unwrap_err();
    assert!(unknown.to_string().contains("colour"), "{unknown}");
    let unphysical = Material::from_json_str(
        r#"{"gamma_sv": -0.1, "young": 7e9, "poisson": 0.25, "density": 930}"#,
    )
    .unwrap_err();
    assert!(unphysical.to_string().contains("gamma_sv"), "{unphysical}");
    let unknown_name = Material::from_name_or_path("co3").unwrap_err();
    assert!(
        unknown_name.to_string().contains("co2, h2o"),
        "{unknown_name}"
    );
}

/// A material written as JSON (shortest round-trip numbers) reads back to the same constants,
/// to the bit: CO2's E and nu from the sound speeds have 17 significant digits.
#[test]
fn json_round_trip_is_exact() {
    for m in [Material::co2(), Material::h2o()] {
        let text = serde_json::to_string(&m).unwrap();
        assert_eq!(Material::from_json_str(&text).unwrap(), m, "{text}");
    }
}
