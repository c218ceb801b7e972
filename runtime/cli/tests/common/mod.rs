//! What every test file of the binary uses: running it, and reading its JSON.

// Each test file is its own crate and uses only some of these.
#![allow(dead_code)]

use std::process::{Command, Output};

/// `rinshan ARGS`, run to the end.
pub fn rinshan(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .args(args)
        .output()
        .expect("run rinshan")
}

/// The JSON a successful run printed.
pub fn json(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}
