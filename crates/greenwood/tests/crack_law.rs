//! Greenwood's crack law: limits, signs, inversion, and the accuracy of the interpolated table.
//! Source: Arakawa & Krijt (2021) Appendix A and Figure 1 (v > 0 for beta < 1, v < 0 for
//! beta > 1, v(k, 1) = 0, beta -> k and 1/k with |v| -> infinity as alpha -> 0).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use greenwood::{
    alpha_of_beta, v_direct, Branch, CrackLaw, CrackPoint, GreenwoodError, OutOfRange,
};

const K: f64 = 0.01;

/// A deterministic low-discrepancy sample of ln(alpha) over [1e-6, 1e8], never on table nodes
/// (golden-ratio sequence).
fn sample_alphas(n: usize) -> impl Iterator<Item = f64> {
    let (lo, hi) = (1e-6f64.ln(), 1e8f64.ln());
    let phi = 0.618_033_988_749_894_8;
    (0..n).map(move |i| (lo + (hi - lo) * ((i as f64 + 0.5) * phi).fract()).exp())
}

#[test]
fn alpha_to_infinity_gives_beta_one_and_v_zero() {
    for branch in [Branch::Opening, Branch::Closing] {
        let p = CrackPoint::new(K, 1e12, branch).unwrap();
        assert!(p.distance_to_one < 1e-10, "{p:?}");
        assert!(p.v.abs() < 1e-12, "{p:?}");
    }
}

#[test]
fn alpha_to_zero_gives_beta_limits_and_infinite_speed() {
    let o = CrackPoint::new(K, 1e-12, Branch::Opening).unwrap();
    assert!(((o.beta - 1.0 / K) * K).abs() < 1e-9 && o.v < -1e13);
    let c = CrackPoint::new(K, 1e-12, Branch::Closing).unwrap();
    assert!(((c.beta - K) / K).abs() < 1e-9 && c.v > 1e13);
}

#[test]
fn distances_agree_with_beta() {
    for alpha in sample_alphas(50) {
        for branch in [Branch::Opening, Branch::Closing] {
            let p = CrackPoint::new(K, alpha, branch).unwrap();
            let (to_one, to_limit) = match branch {
                Branch::Opening => (p.beta - 1.0, 1.0 / K - p.beta),
                Branch::Closing => (1.0 - p.beta, p.beta - K),
            };
            // the plain differences are only good to rounding of beta: compare in absolute terms
            assert!((to_one - p.distance_to_one).abs() < 1e-13 * p.beta.max(1.0));
            assert!((to_limit - p.distance_to_limit).abs() < 1e-13 * p.beta.max(1.0));
            assert!(p.distance_to_one > 0.0 && p.distance_to_limit > 0.0);
        }
    }
}

#[test]
fn sign_of_v_is_sign_of_one_minus_beta() {
    let law = CrackLaw::new(K).unwrap();
    for beta in [
        0.011, 0.05, 0.5, 0.99, 0.999_999, 1.000_001, 1.01, 2.0, 50.0, 99.9,
    ] {
        let v = law.v(beta).unwrap();
        assert_eq!(v > 0.0, beta < 1.0, "beta = {beta}, v = {v}");
    }
    assert_eq!(law.v(1.0).unwrap(), 0.0);
    assert_eq!(v_direct(K, 1.0).unwrap(), 0.0);
}

#[test]
fn out_of_range_is_a_typed_error() {
    let law = CrackLaw::new(K).unwrap();
    for beta in [K, 1.0 / K, 0.0, -1.0, 1e3, f64::NAN] {
        assert!(matches!(
            law.v(beta),
            Err(GreenwoodError::OutOfRange(OutOfRange { field: "beta", .. }))
        ));
        assert!(v_direct(K, beta).is_err());
    }
    for k in [0.0, 1.0, -0.1, 1.5, f64::NAN] {
        assert!(matches!(
            CrackLaw::new(k),
            Err(GreenwoodError::OutOfRange(OutOfRange { field: "k", .. }))
        ));
    }
}

#[test]
fn direct_inversion_round_trips() {
    for alpha in sample_alphas(40) {
        for branch in [Branch::Opening, Branch::Closing] {
            let p = CrackPoint::new(K, alpha, branch).unwrap();
            if p.distance_to_one < 1e-12 || p.distance_to_limit < 1e-12 * p.beta {
                continue; // beta not resolvable in f64 there
            }
            let q = alpha_of_beta(K, p.beta).unwrap().unwrap();
            assert_eq!(q.branch, branch);
            // beta is rounded to f64: v is then determined to ~ cond * 1e-16
            assert!(
                ((q.v - p.v) / p.v).abs() < 1e-9,
                "alpha {alpha}: {p:?} vs {q:?}"
            );
        }
    }
}

/// The requirement of the Foundation issue: max relative error of v below 1e-8 against direct
/// evaluation over alpha in [1e-6, 1e8], sampled densely between the nodes, for several k.
#[test]
fn table_interpolation_bound() {
    for k in [0.005, 0.01, 0.02, 0.05] {
        let law = CrackLaw::new(k).unwrap();
        let mut worst: f64 = 0.0;
        let mut worst_slope: f64 = 0.0;
        for alpha in sample_alphas(20_000) {
            for branch in [Branch::Opening, Branch::Closing] {
                let p = CrackPoint::new(k, alpha, branch).unwrap();
                let s = law.speed(p.beta).unwrap();
                worst = worst.max(((s.v - p.v) / p.v).abs());
                // slope against a central difference of exact points
                let h = 1e-4;
                let a = CrackPoint::new(k, alpha * (1.0 + h), branch).unwrap();
                let b = CrackPoint::new(k, alpha * (1.0 - h), branch).unwrap();
                // difference beta through its cancellation-free distance to 1
                let dbeta = match branch {
                    Branch::Opening => a.distance_to_one - b.distance_to_one,
                    Branch::Closing => b.distance_to_one - a.distance_to_one,
                };
                let fd = (a.v - b.v) / dbeta;
                worst_slope = worst_slope.max(((s.dv_dbeta - fd) / fd).abs());
            }
        }
        // beta itself is rounded to f64 before lookup; near beta = 1 that rounding alone moves v
        // by |d ln v / d ln|beta-1|| * 1e-16 / |beta - 1|, below 1e-8 for alpha <= 1e8.
        assert!(worst < 1e-8, "k = {k}: worst relative error {worst:e}");
        assert!(
            worst_slope < 1e-5,
            "k = {k}: worst slope error {worst_slope:e}"
        );
    }
}

#[test]
fn unchecked_speed_saturates_beyond_bounds() {
    let law = CrackLaw::new(K).unwrap();
    assert_eq!(law.speed_unchecked(K / 2.0).v, f64::INFINITY);
    assert_eq!(law.speed_unchecked(2.0 / K).v, f64::NEG_INFINITY);
    assert!(law.speed_unchecked(f64::NAN).v.is_nan());
}

/// `∫_0^1 f(s) ds` by tanh-sinh quadrature (written here, independent of the crate's
/// quadrature): s = 1 / (1 + e^(-2u)), u = (pi/2) sinh t, step 1/64 in t out to |t| = 4;
/// `f` gets s and 1 - s (computed without cancellation next to s = 1).
fn tanh_sinh(f: impl Fn(f64, f64) -> f64) -> f64 {
    let h = 1.0 / 64.0;
    let mut sum = 0.0;
    for i in -256..=256 {
        let t = f64::from(i) * h;
        let u = std::f64::consts::FRAC_PI_2 * t.sinh();
        let (s, c) = (
            1.0 / (1.0 + (-2.0 * u).exp()),
            1.0 / (1.0 + (2.0 * u).exp()),
        );
        // ds/dt = (pi/2) cosh t * 2 s (1 - s)
        let w = std::f64::consts::PI * t.cosh() * s * c;
        if s > 0.0 && c > 0.0 {
            sum += w * f(s, c);
        }
    }
    sum * h
}

/// Appendix A as printed, from its integrals: J1, J2, J3 by [`tanh_sinh`] (with xi = s^2, so
/// that J3's xi^(-1/2) goes), then I1 = k + (1 - k) J1, I2 = k + (1 - k) J2,
/// I3 = 1 - (1 - k) J3, and beta = 1/I1, v = -(pi/4)/(alpha I1) (opening), beta = I3^2/I2,
/// v = (pi/4)/(alpha I2) (closing), against the crate's crack-law points and the table's v(beta)
/// at several k and alpha: the formulas' factors and which integral goes where, checked
/// against the paper's equations rather than the crate's own code.
#[test]
fn appendix_a_from_its_integrals() {
    let j = |alpha: f64| {
        // e^(-alpha (1 - xi)) with xi = s^2 and 1 - xi = c (1 + s)
        let damp = |s: f64, c: f64| (-alpha * c * (1.0 + s)).exp();
        // ln((1 + sqrt xi)/(1 - sqrt xi)) = ln((1 + s)/c); dxi = 2 s ds
        let log = |s: f64, c: f64| ((1.0 + s) / c).ln();
        let f = |s: f64, c: f64| 2.0 * s - c * (1.0 + s) * log(s, c);
        let a = |s: f64, c: f64| 2.0 * s + c * (1.0 + s) * log(s, c);
        let j1 = 0.5 * alpha * tanh_sinh(|s, c| damp(s, c) * f(s, c) * 2.0 * s);
        let j2 = 0.5 * alpha * tanh_sinh(|s, c| damp(s, c) * a(s, c) * 2.0 * s);
        // (1/2) xi^(-1/2) dxi = ds
        let j3 = tanh_sinh(damp);
        (j1, j2, j3)
    };
    let pi4 = std::f64::consts::FRAC_PI_4;
    for k in [0.01, 0.05, 0.3] {
        let law = CrackLaw::new(k).unwrap();
        for alpha in [0.03, 0.5, 4.0, 40.0] {
            let (j1, j2, j3) = j(alpha);
            let (i1, i2, i3) = (k + (1.0 - k) * j1, k + (1.0 - k) * j2, 1.0 - (1.0 - k) * j3);
            for (branch, beta, v) in [
                (Branch::Opening, 1.0 / i1, -pi4 / (alpha * i1)),
                (Branch::Closing, i3 * i3 / i2, pi4 / (alpha * i2)),
            ] {
                let p = CrackPoint::new(k, alpha, branch).unwrap();
                let at = format!("k = {k}, alpha = {alpha}, {branch:?}");
                assert!(
                    (p.beta / beta - 1.0).abs() < 1e-10,
                    "{at}: beta {} vs {beta}",
                    p.beta
                );
                assert!((p.v / v - 1.0).abs() < 1e-10, "{at}: v {} vs {v}", p.v);
                let table = law.v(beta).unwrap();
                assert!(
                    (table / v - 1.0).abs() < 1e-7,
                    "{at}: table v {table} vs {v}"
                );
            }
        }
    }
}
