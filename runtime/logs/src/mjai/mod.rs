//! MJAI, the event protocol of the Mahjong AI field (Mortal, akochan, mjai-manue, mjai.app):
//! one JSON object per event, seats 0-3 from East 1's dealer.
//!
//! * [`tile`]  — the protocol's tile names (`5mr`, `E`, `?`)
//! * [`event`] — the events, with the optional extras real logs carry
//! * [`write`] — a [`crate::tenhou::log::Game`] as an MJAI log, in the order the engines emit events
//! * [`live`]  — a game being played as the events sent live, and each seat's view of them
//! * [`read`]  — an MJAI log as a `Game`, so replay, convert and render take any format; `round`
//!   reads a round's events, `yaku` a win's yaku

pub mod event;
pub mod live;
pub mod read;
mod round;
pub mod tile;
pub mod write;
mod yaku;

#[cfg(test)]
mod tests;

pub use event::Event;
pub use tile::Pai;
