use rinshan_engine::hand::{self, Payment, ScoreError};
use rinshan_engine::win_input::{score_json, WinInput};

use crate::args::VariantArg;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    win: WinInput,
    #[command(flatten)]
    variant: VariantArg,
    /// Print the result as JSON
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let variant = args.variant.variant;
    let win = args.win.win().map_err(CliError::input)?;
    let score = match hand::score(variant, &win) {
        Ok(s) => s,
        Err(e @ ScoreError::BadInput(_)) => return Err(CliError::input(e)),
        Err(e) => return Err(CliError::failure(e)),
    };
    if args.json {
        println!("{}", score_json(&score));
        return Ok(());
    }
    for y in &score.yaku {
        let unit = if score.yakuman > 0 { "yakuman" } else { "han" };
        println!("  {:<20} {} {unit}", y.name, y.han.number());
    }
    let value = if score.yakuman > 0 {
        format!("{} x yakuman", score.yakuman)
    } else {
        format!("{} han {} fu", score.han, score.fu)
    };
    let pay = match score.payment {
        Payment::Ron { discarder } => format!("ron {discarder}"),
        Payment::Tsumo {
            dealer: Some(d),
            others,
        } => format!("tsumo {others}/{d}"),
        Payment::Tsumo { dealer: None, others } => format!("tsumo {others} all"),
    };
    println!("{value}: {pay} (winner gains {})", score.gain);
    Ok(())
}
