//! `rinshan serve`: the web page to play against the agents, watch them, or replay a log.

use std::net::SocketAddr;
use std::time::Duration;

use rinshan_serve::Limits;

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
    /// Minutes after which an untouched game is dropped
    #[arg(long, default_value_t = 30)]
    idle_minutes: u64,
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.max_games == 0 || args.idle_minutes == 0 {
        return Err(CliError::input("--max-games and --idle-minutes must be at least 1"));
    }
    let limits = Limits {
        max_games: args.max_games,
        idle: Duration::from_secs(args.idle_minutes.saturating_mul(60)),
    };
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| CliError::failure(format!("could not start the async runtime: {e}")))?;
    let addr = SocketAddr::new(args.host, args.port);
    runtime
        .block_on(rinshan_serve::serve(addr, limits))
        .map_err(|e| CliError::input(format!("{addr}: {e}")))
}
