//! rinshan-logs: game records, read, written and replayed through the engine.
//!
//! * [`tenhou`] — tenhou.net/6 JSON logs: reading them, planning a logged round as the engine plays
//!   it, replaying and comparing every round, and recording games played in rinshan.
//!
//! Depends on `rinshan-engine` only; pictures (`rinshan-render`), the web page and the `rinshan`
//! command build on it.

#![warn(missing_docs)]

pub mod tenhou;
