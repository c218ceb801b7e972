use rinshan::hand::{self, Payment, ScoreError, Win, WinContext};
use rinshan::notation::{parse_meld, parse_tile, parse_tiles, parse_wind};
use rinshan::{TileType, Variant};

use super::args::VariantArg;
use super::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Concealed tiles, with or without the winning tile, e.g. `234567m234p456s6s` (0 = red five)
    hand: String,
    /// The winning tile, e.g. `6s`
    #[arg(long)]
    win: String,
    /// Won by self-draw (default: ron)
    #[arg(long)]
    tsumo: bool,
    #[arg(long)]
    riichi: bool,
    /// Double riichi (implies riichi)
    #[arg(long)]
    double_riichi: bool,
    #[arg(long)]
    ippatsu: bool,
    /// Tsumo on the last tile of the wall
    #[arg(long)]
    haitei: bool,
    /// Ron on the last discard
    #[arg(long)]
    houtei: bool,
    /// Tsumo on a kan replacement tile
    #[arg(long)]
    rinshan: bool,
    /// Ron on a tile added to a pon
    #[arg(long)]
    chankan: bool,
    #[arg(long)]
    tenhou: bool,
    #[arg(long)]
    chiihou: bool,
    /// The winner is the dealer (seat wind East)
    #[arg(long)]
    dealer: bool,
    /// E, S, W or N
    #[arg(long, default_value = "E")]
    round_wind: String,
    /// E, S, W or N (default: E for the dealer, else S)
    #[arg(long)]
    seat_wind: Option<String>,
    /// Dora indicator tiles, e.g. `3m7z`
    #[arg(long)]
    dora: Option<String>,
    /// Ura-dora indicator tiles (count only with riichi)
    #[arg(long)]
    ura: Option<String>,
    /// A called or declared meld: chi:123m, pon:555z, kan:2222p (open), ankan:1111s, kakan:3333m
    #[arg(long = "meld")]
    melds: Vec<String>,
    #[command(flatten)]
    variant: VariantArg,
    #[arg(long, default_value_t = 0)]
    honba: u32,
    /// Riichi sticks on the table
    #[arg(long, default_value_t = 0)]
    sticks: u32,
    /// Print the result as JSON
    #[arg(long)]
    json: bool,
}

fn indicators(src: &Option<String>) -> Result<Vec<TileType>, CliError> {
    match src {
        None => Ok(Vec::new()),
        Some(s) => Ok(parse_tiles(s)
            .map_err(CliError::input)?
            .tiles
            .iter()
            .map(|t| t.kind())
            .collect()),
    }
}

fn build_win(args: &Args) -> Result<(Variant, Win), CliError> {
    let variant = args.variant.variant;
    let tiles = parse_tiles(&args.hand).map_err(CliError::input)?;
    let win_tile = parse_tile(&args.win).map_err(CliError::input)?;
    let win = win_tile.kind();
    let melds = args
        .melds
        .iter()
        .map(|m| parse_meld(m).map_err(CliError::input))
        .collect::<Result<Vec<_>, _>>()?;
    let mut hand = tiles.counts();
    let mut red = tiles.red() + melds.iter().map(|m| m.red).sum::<u8>();
    let concealed = tiles.tiles.len();
    if concealed + 3 * melds.len() == 13 {
        hand[win.index()] += 1;
        red += u8::from(win_tile.is_red());
    } else if concealed + 3 * melds.len() != 14 {
        return Err(CliError::input(format!(
            "{concealed} concealed tiles with {} meld(s): give 13 - 3 x melds tiles (the winning tile then comes from --win) or 14 - 3 x melds including it",
            melds.len()
        )));
    } else if hand[win.index()] == 0 {
        return Err(CliError::input(format!(
            "the hand has 14 tiles but not the winning tile {}",
            args.win
        )));
    }
    let round_wind = parse_wind(&args.round_wind).map_err(CliError::input)?;
    let seat_wind = match &args.seat_wind {
        Some(s) => parse_wind(s).map_err(CliError::input)?,
        None if args.dealer => 0,
        None => 1,
    };
    if args.dealer && seat_wind != 0 {
        return Err(CliError::input(
            "the dealer's seat wind is East: drop --seat-wind or --dealer",
        ));
    }
    let context = WinContext {
        tsumo: args.tsumo,
        riichi: args.riichi || args.double_riichi,
        double_riichi: args.double_riichi,
        ippatsu: args.ippatsu,
        haitei: args.haitei,
        houtei: args.houtei,
        rinshan: args.rinshan,
        chankan: args.chankan,
        tenhou: args.tenhou,
        chiihou: args.chiihou,
        dealer: seat_wind == 0,
        round_wind,
        seat_wind,
        dora: indicators(&args.dora)?,
        ura: indicators(&args.ura)?,
        honba: args.honba,
        sticks: args.sticks,
    };
    check_context(&context, &melds)?;
    Ok((
        variant,
        Win {
            hand,
            win,
            melds,
            aka: red,
            context,
        },
    ))
}

/// Circumstances that contradict each other are input errors, not silently scored.
fn check_context(c: &WinContext, melds: &[rinshan::notation::Meld]) -> Result<(), CliError> {
    use rinshan::notation::MeldKind;
    let closed = melds.iter().all(|m| m.kind == MeldKind::Ankan);
    let rules: [(bool, &str); 9] = [
        (c.riichi && !closed, "riichi needs a concealed hand (closed kans only)"),
        (c.ippatsu && !c.riichi, "ippatsu needs riichi"),
        (c.haitei && !c.tsumo, "haitei is a tsumo win: add --tsumo"),
        (c.houtei && c.tsumo, "houtei is a ron win: drop --tsumo"),
        (c.rinshan && !c.tsumo, "rinshan is a tsumo win: add --tsumo"),
        (
            c.rinshan && !melds.iter().any(|m| m.kind != MeldKind::Chi && m.kind != MeldKind::Pon),
            "rinshan needs a kan among the melds",
        ),
        (c.chankan && c.tsumo, "chankan is a ron win: drop --tsumo"),
        (
            (c.tenhou || c.chiihou) && (!c.tsumo || !melds.is_empty()),
            "tenhou and chiihou are tsumo wins without melds",
        ),
        (
            (c.tenhou && !c.dealer) || (c.chiihou && c.dealer),
            "tenhou is the dealer's, chiihou a non-dealer's",
        ),
    ];
    match rules.iter().find(|(bad, _)| *bad) {
        Some((_, message)) => Err(CliError::input(message)),
        None => Ok(()),
    }
}

pub fn run(args: Args) -> Result<(), CliError> {
    let (variant, win) = build_win(&args)?;
    let score = match hand::score(variant, &win) {
        Ok(s) => s,
        Err(e @ ScoreError::BadInput(_)) => return Err(CliError::input(e)),
        Err(e) => return Err(CliError::failure(e)),
    };
    if args.json {
        let yaku: Vec<_> = score
            .yaku
            .iter()
            .map(|y| serde_json::json!({"name": y.name, "han": y.han.number()}))
            .collect();
        let points = match score.payment {
            Payment::Ron { discarder } => serde_json::json!({ "ron": discarder, "total": score.gain }),
            Payment::Tsumo {
                dealer: Some(d),
                others,
            } => serde_json::json!({ "dealer_pays": d, "others_pay": others, "total": score.gain }),
            Payment::Tsumo { dealer: None, others } => serde_json::json!({ "others_pay": others, "total": score.gain }),
        };
        let v = serde_json::json!({
            "han": score.han,
            "fu": score.fu,
            "yakuman": score.yakuman,
            "yaku": yaku,
            "base": score.base,
            "points": points,
        });
        println!("{v}");
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
