//! `rinshan selfplay`: the built-in agents (or a random legal policy) play whole games in a batch
//! of envs; prints how fast, and how the games went (win, deal-in and draw rates, final scores,
//! yaku frequencies, and per agent its average rank, score, win and deal-in rates); with
//! `--export DIR`, writes each counted game as a tenhou.net/6 or MJAI log.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_engine::agents::Agent;
use rinshan_engine::env::{env_seed, events, Backend, Config, Env, Mode};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;
use rinshan_logs::file::write_log;
use rinshan_logs::mjai::batch::BatchBots;
use rinshan_logs::mjai::seat::MjaiEntrant;
use rinshan_logs::tenhou::write::{Finished, Recorder};
use rinshan_net::BatchNet;
use rinshan_search::BatchSearch;
use serde_json::json;

use crate::args::{net_agent, FormatArg, GameArgs, MjaiArgs, SeatArg};
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    game: GameArgs,
    /// Games to finish
    #[arg(long, default_value_t = 1000)]
    games: u64,
    /// Envs stepped together
    #[arg(long, default_value_t = 256)]
    batch: usize,
    /// Print the summary as JSON
    #[arg(long)]
    json: bool,
    /// Who plays the seats: built-in agents (random, rule, greedy, defensive), the look-ahead
    /// (`search`, or with settings as in `arena`; CPU backend), trained nets (`net:PATH`: a file of
    /// examples/train/export.py, each step's decisions in one forward pass; CPU backend) or MJAI
    /// bots (`mjai:COMMAND`, see `arena`), one per seat (three players: three, or four taking turns to
    /// sit out); env i seats agent (p + i) mod n of the n listed at seat p, so over a batch of a
    /// multiple of n envs each agent plays every seat equally; or `uniform` for a uniformly random
    /// legal policy drawn on the host (most such games end in draws)
    #[arg(long, value_delimiter = ',', default_value = "defensive,greedy,rule,random")]
    agents: Vec<String>,
    #[command(flatten)]
    mjai: MjaiArgs,
    /// Also write each counted game as DIR/game-<n>.json (n = 1..games), a tenhou.net/6 log that
    /// `rinshan replay` replays under the game's rule set (or .mjson, see --export-format, which
    /// names it too). East or half games, CPU backend only (the games' states are read after
    /// every step)
    #[arg(long, value_name = "DIR")]
    export: Option<PathBuf>,
    /// The format of --export's logs
    #[arg(long, value_enum, default_value = "tenhou")]
    export_format: FormatArg,
}

/// The policy's random stream of env `i` (independent of the walls' seeds).
pub fn policy_rng(seed: u64, i: usize) -> Rng {
    Rng::new(env_seed(seed ^ 0x706f_6c69_6379, i as u64, 0))
}

/// What one game (or all the counted games) did.
#[derive(Clone, Default)]
struct Tally {
    steps: u64,
    rounds: u64,
    ron: u64,
    tsumo: u64,
    exhaustive: u64,
    abortive: u64,
    nagashi: u64,
    rewards: [f64; 4],
    /// Rounds each seat won, and dealt in.
    wins: [u64; 4],
    deal_ins: [u64; 4],
    yaku: Vec<u64>,
}

impl Tally {
    fn new(yaku: usize) -> Tally {
        Tally {
            yaku: vec![0; yaku],
            ..Tally::default()
        }
    }

    fn add(&mut self, other: &Tally) {
        self.steps += other.steps;
        self.rounds += other.rounds;
        self.ron += other.ron;
        self.tsumo += other.tsumo;
        self.exhaustive += other.exhaustive;
        self.abortive += other.abortive;
        self.nagashi += other.nagashi;
        for (a, b) in self.rewards.iter_mut().zip(other.rewards) {
            *a += b;
        }
        for p in 0..4 {
            self.wins[p] += other.wins[p];
            self.deal_ins[p] += other.deal_ins[p];
        }
        for (a, b) in self.yaku.iter_mut().zip(&other.yaku) {
            *a += b;
        }
    }
}

/// One agent's games, whatever seats it played.
#[derive(Clone, Default)]
struct AgentTally {
    games: u64,
    /// Games finished 1st..4th.
    ranks: [u64; 4],
    /// Final scores (uma included), points.
    score: f64,
    rounds: u64,
    wins: u64,
    deal_ins: u64,
}

impl AgentTally {
    /// Seat `p`'s part of a finished game `t` that ended with `ranks` (0 = first).
    fn add(&mut self, t: &Tally, p: usize, rank: u8, start: f64) {
        self.games += 1;
        self.ranks[usize::from(rank.min(3))] += 1;
        self.score += start + t.rewards[p] * 100.0;
        self.rounds += t.rounds;
        self.wins += t.wins[p];
        self.deal_ins += t.deal_ins[p];
    }

    fn mean_rank(&self) -> f64 {
        let sum: u64 = self.ranks.iter().enumerate().map(|(r, n)| (r as u64 + 1) * n).sum();
        ratio(sum, self.games)
    }
}

/// The players of `--agents` (one per seat at a table of `seats`, or four), and each env's
/// kernel seating (None: the host's uniform random policy). An MJAI bot's seats hold `random` in
/// the kernel's seating: the bot's action replaces it.
#[allow(clippy::type_complexity)]
fn seatings(
    agents: &[String],
    batch: usize,
    seats: usize,
) -> Result<Option<(Vec<SeatArg>, Vec<[Agent; 4]>)>, CliError> {
    if agents.len() == 1 && agents[0] == "uniform" {
        return Ok(None);
    }
    let players: Vec<SeatArg> = agents
        .iter()
        .map(|a| a.parse().map_err(CliError::input))
        .collect::<Result<_, _>>()?;
    let n = players.len();
    if n != seats && n != 4 {
        let three = if seats == 3 {
            " (three players: 3, or 4 taking turns to sit out)"
        } else {
            ""
        };
        return Err(CliError::input(format!(
            "--agents needs {seats} agents, one per seat{three}, or `uniform`; got {n}"
        )));
    }
    let kernel: Vec<Agent> = players
        .iter()
        .map(|a| match a {
            SeatArg::Builtin(a) => *a,
            SeatArg::Mjai(_) | SeatArg::Search(_) | SeatArg::Net(_) => Agent::Random,
        })
        .collect();
    // A place past the list (three players' fourth) is never played.
    let seating = (0..batch)
        .map(|i| std::array::from_fn(|p| if p < n { kernel[(p + i) % n] } else { Agent::Random }))
        .collect();
    Ok(Some((players, seating)))
}

pub fn run(args: Args) -> Result<(), CliError> {
    let config = args.game.config(args.batch);
    let (players, seatings) = match seatings(&args.agents, args.batch, config.variant.seats() as usize)? {
        Some((players, seatings)) => (Some(players), Some(seatings)),
        None => (None, None),
    };
    // Per entry of --agents, its MJAI bot if it is one.
    let entrants: Vec<Option<MjaiEntrant>> = match &players {
        Some(players) => players
            .iter()
            .map(|p| match p {
                SeatArg::Mjai(cmd) => args.mjai.entrant(cmd).map(Some),
                SeatArg::Builtin(_) | SeatArg::Search(_) | SeatArg::Net(_) => Ok(None),
            })
            .collect::<Result<_, _>>()?,
        None => Vec::new(),
    };
    let with_bots = entrants.iter().any(Option::is_some);
    if with_bots {
        MjaiArgs::check_rules(config.variant, config.mode, Some(config.backend))?;
    }
    let with_search = players.iter().flatten().any(|p| matches!(p, SeatArg::Search(_)));
    if with_search && config.backend == Backend::Gpu {
        return Err(CliError::input(
            "the look-ahead needs --backend cpu: it follows every game's state after every step",
        ));
    }
    let with_nets = players.iter().flatten().any(|p| matches!(p, SeatArg::Net(_)));
    if with_nets && config.backend == Backend::Gpu {
        return Err(CliError::input(
            "net agents need --backend cpu: they read every game's state after every step",
        ));
    }
    let (variant, seed) = (config.variant, config.seed);
    if args.games == 0 {
        return Err(CliError::input("--games must be at least 1"));
    }
    if let Some(dir) = &args.export {
        check_export(dir, &config)?;
    }
    let mut env = Env::new(config).map_err(|e| match e {
        rinshan_engine::env::EnvError::Gpu(_) => CliError::failure(e),
        _ => CliError::input(e),
    })?;
    if env.gpu_is_software() {
        eprintln!("{}", software_adapter_note(&env.adapter().unwrap_or_default()));
    }
    let yaku_names: &[&str] = rinshan_engine::env::yaku_names(variant);
    let b = env.batch();
    let mut rngs: Vec<Rng> = (0..b).map(|i| policy_rng(seed, i)).collect();
    let mut current: Vec<Tally> = vec![Tally::new(yaku_names.len()); b];
    let mut total = Tally::new(yaku_names.len());
    // Per distinct agent name of --agents, in the order first named.
    let mut agent_names: Vec<String> = Vec::new();
    for agent in players.iter().flatten() {
        let name = agent.to_string();
        if !agent_names.contains(&name) {
            agent_names.push(name);
        }
    }
    let mut per_agent: Vec<AgentTally> = vec![AgentTally::default(); agent_names.len()];
    let start = f64::from(variant.starting_points());
    let mut games = 0u64;
    let mut env_steps = 0u64;
    let mut faults = 0u64;
    let mut actions = vec![0u32; b];

    let bar = if args.json || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::new(args.games);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} games  {per_sec}  eta {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    };
    let started = Instant::now();
    env.reset().map_err(CliError::failure)?;
    let mut recorder = match args.export {
        Some(_) => Some(Recorder::new(&env).map_err(CliError::failure)?),
        None => None,
    };
    let mut bots = match with_bots {
        true => {
            let states = env.game_states().map_err(CliError::failure)?;
            // Env i seats the players rotated by i, as the kernel's agents are; a three-player
            // game's fourth place is never played.
            let (at_table, n) = (variant.seats() as usize, entrants.len());
            let seating = (0..states.len())
                .map(|i| std::array::from_fn(|p| entrants[(p + i) % n].clone().filter(|_| p < at_table)))
                .collect();
            Some(BatchBots::new(seating, states, variant))
        }
        false => None,
    };
    let mut searches = match (&players, with_search) {
        (Some(players), true) => look_aheads(players, env.game_states().map_err(CliError::failure)?, variant),
        _ => Vec::new(),
    };
    let mut nets = match (&players, with_nets) {
        (Some(players), true) => nets(players, env.game_states().map_err(CliError::failure)?, variant)?,
        _ => Vec::new(),
    };
    while games < args.games {
        match &seatings {
            Some(seats) => actions = env.agent_actions(seats).map_err(CliError::failure)?,
            None => {
                let step = env.last();
                for (i, a) in actions.iter_mut().enumerate() {
                    *a = rngs[i].pick_legal(&step.legal_action_mask[i]);
                }
            }
        }
        let mut bot_faults = match &mut bots {
            Some(bots) => bots.act(&mut actions),
            None => Vec::new(),
        };
        for search in &mut searches {
            search.act(&mut actions);
        }
        for net in &mut nets {
            net.act(&mut actions).map_err(CliError::failure)?;
        }
        env.step(&actions).map_err(CliError::failure)?;
        // The games' states, read once for all the host's players that follow them.
        if bots.is_some() || !searches.is_empty() || !nets.is_empty() {
            let after = env.game_states().map_err(CliError::failure)?;
            for net in &mut nets {
                net.stepped(after.clone());
            }
            let ended = &env.last().terminated;
            for search in &mut searches {
                search.stepped(after.clone(), ended);
            }
            if let Some(bots) = &mut bots {
                bot_faults.extend(bots.stepped(&actions, after, ended));
            }
        }
        for fault in bot_faults {
            eprintln!("rinshan selfplay: {fault}");
            faults += 1;
        }
        let mut recorded = match &mut recorder {
            Some(r) => {
                r.observe(&env, &actions).map_err(CliError::failure)?;
                r.take_finished()
            }
            None => Vec::new(),
        };
        let step = env.last();
        env_steps += b as u64;
        for (i, t) in current.iter_mut().enumerate() {
            t.steps += 1;
            let ev = step.events[i];
            if ev & events::ROUND_OVER != 0 {
                t.rounds += 1;
            }
            for p in 0..4 {
                t.wins[p] += u64::from(step.winners[i] >> p & 1);
            }
            if step.deal_in[i] != 0 {
                t.deal_ins[(step.deal_in[i] - 1) as usize] += 1;
            }
            if ev & events::RON != 0 {
                t.ron += 1;
            }
            if ev & events::TSUMO != 0 {
                t.tsumo += 1;
            }
            if ev & events::EXHAUSTIVE_DRAW != 0 {
                t.exhaustive += 1;
            }
            if ev & events::ABORTIVE_DRAW != 0 {
                t.abortive += 1;
            }
            if ev & events::NAGASHI != 0 {
                t.nagashi += 1;
            }
            if step.winners[i] != 0 {
                let [lo, hi] = step.yaku[i];
                for (y, n) in t.yaku.iter_mut().enumerate() {
                    let word = if y < 32 { lo >> y } else { hi >> (y - 32) };
                    *n += u64::from(word & 1);
                }
            }
            for (r, x) in t.rewards.iter_mut().zip(step.rewards[i]) {
                *r += f64::from(x);
            }
            if step.terminated[i] {
                let finished = std::mem::replace(t, Tally::new(yaku_names.len()));
                // Games are counted in env order within a step, so the same seed counts the same games.
                if games < args.games {
                    if let Some(players) = &players {
                        // Three players with four listed: the agent the rotation puts in seat 3
                        // sits this game out.
                        for p in 0..variant.seats() as usize {
                            // Env i seats entry (p + i) mod n of --agents at seat p.
                            let name = players[(p + i) % players.len()].to_string();
                            if let Some(k) = agent_names.iter().position(|n| *n == name) {
                                per_agent[k].add(&finished, p, step.ranks[i][p], start);
                            }
                        }
                    }
                    total.add(&finished);
                    games += 1;
                    bar.inc(1);
                    if let Some(dir) = &args.export {
                        export(dir, args.export_format, games, i, &mut recorded)?;
                    }
                }
            }
        }
    }
    let seconds = started.elapsed().as_secs_f64();
    bar.finish_and_clear();
    summary(
        &args,
        variant,
        env.adapter(),
        games,
        env_steps,
        seconds,
        &total,
        &agent_names,
        &per_agent,
        yaku_names,
        faults,
    );
    Ok(())
}

/// Per entry of `players` that is the look-ahead, the look-ahead at that entry's seats of every
/// game (env i seats entry (p + i) mod n at seat p, as the kernel's agents are).
fn look_aheads(players: &[SeatArg], states: Vec<GameState>, variant: Variant) -> Vec<BatchSearch> {
    let n = players.len();
    players
        .iter()
        .enumerate()
        .filter_map(|(k, p)| match p {
            SeatArg::Search(options) => Some((k, *options)),
            _ => None,
        })
        .map(|(k, options)| BatchSearch::new(variant, options, entry_seats(k, n, &states, variant), states.clone()))
        .collect()
}

/// Per game, the seats where entry `k` of `n` entries of --agents sits: env i seats entry
/// (p + i) mod n at seat p, as the kernel's agents are.
fn entry_seats(k: usize, n: usize, states: &[GameState], variant: Variant) -> Vec<[bool; 4]> {
    let at_table = variant.seats() as usize;
    (0..states.len())
        .map(|i| std::array::from_fn(|p| p < at_table && (p + i) % n == k))
        .collect()
}

/// Per entry of `players` that is a net, the net at that entry's seats of every game (seated as
/// [`look_aheads`] seats the look-ahead).
fn nets(players: &[SeatArg], states: Vec<GameState>, variant: Variant) -> Result<Vec<BatchNet>, CliError> {
    let n = players.len();
    let mut out = Vec::new();
    for (k, p) in players.iter().enumerate() {
        if let SeatArg::Net(path) = p {
            let seats = entry_seats(k, n, &states, variant);
            out.push(BatchNet::new(net_agent(path, variant)?, seats, states.clone()));
        }
    }
    Ok(out)
}

/// Why games cannot be exported as asked; creates the folder.
fn check_export(dir: &Path, config: &Config) -> Result<(), CliError> {
    if config.mode == Mode::Single {
        return Err(CliError::input(
            "--export needs --mode east or half: Tenhou has no one-hand games",
        ));
    }
    if config.backend == Backend::Gpu {
        return Err(CliError::input(
            "--export needs --backend cpu: the recorder reads every game's state after each step",
        ));
    }
    std::fs::create_dir_all(dir).map_err(|e| CliError::input(format!("--export {}: {e}", dir.display())))
}

/// Writes the `n`-th counted game, which env `env` has just finished, from this step's records.
fn export(dir: &Path, format: FormatArg, n: u64, env: usize, recorded: &mut Vec<Finished>) -> Result<(), CliError> {
    let at = recorded.iter().position(|f| f.env == env);
    let done = at
        .map(|i| recorded.remove(i))
        .ok_or_else(|| CliError::failure(format!("game {n} (env {env}) was not recorded")))?;
    let path = dir.join(format!("game-{n}.{}", format.extension()));
    write_log(&path, &done.game, format.format()).map_err(CliError::failure)
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

#[allow(clippy::too_many_arguments)]
fn summary(
    args: &Args,
    variant: Variant,
    adapter: Option<String>,
    games: u64,
    env_steps: u64,
    seconds: f64,
    t: &Tally,
    agent_names: &[String],
    per_agent: &[AgentTally],
    yaku_names: &[&str],
    faults: u64,
) {
    let wins = t.ron + t.tsumo;
    let start = f64::from(variant.starting_points());
    let scores: Vec<f64> = t.rewards.iter().map(|r| start + r * 100.0 / games as f64).collect();
    let steps_per_s = env_steps as f64 / seconds.max(1e-9);
    let mut yaku: Vec<(&str, u64)> = yaku_names
        .iter()
        .zip(&t.yaku)
        .filter(|(_, &n)| n > 0)
        .map(|(name, &n)| (*name, n))
        .collect();
    yaku.sort_by_key(|&(_, n)| std::cmp::Reverse(n));
    let backend = match adapter {
        Some(a) => format!("gpu ({a})"),
        None => "cpu".to_string(),
    };
    let agents_json: Vec<_> = agent_names
        .iter()
        .zip(per_agent)
        .map(|(name, a)| {
            json!({
                "agent": name, "games": a.games, "mean_rank": a.mean_rank(), "ranks": a.ranks[..variant.seats() as usize],
                "mean_score": a.score / a.games.max(1) as f64, "rounds": a.rounds,
                "win_rate": ratio(a.wins, a.rounds), "deal_in_rate": ratio(a.deal_ins, a.rounds),
            })
        })
        .collect();
    if args.json {
        let v = json!({
            "variant": variant.to_string(),
            "mode": args.game.mode.to_string(),
            "backend": args.game.backend.backend.to_string(),
            "batch": args.batch,
            "seed": args.game.seed,
            "agents": args.agents,
            "games": games,
            "steps": t.steps,
            "avg_steps_per_game": ratio(t.steps, games),
            "rounds": t.rounds,
            "avg_rounds_per_game": ratio(t.rounds, games),
            "win_rate": ratio(wins, t.rounds),
            "ron_rate": ratio(t.ron, t.rounds),
            "tsumo_rate": ratio(t.tsumo, t.rounds),
            "deal_in_rate": ratio(t.ron, t.rounds),
            "draw_rate": ratio(t.exhaustive + t.abortive, t.rounds),
            "exhaustive_draw_rate": ratio(t.exhaustive, t.rounds),
            "abortive_draw_rate": ratio(t.abortive, t.rounds),
            "nagashi": t.nagashi,
            "avg_final_score": scores[..variant.seats() as usize],
            "per_agent": agents_json,
            "yaku": yaku.iter().map(|(name, n)| json!({"name": name, "count": n, "per_win": ratio(*n, wins)})).collect::<Vec<_>>(),
            "bot_faults": faults,
            "env_steps": env_steps,
            "seconds": seconds,
            "steps_per_second": steps_per_s,
        });
        println!("{v}");
        return;
    }
    let pct = |a: u64, b: u64| 100.0 * ratio(a, b);
    println!(
        "rinshan selfplay: variant {variant}, mode {}, batch {}, backend {backend}, seed {}, players {}",
        args.game.mode,
        args.batch,
        args.game.seed,
        args.agents.join(",")
    );
    println!("  games                 {games}");
    if faults > 0 {
        println!("  bot faults            {faults} (each ended its game with the illegal-action penalty; see stderr)");
    }
    println!(
        "  steps                 {} in the counted games ({:.1} per game), {env_steps} env steps in all",
        t.steps,
        ratio(t.steps, games)
    );
    // The figure a reader compares with the engine's: this one pays for the players' decisions
    // (the agents' planes and choices, a bot's process), `bench env` steps random legal actions.
    println!(
        "  speed                 {steps_per_s:.0} env steps/s with these players choosing every action, {seconds:.2} s \
         (the engine alone, random actions: `rinshan bench env`)"
    );
    println!(
        "  rounds                {} ({:.2} per game)",
        t.rounds,
        ratio(t.rounds, games)
    );
    println!(
        "  win rate              {:.1}% of rounds (ron {:.1}%, tsumo {:.1}%)",
        pct(wins, t.rounds),
        pct(t.ron, t.rounds),
        pct(t.tsumo, t.rounds)
    );
    println!(
        "  deal-in rate          {:.1}% of rounds end with a deal-in",
        pct(t.ron, t.rounds)
    );
    println!(
        "  draw rate             {:.1}% of rounds (exhaustive {:.1}%, abortive {:.1}%; nagashi {})",
        pct(t.exhaustive + t.abortive, t.rounds),
        pct(t.exhaustive, t.rounds),
        pct(t.abortive, t.rounds),
        t.nagashi
    );
    let seats = variant.seats() as usize;
    let per_seat: Vec<String> = (0..seats).map(|p| format!("seat {p}: {:.0}", scores[p])).collect();
    println!(
        "  average final score   {}  (points, uma included)",
        per_seat.join("  ")
    );
    if !agent_names.is_empty() {
        let places = ["1st", "2nd", "3rd", "4th"][..seats].join("/");
        if args.agents.len() == seats {
            println!("  per agent (each plays every seat in turn; win and deal-in rates per round):");
        } else {
            println!(
                "  per agent (each plays every seat in turn, sitting out one game in four; win and deal-in rates per round):"
            );
        }
        println!(
            "    {:<10} {:>6} {:>8} {:>19} {:>8} {:>6} {:>7}",
            "agent", "games", "avg rank", places, "score", "win", "deal-in"
        );
        for (name, a) in agent_names.iter().zip(per_agent) {
            let hist = a.ranks[..seats]
                .iter()
                .map(|&r| format!("{:.0}%", pct(r, a.games)))
                .collect::<Vec<_>>()
                .join("/");
            println!(
                "    {:<10} {:>6} {:>8.3} {:>19} {:>8.0} {:>5.1}% {:>6.1}%",
                name,
                a.games,
                a.mean_rank(),
                hist,
                a.score / a.games.max(1) as f64,
                pct(a.wins, a.rounds),
                pct(a.deal_ins, a.rounds)
            );
        }
    }
    println!("  yaku (share of winning steps):");
    for (name, n) in &yaku {
        println!("    {name:<22} {n:>8}  {:>6.2}%", pct(*n, wins));
    }
}

/// What a run on Mesa's software driver pays first, and the settings that cut it (README, "The two
/// commands"; docs/performance.md, "How long each pipeline takes to compile").
pub(crate) fn software_adapter_note(adapter: &str) -> String {
    format!(
        "note: {adapter} is a software adapter: it compiles the game's pipelines the first time, minutes of one core (cached afterwards); LP_NATIVE_VECTOR_WIDTH=128 and GALLIVM_PERF=nopt make that several times faster"
    )
}
