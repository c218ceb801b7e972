//! `rinshan`: the command-line front end over the engine, logs, render and serve crates: self-play,
//! the hand calculator, log replay, pictures, the web page, the arena, benchmarks and the soak. Each
//! subcommand lives in its own module; nothing here plays a rule.

// The doc comments of the arguments are clap's help text, written for a terminal (`game-<n>.json`),
// not rustdoc's HTML.
#![allow(rustdoc::invalid_html_tags)]

mod arena;
mod args;
mod bench;
mod convert;
mod dataset;
mod error;
mod mjai_bot;
mod observe;
mod outlook;
mod reference;
mod render;
mod replay;
mod review;
mod score;
mod selfplay;
mod serve;
mod shanten;
mod soak;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

use error::CliError;

#[derive(Parser)]
#[command(
    name = "rinshan",
    version,
    about = "Vectorized Riichi Mahjong whose rules are data: self-play of the built-in agents, hand calculator, log replay, pictures, a web page, an arena and benchmarks"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Shanten of a concealed hand (-1 = complete), e.g. `rinshan shanten 123m456p789s1122z`
    Shanten(shanten::Args),
    /// Score a winning hand, e.g. `rinshan score 234567m234p4566s --win 6s --tsumo`
    Score(score::Args),
    /// Win odds per discard, drawing alone from the tiles the seat cannot see, e.g. `rinshan outlook 123456789m1145p9s --draws 12`
    Outlook(outlook::Args),
    /// Self-play of the built-in agents (or a uniformly random policy): speed, game statistics and how each agent did, e.g. `rinshan selfplay --games 1000`
    Selfplay(selfplay::Args),
    /// Replay tenhou.net/6, MJAI or mjlog logs, each under its rule set (red for Tenhou's), and compare every round, e.g. `rinshan replay logs/`
    Replay(replay::Args),
    /// Convert logs between tenhou.net/6 JSON and MJAI, e.g. `rinshan convert game.json -o game.mjson`
    Convert(convert::Args),
    /// Training data from logs: every decision replayed into .npy shards with a manifest, e.g. `rinshan dataset logs/ -o data/`
    Dataset(dataset::Args),
    /// A player's decisions in a log judged by the look-ahead: each action's value, the mistakes ranked by loss, as text, JSON or an HTML report, e.g. `rinshan review game.json --player NAME -o review.html`
    Review(review::Args),
    /// A seat's observation at a position of a log, e.g. `rinshan observe game.json --round 2 --step 10`
    Observe(observe::Args),
    /// Draw a table as SVG or PNG, or a whole logged game as an HTML replay, e.g. `rinshan render game.json --round 1 --step 20 --png -o board.png`
    Render(render::Args),
    /// A web page to play against the agents, watch them or replay a log, e.g. `rinshan serve --port 8000`
    Serve(serve::Args),
    /// Rate agents and MJAI bots by duplicate play, e.g. `rinshan arena --agents greedy,rule,rule,mjai:"python bot.py" --games 4000`
    Arena(arena::Args),
    /// A built-in agent as an MJAI bot on stdin/stdout (mjai.app's or Mortal's dialect), e.g. `rinshan mjai-bot --agent defensive 0`
    MjaiBot(mjai_bot::Args),
    /// Many whole games with every invariant checked after every step, e.g. `rinshan soak --games 10000`
    Soak(soak::Args),
    /// This command's reference: every subcommand and flag as Markdown (docs/cli.md) or, with
    /// `--man`, a man page, e.g. `rinshan reference --man > rinshan.1`
    Reference(reference::Args),
    /// Benchmarks: `bench hands` (shanten, scoring), `bench env` (environment steps by batch size)
    Bench {
        #[command(subcommand)]
        what: bench::What,
    },
}

fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Shanten(a) => shanten::run(a),
        Command::Score(a) => score::run(a),
        Command::Outlook(a) => outlook::run(a),
        Command::Selfplay(a) => selfplay::run(a),
        Command::Replay(a) => replay::run(a),
        Command::Convert(a) => convert::run(a),
        Command::Dataset(a) => dataset::run(a),
        Command::Arena(a) => arena::run(a),
        Command::MjaiBot(a) => mjai_bot::run(a),
        Command::Review(a) => review::run(a),
        Command::Observe(a) => observe::run(a),
        Command::Render(a) => render::run(a),
        Command::Serve(a) => serve::run(a),
        Command::Soak(a) => soak::run(a),
        Command::Reference(a) => reference::run(a, <Cli as clap::CommandFactory>::command()),
        Command::Bench { what } => bench::run(what),
    }
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", e.message);
            ExitCode::from(e.code)
        }
    }
}
