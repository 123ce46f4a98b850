//! Thresholds beyond identical spheres. Sources: the reduced radius and mass of two spheres,
//! R = R1 R2/(R1 + R2) and m* = m1 m2/(m1 + m2), which the model (Arakawa & Krijt 2021,
//! Sections 2.1 and 2.5) uses through R and m* only; a wall is R2 -> infinity; and V_stick ->
//! V_stick,JKR as T_vis -> 0 (Section 5.1).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use thresholds::{
    sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions, StickingThresholds,
};

fn thresholds(m: Material, g: Geometry, t_vis: f64) -> StickingThresholds {
    let law = CrackLaw::new(0.01).unwrap();
    let c = Contact::new(m, g).unwrap();
    sticking_thresholds(&c, &law, t_vis, &SearchOptions::exact()).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// R2 = R1 is the paper's case: identical results, still in the windows of Section 4.4
/// (4.03-4.04 and 4.13-4.14 cm/s); R2 a hair from R1 moves them by the hair only.
#[test]
fn equal_radii_reproduce_the_identical_spheres() {
    let co2 = Material::co2();
    let id = thresholds(co2, Geometry::identical(60e-6), 1e-9);
    let eq = thresholds(co2, Geometry::spheres(60e-6, 60e-6), 1e-9);
    assert_eq!(id, eq);
    let vs = eq.v_stick.unwrap() * 100.0;
    assert!(vs > 4.13 && vs <= 4.14, "{vs}");
    let near = thresholds(co2, Geometry::spheres(60e-6, 60e-6 * (1.0 + 1e-12)), 1e-9);
    assert!(rel(near.v_stick.unwrap(), id.v_stick.unwrap()) < 1e-9);
    assert!(rel(near.v_double_onset.unwrap(), id.v_double_onset.unwrap()) < 1e-9);
}

/// Which sphere is called 1 does not matter, to the bit.
#[test]
fn swapping_the_spheres_changes_nothing() {
    let a = thresholds(Material::co2(), Geometry::spheres(60e-6, 30e-6), 1e-9);
    let b = thresholds(Material::co2(), Geometry::spheres(30e-6, 60e-6), 1e-9);
    assert_eq!(a, b);
}

/// A sphere a million times larger is the wall to about 1e-6 (R differs by 1e-6 relative).
#[test]
fn a_very_large_partner_is_a_wall() {
    let wall = thresholds(Material::co2(), Geometry::wall(60e-6), 1e-9);
    let big = thresholds(Material::co2(), Geometry::spheres(60e-6, 60.0), 1e-9);
    assert!(rel(big.v_stick.unwrap(), wall.v_stick.unwrap()) < 1e-5);
    assert!(rel(big.v_double_onset.unwrap(), wall.v_double_onset.unwrap()) < 1e-5);
}

/// Everything follows from R and m*: a sphere of R1/2 on a wall at density 4 rho has R = R1/2 and
/// m* = (4 pi 4 rho (R1/2)^3/3) = m1/2, exactly those of identical spheres of R1 and density rho,
/// so the thresholds agree to rounding.
#[test]
fn only_reduced_radius_and_mass_matter() {
    let co2 = Material::co2();
    let id = thresholds(co2, Geometry::identical(60e-6), 1e-9);
    let dense = Material {
        density: 4.0 * co2.density,
        ..co2
    };
    let wall = thresholds(dense, Geometry::wall(30e-6), 1e-9);
    assert!(rel(wall.v_stick_jkr, id.v_stick_jkr) < 1e-12);
    assert!(rel(wall.v_stick.unwrap(), id.v_stick.unwrap()) < 2e-6);
    assert!(rel(wall.v_double_onset.unwrap(), id.v_double_onset.unwrap()) < 2e-6);
}

/// Section 5.1: V_stick -> V_stick,JKR as T_vis -> 0, in every geometry (within 1e-3 at 1e-14 s,
/// as for identical spheres), and V_stick,JKR on a wall is 2^(1/6) that of identical spheres.
#[test]
fn jkr_limit_in_every_geometry() {
    for g in [Geometry::wall(60e-6), Geometry::spheres(60e-6, 30e-6)] {
        let th = thresholds(Material::co2(), g, 1e-14);
        assert!(
            rel(th.v_stick.unwrap(), th.v_stick_jkr) < 1e-3,
            "{g}: {th:?}"
        );
        assert!(th.v_stick.unwrap() >= th.v_stick_jkr * (1.0 - 1e-6));
    }
    let wall = thresholds(Material::co2(), Geometry::wall(60e-6), 0.0);
    let id = thresholds(Material::co2(), Geometry::identical(60e-6), 0.0);
    assert!(
        rel(
            wall.v_stick.unwrap() / id.v_stick.unwrap(),
            2f64.powf(1.0 / 6.0)
        ) < 1e-12
    );
}
