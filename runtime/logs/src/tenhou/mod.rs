//! Tenhou game records, and replaying them through the red variant.
//!
//! * [`log`]    — reads tenhou.net/6 JSON logs (one record per line, or one whole game) into typed
//!   rounds: starting hands, draws and calls, discards and kans, and the result with its yaku.
//! * [`plan`]   — a logged round in the order of play: the wall it was dealt from and its decisions
//! * [`position`] — every decision of a logged round with the state before it (for observations)
//! * [`replay`] — drives the environment with the logged decisions and compares every round
//! * [`write`](mod@write) — records games played in rinshan (red variant) as tenhou.net/6 logs
//!
//! Tenhou's names, once: a round is a kyoku (`East 1` = East round, first dealer), honba are the
//! repeat counters, riichi sticks are the 1000-point deposits; seat 0 is East 1's dealer.

pub mod log;
pub mod plan;
pub mod position;
pub mod replay;
pub mod write;
