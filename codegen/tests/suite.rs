//! The rules compiler's tests in one binary (one link for the crate instead of one per file).

mod common;
mod generated_code;
mod malformed;
mod real_specs;
mod snapshots;
mod tables;
