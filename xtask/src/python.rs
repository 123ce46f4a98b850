//! The virtual environment of the Python side of `cargo xtask test` and `cargo xtask wheel`:
//! created once under `target/venv`, with the tools and test dependencies installed into it.

use crate::test::{run, Error};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The project's virtual environment: its interpreter, and PATH with its `bin` first (as if
/// activated: maturin's build backend calls `maturin` from PATH).
pub struct Venv {
    /// Its Python interpreter.
    pub python: PathBuf,
    /// PATH with the environment's `bin` first.
    pub path: OsString,
}

/// The Python interpreter to build environments with: `$PYTHON`, else `python3`.
pub fn system_python() -> String {
    std::env::var("PYTHON").unwrap_or_else(|_| "python3".into())
}

impl Venv {
    /// The environment at `root/target/venv`, created when missing.
    pub fn open(root: &Path) -> Result<Self, Error> {
        let dir = root.join("target").join("venv");
        let python = dir.join("bin").join("python");
        if !python.is_file() {
            run(Command::new(system_python()).args(["-m", "venv"]).arg(&dir)).map_err(|e| {
                format!("{e}\nthe Python side needs CPython >= 3.9 with the venv module (Debian: apt-get install python3-venv)")
            })?;
        }
        let path = std::env::join_paths(std::iter::once(dir.join("bin")).chain(
            std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
        ))?;
        Ok(Self { python, path })
    }

    /// `python args...` in `root`, with this environment's PATH.
    pub fn command(&self, root: &Path) -> Command {
        let mut c = Command::new(&self.python);
        c.current_dir(root).env("PATH", &self.path);
        c
    }

    /// `pip install -q args...`.
    pub fn pip(&self, root: &Path, args: &[&str]) -> Result<(), Error> {
        run(self
            .command(root)
            .args(["-m", "pip", "install", "--disable-pip-version-check", "-q"])
            .args(args))
    }
}
