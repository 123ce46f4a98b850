//! The binaries resolve every shared crate with the features the test build uses, so that
//! `cargo xtask figures`, `cargo test --workspace`, `cargo run -p cli` and the Python build
//! compile each shared crate once (docs/performance.md, "Build time"). A new dev-dependency or
//! binary dependency that turns on another feature fails this test; the fix is a line in
//! crates/workspace-hack/Cargo.toml (and the root Cargo.toml's version of that crate).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;
use std::process::Command;

/// `package@version -> features` of the normal and build dependencies of a selection.
fn features(selection: &[&str], edges: &str) -> BTreeMap<String, String> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = Command::new(cargo)
        .args([
            "tree", "--locked", "--prefix", "none", "-f", "{p}|{f}", "-e", edges,
        ])
        .args(selection)
        .current_dir(xtask::workspace_root())
        .output()
        .expect("cargo tree runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let (p, f) = l.trim_end_matches(" (*)").split_once('|')?;
            // "name v1.2.3 (path)" -> "name v1.2.3"
            let key: Vec<&str> = p.split_whitespace().take(2).collect();
            Some((key.join(" "), f.to_string()))
        })
        .collect()
}

#[test]
fn binaries_build_shared_crates_as_the_tests_do() {
    let workspace = features(&["--workspace"], "normal,build,dev");
    for package in ["xtask", "cli", "stickiness-python"] {
        let own = features(&["-p", package], "normal,build");
        let differ: Vec<String> = own
            .iter()
            .filter(|(p, _)| !p.starts_with("xtask") && !p.starts_with("cli "))
            .filter(|(p, _)| !p.starts_with("workspace-hack"))
            .filter_map(|(p, f)| {
                let w = workspace.get(p)?;
                (w != f).then(|| format!("{p}: {f:?} here, {w:?} in the test build"))
            })
            .collect();
        assert!(
            differ.is_empty(),
            "-p {package} resolves shared crates with other features than `cargo test --workspace`:\n{}",
            differ.join("\n")
        );
    }
}
