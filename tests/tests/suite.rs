//! rinshan's test suite in one binary: each module is one concern (a clean build links one
//! wgpu-heavy test executable for this crate instead of one per file).

mod agents;
mod browser;
mod brute_force;
mod env_api;
mod env_parity;
mod game_invariants;
mod generated_modules;
mod observation;
mod observation_bytes;
mod observation_fields;
mod observation_snapshots;
mod parity;
mod randomness;
mod render;
mod rules_as_data;
mod scenarios;
mod scoring_cases;
mod serve_hold;
mod serve_http;
mod serve_mjai;
mod shanten_data;
mod soak;
mod tenhou_replay;
mod tenhou_roundtrip;
mod tenpai_shortcuts;
mod uma;
