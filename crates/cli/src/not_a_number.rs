//! A value that is not a number.
//!
//! clap reports `--radius abc` in three lines that name the flag but not what it takes; the
//! rest of the CLI's bad input is one line naming the flag, the value and the allowed range.
//! This gives a value that does not parse the same shape: the flag, the value, and the flag's
//! own help line (its quantity, unit and range) in the subcommand given.

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::Command;
use std::ffi::OsString;
use std::num::IntErrorKind;

/// One line for a value that does not parse (`--radius = abc: not a number; radius R1 of the
/// (first) sphere (m, > 0)`; `--jobs = 1.5: not a whole number; ...`), or `None` for any other
/// error. `argv` names the subcommand whose flag it is.
pub fn message(cmd: &Command, argv: &[OsString], e: &clap::Error) -> Option<String> {
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
    // the flag of the subcommand given (the same flag reads differently in `sweep`), else a
    // global one
    let sub = argv
        .iter()
        .skip(1)
        .filter_map(|a| a.to_str())
        .find_map(|a| cmd.find_subcommand(a));
    let help = sub
        .into_iter()
        .chain(std::iter::once(cmd))
        .flat_map(|c| c.get_arguments())
        .find(|a| a.get_long() == Some(long.as_str()))
        .and_then(|a| a.get_help().map(|h| h.to_string()))?;
    let help = help.lines().next()?.trim_end_matches('.');
    // the help line continues the sentence: its first word in lower case, unless it is an
    // acronym or a symbol (`JKR`, `T_vis`), whose second letter is not a lower-case one
    let mut chars = help.chars();
    let help = match (chars.next(), chars.next()) {
        (Some(first), Some(second))
            if first.is_ascii_uppercase() && second.is_ascii_lowercase() =>
        {
            format!("{}{}", first.to_ascii_lowercase(), &help[1..])
        }
        _ => help.to_string(),
    };
    // a count (`--jobs`) takes a whole number, and one that fits
    let int =
        std::error::Error::source(e).and_then(|s| s.downcast_ref::<std::num::ParseIntError>());
    let what = match int.map(|i| i.kind()) {
        Some(IntErrorKind::PosOverflow) => "too large",
        Some(_) => "not a whole number",
        None => "not a number",
    };
    Some(format!("--{long} = {value}: {what}; {help}"))
}
