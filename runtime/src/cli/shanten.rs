use rinshan::hand;
use rinshan::notation::parse_tiles;
use rinshan::TileType;

use super::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Concealed tiles, e.g. `123m456p789s1122z` (0 = red five); 1 to 14 tiles
    hand: String,
    /// Print `{"shanten": n, "normal": a, "chiitoitsu": b, "kokushi": c}`
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let tiles = parse_tiles(&args.hand).map_err(CliError::input)?;
    let counts = tiles.counts();
    if let Some((t, n)) = TileType::all().zip(counts).find(|&(_, n)| n > 4) {
        return Err(CliError::input(format!("{n} copies of {t}: there are only 4")));
    }
    let n = tiles.tiles.len();
    if n > 14 || n % 3 == 0 {
        return Err(CliError::input(format!(
            "{n} tiles: a hand to measure has 3k+1 or 3k+2 tiles (13 or 14 without melds)"
        )));
    }
    let s = hand::shanten(&counts);
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
