//! Unequal spheres and a sphere on a wall: the reduced radius and mass against their closed forms
//! (R = R1 R2/(R1 + R2), m* = m1 m2/(m1 + m2); R2 -> infinity for a wall), the identical-sphere
//! limit of the paper (R = R1/2, m* = m1/2, Section 2.1), and the JKR sticking velocity
//! V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6) (Section 5.1) in each geometry.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material, Warning};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn co2(g: Geometry) -> Contact {
    Contact::new(Material::co2(), g).unwrap()
}

/// Closed forms for a 60 um and a 30 um sphere: R = 60*30/90 um = 20 um, and with m2 = m1/8,
/// m* = m1 (1/8)/(9/8) = m1/9.
#[test]
fn unequal_spheres_closed_forms() {
    let c = co2(Geometry::spheres(60e-6, 30e-6));
    assert!(rel(c.reduced_radius(), 20e-6) < 1e-15);
    let m1 = 4.0 * PI * 1560.0 * (60e-6f64).powi(3) / 3.0;
    assert!(rel(c.m1(), m1) < 1e-15);
    assert!(rel(c.m_star(), m1 / 9.0) < 1e-15);
    // E*, gamma do not depend on the geometry (one material on both sides)
    let id = co2(Geometry::identical(60e-6));
    assert_eq!((c.e_star(), c.gamma()), (id.e_star(), id.gamma()));
}

/// The paper's identical spheres: R = R1/2 and m* = m1/2 exactly, and R2 -> R1 from either side
/// reaches them continuously (to 1e-12).
#[test]
fn equal_radii_are_the_identical_spheres() {
    let r1 = 60e-6;
    let id = co2(Geometry::identical(r1));
    assert_eq!(id.reduced_radius(), 0.5 * r1);
    assert_eq!(id.m_star(), 0.5 * id.m1());
    assert_eq!(co2(Geometry::spheres(r1, r1)), id);
    for f in [1.0 - 1e-13, 1.0 + 1e-13] {
        let near = co2(Geometry::spheres(r1, r1 * f));
        for (a, b) in [
            (near.reduced_radius(), id.reduced_radius()),
            (near.m_star(), id.m_star()),
            (near.v_stick_jkr(), id.v_stick_jkr()),
            (near.a_eq(), id.a_eq()),
            (near.delta_eq(), id.delta_eq()),
            (near.tabor(), id.tabor()),
        ] {
            assert!(rel(a, b) < 1e-12, "{a} vs {b}");
        }
    }
}

/// Swapping R1 and R2 changes nothing, to the bit.
#[test]
fn swapping_the_spheres_changes_nothing() {
    for (a, b) in [(60e-6, 30e-6), (1e-7, 3.3e-3), (2.5e-6, 2.5000001e-6)] {
        let (x, y) = (co2(Geometry::spheres(a, b)), co2(Geometry::spheres(b, a)));
        assert_eq!(x.reduced_radius(), y.reduced_radius());
        assert_eq!(x.m_star(), y.m_star());
        assert_eq!(x.v_stick_jkr(), y.v_stick_jkr());
    }
}

/// A wall is R2 -> infinity: R = R1, m* = m1; a sphere a million times larger is within ~1e-6.
#[test]
fn a_very_large_sphere_approaches_the_wall() {
    let r1 = 60e-6;
    let wall = co2(Geometry::wall(r1));
    assert_eq!(wall.reduced_radius(), r1);
    assert_eq!(wall.m_star(), wall.m1());
    let big = co2(Geometry::spheres(r1, 1e6 * r1));
    // R = R1/(1 + 1e-6); m* = m1/(1 + 1e-18)
    assert!(rel(big.reduced_radius(), r1 / (1.0 + 1e-6)) < 1e-15);
    assert!(rel(big.v_stick_jkr(), wall.v_stick_jkr()) < 1e-6);
    assert!(rel(big.a_eq(), wall.a_eq()) < 1e-6);
}

/// V_stick,JKR ∝ m*^(-1/2) R^(2/3): on a wall (R = R1, m* = m1) against identical spheres
/// (R1/2, m1/2) the ratio is 2^(-1/2) 2^(2/3) = 2^(1/6), for any radius and material.
#[test]
fn wall_over_identical_is_two_to_the_sixth() {
    for m in [Material::co2(), Material::h2o()] {
        for r1 in [1e-7, 60e-6, 1e-3] {
            let w = Contact::new(m, Geometry::wall(r1)).unwrap();
            let i = Contact::new(m, Geometry::identical(r1)).unwrap();
            assert!(rel(w.v_stick_jkr() / i.v_stick_jkr(), 2f64.powf(1.0 / 6.0)) < 1e-12);
        }
    }
}

#[test]
fn geometry_reads_as_a_sentence() {
    assert_eq!(
        Geometry::identical(60e-6).to_string(),
        "two identical spheres of 60 um"
    );
    assert_eq!(
        Geometry::spheres(60e-6, 30e-6).to_string(),
        "two spheres of 60 um and 30 um"
    );
    assert_eq!(
        Geometry::wall(60e-6).to_string(),
        "a 60 um sphere on a wall"
    );
    assert_eq!(Geometry::wall(60e-6).r2(), None);
}

/// A radius in the wrong unit is valid input but earns a warning that suggests the likely value.
#[test]
fn implausible_radius_warns() {
    let c = co2(Geometry::identical(60.0));
    let w = c.warnings();
    assert_eq!(w.len(), 1);
    assert!(matches!(
        w[0],
        Warning::ImplausibleRadius {
            field: "radius",
            ..
        }
    ));
    assert!(
        w[0].to_string().contains("did you mean 60e-6 m?"),
        "{}",
        w[0]
    );
    assert!(co2(Geometry::identical(60e-6)).warnings().is_empty());
    // 5 nm: implausible, and below the Tabor validity of JKR theory (Section 2.2)
    assert_eq!(co2(Geometry::identical(5e-9)).warnings().len(), 2);
    // the second sphere's radius is checked too, once
    let w = co2(Geometry::spheres(60e-6, 30.0)).warnings();
    assert!(matches!(
        w.as_slice(),
        [Warning::ImplausibleRadius {
            field: "radius2",
            ..
        }]
    ));
    assert_eq!(co2(Geometry::spheres(60.0, 60.0)).warnings().len(), 1);
    assert!(Warning::for_speed("v_in", 2e3).is_some());
    assert!(Warning::for_speed("v_in", 20.0).is_none());
    // has_warnings (no list built) says the same as the list, on every case above and across
    // the radii and the Tabor limit (mu = TABOR_MIN = 1 near R1 = 70 nm for CO2: 9.5 at 60 um)
    let geometries = |r: f64| {
        [
            Geometry::identical(r),
            Geometry::spheres(r, 30.0),
            Geometry::spheres(60e-6, r),
            Geometry::wall(r),
        ]
    };
    let mut warned = 0;
    for i in 0..=60 {
        let r = 10f64.powf(-10.0 + 0.15 * i as f64);
        for g in geometries(r) {
            let c = co2(g);
            assert_eq!(c.has_warnings(), !c.warnings().is_empty(), "{g:?}");
            warned += usize::from(c.has_warnings());
        }
    }
    // both kinds of case occur in the sweep (a guard of the test's reach, not a physics number)
    assert!(warned > 0 && warned < 61 * 4, "{warned}");
}

/// Valid constants can still overflow: a radius of 1e300 m has an infinite mass, which no
/// formula survives; it is bad input naming the radius, not a contact with infinities.
#[test]
fn radii_beyond_f64_are_refused() {
    let e = Contact::new(Material::co2(), Geometry::identical(1e300)).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("radius = 1e+300: must be such that"),
        "{e}"
    );
    assert!(Contact::new(Material::co2(), Geometry::identical(1e2)).is_ok());
    // the message names the radius at fault: a 60 um grain on a tiny second sphere is R2's
    let e = Contact::new(Material::co2(), Geometry::spheres(60e-6, 6e-92)).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("radius2 = 6e-92: must be such that"),
        "{e}"
    );
    let e = Contact::new(Material::co2(), Geometry::spheres(1e300, 1e299)).unwrap_err();
    assert!(e.to_string().starts_with("radius = 1e+300"), "{e}");
}

/// A material constant in cgs or in GPa is valid input but earns a warning that names it and
/// suggests the SI value: CO2 of Section 3 (gamma_SV = 80 mJ/m^2 = 80 erg/cm^2, E = 10.7 GPa,
/// rho = 1.56 g/cm^3) written in those units; the paper's CO2 and H2O earn none.
#[test]
fn a_material_constant_in_another_unit_warns() {
    let g = Geometry::identical(60e-6);
    for m in [Material::co2(), Material::h2o()] {
        assert!(Contact::new(m, g).unwrap().warnings().is_empty());
    }
    let cases = [
        (
            Material {
                gamma_sv: 80.0,
                ..Material::co2()
            },
            "gamma_sv = 80.0 J/m^2",
            "given in erg/cm^2 (mJ/m^2)? that is 0.08 J/m^2",
        ),
        (
            Material {
                young: 10.7,
                ..Material::co2()
            },
            "young = 10.7 Pa",
            "given in GPa? that is 10700000000.0 Pa",
        ),
        (
            Material {
                density: 1.56,
                ..Material::co2()
            },
            "density = 1.56 kg/m^3",
            "given in g/cm^3? that is 1560.0 kg/m^3",
        ),
    ];
    for (m, starts, hint) in cases {
        let c = Contact::new(m, g).unwrap();
        let w = c.warnings();
        assert!(c.has_warnings());
        assert!(
            matches!(w[..], [Warning::ImplausibleMaterial { .. }]),
            "{w:?}"
        );
        let text = w[0].to_string();
        assert!(text.starts_with(starts) && text.ends_with(hint), "{text}");
    }
}
