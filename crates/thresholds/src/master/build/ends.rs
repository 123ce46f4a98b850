//! The end curves: where one collision at [`F_TOP`] V_stick,JKR stops bouncing (x_s, F = F_TOP)
//! and where it starts to stick (x_on, F_on = F_TOP), on a grid of y and k.
//!
//! V_out of that collision is continuous in x through the double-collision side (the spheres
//! still approaching, V_out > 0) and negative while it bounces, so x_s is a root of a smooth
//! function, found by Illinois regula falsi to [`ROOT_TOL`]; x_on, where the outcome jumps to
//! sticking, by bisection to the same width. Each y starts from the previous y's ends.

use super::{grid_k, synthetic, BuildConfig, RETRY_DENSITY};
use crate::master::format::{EndsData, F_TOP};
use dynamics::{Collider, Method, Outcome, SolverOptions};
use greenwood::CrackLaw;
use numerics::roots::{illinois, Illinois};
use rayon::prelude::*;

/// Width in x of the final brackets of x_s and x_on: 1e-11, so that the end curves carry no
/// error of their own beside their interpolation (about 1e-10).
pub const ROOT_TOL: f64 = 1e-11;

/// The first bracket around a guess, half-width in x; doubled until it brackets.
const FIRST_HALF_WIDTH: f64 = 0.004;

/// Where the scan for the first y of a k starts, and its step: x_s lies between -0.36 and 1.6
/// over the tables' y range.
const SCAN: (f64, f64) = (-2.0, 0.125);

/// No end is sought beyond this x.
const X_MAX: f64 = 4.0;

/// A fourth difference of an end curve (in y or in k) above this marks a kink (where the regime
/// of the cliff changes, and the differences reach 0.1): the cubic through the points around it
/// would be off by more than about 3/128 of it, 2e-6. Smooth stretches stay below 3e-7 (along k)
/// and 5e-9 (along y) where the cliff ends F; where F rises as a power of c_D up to F_TOP (y
/// below -4.7 at k = 0.01, -3.3 at 0.05) the end itself is fuzzy to about 5e-7 in x (the outcome
/// of a collision at V_stick flips with rounding), and the differences with it.
pub const KINK: f64 = 1e-4;

/// Below x_s by this much (in x) a collision at F_TOP V_stick,JKR surely does not stick: where
/// x_on is sought from. Larger than the fuzz of x_s where F rises as a power of c_D (5e-7).
const BELOW_X_S: f64 = 1e-5;

/// The collision at F_TOP V_stick,JKR at `(x, y)`: V_out / V_stick,JKR (negative: bouncing,
/// positive: double collision) or infinity (sticking); `None` if it fails for every synthetic
/// contact and with BDF as well.
pub fn top_collision(cfg: &BuildConfig, law: &CrackLaw, x: f64, y: f64) -> Option<f64> {
    let y = y.min(x + cfg.z_clamp);
    let bdf = SolverOptions {
        method: Method::Bdf,
        ..cfg.solver
    };
    [cfg.solver, bdf].iter().find_map(|&solver| {
        RETRY_DENSITY.iter().find_map(|&factor| {
            let (contact, t_vis) = synthetic(x, y, factor).ok()?;
            let jkr = contact.v_stick_jkr();
            let collider = Collider::new(contact, law, t_vis)
                .ok()?
                .with_options(solver)
                .ok()?;
            let c = collider.collide(F_TOP * jkr).ok()?;
            Some(match c.outcome {
                Outcome::Sticking => f64::INFINITY,
                _ => c.v_out / jkr,
            })
        })
    })
}

/// x_s at `y` near `guess` (or scanned for from `SCAN` without one).
pub fn x_s(cfg: &BuildConfig, law: &CrackLaw, y: f64, guess: Option<f64>) -> Option<f64> {
    let f = |x: f64| top_collision(cfg, law, x, y);
    let (mut a, mut fa, mut b, mut fb);
    match guess {
        Some(g) => {
            let mut h = FIRST_HALF_WIDTH;
            (a, b) = (g - h, g + h);
            (fa, fb) = (f(a)?, f(b)?);
            while fa >= 0.0 {
                h *= 2.0;
                (b, fb) = (a, fa);
                a -= h;
                if a < SCAN.0 {
                    return None;
                }
                fa = f(a)?;
            }
            while fb < 0.0 {
                h *= 2.0;
                (a, fa) = (b, fb);
                b += h;
                if b > X_MAX {
                    return None;
                }
                fb = f(b)?;
            }
        }
        None => {
            (a, fa) = (SCAN.0, f(SCAN.0)?);
            if fa >= 0.0 {
                return None;
            }
            loop {
                b = a + SCAN.1;
                fb = f(b)?;
                if fb >= 0.0 {
                    break;
                }
                (a, fa) = (b, fb);
                if a > X_MAX {
                    return None;
                }
            }
        }
    }
    let opts = Illinois {
        x_tol: ROOT_TOL,
        max_iter: 120,
        guard: 0.02,
        ..Illinois::default()
    };
    let r = illinois(|x| f(x).ok_or(()), (a, fa), (b, fb), &opts).ok()?;
    (r.hi - r.lo <= 10.0 * ROOT_TOL).then_some(r.midpoint())
}

/// x_on at `y`, at least `x_s`, near `guess`: x_s itself where a collision just below x_s
/// already sticks (F rises as a power of c_D there and F_on = F).
pub fn x_on(
    cfg: &BuildConfig,
    law: &CrackLaw,
    y: f64,
    x_s: f64,
    guess: Option<f64>,
) -> Option<f64> {
    let sticks = |x: f64| top_collision(cfg, law, x, y).map(|v| v == f64::INFINITY);
    let mut lo = x_s - BELOW_X_S;
    if sticks(lo)? {
        return Some(x_s);
    }
    let mut h = guess.map_or(FIRST_HALF_WIDTH, |g| (g - x_s).max(0.0) + FIRST_HALF_WIDTH);
    let mut hi = x_s + h;
    while !sticks(hi)? {
        lo = hi;
        h *= 2.0;
        hi = x_s + h;
        if hi > X_MAX {
            return None;
        }
    }
    while hi - lo > ROOT_TOL {
        let mid = 0.5 * (lo + hi);
        if sticks(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some((0.5 * (lo + hi)).max(x_s))
}

/// The end curves on the grid of `cfg` (y every `min_y_step` over `y_range`, k as `ends_k`);
/// `progress` is told of each k done.
pub fn build_ends(cfg: &BuildConfig, progress: &(dyn Fn(&str) + Sync)) -> EndsData {
    repair_ends(cfg, None, progress)
}

/// [`build_ends`], keeping the values `previous` holds (on the same grid) and computing only
/// the missing ones: a build interrupted, or one whose root finder failed at some points.
pub fn repair_ends(
    cfg: &BuildConfig,
    previous: Option<&EndsData>,
    progress: &(dyn Fn(&str) + Sync),
) -> EndsData {
    let (y0, y1) = cfg.y_range;
    let dy = cfg.min_y_step;
    let ny = ((y1 - y0) / dy).round() as usize + 1;
    let (k0, per_octave, nk) = cfg.ends_k;
    let columns: Vec<(Vec<f64>, Vec<f64>)> = (0..nk)
        .into_par_iter()
        .map(|j| {
            let k = grid_k(k0, per_octave, j);
            let known = previous
                .filter(|p| p.ny == ny && p.nk == nk)
                .map(|p| (&p.x_s[j * ny..(j + 1) * ny], &p.x_on[j * ny..(j + 1) * ny]));
            let column = ends_column(cfg, k, y0, dy, ny, known);
            let missing = column.0.iter().filter(|v| v.is_nan()).count();
            progress(&format!(
                "end curves at k = {k}: {ny} points, {missing} missing"
            ));
            column
        })
        .collect();
    let x_s: Vec<f64> = columns.iter().flat_map(|c| c.0.iter().copied()).collect();
    let x_on: Vec<f64> = columns.iter().flat_map(|c| c.1.iter().copied()).collect();
    let valid = validity(&x_s, &x_on, ny, nk);
    let (x_s, x_on) = (x_s.into(), x_on.into());
    let valid = valid
        .iter()
        .map(|&v| f64::from(u8::from(v)))
        .collect::<Vec<_>>()
        .into();
    EndsData {
        header: vec![
            format!(
                "end curves of the master tables: x_s, where one collision at {F_TOP} V_stick,JKR stops bouncing (F = V_stick/V_stick,JKR reaches {F_TOP}), and x_on, where it starts to stick (F_on reaches it); x = log10 c_D, y = log10(c_D c_a)"
            ),
            format!(
                "roots to {ROOT_TOL:e} in x with collisions at rtol {:e}; valid = 0 next to a kink (fourth difference above {KINK:e}) or a missing value",
                cfg.solver.rtol
            ),
        ],
        y0,
        dy,
        ny,
        k0,
        per_octave,
        nk,
        x_s,
        x_on,
        valid,
        kcheck_y: (y0, cfg.kcheck_dy, ((y1 - y0) / cfg.kcheck_dy).ceil() as usize),
        kcheck: Vec::new(),
    }
}

/// The ends at one k for every y of the grid, each y started from the previous one's.
fn ends_column(
    cfg: &BuildConfig,
    k: f64,
    y0: f64,
    dy: f64,
    ny: usize,
    known: Option<(&[f64], &[f64])>,
) -> (Vec<f64>, Vec<f64>) {
    let Ok(law) = CrackLaw::new(k) else {
        return (vec![f64::NAN; ny], vec![f64::NAN; ny]);
    };
    let (mut xs, mut xo) = (Vec::with_capacity(ny), Vec::with_capacity(ny));
    let mut last: Option<(f64, f64)> = None;
    for i in 0..ny {
        let y = y0 + i as f64 * dy;
        if let Some((s, o)) = known
            .map(|(s, o)| (s[i], o[i]))
            .filter(|v| v.0.is_finite() && v.1.is_finite())
        {
            last = Some((s, o));
            xs.push(s);
            xo.push(o);
            continue;
        }
        let s = x_s(cfg, &law, y, last.map(|l| l.0)).or_else(|| x_s(cfg, &law, y, None));
        let o = s.and_then(|s| x_on(cfg, &law, y, s, last.map(|l| l.1)));
        match (s, o) {
            (Some(s), Some(o)) => {
                last = Some((s, o));
                xs.push(s);
                xo.push(o);
            }
            _ => {
                xs.push(f64::NAN);
                xo.push(f64::NAN);
            }
        }
    }
    (xs, xo)
}

/// `valid[j * ny + i]`: no kink or missing value within two grid steps in y or in k.
pub fn validity(x_s: &[f64], x_on: &[f64], ny: usize, nk: usize) -> Vec<bool> {
    let mut valid = vec![true; ny * nk];
    let at = |j: usize, i: usize| j * ny + i;
    let fourth = |v: [f64; 5]| (v[0] - 4.0 * v[1] + 6.0 * v[2] - 4.0 * v[3] + v[4]).abs();
    // the five points of each difference above KINK (or missing), along y and along k
    let mut marked: Vec<usize> = Vec::new();
    for curve in [x_s, x_on] {
        marked.extend((0..ny * nk).filter(|&p| curve[p].is_nan()));
        for j in 0..nk {
            for i in 0..ny.saturating_sub(4) {
                let v = [0, 1, 2, 3, 4].map(|q| curve[at(j, i + q)]);
                if fourth(v).is_nan() || fourth(v) > KINK {
                    marked.extend((0..5).map(|q| at(j, i + q)));
                }
            }
        }
        for i in 0..ny {
            for j in 0..nk.saturating_sub(4) {
                let v = [0, 1, 2, 3, 4].map(|q| curve[at(j + q, i)]);
                if fourth(v).is_nan() || fourth(v) > KINK {
                    marked.extend((0..5).map(|q| at(j + q, i)));
                }
            }
        }
    }
    for p in marked {
        valid[p] = false;
    }
    valid
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A smooth curve is valid everywhere; a kink marks the points within two steps of it; a
    /// missing value marks itself and the points whose differences reach it.
    #[test]
    fn kinks_and_gaps_are_marked() {
        let (ny, nk) = (20, 5);
        let smooth: Vec<f64> = (0..ny * nk).map(|p| 0.01 * (p % ny) as f64).collect();
        assert!(validity(&smooth, &smooth, ny, nk).iter().all(|&v| v));
        let kinked: Vec<f64> = (0..ny * nk)
            .map(|p| 0.01 * ((p % ny) as f64 - 10.0).abs())
            .collect();
        let v = validity(&kinked, &kinked, ny, nk);
        assert!(!v[10] && !v[8] && !v[12] && v[4] && v[16]);
        let mut gap = smooth.clone();
        gap[2 * ny + 7] = f64::NAN;
        let v = validity(&gap, &smooth, ny, nk);
        assert!(!v[2 * ny + 7] && !v[2 * ny + 5] && v[2 * ny + 15] && v[ny + 15]);
    }
}
