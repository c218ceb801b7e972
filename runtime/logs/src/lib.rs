//! rinshan-logs: game records, read, written and replayed through the engine.
//!
//! * [`tenhou`] — tenhou.net/6 JSON logs: reading them, planning a logged round as the engine plays
//!   it, replaying and comparing every round, and recording games played in rinshan.
//! * [`mjai`] — MJAI event logs, read into and written from the same game records.
//! * [`mjlog`] — Tenhou's mjlog XML, read into the same game records.
//! * [`file`](mod@file) — either format from a file, plain or gzipped, told apart by its text.
//!
//! Depends on `rinshan-engine` only; pictures (`rinshan-render`), the web page and the `rinshan`
//! command build on it.
//!
//! An east game played in rinshan, written as a tenhou.net/6 log, read back and replayed: every logged
//! decision is taken and every win scores as logged.
//!
//! ```
//! use rinshan_engine::env::{Backend, Config, Env, Mode};
//! use rinshan_engine::Variant;
//! use rinshan_logs::tenhou::{log::parse_game, replay::replay, write::{game_text, Recorder}};
//!
//! let mut env = Env::new(Config { mode: Mode::East, auto_reset: false, ..Config::new(Variant::Red, 1) })?;
//! env.reset()?;
//! let mut recorder = Recorder::new(&env)?;
//! let mut finished = Vec::new();
//! while finished.is_empty() {
//!     // Any policy goes here: this one plays the lowest legal action id.
//!     let action = env.last().legal_actions(0).next().expect("a legal action");
//!     env.step(&[action])?;
//!     recorder.observe(&env, &[action])?;
//!     finished = recorder.take_finished();
//! }
//! let text = game_text(&finished[0].game);
//! let game = parse_game("played.json", &text)?;
//! let report = replay(&[game], Backend::Cpu)?;
//! assert_eq!(report.actions_accepted, report.actions);
//! assert_eq!(report.wins_matching, report.wins);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod file;
pub mod mjai;
pub mod mjlog;
pub mod tenhou;

pub use file::{read_log, Format};
