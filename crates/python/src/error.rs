//! The one error newtype of the bindings: each kind of failure maps to one Python exception.
//!
//! The orphan rule forbids `impl From<ThresholdsError> for PyErr` here, so failures pass through
//! [`Error`], whose `From<Error> for PyErr` is the single place where kinds meet exceptions.

use pyo3::create_exception;
use pyo3::exceptions::{PyFileNotFoundError, PyRuntimeError, PyValueError};
use pyo3::prelude::PyAnyMethods;
use pyo3::PyErr;
use thresholds::{ContactError, DynamicsError, OutOfRange, ThresholdsError};

create_exception!(
    stickiness,
    SolverError,
    PyRuntimeError,
    "A computation failed (the ODE solver, or no outcome within the step budget); the message names the parameters and the state where it stopped."
);

create_exception!(
    stickiness._core,
    _InputError,
    PyValueError,
    "Bad input at one element: a ValueError whose message names the argument and its range. Its attributes `field` (the argument), `index` (the flat index into the broadcast arrays) and `rest` (the message after the argument's name) let the package name the argument's own index."
);

/// A failure on its way to Python.
#[derive(Debug)]
pub enum Error {
    /// An input outside its range, at element `index` of the broadcast arrays.
    Input {
        /// The input and its range.
        bad: OutOfRange,
        /// Flat index into the broadcast arrays.
        index: usize,
    },
    /// The computation failed (message names the parameters).
    Solver(String),
    /// A material file that does not exist.
    FileNotFound(String),
    /// Any other bad input (an unreadable material file, an unknown law), as `ValueError`.
    Value(String),
}

impl Error {
    /// Classifies a failure of the workspace at element `index`.
    pub fn from_thresholds(e: ThresholdsError, index: usize) -> Self {
        if let Some(bad) = e.out_of_range() {
            return Error::Input { bad, index };
        }
        match e {
            ThresholdsError::Dynamics(DynamicsError::Contact(c)) => Self::from_contact(c, index),
            ThresholdsError::Unreachable { .. }
            | ThresholdsError::Axis(_)
            | ThresholdsError::Grid(_) => Error::Value(e.to_string()),
            other => Error::Solver(other.to_string()),
        }
    }

    /// Classifies a failure of a material or a contact at element `index`.
    pub fn from_contact(e: ContactError, index: usize) -> Self {
        match e {
            ContactError::OutOfRange(bad) => Error::Input { bad, index },
            ContactError::MaterialFileNotFound { .. } => Error::FileNotFound(e.to_string()),
            other => Error::Value(other.to_string()),
        }
    }
}

impl From<Error> for PyErr {
    fn from(e: Error) -> PyErr {
        match e {
            Error::Input { bad, index } => pyo3::Python::attach(|py| {
                let err = _InputError::new_err(bad.to_string());
                let value = err.value(py);
                // (the message alone still names the argument if an attribute cannot be set)
                let _ = value.setattr("field", bad.field);
                let _ = value.setattr("index", index);
                let _ = value.setattr("rest", bad.message_for(""));
                err
            }),
            Error::Solver(m) => SolverError::new_err(m),
            Error::FileNotFound(m) => PyFileNotFoundError::new_err(m),
            Error::Value(m) => PyValueError::new_err(m),
        }
    }
}

/// A `ValueError` with the message of an input out of range (no index: a scalar argument).
pub fn value_error(bad: &OutOfRange) -> PyErr {
    PyValueError::new_err(bad.to_string())
}
