//! A win's yaku from an MJAI `hora`: rinshan's names (what the writer uses, lossless) or the
//! original mjai server's, whose `sangenpai` sums the dragon triplets; and the logged win with
//! its points text, rebuilt from the yaku, fu and han by the scoring kernel's rules (a hand with
//! under 5 han and no fu is taken for a mangan, as Tenhou writes no fu for limit hands).

use rinshan_engine::hand::{Yaku, YakuHan};

use super::write::YAKUMAN_HAN;
use crate::tenhou::log::{check_yaku, our_yaku, LoggedWin, MOST_YAKU_HAN};
use crate::tenhou::write::{limit_of, points_text, Scoring};

/// The original mjai server's yaku names (also written by the Tenhou-to-MJAI converters) and
/// ours. Its `sangenpai` sums the dragon triplets; the reader tells them apart from the hand.
pub(crate) const MJAI_YAKU: [(&str, &str); 41] = [
    ("reach", "riichi"),
    ("double_reach", "double_riichi"),
    ("ippatsu", "ippatsu"),
    ("menzenchin_tsumoho", "menzen_tsumo"),
    ("tanyaochu", "tanyao"),
    ("pinfu", "pinfu"),
    ("ipeko", "iipeikou"),
    ("bakaze", "yakuhai_round_wind"),
    ("jikaze", "yakuhai_seat_wind"),
    ("rinshankaiho", "rinshan"),
    ("chankan", "chankan"),
    ("haiteiraoyue", "haitei"),
    ("hoteiraoyui", "houtei"),
    ("sanshokudojun", "sanshoku_doujun"),
    ("ikkitsukan", "ittsu"),
    ("honchantaiyao", "chanta"),
    ("chitoitsu", "chiitoitsu"),
    ("toitoiho", "toitoi"),
    ("sananko", "sanankou"),
    ("honroto", "honroutou"),
    ("sanshokudoko", "sanshoku_doukou"),
    ("sankantsu", "sankantsu"),
    ("shosangen", "shousangen"),
    ("honiso", "honitsu"),
    ("junchantaiyao", "junchan"),
    ("ryanpeko", "ryanpeikou"),
    ("chiniso", "chinitsu"),
    ("tenho", "tenhou"),
    ("chiho", "chiihou"),
    ("kokushimuso", "kokushi"),
    ("daisangen", "daisangen"),
    ("suanko", "suuankou"),
    ("tsuiso", "tsuuiisou"),
    ("ryuiso", "ryuuiisou"),
    ("chinroto", "chinroutou"),
    ("daisushi", "daisuushi"),
    ("shosushi", "shousuushi"),
    ("sukantsu", "suukantsu"),
    ("churenpoton", "chuuren"),
    ("uradora", "ura"),
    ("akadora", "aka"),
];

/// The dragons' yakuhai with their tile types, in the order Tenhou lists them.
pub(crate) const DRAGONS: [(&str, usize); 3] = [("yakuhai_red", 33), ("yakuhai_green", 32), ("yakuhai_white", 31)];

/// Our name for a yaku named in our words or the original mjai's.
fn yaku_name(name: &str) -> Option<&'static str> {
    our_yaku(name).or_else(|| MJAI_YAKU.iter().find(|(m, _)| *m == name).map(|(_, ours)| *ours))
}

/// The yaku of a `yakus` list; `dragons` tells which dragon yakuhai a `sangenpai` stands for.
/// `fan`, when given, must be what the yaku add up to.
pub(super) fn hora_yaku(
    yakus: Vec<(String, u32)>,
    fan: Option<u32>,
    dragons: impl Fn() -> Vec<&'static str>,
) -> Result<Vec<Yaku>, String> {
    let mut yaku = Vec::new();
    for (name, han) in yakus {
        if name == "sangenpai" {
            let held = dragons();
            if held.len() as u32 != han {
                return Err(format!(
                    "sangenpai {han}, but the winner holds {} dragon triplets",
                    held.len()
                ));
            }
            yaku.extend(held.into_iter().map(|name| Yaku {
                name,
                han: YakuHan::Han(1),
            }));
            continue;
        }
        let name = yaku_name(&name).ok_or_else(|| format!("unknown yaku {name:?}"))?;
        if han > MOST_YAKU_HAN {
            return Err(format!("yaku {name} is worth {han} han, more than a hand holds"));
        }
        let han = if han >= YAKUMAN_HAN && !["dora", "aka", "ura"].contains(&name) {
            YakuHan::Yakuman(han / YAKUMAN_HAN)
        } else {
            YakuHan::Han(han)
        };
        yaku.push(Yaku { name, han });
    }
    check_yaku(&yaku)?;
    let han_sum: u32 = yaku
        .iter()
        .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
        .sum();
    let yakuman = yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_)));
    match fan {
        Some(fan) if !yakuman && fan != han_sum => Err(format!("fan {fan}, but the yakus add up to {han_sum} han")),
        _ => Ok(yaku),
    }
}

/// A logged win from an MJAI `hora`: the points text as Tenhou writes it, rebuilt from the
/// yaku, fu and han by the scoring kernel's rules of the game's rule set (`scoring`).
#[allow(clippy::too_many_arguments)]
pub(super) fn win(
    scoring: Scoring,
    winner: usize,
    from: usize,
    pao: usize,
    deltas: [i32; 4],
    fu: Option<u32>,
    fan: Option<u32>,
    yaku: Vec<Yaku>,
    dealer: bool,
) -> LoggedWin {
    let yakuman: u32 = yaku
        .iter()
        .map(|y| if let YakuHan::Yakuman(n) = y.han { n } else { 0 })
        .sum();
    let han_sum: u32 = yaku
        .iter()
        .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
        .sum();
    let han = fan.unwrap_or(han_sum);
    let base = match (yakuman, fu) {
        (0, Some(fu)) => scoring.base_points(han, fu, 0),
        (0, None) => scoring.base_points(han.max(5), 30, 0),
        (n, _) => scoring.base_points(0, 0, n),
    };
    let limit = limit_of(base);
    let tsumo = winner == from;
    let points = points_text(fu.unwrap_or(0), han, limit, scoring.payment(base, dealer, tsumo));
    LoggedWin {
        deltas,
        winner,
        from,
        pao,
        tsumo,
        fu: if limit.is_none() { fu } else { None },
        han: if limit.is_none() { Some(han) } else { None },
        limit,
        points,
        yaku,
        computed: false,
    }
}
