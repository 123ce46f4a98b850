//! Accuracy of J1, J2, J3 against closed forms, exact identities and limits.
//! Sources: Arakawa & Krijt (2021) Appendix A (definitions); the closed forms are derived in the
//! doc comment of `greenwood::integrals` and below.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use greenwood::{j1, j2, j3, log_term, JIntegrals};

/// Dawson's integral D(x) = e^{-x^2} ∫_0^x e^{t^2} dt, independently of any quadrature:
/// the positive-term series D(x) = e^{-x^2} Σ x^{2n+1} / (n! (2n+1)) (no cancellation) for x <= 6,
/// the asymptotic series D(x) ~ 1/(2x) Σ (2n-1)!! / (2x^2)^n (error ~ e^{-x^2}) above.
fn dawson(x: f64) -> f64 {
    if x <= 6.0 {
        let x2 = x * x;
        let mut term = x; // x^{2n+1} / n!
        let mut sum = 0.0;
        let mut n = 0.0;
        loop {
            let add = term / (2.0 * n + 1.0);
            sum += add;
            if add < 1e-18 * sum {
                break;
            }
            n += 1.0;
            term *= x2 / n;
        }
        (-x2).exp() * sum
    } else {
        let y = 1.0 / (2.0 * x * x);
        let mut term = 1.0;
        let mut sum = 1.0;
        let mut n = 1.0;
        loop {
            let next = term * (2.0 * n - 1.0) * y;
            if next >= term || next < 1e-18 {
                break;
            }
            term = next;
            sum += term;
            n += 1.0;
        }
        sum / (2.0 * x)
    }
}

/// 1 - J3 = 1 - D(x)/x without cancellation: the series Σ_{n>=1} (-1)^{n+1} (2 alpha)^n / (2n+1)!!
/// (terms decrease monotonically for alpha <= 1), else the subtraction (J3 < 0.54 there).
fn one_minus_j3_exact(a: f64) -> f64 {
    if a <= 1.0 {
        let mut s = 0.0;
        let mut t = 1.0;
        for n in 1..60 {
            t *= 2.0 * a / (2.0 * n as f64 + 1.0);
            s += if n % 2 == 1 { t } else { -t };
        }
        s
    } else {
        1.0 - dawson(a.sqrt()) / a.sqrt()
    }
}

fn alphas() -> Vec<f64> {
    // 1e-6 ..= 1e8, 8 points a decade
    (0..=112)
        .map(|i| 10f64.powf(-6.0 + i as f64 / 8.0))
        .collect()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn dawson_reference_is_right() {
    // Tabulated values (Abramowitz & Stegun Table 7.5): D(1) = 0.5380795069, D(2) = 0.3013403889.
    assert!((dawson(1.0) - 0.538_079_506_9).abs() < 1e-10);
    assert!((dawson(2.0) - 0.301_340_388_9).abs() < 1e-10);
    // Both series agree where they overlap.
    assert!(
        rel(dawson(6.0), {
            let x: f64 = 6.0;
            let y = 1.0 / (2.0 * x * x);
            let mut t = 1.0;
            let mut s = 1.0;
            for n in 1..40 {
                t *= (2.0 * n as f64 - 1.0) * y;
                s += t;
            }
            s / (2.0 * x)
        }) < 1e-13
    );
}

/// J3 = D(sqrt(alpha)) / sqrt(alpha): substitute xi = s^2 in Appendix A's J3.
#[test]
fn j3_matches_dawson_closed_form() {
    let mut worst: f64 = 0.0;
    for a in alphas() {
        let x = a.sqrt();
        let exact = dawson(x) / x;
        worst = worst.max(rel(j3(a).unwrap(), exact));
        let j = JIntegrals::new(a).unwrap();
        worst = worst.max(rel(j.j3, exact));
        // 1 - J3 is computed without subtraction for small alpha.
        worst = worst.max(rel(j.one_minus_j3, one_minus_j3_exact(a)));
    }
    assert!(worst < 1e-13, "worst relative error {worst:e}");
}

/// Integration by parts of alpha ∫ e^{-alpha(1-xi)} sqrt(xi) dxi gives J1 + J2 = 2 (1 - J3).
/// J1 and J2 here integrate Appendix A's F and A directly; J3 is the independent closed form.
#[test]
fn j1_plus_j2_identity() {
    let mut worst: f64 = 0.0;
    for a in alphas() {
        let one_minus_j3 = one_minus_j3_exact(a);
        let lhs = j1(a).unwrap() + j2(a).unwrap();
        worst = worst.max(rel(lhs, 2.0 * one_minus_j3));
    }
    assert!(worst < 1e-13, "worst relative error {worst:e}");
}

/// The identity form used by the crack law agrees with the direct quadrature of F and A.
#[test]
fn identity_form_matches_direct_quadrature() {
    let mut worst: f64 = 0.0;
    for a in alphas() {
        let j = JIntegrals::new(a).unwrap();
        worst = worst.max(rel(j.j1, j1(a).unwrap()));
        worst = worst.max(rel(j.j2, j2(a).unwrap()));
    }
    assert!(worst < 1e-13, "worst relative error {worst:e}");
}

/// alpha -> 0: J1 ~ alpha ∫F/2 = alpha/3, J2 ~ alpha ∫A/2 = alpha, J3 -> 1 - 2 alpha/3,
/// using ∫_0^1 2 sqrt(xi) = 4/3 and ∫_0^1 (1 - xi) L(xi) dxi = 2/3 (integration by parts with
/// the antiderivative -(1 - s^2)^2 / 4 of s - s^3).
#[test]
fn small_alpha_limit() {
    for a in [1e-6, 1e-7, 1e-8] {
        // next terms are O(alpha^2) relative O(alpha)
        assert!(rel(j1(a).unwrap(), a / 3.0) < 5.0 * a, "J1 at {a}");
        assert!(rel(j2(a).unwrap(), a) < 5.0 * a, "J2 at {a}");
        assert!(rel(log_term(a).unwrap(), a / 3.0) < 5.0 * a, "K at {a}");
        let j = JIntegrals::new(a).unwrap();
        assert!(rel(j.one_minus_j3, 2.0 * a / 3.0) < 5.0 * a, "1-J3 at {a}");
    }
}

/// alpha -> infinity: J1, J2 -> F(1)/2 = A(1)/2 = 1, J3 ~ 1/(2 alpha) (Dawson asymptotics), and
/// K ~ (ln(4 alpha) + gamma_E - 1) / (2 alpha) from ∫_0^∞ e^{-alpha t} t ln t dt
/// = (1 - gamma_E - ln alpha) / alpha^2.
#[test]
fn large_alpha_limit() {
    const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
    for a in [1e6, 1e7, 1e8] {
        let j = JIntegrals::new(a).unwrap();
        assert!((j.j1 - 1.0).abs() < 10.0 * a.ln() / a);
        assert!((j.j2 - 1.0).abs() < 10.0 * a.ln() / a);
        assert!(rel(j.j3, 0.5 / a) < 1.0 / a);
        let k_asym = ((4.0 * a).ln() + EULER_GAMMA - 1.0) / (2.0 * a);
        assert!(rel(j.k_log, k_asym) < 5.0 * a.ln() / a, "K at {a}");
    }
}

#[test]
fn bad_alpha_is_an_error() {
    for a in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(JIntegrals::new(a).is_err());
        assert!(j1(a).is_err());
    }
}
