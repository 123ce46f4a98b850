//! Properties of single collisions over random grains, relaxation times and speeds
//! (Arakawa & Krijt 2021, Sections 2.5 and 4.4): the energy never increases along a trajectory,
//! so a contact that ends leaves with less kinetic energy than it came with (|e| < 1, for
//! bouncing and double collisions alike), and a contact declared sticking is bound: its energy
//! has fallen below the initial kinetic energy and it is still in contact (a > 0, with beta
//! short of the end of contact at (1 - eps)/k).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, Outcome, SolverOptions, EPS};
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
        let last = r.trajectory.last().unwrap();
        match r.outcome {
            Outcome::Bouncing | Outcome::DoubleCollision => {
                prop_assert!(r.e.abs() < 1.0, "{:?}: e = {}", r.outcome, r.e);
                prop_assert!(r.contact_time.is_some_and(|t| t > 0.0));
            }
            Outcome::Sticking => {
                prop_assert!(last.energy < e_in, "{} >= {e_in}", last.energy);
                prop_assert!(last.a > 0.0, "a = {}", last.a);
                prop_assert!(last.beta < (1.0 - EPS) / 0.01, "beta = {}", last.beta);
            }
        }
    }
}
