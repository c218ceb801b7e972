//! Worlds played to the end of their round: one kernel call of hero mode each (`PLAY_ROUND`: the
//! first action, then the built-in agent at every seat until the round ends), on the CPU or, in
//! batches, on the GPU backend. Both run the same kernel, so a play-out's end is the same bit for
//! bit wherever it ran, and so is every decision taken from them.

use std::sync::{Mutex, OnceLock};

use rinshan_engine::agents::{hero_arg, seats_word, Agent};
use rinshan_engine::env::{Backend, Config, Env, EnvError};
use rinshan_engine::generated::kernel::{GameState, PLAY_ROUND};
use rinshan_engine::{with_variant, Variant};

/// Plays `first` in `world`, then `agent` for every seat, until the round ends (the next one is
/// dealt, or the game is over). Returns the state then and the steps played.
pub fn play_round(variant: Variant, mut world: GameState, first: u32, agent: Agent) -> (GameState, u32) {
    let arg = hero_arg(first, seats_word(&[Some(agent); 4])) | PLAY_ROUND;
    let before = world.steps;
    with_variant!(variant, v => v::game_play(&mut world, arg));
    (world, world.steps.wrapping_sub(before))
}

/// Play-outs per GPU call at most: a batch beyond it is played in parts.
const GPU_BATCH_MAX: usize = 1 << 16;

/// The GPU env of the play-outs: of the rule set last asked for, grown to the largest batch asked
/// for so far. A software adapter takes minutes to compile a rule set's pipelines, so every
/// look-ahead of the process shares it (and the device caches the pipelines of every rule set).
/// `Err` holds why the GPU could not be opened (asked once).
static GPU: OnceLock<Mutex<Result<Env, String>>> = OnceLock::new();

fn gpu_config(variant: Variant, batch: usize) -> Config {
    Config {
        backend: Backend::Gpu,
        ..Config::new(variant, batch)
    }
}

/// Plays `plays` (a world and its first action each) on the GPU. `Err`: the GPU is not there.
fn play_on_gpu(variant: Variant, plays: &[(GameState, u32)], agent: Agent) -> Result<Vec<(GameState, u32)>, String> {
    let cell = GPU.get_or_init(|| Mutex::new(Env::new(gpu_config(variant, 1)).map_err(|e| e.to_string())));
    let mut guard = cell.lock().map_err(|_| "a GPU play-out panicked".to_string())?;
    let env = guard.as_mut().map_err(|e| e.clone())?;
    let mut out = Vec::with_capacity(plays.len());
    for part in plays.chunks(GPU_BATCH_MAX) {
        out.extend(play_part(env, variant, part, agent).map_err(|e| e.to_string())?);
    }
    Ok(out)
}

/// One part of a GPU batch, in an env of the rule set made here (on the same device) where the
/// one there is of another rule set or smaller than the next power of two at or above the part's
/// size; padded with copies of its first play-out.
fn play_part(
    env: &mut Env,
    variant: Variant,
    part: &[(GameState, u32)],
    agent: Agent,
) -> Result<Vec<(GameState, u32)>, EnvError> {
    let want = part.len().next_power_of_two();
    if env.variant() != variant || env.batch() < want {
        let old = std::mem::replace(env, Env::new(Config::new(variant, 1))?);
        *env = match old.into_gpu() {
            Some(gpu) => Env::with_gpu(gpu_config(variant, want), gpu)?,
            None => Env::new(gpu_config(variant, want))?,
        };
    }
    let b = env.batch();
    let pad = |i: usize| part.get(i).unwrap_or(&part[0]);
    let worlds: Vec<GameState> = (0..b).map(|i| pad(i).0).collect();
    let firsts: Vec<u32> = (0..b).map(|i| pad(i).1).collect();
    env.load_game_states(&worlds)?;
    env.play_rounds(&firsts, &[[agent; 4]])?;
    let ends = env.game_states()?;
    Ok(part
        .iter()
        .zip(ends)
        .map(|((world, _), end)| (end, end.steps.wrapping_sub(world.steps)))
        .collect())
}

/// Whether the play-outs asked for on the GPU ran there: `Err` says why not (no adapter), and
/// they ran on the CPU, with the same results.
pub fn gpu_status() -> Option<Result<(), String>> {
    let cell = GPU.get()?;
    let guard = cell.lock().ok()?;
    Some(guard.as_ref().map(|_| ()).map_err(|e| e.clone()))
}

/// Plays every world of `plays` from its first action to the round's end, on `backend`. The
/// GPU's play-outs are the CPU's bit for bit; where no GPU can be opened they run on the CPU, and
/// the first such batch says so on stderr.
pub fn play_rounds(
    variant: Variant,
    plays: &[(GameState, u32)],
    agent: Agent,
    backend: Backend,
) -> Vec<(GameState, u32)> {
    if backend == Backend::Gpu && !plays.is_empty() {
        match play_on_gpu(variant, plays, agent) {
            Ok(ends) => return ends,
            Err(e) => warn_once(&e),
        }
    }
    plays
        .iter()
        .map(|&(world, first)| play_round(variant, world, first, agent))
        .collect()
}

fn warn_once(why: &str) {
    static WARNED: OnceLock<()> = OnceLock::new();
    WARNED.get_or_init(|| eprintln!("search: backend=gpu: {why}; playing out on the CPU instead"));
}
