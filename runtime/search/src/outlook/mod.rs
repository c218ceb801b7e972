//! Win odds per discard, the outlook of a hand:
//!
//! * [`solo`](mod@solo) — drawing alone from the unseen tiles: the chances of tenpai and of a
//!   win by each draw, fast enough for every turn (the web page's hint, `rinshan outlook`).
//! * [`played`] — with the other seats playing: each discard played out to the round's end in
//!   worlds dealt from the seat's view, with a built-in agent in every seat: the chances of
//!   winning and of dealing in, and the points each brings.

pub mod played;
pub mod solo;

pub use played::{in_play, InPlay};
pub use solo::{at_turn, of_notation, solo, to_json, unseen, Odds};
