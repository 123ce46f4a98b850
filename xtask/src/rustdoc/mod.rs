//! The Rust API's pages from the test build's own libraries.
//!
//! `cargo doc --no-deps --workspace` first compiles every dependency again in check mode, because
//! cargo does not reuse the metadata of a build for rustdoc (rust-lang/cargo#3501): on a fresh
//! clone that is 75-150 s of CPU (faer and its kernels, diffsol, PyO3, clap; measured in
//! `docs/performance.md`, "Build time"), 25-30 s of the test command's wall time on two cores.
//! Nearly every library those pages need exists once `cargo test --workspace` has built:
//! [`commands`] runs `rustdoc` on each workspace crate as `cargo doc` would (the same edition,
//! crate types, features, build-script output, workspace lints and `-D warnings`), with
//! `--extern` paths to the libraries `cargo test --workspace --no-run --message-format=json`
//! names (nothing is rebuilt after the test build; PyO3 and numpy, which no test needs, as the
//! wheel's build left them), crate by crate in dependency order so that each links to the
//! pages of the crates below it.
//!
//! Where a package was built twice (for a build script, with the build-override profile, and for
//! the crates that use it) the library a crate was compiled against is the one whose file-name
//! hash its own metadata names. Anything this module cannot resolve is an error, and
//! [`crate::docs::RustDoc`] then falls back to `cargo doc`, whose verdict counts; so does a
//! rustdoc that fails (a doc warning, or libraries that do not fit together).

mod cargo;

use crate::test::Error;
use cargo::{array, is_library, strings, text, Built};
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The `rustdoc` commands that document the workspace's crates, each with the name of the crate
/// it documents, in dependency order; runs `cargo test --workspace --no-run` (nothing to do
/// after the test build) and `cargo metadata` to find them, their standard error into `log`.
/// The libraries no test needs (PyO3 and numpy, for the Python crate, whose library no test
/// builds) are the newest in the build's `deps` directory: the wheel's, built just before
/// (`cargo build --workspace` would name them too, but it compiles them again, in another
/// environment than maturin's, and the next wheel build once more after it).
pub fn commands(root: &Path, log: &std::fs::File) -> Result<Vec<(String, Command)>, Error> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let built = cargo::built(&cargo::capture(
        Command::new(&cargo).current_dir(root).args([
            "test",
            "--workspace",
            "--no-run",
            "--message-format=json",
        ]),
        log,
    )?)?;
    let host = host_triple(log)?;
    let metadata: Value = serde_json::from_str(&cargo::capture(
        Command::new(&cargo).current_dir(root).args([
            "metadata",
            "--format-version",
            "1",
            "--filter-platform",
            &host,
        ]),
        log,
    )?)?;
    let lints = cargo::workspace_lints(&std::fs::read_to_string(root.join("Cargo.toml"))?)?;
    let packages: BTreeMap<&str, &Value> = array(&metadata, "packages")?
        .iter()
        .filter_map(|p| Some((p["id"].as_str()?, p)))
        .collect();
    let nodes: BTreeMap<&str, &Value> = array(&metadata["resolve"], "nodes")?
        .iter()
        .filter_map(|n| Some((n["id"].as_str()?, n)))
        .collect();
    let deps: BTreeMap<&str, Vec<(&str, &str)>> = nodes
        .iter()
        .map(|(&id, n)| (id, cargo::normal_deps(n)))
        .collect();
    let members: Vec<&str> = array(&metadata, "workspace_members")?
        .iter()
        .filter_map(Value::as_str)
        .collect();
    let doc = PathBuf::from(text(&metadata, "target_directory")?).join("doc");
    // where the dependencies' dependencies are found
    let deps_dir = built
        .values()
        .flat_map(|b| b.libs.iter().flatten())
        .filter_map(|f| f.parent())
        .find(|d| d.ends_with("deps"))
        .ok_or("no library of the build lies in a `deps` directory")?
        .to_path_buf();
    let mut commands = Vec::new();
    for id in dependency_order(&members, &deps) {
        let package = packages.get(id).ok_or(format!("no package {id}"))?;
        let manifest = PathBuf::from(text(package, "manifest_path")?);
        let own = built.get(id);
        // the crate's own metadata (an `.rmeta`, or inside its `.rlib`): it names the builds of
        // its dependencies
        let own_rmeta = own.and_then(|b| {
            let files = || b.libs.iter().flatten();
            files()
                .find(|f| cargo::ext(f) == "rmeta")
                .or_else(|| files().find(|f| cargo::ext(f) == "rlib"))
        });
        let mut externs = Vec::new();
        for &(name, dep) in deps.get(id).map_or(&[][..], |d| &d[..]) {
            let lib = match built.get(dep).filter(|b| !b.libs.is_empty()) {
                Some(b) => pick(name, &b.libs, own_rmeta)?,
                // a library no test needs (PyO3 for the Python crate): the last build of it,
                // the wheel's
                None => newest(&deps_dir, &lib_target(packages.get(dep))?)?,
            };
            externs.push(format!("{name}={}", lib.display()));
        }
        let krate = Crate {
            root,
            package,
            manifest: &manifest,
            enabled: nodes
                .get(id)
                .map(|n| strings(&n["features"]))
                .unwrap_or_default(),
            own,
            own_rmeta,
            externs,
            lints: if cargo::inherits_lints(&std::fs::read_to_string(&manifest)?)? {
                &lints
            } else {
                &[]
            },
            doc: &doc,
            deps_dir: &deps_dir,
        };
        let lib_name = array(package, "targets")?
            .iter()
            .find(|t| is_library(t))
            .and_then(|t| t["name"].as_str());
        for target in array(package, "targets")? {
            let lib = is_library(target);
            let bin = strings(&target["kind"]).iter().any(|k| k == "bin");
            let name = text(target, "name")?;
            // `cargo doc` documents the library, and each binary not named like it, unless
            // `doc = false` or a required feature is off
            let required = strings(&target["required-features"]);
            if !(lib || bin && lib_name != Some(name))
                || target["doc"] == Value::Bool(false)
                || !required.iter().all(|f| krate.enabled.contains(f))
            {
                continue;
            }
            let crate_name = name.replace('-', "_");
            let own_lib = if bin { lib_name } else { None };
            commands.push((
                crate_name.clone(),
                krate.command(target, &crate_name, own_lib)?,
            ));
        }
    }
    Ok(commands)
}

/// One workspace package, as [`Crate::command`] documents its targets.
struct Crate<'a> {
    root: &'a Path,
    package: &'a Value,
    manifest: &'a Path,
    /// Its features the resolve turned on.
    enabled: Vec<String>,
    own: Option<&'a Built>,
    own_rmeta: Option<&'a PathBuf>,
    /// `name=path` of each normal dependency.
    externs: Vec<String>,
    lints: &'a [String],
    doc: &'a Path,
    deps_dir: &'a Path,
}

impl Crate<'_> {
    /// The rustdoc command of `target` (a `cargo metadata` target) as crate `crate_name`; a
    /// binary also gets its package's library `own_lib`, and its private items, as cargo
    /// documents binaries.
    fn command(
        &self,
        target: &Value,
        crate_name: &str,
        own_lib: Option<&str>,
    ) -> Result<Command, Error> {
        let mut cmd = Command::new(std::env::var("RUSTDOC").unwrap_or_else(|_| "rustdoc".into()));
        // from the root, with the source path relative to it, as cargo runs it (the pages of
        // the sources are named after that path)
        let src = PathBuf::from(text(target, "src_path")?);
        cmd.current_dir(self.root)
            .arg(format!("--edition={}", text(target, "edition")?));
        let types = strings(&target["crate_types"]);
        for t in &types {
            cmd.args(["--crate-type", t]);
        }
        cmd.args(["--crate-name", crate_name])
            .arg(src.strip_prefix(self.root).unwrap_or(&src))
            .arg("-o")
            .arg(self.doc)
            .args(["--check-cfg", "cfg(docsrs,test)"]);
        // every declared feature may be named in a cfg; the enabled ones are set
        let declared: Vec<String> = self.package["features"]
            .as_object()
            .map(|f| f.keys().map(|k| format!("\"{k}\"")).collect())
            .unwrap_or_default();
        cmd.args([
            "--check-cfg",
            &format!("cfg(feature, values({}))", declared.join(", ")),
        ]);
        for f in &self.enabled {
            cmd.args(["--cfg", &format!("feature=\"{f}\"")]);
        }
        cmd.args(self.lints);
        if let Some(b) = self.own {
            for c in &b.cfgs {
                cmd.args(["--cfg", c]);
            }
            for (k, v) in &b.env {
                cmd.env(k, v);
            }
            if let Some(out) = &b.out_dir {
                cmd.env("OUT_DIR", out);
            }
        }
        cmd.arg("-L")
            .arg(format!("dependency={}", self.deps_dir.display()));
        for e in &self.externs {
            cmd.args(["--extern", e]);
        }
        if types.iter().any(|t| t == "proc-macro") {
            cmd.args(["--extern", "proc_macro"]);
        }
        if let Some(lib) = own_lib {
            let rmeta = self
                .own_rmeta
                .ok_or(format!("no library of `{lib}` for its binary {crate_name}"))?;
            cmd.args([
                "--extern",
                &format!("{}={}", lib.replace('-', "_"), rmeta.display()),
            ]);
        }
        if strings(&target["kind"]).iter().any(|k| k == "bin") {
            cmd.env("CARGO_BIN_NAME", text(target, "name")?);
            cmd.args([
                "--document-private-items",
                "-Arustdoc::private-intra-doc-links",
            ]);
        }
        cmd.args([
            "-D",
            "warnings",
            "--crate-version",
            text(self.package, "version")?,
        ]);
        cargo::package_env(&mut cmd, self.package, self.manifest, crate_name);
        Ok(cmd)
    }
}

/// The host's target triple (`rustc -vV`), whose dependencies `cargo metadata` keeps.
fn host_triple(log: &std::fs::File) -> Result<String, Error> {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let version = cargo::capture(Command::new(rustc).arg("-vV"), log)?;
    version
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .map(|h| h.trim().to_string())
        .ok_or_else(|| "rustc -vV names no host".into())
}

/// The library of package `name` to pass as `--extern`: the only one built, or, where it was
/// built twice, the one whose file-name hash (`lib<name>-<hash>.rlib`) the dependent crate's
/// metadata `own_rmeta` names (rustc records each dependency's file-name suffix there).
fn pick(
    name: &str,
    builds: &[Vec<PathBuf>],
    own_rmeta: Option<&PathBuf>,
) -> Result<PathBuf, Error> {
    // each build's library, and the hash of its file names (a workspace crate's `.rlib` may be
    // copied up without it, as `cargo build` reports it; its `.rmeta` keeps it)
    let lib = |files: &Vec<PathBuf>| {
        let file = files.iter().find(|f| cargo::is_library_file(f))?;
        Some((file.clone(), files.iter().find_map(|f| cargo::suffix(f))))
    };
    let candidates: Vec<(PathBuf, Option<String>)> = builds.iter().filter_map(lib).collect();
    match candidates.len() {
        0 => Err(format!("no library of `{name}` in the test build").into()),
        1 => Ok(candidates[0].0.clone()),
        _ => {
            let rmeta =
                own_rmeta.ok_or(format!("`{name}` was built {} times", candidates.len()))?;
            let bytes = std::fs::read(rmeta)?;
            let named: Vec<&PathBuf> = candidates
                .iter()
                .filter(|(_, s)| {
                    s.as_ref()
                        .is_some_and(|s| bytes.windows(s.len()).any(|w| w == s.as_bytes()))
                })
                .map(|(file, _)| file)
                .collect();
            match named[..] {
                [one] => Ok(one.clone()),
                _ => Err(format!(
                    "cannot tell which build of `{name}` {} uses",
                    rmeta.display()
                )
                .into()),
            }
        }
    }
}

/// The name of the library target of `package` (`-` as `_`).
fn lib_target(package: Option<&&Value>) -> Result<String, Error> {
    let package = package.ok_or("a dependency missing from cargo's metadata")?;
    array(package, "targets")?
        .iter()
        .find(|t| is_library(t))
        .and_then(|t| t["name"].as_str())
        .map(|n| n.replace('-', "_"))
        .ok_or_else(|| format!("`{}` has no library", package["name"]).into())
}

/// The most recently written `lib<name>-<hash>.rlib` (or a proc macro's `.so`) in `deps`. A
/// stale one (say, of other features, written after the wheel's, which a fresh wheel build
/// does not rewrite) or two that do not fit together make rustdoc fail, and `cargo doc` answer.
fn newest(deps: &Path, name: &str) -> Result<PathBuf, Error> {
    let prefix = format!("lib{name}-");
    std::fs::read_dir(deps)?
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            // lib<name>-<hash>.rlib: not another crate's named alike (lib<name>_ffi-...)
            let file = p.file_name().and_then(|f| f.to_str()).unwrap_or("");
            let hash = file
                .strip_prefix(&prefix)
                .and_then(|rest| rest.split_once('.'))
                .map(|(h, _)| format!("-{h}"));
            cargo::is_library_file(p) && hash.is_some() && cargo::suffix(p) == hash
        })
        .filter_map(|p| Some((std::fs::metadata(&p).ok()?.modified().ok()?, p)))
        .max()
        .map(|(_, p)| p)
        .ok_or_else(|| format!("no library of `{name}` in {}", deps.display()).into())
}

/// The workspace members ordered so that each comes after the members it depends on.
fn dependency_order<'a>(
    members: &[&'a str],
    deps: &BTreeMap<&str, Vec<(&str, &str)>>,
) -> Vec<&'a str> {
    let mut done: Vec<&str> = Vec::new();
    let set: BTreeSet<&str> = members.iter().copied().collect();
    while done.len() < members.len() {
        let before = done.len();
        for &m in members {
            let ready = deps
                .get(m)
                .into_iter()
                .flatten()
                .all(|(_, d)| !set.contains(d) || done.contains(d));
            if !done.contains(&m) && ready {
                done.push(m);
            }
        }
        if done.len() == before {
            // a cycle cannot happen among cargo packages; keep the rest as listed
            done.extend(
                members
                    .iter()
                    .filter(|m| !done.contains(m))
                    .collect::<Vec<_>>(),
            );
        }
    }
    done
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scratch directory of this test process.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("xtask-{name}-{}", std::process::id()));
        assert!(std::fs::create_dir_all(&dir).is_ok());
        dir
    }

    /// Of two builds of one package, the one whose hash the dependent's metadata names.
    #[test]
    fn the_build_the_metadata_names() {
        let dir = scratch("pick");
        let rmeta = dir.join("libuser-0123456789abcdef.rmeta");
        assert!(std::fs::write(&rmeta, b"\0\0dep\0-bbbbbbbb22222222\0\0").is_ok());
        let builds = vec![
            vec![
                dir.join("libdep-aaaaaaaa11111111.rlib"),
                dir.join("libdep-aaaaaaaa11111111.rmeta"),
            ],
            // as `cargo build` reports a workspace crate: copied up without its hash, the
            // `.rmeta` keeps it
            vec![
                dir.join("libdep.rlib"),
                dir.join("libdep-bbbbbbbb22222222.rmeta"),
            ],
        ];
        let picked = pick("dep", &builds, Some(&rmeta)).ok();
        assert_eq!(picked, Some(dir.join("libdep.rlib")));
        assert!(
            pick("dep", &builds, None).is_err(),
            "two builds, no metadata: cannot tell"
        );
        assert_eq!(
            pick("dep", &builds[..1], None).ok(),
            Some(dir.join("libdep-aaaaaaaa11111111.rlib"))
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A library no test builds: the newest `lib<name>-<hash>.rlib`, not another crate's whose
    /// name starts alike.
    #[test]
    fn the_newest_build_of_a_library() {
        let dir = scratch("newest");
        let t0 = std::time::SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1_000_000);
        for (file, age) in [
            ("libpyo3-00000000000000aa.rlib", 3),
            ("libpyo3-00000000000000bb.rlib", 2),
            ("libpyo3-00000000000000cc.rmeta", 1),
            ("libpyo3_ffi-00000000000000dd.rlib", 0),
        ] {
            let f = std::fs::File::create(dir.join(file));
            let when = t0 - std::time::Duration::from_secs(age);
            assert!(f.and_then(|f| f.set_modified(when)).is_ok());
        }
        assert_eq!(
            newest(&dir, "pyo3").ok(),
            Some(dir.join("libpyo3-00000000000000bb.rlib"))
        );
        assert!(newest(&dir, "numpy").is_err());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
