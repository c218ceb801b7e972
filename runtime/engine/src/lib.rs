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
//! * [`env`]      — the batched game environment (reset, step, masks, rewards) on the CPU or the GPU
//! * [`observe`]  — what an agent sees: the observation forms and the table documenting their fields
//! * [`agents`]   — the built-in baseline agents (random, rule, greedy, defensive)
//! * [`arena`]    — rating agents by duplicate play
//! * [`invariants`] — what holds of every game state (tiles and points conserved, one seat to act)
//! * [`random`]   — deterministic random hands and legal actions for tests, benchmarks and self-play
//! * [`names`]    — the names users write for variants, modes and the rest, and their error

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
