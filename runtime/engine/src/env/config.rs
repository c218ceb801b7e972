//! What an [`Env`](super::Env) is made with, and what can be wrong with it or its inputs.

use crate::generated::kernel;
use crate::gpu::GpuError;
use crate::names::UnknownName;
use crate::Variant;

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
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Mode, UnknownName> {
        UnknownName::find("mode", name, &Mode::ALL)
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
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Backend, UnknownName> {
        UnknownName::find("backend", name, &Backend::ALL)
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
    /// Seeds every env's games: env `i` of the `r`-th [`Env::reset`](crate::env::Env::reset) gets seed words derived from
    /// `(seed, i, r)`.
    pub seed: u64,
    /// Uma by final rank in points (paid with the leftover riichi sticks in a game's last step);
    /// `None`: the variant spec's `UMA` (thousands) x 1000.
    pub uma: Option<[i32; 4]>,
    /// Reward of a seat that plays an illegal action; `None`: the spec's `ILLEGAL_ACTION_PENALTY`.
    pub penalty: Option<f32>,
    /// A finished game is replaced by a new one in the same step (its view still reports the end).
    pub auto_reset: bool,
    /// CPU threads, the calling thread included: `None` = as many as rayon's pool has (all cores
    /// by default), `Some(n)` = n. The thread that makes the env works in its pool (see the CPU
    /// backend's `pool_for`); stepped from another thread, the pool's other threads do the work.
    pub threads: Option<usize>,
    /// Observation forms written for each env's current player by every reset and step
    /// ([`Env::observation`](crate::env::Env::observation)); empty (the default) costs nothing.
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
    /// A wall given to [`Env::reset_with_walls`](crate::env::Env::reset_with_walls) or [`Env::deal`](crate::env::Env::deal) is not a full set of this
    /// variant's tiles.
    BadWall {
        /// The env it was for.
        env: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// An observer seat that is not a seat of the table (nor 4, the current player).
    BadSeat {
        /// The env it was for.
        env: usize,
        /// The seat given.
        seat: u32,
        /// Seats at the table: 4, or 3.
        seats: u32,
    },
    /// A first dealer who is not a seat of the table.
    BadDealer {
        /// The env it was for.
        env: usize,
        /// The seat given.
        dealer: u32,
        /// Seats at the table: 4, or 3.
        seats: u32,
    },
    /// A forced deal's table cannot be dealt ([`check_table`](super::check_table)).
    BadDeal {
        /// The env it was for.
        env: usize,
        /// What is wrong with it.
        reason: String,
    },
    /// A saved state given to [`Env::load_states`](crate::env::Env::load_states) failed its check.
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
            EnvError::BadDealer { env, dealer, seats } => {
                write!(f, "first dealer of env {env} is {dealer}: seats are 0..{}", seats - 1)
            }
            EnvError::BadSeat { env, seat, seats } => {
                write!(
                    f,
                    "observer seat {seat} of env {env}: seats are 0..{} (4 = the current player)",
                    seats - 1
                )
            }
            EnvError::BadDeal { env, reason } => write!(f, "deal of env {env}: {reason}"),
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
