//! Errors at the CLI edge: one line each, naming the flag, the value and the allowed range.

use contact::ContactError;
use dynamics::DynamicsError;
use greenwood::GreenwoodError;
use numerics::format::number;
use numerics::OutOfRange;
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

/// The command-line flag that sets a library input: `gamma_sv` -> `--gamma-sv`; the collision's
/// `decide_after` is set by `--t-end`.
pub fn flag_of(field: &str) -> String {
    match field {
        "decide_after" => "--t-end".into(),
        other => format!("--{}", other.replace('_', "-")),
    }
}

impl From<OutOfRange> for CliError {
    fn from(e: OutOfRange) -> Self {
        CliError::Usage(e.message_for(&flag_of(e.field)))
    }
}

impl From<thresholds::sweep::AxisError> for CliError {
    fn from(e: thresholds::sweep::AxisError) -> Self {
        CliError::Usage(e.to_string())
    }
}

impl From<thresholds::sweep::GridError> for CliError {
    fn from(e: thresholds::sweep::GridError) -> Self {
        CliError::Usage(e.message_for(&flag_of(e.field())))
    }
}

impl From<ContactError> for CliError {
    fn from(e: ContactError) -> Self {
        match e {
            ContactError::OutOfRange(o) => o.into(),
            other => CliError::Usage(other.to_string()),
        }
    }
}

impl From<GreenwoodError> for CliError {
    fn from(e: GreenwoodError) -> Self {
        match e {
            GreenwoodError::OutOfRange(o) => o.into(),
        }
    }
}

impl From<DynamicsError> for CliError {
    fn from(e: DynamicsError) -> Self {
        match e {
            DynamicsError::Contact(c) => c.into(),
            other => match other.out_of_range() {
                Some(o) => o.clone().into(),
                None => CliError::Compute(other.to_string()),
            },
        }
    }
}

impl From<ThresholdsError> for CliError {
    fn from(e: ThresholdsError) -> Self {
        match (e.out_of_range(), e) {
            (Some(o), _) => o.into(),
            (None, ThresholdsError::Dynamics(d)) => d.into(),
            (None, ThresholdsError::Axis(a)) => a.into(),
            (None, ThresholdsError::Grid(g)) => g.into(),
            (
                None,
                ThresholdsError::Unreachable {
                    v_stick,
                    t_vis_max,
                    geometry,
                },
            ) => CliError::Usage(format!(
                "--v-stick = {} m/s is not reached by any T_vis up to {} s for these grains ({}; the T_vis of a given V_stick grows roughly as R^(7/6))",
                number(v_stick),
                number(t_vis_max),
                geometry
                    .as_arguments()
                    .replace("radius2 =", "--radius2 =")
                    .replace("radius =", "--radius =")
            )),
            (None, e) => CliError::Compute(e.to_string()),
        }
    }
}
