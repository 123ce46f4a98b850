//! What cargo knows, read for [`super::commands`]: the JSON messages of a build (each
//! package's libraries and build-script output), `cargo metadata` (targets, features,
//! dependencies) and the manifests' lint tables, and the environment cargo gives a compilation.

use crate::test::Error;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Hexadecimal digits of the hash cargo appends to a library's file name,
/// `lib<name>-<hash>.rlib`.
pub const HASH_DIGITS: usize = 16;

/// What a build made of one package: its library files (`.rlib`, `.rmeta`, a proc macro's
/// `.so`), one entry per build of it (a package built for a build script and for the crates is
/// built twice), and what its build script printed.
#[derive(Debug, Default)]
pub struct Built {
    /// The files of each build of the library.
    pub libs: Vec<Vec<PathBuf>>,
    /// The build script's `OUT_DIR`.
    pub out_dir: Option<PathBuf>,
    /// Its `cargo:rustc-cfg` lines.
    pub cfgs: Vec<String>,
    /// Its `cargo:rustc-env` lines.
    pub env: Vec<(String, String)>,
}

/// Every package's libraries and build-script output from cargo's JSON `messages`. A package
/// whose build script ran twice (for two feature sets) keeps the last one's output: this
/// workspace's build scripts (greenwood's and thresholds') run once.
pub fn built(messages: &str) -> Result<BTreeMap<String, Built>, Error> {
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
                    .any(|f| is_library_file(f) || ext(f) == "rmeta")
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

/// A package's normal (not dev-, not build-) dependencies in `cargo metadata`'s resolve node:
/// (extern crate name, as renamed, and package id).
pub fn normal_deps(node: &Value) -> Vec<(&str, &str)> {
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

/// Whether a `cargo metadata` target is a library (of any crate type) or a proc macro.
pub fn is_library(target: &Value) -> bool {
    strings(&target["kind"])
        .iter()
        .any(|k| k.ends_with("lib") || k == "proc-macro")
}

/// Whether `file` is a library a crate can be compiled against (`.rlib`, or a proc macro's
/// shared object).
pub fn is_library_file(file: &Path) -> bool {
    matches!(ext(file), "rlib" | "so" | "dylib" | "dll")
}

/// `-<hash>` of `lib<name>-<hash>.<ext>`, if the name ends in cargo's hash.
pub fn suffix(file: &Path) -> Option<String> {
    let stem = file.file_stem()?.to_str()?;
    let hash = &stem[stem.rfind('-')? + 1..];
    (hash.len() == HASH_DIGITS && hash.bytes().all(|b| b.is_ascii_hexdigit()))
        .then(|| format!("-{hash}"))
}

/// The extension of `file` ("" without one).
pub fn ext(file: &Path) -> &str {
    file.extension().and_then(|e| e.to_str()).unwrap_or("")
}

/// A line of a manifest without its comment and surrounding blanks (no `#` in this workspace's
/// lint tables is inside a string).
fn bare(line: &str) -> &str {
    line.split('#').next().unwrap_or("").trim()
}

/// The lint flags of the root manifest's `[workspace.lints.rust]`, `.clippy` and `.rustdoc`
/// tables, as cargo passes them (`--warn=missing_docs`, `--deny=clippy::...`), lower priorities
/// first. Entries are `name = "level"` or `name = { level = "...", priority = n }`; anything
/// else in a lint table (or lints set another way) is an error, so that no lint is dropped
/// unseen: the caller then lets `cargo doc` read the manifest.
pub fn workspace_lints(toml: &str) -> Result<Vec<String>, Error> {
    let mut flags: Vec<(i64, String)> = Vec::new();
    let mut section = String::new();
    for line in toml.lines().map(bare).filter(|l| !l.is_empty()) {
        if line.starts_with('[') {
            section = line.to_string();
            continue;
        }
        let tool = match section.as_str() {
            "[workspace.lints.rust]" => "",
            "[workspace.lints.clippy]" => "clippy::",
            "[workspace.lints.rustdoc]" => "rustdoc::",
            s if s.starts_with("[workspace.lints") => {
                return Err(format!("cannot read the lint table {s}").into())
            }
            "[workspace]" if line.starts_with("lints") => {
                return Err(format!("cannot read the lints of `{line}`").into())
            }
            _ => continue,
        };
        let (name, value) = line
            .split_once('=')
            .ok_or_else(|| format!("cannot read the lint line `{line}`"))?;
        let (level, priority) = lint_value(value.trim())
            .ok_or_else(|| format!("cannot read the lint line `{line}`"))?;
        flags.push((priority, format!("--{level}={tool}{}", name.trim())));
    }
    flags.sort_by_key(|f| f.0);
    Ok(flags.into_iter().map(|f| f.1).collect())
}

/// `"level"` or `{ level = "level", priority = n }`: the level and the priority (0 if none).
fn lint_value(value: &str) -> Option<(&str, i64)> {
    fn level(s: &str) -> Option<&str> {
        let s = s.trim().trim_matches('"');
        matches!(s, "allow" | "warn" | "deny" | "forbid").then_some(s)
    }
    if let Some(table) = value.strip_prefix('{').and_then(|v| v.strip_suffix('}')) {
        let (mut found, mut priority) = (None, 0);
        for entry in table.split(',').filter(|e| !e.trim().is_empty()) {
            let (k, v) = entry.split_once('=')?;
            match k.trim() {
                "level" => found = Some(level(v)?),
                "priority" => priority = v.trim().parse().ok()?,
                _ => return None,
            }
        }
        return Some((found?, priority));
    }
    Some((level(value)?, 0))
}

/// Whether a member's manifest takes the workspace's lints (`[lints]` with `workspace = true`);
/// lints of its own (or written another way) are an error, as in [`workspace_lints`].
pub fn inherits_lints(manifest: &str) -> Result<bool, Error> {
    let mut inherits = false;
    let mut in_lints = false;
    for line in manifest.lines().map(bare).filter(|l| !l.is_empty()) {
        if line.starts_with('[') {
            in_lints = line == "[lints]";
            if line.starts_with("[lints.") {
                return Err(format!("cannot read the member's lint table {line}").into());
            }
            continue;
        }
        let key = line.split('=').next().unwrap_or("").trim();
        if in_lints && key == "workspace" && line.replace(' ', "") == "workspace=true" {
            inherits = true;
        } else if in_lints || key.starts_with("lints") {
            return Err(format!("cannot read the member's lints `{line}`").into());
        }
    }
    Ok(inherits)
}

/// The `CARGO_*` variables cargo sets for a crate's compilation (what `env!` may ask for).
pub fn package_env(cmd: &mut Command, package: &Value, manifest: &Path, crate_name: &str) {
    let field = |k: &str| package[k].as_str().unwrap_or("").to_string();
    let version = field("version");
    let mut parts = version.splitn(3, '.');
    let (major, minor, rest) = (
        parts.next().unwrap_or(""),
        parts.next().unwrap_or(""),
        parts.next().unwrap_or(""),
    );
    let (patch, pre) = rest.split_once('-').unwrap_or((rest, ""));
    cmd.env("CARGO_PKG_NAME", field("name"))
        .env("CARGO_PKG_VERSION", &version)
        .env("CARGO_PKG_VERSION_MAJOR", major)
        .env("CARGO_PKG_VERSION_MINOR", minor)
        .env("CARGO_PKG_VERSION_PATCH", patch)
        .env("CARGO_PKG_VERSION_PRE", pre)
        .env("CARGO_PKG_AUTHORS", strings(&package["authors"]).join(":"))
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

/// The standard output of `cmd`, its standard error into `log`; an error if it fails.
pub fn capture(cmd: &mut Command, log: &std::fs::File) -> Result<String, Error> {
    let out = cmd
        .stderr(log.try_clone()?)
        .output()
        .map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{cmd:?} failed ({})", out.status).into());
    }
    Ok(String::from_utf8(out.stdout)?)
}

/// The list `v[key]`.
pub fn array<'a>(v: &'a Value, key: &str) -> Result<&'a Vec<Value>, Error> {
    v[key]
        .as_array()
        .ok_or_else(|| format!("cargo's JSON has no `{key}` list").into())
}

/// The string `v[key]`.
pub fn text<'a>(v: &'a Value, key: &str) -> Result<&'a str, Error> {
    v[key]
        .as_str()
        .ok_or_else(|| format!("cargo's JSON has no `{key}`").into())
}

/// The strings of the list `v` (none if it is no list).
pub fn strings(v: &Value) -> Vec<String> {
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
    /// (`--warn=missing_docs`, `--deny=unsafe_code`, `--warn=clippy::unwrap_used`), a lower
    /// priority first.
    #[test]
    fn lints_as_cargo_passes_them() {
        let toml = "[workspace]\nmembers = []\n\n[workspace.lints.rust]\n\
                    missing_docs = \"warn\" # every public item\nunsafe_code = \"deny\"\n\n\
                    [workspace.lints.clippy]\nall = { level = \"warn\", priority = -1 }\n\
                    unwrap_used = \"warn\"\n\n[workspace.dependencies]\nserde = \"1\"\n";
        assert_eq!(
            workspace_lints(toml).ok(),
            Some(
                [
                    "--warn=clippy::all",
                    "--warn=missing_docs",
                    "--deny=unsafe_code",
                    "--warn=clippy::unwrap_used"
                ]
                .map(String::from)
                .to_vec()
            )
        );
        assert!(matches!(
            inherits_lints("[package]\nname = \"a\"\n\n[lints]\n# shared\nworkspace = true\n"),
            Ok(true)
        ));
        assert!(matches!(
            inherits_lints("[package]\nname = \"a\"\n"),
            Ok(false)
        ));
    }

    /// Lints written in a way these readers do not follow are errors, never dropped.
    #[test]
    fn unread_lints_are_errors() {
        for toml in [
            "[workspace.lints.rust]\nmissing_docs = { level = \"warn\", note = \"x\" }\n",
            "[workspace.lints.rust]\nmissing_docs = \"loud\"\n",
            "[workspace]\nlints.rust.missing_docs = \"warn\"\n",
            "[workspace.lints]\nrust = { missing_docs = \"warn\" }\n",
        ] {
            assert!(workspace_lints(toml).is_err(), "{toml}");
        }
        for manifest in [
            "[package]\nlints.workspace = true\n",
            "[lints.rust]\nmissing_docs = \"warn\"\n",
            "[lints]\nworkspace = true\nrust = { unsafe_code = \"deny\" }\n",
        ] {
            assert!(inherits_lints(manifest).is_err(), "{manifest}");
        }
    }
}
