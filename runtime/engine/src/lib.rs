//! rinshan-engine: the batched four-player Riichi Mahjong game whose rules are data, on the CPU and
//! the GPU, with what an agent sees and the built-in agents.
//!
//! `rules/` (variant specs, the yaku spec and the portable kernels) is compiled at build time (this
//! crate's build script runs `rinshan-codegen` and `rinshan-shaders-gen`) into the modules of
//! [`generated`]: one per variant, each with the kernels compiled natively and the same kernels
//! translated to WGSL for the GPU backend. This crate depends on no other rinshan crate at run
//! time; the log formats (`rinshan-logs`), pictures (`rinshan-render`), the web page
//! (`rinshan-serve`), the `rinshan` command and the Python package build on it.
//!
//! * [`tile`]     — tile types and physical tiles, and their encodings (kernel values, Tenhou codes)
//! * [`notation`] — hands written as `123m456p789s11z` (0 = red five) and melds as `pon:555z`
//! * [`hand`]     — shanten and hand scoring on the CPU, one hand or a batch
//! * [`win_input`] — a winning hand described as people write it (the `score` command, Python)
//! * [`gpu`]      — the same kernels on a GPU through wgpu
//! * [`env`](mod@env) — the batched game environment (reset, step, masks, rewards) on the CPU or the GPU
//! * [`observe`]  — what an agent sees: the observation forms and the table documenting their fields
//! * [`agents`]   — the built-in baseline agents (random, rule, greedy, defensive)
//! * [`arena`]    — rating agents by duplicate play
//! * [`invariants`] — what holds of every game state (tiles and points conserved, one seat to act)
//! * [`random`]   — deterministic random hands and legal actions for tests, benchmarks and self-play
//! * [`names`]    — the names users write for variants, modes and the rest, and their error
//!
//! Four single hands of Tenhou's rules played to their end, each seat choosing among its legal
//! actions by a counter (any policy goes where the counter is):
//!
//! ```
//! use rinshan_engine::env::{Config, Env, Mode};
//! use rinshan_engine::Variant;
//!
//! let mut env = Env::new(Config { mode: Mode::Single, auto_reset: false, ..Config::new(Variant::Red, 4) })?;
//! env.reset()?;
//! let mut places: Vec<Option<[u8; 4]>> = vec![None; env.batch()];
//! let mut turn = 0usize;
//! while places.iter().any(Option::is_none) {
//!     let step = env.last();
//!     let actions: Vec<u32> = (0..env.batch())
//!         .map(|i| {
//!             // A finished hand offers nothing and stays finished, whatever it is given.
//!             let legal: Vec<u32> = step.legal_actions(i).collect();
//!             legal.get(turn % legal.len().max(1)).copied().unwrap_or(0)
//!         })
//!         .collect();
//!     let step = env.step(&actions)?;
//!     // The step that ends a game carries its places (0 = first).
//!     for (i, place) in places.iter_mut().enumerate() {
//!         if step.terminated[i] && place.is_none() {
//!             *place = Some(step.ranks[i]);
//!         }
//!     }
//!     assert!(step.illegal.iter().all(|&bad| !bad));
//!     turn += 1;
//! }
//! // Every hand ended by the rules, its places a permutation of first to fourth.
//! for place in places.into_iter().flatten() {
//!     let mut sorted = place;
//!     sorted.sort();
//!     assert_eq!(sorted, [0, 1, 2, 3]);
//! }
//! # Ok::<(), rinshan_engine::env::EnvError>(())
//! ```

#![warn(missing_docs)]

include!(concat!(env!("OUT_DIR"), "/dispatch.rs"));

mod tables;

#[allow(missing_docs)]
pub mod generated {
    include!(concat!(env!("OUT_DIR"), "/generated.rs"));
}

pub mod agents;
pub mod arena;
mod batch;
mod entries;
pub mod env;
pub mod gpu;
pub mod hand;
pub mod invariants;
pub mod names;
pub mod notation;
pub mod observe;
pub mod random;
pub mod tile;
mod variant;
pub mod win_input;

pub use generated::Variant;
pub use names::UnknownName;
pub use tile::{Tile, TileType};
pub use variant::WallLayout;
