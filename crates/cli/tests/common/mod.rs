//! Running the `stickiness` binary in tests.

#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use std::ffi::OsStr;
use std::process::Command;

/// Runs `stickiness` with `args`: `(exit code, stdout, stderr)`.
pub fn run<S: AsRef<OsStr>>(args: &[S]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_stickiness"))
        .args(args)
        .output()
        .expect("binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs `stickiness` with `args`, expects success and one JSON object on stdout.
pub fn json<S: AsRef<OsStr> + std::fmt::Debug>(args: &[S]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).expect("one JSON object")
}

/// Runs `stickiness` with the words of `line` as its arguments.
pub fn run_line(line: &str) -> (i32, String, String) {
    run(&line.split_whitespace().collect::<Vec<_>>())
}

/// [`json`] with the words of `line` as its arguments.
pub fn json_of(line: &str) -> serde_json::Value {
    json(&line.split_whitespace().collect::<Vec<_>>())
}

/// A fresh directory for the files of one test, unique to this process, removed when dropped.
pub struct TempDir(std::path::PathBuf);

impl TempDir {
    /// The directory `stickiness-{name}-{pid}` under the system's temporary directory.
    pub fn new(name: &str) -> Self {
        let d = std::env::temp_dir().join(format!("stickiness-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).expect("temporary directory");
        Self(d)
    }

    /// The path of `file` in the directory.
    pub fn join(&self, file: &str) -> std::path::PathBuf {
        self.0.join(file)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Each `(arguments, name)` is bad input: exit code 2, nothing on stdout, and one line on
/// stderr that names `name` (a flag, a file) and the allowed range.
pub fn assert_bad_input(cases: &[(&str, &str)]) {
    for (line, name) in cases {
        let (code, out, err) = run_line(line);
        assert_eq!(code, 2, "{line}: {err}");
        assert!(out.is_empty(), "{line}: {out}");
        assert!(
            err.contains(name) && err.contains(": must be"),
            "{line}: {err}"
        );
    }
}
