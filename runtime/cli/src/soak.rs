//! `rinshan soak`: many whole games of every variant, by the built-in agents and by a uniformly
//! random policy, with every invariant checked after every step (see `rinshan-soak`); prints
//! games, steps and violations per run, and writes each violation (seed and actions, and the
//! game's Tenhou log when that is what failed) to `--out`.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_engine::agents::Agent;
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_soak::{Outcome, Players, Soak};
use serde_json::json;

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Games per variant and players
    #[arg(long, default_value_t = 1000)]
    games: u64,
    /// Variants to play, comma-separated (default: all)
    #[arg(long, value_delimiter = ',')]
    variants: Vec<Variant>,
    /// Who plays, comma-separated: `agents` (the four built-in agents rotated over the seats) and
    /// `uniform` (a uniformly random legal policy)
    #[arg(long, value_delimiter = ',', default_value = "agents,uniform")]
    players: Vec<String>,
    /// Game length: single, east or half
    #[arg(long, default_value = "half")]
    mode: Mode,
    /// Seeds the games: game g of a run is dealt from a seed derived from (seed, g)
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Check the deciding seat's observation against hidden resampling every this many decisions
    /// (0: never)
    #[arg(long, default_value_t = 64)]
    leak_every: u64,
    /// Where each violation is written (a JSON file with the game's seed and actions)
    #[arg(long, default_value = "soak-violations")]
    out: PathBuf,
    /// CPU threads (default: all cores)
    #[arg(long)]
    threads: Option<usize>,
    /// Print the summary as JSON
    #[arg(long)]
    json: bool,
}

fn players(name: &str) -> Result<Players, CliError> {
    match name {
        "agents" => Ok(Players::Agents([
            Agent::Defensive,
            Agent::Greedy,
            Agent::Rule,
            Agent::Random,
        ])),
        "uniform" => Ok(Players::Uniform),
        other => Err(CliError::input(format!("--players {other}: `agents` or `uniform`"))),
    }
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.games == 0 {
        return Err(CliError::input("--games must be at least 1"));
    }
    let variants = if args.variants.is_empty() {
        Variant::ALL.to_vec()
    } else {
        args.variants.clone()
    };
    let who: Vec<Players> = args.players.iter().map(|p| players(p)).collect::<Result<_, _>>()?;
    let pool = match args.threads {
        Some(0) => return Err(CliError::input("--threads must be at least 1")),
        Some(n) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| CliError::failure(format!("thread pool: {e}")))?,
        ),
        None => None,
    };
    let runs: Vec<Soak> = variants
        .iter()
        .flat_map(|&variant| {
            who.iter().map(move |&players| Soak {
                variant,
                mode: args.mode,
                players,
                games: args.games,
                seed: args.seed,
                leak_every: args.leak_every,
            })
        })
        .collect();
    let bar = if args.json || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::new(args.games * runs.len() as u64);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} games  {per_sec}  eta {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    };
    let mut results: Vec<(&Soak, Outcome, f64)> = Vec::new();
    for (i, soak) in runs.iter().enumerate() {
        let base = i as u64 * args.games;
        let progress = |done: u64| bar.set_position(base + done);
        let started = Instant::now();
        let outcome = match &pool {
            Some(p) => p.install(|| rinshan_soak::run(soak, &progress)),
            None => rinshan_soak::run(soak, &progress),
        };
        results.push((soak, outcome, started.elapsed().as_secs_f64()));
    }
    bar.finish_and_clear();
    let mut written = Vec::new();
    for (soak, o, _) in &results {
        for v in &o.violations {
            std::fs::create_dir_all(&args.out)
                .map_err(|e| CliError::failure(format!("--out {}: {e}", args.out.display())))?;
            let path = args.out.join(format!(
                "{}-{}-game-{}.json",
                soak.variant,
                players_name(soak.players),
                v.game
            ));
            let text = serde_json::to_string_pretty(v).map_err(CliError::failure)?;
            std::fs::write(&path, text).map_err(|e| CliError::failure(format!("{}: {e}", path.display())))?;
            written.push(path.clone());
            if let Some(log) = &v.log {
                // Beside the violation, the log `rinshan replay` and the replay page read.
                let log_path = path.with_extension("tenhou.json");
                std::fs::write(&log_path, log)
                    .map_err(|e| CliError::failure(format!("{}: {e}", log_path.display())))?;
                written.push(log_path);
            }
        }
    }
    let violations: usize = results.iter().map(|r| r.1.violations.len()).sum();
    if args.json {
        let rows: Vec<_> = results
            .iter()
            .map(|(s, o, secs)| {
                json!({
                    "variant": s.variant.to_string(), "mode": s.mode.name(), "players": s.players.to_string(),
                    "games": o.games, "steps": o.steps, "leak_checks": o.leak_checks, "replayed": o.replayed,
                    "violations": o.violations.len(), "seconds": secs,
                })
            })
            .collect();
        println!(
            "{}",
            json!({ "seed": args.seed, "runs": rows, "violations": violations })
        );
    } else {
        println!(
            "{:<7} {:<6} {:<30} {:>9} {:>12} {:>11} {:>9} {:>10} {:>9}",
            "variant", "mode", "players", "games", "steps", "leak checks", "replayed", "violations", "seconds"
        );
        for (s, o, secs) in &results {
            println!(
                "{:<7} {:<6} {:<30} {:>9} {:>12} {:>11} {:>9} {:>10} {:>9.1}",
                s.variant.to_string(),
                s.mode.name(),
                s.players.to_string(),
                o.games,
                o.steps,
                o.leak_checks,
                o.replayed,
                o.violations.len(),
                secs
            );
        }
        for (_, o, _) in &results {
            for v in o.violations.iter().take(5) {
                println!(
                    "  {} {} game {} (seed {}), step {}: {}",
                    v.variant, v.players, v.game, v.seed, v.step, v.what
                );
            }
        }
        for path in &written {
            println!("  written: {}", path.display());
        }
    }
    if violations > 0 {
        return Err(CliError::failure(format!("{violations} violation(s)")));
    }
    Ok(())
}

fn players_name(p: Players) -> &'static str {
    match p {
        Players::Agents(_) => "agents",
        Players::Uniform => "uniform",
    }
}
