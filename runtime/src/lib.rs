//! rinshan: a vectorized four-player Riichi Mahjong environment whose rules are data.
//!
//! `rules/` (variant specs, the yaku spec and the portable kernels) is compiled at build time into
//! the modules of [`generated`]: one per variant, each with the kernels compiled natively and the
//! same kernels translated to WGSL for the GPU backend.
//!
//! * [`tile`]     — tile types and physical tiles, and their encodings (kernel values, Tenhou codes)
//! * [`notation`] — hands written as `123m456p789s11z` (0 = red five) and melds as `pon:555z`
//! * [`hand`]     — shanten and hand scoring on the CPU, one hand or a batch
//! * [`gpu`]      — the same kernels on a GPU through wgpu
//! * [`env`]      — the batched game environment (reset, step, masks, rewards) on the CPU or the GPU
//! * [`agents`]   — the built-in baseline agents (random, rule, greedy, defensive)
//! * [`arena`]    — rating agents by duplicate play
//! * [`observe`]  — what an agent sees: the observation forms and the table documenting their fields
//! * [`tenhou`]   — tenhou.net/6 logs: reading them and replaying them through the red variant
//! * [`render`]   — pictures: the table as SVG or PNG, a whole game as an HTML replay page
//! * [`serve`]    — the web page: play against the agents, spectate, replay (axum)
//! * [`random`]   — deterministic random hands and legal actions for tests, benchmarks and self-play

#![warn(missing_docs)]

include!(concat!(env!("OUT_DIR"), "/dispatch.rs"));

mod tables;

#[allow(missing_docs)]
pub mod generated {
    include!(concat!(env!("OUT_DIR"), "/generated.rs"));
}

pub mod agents;
pub mod arena;
mod entries;
pub mod env;
mod env_gpu;
pub mod gpu;
pub mod hand;
pub mod notation;
pub mod observe;
pub mod random;
pub mod render;
pub mod serve;
pub mod tenhou;
pub mod tile;
pub mod win_input;

pub use generated::Variant;
pub use tile::{Tile, TileType};

impl Variant {
    /// Parses a variant name as users write it: `red`, `no-red` or `no_red`.
    pub fn from_name(name: &str) -> Option<Variant> {
        let wanted = name.replace('-', "_");
        Variant::ALL.iter().copied().find(|v| v.name() == wanted)
    }

    /// Each player's points at the start of a game (`[game] starting_points` of the spec).
    pub fn starting_points(self) -> u32 {
        with_variant!(self, v => v::STARTING_POINTS)
    }
}

impl std::fmt::Display for Variant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name().replace('_', "-"))
    }
}

impl std::str::FromStr for Variant {
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Variant, UnknownName> {
        Variant::from_name(name).ok_or_else(|| UnknownName::new("variant", name, Variant::ALL))
    }
}

/// A name that is none of the known ones (a variant, mode or backend), with the ones it could be.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownName {
    /// What was named: `variant`, `mode`, `backend`.
    pub what: &'static str,
    /// The name as given.
    pub name: String,
    /// The known names, as users write them.
    pub known: Vec<String>,
}

impl UnknownName {
    pub(crate) fn new<T: std::fmt::Display>(what: &'static str, name: &str, known: &[T]) -> UnknownName {
        UnknownName {
            what,
            name: name.to_string(),
            known: known.iter().map(ToString::to_string).collect(),
        }
    }

    /// The one of `all` written `name` (as its `Display` writes it), or the error naming them.
    pub(crate) fn find<T: Copy + std::fmt::Display>(
        what: &'static str,
        name: &str,
        all: &[T],
    ) -> Result<T, UnknownName> {
        all.iter()
            .copied()
            .find(|t| t.to_string() == name)
            .ok_or_else(|| UnknownName::new(what, name, all))
    }
}

impl std::fmt::Display for UnknownName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "unknown {} `{}` (known: {})",
            self.what,
            self.name,
            self.known.join(", ")
        )
    }
}

impl std::error::Error for UnknownName {}
