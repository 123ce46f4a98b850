//! The inverse problem: the relaxation time that reproduces a measured V_stick (Sections 5.1-5.2).
//!
//! V_stick grows monotonically with T_vis from V_stick,JKR at T_vis -> 0, so
//! `ln V_stick(T_vis) = ln V_measured` has one root in `ln T_vis`, bracketed by steps of a decade
//! and found with the Illinois root finder of `numerics::roots`. A measured value at or below
//! V_stick,JKR is reached by no T_vis > 0 ([`ThresholdsError::BelowJkr`]). Nor is one just
//! above it: the model's own T_vis -> 0 limit of V_stick lies 1.55e-4 above V_stick,JKR (whose
//! 14.18 the paper rounds; 14.1844 from the model's potential), and a value between the two is
//! fitted with T_vis = 0, the JKR limit, with a warning ([`FitWarning::AtJkrLimit`]).

use crate::stick::{
    sticking_thresholds, SearchOptions, ThresholdMethod, DEFAULT_V_MAX_OVER_JKR, V_SEARCH_LIMIT,
};
use crate::ThresholdsError;
use contact::Contact;
use greenwood::CrackLaw;
use numerics::roots::{illinois, Illinois};
use numerics::{format::number, OutOfRange};
use std::cell::Cell;

/// How far the model's own T_vis -> 0 limit of V_stick lies above V_stick,JKR (relative):
/// 1.5496e-4 at every k of the master tables (their JKR plateau, F = 1.000155 at x = -17), as
/// sqrt(14.1844/14.18) - 1 from the potential (the paper rounds the coefficient to 14.18). For
/// the messages only: the fit finds the limit itself, as V_stick at its smallest T_vis (1e-20 s).
pub const JKR_LIMIT_EXCESS: f64 = 1.55e-4;

/// Relative tolerance of the fitted T_vis (dimensionless): the bracket in ln T_vis at most this
/// wide, far below the uncertainty of any measured V_stick. Alone it is not enough next to the
/// no-bouncing cliff, where d ln V_stick / d ln T_vis grows without bound: there a bracket of
/// 1e-5 held V_stick values up to 1.5e-3 apart (`examples/python/fit_round_trip.py`, 1985 fits
/// of random materials, sizes, k and targets of the whole domain, before 2026-11-28: V_stick at
/// the fitted T_vis off the target by more than 1e-5 at 18 %, by more than 1e-4 at 1.3 %). So
/// the fit goes on until a T_vis tried gives V_stick within the searches' `rel_tol` of the
/// target, or the bracket is 1e-9 (`T_VIS_FLOOR_TOL`; now 99.9 % within 1e-6, all within
/// 7.4e-6).
pub const T_VIS_REL_TOL: f64 = 1e-5;
/// The narrowest bracket in ln T_vis the fit goes to for a V_stick within `rel_tol` of the
/// target: across 1e-9 even d ln V / d ln T = 1000 moves V_stick by 1e-6; it bounds the work
/// where searched values of V_stick scatter by their own tolerance.
const T_VIS_FLOOR_TOL: f64 = 1e-9;
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

/// Fitted relaxation times (s), with the measurement they were fitted to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TVisFit {
    /// T_vis reproducing the measured V_stick (s); 0 when it lies at the T_vis -> 0 limit of
    /// V_stick, within 1.55e-4 above V_stick,JKR ([`FitWarning::AtJkrLimit`]).
    pub t_vis: f64,
    /// T_vis reproducing V_stick - dV (s); 0 when V_stick - dV is at or below the T_vis -> 0
    /// limit of V_stick (every T_vis below `t_vis` is then consistent with the measurement).
    pub t_vis_min: f64,
    /// T_vis reproducing V_stick + dV (s).
    pub t_vis_max: f64,
    /// V_stick,JKR of the contact (m/s).
    pub v_stick_jkr: f64,
    /// The measured V_stick (m/s).
    pub v_stick: f64,
    /// Its uncertainty dV (m/s).
    pub v_stick_err: f64,
    /// The search limit given for the fit ([`SearchOptions::v_max`], m/s), if any.
    pub v_max: Option<f64>,
    /// Which answered: [`ThresholdMethod::Table`] when the master table gave every V_stick the
    /// fit needed, else [`ThresholdMethod::Search`].
    pub method: ThresholdMethod,
}

/// A fit that is valid but should be read with care.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FitWarning {
    /// V_stick + dV lies above the default search limit of [`sticking_thresholds`]
    /// (1000 V_stick,JKR, at most 1e4 m/s): a search from the fitted T_vis finds it again only
    /// with `v_max` raised.
    AboveDefaultSearchLimit {
        /// V_stick + dV (m/s).
        v_stick: f64,
        /// The default search limit (m/s).
        limit: f64,
        /// A `v_max` (m/s) that finds it: twice it, at most 1e4 m/s.
        v_max: f64,
    },
    /// The measured V_stick lies above V_stick,JKR but at or below the model's T_vis -> 0 limit of
    /// V_stick (1.55e-4 above V_stick,JKR, whose 14.18 the paper rounds), which every T_vis > 0
    /// exceeds: `t_vis = 0`, the JKR limit.
    AtJkrLimit {
        /// The measured V_stick (m/s).
        v_stick: f64,
        /// V_stick,JKR (m/s).
        v_stick_jkr: f64,
    },
    /// V_stick - dV is at or below the T_vis -> 0 limit of V_stick (at most 1.55e-4 above
    /// V_stick,JKR), which every T_vis > 0 exceeds: `t_vis_min = 0`, the JKR limit.
    LowerEndAtJkr {
        /// V_stick - dV (m/s).
        low: f64,
        /// V_stick,JKR (m/s).
        v_stick_jkr: f64,
    },
}

impl FitWarning {
    /// The message, naming the search limit `v_max_as` as the caller spells it with its
    /// separator (`"--v-max "` in the CLI, `"v_max="` in Python).
    ///
    /// ```
    /// use thresholds::FitWarning;
    /// let w = FitWarning::AboveDefaultSearchLimit { v_stick: 20.0, limit: 16.6, v_max: 40.0 };
    /// assert!(w.message_for("--v-max ").ends_with("pass --v-max 40.0 to find it from the fitted T_vis"));
    /// ```
    pub fn message_for(&self, v_max_as: &str) -> String {
        match self {
            FitWarning::AboveDefaultSearchLimit {
                v_stick,
                limit,
                v_max,
            } => format!(
                "V_stick = {} m/s is above the default search limit of V_stick and V_frag searches (1000 V_stick,JKR = {} m/s): pass {v_max_as}{} to find it from the fitted T_vis",
                number(*v_stick),
                number(*limit),
                number(*v_max)
            ),
            FitWarning::AtJkrLimit {
                v_stick,
                v_stick_jkr,
            } => format!(
                "V_stick = {} m/s lies between V_stick,JKR = {} m/s and the T_vis -> 0 limit of V_stick, {JKR_LIMIT_EXCESS:.2e} above it (the paper's 14.18 is rounded): T_vis = 0 (the JKR limit; no T_vis > 0 gives a V_stick that low)",
                number(*v_stick),
                number(*v_stick_jkr)
            ),
            FitWarning::LowerEndAtJkr { low, v_stick_jkr } => format!(
                "V_stick - dV = {} m/s is at or below {}: t_vis_min = 0 (the JKR limit; no T_vis > 0 gives a V_stick that low)",
                numerics::format::derived(*low),
                if low <= v_stick_jkr {
                    format!("V_stick,JKR = {} m/s", number(*v_stick_jkr))
                } else {
                    format!(
                        "the T_vis -> 0 limit of V_stick, {JKR_LIMIT_EXCESS:.2e} above V_stick,JKR = {} m/s",
                        number(*v_stick_jkr)
                    )
                }
            ),
        }
    }
}

impl std::fmt::Display for FitWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message_for("v_max = "))
    }
}

impl TVisFit {
    /// The warnings of this fit ([`FitWarning`]): a V_stick + dV beyond the default search limit
    /// when no `v_max` was given, a V_stick at the T_vis -> 0 limit and a V_stick - dV at or
    /// below it.
    ///
    /// # Example
    /// ```
    /// use thresholds::{fit_t_vis, Contact, CrackLaw, FitWarning, Geometry, Material, SearchOptions};
    /// // 0.01 m/s is below V_stick,JKR = 0.0166 m/s of 60 um CO2 grains: t_vis_min = 0
    /// let c = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
    /// let fit = fit_t_vis(&c, &CrackLaw::new(0.01)?, 0.03, 0.02, &SearchOptions::default())?;
    /// assert_eq!(fit.t_vis_min, 0.0);
    /// assert!(matches!(fit.warnings()[..], [FitWarning::LowerEndAtJkr { .. }]));
    /// # Ok::<(), thresholds::ThresholdsError>(())
    /// ```
    pub fn warnings(&self) -> Vec<FitWarning> {
        let mut out = Vec::new();
        let top = self.v_stick + self.v_stick_err;
        let limit = (DEFAULT_V_MAX_OVER_JKR * self.v_stick_jkr).min(V_SEARCH_LIMIT);
        if self.v_max.is_none() && top > limit {
            out.push(FitWarning::AboveDefaultSearchLimit {
                v_stick: top,
                limit,
                v_max: (V_MAX_OVER_TARGET * top).min(V_SEARCH_LIMIT),
            });
        }
        if self.t_vis == 0.0 {
            out.push(FitWarning::AtJkrLimit {
                v_stick: self.v_stick,
                v_stick_jkr: self.v_stick_jkr,
            });
        }
        let low = self.v_stick - self.v_stick_err;
        if self.v_stick_err > 0.0 && self.t_vis_min == 0.0 {
            out.push(FitWarning::LowerEndAtJkr {
                low,
                v_stick_jkr: self.v_stick_jkr,
            });
        }
        out
    }
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

/// Relaxation time (s) whose V_stick equals `v_target` (m/s, above V_stick,JKR); 0 (the JKR
/// limit) when `v_target` lies at or below the T_vis -> 0 limit of V_stick, 1.55e-4 above
/// V_stick,JKR (no T_vis > 0 reaches it).
///
/// Each trial T_vis is searched up to `2 v_target` (or `opts.v_max` if larger), so a target above
/// the default search limit of [`sticking_thresholds`] is still found.
pub fn t_vis_for_v_stick(
    contact: &Contact,
    law: &CrackLaw,
    v_target: f64,
    opts: &SearchOptions,
) -> Result<f64, ThresholdsError> {
    solve(contact, law, v_target, opts, &Cell::new(false))
}

/// [`t_vis_for_v_stick`], setting `searched` when the exact search answered a trial.
fn solve(
    contact: &Contact,
    law: &CrackLaw,
    v_target: f64,
    opts: &SearchOptions,
    searched: &Cell<bool>,
) -> Result<f64, ThresholdsError> {
    check_v_stick(v_target)?;
    let v_stick_jkr = contact.v_stick_jkr();
    if v_target <= v_stick_jkr {
        return Err(ThresholdsError::BelowJkr {
            v_stick: v_target,
            v_stick_jkr,
            geometry: *contact.geometry(),
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
        if th.method == ThresholdMethod::Search {
            searched.set(true);
        }
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
                // V_stick at T_VIS_FLOOR is its T_vis -> 0 limit (1.55e-4 above V_stick,JKR)
                // to 1e-6 and still above the target: the target is at the JKR limit, T_vis = 0
                // (the tables and the search then give the same answer)
                return Ok(0.0);
            }
            f_lo = match f(lo) {
                Ok(v) => v,
                // below the T_vis that can be integrated (dynamics::MAX_CRACK_SPEED_NUMBER),
                // V_stick has reached its T_vis -> 0 limit, still above the target: T_vis = 0
                Err(e) if e.out_of_range().is_some_and(|o| o.field == "t_vis") => return Ok(0.0),
                Err(e) => return Err(e),
            };
        }
    } else {
        while f_hi <= 0.0 {
            (lo, f_lo) = (hi, f_hi);
            hi += BRACKET_STEP;
            if hi > ceiling {
                return Err(ThresholdsError::Unreachable {
                    v_stick: v_target,
                    t_vis_max: T_VIS_CEILING,
                    geometry: *contact.geometry(),
                });
            }
            f_hi = f(hi)?;
        }
    }
    let settings = Illinois {
        x_tol: T_VIS_REL_TOL,
        // f is ln(V_stick / v_target): V_stick at the T_vis returned within rel_tol of the target
        f_tol: opts.rel_tol,
        x_floor: T_VIS_FLOOR_TOL,
        // an infinite f_hi (no bouncing) makes the next trial the midpoint; the guard keeps every
        // trial 1 % inside the bracket
        guard: 0.01,
        ..Illinois::default()
    };
    // the T_vis tried whose V_stick came closest to the target
    Ok(illinois(f, (lo, f_lo), (hi, f_hi), &settings)?.best.exp())
}

/// T_vis for a measured `v_stick` (m/s, above V_stick,JKR) with uncertainty `v_stick_err`
/// (m/s, at least 0): the central value and the range `[t_vis_min, t_vis_max]` (Section 5.1:
/// 0.04 ± 0.02 m/s for CO2 at 60 um).
///
/// Near the JKR limit V_stick hardly depends on T_vis (CO2 at 60 um: d ln V_stick / d ln T_vis
/// is 4e-3 at T_vis = 1e-12 s, 5e-4 at 1e-13 s, 6e-5 at 1e-14 s), and the fitted T_vis is only
/// as sharp as the threshold: its relative error is the threshold's (up to 1e-5 from the
/// master tables, about 1e-7 from the search) divided by that slope. Fits of the same V_stick
/// by the tables and by the search then differ by percents to tens of percent in T_vis while
/// V_stick at either agrees with the measured one to 1e-5; an uncertainty `v_stick_err` gives
/// the range that matters. Each T_vis returned is the one tried whose V_stick came closest to
/// its target: within `opts.rel_tol` ([`SearchOptions::rel_tol`]) of it unless the bracket
/// reached 1e-9 in ln T_vis first (the usual bracket is [`T_VIS_REL_TOL`]; 1e-9 bounds the
/// work where the searched V_stick scatters by its own tolerance).
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
    // the highest target, V_stick + dV, is searched too: named as the uncertainty that took it
    // past the cap (v_stick itself was checked above)
    let top = v_stick + v_stick_err;
    if top > V_STICK_FIT_MAX {
        return Err(OutOfRange::new(
            "v_stick_err",
            v_stick_err,
            format!(
                "<= {} m/s here, so that V_stick + dV stays within {} m/s (each trial T_vis \
                 is searched up to twice its target, within the {} m/s search limit)",
                number(V_STICK_FIT_MAX - v_stick),
                number(V_STICK_FIT_MAX),
                number(V_SEARCH_LIMIT)
            ),
            "m/s",
        )
        .into());
    }
    // a given limit only raises the trials' own (twice their target): one below the highest
    // target cannot be meant
    if let Some(v_max) = opts.v_max.filter(|&v| v < top) {
        return Err(OutOfRange::new(
            "v_max",
            v_max,
            format!(
                ">= {} m/s, the highest V_stick of the fit (V_stick + dV): each trial T_vis is \
                 searched up to twice its target, or up to v_max where that is higher",
                number(top)
            ),
            "m/s",
        )
        .into());
    }
    let searched = Cell::new(opts.method == ThresholdMethod::Search);
    let t_vis = solve(contact, law, v_stick, opts, &searched)?;
    let (t_vis_min, t_vis_max) = if v_stick_err == 0.0 {
        (t_vis, t_vis)
    } else {
        let low = v_stick - v_stick_err;
        let t_vis_min = if low <= contact.v_stick_jkr() {
            0.0
        } else {
            solve(contact, law, low, opts, &searched)?
        };
        (
            t_vis_min,
            solve(contact, law, v_stick + v_stick_err, opts, &searched)?,
        )
    };
    Ok(TVisFit {
        t_vis,
        t_vis_min,
        t_vis_max,
        v_stick_jkr: contact.v_stick_jkr(),
        v_stick,
        v_stick_err,
        v_max: opts.v_max,
        method: if searched.get() {
            ThresholdMethod::Search
        } else {
            ThresholdMethod::Table
        },
    })
}
