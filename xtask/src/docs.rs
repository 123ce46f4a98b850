//! `cargo xtask docs`: the documentation site, built into `target/site/` (open
//! `target/site/index.html`).
//!
//! 1. the package itself, its wheel on the dev profile (as `cargo xtask test` installs it), whose
//!    docstrings the API reference renders, in the test command's environment `target/venv`;
//! 2. the Rust API: `rustdoc` on each workspace crate against the test build's libraries (and
//!    the wheel's PyO3), as `cargo doc --no-deps --workspace` would with `RUSTDOCFLAGS="-D
//!    warnings"` (a broken intra-doc link fails; [`crate::rustdoc`], `cargo doc` itself where
//!    that cannot be set up), copied into `target/site/rust/`;
//! 3. `cargo build -p cli`: the `stickiness` binary, whose `--help` of every subcommand the CLI
//!    reference page is generated from at build time (so it cannot drift), and the Sphinx tools
//!    ([`DOCS_REQUIREMENTS`]);
//! 4. `sphinx-build` of `docs/site/` with warnings as errors (`-W --keep-going`), nitpicky (every
//!    cross-reference must resolve), from a fresh environment (`-E`, so that a warning of an
//!    unchanged page is never hidden by the cache);
//! 5. a check that every link of the site into the Rust API lands on a page.
//!
//! `cargo xtask test` runs steps 2-5 after the Python tests, on the wheel it has just installed,
//! with step 2 started before pytest and run alongside it ([`RustDoc`]).

use crate::python::Venv;
use crate::test::{run, Error};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The Sphinx tools of the site (installed into `target/venv`).
pub const DOCS_REQUIREMENTS: &[&str] = &[
    "sphinx>=7.2,<10",
    "furo>=2024.1",
    "myst-parser>=2",
    "myst-nb>=1.0",
    "numpydoc>=1.6",
];

/// The site's sources, relative to the workspace root.
pub const SOURCE_DIR: &str = "docs/site";

/// Where the package the API reference documents comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Package {
    /// Build the wheel (dev profile) and install it, as `cargo xtask test` does.
    Install,
    /// It is installed already (the test command has just installed its wheel).
    Installed,
}

/// `cargo doc --no-deps --workspace` with `RUSTDOCFLAGS="-D warnings"`.
fn rustdoc(root: &Path) -> Command {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.current_dir(root)
        .env("RUSTDOCFLAGS", "-D warnings")
        .args(["doc", "--no-deps", "--workspace"]);
    cmd
}

/// The Rust API's documentation building in the background (its output in
/// `target/rustdoc.log`), for `cargo xtask test` to overlap it with pytest: `rustdoc` on each
/// workspace crate against the libraries of the test build ([`crate::rustdoc`]), or, where that
/// cannot be set up or fails, `cargo doc --no-deps --workspace`, which first compiles every
/// dependency again in check mode (75-150 s of CPU on a fresh clone) and whose verdict then
/// counts (so a doc warning costs that check before it fails the build).
pub struct RustDoc {
    worker: std::thread::JoinHandle<Result<(), Error>>,
    log: PathBuf,
}

impl RustDoc {
    /// Starts it: the commands are found here, before anything else runs (the `cargo test
    /// --no-run` that names the libraries would relink a binary pytest runs, were anything out
    /// of date), and run in the background; nothing else may run cargo until
    /// [`RustDoc::wait`] (the build directory's lock would serialise them, and the fallback to
    /// `cargo doc` may take it).
    pub fn start(root: &Path) -> Result<RustDoc, Error> {
        let log = root.join("target").join("rustdoc.log");
        let file = std::fs::File::create(&log)?;
        eprintln!(
            "+ rustdoc of the workspace's crates (in the background, log: {})",
            log.display()
        );
        let commands = crate::rustdoc::commands(root, &file);
        let root = root.to_path_buf();
        let worker = std::thread::spawn(move || document(&root, &file, commands));
        Ok(RustDoc { worker, log })
    }

    /// Waits for it; an error with its log when it failed.
    pub fn wait(self) -> Result<(), Error> {
        let done = self
            .worker
            .join()
            .map_err(|_| "the rustdoc thread panicked")?;
        done.map_err(|e| {
            let log = std::fs::read_to_string(&self.log).unwrap_or_default();
            format!("{e}:\n{log}").into()
        })
    }
}

/// Documents the workspace into `target/doc` with `commands` (each with its crate's name), the
/// output of every command into `log`; with `cargo doc` where they could not be found or one
/// failed.
fn document(
    root: &Path,
    log: &std::fs::File,
    commands: Result<Vec<(String, Command)>, Error>,
) -> Result<(), Error> {
    use std::io::Write;
    let start = std::time::Instant::now();
    let quick = commands.and_then(|commands| {
        let n = commands.len();
        for (name, mut cmd) in commands {
            let one = std::time::Instant::now();
            let status = cmd
                .stdout(log.try_clone()?)
                .stderr(log.try_clone()?)
                .status()
                .map_err(|e| format!("cannot run rustdoc: {e}"))?;
            let mut out = log.try_clone()?;
            if !status.success() {
                writeln!(out, "the command: {cmd:?}")?;
                return Err(format!("rustdoc of `{name}` failed ({status})").into());
            }
            writeln!(out, "rustdoc {name}: {:.1} s", one.elapsed().as_secs_f64())?;
        }
        let mut out = log.try_clone()?;
        writeln!(
            out,
            "rustdoc: {n} crates documented against the build's libraries in {:.0} s",
            start.elapsed().as_secs_f64()
        )?;
        Ok(())
    });
    let Err(why) = quick else {
        return Ok(());
    };
    let mut out = log.try_clone()?;
    writeln!(
        out,
        "\nrustdoc on the test build's libraries: {why}\nnow cargo doc:"
    )?;
    eprintln!(
        "rustdoc against the test build's libraries: {why} (a doc warning, or libraries that \
         could not be found or do not fit together); confirming with cargo doc, which checks \
         every dependency first (log: target/rustdoc.log)"
    );
    let status = rustdoc(root)
        .stdout(log.try_clone()?)
        .stderr(log.try_clone()?)
        .status()
        .map_err(|e| format!("cannot start cargo doc: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`cargo doc --no-deps --workspace` (-D warnings) failed ({status})").into())
    }
}

/// Builds the site into `root/target/site/` and returns the path of its `index.html`; with
/// `rustdoc`, the Rust API's build started earlier is waited for instead of run here.
pub fn build(
    root: &Path,
    package: Package,
    rustdoc_started: Option<RustDoc>,
) -> Result<PathBuf, Error> {
    let start = std::time::Instant::now();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let target = root.join("target");
    let venv = Venv::open(root)?;
    // the wheel first: the Rust API's pages of the Python crate read the PyO3 its build made
    if package == Package::Install {
        let wheel = crate::wheel::build(root, "dev")?;
        let wheel_arg = wheel.to_string_lossy().into_owned();
        venv.pip(root, &["--force-reinstall", "--no-deps", &wheel_arg])?;
        venv.pip(root, &[&wheel_arg])?; // its dependencies, when missing
    }
    rustdoc_started
        .map_or_else(|| RustDoc::start(root), Ok)?
        .wait()?;
    run(Command::new(&cargo)
        .current_dir(root)
        .args(["build", "-p", "cli"]))?;
    venv.pip(root, DOCS_REQUIREMENTS)?;
    let site = target.join("site");
    run(venv
        .command(root)
        .env("STICKINESS_CLI", target.join("debug").join("stickiness"))
        .env("MPLBACKEND", "Agg")
        .args([
            "-m",
            "sphinx",
            "-b",
            "html",
            "-W",
            "--keep-going",
            "-n",
            "-E",
            "-q",
        ])
        .arg("-d")
        .arg(target.join("site-doctrees"))
        .arg(root.join(SOURCE_DIR))
        .arg(&site))?;
    let rust = site.join("rust");
    if rust.exists() {
        std::fs::remove_dir_all(&rust)?;
    }
    copy_dir(&target.join("doc"), &rust)?;
    check_rust_links(&site)?;
    let index = site.join("index.html");
    eprintln!(
        "the site is in {} ({:.0} s)",
        index.display(),
        start.elapsed().as_secs_f64()
    );
    Ok(index)
}

/// Copies the directory tree `from` to `to` (files only; `to` is created).
fn copy_dir(from: &Path, to: &Path) -> Result<(), Error> {
    std::fs::create_dir_all(to)?;
    for entry in
        std::fs::read_dir(from).map_err(|e| format!("cannot read {}: {e}", from.display()))?
    {
        let entry = entry?;
        let dest = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &dest)?;
        } else {
            std::fs::copy(entry.path(), &dest)?;
        }
    }
    Ok(())
}

/// Every `href="rust/..."` (or `../rust/...`) of the site's top-level pages names a file that
/// the copied rustdoc output holds: a renamed crate fails the build.
fn check_rust_links(site: &Path) -> Result<(), Error> {
    let mut missing = Vec::new();
    let mut found = 0;
    for entry in std::fs::read_dir(site)?.flatten() {
        let page = entry.path();
        if page.extension().is_none_or(|e| e != "html") {
            continue;
        }
        let html = std::fs::read_to_string(&page)?;
        for link in html.split("href=\"").skip(1) {
            let Some(target) = link.split('"').next() else {
                continue;
            };
            let Some(rest) = target.strip_prefix("rust/") else {
                continue;
            };
            found += 1;
            let file = rest.split('#').next().unwrap_or(rest);
            if !site.join("rust").join(file).is_file() {
                missing.push(format!("{}: {target}", page.display()));
            }
        }
    }
    if found == 0 {
        return Err("no page of the site links into the Rust API (target/site/rust/)".into());
    }
    if missing.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "links into the Rust API that land nowhere:\n  {}",
            missing.join("\n  ")
        )
        .into())
    }
}
