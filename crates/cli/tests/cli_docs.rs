//! The `stickiness` command lines of README.md and of the documentation site (`docs/site`) run
//! as a reader would run them, and what their comments give holds: a comment that starts with
//! a number (`stickiness v-stick --t-vis 1e-9   # 0.041376 m/s (Sec. 4.4)`) names numbers of the
//! output, each at the digits written, and so does a number after `= ` (`# bouncing, e =
//! 0.172`); numbers in parentheses are the paper's or a section, not checked here (the paper's
//! numbers are tested in `cli_foundation.rs` and the library's tests); a comment that quotes a
//! JSON member (`# "method": "table"`) names one of the output. This keeps the
//! pages true to the binary; the Python blocks are checked by `crates/python/tests/test_docs.py`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::TempDir;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace root (this crate is `crates/cli`).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

/// How a command line starts on the pages: the installed binary, or the README's run through
/// cargo.
const PREFIXES: [&str; 2] = ["stickiness ", "cargo run -q -p cli -- "];

/// README.md and every page under `docs/site`, in a fixed order.
fn pages() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().flatten().collect();
        entries.sort_by_key(|e| e.path());
        for e in entries {
            let p = e.path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "md") {
                out.push(p);
            }
        }
    }
    let mut out = vec![root().join("README.md")];
    walk(&root().join("docs/site"), &mut out);
    out
}

/// The command lines of a page's shell blocks: `(line number, arguments, comment)`.
fn command_lines(page: &Path) -> Vec<(usize, String, String)> {
    let text = std::fs::read_to_string(page).unwrap();
    let mut shell = false;
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(lang) = t.strip_prefix("```") {
            shell = !shell && matches!(lang, "sh" | "bash" | "console");
            continue;
        }
        let rest = PREFIXES.iter().find_map(|p| t.strip_prefix(p));
        if let (true, Some(rest)) = (shell, rest) {
            let (args, comment) = rest.split_once(" #").unwrap_or((rest, ""));
            out.push((n + 1, args.trim().to_string(), comment.trim().to_string()));
        }
    }
    out
}

/// The numbers of `text`: every maximal run of number characters that parses as a float.
fn numbers(text: &str) -> Vec<(f64, String)> {
    let is_num = |c: char| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+');
    text.split(|c: char| !is_num(c))
        .map(|w| w.trim_matches(|c| matches!(c, '.' | '-' | '+' | 'e' | 'E')))
        .filter(|w| w.chars().any(|c| c.is_ascii_digit()))
        .filter_map(|w| w.parse::<f64>().ok().map(|v| (v, w.to_string())))
        .collect()
}

/// The numbers a comment's own part (before any parenthesis) gives: all of them where it starts
/// with a number, else each that follows `= `.
fn stated(own: &str) -> Vec<String> {
    if own.starts_with(|c: char| c.is_ascii_digit()) {
        return numbers(own).into_iter().map(|(_, w)| w).collect();
    }
    own.split("= ")
        .skip(1)
        .filter_map(|s| numbers(s).into_iter().next().map(|(_, w)| w))
        .collect()
}

/// Whether `value` rounds to `written` at the digits written (half a unit of the last one).
fn agrees(value: f64, written: &str) -> bool {
    let want: f64 = written.parse().unwrap();
    let mantissa = written.to_lowercase();
    let mantissa = mantissa.split('e').next().unwrap();
    let digits = mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .skip_while(|&c| c == '0')
        .count()
        .max(1) as i32;
    if want == 0.0 {
        return value == 0.0;
    }
    let unit = 10f64.powi(want.abs().log10().floor() as i32 - digits + 1);
    (value - want).abs() <= 0.5 * unit * (1.0 + 1e-12)
}

#[test]
fn agrees_reads_the_digits_written() {
    assert!(agrees(0.04137623, "0.041376"));
    assert!(!agrees(0.04137723, "0.041376"));
    assert!(agrees(8.4905e-11, "8.49e-11"));
    assert!(!agrees(1.9756e-9, "1.97e-9"));
    assert!(agrees(1.9756e-9, "1.976e-9"));
}

#[test]
fn the_command_lines_of_the_pages_run_and_give_what_their_comments_say() {
    let dir = TempDir::new("docs");
    let mut ran = 0;
    for page in pages() {
        for (line, args, comment) in command_lines(&page) {
            let at = format!("{}:{line}: stickiness {args}", page.display());
            let out = Command::new(env!("CARGO_BIN_EXE_stickiness"))
                .args(args.split_whitespace())
                .current_dir(dir.join(""))
                .output()
                .expect("binary runs");
            let stdout = String::from_utf8_lossy(&out.stdout);
            assert!(
                out.status.success(),
                "{at}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            ran += 1;
            // the comment's own numbers, before any parenthesis (the paper's, a section)
            let own = comment.split('(').next().unwrap_or("");
            let given = numbers(&stdout);
            for written in stated(own) {
                assert!(
                    given.iter().any(|(v, _)| agrees(*v, &written)),
                    "{at}: no {written} in the output\n{stdout}"
                );
            }
            if let Some((key, value)) = comment
                .strip_prefix('"')
                .and_then(|c| c.split_once("\": \""))
            {
                let value = value.split('"').next().unwrap_or("");
                let member = format!("\"{key}\":\"{value}\"");
                assert!(stdout.contains(&member), "{at}: no {member} in\n{stdout}");
            }
        }
    }
    // the pages show at least the thresholds, the fit, a collision, a sweep
    assert!(ran >= 8, "only {ran} command lines found");
}
