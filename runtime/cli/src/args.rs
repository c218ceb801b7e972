//! Arguments several commands take, declared once: the same names, defaults, help and errors
//! everywhere (`--variant blue` fails the same way in `selfplay`, `score` and `bench`).

use rinshan_engine::env::{Backend, Config, Mode};
use rinshan_engine::Variant;

/// `--variant`.
#[derive(clap::Args, Clone, Debug)]
pub struct VariantArg {
    /// Rule variant: a file of rules/variants/ (red, no-red)
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
