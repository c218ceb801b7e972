//! rinshan-codegen: `rules/` -> spec model -> checker -> emitters, plus the suit tables.
//!
//! Stages, each in its own module (the way naga splits front end, IR, validator and back ends):
//! * `diag`     — errors with file:line:col
//! * `model`    — the typed spec model (serde)
//! * `expr`     — the yaku condition language: parser and type checker
//! * `check`    — semantic checks over the model (unknown features, duplicates, supersedes cycles, ranges)
//! * `emit_rust`— kernel-subset Rust (variant consts, yaku table, yaku conditions) and host-only metadata
//! * `tables`   — per-suit base-5 tables (shanten costs, decompositions) built from first principles
pub mod tables;
