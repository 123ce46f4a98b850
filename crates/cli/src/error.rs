//! Errors at the CLI edge: one line each, naming the flag, the value and the allowed range.

use contact::ContactError;
use dynamics::DynamicsError;
use greenwood::GreenwoodError;
use std::process::ExitCode;
use thresholds::ThresholdsError;

/// A failure of a `stickiness` command.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input (exit code 2).
    #[error("{0}")]
    Usage(String),
    /// The computation failed (exit code 1).
    #[error("{0}")]
    Compute(String),
}

impl CliError {
    /// Process exit code: 2 for usage errors, 1 for failures of the computation.
    pub fn exit_code(&self) -> ExitCode {
        match self {
            CliError::Usage(_) => ExitCode::from(2),
            CliError::Compute(_) => ExitCode::from(1),
        }
    }
}

/// The command-line flag that sets a model field.
pub fn flag_of(field: &str) -> String {
    match field {
        "gamma_sv" => "--gamma-sv".into(),
        "young" => "--young".into(),
        "poisson" => "--poisson".into(),
        "density" => "--density".into(),
        "radius" => "--radius".into(),
        "t_vis" => "--t-vis".into(),
        "v_in" => "--v-in".into(),
        "v_stick" => "--v-stick".into(),
        "v_stick_err" => "--v-stick-err".into(),
        "v_max" => "--v-max".into(),
        "rel_tol" => "--rel-tol".into(),
        other => format!("--{}", other.replace('_', "-")),
    }
}

impl From<ContactError> for CliError {
    fn from(e: ContactError) -> Self {
        match e {
            ContactError::OutOfRange {
                field,
                value,
                allowed,
                unit,
            } => CliError::Usage(format!(
                "{} = {value:?} is outside the allowed range {allowed} ({unit})",
                flag_of(field)
            )),
            other => CliError::Usage(other.to_string()),
        }
    }
}

impl From<GreenwoodError> for CliError {
    fn from(e: GreenwoodError) -> Self {
        match e {
            GreenwoodError::KOutOfRange { k } => {
                CliError::Usage(format!("--k = {k:?} is outside the allowed range 0 < k < 1"))
            }
            GreenwoodError::BetaOutOfRange { beta, min, max, .. } => CliError::Usage(format!(
                "--beta = {beta:?} is outside the allowed range {min:?} < beta < {max:?} (k < beta < 1/k)"
            )),
            other => CliError::Compute(other.to_string()),
        }
    }
}

fn out_of_range(field: &str, value: f64, allowed: &str, unit: &str) -> CliError {
    CliError::Usage(format!(
        "{} = {value:?} is outside the allowed range {allowed} ({unit})",
        flag_of(field)
    ))
}

impl From<DynamicsError> for CliError {
    fn from(e: DynamicsError) -> Self {
        match e {
            DynamicsError::Contact(c) => c.into(),
            DynamicsError::Greenwood(g) => g.into(),
            DynamicsError::OutOfRange {
                field,
                value,
                allowed,
                unit,
            } => out_of_range(field, value, allowed, unit),
            other => CliError::Compute(other.to_string()),
        }
    }
}

impl From<ThresholdsError> for CliError {
    fn from(e: ThresholdsError) -> Self {
        match e {
            ThresholdsError::Dynamics(d) => d.into(),
            ThresholdsError::OutOfRange {
                field,
                value,
                allowed,
                unit,
            } => out_of_range(field, value, allowed, unit),
            other => CliError::Compute(other.to_string()),
        }
    }
}
