//! Tabulates `[alpha, J3, 1 - J3, K]` at the crack-law table's alpha nodes (they do not depend
//! on k), with the crate's own quadrature kernels (`src/quad.rs`), into `$OUT_DIR/j_nodes.rs`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

#[allow(dead_code)]
#[path = "src/quad.rs"]
mod quad;

use std::fmt::Write as _;

fn main() {
    println!("cargo:rerun-if-changed=src/quad.rs");
    println!("cargo:rerun-if-changed=build.rs");
    let n = quad::node_count();
    let mut out = String::with_capacity(n * 80);
    let _ = writeln!(out, "static J_NODES: [[f64; 4]; {n}] = [");
    for i in 0..n {
        let alpha = quad::node_alpha(i);
        let (j3, m, k) = quad::j3_complement_log_term(alpha);
        // `{:?}` prints the shortest representation that reads back to the same f64
        let _ = writeln!(out, "    [{alpha:?}, {j3:?}, {m:?}, {k:?}],");
    }
    out.push_str("];\n");
    let dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    std::fs::write(std::path::Path::new(&dir).join("j_nodes.rs"), out)
        .expect("OUT_DIR is writable");
}
