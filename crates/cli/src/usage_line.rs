//! clap's usage errors in one line, as every other bad input prints: clap's `error: ...` with
//! what it adds on the lines below (the possible values, the missing flags, a tip) appended,
//! without the usage synopsis and the pointer to `--help`.

use clap::error::ErrorKind;

/// The one line of a usage error, or `None` for help and version, which print as clap prints
/// them (a synopsis is what was asked for there).
pub fn line(e: &clap::Error) -> Option<String> {
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        return None;
    }
    let text = e.render().to_string();
    let mut out = String::new();
    let mut in_usage = false;
    for raw in text.lines() {
        let t = raw.trim();
        // the synopsis runs from "Usage:" to the next blank line
        in_usage = (in_usage && !t.is_empty()) || t.starts_with("Usage:");
        if t.is_empty() || in_usage || t.starts_with("For more information") {
            continue;
        }
        if !out.is_empty() {
            // an indented line continues the one above (values, flags); a tip or another line
            // is a clause of its own
            let continues = raw.starts_with(char::is_whitespace) && !t.starts_with("tip:");
            out.push_str(if continues { " " } else { "; " });
        }
        out.push_str(t);
    }
    Some(out)
}
