//! `rinshan serve`: the web page to play against the agents, watch them, or replay a log.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use rinshan_net::Net;
use rinshan_serve::{Limits, NamedBot};

use crate::args::MjaiArgs;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Port to listen on
    #[arg(long, default_value_t = 8000)]
    port: u16,
    /// Address to listen on (0.0.0.0 to let other machines in; there is no login)
    #[arg(long, default_value = "127.0.0.1")]
    host: std::net::IpAddr,
    /// Games held at once; past it new games are refused (503)
    #[arg(long, default_value_t = 256)]
    max_games: usize,
    /// Games one client (IP address) may hold at once; past it its new games are refused (429)
    #[arg(long, default_value_t = 8)]
    games_per_client: usize,
    /// Minutes after which a game no client request touched is dropped
    #[arg(long, default_value_t = 30)]
    idle_minutes: u64,
    /// Minutes after which any game is dropped
    #[arg(long, default_value_t = 240)]
    max_game_minutes: u64,
    /// Games one network (an IPv4 /24, an IPv6 /64) may hold at once (429 past it)
    #[arg(long, default_value_t = 16)]
    games_per_network: usize,
    /// Event streams (open pages) one client may hold at once
    #[arg(long, default_value_t = 16)]
    streams_per_client: usize,
    /// Connections served at once (lowered to what `ulimit -n` allows); more wait to be accepted
    #[arg(long, default_value_t = 16_384)]
    max_connections: usize,
    /// Connections one network may hold open; more are closed at once
    #[arg(long, default_value_t = 64)]
    connections_per_network: usize,
    /// Seconds a connection has to send a request's headers (or its HTTP/2 preface) before it is
    /// closed; also how long an idle connection is kept, and an HTTP/2 ping waits for its answer
    #[arg(long, default_value_t = 10)]
    header_timeout_seconds: u64,
    /// Seconds a request's body has to arrive and its answer to be ready (408 past it)
    #[arg(long, default_value_t = 30)]
    request_timeout_seconds: u64,
    /// MJAI bot processes running at once, server-wide (each bot seat runs one)
    #[arg(long, default_value_t = 48)]
    bot_processes: usize,
    /// MJAI bot processes one client's games may run at once
    #[arg(long, default_value_t = 6)]
    bot_processes_per_client: usize,
    /// Finished games kept at most in the data directory; the oldest are deleted past it
    #[arg(long, default_value_t = 10_000)]
    saved_games: usize,
    /// Megabytes of finished games kept at most; the oldest are deleted past it
    #[arg(long, default_value_t = 1024)]
    saved_megabytes: u64,
    /// Finished games one network may have kept in any hour; later ones are played, not kept
    #[arg(long, default_value_t = 120)]
    saves_per_network_hour: usize,
    /// Where finished games are kept as Tenhou logs (the replay page lists them); default: rinshan
    /// in the user's data directory (~/.local/share/rinshan on Linux)
    #[arg(long, value_name = "DIR", conflicts_with = "no_data_dir")]
    data_dir: Option<PathBuf>,
    /// Keep no finished games
    #[arg(long)]
    no_data_dir: bool,
    /// The look-ahead's play-outs per decision when the replay page reviews a log: a review must
    /// be drawn within --request-timeout-seconds (256 take about 3 s of 2 cores per half game)
    #[arg(long, default_value_t = 256)]
    review_rollouts: u32,
    /// An MJAI bot the page offers as an opponent, `NAME=COMMAND` (repeatable): each seat it
    /// takes runs `sh -c "COMMAND SEAT"`; visitors choose it by NAME, never give a command
    #[arg(long = "mjai-bot", value_name = "NAME=COMMAND")]
    mjai_bots: Vec<String>,
    /// A trained net the page offers as an opponent, `NAME=PATH` (repeatable): a file of
    /// examples/train/export.py, played on the CPU; visitors choose it by NAME, never give a path
    #[arg(long = "net", value_name = "NAME=PATH")]
    nets: Vec<String>,
    #[command(flatten)]
    mjai: MjaiArgs,
}

/// `NAME=VALUE` of a repeatable `flag` naming a `noun`, the name letters, digits, `-`, `_` and `.`.
fn named<'a>(flag: &str, given: &'a str, noun: &str, what: &str) -> Result<(&'a str, &'a str), CliError> {
    let (name, value) = given
        .split_once('=')
        .map(|(n, c)| (n.trim(), c.trim()))
        .filter(|(n, c)| !n.is_empty() && !c.is_empty())
        .ok_or_else(|| CliError::input(format!("{flag} {given:?}: give NAME={what}")))?;
    if !name.chars().all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c)) {
        return Err(CliError::input(format!(
            "{flag} {given:?}: a {noun}'s name is letters, digits, `-`, `_` and `.`"
        )));
    }
    Ok((name, value))
}

/// The nets of `--net`, each `NAME=PATH`, read at start: a file that cannot be played fails the
/// command, not a visitor's game.
fn nets(args: &Args) -> Result<Vec<(String, Arc<Net>)>, CliError> {
    let mut out: Vec<(String, Arc<Net>)> = Vec::new();
    for given in &args.nets {
        let (name, path) = named("--net", given, "net", "PATH")?;
        if out.iter().any(|(n, _)| n == name) {
            return Err(CliError::input(format!("--net: two nets are named `{name}`")));
        }
        let net = Net::load(path).map_err(|e| CliError::input(format!("--net {name}: {e}")))?;
        out.push((name.to_string(), Arc::new(net)));
    }
    Ok(out)
}

/// The bots of `--mjai-bot`, each `NAME=COMMAND`.
fn bots(args: &Args) -> Result<Vec<NamedBot>, CliError> {
    let mut out: Vec<NamedBot> = Vec::new();
    for given in &args.mjai_bots {
        let (name, command) = named("--mjai-bot", given, "bot", "COMMAND")?;
        if out.iter().any(|b| b.name == name) {
            return Err(CliError::input(format!("--mjai-bot: two bots are named `{name}`")));
        }
        out.push(NamedBot {
            name: name.to_string(),
            spec: args.mjai.entrant(command)?.spec,
        });
    }
    Ok(out)
}

pub fn run(args: Args) -> Result<(), CliError> {
    let counts = [
        ("--max-games", args.max_games as u64),
        ("--games-per-client", args.games_per_client as u64),
        ("--idle-minutes", args.idle_minutes),
        ("--max-game-minutes", args.max_game_minutes),
        ("--games-per-network", args.games_per_network as u64),
        ("--streams-per-client", args.streams_per_client as u64),
        ("--max-connections", args.max_connections as u64),
        ("--connections-per-network", args.connections_per_network as u64),
        ("--header-timeout-seconds", args.header_timeout_seconds),
        ("--request-timeout-seconds", args.request_timeout_seconds),
        ("--saved-games", args.saved_games as u64),
        ("--saved-megabytes", args.saved_megabytes),
        ("--saves-per-network-hour", args.saves_per_network_hour as u64),
        ("--review-rollouts", u64::from(args.review_rollouts)),
    ];
    if let Some((name, _)) = counts.iter().find(|(_, n)| *n == 0) {
        return Err(CliError::input(format!("{name} must be at least 1")));
    }
    let bots = bots(&args)?;
    let nets = nets(&args)?;
    let data_dir = match (args.no_data_dir, args.data_dir) {
        (true, _) => None,
        (false, Some(dir)) => Some(dir),
        (false, None) => dirs::data_dir().map(|d| d.join("rinshan")),
    };
    let minutes = |m: u64| Duration::from_secs(m.saturating_mul(60));
    let limits = Limits {
        max_games: args.max_games,
        games_per_client: args.games_per_client,
        games_per_network: args.games_per_network,
        idle: minutes(args.idle_minutes),
        max_duration: minutes(args.max_game_minutes),
        streams_per_client: args.streams_per_client,
        max_connections: args.max_connections,
        connections_per_network: args.connections_per_network,
        header_timeout: Duration::from_secs(args.header_timeout_seconds),
        request_timeout: Duration::from_secs(args.request_timeout_seconds),
        bot_processes: args.bot_processes,
        bot_processes_per_client: args.bot_processes_per_client,
        data_dir,
        saved_games: args.saved_games,
        saved_bytes: args.saved_megabytes.saturating_mul(1 << 20),
        saves_per_network_hour: args.saves_per_network_hour,
        fixed_seed: None,
        bots,
        nets,
        review_rollouts: args.review_rollouts,
    };
    for b in &limits.bots {
        println!("MJAI bot `{}` offered as mjai:{}: {}", b.name, b.name, b.spec.command);
    }
    for (name, net) in &limits.nets {
        println!("net `{name}` offered as net:{name} ({} actions)", net.actions.len());
    }
    match &limits.data_dir {
        Some(dir) => println!("finished games are kept in {}", dir.join("games").display()),
        None => println!("finished games are not kept (no data directory)"),
    }
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| CliError::failure(format!("could not start the async runtime: {e}")))?;
    let addr = SocketAddr::new(args.host, args.port);
    runtime
        .block_on(rinshan_serve::serve(addr, limits))
        .map_err(|e| CliError::input(format!("{addr}: {e}")))
}
