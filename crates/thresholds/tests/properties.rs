//! Property: dissipation only makes sticking easier, so V_stick >= V_stick,JKR (within the
//! search tolerance) for any grain and relaxation time (Arakawa & Krijt 2021, Section 5.1).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact::{Contact, Geometry, Material};
use greenwood::CrackLaw;
use proptest::prelude::*;
use thresholds::{sticking_thresholds, SearchOptions};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn v_stick_is_at_least_jkr(
        h2o in any::<bool>(),
        log_r1 in -7.0f64..-3.0,
        log_t in -15.0f64..-8.0,
    ) {
        let law = CrackLaw::new(0.01).unwrap();
        let m = if h2o { Material::h2o() } else { Material::co2() };
        let c = Contact::new(m, Geometry::identical(10f64.powf(log_r1))).unwrap();
        let th = sticking_thresholds(&c, &law, 10f64.powf(log_t), &SearchOptions::default()).unwrap();
        if let Some(vs) = th.v_stick {
            prop_assert!(vs >= th.v_stick_jkr * (1.0 - 2e-6), "{vs} < {}", th.v_stick_jkr);
            let vd = th.v_double_onset.unwrap();
            prop_assert!(vd <= vs * (1.0 + 1e-6) && vd >= th.v_stick_jkr * (1.0 - 2e-6));
        } else {
            prop_assert!(th.v_max > th.v_stick_jkr);
        }
    }
}
