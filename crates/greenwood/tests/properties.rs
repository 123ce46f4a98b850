//! Property: v(k, beta) decreases monotonically in beta over (k, 1/k) and has the sign of
//! 1 - beta (Greenwood 2004; Arakawa & Krijt 2021, Figure 1), for any k.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use greenwood::CrackLaw;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn crack_law_is_monotone(k in 0.002f64..0.4, a in 0.0f64..1.0, b in 0.0f64..1.0) {
        let law = CrackLaw::new(k).unwrap();
        // map a, b to beta in (k, 1/k) on a log scale
        let beta = |f: f64| k * (1.0 / (k * k)).powf(0.001 + 0.998 * f);
        let (b1, b2) = (beta(a.min(b)), beta(a.max(b)));
        let (v1, v2) = (law.v(b1).unwrap(), law.v(b2).unwrap());
        prop_assert!(v1 >= v2, "k {k}: v({b1}) = {v1} < v({b2}) = {v2}");
        prop_assert!(v1.is_finite() && v2.is_finite());
        prop_assert_eq!(v1 > 0.0, b1 < 1.0);
        let s = law.speed(b1).unwrap();
        prop_assert!(s.dv_dbeta <= 0.0);
    }
}
