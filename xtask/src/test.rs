//! `cargo xtask test`: every test of the project, Rust and Python, in one command on a fresh
//! machine.
//!
//! 1. `cargo test --workspace` (which also builds the `stickiness` binary) and
//!    `cargo xtask master-table --check` and `cargo xtask restitution-table --check` (a sample
//!    of the tables' values recomputed): after `cargo test` when only the Rust part runs; with
//!    steps 2-5, from the start beside all of them at a lower priority, their report printed
//!    after them in one piece;
//! 2. made in a thread while step 1 runs (most of it waits on downloads): a virtual
//!    environment under `target/venv` with the Python test dependencies, DustPy for the
//!    coupling tests (its PyPI release is a source distribution built with meson and f2py, so
//!    gfortran is installed first when missing: `apt-get`, as root; otherwise the run stops
//!    with the command to run) and the site's Sphinx tools; a failure there is printed at once
//!    and ends the run after step 1;
//! 3. the package as users install it: its wheel (`cargo xtask wheel`, here on the workspace's
//!    opt-level-3 dev profile, so that it reuses the build of step 1), installed into it;
//! 4. `pytest crates/python/tests` (with `STICKINESS_CLI` pointing at the binary of step 1 and
//!    `STICKINESS_WHEEL` at the wheel, which one test installs into a fresh environment without
//!    Rust; the tutorial notebook runs as a test), then the docstrings' examples
//!    (`--doctest-modules`);
//! 5. the documentation site (`cargo xtask docs`, [`crate::docs`]) on that wheel, with warnings
//!    as errors: a renamed function, a broken cross-reference or a broken intra-doc link fails.
//!
//! It installs what it needs itself and fails loudly on anything missing; it never skips.

use crate::python::Venv;
use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicBool, Ordering};

/// Any failure of the test run.
pub type Error = Box<dyn std::error::Error + Send + Sync>;

/// Python packages the tests need (beyond the package itself and its dependency numpy).
pub const PYTHON_TEST_REQUIREMENTS: &[&str] = &[
    crate::wheel::MATURIN,
    "numpy>=1.22",
    "pytest>=7",
    "pandas>=1.5",
    "matplotlib>=3.5",
    "mypy>=1.10",
    "dask[distributed]>=2023.1",
    "hypothesis>=6.80",
    "astropy>=5.0",
    "emcee>=3.1",
    "corner>=2.2",
    "tqdm>=4.0",
    "scipy>=1.8",
    "nbclient>=0.7",
    "nbformat>=5.7",
    "ipykernel>=6.0",
];

/// The DustPy release the coupling is tested with.
pub const DUSTPY: &str = "dustpy==1.0.9";

/// Whether a command is on PATH.
fn on_path(name: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|dir| dir.join(name).is_file()))
}

/// gfortran for DustPy's build: present, or installed with apt-get when running as root.
fn ensure_gfortran() -> Result<(), Error> {
    if on_path("gfortran") {
        return Ok(());
    }
    let root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !(root && on_path("apt-get")) {
        return Err("DustPy (tested by crates/python/tests/test_dustpy.py) is built from source and needs gfortran: run `sudo apt-get install gfortran` (or your system's package), then `cargo xtask test` again".into());
    }
    let install = || {
        Command::new("apt-get")
            .args(["install", "-y", "-q", "gfortran"])
            .env("DEBIAN_FRONTEND", "noninteractive")
            .status()
            .is_ok_and(|s| s.success())
    };
    if install() {
        return Ok(());
    }
    // a fresh machine may have no package lists yet
    run(Command::new("apt-get").args(["update", "-q"]))?;
    run(Command::new("apt-get")
        .args(["install", "-y", "-q", "gfortran"])
        .env("DEBIAN_FRONTEND", "noninteractive"))
}

/// Which parts to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Parts {
    /// `cargo test --workspace`.
    pub rust: bool,
    /// The Python package and its tests.
    pub python: bool,
}

impl Parts {
    /// What these parts run, for the closing line of `cargo xtask test`.
    pub fn described(self) -> &'static str {
        match (self.rust, self.python) {
            (true, true) => {
                "the Rust tests, the tables' checks, pytest, the docstrings' examples, the \
                 notebook and the site"
            }
            (true, false) => "the Rust tests and the tables' checks",
            (false, true) => "pytest, the docstrings' examples, the notebook and the site",
            (false, false) => "nothing",
        }
    }
}

/// Runs `cmd`, echoing it; an error naming it when it fails.
pub fn run(cmd: &mut Command) -> Result<(), Error> {
    eprintln!("+ {}", shown(cmd));
    let status = cmd
        .status()
        .map_err(|e| format!("cannot run `{}`: {e}", shown(cmd)))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`{}` failed ({status})", shown(cmd)).into())
    }
}

fn shown(cmd: &Command) -> String {
    std::iter::once(cmd.get_program())
        .chain(cmd.get_args())
        .map(|s| s.to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Runs the requested parts from the workspace `root`. The Python environment (downloads,
/// DustPy's Fortran build) is made while the Rust tests run: most of it waits on the network.
pub fn run_tests(root: &Path, parts: Parts) -> Result<(), Error> {
    // the tables' checks' report while they run beside the rest (see below), and the word to
    // abandon them when the run fails first
    let lines = std::sync::Mutex::new(Vec::new());
    let abandon = AtomicBool::new(false);
    std::thread::scope(|s| {
        let environment = parts.python.then(|| {
            s.spawn(|| {
                python_environment(root)
                    .inspect_err(|e| eprintln!("error: making the Python environment: {e}"))
            })
        });
        // with the Python part, the tables' checks run from the start beside everything else
        // (the test build, the Rust tests, the wheel, pytest, the site) at a lower priority:
        // they take the cores the others leave idle. Their report is kept in `lines`,
        // printed even if their thread panics.
        let checks = (parts.rust && parts.python)
            .then(|| s.spawn(|| table_checks_kept(root, &lines, &abandon)));
        let outcome = (|| {
            if parts.rust {
                rust_tests(root)?;
            }
            let Some(environment) = environment else {
                return if parts.rust {
                    table_checks(root, &mut |s| eprintln!("{s}"))
                } else {
                    Ok(())
                };
            };
            let venv = environment
                .join()
                .map_err(|_| "making the Python environment panicked")??;
            let wheel = install_wheel(root, &venv)?;
            python_tests(root, &venv, &wheel)
        })();
        let Some(checks) = checks else {
            return outcome;
        };
        if outcome.is_err() {
            // the run has failed: no need to wait for the checks
            abandon.store(true, Ordering::Relaxed);
        } else if !checks.is_finished() {
            eprintln!("(waiting for the tables' checks)");
        }
        let checked = checks.join();
        let kept = std::mem::take(&mut *lines.lock().unwrap_or_else(|e| e.into_inner()));
        kept.iter().for_each(|l| eprintln!("{l}"));
        let checked = checked.map_err(|_| "the tables' checks panicked")?;
        match (outcome, checked) {
            (Err(run), Err(check)) => Err(format!("{run}; and {check}").into()),
            (outcome, checked) => outcome.and(checked),
        }
    })
}

/// `cargo test --workspace`.
fn rust_tests(root: &Path) -> Result<(), Error> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    run(Command::new(&cargo)
        .current_dir(root)
        .args(["test", "--workspace"]))
}

/// The master and restitution tables' checks: a change of the model must not leave the
/// committed tables stale. Each line of their report goes to `say`.
fn table_checks(root: &Path, say: &mut dyn FnMut(String)) -> Result<(), Error> {
    say("+ cargo xtask master-table --check".into());
    crate::master_table::run_check(root, say)?;
    say("+ cargo xtask restitution-table --check".into());
    crate::restitution_table::run_check(root, say)
}

/// Priority of the tables' checks beside the rest of the run (`nice`): low enough that the
/// builds, the tests and pytest (one process, whose array calls use every core) keep the cores
/// they ask for, so that the checks take what they leave idle, and both cores once the rest is
/// done. On both cores at pytest's priority the checks had slowed pytest from 85 s alone to
/// 204 s beside them (a fresh clone, 2026-11-27); on one thread of their own at its priority
/// they ended a slow hour's run alone on one core, the other idle.
const CHECKS_NICENESS: &str = "10";

/// How often the checks' thread looks whether the run has failed elsewhere.
const CHECKS_POLL: std::time::Duration = std::time::Duration::from_millis(100);

/// [`table_checks`] beside the rest of the run: the `--check` commands of this binary, one
/// after the other, in processes of their own at [`CHECKS_NICENESS`] (with `nice` where it is
/// on PATH; at the same priority otherwise), killed when `abandon` is set (the run has failed
/// elsewhere); their report (what each printed) kept in `lines`, to be printed in one piece
/// afterwards instead of between the other steps' lines.
fn table_checks_kept(
    root: &Path,
    lines: &std::sync::Mutex<Vec<String>>,
    abandon: &AtomicBool,
) -> Result<(), Error> {
    let keep = |s: &str| {
        lines
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(s.to_owned())
    };
    let exe = std::env::current_exe()?;
    let logs = root.join("target");
    std::fs::create_dir_all(&logs)
        .map_err(|e| format!("cannot create {} for the checks' logs: {e}", logs.display()))?;
    for part in ["master-table", "restitution-table"] {
        if abandon.load(Ordering::Relaxed) {
            return Ok(());
        }
        let mut cmd = if on_path("nice") {
            let mut c = Command::new("nice");
            c.args(["-n", CHECKS_NICENESS]).arg(&exe);
            c
        } else {
            Command::new(&exe)
        };
        // the report into a file, read when the check ends (a pipe left unread would stall it
        // once full)
        let log = logs.join(format!("{part}-check.log"));
        let file = std::fs::File::create(&log)
            .map_err(|e| format!("cannot create {}: {e}", log.display()))?;
        cmd.current_dir(root)
            .args([part, "--check"])
            .stdout(file.try_clone()?)
            .stderr(file);
        keep(&format!("+ cargo xtask {part} --check"));
        let mut child = cmd
            .spawn()
            .map_err(|e| format!("cannot run `cargo xtask {part} --check`: {e}"))?;
        let status = loop {
            match child.try_wait() {
                Ok(Some(status)) => break status,
                Ok(None) => {}
                Err(e) => {
                    let _ = child.kill();
                    let _ = child.wait();
                    return Err(format!("waiting for `cargo xtask {part} --check`: {e}").into());
                }
            }
            if abandon.load(Ordering::Relaxed) {
                let _ = child.kill();
                let _ = child.wait();
                keep(&format!(
                    "(cargo xtask {part} --check abandoned: the run failed)"
                ));
                return Ok(());
            }
            std::thread::sleep(CHECKS_POLL);
        };
        std::fs::read_to_string(&log)
            .unwrap_or_default()
            .lines()
            .for_each(keep);
        if !status.success() {
            return Err(format!("`cargo xtask {part} --check` failed ({status})").into());
        }
    }
    Ok(())
}

/// The virtual environment with the test requirements, DustPy and the site's builders.
fn python_environment(root: &Path) -> Result<Venv, Error> {
    let venv = Venv::open(root)?;
    venv.pip(root, PYTHON_TEST_REQUIREMENTS)?;
    ensure_gfortran()?;
    venv.pip(root, &[DUSTPY])?;
    // the site's builders too (the docs step finds them installed)
    venv.pip(root, crate::docs::DOCS_REQUIREMENTS)?;
    Ok(venv)
}

/// The CLI (for the identity tests) and the package's wheel, installed into `venv`; the wheel.
fn install_wheel(root: &Path, venv: &Venv) -> Result<std::path::PathBuf, Error> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    // the CLI for the identity tests (already built by `cargo test`; quick otherwise)
    run(Command::new(&cargo)
        .current_dir(root)
        .args(["build", "-p", "cli"]))?;
    // the package as users install it: the wheel, built on the dev profile (opt-level 3) so
    // that it shares the build of step 1 (`cargo xtask wheel` builds the release one)
    let wheel = crate::wheel::build(root, "dev")?;
    let wheel_arg = wheel.to_string_lossy().into_owned();
    venv.pip(root, &["--force-reinstall", "--no-deps", &wheel_arg])?;
    Ok(wheel)
}

/// pytest on the installed `wheel`, the docstrings' examples and the site.
fn python_tests(root: &Path, venv: &Venv, wheel: &Path) -> Result<(), Error> {
    // the Rust API's docs build alongside pytest (rustdoc against the test build's libraries;
    // no cargo runs until the docs step)
    let rustdoc = crate::docs::RustDoc::start(root)?;
    let cli = root.join("target").join("debug").join("stickiness");
    run(venv
        .command(root)
        .env("STICKINESS_CLI", &cli)
        .env("STICKINESS_WHEEL", wheel)
        .env("MPLBACKEND", "Agg")
        .args(["-m", "pytest", "-q", "crates/python/tests"]))?;
    // the Examples of every docstring
    run(venv
        .command(&root.join("target"))
        .env("MPLBACKEND", "Agg")
        .args([
            "-m",
            "pytest",
            "-q",
            "--doctest-modules",
            "--pyargs",
            "stickiness",
        ]))?;
    crate::docs::build(root, crate::docs::Package::Installed, Some(rustdoc))?;
    Ok(())
}
