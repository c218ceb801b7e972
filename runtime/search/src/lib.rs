//! rinshan-search: the look-ahead agent (`search`). At a decision of its own turn it values every
//! legal action by playing the round out many times, each time in a world dealt afresh from what
//! the seat can see, with a built-in agent playing every seat after the first move; it plays the
//! action whose outcomes are best, judged by a placement-aware value of the round's final scores.
//!
//! * [`world`]   — worlds consistent with a seat's view: the hidden tiles dealt afresh, what follows
//!   from the new hands recomputed, riichi seats dealt tenpai hands.
//! * [`rollout`] — one world played to the round's end by a built-in agent.
//! * [`value`]   — a round's final scores as a placement-aware value.
//! * [`decide`]  — the budget spent over the candidates: common worlds for all (paired
//!   comparisons), successive halving, and a switch from the base agent's choice only on evidence.
//! * [`positions`] — the decisions of `defensive` self-play, for the tests and measurements.
//! * [`options`] — `search:rollouts=256:base=defensive` as users write it.
//! * [`seat`]    — the agent as an arena [`Entrant`](rinshan_engine::arena::Entrant).
//! * [`batch`]   — the look-ahead at seats of a batch of games stepped by someone else (Python).
//! * [`outlook`] — win odds per discard: drawing alone from the unseen tiles, and with the other
//!   seats playing.
//!
//! It sees only what its seat sees: every world is dealt by the observation leak tests'
//! resampler ([`rinshan_engine::observe::resample_hidden`]), which reads the hidden tiles only as a
//! multiset in a fixed order, so the decision is the same whatever the hidden tiles are (a test
//! shuffles them and compares).
//!
//! ```
//! use rinshan_engine::env::{Config, Env};
//! use rinshan_engine::observe::OwnDraws;
//! use rinshan_engine::Variant;
//! use rinshan_search::{Focus, Options, Search};
//!
//! let mut env = Env::new(Config::new(Variant::Red, 1))?;
//! env.reset()?;
//! let state = env.game_states()?[0];
//! // The dealer's first decision, from its seat: the wall places it drew are all it knows
//! // beyond what the state shows every seat.
//! let mut own = OwnDraws::default();
//! own.update(Variant::Red, &state, &mut state.clone(), state.current);
//! // Every own-turn decision (by default only those with a riichi in play).
//! let search = Search::new(Variant::Red, Options { rollouts: 32, focus: Focus::All, ..Options::default() });
//! let decision = search.decide(&state, state.current, &own.positions, 0);
//! assert!(state.mask[decision.action as usize / 32] >> (decision.action % 32) & 1 == 1);
//! assert!(decision.candidates.len() >= 2 && decision.rollouts >= 16);
//! # Ok::<(), rinshan_engine::env::EnvError>(())
//! ```

#![warn(missing_docs)]

pub mod batch;
pub mod decide;
pub mod options;
pub mod outlook;
pub mod positions;
pub mod rollout;
pub mod seat;
pub mod value;
pub mod world;

pub use batch::BatchSearch;
pub use decide::{Appraisal, Candidate, Decision, Search};
pub use options::{Focus, Options};
pub use seat::SearchEntrant;
