//! rinshan-logs: game records, read, written and replayed through the engine.
//!
//! * [`tenhou`] — tenhou.net/6 JSON logs: reading them, planning a logged round as the engine plays
//!   it, replaying and comparing every round, and recording games played in rinshan.
//! * [`mjai`] — MJAI event logs, read into and written from the same game records.
//! * [`mjlog`] — Tenhou's mjlog XML, read into the same game records.
//! * [`file`] — either format from a file, plain or gzipped, told apart by its text.
//!
//! Depends on `rinshan-engine` only; pictures (`rinshan-render`), the web page and the `rinshan`
//! command build on it.

#![warn(missing_docs)]

pub mod file;
pub mod mjai;
pub mod mjlog;
pub mod tenhou;

pub use file::{read_log, Format};
