//! The Rust API's pages from the test build's own libraries.
//!
//! `cargo doc --no-deps --workspace` first compiles every dependency again in check mode, because
//! cargo does not reuse the metadata of a build for rustdoc (rust-lang/cargo#3501): on a fresh
//! clone that is about 150 s of CPU (faer and its kernels, diffsol, pyo3, clap; measured in
//! `docs/performance.md`, "Build time"), a third of a minute to a minute of the test command's
//! wall time on two cores. Nearly every library those pages need exists once `cargo test
//! --workspace` has built: [`commands`] runs `rustdoc` on each workspace crate, as `cargo doc`
//! would (the same edition, crate types, features, build-script output, workspace lints and
//! `-D warnings`), with `--extern` paths to the libraries `cargo test --workspace --no-run
//! --message-format=json` names (nothing is rebuilt after the test build; PyO3 and numpy, which
//! no test needs, as the wheel's build left them), crate by crate in dependency order so that
//! each links to the pages of the crates below it.
//!
//! Where a package was built twice (for a build script, with the build-override profile, and for
//! the crates that use it) the library a crate was compiled against is the one whose file-name
//! hash its own metadata names. Anything this module cannot resolve is an error, and
//! [`crate::docs::RustDoc`] then falls back to `cargo doc`, whose verdict counts.

use crate::test::Error;
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// What the test build made of one package: its library files (`.rlib`, `.rmeta`, a proc
/// macro's `.so`), one entry per build of it, and what its build script printed.
#[derive(Debug, Default)]
struct Built {
    libs: Vec<Vec<PathBuf>>,
    out_dir: Option<PathBuf>,
    cfgs: Vec<String>,
    env: Vec<(String, String)>,
}

/// The `rustdoc` commands that document the workspace's crates into `root/target/doc`, in
/// dependency order; runs `cargo test --workspace --no-run` (nothing to do after the test
/// build) and `cargo metadata` to find them. The libraries no test needs (PyO3 and numpy, for
/// the Python crate, whose library no test builds) are the newest in the build's `deps`
/// directory: the wheel's, built just before. (`cargo build --workspace` would name them too,
/// but it compiles them again, with another environment than maturin's, and the next wheel
/// build again after it.)
pub fn commands(root: &Path) -> Result<Vec<Command>, Error> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let built = built(&capture(Command::new(&cargo).current_dir(root).args([
        "test",
        "--workspace",
        "--no-run",
        "--message-format=json",
    ]))?)?;
    let metadata: Value =
        serde_json::from_str(&capture(Command::new(&cargo).current_dir(root).args([
            "metadata",
            "--format-version",
            "1",
        ]))?)?;
    let lints = workspace_lints(&std::fs::read_to_string(root.join("Cargo.toml"))?);
    let packages: BTreeMap<&str, &Value> = array(&metadata, "packages")?
        .iter()
        .filter_map(|p| Some((p["id"].as_str()?, p)))
        .collect();
    let nodes: BTreeMap<&str, &Value> = array(&metadata["resolve"], "nodes")?
        .iter()
        .filter_map(|n| Some((n["id"].as_str()?, n)))
        .collect();
    let deps: BTreeMap<&str, Vec<(&str, &str)>> =
        nodes.iter().map(|(&id, n)| (id, normal_deps(n))).collect();
    let members: Vec<&str> = array(&metadata, "workspace_members")?
        .iter()
        .filter_map(Value::as_str)
        .collect();
    let doc = root.join("target").join("doc");
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
        let uses_lints = std::fs::read_to_string(&manifest)
            .map(|m| inherits_lints(&m))
            .unwrap_or(false);
        let own = built.get(id);
        // the crate's own metadata (an `.rmeta`, or inside its `.rlib`): it names the builds of
        // its dependencies
        let own_rmeta = own.and_then(|b| {
            let files = || b.libs.iter().flatten();
            files()
                .find(|f| ext(f) == "rmeta")
                .or_else(|| files().find(|f| ext(f) == "rlib"))
        });
        let mut externs = Vec::new();
        for &(name, dep) in deps.get(id).map_or(&[][..], |d| &d[..]) {
            let lib = match built.get(dep).filter(|b| !b.libs.is_empty()) {
                Some(b) => pick(name, &b.libs, own_rmeta)?,
                // a library no test needs (PyO3 for the Python crate): the last build of it,
                // the wheel's
                None => newest(&deps_dir, lib_target(packages.get(dep))?)?,
            };
            externs.push(format!("{name}={}", lib.display()));
        }
        for target in array(package, "targets")? {
            let kinds = strings(&target["kind"]);
            let is_lib = kinds
                .iter()
                .any(|k| k.ends_with("lib") || k == "proc-macro");
            let is_bin = kinds.iter().any(|k| k == "bin");
            let name = text(target, "name")?;
            // `cargo doc` documents the library, and each binary not named like it
            let lib_name = array(package, "targets")?
                .iter()
                .find(|t| strings(&t["kind"]).iter().any(|k| k.ends_with("lib")))
                .and_then(|t| t["name"].as_str());
            if !(is_lib || is_bin && lib_name != Some(name)) {
                continue;
            }
            let mut cmd =
                Command::new(std::env::var("RUSTDOC").unwrap_or_else(|_| "rustdoc".into()));
            // from the root, with the source path relative to it, as cargo runs it (the pages
            // of the sources are named after that path)
            let src = PathBuf::from(text(target, "src_path")?);
            cmd.current_dir(root)
                .arg(format!("--edition={}", text(target, "edition")?));
            for t in strings(&target["crate_types"]) {
                cmd.args(["--crate-type", &t]);
            }
            let crate_name = name.replace('-', "_");
            cmd.args(["--crate-name", &crate_name])
                .arg(src.strip_prefix(root).unwrap_or(&src))
                .arg("-o")
                .arg(&doc)
                .args(["--check-cfg", "cfg(docsrs,test)"]);
            let features = nodes
                .get(id)
                .map(|n| strings(&n["features"]))
                .unwrap_or_default();
            let values: Vec<String> = features.iter().map(|f| format!("\"{f}\"")).collect();
            cmd.args([
                "--check-cfg",
                &format!("cfg(feature, values({}))", values.join(", ")),
            ]);
            for f in &features {
                cmd.args(["--cfg", &format!("feature=\"{f}\"")]);
            }
            if uses_lints {
                cmd.args(&lints);
            }
            if let Some(b) = own {
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
                .arg(format!("dependency={}", deps_dir.display()));
            for e in &externs {
                cmd.args(["--extern", e]);
            }
            if is_bin && !is_lib {
                if let (Some(lib), Some(rmeta)) = (lib_name, own_rmeta) {
                    cmd.args([
                        "--extern",
                        &format!("{}={}", lib.replace('-', "_"), rmeta.display()),
                    ]);
                }
                cmd.args([
                    "--document-private-items",
                    "-Arustdoc::private-intra-doc-links",
                ]);
            }
            cmd.args([
                "-D",
                "warnings",
                "--crate-version",
                text(package, "version")?,
            ]);
            package_env(&mut cmd, package, &manifest, &crate_name);
            commands.push(cmd);
        }
    }
    Ok(commands)
}

/// The library of package `name` to pass as `--extern`: the only one built, or, where it was
/// built twice, the one whose file-name hash (`lib<name>-<hash>.rlib`) the dependent crate's
/// metadata `own_rmeta` names (rustc records each dependency's file-name suffix there).
fn pick(
    name: &str,
    builds: &[Vec<PathBuf>],
    own_rmeta: Option<&PathBuf>,
) -> Result<PathBuf, Error> {
    // each build's library, and the hash of its file names (a workspace crate's `.rlib` is
    // also copied up without it, its `.rmeta` keeps it)
    let lib = |files: &Vec<PathBuf>| {
        let file = files
            .iter()
            .find(|f| matches!(ext(f), "rlib" | "so" | "dylib" | "dll"))?;
        Some((file.clone(), files.iter().find_map(|f| suffix(f))))
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
    package["targets"]
        .as_array()
        .into_iter()
        .flatten()
        .find(|t| {
            strings(&t["kind"])
                .iter()
                .any(|k| k.ends_with("lib") || k == "proc-macro")
        })
        .and_then(|t| t["name"].as_str())
        .map(|n| n.replace('-', "_"))
        .ok_or_else(|| format!("`{}` has no library", package["name"]).into())
}

/// The most recently written `lib<name>-<hash>.rlib` (or a proc macro's `.so`) in `deps`.
fn newest(deps: &Path, name: String) -> Result<PathBuf, Error> {
    let prefix = format!("lib{name}-");
    std::fs::read_dir(deps)?
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            let file = p.file_name().and_then(|f| f.to_str()).unwrap_or("");
            // lib<name>-<16 hexadecimal digits>.rlib: not another crate's named alike
            let hash = file.strip_prefix(&prefix).and_then(|r| r.split_once('.'));
            matches!(ext(p), "rlib" | "so")
                && hash
                    .is_some_and(|(h, _)| h.len() == 16 && h.bytes().all(|b| b.is_ascii_hexdigit()))
        })
        .filter_map(|p| Some((std::fs::metadata(&p).ok()?.modified().ok()?, p)))
        .max()
        .map(|(_, p)| p)
        .ok_or_else(|| format!("no library of `{name}` in {}", deps.display()).into())
}

/// `-<hash>` of `lib<name>-<hash>.<ext>` (cargo's 16 hexadecimal digits).
fn suffix(file: &Path) -> Option<String> {
    let stem = file.file_stem()?.to_str()?;
    let hash = &stem[stem.rfind('-')? + 1..];
    (hash.len() == 16 && hash.bytes().all(|b| b.is_ascii_hexdigit())).then(|| format!("-{hash}"))
}

fn ext(file: &Path) -> &str {
    file.extension().and_then(|e| e.to_str()).unwrap_or("")
}

/// Every package's libraries and build-script output from cargo's JSON messages.
fn built(messages: &str) -> Result<BTreeMap<String, Built>, Error> {
    let mut out: BTreeMap<String, Built> = BTreeMap::new();
    for line in messages.lines().filter(|l| l.starts_with('{')) {
        let m: Value = serde_json::from_str(line)?;
        let Some(id) = m["package_id"].as_str() else {
            continue;
        };
        match m["reason"].as_str() {
            Some("compiler-artifact") if m["profile"]["test"] == Value::Bool(false) => {
                let files: Vec<PathBuf> = strings(&m["filenames"])
                    .into_iter()
                    .map(PathBuf::from)
                    .collect();
                if files
                    .iter()
                    .any(|f| matches!(ext(f), "rlib" | "rmeta" | "so" | "dylib" | "dll"))
                {
                    out.entry(id.into()).or_default().libs.push(files);
                }
            }
            Some("build-script-executed") => {
                let b = out.entry(id.into()).or_default();
                b.out_dir = m["out_dir"].as_str().map(PathBuf::from);
                b.cfgs = strings(&m["cfgs"]);
                b.env = m["env"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .filter_map(|kv| Some((kv[0].as_str()?.into(), kv[1].as_str()?.into())))
                    .collect();
            }
            _ => {}
        }
    }
    Ok(out)
}

/// A package's normal (not dev-, not build-) dependencies: (extern crate name, package id).
fn normal_deps(node: &Value) -> Vec<(&str, &str)> {
    node["deps"]
        .as_array()
        .into_iter()
        .flatten()
        .filter(|d| {
            d["dep_kinds"]
                .as_array()
                .is_some_and(|ks| ks.iter().any(|k| k["kind"].is_null()))
        })
        .filter_map(|d| Some((d["name"].as_str()?, d["pkg"].as_str()?)))
        .collect()
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

/// The lint flags of `[workspace.lints.rust]` and `[workspace.lints.clippy]` of the root
/// manifest `toml`, as cargo passes them (`name = "level"` entries).
pub fn workspace_lints(toml: &str) -> Vec<String> {
    let mut flags = Vec::new();
    let mut tool = None;
    for line in toml.lines().map(str::trim) {
        if line.starts_with('[') {
            tool = match line {
                "[workspace.lints.rust]" => Some(""),
                "[workspace.lints.clippy]" => Some("clippy::"),
                "[workspace.lints.rustdoc]" => Some("rustdoc::"),
                _ => None,
            };
            continue;
        }
        let Some(tool) = tool else { continue };
        let Some((name, level)) = line.split_once('=') else {
            continue;
        };
        let level = level.trim().trim_matches('"');
        if matches!(level, "allow" | "warn" | "deny" | "forbid") {
            flags.push(format!("--{level}={tool}{}", name.trim()));
        }
    }
    flags
}

/// Whether a member's manifest says `[lints] workspace = true`.
pub fn inherits_lints(manifest: &str) -> bool {
    let mut lines = manifest
        .lines()
        .map(str::trim)
        .skip_while(|l| *l != "[lints]");
    lines.next().is_some()
        && lines
            .next()
            .is_some_and(|l| l.replace(' ', "") == "workspace=true")
}

/// The `CARGO_*` variables cargo sets for a crate's compilation (what `env!` may ask for).
fn package_env(cmd: &mut Command, package: &Value, manifest: &Path, crate_name: &str) {
    let field = |k: &str| package[k].as_str().unwrap_or("").to_string();
    let version = field("version");
    let mut parts = version.splitn(3, '.');
    let (major, minor, rest) = (
        parts.next().unwrap_or(""),
        parts.next().unwrap_or(""),
        parts.next().unwrap_or(""),
    );
    let (patch, pre) = rest.split_once('-').unwrap_or((rest, ""));
    let authors: Vec<String> = strings(&package["authors"]);
    cmd.env("CARGO_PKG_NAME", field("name"))
        .env("CARGO_PKG_VERSION", &version)
        .env("CARGO_PKG_VERSION_MAJOR", major)
        .env("CARGO_PKG_VERSION_MINOR", minor)
        .env("CARGO_PKG_VERSION_PATCH", patch)
        .env("CARGO_PKG_VERSION_PRE", pre)
        .env("CARGO_PKG_AUTHORS", authors.join(":"))
        .env("CARGO_PKG_DESCRIPTION", field("description"))
        .env("CARGO_PKG_HOMEPAGE", field("homepage"))
        .env("CARGO_PKG_REPOSITORY", field("repository"))
        .env("CARGO_PKG_LICENSE", field("license"))
        .env("CARGO_PKG_LICENSE_FILE", field("license_file"))
        .env("CARGO_PKG_RUST_VERSION", field("rust_version"))
        .env("CARGO_PKG_README", field("readme"))
        .env("CARGO_MANIFEST_PATH", manifest)
        .env("CARGO_MANIFEST_DIR", manifest.parent().unwrap_or(manifest))
        .env("CARGO_CRATE_NAME", crate_name)
        .env("CARGO_PRIMARY_PACKAGE", "1");
}

fn capture(cmd: &mut Command) -> Result<String, Error> {
    let out = cmd
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{cmd:?} failed ({})", out.status).into());
    }
    Ok(String::from_utf8(out.stdout)?)
}

fn array<'a>(v: &'a Value, key: &str) -> Result<&'a Vec<Value>, Error> {
    v[key]
        .as_array()
        .ok_or_else(|| format!("cargo's JSON has no `{key}` list").into())
}

fn text<'a>(v: &'a Value, key: &str) -> Result<&'a str, Error> {
    v[key]
        .as_str()
        .ok_or_else(|| format!("cargo's JSON has no `{key}`").into())
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .into_iter()
        .flatten()
        .filter_map(|s| s.as_str().map(String::from))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lints of a manifest like the workspace's, as `cargo doc -v` shows it passing them
    /// (`--warn=missing_docs`, `--deny=unsafe_code`, `--warn=clippy::unwrap_used`).
    #[test]
    fn lints_as_cargo_passes_them() {
        let toml = "[workspace.lints.rust]\nmissing_docs = \"warn\"\nunsafe_code = \"deny\"\n\n\
                    [workspace.lints.clippy]\nunwrap_used = \"warn\"\n\n[workspace.dependencies]\n\
                    serde = \"1\"\n";
        assert_eq!(
            workspace_lints(toml),
            [
                "--warn=missing_docs",
                "--deny=unsafe_code",
                "--warn=clippy::unwrap_used"
            ]
        );
        assert!(inherits_lints(
            "[package]\nname = \"a\"\n\n[lints]\nworkspace = true\n"
        ));
        assert!(!inherits_lints("[package]\nname = \"a\"\n"));
    }

    /// Of two builds of one package, the one whose hash the dependent's metadata names.
    #[test]
    fn the_build_the_metadata_names() {
        let dir = std::env::temp_dir().join(format!("xtask-pick-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_default();
        let rmeta = dir.join("libuser-0123456789abcdef.rmeta");
        std::fs::write(&rmeta, b"\0\0dep\0-bbbbbbbb22222222\0\0").unwrap_or_default();
        let builds = vec![
            vec![
                dir.join("libdep-aaaaaaaa11111111.rlib"),
                dir.join("libdep-aaaaaaaa11111111.rmeta"),
            ],
            // a workspace crate's: copied up without its hash, the `.rmeta` keeps it
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
        let dir = std::env::temp_dir().join(format!("xtask-newest-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap_or_default();
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
            newest(&dir, "pyo3".into()).ok(),
            Some(dir.join("libpyo3-00000000000000bb.rlib"))
        );
        assert!(newest(&dir, "numpy".into()).is_err());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
