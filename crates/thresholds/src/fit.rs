//! The inverse problem: the relaxation time that reproduces a measured V_stick (Sections 5.1-5.2).
//!
//! V_stick grows monotonically with T_vis from V_stick,JKR at T_vis -> 0, so
//! `ln V_stick(T_vis) = ln V_measured` has one root in `ln T_vis`, bracketed by steps of a decade
//! and found with the Illinois root finder of `numerics::roots`. A measured value at or below
//! V_stick,JKR is reached by no T_vis > 0 ([`ThresholdsError::BelowJkr`]).

use crate::stick::{sticking_thresholds, SearchOptions, V_SEARCH_LIMIT};
use crate::ThresholdsError;
use contact::Contact;
use greenwood::CrackLaw;
use numerics::roots::{illinois, Illinois};
use numerics::{format::number, OutOfRange};

/// Relative tolerance of the fitted T_vis (dimensionless): far below the uncertainty of any
/// measured V_stick, and 1e-5 in T_vis moves V_stick by at most ~1e-4 (d ln V/d ln T < 13).
pub const T_VIS_REL_TOL: f64 = 1e-5;
/// First T_vis tried (s): between the CO2 (1e-10 s) and JKR-like (1e-14 s) regimes of Figure 4.
const FIRST_T_VIS: f64 = 1e-12;
/// Smallest T_vis tried (s): V_stick is within 1e-6 of V_stick,JKR far above it (Figure 4).
const T_VIS_FLOOR: f64 = 1e-20;
/// Largest T_vis tried (s): beyond 1e-2 s the drag makes every grain of 10 nm - 1 cm stick.
const T_VIS_CEILING: f64 = 1e-2;
/// The bracketing steps of one decade in T_vis.
const BRACKET_STEP: f64 = std::f64::consts::LN_10;
/// Each search for the V_stick of a trial T_vis goes this far above the target (in units of
/// the target), so that "no bouncing" means "V_stick above the target".
const V_MAX_OVER_TARGET: f64 = 2.0;
/// Largest measured V_stick accepted (m/s): the searches must reach twice it.
pub const V_STICK_FIT_MAX: f64 = V_SEARCH_LIMIT / V_MAX_OVER_TARGET;

/// Fitted relaxation times (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TVisFit {
    /// T_vis reproducing the measured V_stick (s).
    pub t_vis: f64,
    /// T_vis reproducing V_stick - dV (s); 0 when V_stick - dV is at or below V_stick,JKR (every
    /// T_vis below `t_vis` is then consistent with the measurement).
    pub t_vis_min: f64,
    /// T_vis reproducing V_stick + dV (s).
    pub t_vis_max: f64,
    /// V_stick,JKR of the contact (m/s).
    pub v_stick_jkr: f64,
}

fn check_v_stick(v: f64) -> Result<(), OutOfRange> {
    if v.is_finite() && v > 0.0 && v <= V_STICK_FIT_MAX {
        Ok(())
    } else {
        Err(OutOfRange::new(
            "v_stick",
            v,
            format!("0 < v_stick <= {}", number(V_STICK_FIT_MAX)),
            "m/s",
        ))
    }
}

/// Relaxation time (s) whose V_stick equals `v_target` (m/s, above V_stick,JKR).
///
/// Each trial T_vis is searched up to `2 v_target` (or `opts.v_max` if larger), so a target above
/// the default search limit of [`sticking_thresholds`] is still found.
pub fn t_vis_for_v_stick(
    contact: &Contact,
    law: &CrackLaw,
    v_target: f64,
    opts: &SearchOptions,
) -> Result<f64, ThresholdsError> {
    check_v_stick(v_target)?;
    let v_stick_jkr = contact.v_stick_jkr();
    if v_target <= v_stick_jkr {
        return Err(ThresholdsError::BelowJkr {
            v_stick: v_target,
            v_stick_jkr,
        });
    }
    let opts = SearchOptions {
        v_max: Some(
            opts.v_max
                .unwrap_or(0.0)
                .max(V_MAX_OVER_TARGET * v_target)
                .min(V_SEARCH_LIMIT),
        ),
        ..*opts
    };
    // f(u) = ln V_stick(e^u) - ln v_target; "no bouncing below v_max" means V_stick > v_target.
    let f = |u: f64| -> Result<f64, ThresholdsError> {
        let th = sticking_thresholds(contact, law, u.exp(), &opts)?;
        Ok(th.v_stick.map_or(f64::INFINITY, |v| (v / v_target).ln()))
    };
    let (floor, ceiling) = (T_VIS_FLOOR.ln(), T_VIS_CEILING.ln());
    let mut lo = FIRST_T_VIS.ln();
    let mut f_lo = f(lo)?;
    let (mut hi, mut f_hi) = (lo, f_lo);
    if f_lo > 0.0 {
        while f_lo > 0.0 {
            (hi, f_hi) = (lo, f_lo);
            lo -= BRACKET_STEP;
            if lo < floor {
                // V_stick is within rounding of V_stick,JKR: the target is at the JKR limit
                return Ok(lo.exp());
            }
            f_lo = f(lo)?;
        }
    } else {
        while f_hi <= 0.0 {
            (lo, f_lo) = (hi, f_hi);
            hi += BRACKET_STEP;
            if hi > ceiling {
                return Err(ThresholdsError::Unreachable {
                    v_stick: v_target,
                    t_vis_max: T_VIS_CEILING,
                });
            }
            f_hi = f(hi)?;
        }
    }
    let settings = Illinois {
        x_tol: T_VIS_REL_TOL,
        // an infinite f_hi (no bouncing) makes the next trial the midpoint; the guard keeps every
        // trial 1 % inside the bracket
        guard: 0.01,
        ..Illinois::default()
    };
    Ok(illinois(f, (lo, f_lo), (hi, f_hi), &settings)?
        .midpoint()
        .exp())
}

/// T_vis for a measured `v_stick` (m/s, above V_stick,JKR) with uncertainty `v_stick_err`
/// (m/s, at least 0): the central value and the range `[t_vis_min, t_vis_max]` (Section 5.1:
/// 0.04 ± 0.02 m/s for CO2 at 60 um).
///
/// # Example
/// ```
/// use thresholds::{fit_t_vis, Contact, CrackLaw, Geometry, Material, SearchOptions};
/// // Section 5.1: V_stick = 0.04 ± 0.02 m/s for CO2 grains of 60 um needs
/// // 8.5e-11 s <= T_vis <= 1.97e-9 s
/// let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
/// let fit = fit_t_vis(&contact, &CrackLaw::new(0.01)?, 0.04, 0.02, &SearchOptions::default())?;
/// assert!(fit.t_vis_min > 8.4e-11 && fit.t_vis_min <= 8.5e-11);
/// assert!(fit.t_vis_max >= 1.97e-9 && fit.t_vis_max < 1.98e-9);
/// # Ok::<(), thresholds::ThresholdsError>(())
/// ```
pub fn fit_t_vis(
    contact: &Contact,
    law: &CrackLaw,
    v_stick: f64,
    v_stick_err: f64,
    opts: &SearchOptions,
) -> Result<TVisFit, ThresholdsError> {
    check_v_stick(v_stick)?;
    if !(v_stick_err.is_finite() && v_stick_err >= 0.0 && v_stick_err < v_stick) {
        return Err(OutOfRange::new(
            "v_stick_err",
            v_stick_err,
            "0 <= v_stick_err < v_stick",
            "m/s",
        )
        .into());
    }
    let t_vis = t_vis_for_v_stick(contact, law, v_stick, opts)?;
    let (t_vis_min, t_vis_max) = if v_stick_err == 0.0 {
        (t_vis, t_vis)
    } else {
        let low = v_stick - v_stick_err;
        let t_vis_min = if low <= contact.v_stick_jkr() {
            0.0
        } else {
            t_vis_for_v_stick(contact, law, low, opts)?
        };
        (
            t_vis_min,
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
