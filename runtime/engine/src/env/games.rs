//! [`Env`]: the batch of games, its configuration checks, resets and steps on either backend.

use rayon::prelude::*;

use super::config::{Backend, Config, EnvError};
use super::cpu::{CpuEnv, PARALLEL_MIN};
use super::gpu::GpuEnv;
use super::seed::env_seed;
use super::step::Step;
use crate::generated::kernel;
use crate::gpu::Gpu;
use crate::tile::Tile;
use crate::Variant;

/// Sizes of the kernel records, in 32-bit words: (ResetInput, GameState, StepView).
pub(crate) const RECORD_WORDS: (usize, usize, usize) = (
    crate::hand::words::<kernel::ResetInput>(),
    crate::hand::words::<kernel::GameState>(),
    crate::hand::words::<kernel::StepView>(),
);

/// Words of a kernel `DealInput` ([`Env::deal`]).
pub(super) const DEAL_WORDS: usize = crate::hand::words::<kernel::DealInput>();

/// The uma `config` pays: its own, or the spec's `UMA` (thousands) x 1000.
fn uma_of(config: &Config) -> [i32; 4] {
    config
        .uma
        .unwrap_or(with_variant!(config.variant, v => v::host::UMA.map(|x| x * 1000)))
}

/// Checks that `wall` holds exactly this variant's 136 tiles: every type 4 times, counting a red
/// five as a five, and with red fives (only in a variant that has them) once each.
pub(crate) fn check_wall(variant: Variant, wall: &[Tile; 136]) -> Result<(), String> {
    let red_fives = with_variant!(variant, v => v::RED_FIVES);
    // Three players play 108 tiles, without 2m-8m; the array's last 28 places are not read.
    let in_play = |t: usize| variant.tile_in_play(t as u32);
    let mut counts = [0u32; 34];
    let mut reds = [0u32; 3];
    for (i, &t) in wall.iter().enumerate().take(variant.wall().tiles as usize) {
        if t.is_red() && !red_fives {
            return Err(format!("tile {i} is a red five ({t}), but variant {variant} has none"));
        }
        if let (true, Some(suit)) = (t.is_red(), t.kind().suit()) {
            reds[usize::from(suit)] += 1;
        }
        counts[t.kind().index()] += 1;
    }
    if let Some(t) = (0..34).find(|&t| counts[t] != if in_play(t) { 4 } else { 0 }) {
        let want = if in_play(t) {
            "every type appears 4 times"
        } else {
            "three players have no 2m-8m"
        };
        return Err(format!("{} copies of tile type {t}: {want}", counts[t]));
    }
    if red_fives {
        if let Some(s) = (0..3).find(|&s| reds[s] != u32::from(in_play(s * 9 + 4))) {
            return Err(format!(
                "{} red fives of suit {s}: this variant has exactly one per suit (value {})",
                reds[s],
                34 + s
            ));
        }
    }
    Ok(())
}

/// One step of every env (`play`: hero mode, `actions` are its arguments), its view in `step`.
fn advance(
    backing: &mut Backing,
    step: &mut Step,
    variant: Variant,
    actions: &[u32],
    play: bool,
) -> Result<(), EnvError> {
    match backing {
        Backing::Cpu(cpu) => {
            cpu.step(variant, actions, play);
            step.fill(&cpu.views);
        }
        Backing::Gpu(gpu) => {
            let views = gpu.step(actions, play)?;
            step.fill(views);
        }
    }
    Ok(())
}

pub(super) enum Backing {
    Cpu(CpuEnv),
    Gpu(Box<GpuEnv>),
}

/// A batch of B games. See the module docs.
pub struct Env {
    pub(super) config: Config,
    pub(super) uma: [i32; 4],
    pub(super) penalty: f32,
    pub(super) num_actions: u32,
    pub(super) words: (usize, usize, usize),
    pub(super) backing: Backing,
    pub(super) step: Step,
    /// ResetInput words of every env, reused by each reset.
    pub(super) reset_inputs: Vec<u32>,
    pub(super) epoch: u64,
    /// The per-step observations, one buffer per form of `config.observe`.
    pub(super) observations: Vec<Vec<u32>>,
    /// The buffer [`Env::observe`] returns.
    pub(super) observed: Vec<u8>,
    /// Hero mode's per-env step arguments.
    pub(super) play_args: Vec<u32>,
}

impl Env {
    /// Makes the envs (not yet dealt: call [`Env::reset`] first). `Backend::Gpu` opens the first
    /// GPU adapter (see [`Gpu::new`]).
    pub fn new(config: Config) -> Result<Env, EnvError> {
        let gpu = match config.backend {
            Backend::Gpu => {
                Env::check(&config)?;
                Some(Gpu::new()?)
            }
            Backend::Cpu => None,
        };
        Env::build(config, gpu)
    }

    /// As [`Env::new`] with `Backend::Gpu` on an already opened device.
    pub fn with_gpu(mut config: Config, gpu: Gpu) -> Result<Env, EnvError> {
        config.backend = Backend::Gpu;
        Env::build(config, Some(gpu))
    }

    fn check(config: &Config) -> Result<(), EnvError> {
        if config.batch == 0 {
            return Err(EnvError::EmptyBatch);
        }
        if config.threads == Some(0) {
            return Err(EnvError::BadThreads(
                "threads must be at least 1 (None = all cores)".into(),
            ));
        }
        if config.agents.len() > 1 && config.agents.len() != config.batch {
            return Err(EnvError::WrongLength {
                what: "agent seatings",
                expected: config.batch,
                got: config.agents.len(),
            });
        }
        if let Some(p) = config.penalty {
            if !p.is_finite() {
                return Err(EnvError::BadPenalty(p));
            }
        }
        if config.backend == Backend::Gpu && config.batch > crate::gpu::MAX_DISPATCH {
            return Err(EnvError::BatchTooLarge {
                batch: config.batch,
                max: crate::gpu::MAX_DISPATCH,
            });
        }
        Ok(())
    }

    fn build(config: Config, gpu: Option<Gpu>) -> Result<Env, EnvError> {
        Env::check(&config)?;
        let variant = config.variant;
        let b = config.batch;
        let words = RECORD_WORDS;
        let uma = uma_of(&config);
        let (penalty, num_actions) = with_variant!(variant, v => (
            config.penalty.unwrap_or(v::host::ILLEGAL_ACTION_PENALTY),
            v::NUM_ACTIONS,
        ));
        let backing = match gpu {
            Some(gpu) => Backing::Gpu(Box::new(GpuEnv::new(gpu, variant, b, words, DEAL_WORDS)?)),
            None => {
                let serial = config.threads == Some(1) || b < PARALLEL_MIN;
                let pool = if serial {
                    None
                } else {
                    super::cpu::pool_for(config.threads).map_err(EnvError::BadThreads)?
                };
                Backing::Cpu(CpuEnv {
                    states: vec![0; b * words.1],
                    views: vec![0; b * words.2],
                    tables: Vec::new(),
                    pool,
                    serial,
                })
            }
        };
        Ok(Env {
            uma,
            penalty,
            num_actions,
            words,
            backing,
            step: Step::with_batch(b),
            reset_inputs: vec![0; b * words.0],
            epoch: 0,
            observations: config.observe.iter().map(|f| vec![0; b * f.words()]).collect(),
            observed: Vec::new(),
            play_args: vec![0; if config.agents.is_empty() { 0 } else { b }],
            config,
        })
    }

    /// The GPU device of a GPU env, with every pipeline it compiled, to build another env on (of
    /// another mode, uma or batch) without compiling them again: on a software adapter a variant's
    /// pipelines take minutes of one core. `None` on the CPU backend.
    pub fn into_gpu(self) -> Option<Gpu> {
        match self.backing {
            Backing::Gpu(gpu) => Some(gpu.gpu),
            Backing::Cpu(_) => None,
        }
    }

    /// Number of action ids of the variant (red 87, no-red 79); masks have 96 bits.
    pub fn num_actions(&self) -> u32 {
        self.num_actions
    }

    /// The rules played.
    pub fn variant(&self) -> Variant {
        self.config.variant
    }

    /// The uma this env pays at a game's end, by final place (points).
    pub fn uma(&self) -> [i32; 4] {
        uma_of(&self.config)
    }

    /// Number of games stepped together.
    pub fn batch(&self) -> usize {
        self.config.batch
    }

    /// The configuration the envs were made with.
    pub fn config(&self) -> &Config {
        &self.config
    }

    /// The GPU adapter's description, or `None` on the CPU backend.
    pub fn adapter(&self) -> Option<String> {
        match &self.backing {
            Backing::Gpu(g) => Some(g.adapter()),
            Backing::Cpu(_) => None,
        }
    }

    /// Whether the GPU backend runs on a software adapter (Mesa's lavapipe): correct, but its
    /// pipelines take minutes to compile.
    pub fn gpu_is_software(&self) -> bool {
        matches!(&self.backing, Backing::Gpu(g) if g.is_software())
    }

    /// The outcome of the last reset or step.
    pub fn last(&self) -> &Step {
        &self.step
    }

    /// Runs `job` on every part with the threads the step uses (the env's pool, or only the
    /// calling thread when the env steps serially or on the GPU): for callers that copy a step's
    /// rows into arrays of their own, split by rows as the envs are.
    pub fn for_each_part<T: Send>(&self, parts: Vec<T>, job: impl Fn(T) + Send + Sync) {
        match &self.backing {
            Backing::Cpu(cpu) if !cpu.serial => cpu.install(|| parts.into_par_iter().for_each(job)),
            _ => parts.into_iter().for_each(job),
        }
    }

    /// New games in every env: env `i` is seeded from `(config.seed, i, r)` where `r` counts the
    /// calls to `reset` so far, so a run is reproducible and each reset deals new games. Fails
    /// only if the GPU does (device lost).
    pub fn reset(&mut self) -> Result<&Step, EnvError> {
        let seeds = self.next_seeds();
        self.write_inputs(&seeds, None);
        self.run_reset()
    }

    fn next_seeds(&mut self) -> Vec<u64> {
        let epoch = self.epoch;
        self.epoch += 1;
        let seed = self.config.seed;
        (0..self.batch() as u64).map(|i| env_seed(seed, i, epoch)).collect()
    }

    /// New games with one 64-bit seed per env (the same seed deals the same games on both backends).
    pub fn reset_with_seeds(&mut self, seeds: &[u64]) -> Result<&Step, EnvError> {
        self.check_len("seeds", seeds.len())?;
        self.write_inputs(seeds, None);
        self.run_reset()
    }

    /// New games whose first round deals the given walls (tiles in dealing order) with the given
    /// first dealers (0..3, 0..2 with three players). Later rounds shuffle from the seeds [`Env::reset`] would use.
    pub fn reset_with_walls(&mut self, walls: &[[Tile; 136]], dealers: &[u32]) -> Result<&Step, EnvError> {
        self.check_len("walls", walls.len())?;
        self.check_len("dealers", dealers.len())?;
        for (env, wall) in walls.iter().enumerate() {
            check_wall(self.variant(), wall).map_err(|reason| EnvError::BadWall { env, reason })?;
        }
        let seats = self.variant().seats();
        if let Some(env) = dealers.iter().position(|&d| d >= seats) {
            return Err(EnvError::BadDealer {
                env,
                dealer: dealers[env],
                seats,
            });
        }
        let seeds = self.next_seeds();
        self.write_inputs(&seeds, Some((walls, dealers)));
        self.run_reset()
    }

    /// One decision per env: `actions[i]` is the action id of env `i`'s current player. An
    /// illegal action is not an error: it ends that env's game with the penalty for the actor.
    /// A finished env without auto-reset stays finished (its view repeats, with no reward).
    pub fn step(&mut self, actions: &[u32]) -> Result<&Step, EnvError> {
        self.check_len("actions", actions.len())?;
        let variant = self.variant();
        let play = !self.config.agents.is_empty();
        if play {
            for (i, (arg, &a)) in self.play_args.iter_mut().zip(actions).enumerate() {
                let seats = &self.config.agents[if self.config.agents.len() == 1 { 0 } else { i }];
                *arg = crate::agents::hero_arg(a, crate::agents::seats_word(seats));
            }
        }
        let actions = if play { &self.play_args[..] } else { actions };
        advance(&mut self.backing, &mut self.step, variant, actions, play)?;
        self.write_observations()?;
        Ok(&self.step)
    }

    /// Play-outs (the look-ahead's): in every env, `firsts[i]` is played whoever is to move, then
    /// the built-in agents of `seatings` (one per env, or one for all) play every seat until the
    /// round ends or the game does. One call of hero mode, on either backend; `rewards` and
    /// `events` add up every decision played. An illegal first action ends that game with the
    /// penalty, as in [`Env::step`].
    pub fn play_rounds(&mut self, firsts: &[u32], seatings: &[[crate::agents::Agent; 4]]) -> Result<&Step, EnvError> {
        self.check_len("first actions", firsts.len())?;
        let args: Vec<u32> = firsts
            .iter()
            .zip(self.seats_words(seatings)?)
            .map(|(&a, seats)| crate::agents::hero_arg(a, seats) | kernel::PLAY_ROUND)
            .collect();
        let variant = self.variant();
        advance(&mut self.backing, &mut self.step, variant, &args, true)?;
        self.write_observations()?;
        Ok(&self.step)
    }

    /// The raw `GameState` words of every env ([`Env::state_words`] words each, the kernel's
    /// `generated::kernel::GameState`), read back from the GPU on that backend.
    pub fn states_words(&self) -> Result<Vec<u32>, EnvError> {
        match &self.backing {
            Backing::Cpu(cpu) => Ok(cpu.states.clone()),
            Backing::Gpu(gpu) => Ok(gpu.states()?),
        }
    }

    /// Every env's game state, read back from the GPU on that backend (for pictures and tools;
    /// [`Env::states_words`] gives the same as raw words).
    pub fn game_states(&self) -> Result<Vec<kernel::GameState>, EnvError> {
        let words = self.states_words()?;
        Ok(words
            .chunks_exact(self.state_words())
            .map(|w| bytemuck::pod_read_unaligned(bytemuck::cast_slice(w)))
            .collect())
    }

    /// The kernel's [`crate::agents::seats_word`] of every env from `seatings`: one per env, or
    /// one for all.
    pub(super) fn seats_words(&self, seatings: &[[crate::agents::Agent; 4]]) -> Result<Vec<u32>, EnvError> {
        let b = self.batch();
        if seatings.len() != 1 && seatings.len() != b {
            return Err(EnvError::WrongLength {
                what: "agent seatings",
                expected: b,
                got: seatings.len(),
            });
        }
        Ok((0..b)
            .map(|i| crate::agents::seats_word(&seatings[if seatings.len() == 1 { 0 } else { i }].map(Some)))
            .collect())
    }

    /// Words of one env's `GameState`.
    pub fn state_words(&self) -> usize {
        self.words.1
    }

    pub(super) fn check_len(&self, what: &'static str, got: usize) -> Result<(), EnvError> {
        if got != self.batch() {
            return Err(EnvError::WrongLength {
                what,
                expected: self.batch(),
                got,
            });
        }
        Ok(())
    }

    fn write_inputs(&mut self, seeds: &[u64], walls: Option<(&[[Tile; 136]], &[u32])>) {
        let (mode, uma, penalty, auto) = (
            self.config.mode.kernel(),
            self.uma,
            self.penalty,
            u32::from(self.config.auto_reset),
        );
        {
            let ins: &mut [kernel::ResetInput] = bytemuck::cast_slice_mut(&mut self.reset_inputs);
            for (i, inp) in ins.iter_mut().enumerate() {
                let (use_wall, dealer, wall) = match walls {
                    Some((w, d)) => (1, d[i], w[i].map(|t| u32::from(t.value()))),
                    None => (0, 4, [0u32; 136]),
                };
                *inp = kernel::ResetInput {
                    seed: [seeds[i] as u32, (seeds[i] >> 32) as u32],
                    mode,
                    dealer,
                    use_wall,
                    wall,
                    uma,
                    penalty,
                    auto_reset: auto,
                };
            }
        };
    }

    fn run_reset(&mut self) -> Result<&Step, EnvError> {
        let variant = self.variant();
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                cpu.reset(variant, &self.reset_inputs);
                self.step.fill(&cpu.views);
            }
            Backing::Gpu(gpu) => {
                let views = gpu.reset(&self.reset_inputs)?;
                self.step.fill(views);
            }
        }
        self.write_observations()?;
        Ok(&self.step)
    }
}
