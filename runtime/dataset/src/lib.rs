//! rinshan-dataset: training data from game logs. A folder, glob or tar archive of logs in any
//! format `rinshan-logs` reads is replayed through the engine; every decision of the chosen seats
//! becomes a row (the seat's observation in the asked forms, its legal mask, the action the log
//! took), every kept game gets its final scores and ranks, and the rows go to `.npy` shards with a
//! manifest that carries the field schema.
//!
//! * [`inputs`] — which logs, in one fixed order (files, folders, globs, tar archives).
//! * [`record`] — a batch of games replayed into rows.
//! * [`label`] — each row's action and action values by the look-ahead (`rinshan-search`), when
//!   asked for.
//! * [`shard`] — one shard's arrays on disk.
//! * [`manifest`] — the schema, options and finished shards.
//! * [`same`] — one game in two files (two formats, two copies), recognised by its content.
//! * [`build`](mod@build) — the parallel, resumable run over all of it.
//!
//! Depends on `rinshan-engine`, `rinshan-logs` and `rinshan-search`; the `rinshan dataset` command and the Python
//! package build on it.

#![warn(missing_docs)]

pub mod build;
pub mod inputs;
pub mod label;
pub mod manifest;
pub mod record;
pub mod same;
pub mod shard;

pub use build::{build, Build, Progress, Summary, DEFAULT_INPUTS_PER_SHARD};
pub use record::{Options, Seats, DEFAULT_VARIANT};

#[cfg(test)]
mod tests;
