//! The tenhou.net/6 text of a [`Game`]: what [`crate::tenhou::log::parse_game`] reads, written
//! the way Tenhou writes it (key order, tile order in calls, `60`, `r60`, `0`, result names).

use serde_json::{json, Value};

use crate::tenhou::log::{tenhou_yaku, Discard, Draw, Game, LoggedWin, Outcome, Rel, Round};
use rinshan_engine::hand::{Yaku, YakuHan};
use rinshan_engine::tile::Tile;
use rinshan_engine::Variant;

/// The game as a tenhou.net/6 file: one record per round, one line each.
pub fn game_text(game: &Game) -> String {
    let mut text = String::new();
    for round in &game.rounds {
        text.push_str(&round_line(game, round));
        text.push('\n');
    }
    text
}

/// One round as a whole record: `{"title":["",""],"name":[..],"rule":{..},"log":[ROUND]}`.
pub(super) fn round_line(game: &Game, round: &Round) -> String {
    // Put together by hand: a serde_json map sorts its keys, and Tenhou writes title, name,
    // rule, log (and disp before aka).
    let names = Value::from(game.names.to_vec());
    let disp = Value::from(game.rule.as_str());
    // Tenhou's own rules are named by `disp` alone, so their logs stay as Tenhou writes them.
    let variant = match game.variant {
        Variant::Red => String::new(),
        v => format!(",\"variant\":{}", Value::from(v.to_string())),
    };
    format!(
        "{{\"title\":[\"\",\"\"],\"name\":{names},\"rule\":{{\"disp\":{disp},\"aka\":{}{variant}}},\"log\":[{}]}}",
        u8::from(game.red_fives),
        round_value(round)
    )
}

/// The 17-element round array (see [`crate::tenhou::log`]).
pub(crate) fn round_value(r: &Round) -> Value {
    let codes = |tiles: &[Tile]| Value::from(tiles.iter().map(|t| t.tenhou_code()).collect::<Vec<u8>>());
    let mut items = vec![
        json!([r.kyoku, r.honba, r.sticks]),
        json!(r.scores),
        codes(&r.dora),
        codes(&r.ura),
    ];
    for seat in 0..4 {
        items.push(codes(&r.hands[seat]));
        items.push(r.draws[seat].iter().map(draw_value).collect());
        items.push(r.discards[seat].iter().map(discard_value).collect());
    }
    items.push(outcome_value(r));
    Value::Array(items)
}

/// `others[..at]`, the letter, `picked`, `others[at..]` as one string of two-digit codes.
fn written(letter: char, at: usize, picked: &[Tile], others: &[Tile]) -> String {
    let (before, after) = others.split_at(at.min(others.len()));
    let mut s = String::new();
    for t in before {
        s.push_str(&t.tenhou_code().to_string());
    }
    s.push(letter);
    for t in picked.iter().chain(after) {
        s.push_str(&t.tenhou_code().to_string());
    }
    s
}

/// How many of the caller's own tiles stand before the letter: the called tile is drawn turned
/// at the place of the seat it came from (left, across, right); an open kan has three own tiles.
fn own_before(from: Rel, own: usize) -> usize {
    match from {
        Rel::Left => 0,
        Rel::Across => 1,
        Rel::Right => own,
    }
}

/// A draw entry: a tile code, or a call string (`c131415`, `43p4343`, `393939m39`).
pub(super) fn draw_value(d: &Draw) -> Value {
    match *d {
        Draw::Tile(t) => t.tenhou_code().into(),
        Draw::Chi { called, own } => written('c', 0, &[called], &own).into(),
        Draw::Pon { called, own, from } => written('p', own_before(from, 2), &[called], &own).into(),
        Draw::OpenKan { called, own, from } => written('m', own_before(from, 3), &[called], &own).into(),
    }
}

/// A discard entry: a tile code, `60`, `r24`/`r60`, a kan string (`42k424242`, `151515a51`) or
/// the `0` after an open kan.
pub(super) fn discard_value(d: &Discard) -> Value {
    match *d {
        Discard::Tile(t) => t.tenhou_code().into(),
        Discard::Tsumogiri => 60.into(),
        Discard::Riichi(Some(t)) => format!("r{}", t.tenhou_code()).into(),
        Discard::Riichi(None) => "r60".into(),
        Discard::AddedKan {
            added,
            pon: [called, a, b],
            from,
        } => written('k', own_before(from, 2), &[added, called], &[a, b]).into(),
        Discard::ClosedKan { tiles } => written('a', 3, &tiles[3..], &tiles[..3]).into(),
        Discard::Nothing => 0.into(),
        Discard::Kita => crate::tenhou::log::KITA.into(),
    }
}

fn outcome_value(r: &Round) -> Value {
    let mut items: Vec<Value> = Vec::new();
    match &r.outcome {
        Outcome::Wins(wins) => {
            items.push("和了".into());
            for w in wins {
                items.push(json!(w.deltas));
                items.push(win_info(r, w));
            }
        }
        Outcome::Draw { kind, deltas } => {
            items.push(kind.tenhou_name().into());
            if let Some(d) = deltas {
                items.push(json!(d));
            }
        }
    }
    Value::Array(items)
}

/// `[winner, from, pao, "30符4飜7700点", "立直(1飜)", ..]`.
fn win_info(r: &Round, w: &LoggedWin) -> Value {
    let seat_wind = (w.winner + r.seats - r.dealer()) % r.seats;
    let round_wind = (r.kyoku / 4 % 4) as usize;
    let mut items: Vec<Value> = vec![w.winner.into(), w.from.into(), w.pao.into(), w.points.as_str().into()];
    items.extend(w.yaku.iter().map(|y| Value::from(yaku_text(y, seat_wind, round_wind))));
    Value::Array(items)
}

/// `立直(1飜)`, `大三元(役満)`, `国士無双１３面(ダブル役満)`.
pub(super) fn yaku_text(y: &Yaku, seat_wind: usize, round_wind: usize) -> String {
    let name = tenhou_yaku(y.name, seat_wind, round_wind).map_or(y.name, |(name, _)| name);
    match y.han {
        YakuHan::Han(h) => format!("{name}({h}飜)"),
        YakuHan::Yakuman(2) => format!("{name}(ダブル役満)"),
        YakuHan::Yakuman(_) => format!("{name}(役満)"),
    }
}
