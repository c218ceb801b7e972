//! `rinshan arena`: rates built-in agents by duplicate play (every wall set played with the
//! agents rotated through all seats) and prints, per agent, the average rank with its 95%
//! confidence interval, the rank histogram, the final score and per-round rates.

use std::io::IsTerminal;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Entrant, Player};
use rinshan_engine::env::Mode;
use rinshan_logs::mjai::seat::MjaiEntrant;
use rinshan_net::NetAgent;
use rinshan_search::SearchEntrant;
use serde_json::json;

use crate::args::{net_agent, on_threads, MjaiArgs, SeatArg, VariantArg};
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// The seats' agents, comma-separated, one per seat: random, rule, greedy, defensive, the
    /// look-ahead `search` (or `search:rollouts=N:ms=M:base=AGENT:margin=Z:seed=S:backend=gpu`:
    /// play-outs per decision, a time cap, the agent of the play-outs, how sure it must be to
    /// differ from it, where the play-outs run), `net:PATH`, a trained net's file
    /// (examples/train/export.py) played on the CPU, or `mjai:COMMAND`, an MJAI bot run as
    /// `sh -c "COMMAND SEAT"` over its stdin and stdout
    /// [default: defensive,greedy,rule,random; three players: defensive,greedy,rule]
    #[arg(long, value_delimiter = ',')]
    agents: Option<Vec<SeatArg>>,
    #[command(flatten)]
    mjai: MjaiArgs,
    /// Games to play, a multiple of the seat count (each wall set is played once per seat, rotated)
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
    /// Exit with status 1, after the report, when an MJAI bot faulted in more than this share of
    /// the games it played (0 to 1). A faulted game ends at once with the illegal-action penalty,
    /// so past one half the bot's standing measures its faults, not its play (a bot that cannot
    /// start, e.g. its Python lacks a module, faults in every game). 1 never fails the run
    #[arg(long, default_value_t = 0.5)]
    max_fault_rate: f64,
}

/// The built-in agents of the seats when `--agents` is not given (the first ones at three seats).
const DEFAULT_AGENTS: [Agent; 4] = [Agent::Defensive, Agent::Greedy, Agent::Rule, Agent::Random];

pub fn run(args: Args) -> Result<(), CliError> {
    let seats = args.variant.variant.seats() as usize;
    let agents: Vec<SeatArg> = match &args.agents {
        Some(agents) => agents.clone(),
        None => DEFAULT_AGENTS[..seats].iter().map(|&a| SeatArg::Builtin(a)).collect(),
    };
    if agents.len() != seats {
        return Err(CliError::input(format!(
            "--agents needs exactly {seats} agents (one per seat of {}), got {}",
            args.variant.variant,
            agents.len()
        )));
    }
    let bots: Vec<(String, MjaiEntrant)> = agents
        .iter()
        .filter_map(|a| match a {
            SeatArg::Mjai(cmd) => Some(args.mjai.entrant(cmd).map(|e| (a.to_string(), e))),
            _ => None,
        })
        .collect::<Result<_, _>>()?;
    let nets: Vec<(String, NetAgent)> = agents
        .iter()
        .filter_map(|a| match a {
            SeatArg::Net(path) => Some(net_agent(path, args.variant.variant).map(|n| (a.to_string(), n))),
            _ => None,
        })
        .collect::<Result<_, _>>()?;
    let searches: Vec<(String, SearchEntrant)> = agents
        .iter()
        .filter_map(|a| match a {
            SeatArg::Search(o) => Some((a.to_string(), SearchEntrant::new(*o))),
            _ => None,
        })
        .collect();
    if !bots.is_empty() {
        MjaiArgs::check_rules(args.variant.variant, args.mode, None)?;
    }
    let (mut next_bot, mut next_search, mut next_net) = (bots.iter(), searches.iter(), nets.iter());
    // The player of each seat that is not built in, in the order of --agents.
    let mut next_entrant = |a: &SeatArg| -> Option<(&str, &dyn Entrant)> {
        match a {
            SeatArg::Builtin(_) => None,
            SeatArg::Mjai(_) => next_bot.next().map(|(n, e)| (n.as_str(), e as &dyn Entrant)),
            SeatArg::Search(_) => next_search.next().map(|(n, e)| (n.as_str(), e as &dyn Entrant)),
            SeatArg::Net(_) => next_net.next().map(|(n, e)| (n.as_str(), e as &dyn Entrant)),
        }
    };
    // A three-player game seats the first three; the fourth place is never played.
    let players: [Player; 4] = std::array::from_fn(|p| match agents.get(p) {
        Some(SeatArg::Builtin(a)) => Player::Builtin(*a),
        Some(a) => match next_entrant(a) {
            Some((name, entrant)) => Player::Entrant { name, entrant },
            None => Player::Builtin(Agent::Random),
        },
        None => Player::Builtin(Agent::Random),
    });
    if !(0.0..=1.0).contains(&args.max_fault_rate) {
        return Err(CliError::input(format!(
            "--max-fault-rate {}: a share of games, 0 to 1",
            args.max_fault_rate
        )));
    }
    if args.games == 0 || !args.games.is_multiple_of(seats as u64) {
        return Err(CliError::input(format!(
            "--games {} is not a positive multiple of {seats}: each wall set is played once per rotation",
            args.games
        )));
    }
    let arena = Arena {
        variant: args.variant.variant,
        mode: args.mode,
        players,
        sets: (args.games / seats as u64) as usize,
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
    let report = on_threads(args.threads, || arena::run(&arena, &progress))?;
    bar.finish_and_clear();
    let seconds = started.elapsed().as_secs_f64();
    let verdict = fault_verdict(&report, args.max_fault_rate);
    if args.json {
        let standings: Vec<_> = report
            .standings
            .iter()
            .map(|s| {
                json!({
                    "agent": s.name, "games": s.games, "mean_rank": s.mean_rank, "rank_ci95": s.rank_ci95,
                    "ranks": s.ranks[..seats], "mean_score": s.mean_score, "rounds": s.rounds, "win_rate": s.win_rate,
                    "deal_in_rate": s.deal_in_rate, "call_rate": s.call_rate, "riichi_rate": s.riichi_rate,
                    "points_per_win": s.points_per_win, "illegal": s.illegal,
                })
            })
            .collect();
        let out = json!({
            "variant": arena.variant.to_string(), "mode": arena.mode.name(), "games": report.games,
            "seed": args.seed, "seconds": seconds, "games_per_second": report.games as f64 / seconds,
            "decisions": report.decisions, "standings": standings,
            "search": searches.iter().map(|(name, e)| {
                let t = e.totals();
                json!({
                    "agent": name, "decisions": t.decisions, "searched": t.searched, "rollouts": t.rollouts,
                    "steps": t.steps, "changed": t.changed, "seconds": t.seconds,
                    "ms_per_decision": 1e3 * t.seconds / t.decisions.max(1) as f64,
                    "median_ms": t.median_ms, "p99_ms": t.p99_ms,
                })
            }).collect::<Vec<_>>(),
            "faults": report.faults.iter().map(|f| json!({
                "player": f.player, "game": f.game, "seat": f.seat, "decision": f.decision, "message": f.message,
            })).collect::<Vec<_>>(),
        });
        println!("{out:#}");
        return verdict;
    }
    println!(
        "{} {} {} games ({} wall sets x {seats} seatings), seed {}, {:.1}s ({:.1} games/s, {:.0} decisions/s)",
        report.games,
        arena.variant,
        arena.mode,
        arena.sets,
        args.seed,
        seconds,
        report.games as f64 / seconds,
        report.decisions as f64 / seconds
    );
    println!(
        "{:<10} {:>6} {:>15} {:>23} {:>8} {:>6} {:>7} {:>6} {:>7} {:>8}",
        "agent",
        "games",
        "avg rank (95%)",
        ["1st/2nd/3rd", "1st/2nd/3rd/4th"][seats - 3],
        "score",
        "win",
        "deal-in",
        "call",
        "riichi",
        "pts/win"
    );
    for s in &report.standings {
        let hist = s.ranks[..seats]
            .iter()
            .map(|&r| format!("{:.0}%", 100.0 * r as f64 / s.games.max(1) as f64))
            .collect::<Vec<_>>()
            .join("/");
        // One wall set gives no interval (NaN): "±n/a", never a "±0.000" that reads as certainty.
        let ci = if s.rank_ci95.is_finite() {
            format!("{:.3}", s.rank_ci95)
        } else {
            "n/a".to_string()
        };
        println!(
            "{:<10} {:>6} {:>8.3}±{ci} {:>23} {:>8.0} {:>5.1}% {:>6.1}% {:>5.1}% {:>6.1}% {:>8.0}",
            s.name,
            s.games,
            s.mean_rank,
            hist,
            s.mean_score,
            100.0 * s.win_rate,
            100.0 * s.deal_in_rate,
            100.0 * s.call_rate,
            100.0 * s.riichi_rate,
            s.points_per_win
        );
    }
    for (name, e) in &searches {
        let t = e.totals();
        println!(
            "{name}: {} decisions, {} looked ahead at ({} rollouts, {:.0} steps each), {} unlike its base agent; \
             {:.1} ms per decision on average (median {:.1}, p99 {:.1}; one thread each)",
            t.decisions,
            t.searched,
            t.rollouts,
            t.steps as f64 / t.rollouts.max(1) as f64,
            t.changed,
            1e3 * t.seconds / t.decisions.max(1) as f64,
            t.median_ms,
            t.p99_ms
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
    verdict
}

/// A failure naming every player that faulted in more than `max_rate` of its games (games it
/// faulted in, each seat-game once however many faults it logged), with its first fault.
fn fault_verdict(report: &arena::Report, max_rate: f64) -> Result<(), CliError> {
    let over: Vec<String> = report
        .standings
        .iter()
        .filter_map(|s| {
            let mine: Vec<&arena::Fault> = report.faults.iter().filter(|f| f.player == s.name).collect();
            let mut games: Vec<(u64, u32)> = mine.iter().map(|f| (f.game, f.seat)).collect();
            games.sort_unstable();
            games.dedup();
            let faulted = games.len() as u64;
            let first = mine.first()?;
            (faulted as f64 > max_rate * s.games as f64).then(|| {
                format!(
                    "{} faulted in {faulted} of its {} games (first: game {} seat {}, decision {}: {})",
                    s.name, s.games, first.game, first.seat, first.decision, first.message
                )
            })
        })
        .collect();
    match over.is_empty() {
        true => Ok(()),
        false => Err(CliError::failure(format!(
            "an MJAI bot faulted in more than --max-fault-rate {max_rate} of its games, so its standing is the \
             penalty's, not its play: {}",
            over.join("; ")
        ))),
    }
}
