//! Arguments several commands take, declared once: the same names, defaults, help and errors
//! everywhere (`--variant blue` fails the same way in `selfplay`, `score` and `bench`).

use std::time::Duration;

use rinshan_engine::agents::Agent;
use rinshan_engine::env::{Backend, Config, Mode};
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::{check_games, wait, BotSpec, Dialect, Unplayable};
use rinshan_logs::mjai::seat::MjaiEntrant;
use rinshan_net::{Net, NetAgent};

use crate::error::CliError;

/// `--variant`.
#[derive(clap::Args, Clone, Debug)]
pub struct VariantArg {
    /// Rule variant: the name of a file of rules/variants/, e.g. red, mjsoul, mleague, wrc, no-red, sanma, mjsoul-sanma
    #[arg(long, default_value = "red")]
    pub variant: Variant,
}

/// `--backend`.
#[derive(clap::Args, Clone, Debug)]
pub struct BackendArg {
    /// cpu or gpu
    #[arg(long, default_value = "cpu")]
    pub backend: Backend,
}

/// `--format` of a written log.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatArg {
    /// tenhou.net/6 JSON, one round per line (`.json`)
    Tenhou,
    /// MJAI events, one per line (`.mjson`)
    Mjai,
}

impl FormatArg {
    /// The logs crate's format.
    pub fn format(self) -> rinshan_logs::Format {
        match self {
            FormatArg::Tenhou => rinshan_logs::Format::Tenhou,
            FormatArg::Mjai => rinshan_logs::Format::Mjai,
        }
    }

    /// The file extension a log of this format is written with.
    pub fn extension(self) -> &'static str {
        match self {
            FormatArg::Tenhou => "json",
            FormatArg::Mjai => "mjson",
        }
    }
}

/// What a run of whole games takes: variant, mode, backend, seed, threads.
#[derive(clap::Args, Clone, Debug)]
pub struct GameArgs {
    #[command(flatten)]
    pub variant: VariantArg,
    /// Game length: single (one hand), east or half (East and South rounds)
    #[arg(long, default_value = "half")]
    pub mode: Mode,
    #[command(flatten)]
    pub backend: BackendArg,
    /// Seeds the walls and the policy: the same seed plays the same games
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// CPU threads (default: all cores)
    #[arg(long)]
    pub threads: Option<usize>,
}

impl GameArgs {
    /// The environment these arguments describe, `batch` games stepped together, each game
    /// followed at once by the next (auto-reset).
    pub fn config(&self, batch: usize) -> Config {
        Config {
            mode: self.mode,
            backend: self.backend.backend,
            seed: self.seed,
            threads: self.threads,
            auto_reset: true,
            ..Config::new(self.variant.variant, batch)
        }
    }
}

/// One seat's player as `--agents` names it.
#[derive(Clone, Debug)]
pub enum SeatArg {
    /// A built-in agent.
    Builtin(Agent),
    /// An MJAI bot's command line.
    Mjai(String),
    /// The look-ahead agent with its settings.
    Search(rinshan_search::Options),
    /// A trained net's file (examples/train/export.py), played on the CPU.
    Net(std::path::PathBuf),
}

impl std::str::FromStr for SeatArg {
    type Err = String;
    fn from_str(s: &str) -> Result<SeatArg, String> {
        match s.strip_prefix("mjai:") {
            Some(cmd) if cmd.trim().is_empty() => Err("`mjai:` needs the bot's command line after it".into()),
            Some(cmd) => Ok(SeatArg::Mjai(cmd.trim().to_string())),
            None if s.starts_with("net:") => match s["net:".len()..].trim() {
                "" => {
                    Err("`net:` needs the path of a net's file after it (examples/train/export.py writes one)".into())
                }
                path => Ok(SeatArg::Net(path.into())),
            },
            None if s == "search" || s.starts_with("search:") => s.parse().map(SeatArg::Search),
            None => s
                .parse::<Agent>()
                .map(SeatArg::Builtin)
                .map_err(|e| format!("{e} (or search, search:rollouts=N, net:PATH, mjai:COMMAND)")),
        }
    }
}

/// The net exported at `path`, playing `variant`.
pub fn net_agent(path: &std::path::Path, variant: Variant) -> Result<NetAgent, CliError> {
    let net = Net::load(path).map_err(CliError::input)?;
    NetAgent::new(std::sync::Arc::new(net), variant).map_err(CliError::input)
}

fn seconds(flag: &str, s: f64) -> Result<Duration, CliError> {
    wait(s).ok_or_else(|| CliError::input(format!("{flag} {s} is not a positive number of seconds")))
}

impl std::fmt::Display for SeatArg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SeatArg::Builtin(a) => write!(f, "{a}"),
            SeatArg::Mjai(cmd) => write!(f, "mjai:{cmd}"),
            SeatArg::Search(o) => f.write_str(&o.name()),
            SeatArg::Net(path) => write!(f, "net:{}", path.display()),
        }
    }
}

/// How `mjai:` seats are run.
#[derive(clap::Args, Clone, Debug)]
pub struct MjaiArgs {
    /// How the MJAI bots are spoken to: app (mjai.app: a JSON array of events per line, one
    /// reaction per line) or stdio (Mortal, mjai-manue: one event per line, replies when asked)
    #[arg(long, default_value = "app")]
    pub mjai_dialect: Dialect,
    /// Seconds an MJAI bot may take to answer; later, it loses the game by the illegal-action penalty
    #[arg(long, default_value_t = 5.0)]
    pub mjai_timeout: f64,
    /// Seconds an MJAI bot may take for its first answer of a game (loading a model)
    #[arg(long, default_value_t = 60.0)]
    pub mjai_startup: f64,
}

impl MjaiArgs {
    /// The seat player that runs `command`.
    pub fn entrant(&self, command: &str) -> Result<MjaiEntrant, CliError> {
        Ok(MjaiEntrant {
            spec: BotSpec {
                command: command.to_string(),
                dialect: self.mjai_dialect,
                timeout: seconds("--mjai-timeout", self.mjai_timeout)?,
                startup: seconds("--mjai-startup", self.mjai_startup)?,
            },
        })
    }

    /// Why MJAI bots cannot play these games, if they cannot.
    pub fn check_rules(variant: Variant, mode: Mode, backend: Option<Backend>) -> Result<(), CliError> {
        check_games(variant, mode, backend.unwrap_or(Backend::Cpu)).map_err(|e| {
            CliError::input(match e {
                Unplayable::Rules => {
                    "MJAI bots play Tenhou's rules (--variant red, or sanma for three players) in east or half games (--mode east|half)"
                }
                Unplayable::Backend => {
                    "MJAI bots need --backend cpu: each bot follows its game's state after every step"
                }
            })
        })
    }
}

/// `work` on `threads` CPU threads (`--threads`; `None`: all cores), in a rayon pool of its own.
pub fn on_threads<T: Send>(threads: Option<usize>, work: impl FnOnce() -> T + Send) -> Result<T, CliError> {
    match threads {
        Some(0) => Err(CliError::input("--threads must be at least 1")),
        Some(n) => Ok(rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| CliError::failure(format!("thread pool: {e}")))?
            .install(work)),
        None => Ok(work()),
    }
}
