//! `cargo xtask wheel`: the Python package as one wheel per platform, for every CPython >= 3.9
//! (PyO3's stable ABI, `abi3-py39`), built by maturin and checked for manylinux compliance
//! (maturin's own auditwheel check), into `target/wheels/`.

use crate::python::Venv;
use crate::test::{run, Error};
use std::path::{Path, PathBuf};

/// The maturin the wheel is built with.
pub const MATURIN: &str = "maturin>=1.9.4,<2";

/// Builds the wheel with the cargo `profile` (`release` for distribution; the test command uses
/// `dev`, the workspace's opt-level-3 profile, to share its build) and returns its path.
pub fn build(root: &Path, profile: &str) -> Result<PathBuf, Error> {
    let venv = Venv::open(root)?;
    venv.pip(root, &[MATURIN])?;
    let out = root.join("target").join("wheels");
    if let Ok(entries) = std::fs::read_dir(&out) {
        for e in entries.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with("stickiness-") && name.ends_with(".whl") {
                std::fs::remove_file(e.path())?;
            }
        }
    }
    run(venv
        .command(root)
        .args([
            "-m",
            "maturin",
            "build",
            "--profile",
            profile,
            "--auditwheel",
            "check",
        ])
        .args(["--manifest-path", "crates/python/Cargo.toml", "--out"])
        .arg(&out))?;
    let wheel = std::fs::read_dir(&out)?
        .flatten()
        .map(|e| e.path())
        .find(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("stickiness-"))
        })
        .ok_or("maturin wrote no stickiness-*.whl")?;
    Ok(wheel)
}
