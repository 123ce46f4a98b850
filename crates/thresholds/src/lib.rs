//! # thresholds
//!
//! One job: the threshold velocities that dust-growth codes need, built on collisions from
//! `dynamics` (Arakawa & Krijt 2021, Sections 4.4, 5 and 6).
//!
//! ## Definitions
//! ```text
//! V_double_onset : sticking -> double collision transition in V_in                  (Sec. 4.4)
//! V_stick        : double collision -> bouncing transition in V_in                  (Sec. 4.4, 5)
//! V_stick,JKR    = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6), the T_vis -> 0 limit   (Sec. 5.1)
//! T_vis,CO2(R1)  = 1e-11 s (R1/1 um)^1.11,  T_vis,H2O(R1) = 1e-10 s (R1/1.5 um)^1.11  (Sec. 5.3)
//! V_frag         = 10 V_stick,  V_frag,JKR = 10 V_stick,JKR                           (Sec. 6)
//! ```
//! and the inverse problem: the T_vis whose V_stick equals a measured value, with the range
//! for its uncertainty (Sections 5.1-5.2).
//!
//! ## Map
//! - [`stick`]: [`sticking_thresholds`] by bracketing, regula falsi and bisection, capped at
//!   `v_max`; [`sweep_t_vis`] chains searches over T_vis with hints from the neighbours.
//! - [`fit`]: [`fit_t_vis`], the inverse problem.
//! - [`laws`]: [`TVisLaw`] and [`v_frag`].

#![warn(missing_docs)]

pub mod error;
pub mod fit;
pub mod laws;
pub mod stick;

pub use error::ThresholdsError;
pub use fit::{fit_t_vis, t_vis_for_v_stick, TVisFit};
pub use laws::{v_frag, TVisLaw, V_FRAG_FACTOR};
pub use stick::{
    sticking_thresholds, sweep_t_vis, Hint, SearchOptions, StickingThresholds, V_SEARCH_LIMIT,
};
