//! The inverse problem: the relaxation time that reproduces a measured V_stick (Sections 5.1-5.2).
//!
//! V_stick grows monotonically with T_vis from V_stick,JKR at T_vis -> 0, so
//! `ln V_stick(T_vis) = ln V_measured` has one root in `ln T_vis`, found by bracketing by decades
//! and the Illinois variant of regula falsi. A measured value at or below V_stick,JKR needs no
//! dissipation at all: its T_vis is 0.

use crate::stick::{sticking_thresholds, SearchOptions, V_SEARCH_LIMIT};
use crate::ThresholdsError;
use contact::Contact;
use greenwood::CrackLaw;

/// Relative tolerance of the fitted T_vis (dimensionless).
pub const T_VIS_REL_TOL: f64 = 1e-5;

/// Fitted relaxation times (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TVisFit {
    /// T_vis reproducing the measured V_stick (s); 0 if it is at or below V_stick,JKR.
    pub t_vis: f64,
    /// T_vis reproducing V_stick - dV (s); 0 if that is at or below V_stick,JKR.
    pub t_vis_min: f64,
    /// T_vis reproducing V_stick + dV (s).
    pub t_vis_max: f64,
    /// V_stick,JKR of the contact (m/s).
    pub v_stick_jkr: f64,
}

/// Relaxation time whose V_stick equals `v_target` (m/s, > 0); 0 when `v_target <= V_stick,JKR`.
pub fn t_vis_for_v_stick(
    contact: &Contact,
    law: &CrackLaw,
    v_target: f64,
    opts: &SearchOptions,
) -> Result<f64, ThresholdsError> {
    if !(v_target > 0.0 && v_target <= 0.5 * V_SEARCH_LIMIT) {
        return Err(ThresholdsError::OutOfRange {
            field: "v_stick",
            value: v_target,
            allowed: "0 < v_stick <= 5e3",
            unit: "m/s",
        });
    }
    if v_target <= contact.v_stick_jkr() {
        return Ok(0.0);
    }
    let opts = SearchOptions {
        v_max: Some(
            opts.v_max
                .unwrap_or(0.0)
                .max(2.0 * v_target)
                .min(V_SEARCH_LIMIT),
        ),
        ..*opts
    };
    // f(u) = ln V_stick(e^u) - ln v_target; "no bouncing below v_max" means V_stick > v_target.
    let f = |u: f64| -> Result<f64, ThresholdsError> {
        let th = sticking_thresholds(contact, law, u.exp(), &opts)?;
        Ok(th.v_stick.map_or(f64::INFINITY, |v| (v / v_target).ln()))
    };
    let ln10 = std::f64::consts::LN_10;
    let (mut lo, mut hi) = (-12.0 * ln10, -12.0 * ln10);
    let f0 = f(lo)?;
    let (mut f_lo, mut f_hi) = (f0, f0);
    if f0 > 0.0 {
        while f_lo > 0.0 {
            hi = lo;
            f_hi = f_lo;
            lo -= ln10;
            if lo < -20.0 * ln10 {
                return Ok(lo.exp());
            }
            f_lo = f(lo)?;
        }
    } else {
        while f_hi <= 0.0 {
            lo = hi;
            f_lo = f_hi;
            hi += ln10;
            if hi > -2.0 * ln10 {
                return Err(ThresholdsError::OutOfRange {
                    field: "v_stick",
                    value: v_target,
                    allowed: "a value reached by T_vis <= 1e-2 s",
                    unit: "m/s",
                });
            }
            f_hi = f(hi)?;
        }
    }
    // Illinois; an infinite f_hi (no bouncing) is replaced by bisection steps.
    let mut side = 0i8;
    while hi - lo > T_VIS_REL_TOL {
        let u = if f_hi.is_finite() {
            (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        } else {
            0.5 * (lo + hi)
        };
        let u = u.clamp(lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo));
        let fu = f(u)?;
        if fu == 0.0 {
            return Ok(u.exp());
        }
        if fu < 0.0 {
            lo = u;
            f_lo = fu;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = u;
            f_hi = fu;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
    }
    Ok((0.5 * (lo + hi)).exp())
}

/// T_vis for a measured `v_stick` (m/s) with uncertainty `v_stick_err` (m/s, >= 0): the central
/// value and the range `[t_vis_min, t_vis_max]` (Section 5.1: 0.04 ± 0.02 m/s for CO2 at 60 um).
pub fn fit_t_vis(
    contact: &Contact,
    law: &CrackLaw,
    v_stick: f64,
    v_stick_err: f64,
    opts: &SearchOptions,
) -> Result<TVisFit, ThresholdsError> {
    if !(v_stick > 0.0 && v_stick <= 0.5 * V_SEARCH_LIMIT) {
        return Err(ThresholdsError::OutOfRange {
            field: "v_stick",
            value: v_stick,
            allowed: "0 < v_stick <= 5e3",
            unit: "m/s",
        });
    }
    if !(v_stick_err.is_finite() && v_stick_err >= 0.0 && v_stick_err < v_stick) {
        return Err(ThresholdsError::OutOfRange {
            field: "v_stick_err",
            value: v_stick_err,
            allowed: "0 <= v_stick_err < v_stick",
            unit: "m/s",
        });
    }
    let t_vis = t_vis_for_v_stick(contact, law, v_stick, opts)?;
    let (t_vis_min, t_vis_max) = if v_stick_err == 0.0 {
        (t_vis, t_vis)
    } else {
        (
            t_vis_for_v_stick(contact, law, v_stick - v_stick_err, opts)?,
            t_vis_for_v_stick(contact, law, v_stick + v_stick_err, opts)?,
        )
    };
    Ok(TVisFit {
        t_vis,
        t_vis_min,
        t_vis_max,
        v_stick_jkr: contact.v_stick_jkr(),
    })
}
