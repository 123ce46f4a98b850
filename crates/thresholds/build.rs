//! Turns the committed master tables (`data/master_k<k>.csv`, `data/master_ends.csv`, text) into
//! their binary form (`$OUT_DIR/master.bin`), which the library embeds: at run time its arrays
//! are borrowed in place (about 0.3 ms for the end curves and one table), not parsed. The
//! reader and writer are the library's own (`src/master/format.rs`, `src/master/parse.rs`,
//! `src/master/binary.rs`, `src/bytes.rs`, `src/text.rs`).

#![allow(clippy::unwrap_used, clippy::expect_used)]

#[allow(dead_code)]
#[path = "src/bytes.rs"]
mod bytes;

#[path = "src/text.rs"]
mod text;

// the library's re-export of the reader's error type (`format::FormatError`) is not used here
#[allow(dead_code, unused_imports)]
#[path = "src/master/format.rs"]
mod format;
#[allow(dead_code)]
#[path = "src/master/parse.rs"]
mod parse;

#[allow(dead_code)]
#[path = "src/master/binary.rs"]
mod binary;

#[allow(dead_code)]
#[path = "src/restitution/format.rs"]
mod restitution;

use std::path::{Path, PathBuf};

fn main() {
    let data = Path::new("data");
    println!("cargo:rerun-if-changed=src/bytes.rs");
    println!("cargo:rerun-if-changed=src/text.rs");
    println!("cargo:rerun-if-changed=src/master/format.rs");
    println!("cargo:rerun-if-changed=src/master/parse.rs");
    println!("cargo:rerun-if-changed=src/master/binary.rs");
    println!("cargo:rerun-if-changed=src/restitution/format.rs");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=data");
    let out = Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("master.bin");
    let bytes = match read(data) {
        Ok(bytes) => bytes,
        Err(e) => {
            // the library then answers every threshold with the exact search
            println!("cargo:warning=master tables not embedded: {e}");
            Vec::new()
        }
    };
    std::fs::write(out, bytes).expect("OUT_DIR is writable");
    let out =
        Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("restitution.bin");
    // none built yet is no fault (no warning on every build): collisions are then integrated
    // (`method = "table"` falls back to the ODE, and results say so)
    let bytes = read_restitution(data).unwrap_or_default();
    std::fs::write(out, bytes).expect("OUT_DIR is writable");
}

/// The files of `data` whose names start with `prefix` and end in `.csv`, sorted.
fn files(data: &Path, prefix: &str) -> Result<Vec<PathBuf>, String> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(data)
        .map_err(|e| e.to_string())?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with(prefix) && n.ends_with(".csv"))
        })
        .collect();
    files.sort();
    Ok(files)
}

fn read_restitution(data: &Path) -> Result<Vec<u8>, String> {
    let mut tables = Vec::new();
    for p in files(data, "restitution_k")? {
        println!("cargo:rerun-if-changed={}", p.display());
        let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
        let t = restitution::parse(&text)
            .map_err(|e| format!("{}, line {}: {}", p.display(), e.line, e.problem))?;
        tables.push(t);
    }
    if tables.is_empty() {
        return Err("no data/restitution_k*.csv".into());
    }
    tables.sort_by(|a, b| a.k.total_cmp(&b.k));
    Ok(restitution::to_bytes(&tables))
}

fn read(data: &Path) -> Result<Vec<u8>, String> {
    let text = |p: &PathBuf| {
        println!("cargo:rerun-if-changed={}", p.display());
        std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))
    };
    let ends_path = data.join("master_ends.csv");
    let ends = format::parse_ends(&text(&ends_path)?)
        .map_err(|e| format!("{}, line {}: {}", ends_path.display(), e.line, e.problem))?;
    let mut tables = Vec::new();
    for p in &files(data, "master_k")? {
        let t = format::parse_table(&text(p)?)
            .map_err(|e| format!("{}, line {}: {}", p.display(), e.line, e.problem))?;
        tables.push(t);
    }
    tables.sort_by(|a, b| a.k.total_cmp(&b.k));
    Ok(binary::to_bytes(&tables, &ends))
}
