//! How well the outlook with the others playing predicts what happens (docs/strength.md):
//!
//!     cargo run --release -p rinshan-search --example calibration -- [games] [every] [worlds]
//!
//! At every `every`-th own-turn decision of `defensive` self-play (red half games), the predicted
//! chances of winning and of dealing in after the action `defensive` took, summed, against the
//! counts of the games played on with the real hidden tiles.

use rinshan_engine::Variant;
use rinshan_search::outlook::played::calibration;

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<u64>().expect("a number"));
    let games = args.next().unwrap_or(40);
    let every = args.next().unwrap_or(7) as usize;
    let worlds = args.next().unwrap_or(32) as u32;
    let ((win, deal_in), (won, dealt_in), n) = calibration(Variant::Red, 300..300 + games, every, worlds);
    println!("{n} positions, {worlds} worlds each");
    println!("wins:     predicted {win:.1}, counted {won}");
    println!("deal-ins: predicted {deal_in:.1}, counted {dealt_in}");
}
