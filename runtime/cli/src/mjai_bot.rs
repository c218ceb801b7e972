//! `rinshan mjai-bot`: a built-in agent as an MJAI bot, reading events on stdin and writing its
//! reactions on stdout, for mjai.app-style runners (`python bot.py SEAT`: a JSON array of events
//! per line, one reaction per line) or Mortal's stdio dialect (one event per line, a reaction
//! when the seat can act). Problems go to stderr; the bot always answers.

use std::io::{BufRead, Write};

use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::Dialect;
use rinshan_logs::mjai::player::Player;
use rinshan_search::Search;

use crate::args::{net_agent, SeatArg};
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// The agent that decides: random, rule, greedy, defensive, the look-ahead `search` (or
    /// `search:rollouts=N:ms=M:...` as in `arena --agents`; keep ms within the host's time limit),
    /// or a trained net's file, `net:PATH`
    #[arg(long, default_value = "defensive")]
    agent: SeatArg,
    /// app (mjai.app: a JSON array of events per line, one reaction each) or stdio (Mortal:
    /// one event per line, a reaction when the seat can act)
    #[arg(long, default_value = "app")]
    dialect: Dialect,
    /// The bot's seat, 0-3 from East 1's dealer (mjai.app and Mortal pass it); without it,
    /// `start_game`'s `id` names it
    seat: Option<u8>,
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.seat.is_some_and(|s| s > 3) {
        return Err(CliError::input("the seat is 0, 1, 2 or 3"));
    }
    let mut player = Player::new(args.seat);
    let net = match &args.agent {
        SeatArg::Net(path) => Some(net_agent(path, Variant::Red)?),
        _ => None,
    };
    let search = match &args.agent {
        SeatArg::Builtin(_) | SeatArg::Net(_) => None,
        SeatArg::Search(o) => Some(Search::new(Variant::Red, *o)),
        SeatArg::Mjai(_) => {
            return Err(CliError::input(
                "an MJAI bot cannot be the agent of rinshan's own MJAI bot",
            ))
        }
    };
    let mut nonce = 0u64;
    let mut decide = |s: &rinshan_engine::generated::kernel::GameState| {
        nonce += 1;
        if let Some(net) = &net {
            return net.act(s).map_err(|e| e.to_string());
        }
        match (&args.agent, &search) {
            // The state is rebuilt from the seat's events; the look-ahead deals the rest afresh
            // (the wall places of its past draws play no part in what follows).
            (_, Some(search)) => Ok(search.decide(s, s.current, &[], nonce).action),
            (SeatArg::Builtin(agent), None) => Ok(agent.act(Variant::Red, s)),
            _ => Err("no agent".to_string()),
        }
    };
    let mut log = |message: String| eprintln!("rinshan mjai-bot: {message}");
    let stdin = std::io::stdin();
    let mut stdout = std::io::stdout().lock();
    for line in stdin.lock().lines() {
        let line = line.map_err(|e| CliError::failure(format!("reading stdin: {e}")))?;
        if line.trim().is_empty() {
            continue;
        }
        if let Some(reply) = player.respond(&line, args.dialect, &mut decide, &mut log) {
            // The host is gone when its end of the pipe is: nothing more to answer.
            if writeln!(stdout, "{reply}").and_then(|()| stdout.flush()).is_err() {
                break;
            }
        }
    }
    Ok(())
}
