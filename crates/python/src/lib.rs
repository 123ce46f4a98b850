//! # stickiness._core
//!
//! One job: expose the workspace to Python. This crate holds no physics; it converts numpy
//! arrays to calls of `thresholds` (which re-exports `contact`, `dynamics` and `greenwood`) and
//! back. The Python package `stickiness` (`crates/python/python/stickiness`) wraps these
//! functions: it broadcasts the arguments like numpy, turns one-element results into Python
//! floats, issues warnings and builds the result objects.
//!
//! Every vectorised function here takes flat `float64` arrays of one common length (the
//! broadcast inputs), computes the elements on all cores with the GIL released, checks for
//! Ctrl-C between chunks of elements (`parallel::map`; `parallel::map_rows` for rows of
//! floats, written straight into their columns), and returns a dict of flat arrays
//! (NaN where a value does not exist) plus the warnings of each element. Errors cross the
//! boundary through `error::Error`, one newtype mapping each kind to a Python exception: bad
//! input to `ValueError` (through `_InputError`, which carries the argument and the element so
//! that Python can name the argument's own index), solver failures to `SolverError`
//! (a `RuntimeError`), a missing material file to `FileNotFoundError`.
//!
//! All quantities are SI.

mod args;
mod error;
mod functions;
mod material;
mod parallel;
mod searches;
mod sweep;

use pyo3::prelude::*;

/// The compiled core of the `stickiness` package (see the package for the documented API).
#[pymodule]
mod _core {
    #[pymodule_export]
    use crate::error::{_InputError, SolverError};
    #[pymodule_export]
    use crate::functions::{
        collide, crack_speed, dimensionless, jkr, t_vis_law, t_vis_law_mismatch,
    };
    #[pymodule_export]
    use crate::material::Material;
    #[pymodule_export]
    use crate::searches::{fit_t_vis, v_frag, v_stick};
    #[pymodule_export]
    use crate::sweep::sweep;

    use pyo3::prelude::*;

    /// Elements (or sweep chunks) one call computes between two checks for Ctrl-C on all
    /// cores: a batch that keeps every core busy, for progress reports between batches.
    #[pyfunction]
    fn parallel_batch() -> usize {
        crate::parallel::batch()
    }

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        // the defaults and the sweep's columns, stated once in the library
        m.add("DEFAULT_RADIUS", thresholds::DEFAULT_RADIUS)?;
        m.add("DEFAULT_K", thresholds::DEFAULT_K)?;
        m.add("DEFAULT_REL_TOL", thresholds::DEFAULT_REL_TOL)?;
        m.add("T_VIS_EXPONENT", thresholds::T_VIS_EXPONENT)?;
        m.add("SWEEP_COLUMNS", thresholds::sweep::COLUMNS.to_vec())?;
        Ok(())
    }
}
