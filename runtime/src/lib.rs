//! rinshan: a vectorized four-player Riichi Mahjong environment whose rules are data.
//!
//! `rules/` (variant specs, the yaku spec and the portable kernels) is compiled at build time into
//! the modules of [`generated`]: one per variant, each with the kernels compiled natively and the
//! same kernels translated to WGSL for the GPU backend.
//!
//! * [`notation`] — hands written as `123m456p789s11z` (0 = red five) and melds as `pon:555z`
//! * [`hand`]     — shanten and hand scoring on the CPU, one hand or a batch
//! * [`gpu`]      — the same kernels on a GPU through wgpu
//! * [`env`]      — the batched game environment (reset, step, masks, rewards) on the CPU or the GPU
//! * [`tenhou`]   — tenhou.net/6 logs: reading them and replaying them through the red variant

include!(concat!(env!("OUT_DIR"), "/dispatch.rs"));

pub mod tables;

#[allow(missing_docs)]
pub mod generated {
    include!(concat!(env!("OUT_DIR"), "/generated.rs"));
}

pub mod entries;
pub mod env;
mod env_gpu;
pub mod gpu;
pub mod hand;
pub mod notation;
pub mod random;
pub mod tenhou;

pub use generated::Variant;

impl Variant {
    /// Parses a variant name as users write it: `red`, `no-red` or `no_red`.
    pub fn from_name(name: &str) -> Option<Variant> {
        let wanted = name.replace('-', "_");
        Variant::ALL.iter().copied().find(|v| v.name() == wanted)
    }
}

impl std::fmt::Display for Variant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name().replace('_', "-"))
    }
}
