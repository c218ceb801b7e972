//! The result of a round (element 16): `["和了", deltas, info, deltas, info, ..]` with one pair per
//! winner, or a draw `["流局", deltas]` / `["九種九牌"]`. A win's info is
//! `[winner, from, pao, "30符4飜7700点", "混一色(2飜)", ..]`.

use serde_json::Value;

use super::value::{numbers, show};
use rinshan_engine::hand::{Yaku, YakuHan};

/// How a round ended without a win, as Tenhou names it. Unlike the engine's
/// [`rinshan_engine::env::DrawKind`], an exhaustive draw has three names here, by how many seats were tenpai.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LoggedDraw {
    /// 流局: the wall ran out with one to three seats tenpai.
    Exhaustive,
    /// 全員聴牌
    AllTenpai,
    /// 全員不聴
    NoTenpai,
    /// 流し満貫
    Nagashi,
    /// 九種九牌
    Kyuushu,
    /// 四家立直
    FourRiichi,
    /// 三家和了
    TripleRon,
    /// 四槓散了
    FourKans,
    /// 四風連打
    FourWinds,
}

const DRAW_KINDS: [(&str, LoggedDraw); 9] = [
    ("流局", LoggedDraw::Exhaustive),
    ("全員聴牌", LoggedDraw::AllTenpai),
    ("全員不聴", LoggedDraw::NoTenpai),
    ("流し満貫", LoggedDraw::Nagashi),
    ("九種九牌", LoggedDraw::Kyuushu),
    ("四家立直", LoggedDraw::FourRiichi),
    ("三家和了", LoggedDraw::TripleRon),
    ("四槓散了", LoggedDraw::FourKans),
    ("四風連打", LoggedDraw::FourWinds),
];

impl LoggedDraw {
    /// The name Tenhou writes, e.g. `流局`.
    pub fn tenhou_name(self) -> &'static str {
        DRAW_KINDS
            .iter()
            .find(|(_, kind)| *kind == self)
            .map_or("", |(name, _)| name)
    }
}

/// A limit hand named in the points text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// 満貫: base 2000.
    Mangan,
    /// 跳満: base 3000.
    Haneman,
    /// 倍満: base 4000.
    Baiman,
    /// 三倍満: base 6000.
    Sanbaiman,
    /// 役満: base 8000 (and its multiples).
    Yakuman,
}

const LIMITS: [(&str, Limit); 7] = [
    ("満貫", Limit::Mangan),
    ("跳満", Limit::Haneman),
    ("倍満", Limit::Baiman),
    ("三倍満", Limit::Sanbaiman),
    ("役満", Limit::Yakuman),
    // Converters from other sites write these two.
    ("数え役満", Limit::Yakuman),
    ("切り上げ満貫", Limit::Mangan),
];

impl Limit {
    /// The name Tenhou writes in the points text, e.g. `満貫`.
    pub fn tenhou_name(self) -> &'static str {
        LIMITS
            .iter()
            .find(|(_, limit)| *limit == self)
            .map_or("", |(name, _)| name)
    }
}

/// One winner's share of a logged result.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LoggedWin {
    /// Score changes by seat, sticks and honba included.
    pub deltas: [i32; 4],
    /// The winner's seat.
    pub winner: usize,
    /// The seat that dealt in, or the winner for a tsumo.
    pub from: usize,
    /// The seat liable for a yakuman (pao), or the winner when nobody is.
    pub pao: usize,
    /// Won on one's own draw.
    pub tsumo: bool,
    /// Fu, from the points text when it gives fu and han (not for limit hands).
    pub fu: Option<u32>,
    /// Han, from the points text as `fu`.
    pub han: Option<u32>,
    /// The limit the points text names instead of fu and han.
    pub limit: Option<Limit>,
    /// The points text as written, e.g. `30符4飜7700点`, `満貫2000-4000点`, `40符3飜2600点∀`.
    pub points: String,
    /// The yaku in the log's order, dora last, by our names.
    pub yaku: Vec<Yaku>,
    /// The log gives no yaku, fu or han (libriichi's `hora` has only the deltas): `yaku`, `fu`,
    /// `han`, `limit` and `points` are rinshan's, scored by playing the round, and a replay
    /// judges the win by its winner and score changes alone.
    pub computed: bool,
}

/// How a round ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// One win, or more on a multiple ron, in the log's order.
    Wins(Vec<LoggedWin>),
    /// A round without a win.
    Draw {
        /// Tenhou's name for it.
        kind: LoggedDraw,
        /// The tenpai payments (or nagashi mangan), summed when the log lists several; `None`
        /// when the log gives none.
        deltas: Option<[i32; 4]>,
    },
}

/// Tenhou's yaku names and ours, in the order Tenhou lists a win's yaku (read off the shared
/// logs: riichi first, then ippatsu and tsumo, dora last; the only disagreements are two hands
/// where Tenhou lists a yakuhai before a wind or after sanankou, as its order there follows the
/// hand). Spellings that other converters write come after Tenhou's own, so the first entry of a
/// yaku is the one a writer uses.
const YAKU: [(&str, &str); 58] = [
    ("立直", "riichi"),
    ("両立直", "double_riichi"),
    ("一発", "ippatsu"),
    ("門前清自摸和", "menzen_tsumo"),
    ("槍槓", "chankan"),
    ("嶺上開花", "rinshan"),
    ("海底摸月", "haitei"),
    ("河底撈魚", "houtei"),
    ("平和", "pinfu"),
    ("一盃口", "iipeikou"),
    ("七対子", "chiitoitsu"),
    ("一気通貫", "ittsu"),
    ("三色同順", "sanshoku_doujun"),
    ("三槓子", "sankantsu"),
    ("三暗刻", "sanankou"),
    ("対々和", "toitoi"),
    ("断幺九", "tanyao"),
    ("三色同刻", "sanshoku_doukou"),
    ("小三元", "shousangen"),
    ("場風 東", "yakuhai_round_wind"),
    ("場風 南", "yakuhai_round_wind"),
    ("場風 西", "yakuhai_round_wind"),
    ("場風 北", "yakuhai_round_wind"),
    ("自風 東", "yakuhai_seat_wind"),
    ("自風 南", "yakuhai_seat_wind"),
    ("自風 西", "yakuhai_seat_wind"),
    ("自風 北", "yakuhai_seat_wind"),
    ("役牌 中", "yakuhai_red"),
    ("役牌 發", "yakuhai_green"),
    ("役牌 白", "yakuhai_white"),
    ("混全帯幺九", "chanta"),
    ("混老頭", "honroutou"),
    ("二盃口", "ryanpeikou"),
    ("純全帯幺九", "junchan"),
    ("混一色", "honitsu"),
    ("清一色", "chinitsu"),
    ("天和", "tenhou"),
    ("地和", "chiihou"),
    ("大三元", "daisangen"),
    ("四暗刻", "suuankou"),
    ("四暗刻単騎", "suuankou_tanki"),
    ("字一色", "tsuuiisou"),
    ("緑一色", "ryuuiisou"),
    ("清老頭", "chinroutou"),
    ("九蓮宝燈", "chuuren"),
    ("純正九蓮宝燈", "junsei_chuuren"),
    ("国士無双", "kokushi"),
    ("国士無双１３面", "kokushi_13"),
    ("大四喜", "daisuushi"),
    ("小四喜", "shousuushi"),
    ("四槓子", "suukantsu"),
    ("ドラ", "dora"),
    ("赤ドラ", "aka"),
    ("裏ドラ", "ura"),
    // Converters from other sites write these spellings.
    ("ダブル立直", "double_riichi"),
    ("国士無双13面", "kokushi_13"),
    // Mahjong Soul's names for the yakuhai of winds, as converters of its games write them.
    ("役牌:場風牌", "yakuhai_round_wind"),
    ("役牌:自風牌", "yakuhai_seat_wind"),
];

/// Mahjong Soul's yaku for the Norths set aside at three players (kita), which converters of
/// its games write beside ドラ. Tenhou lists them as dora, and rinshan's scoring counts them so.
const NORTH_DORA: &str = "抜きドラ";

/// The wind names of the yakuhai of winds, East to North.
const WINDS: [char; 4] = ['東', '南', '西', '北'];

/// Our name for a yaku Tenhou writes as `tenhou`.
pub(crate) fn yaku_name(tenhou: &str) -> Option<&'static str> {
    YAKU.iter().find(|(name, _)| *name == tenhou).map(|(_, ours)| *ours)
}

/// Our name as a `&'static str`, for a yaku named in our words (as MJAI logs written here do).
pub(crate) fn our_yaku(name: &str) -> Option<&'static str> {
    YAKU.iter().find(|(_, ours)| *ours == name).map(|(_, ours)| *ours)
}

/// What a win's points text says the hand is worth before honba and sticks at a table of
/// `seats`: a ron's payment, or a tsumo's payments summed (`500-1000点` from every other seat,
/// the dealer paying the second amount; `2600点∀` from each: three seats of four, two of three).
pub(crate) fn points_total(text: &str, seats: usize) -> Option<u32> {
    let others = seats.checked_sub(1).and_then(|n| u32::try_from(n).ok())?;
    let rest = text.rsplit(['符', '飜']).next().unwrap_or(text);
    let rest = LIMITS
        .iter()
        .find_map(|(name, _)| rest.strip_prefix(name))
        .unwrap_or(rest);
    let (amount, each) = match rest.strip_suffix('∀') {
        Some(amount) => (amount, true),
        None => (rest, false),
    };
    let amount = amount.strip_suffix('点')?;
    match amount.split_once('-') {
        Some((child, dealer)) => Some((others - 1) * number(child).ok()? + number(dealer).ok()?),
        None if each => Some(others * number(amount).ok()?),
        None => number(amount).ok(),
    }
}

/// The name Tenhou writes for our yaku `ours` and where Tenhou lists it among a win's yaku. The
/// yakuhai of winds need the seat's and the round's wind (0 = East .. 3 = North).
pub(crate) fn tenhou_yaku(ours: &str, seat_wind: usize, round_wind: usize) -> Option<(&'static str, usize)> {
    let wind = match ours {
        "yakuhai_seat_wind" => WINDS.get(seat_wind),
        "yakuhai_round_wind" => WINDS.get(round_wind),
        _ => None,
    };
    YAKU.iter()
        .enumerate()
        .find(|(_, (name, our))| *our == ours && wind.is_none_or(|&w| name.ends_with(w)))
        .map(|(rank, (name, _))| (*name, rank))
}

/// The result of a round at a table of `seats`.
pub(super) fn parse_result(v: &Value, seats: usize) -> Result<Outcome, String> {
    let items = v.as_array().ok_or_else(|| format!("{} is not a list", show(v)))?;
    let (kind, rest) = items.split_first().ok_or("is empty")?;
    let kind = kind
        .as_str()
        .ok_or_else(|| format!("{} is not a result kind", show(kind)))?;
    if kind == "和了" {
        if rest.is_empty() || rest.len() % 2 != 0 {
            return Err(format!(
                "和了 needs pairs of [deltas, info], found {} entries after it",
                rest.len()
            ));
        }
        let wins = rest.chunks(2).enumerate().map(|(i, pair)| match pair {
            [deltas, info] => parse_win(deltas, info, seats).map_err(|m| format!("win {i}: {m}")),
            _ => Err(format!("win {i} has no info")),
        });
        return wins.collect::<Result<Vec<LoggedWin>, String>>().map(Outcome::Wins);
    }
    let known = DRAW_KINDS.iter().find(|(name, _)| *name == kind).map(|(_, k)| *k);
    let names: Vec<&str> = DRAW_KINDS.iter().map(|(name, _)| *name).collect();
    let kind = known.ok_or_else(|| format!("{kind:?} is not a known result (和了, {})", names.join(", ")))?;
    let mut deltas = None;
    for (i, item) in rest.iter().enumerate() {
        let more = numbers::<4>(item).map_err(|m| format!("deltas {i}: {m}"))?;
        let sum: [i32; 4] = deltas.unwrap_or_default();
        deltas = Some(std::array::from_fn(|s| sum[s].saturating_add(more[s])));
    }
    if kind == LoggedDraw::Exhaustive && !deltas.is_some_and(|d| d.iter().any(|&x| x != 0)) {
        // 全員聴牌 and 全員不聴 are the exhaustive draws without payments.
        return Err("流局 without tenpai payments (Tenhou writes 全員聴牌 or 全員不聴 then)".into());
    }
    Ok(Outcome::Draw { kind, deltas })
}

fn parse_win(deltas: &Value, info: &Value, seats: usize) -> Result<LoggedWin, String> {
    let deltas = numbers::<4>(deltas).map_err(|m| format!("deltas: {m}"))?;
    let items = info
        .as_array()
        .ok_or_else(|| format!("info {} is not a list", show(info)))?;
    let seat = |i: usize, what: &str| -> Result<usize, String> {
        let item = items
            .get(i)
            .ok_or_else(|| format!("info {} has no {what}", show(info)))?;
        let seat = item.as_u64().filter(|&s| s < 4).and_then(|s| usize::try_from(s).ok());
        seat.ok_or_else(|| format!("{what} {} is not a seat 0-3", show(item)))
    };
    let (winner, from, pao) = (seat(0, "winner")?, seat(1, "from")?, seat(2, "pao")?);
    let points = items.get(3).and_then(Value::as_str);
    let points = points.ok_or_else(|| format!("info {} has no points text", show(info)))?;
    let Points { fu, han, limit } = parse_points(points).map_err(|m| format!("points {points:?}: {m}"))?;
    let yaku = items
        .iter()
        .skip(4)
        .map(parse_yaku)
        .collect::<Result<Vec<Yaku>, String>>()?;
    let yaku = north_dora_counted(yaku, seats)?;
    check_yaku(&yaku)?;
    if let Some(han) = han {
        let sum: u32 = yaku
            .iter()
            .map(|y| if let YakuHan::Han(h) = y.han { h } else { 0 })
            .sum();
        let yakuman = yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_)));
        if sum != han || yakuman {
            return Err(format!(
                "the yaku add up to {sum} han, but the points text {points:?} says {han}"
            ));
        }
    }
    Ok(LoggedWin {
        deltas,
        winner,
        from,
        pao,
        tsumo: winner == from,
        fu,
        han,
        limit,
        points: points.to_string(),
        yaku,
        computed: false,
    })
}

/// The yaku with Mahjong Soul's [`NORTH_DORA`] added to the dora (at three players only).
fn north_dora_counted(yaku: Vec<Yaku>, seats: usize) -> Result<Vec<Yaku>, String> {
    let (north, mut rest): (Vec<Yaku>, Vec<Yaku>) = yaku.into_iter().partition(|y| y.name == NORTH_DORA);
    if north.is_empty() {
        return Ok(rest);
    }
    if seats != 3 {
        return Err(format!(
            "{NORTH_DORA} (the dora of Norths set aside) at four players, who keep North"
        ));
    }
    let mut added = 0u32;
    for y in &north {
        let YakuHan::Han(h) = y.han else {
            return Err(format!("{NORTH_DORA} worth a yakuman"));
        };
        added = added.saturating_add(h);
    }
    match rest.iter_mut().find(|y| y.name == "dora") {
        Some(Yaku {
            han: YakuHan::Han(h), ..
        }) => *h = h.saturating_add(added),
        _ => rest.push(Yaku {
            name: "dora",
            han: YakuHan::Han(added),
        }),
    }
    Ok(rest)
}

/// Fu, han and limit of a points text: `30符4飜7700点`, `30符2飜500-1000点`, `40符3飜2600点∀`
/// (a dealer's tsumo, each pays), `満貫8000点`.
fn parse_points(text: &str) -> Result<Points, String> {
    let (fu, han, limit, rest) = match text.split_once('符') {
        Some((fu, rest)) => {
            let (han, rest) = rest.split_once('飜').ok_or("it has 符 but no 飜")?;
            (Some(number(fu)?), Some(number(han)?), None, rest)
        }
        None => {
            let limit = LIMITS
                .iter()
                .find_map(|&(name, limit)| text.strip_prefix(name).map(|rest| (limit, rest)));
            let (limit, rest) = limit.ok_or("it starts with neither fu and han nor 満貫, 跳満, 倍満, 三倍満, 役満")?;
            (None, None, Some(limit), rest)
        }
    };
    let amount = rest.strip_suffix('∀').unwrap_or(rest);
    let amount = amount.strip_suffix('点').ok_or("it does not end in 点 (or 点∀)")?;
    match amount.split_once('-') {
        Some((child, dealer)) => number(child).and(number(dealer))?,
        None => number(amount)?,
    };
    Ok(Points { fu, han, limit })
}

/// What a points text says besides the points.
struct Points {
    fu: Option<u32>,
    han: Option<u32>,
    limit: Option<Limit>,
}

/// The most han one logged yaku may be worth. No hand comes near it (ten dora indicators can
/// find at most 40 dora, and a yakuman is 13 han in MJAI's count), and with each yaku named once
/// a win's han and yakuman add up without overflow, whatever a log claims.
pub(crate) const MOST_YAKU_HAN: u32 = 99;

/// A win's yaku as the log lists them: each named once and worth at most [`MOST_YAKU_HAN`].
pub(crate) fn check_yaku(yaku: &[Yaku]) -> Result<(), String> {
    for (i, y) in yaku.iter().enumerate() {
        let unit = if matches!(y.han, YakuHan::Han(_)) {
            "han"
        } else {
            "yakuman"
        };
        if y.han.number() > MOST_YAKU_HAN {
            return Err(format!(
                "yaku {} is worth {} {unit}, more than a hand holds",
                y.name,
                y.han.number()
            ));
        }
        if yaku[..i].iter().any(|x| x.name == y.name) {
            return Err(format!("yaku {} is listed twice", y.name));
        }
    }
    Ok(())
}

fn number(digits: &str) -> Result<u32, String> {
    let n = digits
        .parse::<u32>()
        .ok()
        .filter(|_| digits.bytes().all(|b| b.is_ascii_digit()));
    n.ok_or_else(|| format!("{digits:?} is not a number"))
}

/// `混一色(2飜)` or `大三元(役満)`; `国士無双１３面(ダブル役満)` for a yakuman that counts double
/// (Tenhou's rules count each yakuman once and never write it; the writer does for a variant
/// whose spec makes a yakuman double).
fn parse_yaku(v: &Value) -> Result<Yaku, String> {
    let text = v.as_str().ok_or_else(|| format!("yaku {} is not a string", show(v)))?;
    let split = text.strip_suffix(')').and_then(|t| t.rsplit_once('('));
    let (name, value) = split.ok_or_else(|| format!("yaku {text:?} is not written NAME(N飜) or NAME(役満)"))?;
    let han = match value {
        "役満" => YakuHan::Yakuman(1),
        "ダブル役満" => YakuHan::Yakuman(2),
        _ => match value.strip_suffix('飜').map(number) {
            Some(Ok(han)) => YakuHan::Han(han),
            _ => return Err(format!("yaku {text:?}: {value:?} is neither N飜 nor 役満")),
        },
    };
    let name = match name {
        NORTH_DORA => NORTH_DORA,
        _ => yaku_name(name).ok_or_else(|| format!("unknown yaku name {name:?} in {text:?}"))?,
    };
    Ok(Yaku { name, han })
}
