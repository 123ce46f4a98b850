//! The collision ODE in nondimensional variables and pseudo-time.
//!
//! # Scales
//! Lengths: `a = a_eq x`, `delta = delta_eq y` (JKR equilibrium, `delta_eq = a_eq^2/(3R)`).
//! Force: `F0 = 2 E* a_eq^3/(3R) = 3 pi gamma R`, so that `F_E = F0 (x y - x^3)`.
//! Time: `t = t0 tau`, `t0 = sqrt(m* delta_eq / F0)`. Speed: `V0 = delta_eq / t0`, `p = delta_dot / V0`.
//! Energy: `E0 = F0 delta_eq / 2`. Then (Sections 2.1-2.5)
//! ```text
//! dx/dtau = lambda v(k, beta),       lambda = E* gamma t0 / (sigma0^2 T_vis a_eq)
//! dy/dtau = p
//! dp/dtau = -(x y - x^3) - c_D x p,  c_D = 2 A E* a_eq t0 / m*,  A = T_vis/nu^2
//! beta    = (3x^2 - y)^2 / (4x)
//! energy  = p^2 + x y^2 - 2 x^3 y + 9x^5/5 - 2x^2      (kinetic + U_E - pi a^2 gamma, in E0)
//! d energy/dtau = -2 c_D x p^2 + 4 x (beta - 1) lambda v  <= 0
//! ```
//!
//! # Pseudo-time
//! As `T_vis -> 0`, `lambda -> infinity`, and at the end of contact the crack collapses (beta from
//! about 2 to `(1 - eps)/k`) in a time below the floating-point spacing of t. The integration
//! therefore runs in a pseudo-time `s` with
//! ```text
//! dtau/ds = g = 1 / sqrt(1 + (lambda v / F_c)^2),    F_c = lambda clamped to [1, SPEED_CAP = 1e3]
//! ```
//! carrying `tau` as the fourth state. Every right-hand side is then bounded (`|dx/ds| < F_c`):
//! the collapse of the crack takes `Delta s ~ Delta x / F_c` however small T_vis is. Where the crack
//! moves at the speed of the slow, JKR-like motion (`|dx/dtau| = lambda |v| = O(1) << F_c`),
//! `s` is the time itself, so the stiff but smooth dynamics near beta = 1 is left as it is.
//! Two choices were measured to fail there and are avoided: for large lambda a cap of order one
//! turns the crack equation into a steep sigmoid in x whose Newton iterations do not converge
//! for T_vis < 1e-13 s; and a normalizer with `|v|` (such as `1/(1 + lambda |v|)`) has a kink at
//! v = 0, exactly where the solution sits. For small lambda (T_vis ~ 1e-9 s) a cap of about
//! lambda flattens the initial growth and the final collapse of the crack, which otherwise span
//! decades of time scale and half of the solver steps; it halves the steps there. This cap
//! integrates T_vis = 1e-6..1e-16 s with BDF and ESDIRK34.

use greenwood::CrackLaw;

/// Number of ODE states: `(x, y, p, tau)`.
pub const NSTATES: usize = 4;

/// Largest crack speed `|dx/dtau|` above which the pseudo-time slows down; the cap used is
/// `lambda` clamped to `[1, SPEED_CAP]` (see the module docs).
pub const SPEED_CAP: f64 = 1e3;

/// Parameters of the nondimensional system.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Crack-speed ratio lambda (dimensionless).
    pub lambda: f64,
    /// Drag coefficient c_D (dimensionless).
    pub c_d: f64,
    /// Crack-speed cap F_c of the pseudo-time (dimensionless, in units of a_eq/t0).
    pub speed_cap: f64,
}

/// `beta(x, y) = (3x^2 - y)^2 / (4x)` and its partial derivatives.
#[inline]
pub fn beta_with_gradient(x: f64, y: f64) -> (f64, f64, f64) {
    let q = 3.0 * x * x - y;
    let beta = q * q / (4.0 * x);
    (beta, 3.0 * q - beta / x, -q / (2.0 * x))
}

/// `beta(x, y)` (dimensionless).
#[inline]
pub fn beta(x: f64, y: f64) -> f64 {
    beta_with_gradient(x, y).0
}

/// `4x (beta(x, y) - beta_end) = (3x^2 - y)^2 - 4x beta_end`: the sign of `beta - beta_end` for
/// a contact (x > 0), continuous where beta is not (beta -> +inf as x -> 0+), and >= 0 for
/// x <= 0. Its zero places the end of contact inside a step that jumped past x = 0.
#[inline]
pub fn end_gap(x: f64, y: f64, beta_end: f64) -> f64 {
    let q = 3.0 * x * x - y;
    q * q - 4.0 * x * beta_end
}

/// Total energy in units of `E0` (see the module docs).
#[inline]
pub fn energy(x: f64, y: f64, p: f64) -> f64 {
    p * p + x * y * y - 2.0 * x.powi(3) * y + 1.8 * x.powi(5) - 2.0 * x * x
}

/// The speed factor `(F g, g, d(F g)/dbeta, dg/dbeta)` with `F = lambda v`,
/// `g = (1 + F^2)^(-1/2)`, for crack speed `v` and slope `dv` at one beta; saturates to
/// `(±1, 0, 0, 0)` when v is infinite (beta at or beyond its bounds).
#[inline]
fn crack_terms(params: &Params, v: f64, dv: f64) -> (f64, f64, f64, f64) {
    let (lambda, cap) = (params.lambda, params.speed_cap);
    let f = lambda * v;
    if !f.is_finite() {
        return (cap * v.signum(), 0.0, 0.0, 0.0);
    }
    let r = f / cap;
    // |r| < 1e30 here (|v| < 1e20 inside the table's range, lambda < 1e10), so r^2 cannot overflow
    let g = 1.0 / (1.0 + r * r).sqrt();
    let g3 = g * g * g;
    (f * g, g, lambda * dv * g3, -r / cap * lambda * dv * g3)
}

/// Right-hand side `du/ds` at state `u = (x, y, p, tau)`.
pub fn rhs(params: &Params, law: &CrackLaw, u: &[f64], out: &mut [f64]) {
    let (x, y, p) = (u[0], u[1], u[2]);
    let b = beta(x, y);
    let s = law.speed_unchecked(b);
    let (fx, g, _, _) = crack_terms(params, s.v, s.dv_dbeta);
    let force = -(x * y - x * x * x) - params.c_d * x * p;
    out[0] = fx;
    out[1] = p * g;
    out[2] = force * g;
    out[3] = g;
}

/// Jacobian-vector product `J(u) w` of [`rhs`].
pub fn jac_mul(params: &Params, law: &CrackLaw, u: &[f64], w: &[f64], out: &mut [f64]) {
    let (x, y, p) = (u[0], u[1], u[2]);
    let (b, bx, by) = beta_with_gradient(x, y);
    let s = law.speed_unchecked(b);
    let (_, g, dfx, dg) = crack_terms(params, s.v, s.dv_dbeta);
    let force = -(x * y - x * x * x) - params.c_d * x * p;
    // directional derivative of beta
    let db = bx * w[0] + by * w[1];
    let dgw = dg * db;
    let dforce = (3.0 * x * x - y - params.c_d * p) * w[0] - x * w[1] - params.c_d * x * w[2];
    out[0] = dfx * db;
    out[1] = w[2] * g + p * dgw;
    out[2] = dforce * g + force * dgw;
    out[3] = dgw;
}

/// Smallest total energy (units of `E0`) of any state at the end of contact, beta = `beta_end`.
///
/// On the curve `(3x^2 - y)^2 = 4 beta_end x` the potential `x (y - x^2)^2 + 4x^5/5 - 2x^2` is
/// smallest on the branch `y = 3x^2 - 2 sqrt(beta_end x)`, where with `x = beta_end^(1/3) w` it equals
/// `beta_end^(2/3) w^2 [beta_end h(w) - 2]`, `h(w) = 4 (w^(3/2) - 1)^2 + 4 w^3 / 5 >= 2/3`.
/// For `beta_end >= 3` it is positive and tends to 0 as `x -> 0`: the bound is 0. Otherwise the
/// minimum over w is found numerically (golden section). Kinetic energy only adds to it.
pub fn end_energy_bound(beta_end: f64) -> f64 {
    let phi = |w: f64| {
        let z = w.powf(1.5) - 1.0;
        beta_end.powf(2.0 / 3.0) * w * w * (beta_end * (4.0 * z * z + 0.8 * w.powi(3)) - 2.0)
    };
    if beta_end >= 3.0 {
        return 0.0;
    }
    // coarse scan, then golden section around the best sample
    let n = 400;
    let wmax = 2.0;
    let mut best = (0.0, 0.0);
    for i in 1..=n {
        let w = wmax * i as f64 / n as f64;
        let f = phi(w);
        if f < best.1 {
            best = (w, f);
        }
    }
    let (mut lo, mut hi) = (
        (best.0 - wmax / n as f64).max(0.0),
        best.0 + wmax / n as f64,
    );
    let r = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let a = hi - r * (hi - lo);
        let b = lo + r * (hi - lo);
        if phi(a) < phi(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    phi(0.5 * (lo + hi)).min(best.1).min(0.0)
}
