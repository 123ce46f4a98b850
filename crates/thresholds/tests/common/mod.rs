//! The committed master tables as text, read from `crates/thresholds/data/` (what the build
//! script embeds), for the tests that compare the embedded form or a variant with them.

#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

pub mod agree;

use std::path::PathBuf;
use thresholds::master::format::{parse_ends, parse_table, EndsData, TableData};

/// `crates/thresholds/data/`.
fn data() -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data")
}

/// Every committed table (`master_k<k>.csv`) with its path, in increasing k (the file names
/// sort so).
pub fn committed_tables() -> Vec<(PathBuf, TableData)> {
    let mut files: Vec<_> = std::fs::read_dir(data())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_str().unwrap().contains("master_k"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let t = parse_table(&std::fs::read_to_string(&p).unwrap()).unwrap();
            (p, t)
        })
        .collect()
}

/// The committed end curves and k checks (`master_ends.csv`).
pub fn committed_ends() -> EndsData {
    parse_ends(&std::fs::read_to_string(data().join("master_ends.csv")).unwrap()).unwrap()
}
