//! # numerics
//!
//! One job: the small numerical pieces every crate of the workspace shares, so that each exists
//! once. It knows nothing of grains, cracks or collisions.
//!
//! - [`OutOfRange`] (with [`positive`]): the one "bad input" error. Every crate above wraps it
//!   with `#[from]`, so a bad argument reads the same wherever it is caught, in Rust, in the CLI
//!   (`--radius = -1.0: must be > 0 and finite (m)`) and in Python (`radius[1] = nan: ...`).
//! - [`mod@format`]: the one number format, the shortest form that reads back to the same `f64`, as
//!   JSON writes it (`0.00006`, `1e-9`, `60.0`), used by messages, reports, CSV and JSON alike.
//! - [`roots`]: the one bracketing root finder for smooth functions (Illinois), used by the
//!   crack-law inversion (`greenwood`), the end of contact inside a solver step (`dynamics`)
//!   and the relaxation-time fit (`thresholds`).
//!
//! ## Quick start
//! ```
//! use numerics::{format::number, positive, roots::{illinois, Illinois}, OutOfRange};
//! assert_eq!(number(60e-6), "0.00006");
//! let e: OutOfRange = positive("radius", -1.0, "m").unwrap_err();
//! assert_eq!(e.to_string(), "radius = -1.0: must be > 0 and finite (m)");
//! // the root of x^2 - 2 in [1, 2]
//! let r = illinois(|x: f64| Ok::<_, ()>(x * x - 2.0), (1.0, -1.0), (2.0, 2.0), &Illinois::default());
//! assert!((r.unwrap().best - 2f64.sqrt()).abs() < 1e-12);
//! ```

pub mod error;
pub mod format;
pub mod roots;

pub use error::{positive, OutOfRange};
