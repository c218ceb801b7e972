//! A winning hand described as people write it (the `rinshan score` command's arguments, and
//! Python's `rinshan.score`): tiles in notation, circumstances as flags. Contradictory
//! circumstances are refused with a message rather than scored.

use crate::hand::{Payment, Score, Win, WinContext};
use crate::notation::{parse_meld, parse_tile, parse_tiles, parse_wind};
use crate::TileType;

/// A winning hand in notation, with the circumstances of the win.
// The field docs are also the `rinshan score` command's help: the CLI turns on the `clap` feature.
#[derive(Debug, Clone, Default)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct WinInput {
    /// Concealed tiles, with or without the winning tile, e.g. `234567m234p456s6s` (0 = red five)
    pub hand: String,
    /// The winning tile, e.g. `6s`
    #[cfg_attr(feature = "clap", arg(long))]
    pub win: String,
    /// Won by self-draw (default: ron)
    #[cfg_attr(feature = "clap", arg(long))]
    pub tsumo: bool,
    /// Riichi was declared
    #[cfg_attr(feature = "clap", arg(long))]
    pub riichi: bool,
    /// Double riichi (implies riichi)
    #[cfg_attr(feature = "clap", arg(long))]
    pub double_riichi: bool,
    /// Won within the first go-around after riichi
    #[cfg_attr(feature = "clap", arg(long))]
    pub ippatsu: bool,
    /// Tsumo on the last tile of the wall
    #[cfg_attr(feature = "clap", arg(long))]
    pub haitei: bool,
    /// Ron on the last discard
    #[cfg_attr(feature = "clap", arg(long))]
    pub houtei: bool,
    /// Tsumo on a kan replacement tile
    #[cfg_attr(feature = "clap", arg(long))]
    pub rinshan: bool,
    /// Ron on a tile added to a pon
    #[cfg_attr(feature = "clap", arg(long))]
    pub chankan: bool,
    /// The dealer won on the first draw
    #[cfg_attr(feature = "clap", arg(long))]
    pub tenhou: bool,
    /// A non-dealer won on its first draw
    #[cfg_attr(feature = "clap", arg(long))]
    pub chiihou: bool,
    /// The winner is the dealer (seat wind East)
    #[cfg_attr(feature = "clap", arg(long))]
    pub dealer: bool,
    /// E, S, W or N
    #[cfg_attr(feature = "clap", arg(long, default_value = "E"))]
    pub round_wind: String,
    /// E, S, W or N (default: E for the dealer, else S)
    #[cfg_attr(feature = "clap", arg(long))]
    pub seat_wind: Option<String>,
    /// Dora indicator tiles, e.g. `3m7z`
    #[cfg_attr(feature = "clap", arg(long))]
    pub dora: Option<String>,
    /// Ura-dora indicator tiles (count only with riichi)
    #[cfg_attr(feature = "clap", arg(long))]
    pub ura: Option<String>,
    /// A called or declared meld: chi:123m, pon:555z, kan:2222p (open), ankan:1111s, kakan:3333m
    #[cfg_attr(feature = "clap", arg(long = "meld"))]
    pub melds: Vec<String>,
    /// Honba (repeat) sticks on the table
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 0))]
    pub honba: u32,
    /// Riichi sticks on the table
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 0))]
    pub sticks: u32,
}

/// Why a [`WinInput`] does not describe a hand that can be scored.
#[derive(Debug, Clone, PartialEq)]
pub struct WinInputError(pub String);

impl std::fmt::Display for WinInputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for WinInputError {}

impl WinInputError {
    fn from(message: impl std::fmt::Display) -> WinInputError {
        WinInputError(message.to_string())
    }
}

impl WinInput {
    /// The hand to score, or what is wrong with the description.
    pub fn win(&self) -> Result<Win, WinInputError> {
        build_win(self)
    }
}

/// A score as JSON: han, fu, yakuman, yaku (name and han), base points and the payments.
pub fn score_json(score: &Score) -> serde_json::Value {
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
    serde_json::json!({
        "han": score.han,
        "fu": score.fu,
        "yakuman": score.yakuman,
        "yaku": yaku,
        "base": score.base,
        "points": points,
    })
}

fn indicators(src: &Option<String>) -> Result<Vec<TileType>, WinInputError> {
    match src {
        None => Ok(Vec::new()),
        Some(s) => Ok(parse_tiles(s)
            .map_err(WinInputError::from)?
            .tiles
            .iter()
            .map(|t| t.kind())
            .collect()),
    }
}

fn build_win(args: &WinInput) -> Result<Win, WinInputError> {
    let tiles = parse_tiles(&args.hand).map_err(WinInputError::from)?;
    let win_tile = parse_tile(&args.win).map_err(WinInputError::from)?;
    let win = win_tile.kind();
    let melds = args
        .melds
        .iter()
        .map(|m| parse_meld(m).map_err(WinInputError::from))
        .collect::<Result<Vec<_>, _>>()?;
    // The size first: past it every count below is at most 14.
    let concealed = tiles.tiles.len();
    let size = concealed.saturating_add(melds.len().saturating_mul(3));
    if size != 13 && size != 14 {
        return Err(WinInputError::from(format!(
            "{concealed} concealed tiles with {} meld(s): give 13 - 3 x melds tiles (the winning tile then comes from --win) or 14 - 3 x melds including it",
            melds.len()
        )));
    }
    let mut hand = tiles.counts();
    let mut red = tiles.red() + melds.iter().map(|m| m.red).sum::<u8>();
    if size == 13 {
        hand[win.index()] += 1;
        red += u8::from(win_tile.is_red());
    } else if hand[win.index()] == 0 {
        return Err(WinInputError::from(format!(
            "the hand has 14 tiles but not the winning tile {}",
            args.win
        )));
    }
    let round_wind = parse_wind(&args.round_wind).map_err(WinInputError::from)?;
    let seat_wind = match &args.seat_wind {
        Some(s) => parse_wind(s).map_err(WinInputError::from)?,
        None if args.dealer => 0,
        None => 1,
    };
    if args.dealer && seat_wind != 0 {
        return Err(WinInputError::from(
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
    Ok(Win {
        hand,
        win,
        melds,
        aka: red,
        context,
    })
}

/// Circumstances that contradict each other are input errors, not silently scored.
fn check_context(c: &WinContext, melds: &[crate::notation::Meld]) -> Result<(), WinInputError> {
    use crate::notation::MeldKind;
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
        Some((_, message)) => Err(WinInputError::from(message)),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Variant;

    fn input(hand: &str, win: &str) -> WinInput {
        WinInput {
            hand: hand.into(),
            win: win.into(),
            round_wind: "E".into(),
            ..WinInput::default()
        }
    }

    // Found by the hand_text fuzz target: counting 256 copies of a tile overflowed a u8.
    #[test]
    fn a_run_of_hundreds_of_one_tile_is_an_error() {
        let hand = format!("{}m", "1".repeat(300));
        assert!(crate::hand::shanten_of_notation(&hand)
            .unwrap_err()
            .contains("copies of 1m"));
        assert!(input(&hand, "1m").win().is_err());
    }

    #[test]
    fn hundreds_of_red_melds_are_an_error() {
        let mut i = input("11z", "1z");
        i.melds = vec!["chi:340m".to_string(); 300];
        assert!(i.win().unwrap_err().0.contains("300 meld(s)"));
    }

    #[test]
    fn more_sticks_than_points_can_hold_are_an_error() {
        let mut i = input("234567m234p456s6s", "6s");
        i.tsumo = true;
        i.honba = 10_000;
        i.sticks = 10_000;
        let win = i.win().expect("a winning hand");
        assert!(crate::hand::score(Variant::Red, &win).is_ok());
        i.honba = u32::MAX;
        let win = i.win().expect("a winning hand");
        let e = crate::hand::score(Variant::Red, &win).unwrap_err().to_string();
        assert!(e.contains("at most 10000"), "{e}");
    }
}
