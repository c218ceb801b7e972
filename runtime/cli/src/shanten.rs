use rinshan_engine::hand;

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Concealed tiles, e.g. `123m456p789s1122z` (0 = red five); 1 to 14 tiles
    hand: String,
    /// Print `{"shanten": n, "normal": a, "chiitoitsu": b, "kokushi": c}`
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let s = hand::shanten_of_notation(&args.hand).map_err(CliError::input)?;
    if args.json {
        let v = serde_json::json!({
            "shanten": s.shanten,
            "normal": s.normal,
            "chiitoitsu": s.chiitoitsu,
            "kokushi": s.kokushi,
        });
        println!("{v}");
    } else {
        let part = |x: Option<i32>| x.map_or("-".to_string(), |v| v.to_string());
        println!("{}", s.shanten);
        eprintln!(
            "normal {}, chiitoitsu {}, kokushi {}",
            s.normal,
            part(s.chiitoitsu),
            part(s.kokushi)
        );
    }
    Ok(())
}
