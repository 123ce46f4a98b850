//! The workspace's bracketing root finder for smooth functions: the Illinois variant of regula
//! falsi. (The threshold searches of `thresholds` classify outcomes, which jump, and keep their
//! own secant and trisection steps on collisions.)
//!
//! Used for the crack-law inversion (`greenwood::alpha_of_beta`, in `ln alpha`), for the
//! relaxation time that reproduces a measured V_stick (`thresholds::fit_t_vis`, in `ln T_vis`),
//! and for the end of contact and the rebound inside a solver step (`dynamics`, in pseudo-time).
//! Regula falsi keeps a bracket `[lo, hi]` with `f(lo)` and `f(hi)` of opposite signs and tries
//! the secant point; the Illinois rule halves the value kept at an end that survives twice in a
//! row, which restores superlinear convergence where plain regula falsi stalls at one end.

/// Settings of [`illinois`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Illinois {
    /// Stop when the bracket is at most this wide (same unit as x) and `f_tol` is met.
    pub x_tol: f64,
    /// ... and the smallest `|f|` evaluated is at most this (infinite: the bracket alone
    /// decides). Where f is steep a bracket of `x_tol` can hold values of f far apart; the
    /// search then goes on until some point has `|f| <= f_tol` or the bracket is `x_floor`.
    pub f_tol: f64,
    /// Stop when the bracket is at most this wide, whatever `|f|` (same unit as x): the bound
    /// on the work where f is noisy at the level of `f_tol`.
    pub x_floor: f64,
    /// Stop after this many evaluations; the result is then the best end of the bracket.
    pub max_iter: usize,
    /// Keep each trial point at least this fraction of the bracket width away from its ends
    /// (0 for plain Illinois; a small guard bounds the work when `f` is rough).
    pub guard: f64,
}

impl Default for Illinois {
    /// `x_tol = 1e-12` (the bracket alone decides: `f_tol` infinite, `x_floor` 0), 200
    /// evaluations, no guard.
    fn default() -> Self {
        Self {
            x_tol: 1e-12,
            f_tol: f64::INFINITY,
            x_floor: 0.0,
            max_iter: 200,
            guard: 0.0,
        }
    }
}

/// The final bracket of a root search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// Lower end of the final bracket.
    pub lo: f64,
    /// Upper end of the final bracket.
    pub hi: f64,
    /// The evaluated point with the smallest `|f|` (the root itself when `f` vanished there).
    pub best: f64,
}

impl Root {
    /// The centre of the final bracket.
    pub fn midpoint(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }
}

/// A root of `f` in `[lo, hi]`, where `f_lo = f(lo)` and `f_hi = f(hi)` have opposite signs
/// (either may be infinite, for example "no bouncing at this T_vis": an infinite end makes the
/// next trial the midpoint). Errors of `f` are passed on.
///
/// # Example
/// ```
/// use numerics::roots::{illinois, Illinois};
/// // the cube root of 2
/// let f = |x: f64| Ok::<f64, ()>(x * x * x - 2.0);
/// let r = illinois(f, (1.0, -1.0), (2.0, 6.0), &Illinois::default()).unwrap();
/// assert!((r.best - 2f64.cbrt()).abs() < 1e-12);
/// ```
pub fn illinois<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    (mut lo, mut f_lo): (f64, f64),
    (mut hi, mut f_hi): (f64, f64),
    opts: &Illinois,
) -> Result<Root, E> {
    let positive_at_lo = f_lo > 0.0;
    // the values at the ends as evaluated (f_lo, f_hi are scaled by the Illinois rule)
    let (mut best, mut best_f) = if f_lo.abs() <= f_hi.abs() {
        (lo, f_lo.abs())
    } else {
        (hi, f_hi.abs())
    };
    if f_lo == 0.0 || f_hi == 0.0 {
        return Ok(Root { lo, hi, best });
    }
    let mut side = 0i8;
    for _ in 0..opts.max_iter {
        let width = hi - lo;
        // a NaN at an end (best_f NaN) leaves the bracket to decide, as before f_tol
        let f_met = best_f.is_nan() || best_f <= opts.f_tol;
        if (width <= opts.x_tol && f_met) || width <= opts.x_floor {
            break;
        }
        let secant = if f_lo.is_finite() && f_hi.is_finite() {
            (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        } else {
            0.5 * (lo + hi)
        };
        let margin = opts.guard * (hi - lo);
        let x = secant.clamp(lo + margin, hi - margin);
        let fx = f(x)?;
        if fx.abs() < best_f {
            (best, best_f) = (x, fx.abs());
        }
        if fx == 0.0 {
            return Ok(Root {
                lo: x,
                hi: x,
                best: x,
            });
        }
        if (fx > 0.0) == positive_at_lo {
            lo = x;
            f_lo = fx;
            if side == 1 {
                f_hi *= 0.5;
            }
            side = 1;
        } else {
            hi = x;
            f_hi = fx;
            if side == -1 {
                f_lo *= 0.5;
            }
            side = -1;
        }
    }
    Ok(Root { lo, hi, best })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed forms: ln 2 as the root of e^x - 2, with either sign convention, and with an
    /// infinite end (bisection steps until the end is finite).
    #[test]
    fn finds_closed_form_roots() {
        let opts = Illinois::default();
        let up = |x: f64| Ok::<f64, ()>(x.exp() - 2.0);
        let r = illinois(up, (0.0, -1.0), (1.0, 1f64.exp() - 2.0), &opts).unwrap();
        assert!((r.best - 2f64.ln()).abs() < 1e-12);
        let down = |x: f64| Ok::<f64, ()>(2.0 - x.exp());
        let r = illinois(down, (0.0, 1.0), (1.0, 2.0 - 1f64.exp()), &opts).unwrap();
        assert!((r.best - 2f64.ln()).abs() < 1e-12);
        let wall = |x: f64| {
            Ok::<f64, ()>(if x > 0.9 {
                f64::INFINITY
            } else {
                x.exp() - 2.0
            })
        };
        let r = illinois(wall, (0.0, -1.0), (1.0, f64::INFINITY), &opts).unwrap();
        assert!((r.best - 2f64.ln()).abs() < 1e-12);
        assert!(r.lo - 1e-12 <= 2f64.ln() && 2f64.ln() <= r.hi + 1e-12);
    }

    /// A steep f (e^(1e4 x) - 2, root ln 2 / 1e4): the bracket 1e-5 wide that `x_tol` asks for
    /// holds values of f 0.03 apart (a replay of the loop: the bracket 3.5e-6 wide, |f| = 0.035
    /// at its best end); with `f_tol` the search goes on until a point is within it, and
    /// `x_floor` stops it whatever |f| is.
    #[test]
    fn f_tol_goes_on_where_f_is_steep() {
        let steep = |x: f64| Ok::<f64, ()>((1e4 * x).exp() - 2.0);
        let root = 2f64.ln() / 1e4;
        let (lo, hi) = ((0.0, -1.0), (3e-4, 3f64.exp() - 2.0));
        let coarse = Illinois {
            x_tol: 1e-5,
            ..Illinois::default()
        };
        let c = illinois(steep, lo, hi, &coarse).unwrap();
        assert!(c.hi - c.lo <= 1e-5);
        assert!(
            steep(c.best).unwrap().abs() > 1e-3,
            "{}",
            steep(c.best).unwrap()
        );
        let tight = Illinois {
            f_tol: 1e-12,
            x_floor: 1e-15,
            ..coarse
        };
        let t = illinois(steep, lo, hi, &tight).unwrap();
        let at = steep(t.best).unwrap().abs();
        assert!(at <= 1e-12, "{at}");
        assert!((t.best - root).abs() < 1e-15);
        // a floor wider than the bracket f_tol needs stops the search there
        let floored = Illinois {
            x_tol: 1e-9,
            x_floor: 1e-5,
            ..tight
        };
        let f = illinois(steep, lo, hi, &floored).unwrap();
        assert!(f.hi - f.lo <= 1e-5 && f.hi - f.lo > 1e-9);
        assert!(steep(f.best).unwrap().abs() > 1e-12);
    }

    #[test]
    fn errors_pass_through() {
        let f = |x: f64| if x > 0.3 { Err("too far") } else { Ok(x - 1.0) };
        let r = illinois(f, (0.0, -1.0), (2.0, 1.0), &Illinois::default());
        assert_eq!(r, Err("too far"));
    }
}
