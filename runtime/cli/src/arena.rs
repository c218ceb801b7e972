//! `rinshan arena`: rates built-in agents by duplicate play (every wall set played with the
//! agents rotated through all seats) and prints, per agent, the average rank with its 95%
//! confidence interval, the rank histogram, the final score and per-round rates.

use std::io::IsTerminal;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Player};
use rinshan_engine::env::Mode;
use rinshan_logs::mjai::seat::MjaiEntrant;
use serde_json::json;

use crate::args::{MjaiArgs, SeatArg, VariantArg};
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// The four seats' agents, comma-separated: random, rule, greedy, defensive, or
    /// `mjai:COMMAND`, an MJAI bot run as `sh -c "COMMAND SEAT"` over its stdin and stdout
    #[arg(long, default_value = "defensive,greedy,rule,random", value_delimiter = ',')]
    agents: Vec<SeatArg>,
    #[command(flatten)]
    mjai: MjaiArgs,
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

pub fn run(args: Args) -> Result<(), CliError> {
    if args.agents.len() != 4 {
        return Err(CliError::input(format!(
            "--agents needs exactly 4 agents (one per seat), got {}",
            args.agents.len()
        )));
    }
    let bots: Vec<(String, MjaiEntrant)> = args
        .agents
        .iter()
        .filter_map(|a| match a {
            SeatArg::Mjai(cmd) => Some(args.mjai.entrant(cmd).map(|e| (a.to_string(), e))),
            SeatArg::Builtin(_) => None,
        })
        .collect::<Result<_, _>>()?;
    if !bots.is_empty() {
        MjaiArgs::check_rules(args.variant.variant, args.mode, None)?;
    }
    let mut next_bot = bots.iter();
    let players: [Player; 4] = std::array::from_fn(|p| match &args.agents[p] {
        SeatArg::Builtin(a) => Player::Builtin(*a),
        SeatArg::Mjai(_) => match next_bot.next() {
            Some((name, entrant)) => Player::Entrant { name, entrant },
            None => Player::Builtin(Agent::Random),
        },
    });
    if args.variant.variant.seats() != 4 {
        return Err(CliError::input(format!(
            "--variant {}: the duplicate arena rotates four players over four seats; three-player \
             games are not rated yet",
            args.variant.variant
        )));
    }
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
