//! The writer's text against the real Tenhou logs in tests/data/tenhou: every line written back from its parse,
//! every win's points text and score changes worked out from fu, han and the table.

use std::path::PathBuf;

use serde_json::Value;

use super::json::{discard_value, draw_value, round_line, yaku_text};
use super::outcome::{limit_of, points_text, Scoring};
use super::*;
use crate::tenhou::log::{collect_files, parse_game, tenhou_yaku, Discard, Draw, Limit, Outcome, Rel, Round};
use rinshan_engine::hand::{Yaku, YakuHan};
use rinshan_engine::tile::Tile;
use rinshan_engine::Variant;

/// Every real log file's text and its parse (shared with the MJAI tests).
pub(crate) fn real_logs() -> Vec<(String, Game)> {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/tenhou");
    let files = collect_files(&[PathBuf::from(data)]).expect("the data folder lists");
    files
        .iter()
        .map(|f| {
            let text = std::fs::read_to_string(f).expect("a real log reads");
            let game = parse_game(&f.display().to_string(), &text).unwrap_or_else(|e| panic!("{e}"));
            (text, game)
        })
        .collect()
}

fn t(code: u8) -> Tile {
    Tile::from_tenhou_code(code).expect("a valid tile code in the test")
}

#[test]
fn every_real_line_is_written_back_as_tenhou_wrote_it() {
    let mut lines = 0;
    for (text, game) in real_logs() {
        let records: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
        assert_eq!(records.len(), game.rounds.len(), "{}: one round per line", game.path);
        for (line, round) in records.iter().zip(&game.rounds) {
            assert_eq!(&round_line(&game, round), line, "{} line {}", game.path, round.line);
            lines += 1;
        }
        assert_eq!(game_text(&game), format!("{}\n", records.join("\n")));
    }
    assert_eq!(lines, 232);
}

#[test]
fn call_and_kan_strings_in_every_position() {
    let (b5, r5) = (t(25), t(52));
    let cases: [(Value, Value); 9] = [
        (
            draw_value(&Draw::Chi {
                called: t(13),
                own: [t(14), t(51)],
            }),
            "c131451".into(),
        ),
        (
            draw_value(&Draw::Pon {
                called: b5,
                own: [b5, r5],
                from: Rel::Left,
            }),
            "p252552".into(),
        ),
        (
            draw_value(&Draw::Pon {
                called: r5,
                own: [b5, b5],
                from: Rel::Across,
            }),
            "25p5225".into(),
        ),
        (
            draw_value(&Draw::Pon {
                called: b5,
                own: [b5, r5],
                from: Rel::Right,
            }),
            "2552p25".into(),
        ),
        (
            draw_value(&Draw::OpenKan {
                called: t(39),
                own: [t(39); 3],
                from: Rel::Across,
            }),
            "39m393939".into(),
        ),
        (
            draw_value(&Draw::OpenKan {
                called: t(39),
                own: [t(39); 3],
                from: Rel::Right,
            }),
            "393939m39".into(),
        ),
        (
            discard_value(&Discard::AddedKan {
                added: t(42),
                pon: [t(42); 3],
                from: Rel::Across,
            }),
            "42k424242".into(),
        ),
        (
            discard_value(&Discard::ClosedKan {
                tiles: [t(15), t(15), t(15), t(51)],
            }),
            "151515a51".into(),
        ),
        (discard_value(&Discard::Riichi(None)), "r60".into()),
    ];
    for (written, expected) in cases {
        assert_eq!(written, expected);
    }
    assert_eq!(discard_value(&Discard::Tsumogiri), Value::from(60));
    assert_eq!(discard_value(&Discard::Nothing), Value::from(0));
}

/// Riichi sticks a round's first winner collects: the ones on the table and the ones paid in
/// the round (declarations whose discard was not ronned).
fn sticks_collected(r: &Round) -> u32 {
    let ronned = match &r.outcome {
        Outcome::Wins(ws) => ws.iter().find(|w| !w.tsumo).map(|w| w.from),
        Outcome::Draw { .. } => None,
    };
    let paid = (0..4).filter(|&s| {
        let riichi = r.discards[s].iter().any(|d| matches!(d, Discard::Riichi(_)));
        let last_is_riichi = matches!(r.discards[s].last(), Some(Discard::Riichi(_)));
        riichi && !(ronned == Some(s) && last_is_riichi)
    });
    r.sticks + paid.count() as u32
}

#[test]
fn every_real_win_has_the_points_text_and_score_changes_of_its_fu_and_han() {
    let red = Scoring::of(Variant::Red);
    let mut wins = 0;
    for (_, game) in real_logs() {
        for r in &game.rounds {
            let Outcome::Wins(ws) = &r.outcome else { continue };
            for (n, w) in ws.iter().enumerate() {
                let yakuman: u32 = w
                    .yaku
                    .iter()
                    .map(|y| if let YakuHan::Yakuman(x) = y.han { x } else { 0 })
                    .sum();
                let han: u32 = w
                    .yaku
                    .iter()
                    .map(|y| if let YakuHan::Han(x) = y.han { x } else { 0 })
                    .sum();
                // A limit hand's text has no fu: any fu that reaches its limit reads the same.
                let fu = w.fu.unwrap_or(70);
                let base = red.base_points(han, fu, yakuman);
                assert_eq!(limit_of(base), w.limit, "{} {r}: {}", game.path, w.points);
                let pay = red.payment(base, w.winner == r.dealer(), w.tsumo);
                assert_eq!(points_text(fu, han, w.limit, pay), w.points, "{} {r}", game.path);
                let (honba, sticks) = if n == 0 { (r.honba, sticks_collected(r)) } else { (0, 0) };
                let from = (!w.tsumo).then_some(w.from);
                let pao = (w.pao != w.winner).then_some((w.pao, [1, 1]));
                let deltas = red.win_deltas(w.winner, from, r.dealer(), pay, (honba, sticks), pao);
                assert_eq!(deltas, w.deltas, "{} {r}: {}", game.path, w.points);
                wins += 1;
            }
        }
    }
    assert_eq!(wins, 188);
}

/// Mahjong Soul's pao on a composite yakuman (daisangen + tsuuiisou, a non-dealer's double, the
/// dealer liable): the liable seat covers daisangen's half only (ja.wikipedia 責任払い), as the
/// mjsoul scenarios of tests/data/scenarios.toml play it in the engine.
#[test]
fn a_pao_share_pays_only_its_part() {
    let red = Scoring::of(Variant::Red);
    let tsumo = red.payment(red.base_points(0, 0, 2), false, true);
    assert_eq!(
        red.win_deltas(2, None, 0, tsumo, (0, 0), Some((0, [1, 2]))),
        [-48_000, -8_000, 64_000, -8_000],
        "the dealer pays 16000 of its own 32000 and 8000 of each other payer's 16000"
    );
    // Ron off seat 3 with one honba: the liable seat pays half of its 32000 share, the discarder
    // the rest and the 300.
    let ron = red.payment(red.base_points(0, 0, 2), false, false);
    assert_eq!(
        red.win_deltas(2, Some(3), 0, ron, (1, 0), Some((0, [1, 2]))),
        [-16_000, 0, 64_300, -48_300]
    );
    // The whole hand (Tenhou): half each, honba to the discarder; a tsumo all on the liable seat.
    assert_eq!(
        red.win_deltas(2, Some(3), 0, ron, (1, 0), Some((0, [1, 1]))),
        [-32_000, 0, 64_300, -32_300]
    );
    assert_eq!(
        red.win_deltas(2, None, 0, tsumo, (0, 0), Some((0, [1, 1]))),
        [-64_000, 0, 64_000, 0]
    );
}

/// M-League (`pao_pays_honba`): the liable seat also pays the honba the discarder or each payer
/// would (ron: 2 honba, all 600 on the liable seat; a composite double yakuman tsumo: each
/// payer's 100 on the liable seat with its share).
#[test]
fn mleague_pao_pays_the_honba() {
    let m = Scoring::of(Variant::Mleague);
    let ron = m.payment(m.base_points(0, 0, 1), false, false);
    assert_eq!(
        m.win_deltas(2, Some(3), 0, ron, (2, 0), Some((0, [1, 1]))),
        [-16_600, 0, 32_600, -16_000]
    );
    let tsumo = m.payment(m.base_points(0, 0, 2), false, true);
    assert_eq!(
        m.win_deltas(2, None, 0, tsumo, (1, 0), Some((0, [1, 2]))),
        [-48_300, -8_000, 64_300, -8_000]
    );
    // Tenhou: the discarder pays the honba.
    let red = Scoring::of(Variant::Red);
    assert_eq!(
        red.win_deltas(2, Some(3), 0, ron, (2, 0), Some((0, [1, 1]))),
        [-16_000, 0, 32_600, -16_600]
    );
}

/// Kiriage mangan (M-League, WRC) and no kazoe yakuman (13 han is sanbaiman) in the points text.
#[test]
fn points_texts_follow_each_rule_set() {
    let text = |v: Variant, han, fu| {
        let s = Scoring::of(v);
        let base = s.base_points(han, fu, 0);
        points_text(fu, han, limit_of(base), s.payment(base, false, false))
    };
    assert_eq!(text(Variant::Red, 4, 30), "30符4飜7700点");
    assert_eq!(text(Variant::Mleague, 4, 30), "満貫8000点");
    assert_eq!(text(Variant::Wrc, 3, 60), "満貫8000点");
    assert_eq!(text(Variant::Red, 13, 30), "役満32000点");
    assert_eq!(text(Variant::Wrc, 13, 30), "三倍満24000点");
    assert_eq!(text(Variant::Mleague, 13, 30), "三倍満24000点");
}

#[test]
fn points_texts_of_each_form() {
    let red = Scoring::of(Variant::Red);
    let text = |han, fu, yakuman, dealer, tsumo| {
        let base = red.base_points(han, fu, yakuman);
        points_text(fu, han, limit_of(base), red.payment(base, dealer, tsumo))
    };
    assert_eq!(text(4, 30, 0, false, false), "30符4飜7700点");
    assert_eq!(text(2, 30, 0, false, true), "30符2飜500-1000点");
    assert_eq!(text(3, 40, 0, true, true), "40符3飜2600点∀");
    assert_eq!(text(4, 40, 0, false, false), "満貫8000点");
    assert_eq!(text(7, 30, 0, false, true), "跳満3000-6000点");
    assert_eq!(text(9, 30, 0, true, false), "倍満24000点");
    assert_eq!(text(11, 30, 0, true, true), "三倍満12000点∀");
    assert_eq!(text(0, 0, 1, false, false), "役満32000点");
    assert_eq!(text(14, 30, 0, false, false), "役満32000点");
    assert_eq!(text(0, 0, 2, true, false), "役満96000点");
}

#[test]
fn yaku_in_tenhou_order_except_two_yakuhai() {
    let (mut same, mut differ) = (0, 0);
    for (_, game) in real_logs() {
        for r in &game.rounds {
            let Outcome::Wins(ws) = &r.outcome else { continue };
            for w in ws {
                let seat_wind = (w.winner + 4 - r.dealer()) % 4;
                let rank = |y: &Yaku| tenhou_yaku(y.name, seat_wind, (r.kyoku / 4) as usize).map(|(_, rank)| rank);
                let mut sorted = w.yaku.clone();
                sorted.sort_by_key(rank);
                if sorted == w.yaku {
                    same += 1;
                } else {
                    differ += 1;
                }
            }
        }
    }
    // Tenhou lists yakuhai in the order of the hand's sets: `役牌 中` before `自風 北` in one
    // win, `三暗刻` before `役牌 發` in another.
    assert_eq!((same, differ), (186, 2));
}

#[test]
fn double_yakuman_is_written_and_read_back() {
    let y = Yaku {
        name: "kokushi_13",
        han: YakuHan::Yakuman(2),
    };
    let text = yaku_text(&y, 0, 0);
    assert_eq!(text, "国士無双１３面(ダブル役満)");
    let winds = yaku_text(
        &Yaku {
            name: "yakuhai_seat_wind",
            han: YakuHan::Han(1),
        },
        2,
        0,
    );
    assert_eq!(winds, "自風 西(1飜)");
    let limit = Limit::Yakuman.tenhou_name();
    let line = format!(
        r#"{{"title":["",""],"name":["A","B","C","D"],"rule":{{"disp":"鳳南喰赤","aka":1}},"log":[[[0,0,0],[25000,25000,25000,25000],[11],[],[11,19,21,29,31,39,41,42,43,44,45,46,47],[11],[],[12,12,12,13,13,13,14,14,14,15,15,15,16],[],[],[12,12,12,13,13,13,14,14,14,15,15,15,16],[],[],[12,12,12,13,13,13,14,14,14,15,15,15,16],[],[],["和了",[96000,-32000,-32000,-32000],[0,0,0,"{limit}32000点∀","{text}"]]]]}}"#
    );
    let game = parse_game("double.json", &line).expect("a double yakuman reads");
    let Outcome::Wins(ws) = &game.rounds[0].outcome else {
        panic!("a win")
    };
    assert_eq!(ws[0].yaku, vec![y]);
    assert_eq!(round_line(&game, &game.rounds[0]), line);
}
