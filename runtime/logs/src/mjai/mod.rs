//! MJAI, the event protocol of the Mahjong AI field (Mortal, akochan, mjai-manue, mjai.app):
//! one JSON object per event, seats 0-3 from East 1's dealer.
//!
//! * [`tile`]  — the protocol's tile names (`5mr`, `E`, `?`)
//! * [`event`] — the events, with the optional extras real logs carry
//! * [`write`](mod@write) — a [`crate::tenhou::log::Game`] as an MJAI log, in the order the engines emit events
//! * [`live`]  — a game being played as the events sent live, and each seat's view of them
//! * [`reaction`] — a bot's reaction as the engine's action id
//! * [`bot`]   — an MJAI bot as a child process, in mjai.app's or Mortal's dialect
//! * [`seat`]  — such a bot as a seat of the engine's games (the arena's `mjai:` players)
//! * [`player`] — rinshan as an MJAI player: a seat's events in, the engine's state of its
//!   decision out (`rebuild` deals a wall consistent with what the seat saw and replays the round)
//! * [`read`]  — an MJAI log as a `Game`, so replay, convert and render take any format; `round`
//!   reads a round's events, `yaku` a win's yaku, `unlogged` scores the wins a log gives
//!   without yaku (libriichi's), `rules` the rule set a `start_game` names

pub mod batch;
pub mod bot;
pub mod event;
pub mod live;
pub mod player;
pub mod reaction;
pub mod read;
mod rebuild;
mod round;
mod rules;
pub mod seat;
pub mod tile;
mod unlogged;
pub mod write;
mod yaku;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_field;

pub use event::Event;
pub use tile::Pai;
