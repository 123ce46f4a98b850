//! A flag given where a value was expected.
//!
//! The numeric options accept values with a leading hyphen (`--radius -1e-6` reaches the range
//! check, which names the option and its allowed range), so clap takes `--radius --t-vis 1e-9`
//! as a radius of `--t-vis` and then reports the stray `1e-9`. When parsing fails, this names
//! the real mistake instead: the option whose value is missing.

use clap::error::ErrorKind;
use clap::Command;
use std::ffi::OsString;

/// The error for the first option of the invoked subcommand that takes a value but is followed
/// by another of its (or a global) long flags, or `None` when there is no such option.
pub fn flag_as_value(cmd: &mut Command, argv: &[OsString]) -> Option<clap::Error> {
    let args: Vec<&str> = argv.iter().skip(1).filter_map(|a| a.to_str()).collect();
    // built, so that the subcommand's usage line names the program
    cmd.build();
    let globals: Vec<String> = long_flags(cmd, false);
    let at = args.iter().position(|a| !a.starts_with('-'))?;
    let sub = cmd.find_subcommand_mut(args[at])?;
    let flags: Vec<String> = long_flags(sub, false);
    let takes_value = long_flags(sub, true);
    let is_flag = |a: &str| {
        let name = a
            .strip_prefix("--")
            .map(|n| n.split('=').next().unwrap_or(n));
        name.is_some_and(|n| n == "help" || flags.iter().chain(&globals).any(|f| f == n))
    };
    let message = args[at + 1..].windows(2).find_map(|w| {
        let name = w[0].strip_prefix("--")?;
        (takes_value.iter().any(|f| f == name) && is_flag(w[1])).then(|| {
            // spelt as clap's own message for a value left out at the end: '--radius <RADIUS>'
            let value = sub
                .get_arguments()
                .find(|a| a.get_long() == Some(name))
                .and_then(|a| a.get_value_names()?.first().map(|v| v.to_string()))
                .unwrap_or_else(|| name.to_uppercase().replace('-', "_"));
            format!(
                "a value is required for '--{name} <{value}>' but none was supplied (found the flag '{}')",
                w[1]
            )
        })
    })?;
    Some(sub.error(ErrorKind::InvalidValue, message))
}

/// The long names of `cmd`'s options: all of them, or only those that take a value.
fn long_flags(cmd: &Command, with_value: bool) -> Vec<String> {
    cmd.get_arguments()
        .filter(|a| !with_value || a.get_action().takes_values())
        .filter_map(|a| a.get_long().map(str::to_string))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    fn error_for(line: &str) -> Option<String> {
        let argv: Vec<OsString> = line.split_whitespace().map(OsString::from).collect();
        flag_as_value(&mut crate::Cli::command(), &argv).map(|e| e.to_string())
    }

    /// A value left out before another flag is named as missing, with the flag found instead;
    /// negative values and complete lines are left to clap and the range checks.
    #[test]
    fn a_flag_in_place_of_a_value_is_named() {
        let e = error_for("stickiness v-stick --radius --t-vis 1e-9").expect("an error");
        assert!(
            e.contains("'--radius <RADIUS>'") && e.contains("'--t-vis'"),
            "{e}"
        );
        let e = error_for("stickiness --json collide --t-vis --v-in=0.1").expect("an error");
        assert!(
            e.contains("'--t-vis <T_VIS>'") && e.contains("'--v-in=0.1'"),
            "{e}"
        );
        assert_eq!(
            error_for("stickiness v-stick --radius -1e-6 --t-vis 1e-9"),
            None
        );
        assert_eq!(
            error_for("stickiness v-stick --radius 1e-6 --t-vis 1e-9"),
            None
        );
        assert_eq!(error_for("stickiness v-stick --wall --t-vis 1e-9"), None);
    }
}
