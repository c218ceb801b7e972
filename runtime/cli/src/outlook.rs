//! `rinshan outlook`: a hand's odds per discard, drawing alone from the tiles the seat cannot see.

use rinshan_search::outlook::{of_notation, to_json, Odds};

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// The hand to discard from, e.g. `123456789m1145p9s` (0 = red five): 14 concealed tiles, or
    /// 3k+2 when melds are called
    hand: String,
    /// Tiles the seat sees elsewhere (rivers, melds, dora indicators), which it cannot draw
    #[arg(long, value_name = "TILES", default_value = "")]
    seen: String,
    /// Own draws left
    #[arg(long, default_value_t = 12)]
    draws: usize,
    /// Play-outs per discard
    #[arg(long, default_value_t = 10_000)]
    trials: u32,
    /// Seed of the draws
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Print JSON: every discard's shanten and its chances of tenpai and of a win by each draw
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let odds = of_notation(&args.hand, &args.seen, args.draws, args.trials, args.seed).map_err(CliError::input)?;
    if args.json {
        println!("{}", to_json(&odds, args.draws));
        return Ok(());
    }
    print_table(&odds, args.draws, "");
    eprintln!(
        "drawing alone from the unseen tiles, {} play-outs per discard; other seats' wins and an open hand's yaku are not counted",
        args.trials
    );
    Ok(())
}

/// The odds drawing alone as a table: each discard's shanten and its chances by the last of
/// `draws` draws, each line after `indent`.
pub(crate) fn print_table(odds: &[Odds], draws: usize, indent: &str) {
    let last = draws - 1;
    println!("{indent}discard  shanten  tenpai by draw {draws:>2}  win by draw {draws:>2} (95%)");
    for o in odds {
        println!(
            "{indent}{:>7}  {:>7}  {:>17.1}%  {:>8.1}% +- {:.1}",
            o.discard.name(),
            o.shanten,
            100.0 * o.tenpai[last],
            100.0 * o.win[last],
            100.0 * o.interval(o.win[last])
        );
    }
}
