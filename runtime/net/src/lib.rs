//! rinshan-net: a trained policy network as an agent (`net:PATH`). The training example
//! (examples/train) exports its nets as safetensors files (`export.py`); this crate reads one and
//! plays it on the CPU, in pure Rust (candle), wherever an agent sits: the arena, selfplay, the web
//! page, `mjai-bot` and the Python env's opponents.
//!
//! * [`mod@file`] — the export read and checked: the weights, the action names the logits are
//!   indexed by, the observation layout the net was trained on.
//! * [`inputs`] — a decision's inputs from the game state: the seat's planes, the analysis rows
//!   the net reads, the scalars.
//! * [`model`]  — the forward pass: the same function as the training example's `Net`, checked
//!   against PyTorch's outputs on the same inputs (tests/net.rs, python/tests/test_net.py).
//! * [`agent`]  — the net playing a variant: its legal actions mapped to the net's, the greedy
//!   choice, one forward pass for a batch of decisions; an arena entrant.
//! * [`batch`]  — the net at seats of a batch of games stepped by someone else (selfplay, Python).
//! * [`random`] — nets of random weights in the same layout, for tests and timings.
//!
//! The agent sees what its seat sees: its inputs are the observation of the player to move.
//!
//! ```
//! use std::sync::Arc;
//!
//! use rinshan_engine::env::Mode;
//! use rinshan_engine::Variant;
//! use rinshan_net::random::{net_file, Shape};
//! use rinshan_net::{Net, NetAgent};
//!
//! // A trained net comes from `Net::load("ppo.safetensors")`; this one has random weights.
//! let net = Net::from_bytes(&net_file(Shape::default(), 1), "random.safetensors", "random".into())?;
//! let agent = NetAgent::new(Arc::new(net), Variant::Red)?;
//! let state = Variant::Red.new_game(7, Mode::Half);
//! // The dealer's first decision: a legal action of the red variant.
//! let action = agent.act(&state)?;
//! assert!(state.mask[action as usize / 32] >> (action % 32) & 1 == 1);
//! # Ok::<(), rinshan_net::NetError>(())
//! ```

#![warn(missing_docs)]

pub mod agent;
pub mod batch;
pub mod file;
pub mod inputs;
pub mod model;
pub mod random;

pub use agent::NetAgent;
pub use batch::BatchNet;
pub use file::{Net, NetError};
pub use inputs::Decision;
