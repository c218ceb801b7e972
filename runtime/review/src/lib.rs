//! rinshan-review: a player's decisions in a logged game judged by the look-ahead
//! ([`rinshan_search`]). Every decision of the player with a choice (its own turns and the claim
//! prompts it was offered) is replayed to the state before it; the look-ahead values every legal
//! action from what the player could see (worlds dealt from the seat's view, played to the round's
//! end by a built-in agent, valued by the expected final place); the best action other than the
//! one played then meets the played one in fresh worlds, and their paired difference is the
//! decision's loss, in expected places (0.1 = a tenth of a place, over the game).
//!
//! * [`review`](mod@review) — the decisions valued, with totals per round and for the game.
//! * [`html`] — the review as one offline page: each decision's board, its candidates, the
//!   mistakes ranked by loss.
//!
//! The values depend on what the seat saw only, and on the look-ahead's seed and budget: a review
//! is the same whichever format the log is in.

#![warn(missing_docs)]

pub mod html;
pub mod review;

pub use html::review_html;
pub use review::{review, review_spots, seat_for, seat_of, spots, Review, Reviewed, Spot, Summary};
