//! A value that is not a number.
//!
//! clap reports `--radius abc` in three lines that name the flag but not what it takes; the
//! rest of the CLI's bad input is one line naming the flag, the value and the allowed range.
//! This gives a value that does not parse the same shape: the flag, the value, and the flag's
//! own help line (its quantity, unit and range).

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::Command;

/// One line for a value that does not parse (`--radius = abc: not a number; Radius R1 of the
/// (first) sphere (m, > 0)`; `--jobs = 1.5: not a whole number; ...`), or `None` for any other
/// error.
pub fn message(cmd: &Command, e: &clap::Error) -> Option<String> {
    if e.kind() != ErrorKind::ValueValidation {
        return None;
    }
    let text = |kind| match e.get(kind)? {
        ContextValue::String(s) => Some(s.clone()),
        _ => None,
    };
    // clap names the argument as '--radius <RADIUS>'
    let arg = text(ContextKind::InvalidArg)?;
    let value = text(ContextKind::InvalidValue)?;
    let long = arg.strip_prefix("--")?.split(' ').next()?.to_string();
    // the same flag has the same help in every subcommand that takes it
    let help = std::iter::once(cmd)
        .chain(cmd.get_subcommands())
        .flat_map(|c| c.get_arguments())
        .find(|a| a.get_long() == Some(long.as_str()))
        .and_then(|a| a.get_help().map(|h| h.to_string()))?;
    let help = help.lines().next()?.trim_end_matches('.');
    // a count (`--jobs`) takes a whole number
    let whole = std::error::Error::source(e).is_some_and(|s| s.is::<std::num::ParseIntError>());
    let what = if whole { "a whole number" } else { "a number" };
    Some(format!("--{long} = {value}: not {what}; {help}"))
}
