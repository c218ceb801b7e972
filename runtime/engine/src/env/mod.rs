//! The batched environment: B independent games stepped together, on the CPU (rayon) or on the GPU
//! (wgpu, state kept on the device). Both run the same generated kernels (`game_new`, `game_step`,
//! `game_view` of `rules/kernel/game_step.rs`), so for the same seeds and actions they produce the
//! same states, masks and rewards bit for bit.
//!
//! ```no_run
//! use rinshan_engine::env::{Backend, Config, Env, Mode};
//! let mut env = Env::new(Config::new(rinshan_engine::Variant::Red, 64)).unwrap();
//! let step = env.reset().unwrap();
//! // pick one legal action per env from step.legal_action_mask, then:
//! # let actions = vec![0u32; 64];
//! let step = env.step(&actions).unwrap();
//! ```

mod config;
mod cpu;
mod games;
mod gpu;
mod layout;
mod observe;
mod seed;
mod snapshot;
mod step;
mod table;

pub use config::{Backend, Config, EnvError, Mode};
pub use games::Env;
pub use layout::ActionMap;
pub use observe::Observer;
pub use seed::env_seed;
pub use snapshot::CHECK_WORDS;
pub use step::{action_names, events, yaku_names, Step};
pub use table::{check_table, Deal, DrawKind, DrawRecord, Table, WinRecord, MAX_SCORE};
