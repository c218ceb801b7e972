//! The batched environment: B independent games stepped together, on the CPU (rayon) or on the GPU
//! (wgpu, state kept on the device). Both run the same generated kernels (`game_new`, `game_step`,
//! `game_view` of `rules/kernel/game_step.rs`), so for the same seeds and actions they produce the
//! same states, masks and rewards bit for bit.
//!
//! ```no_run
//! use rinshan::env::{Backend, Config, Env, Mode};
//! let mut env = Env::new(Config::new(rinshan::Variant::Red, 64)).unwrap();
//! let step = env.reset().unwrap();
//! // pick one legal action per env from step.legal_action_mask, then:
//! # let actions = vec![0u32; 64];
//! let step = env.step(&actions).unwrap();
//! ```

mod observe;
mod snapshot;
mod table;

use rayon::prelude::*;

use crate::env_gpu::GpuEnv;
use crate::generated::kernel;
use crate::gpu::{Gpu, GpuError};
use crate::tile::Tile;
use crate::Variant;

pub(crate) use observe::observe_cpu;
pub use observe::Observer;
pub use snapshot::CHECK_WORDS;
pub use table::{Deal, DrawKind, DrawRecord, Table, WinRecord};

/// How long one game lasts (the kernel's `MODE_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    /// One hand.
    Single,
    /// East round: E1-E4 (with the variant's extensions).
    East,
    /// East and South rounds: E1-S4 (hanchan).
    Half,
}

impl Mode {
    /// The kernel's `MODE_*` value.
    pub fn kernel(self) -> u32 {
        match self {
            Mode::Single => kernel::MODE_SINGLE,
            Mode::East => kernel::MODE_EAST,
            Mode::Half => kernel::MODE_HALF,
        }
    }

    /// Every mode, shortest first.
    pub const ALL: [Mode; 3] = [Mode::Single, Mode::East, Mode::Half];

    /// The name users write: `single`, `east` or `half`.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Single => "single",
            Mode::East => "east",
            Mode::Half => "half",
        }
    }
}

impl std::fmt::Display for Mode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Mode {
    type Err = crate::UnknownName;

    fn from_str(name: &str) -> Result<Mode, crate::UnknownName> {
        crate::UnknownName::find("mode", name, &Mode::ALL)
    }
}

/// Where the games run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Backend {
    /// Native kernels on the CPU, envs split over rayon threads.
    Cpu,
    /// The WGSL kernels through wgpu, the states kept on the device.
    Gpu,
}

impl Backend {
    /// Both backends.
    pub const ALL: [Backend; 2] = [Backend::Cpu, Backend::Gpu];

    /// The name users write: `cpu` or `gpu`.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Cpu => "cpu",
            Backend::Gpu => "gpu",
        }
    }
}

impl std::fmt::Display for Backend {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Backend {
    type Err = crate::UnknownName;

    fn from_str(name: &str) -> Result<Backend, crate::UnknownName> {
        crate::UnknownName::find("backend", name, &Backend::ALL)
    }
}

/// An environment's configuration; [`Config::new`] gives the defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Config {
    /// The rules played.
    pub variant: Variant,
    /// How long a game lasts.
    pub mode: Mode,
    /// Number of games stepped together (B).
    pub batch: usize,
    /// Where the games run.
    pub backend: Backend,
    /// Seeds every env's games: env `i` of the `r`-th [`Env::reset`] gets seed words derived from
    /// `(seed, i, r)`.
    pub seed: u64,
    /// Uma by final rank in points (paid with the leftover riichi sticks in a game's last step);
    /// `None`: the variant spec's `UMA` (thousands) x 1000.
    pub uma: Option<[i32; 4]>,
    /// Reward of a seat that plays an illegal action; `None`: the spec's `ILLEGAL_ACTION_PENALTY`.
    pub penalty: Option<f32>,
    /// A finished game is replaced by a new one in the same step (its view still reports the end).
    pub auto_reset: bool,
    /// CPU threads: `None` = rayon's global pool (all cores), `Some(n)` = a pool of n threads.
    pub threads: Option<usize>,
    /// Observation forms written for each env's current player by every reset and step
    /// ([`Env::observation`]); empty (the default) costs nothing.
    pub observe: Vec<crate::observe::Form>,
    /// Hero mode: who plays each seat, per env (or one entry for every env); `None` = the caller.
    /// A step then plays the caller's action and the built-in agents' decisions until one of the
    /// caller's seats must decide or the game ends, adding up the rewards. After a reset, a deal or a
    /// finished game an agent may be the first to move: `current_player` then names its seat and
    /// the next step's action for that env is ignored (the agents play up to the caller's turn).
    /// Empty (the default): the caller plays every seat.
    pub agents: Vec<[Option<crate::agents::Agent>; 4]>,
}

impl Config {
    /// Half games on the CPU with all threads, seed 0, the spec's uma and penalty, no auto-reset.
    pub fn new(variant: Variant, batch: usize) -> Config {
        Config {
            variant,
            mode: Mode::Half,
            batch,
            backend: Backend::Cpu,
            seed: 0,
            uma: None,
            penalty: None,
            auto_reset: false,
            threads: None,
            observe: Vec::new(),
            agents: Vec::new(),
        }
    }
}

/// What was wrong with a configuration or an input.
#[derive(Debug, Clone, PartialEq)]
pub enum EnvError {
    /// `batch` is 0.
    EmptyBatch,
    /// The batch is larger than the backend can step at once.
    BatchTooLarge {
        /// The batch asked for.
        batch: usize,
        /// The backend's largest batch.
        max: usize,
    },
    /// `threads: Some(0)`, or the thread pool could not be made.
    BadThreads(String),
    /// A non-finite penalty.
    BadPenalty(f32),
    /// A per-env input had the wrong number of entries.
    WrongLength {
        /// The input: `actions`, `seeds`, `walls`, `dealers` or `deals`.
        what: &'static str,
        /// The batch size.
        expected: usize,
        /// The entries given.
        got: usize,
    },
    /// A wall given to [`Env::reset_with_walls`] or [`Env::deal`] is not a full set of this
    /// variant's tiles.
    BadWall {
        /// The env it was for.
        env: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// An observer seat outside 0..3 (4 = the current player, where a per-env seat is given).
    BadSeat {
        /// The env it was for.
        env: usize,
        /// The seat given.
        seat: u32,
    },
    /// A dealer outside 0..3.
    BadDealer {
        /// The env it was for.
        env: usize,
        /// The seat given.
        dealer: u32,
    },
    /// A saved state given to [`Env::load_states`] failed its check.
    BadState {
        /// The env it was for.
        env: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// The GPU backend could not start or failed.
    Gpu(GpuError),
}

impl std::fmt::Display for EnvError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EnvError::EmptyBatch => f.write_str("the batch size must be at least 1"),
            EnvError::BatchTooLarge { batch, max } => {
                write!(f, "batch {batch} is larger than this backend's maximum {max}")
            }
            EnvError::BadThreads(m) => write!(f, "bad thread count: {m}"),
            EnvError::BadPenalty(p) => write!(f, "the illegal-action penalty must be finite, not {p}"),
            EnvError::WrongLength { what, expected, got } => {
                write!(f, "{got} {what} for a batch of {expected}: give exactly one per env")
            }
            EnvError::BadWall { env, reason } => write!(f, "wall of env {env}: {reason}"),
            EnvError::BadDealer { env, dealer } => {
                write!(f, "first dealer of env {env} is {dealer}: seats are 0..3")
            }
            EnvError::BadSeat { env, seat } => {
                write!(
                    f,
                    "observer seat {seat} of env {env}: seats are 0..3 (4 = the current player)"
                )
            }
            EnvError::BadState { env, reason } => write!(f, "saved state of env {env}: {reason}"),
            EnvError::Gpu(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for EnvError {}

impl From<GpuError> for EnvError {
    fn from(e: GpuError) -> Self {
        EnvError::Gpu(e)
    }
}

/// The outcome of a reset or a step, as flat batch arrays (index = env).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Step {
    /// The seat to act next (0..3).
    pub current_player: Vec<u32>,
    /// Legal actions of `current_player`, a bitset over the variant's action ids (bit `a % 32` of
    /// word `a / 32`).
    pub legal_action_mask: Vec<[u32; 3]>,
    /// This step's score change per seat in units of 100 points (uma in a game's last step), or
    /// the penalty for the seat that played an illegal action.
    pub rewards: Vec<[f32; 4]>,
    /// The game ended in this step (with auto-reset, a new one has already started).
    pub terminated: Vec<bool>,
    /// The game was cut short rather than ended by the rules. The rules end every game, so this
    /// stays false; it completes the usual RL step tuple.
    pub truncated: Vec<bool>,
    /// This step's action was illegal (the game ended with the penalty).
    pub illegal: Vec<bool>,
    /// What the step settled: the kernel's `EVENT_*` bits (see [`events`]).
    pub events: Vec<u32>,
    /// Seats that won in this step, one bit per seat.
    pub winners: Vec<u32>,
    /// The seat that dealt in + 1 (0 = none).
    pub deal_in: Vec<u32>,
    /// Yaku of the winning hands: bit `y` of word `y / 32` for yaku id `y` (`host::YAKU_NAMES`).
    pub yaku: Vec<[u32; 2]>,
    /// Rounds played in the (finished) game so far.
    pub rounds: Vec<u32>,
    /// In the step that ends a game by the rules: each seat's final place (0 = first; ties go to
    /// the seat nearer the game's first dealer), as uma paid it. Zeros elsewhere: other steps,
    /// later steps of a finished game, and a game ended by an illegal action (it has no final
    /// standings).
    pub ranks: Vec<[u8; 4]>,
}

/// The `events` bits of a [`Step`]: the kernel's `EVENT_*`.
pub mod events {
    use crate::generated::kernel as k;
    /// A round ended by ron (one or more winners).
    pub const RON: u32 = k::EVENT_RON;
    /// A round ended by tsumo.
    pub const TSUMO: u32 = k::EVENT_TSUMO;
    /// The wall ran out.
    pub const EXHAUSTIVE_DRAW: u32 = k::EVENT_EXHAUSTIVE_DRAW;
    /// An abortive draw (kyuushu kyuuhai, four riichi, triple ron, four kans, four winds).
    pub const ABORTIVE_DRAW: u32 = k::EVENT_ABORTIVE_DRAW;
    /// The game ended.
    pub const GAME_OVER: u32 = k::EVENT_GAME_OVER;
    /// Nagashi mangan was paid at an exhaustive draw.
    pub const NAGASHI: u32 = k::EVENT_NAGASHI;
    /// Any of the bits of a step that ends a round.
    pub const ROUND_OVER: u32 = RON | TSUMO | EXHAUSTIVE_DRAW | ABORTIVE_DRAW;
}

impl Step {
    fn with_batch(b: usize) -> Step {
        Step {
            current_player: vec![0; b],
            legal_action_mask: vec![[0; 3]; b],
            rewards: vec![[0.0; 4]; b],
            terminated: vec![false; b],
            truncated: vec![false; b],
            illegal: vec![false; b],
            events: vec![0; b],
            winners: vec![0; b],
            deal_in: vec![0; b],
            yaku: vec![[0; 2]; b],
            rounds: vec![0; b],
            ranks: vec![[0; 4]; b],
        }
    }

    /// Legal action ids of env `i`, in increasing order.
    pub fn legal_actions(&self, i: usize) -> impl Iterator<Item = u32> + '_ {
        let mask = self.legal_action_mask[i];
        (0..96u32).filter(move |a| mask[(a / 32) as usize] >> (a % 32) & 1 == 1)
    }

    /// Fills the arrays from kernel `StepView` words (one record per env).
    pub(crate) fn fill(&mut self, view_words: &[u32]) {
        {
            let views: &[kernel::StepView] = bytemuck::cast_slice(view_words);
            for (i, w) in views.iter().enumerate() {
                self.current_player[i] = w.current_player;
                self.legal_action_mask[i] = w.mask;
                self.rewards[i] = w.rewards;
                self.terminated[i] = w.terminated != 0;
                self.truncated[i] = w.truncated != 0;
                self.illegal[i] = w.illegal != 0;
                self.events[i] = w.events;
                self.winners[i] = w.winners;
                self.deal_in[i] = w.deal_in;
                self.yaku[i] = w.yaku;
                self.rounds[i] = w.rounds;
                self.ranks[i] = std::array::from_fn(|p| (w.ranks >> (p as u32 * kernel::RANK_SHIFT)) as u8);
            }
        }
    }
}

/// The yaku names of `variant`, indexed by yaku id (the bits of [`Step::yaku`]).
pub fn yaku_names(variant: Variant) -> &'static [&'static str] {
    with_variant!(variant, v => &v::host::YAKU_NAMES)
}

/// The action ids of `variant` by name, from its `[actions]` layout: `discard_<tile>` (a red five
/// is `discard_0m`), `self_kan_<tile type>`, then one id per other kind (`tsumogiri`, `riichi`,
/// `pon_red`, `pass` ...).
pub fn action_names(variant: Variant) -> Vec<String> {
    let blocks: &[(&str, u32, u32)] = with_variant!(variant, v => &v::host::ACTION_BLOCKS);
    let mut names = Vec::new();
    for &(kind, _, count) in blocks {
        if count == 1 {
            names.push(kind.to_string());
            continue;
        }
        for i in 0..count {
            let tile = u8::try_from(i).ok().and_then(Tile::from_value);
            names.push(match tile {
                Some(t) => format!("{kind}_{t}"),
                None => format!("{kind}_{i}"),
            });
        }
    }
    names
}

/// Sizes of the kernel records, in 32-bit words: (ResetInput, GameState, StepView).
pub(crate) const RECORD_WORDS: (usize, usize, usize) = (
    crate::hand::words::<kernel::ResetInput>(),
    crate::hand::words::<kernel::GameState>(),
    crate::hand::words::<kernel::StepView>(),
);

/// The uma `config` pays: its own, or the spec's `UMA` (thousands) x 1000.
fn uma_of(config: &Config) -> [i32; 4] {
    config
        .uma
        .unwrap_or(with_variant!(config.variant, v => v::host::UMA.map(|x| x * 1000)))
}

/// splitmix64's finalizer.
fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The 64-bit seed of env `index` at the `epoch`-th [`Env::reset`] of an env seeded with `seed`.
pub fn env_seed(seed: u64, index: u64, epoch: u64) -> u64 {
    let a = mix64(seed.wrapping_add(0x9E37_79B9_7F4A_7C15));
    let b = mix64(a ^ index.wrapping_mul(0xD6E8_FEB8_6659_FD93));
    mix64(b ^ epoch.wrapping_mul(0xA076_1D64_78BD_642F).wrapping_add(1))
}

/// Checks that `wall` holds exactly this variant's 136 tiles: every type 4 times, counting a red
/// five as a five, and with red fives (only in a variant that has them) once each.
pub(crate) fn check_wall(variant: Variant, wall: &[Tile; 136]) -> Result<(), String> {
    let red_fives = with_variant!(variant, v => v::RED_FIVES);
    let mut counts = [0u32; 34];
    let mut reds = [0u32; 3];
    for (i, &t) in wall.iter().enumerate() {
        if t.is_red() && !red_fives {
            return Err(format!("tile {i} is a red five ({t}), but variant {variant} has none"));
        }
        if let (true, Some(suit)) = (t.is_red(), t.kind().suit()) {
            reds[usize::from(suit)] += 1;
        }
        counts[t.kind().index()] += 1;
    }
    if let Some(t) = counts.iter().position(|&n| n != 4) {
        return Err(format!(
            "{} copies of tile type {t}: every type appears 4 times",
            counts[t]
        ));
    }
    if red_fives {
        if let Some(s) = reds.iter().position(|&n| n != 1) {
            return Err(format!(
                "{} red fives of suit {s}: this variant has exactly one per suit (value {})",
                reds[s],
                34 + s
            ));
        }
    }
    Ok(())
}

/// The CPU backend: every env's `GameState` as raw kernel words, stepped with rayon.
struct CpuEnv {
    states: Vec<u32>,
    views: Vec<u32>,
    pool: Option<rayon::ThreadPool>,
    serial: bool,
}

/// Below this many envs a step runs on the calling thread (rayon's hand-off costs more).
const PARALLEL_MIN: usize = 32;
/// Envs per rayon task.
const CHUNK: usize = 8;

impl CpuEnv {
    /// Runs `job` on the env's thread pool when it has one (and is not serial).
    fn install<R: Send>(&self, job: impl FnOnce() -> R + Send) -> R {
        match &self.pool {
            Some(pool) if !self.serial => pool.install(job),
            _ => job(),
        }
    }

    fn reset(&mut self, variant: Variant, inputs: &[u32]) {
        let serial = self.serial;
        let states = &mut self.states;
        let views = &mut self.views;
        let mut job = move || {
            with_variant!(variant, v => {
                let ins: &[kernel::ResetInput] = bytemuck::cast_slice(inputs);
                let sts: &mut [kernel::GameState] = bytemuck::cast_slice_mut(states);
                let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(views);
                let one = |((s, w), i): ((&mut kernel::GameState, &mut kernel::StepView), &kernel::ResetInput)| {
                    *s = v::game_new(*i);
                    *w = v::game_view(*s);
                };
                if serial {
                    sts.iter_mut().zip(vws.iter_mut()).zip(ins).for_each(one);
                } else {
                    sts.par_iter_mut().zip(vws.par_iter_mut()).zip(ins.par_iter()).with_min_len(CHUNK).for_each(one);
                }
            })
        };
        match &self.pool {
            Some(pool) if !serial => pool.install(job),
            _ => job(),
        }
    }

    fn step(&mut self, variant: Variant, actions: &[u32], play: bool) {
        let serial = self.serial;
        let states = &mut self.states;
        let views = &mut self.views;
        let mut job = move || {
            with_variant!(variant, v => {
                let sts: &mut [kernel::GameState] = bytemuck::cast_slice_mut(states);
                let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(views);
                let one = |((s, w), a): ((&mut kernel::GameState, &mut kernel::StepView), &u32)| {
                    if play {
                        v::game_play(s, *a);
                    } else {
                        v::game_step(s, *a);
                    }
                    *w = v::game_view(*s);
                };
                if serial {
                    sts.iter_mut().zip(vws.iter_mut()).zip(actions).for_each(one);
                } else {
                    sts.par_iter_mut().zip(vws.par_iter_mut()).zip(actions.par_iter()).with_min_len(CHUNK).for_each(one);
                }
            })
        };
        match &self.pool {
            Some(pool) if !serial => pool.install(job),
            _ => job(),
        }
    }
}

enum Backing {
    Cpu(CpuEnv),
    Gpu(Box<GpuEnv>),
}

/// A batch of B games. See the module docs.
pub struct Env {
    config: Config,
    uma: [i32; 4],
    penalty: f32,
    num_actions: u32,
    words: (usize, usize, usize),
    backing: Backing,
    step: Step,
    /// ResetInput words of every env, reused by each reset.
    reset_inputs: Vec<u32>,
    epoch: u64,
    /// The per-step observations, one buffer per form of `config.observe`.
    observations: Vec<Vec<u32>>,
    /// The buffer [`Env::observe`] returns.
    observed: Vec<u8>,
    /// Hero mode's per-env step arguments.
    play_args: Vec<u32>,
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
            Some(gpu) => Backing::Gpu(Box::new(GpuEnv::new(gpu, variant, b, words, table::DEAL_WORDS)?)),
            None => {
                let pool = match config.threads {
                    Some(n) if n > 1 => Some(
                        rayon::ThreadPoolBuilder::new()
                            .num_threads(n)
                            .build()
                            .map_err(|e| EnvError::BadThreads(e.to_string()))?,
                    ),
                    _ => None,
                };
                Backing::Cpu(CpuEnv {
                    states: vec![0; b * words.1],
                    views: vec![0; b * words.2],
                    pool,
                    serial: config.threads == Some(1) || b < PARALLEL_MIN,
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
    /// first dealers (0..3). Later rounds shuffle from the seeds [`Env::reset`] would use.
    pub fn reset_with_walls(&mut self, walls: &[[Tile; 136]], dealers: &[u32]) -> Result<&Step, EnvError> {
        self.check_len("walls", walls.len())?;
        self.check_len("dealers", dealers.len())?;
        for (env, wall) in walls.iter().enumerate() {
            check_wall(self.variant(), wall).map_err(|reason| EnvError::BadWall { env, reason })?;
        }
        if let Some(env) = dealers.iter().position(|&d| d > 3) {
            return Err(EnvError::BadDealer {
                env,
                dealer: dealers[env],
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
            // The kernel's hero-mode argument: the action in the low byte, the seating above.
            for (i, (arg, &a)) in self.play_args.iter_mut().zip(actions).enumerate() {
                let seats = &self.config.agents[if self.config.agents.len() == 1 { 0 } else { i }];
                *arg = a.min(255) | (crate::agents::seats_word(seats) << 8);
            }
        }
        let actions = if play { &self.play_args[..] } else { actions };
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                cpu.step(variant, actions, play);
                self.step.fill(&cpu.views);
            }
            Backing::Gpu(gpu) => {
                let views = gpu.step(actions, play)?;
                self.step.fill(views);
            }
        }
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

    /// Words of one env's `GameState`.
    pub fn state_words(&self) -> usize {
        self.words.1
    }

    fn check_len(&self, what: &'static str, got: usize) -> Result<(), EnvError> {
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
