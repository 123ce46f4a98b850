//! # workspace-hack
//!
//! One job: make the binaries (`cli`, `xtask`, the Python extension) resolve the crates they
//! share with `cargo test --workspace` with the same features, so that every command compiles
//! each shared crate once. It holds no code; see its `Cargo.toml` for the list and the reason.
