//! # thresholds
//!
//! One job: the threshold velocities that dust-growth codes need, built on collisions from
//! `dynamics` (Arakawa & Krijt 2021, Sections 4.4, 5 and 6). It re-exports the types its threshold
//! functions take (materials, geometry, contact, crack law, collider and their errors), so this
//! one dependency answers "do these grains stick?".
//!
//! ## Quick start
//! ```
//! use thresholds::{sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions};
//! // CO2 grains of R1 = 60 um, relaxation time 1e-9 s, k = 0.01 (Sections 4-5)
//! let contact = Contact::new(Material::co2(), Geometry::identical(60e-6))?;
//! let law = CrackLaw::new(0.01)?; // build once per k, share everywhere
//! let th = sticking_thresholds(&contact, &law, 1e-9, &SearchOptions::default())?;
//! let v_stick = th.v_stick.expect("bounces below the search limit"); // m/s
//! assert!((v_stick - 0.0414).abs() < 1e-4); // Section 4.4: 4.14 cm/s
//! assert!(v_stick > contact.v_stick_jkr()); // dissipation raises V_stick above JKR (1.66 cm/s)
//! // the same grain on a CO2 wall (the laboratory geometry)
//! let wall = Contact::new(Material::co2(), Geometry::wall(60e-6))?;
//! let on_wall = sticking_thresholds(&wall, &law, 1e-9, &SearchOptions::default())?;
//! assert!(on_wall.v_stick.unwrap() > v_stick);
//! # Ok::<(), thresholds::ThresholdsError>(())
//! ```
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
//! - [`stick`]: [`sticking_thresholds`] (V_stick and the onset of double collisions), its
//!   options and the rule that turns the collisions of a search into the two thresholds;
//!   [`sweep_t_vis`] chains searches over T_vis with hints from the neighbours.
//! - [`search`]: how a search chooses its impact speeds: the first bracket, secant steps on
//!   V_out for V_stick and trisection for the onset, on a ladder of solver tolerances, with
//!   rebound restarts and [`Hint`]s.
//! - [`fit`]: [`fit_t_vis`], the inverse problem.
//! - [`laws`]: [`TVisLaw`], [`v_frag`] and [`fragmentation`].
//! - [`paper`]: the measurements the paper compares with (Musiolik 2016a/b, Gundlach 2015).
//! - [`sweep`]: grids of searches in chunks that keep their hints, their axes and their rows,
//!   shared by the CLI and the Python package.
//! - [`master`]: the master tables of V_stick/V_stick,JKR over (c_D, c_a, k) ([`MasterTables`]),
//!   the default answer of [`sticking_thresholds`].
//! - [`restitution`]: the restitution tables ([`RestitutionTables`]) and
//!   [`restitution::collision`], one collision's outcome, e and V_out from the tables or else
//!   the ODE.
//! - [`k_axis`]: the k axis both kinds of table share (a k's own table, the k between tables).

pub mod bytes;
pub mod error;
pub mod fit;
pub mod k_axis;
pub mod laws;
pub mod master;
pub mod paper;
pub mod restitution;
pub mod search;
pub mod stick;
pub mod sweep;
mod text;

pub use contact::{
    elastic_from_sound_speeds, Contact, ContactError, Dimensionless, Geometry, Material, Warning,
    JKR_QUANTITIES, PRESETS, SURFACE_FORCE_RANGE, TABOR_MIN,
};
pub use dynamics::{
    collision_k, collision_poisson, Backend, Collider, Collision, DynamicsError, Method, Outcome,
    Rebound, Scales, SolverOptions, StickingCriterion, TrajectoryPoint, EPS, K_MAX, K_RANGE,
    MAX_CRACK_SPEED_NUMBER,
};
pub use error::ThresholdsError;
pub use fit::{fit_t_vis, t_vis_for_v_stick, FitWarning, TVisFit, T_VIS_REL_TOL, V_STICK_FIT_MAX};
pub use greenwood::{CrackLaw, CrackSpeed, GreenwoodError};
pub use laws::{
    fragmentation, v_frag, Fragmentation, TVisLaw, T_VIS_EXPONENT, T_VIS_LAWS, V_FRAG_FACTOR,
};
pub use master::{MasterTables, Ratios, F_TOP};
pub use numerics::OutOfRange;
pub use restitution::{RestitutionTables, TableRebound};
/// Default radius R1 (m) of the CLI and the Python package: the typical CO2 grain of Musiolik et
/// al. (2016a), [`paper::MUSIOLIK_2016A`].
pub const DEFAULT_RADIUS: f64 = paper::MUSIOLIK_2016A.radius;
/// Default modulus ratio k (dimensionless): the paper's fiducial value (Section 2.3).
pub const DEFAULT_K: f64 = 0.01;

pub use stick::{
    sticking_thresholds, sweep_t_vis, Hint, HintChain, SearchOptions, StickingThresholds,
    ThresholdMethod, DEFAULT_REL_TOL, DEFAULT_V_MAX_OVER_JKR, HINT_NEIGHBOURS, HINT_SPREAD_ONE,
    V_SEARCH_LIMIT,
};
