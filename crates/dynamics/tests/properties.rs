//! Properties of single collisions over random grains, relaxation times and speeds
//! (Arakawa & Krijt 2021, Sections 2.5 and 4.4): the energy never increases along a trajectory,
//! and a bouncing collision has 0 <= e < 1.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, Outcome, SolverOptions};
use greenwood::CrackLaw;
use proptest::prelude::*;

fn material(h2o: bool, gamma_sv: f64) -> Material {
    let m = if h2o {
        Material::h2o()
    } else {
        Material::co2()
    };
    Material { gamma_sv, ..m }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn energy_never_increases_and_e_is_in_range(
        h2o in any::<bool>(),
        gamma_sv in 0.02f64..0.2,
        log_r1 in -7.0f64..-3.0,
        log_t in -15.0f64..-7.0,
        speed in 0.3f64..30.0,
    ) {
        let law = CrackLaw::new(0.01).unwrap();
        let c = Contact::new(material(h2o, gamma_sv), Geometry::identical(10f64.powf(log_r1))).unwrap();
        let v_in = speed * c.v_stick_jkr();
        let col = Collider::new(c, &law, 10f64.powf(log_t)).unwrap()
            .with_options(SolverOptions { record_trajectory: true, ..Default::default() }).unwrap();
        let r = col.collide(v_in).unwrap();
        let e_in = 0.5 * c.m_star() * v_in * v_in;
        let scale = e_in.max(c.e_stick_jkr());
        for w in r.trajectory.windows(2) {
            prop_assert!(w[1].energy <= w[0].energy + 1e-7 * scale,
                "energy rose from {} to {} (scale {scale})", w[0].energy, w[1].energy);
        }
        prop_assert!(r.e.is_finite() && r.v_out.is_finite());
        match r.outcome {
            Outcome::Bouncing => prop_assert!((0.0..1.0).contains(&r.e), "e = {}", r.e),
            Outcome::DoubleCollision => prop_assert!(r.e < 0.0),
            Outcome::Sticking => prop_assert_eq!(r.e, 0.0),
        }
    }
}
