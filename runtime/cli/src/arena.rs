//! `rinshan arena`: rates built-in agents by duplicate play (every wall set played with the
//! agents rotated through all seats) and prints, per agent, the average rank with its 95%
//! confidence interval, the rank histogram, the final score and per-round rates.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Player};
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::{BotSpec, Dialect};
use rinshan_logs::mjai::seat::MjaiEntrant;
use serde_json::json;

use crate::args::VariantArg;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// The four seats' agents, comma-separated: random, rule, greedy, defensive, or
    /// `mjai:COMMAND`, an MJAI bot run as `sh -c "COMMAND SEAT"` over its stdin and stdout
    #[arg(long, default_value = "defensive,greedy,rule,random", value_delimiter = ',')]
    agents: Vec<SeatArg>,
    /// How the MJAI bots are spoken to: app (mjai.app: a JSON array of events per line, one
    /// reaction per line) or stdio (Mortal, mjai-manue: one event per line, replies when asked)
    #[arg(long, default_value = "app")]
    mjai_dialect: Dialect,
    /// Seconds an MJAI bot may take to answer; later, it loses the game by the illegal-action penalty
    #[arg(long, default_value_t = 5.0)]
    mjai_timeout: f64,
    /// Seconds an MJAI bot may take for its first answer of a game (loading a model)
    #[arg(long, default_value_t = 60.0)]
    mjai_startup: f64,
    /// Games to play, a multiple of 4 (each wall set is played 4 times, rotated)
    #[arg(long, default_value_t = 400)]
    games: u64,
    #[command(flatten)]
    variant: VariantArg,
    /// Game length: single, east or half
    #[arg(long, default_value = "half")]
    mode: Mode,
    /// Seeds the walls
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// CPU threads (default: all cores)
    #[arg(long)]
    threads: Option<usize>,
    /// Print the report as JSON
    #[arg(long)]
    json: bool,
}

/// One seat's player as `--agents` names it.
#[derive(Clone, Debug)]
pub enum SeatArg {
    /// A built-in agent.
    Builtin(Agent),
    /// An MJAI bot's command line.
    Mjai(String),
}

impl std::str::FromStr for SeatArg {
    type Err = String;
    fn from_str(s: &str) -> Result<SeatArg, String> {
        match s.strip_prefix("mjai:") {
            Some(cmd) if cmd.trim().is_empty() => Err("`mjai:` needs the bot's command line after it".into()),
            Some(cmd) => Ok(SeatArg::Mjai(cmd.trim().to_string())),
            None => s
                .parse::<Agent>()
                .map(SeatArg::Builtin)
                .map_err(|e| format!("{e} (or mjai:COMMAND)")),
        }
    }
}

fn seconds(flag: &str, s: f64) -> Result<Duration, CliError> {
    Duration::try_from_secs_f64(s)
        .ok()
        .filter(|d| !d.is_zero())
        .ok_or_else(|| CliError::input(format!("{flag} {s} is not a positive number of seconds")))
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.agents.len() != 4 {
        return Err(CliError::input(format!(
            "--agents needs exactly 4 agents (one per seat), got {}",
            args.agents.len()
        )));
    }
    let spec = |command: &String| -> Result<MjaiEntrant, CliError> {
        Ok(MjaiEntrant {
            spec: BotSpec {
                command: command.clone(),
                dialect: args.mjai_dialect,
                timeout: seconds("--mjai-timeout", args.mjai_timeout)?,
                startup: seconds("--mjai-startup", args.mjai_startup)?,
            },
        })
    };
    let bots: Vec<(String, MjaiEntrant)> = args
        .agents
        .iter()
        .filter_map(|a| match a {
            SeatArg::Mjai(cmd) => Some(spec(cmd).map(|e| (format!("mjai:{cmd}"), e))),
            SeatArg::Builtin(_) => None,
        })
        .collect::<Result<_, _>>()?;
    if !bots.is_empty() && (args.variant.variant != Variant::Red || args.mode == Mode::Single) {
        return Err(CliError::input(
            "MJAI bots play the red rules (--variant red) in east or half games (--mode east|half)",
        ));
    }
    let mut next_bot = bots.iter();
    let players: [Player; 4] = std::array::from_fn(|p| match &args.agents[p] {
        SeatArg::Builtin(a) => Player::Builtin(*a),
        SeatArg::Mjai(_) => match next_bot.next() {
            Some((name, entrant)) => Player::Entrant { name, entrant },
            None => Player::Builtin(Agent::Random),
        },
    });
    if args.games == 0 || !args.games.is_multiple_of(4) {
        return Err(CliError::input(format!(
            "--games {} is not a positive multiple of 4: each wall set is played once per rotation",
            args.games
        )));
    }
    let arena = Arena {
        variant: args.variant.variant,
        mode: args.mode,
        players,
        sets: (args.games / 4) as usize,
        seed: args.seed,
    };
    let bar = if std::io::stderr().is_terminal() && !args.json {
        let bar = ProgressBar::new(args.games);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} games {per_sec} eta {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    } else {
        ProgressBar::hidden()
    };
    let started = Instant::now();
    let progress = |done: u64| bar.set_position(done);
    let report = match args.threads {
        Some(0) => return Err(CliError::input("--threads must be at least 1")),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| CliError::failure(format!("thread pool: {e}")))?
            .install(|| arena::run(&arena, &progress)),
        None => arena::run(&arena, &progress),
    };
    bar.finish_and_clear();
    let seconds = started.elapsed().as_secs_f64();
    if args.json {
        let standings: Vec<_> = report
            .standings
            .iter()
            .map(|s| {
                json!({
                    "agent": s.name, "games": s.games, "mean_rank": s.mean_rank, "rank_ci95": s.rank_ci95,
                    "ranks": s.ranks, "mean_score": s.mean_score, "rounds": s.rounds, "win_rate": s.win_rate,
                    "deal_in_rate": s.deal_in_rate, "call_rate": s.call_rate, "riichi_rate": s.riichi_rate,
                    "points_per_win": s.points_per_win, "illegal": s.illegal,
                })
            })
            .collect();
        let out = json!({
            "variant": arena.variant.to_string(), "mode": arena.mode.name(), "games": report.games,
            "seed": args.seed, "seconds": seconds, "games_per_second": report.games as f64 / seconds,
            "decisions": report.decisions, "standings": standings,
            "faults": report.faults.iter().map(|f| json!({
                "player": f.player, "game": f.game, "seat": f.seat, "decision": f.decision, "message": f.message,
            })).collect::<Vec<_>>(),
        });
        println!("{out:#}");
        return Ok(());
    }
    println!(
        "{} {} games ({} wall sets x 4 seatings), seed {}, {:.1}s ({:.1} games/s, {:.0} decisions/s)",
        report.games,
        arena.mode,
        arena.sets,
        args.seed,
        seconds,
        report.games as f64 / seconds,
        report.decisions as f64 / seconds
    );
    println!(
        "{:<10} {:>6} {:>15} {:>23} {:>8} {:>6} {:>7} {:>6} {:>7} {:>8}",
        "agent", "games", "avg rank (95%)", "1st/2nd/3rd/4th", "score", "win", "deal-in", "call", "riichi", "pts/win"
    );
    for s in &report.standings {
        let hist = s
            .ranks
            .map(|r| format!("{:.0}%", 100.0 * r as f64 / s.games.max(1) as f64))
            .join("/");
        println!(
            "{:<10} {:>6} {:>8.3}±{:.3} {:>23} {:>8.0} {:>5.1}% {:>6.1}% {:>5.1}% {:>6.1}% {:>8.0}",
            s.name,
            s.games,
            s.mean_rank,
            s.rank_ci95,
            hist,
            s.mean_score,
            100.0 * s.win_rate,
            100.0 * s.deal_in_rate,
            100.0 * s.call_rate,
            100.0 * s.riichi_rate,
            s.points_per_win
        );
    }
    if !report.faults.is_empty() {
        println!(
            "{} bot faults (a failed bot's game ends at once with the illegal-action penalty); the first:",
            report.faults.len()
        );
        for f in report.faults.iter().take(5) {
            println!(
                "  game {} seat {} ({}), decision {}: {}",
                f.game, f.seat, f.player, f.decision, f.message
            );
        }
    }
    Ok(())
}
