//! What `model`'s integration tests share: running the `model` binary, reading its JSON, and
//! the reference numbers (`reference.rs`, also included by the other crates' tests). Each test
//! file uses part of it.
#![allow(dead_code)]

pub mod reference;

use std::process::{Command, Output};

/// Runs the `model` binary of this build with `args`.
pub fn model(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .output()
        .expect("run the model binary")
}

/// The standard output of a successful run, parsed as JSON (fails with its standard error).
pub fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}
