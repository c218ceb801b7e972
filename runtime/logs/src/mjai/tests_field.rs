//! MJAI as the rest of the field writes it: libriichi's `hora` without yaku and `ryukyoku`
//! without reason (the real logs with those fields struck out read as the same games), the
//! arena's own logs (tests/data/mjai/arena), and the three-player forks' `nukidora`.

use std::path::PathBuf;

use rinshan_engine::env::Backend;
use rinshan_engine::hand::Yaku;
use rinshan_engine::Variant;

use super::read::parse_game;
use super::write::game_text;
use crate::tenhou::log::{collect_files, Game, LoggedDraw, Outcome, Round};
use crate::tenhou::replay::replay;
use crate::tenhou::write::tests::real_logs;

/// The real tenhou.net/6 games: tests/data/tenhou and the JSON twins in tests/data/mjlog.
fn real_games() -> Vec<Game> {
    let mjlog = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjlog");
    let files = collect_files(&[PathBuf::from(mjlog)]).expect("the data folder lists");
    let twins = files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "json"))
        .map(|f| {
            let text = std::fs::read_to_string(f).expect("reads");
            crate::tenhou::log::parse_game(&f.display().to_string(), &text).unwrap_or_else(|e| panic!("{e}"))
        });
    real_logs().into_iter().map(|(_, g)| g).chain(twins).collect()
}

/// `game` as MJAI with `strike` applied to every event's JSON object.
fn struck(game: &Game, strike: impl Fn(&mut serde_json::Map<String, serde_json::Value>)) -> String {
    let mut out = String::new();
    for line in game_text(game).expect("writes").lines() {
        let mut event: serde_json::Map<String, serde_json::Value> = serde_json::from_str(line).expect("JSON");
        strike(&mut event);
        out.push_str(&serde_json::Value::Object(event).to_string());
        out.push('\n');
    }
    out
}

/// A log's events as JSON values (the struck logs' fields are in serde_json's order).
fn events(text: &str) -> Vec<serde_json::Value> {
    text.lines().map(|l| serde_json::from_str(l).expect("JSON")).collect()
}

fn sorted(yaku: &[Yaku]) -> Vec<Yaku> {
    let mut yaku = yaku.to_vec();
    yaku.sort_by_key(|y| y.name);
    yaku
}

#[test]
fn wins_without_yakus_are_scored_as_the_logs_score_them() {
    let mut wins = 0;
    let mut read = Vec::new();
    for game in real_games() {
        // libriichi's hora: actor, target, deltas and ura markers only (the tile won on kept, as
        // the writer gives it and other engines do).
        let text = struck(&game, |e| {
            if e["type"] == "hora" {
                e.retain(|k, _| ["type", "actor", "target", "pai", "deltas", "ura_markers"].contains(&k.as_str()));
            }
        });
        let back = parse_game(&game.path, &text).unwrap_or_else(|e| panic!("{e}"));
        for (ours, theirs) in back.rounds.iter().zip(&game.rounds) {
            let (Outcome::Wins(ours), Outcome::Wins(theirs)) = (&ours.outcome, &theirs.outcome) else {
                assert_eq!(ours.outcome, theirs.outcome, "{} {ours}", game.path);
                continue;
            };
            for (a, b) in ours.iter().zip(theirs) {
                assert!(a.computed && !b.computed);
                let score =
                    |w: &crate::tenhou::log::LoggedWin| (w.fu, w.han, w.limit, w.points.clone(), sorted(&w.yaku));
                assert_eq!(score(a), score(b), "{} {}", game.path, back.rounds[0]);
                wins += 1;
            }
        }
        // What rinshan scored stays out of the MJAI it writes, as it was out of the log.
        let (ours, theirs) = (events(&game_text(&back).expect("writes")), events(&text));
        let differ = ours.iter().zip(&theirs).find(|(a, b)| a != b);
        assert!(
            differ.is_none() && ours.len() == theirs.len(),
            "{}: {differ:?}",
            game.path
        );
        read.push(back);
    }
    assert!(wins > 100, "only {wins} wins");
    let report = replay(&read, Backend::Cpu).expect("the CPU env runs");
    assert!(report.all_agree(), "{report:?}");
    assert_eq!((report.wins_matching, report.wins_yaku_not_logged), (0, wins));
}

#[test]
fn draws_without_reason_or_tenpai_seats_read_as_the_logs_name_them() {
    let mut kinds = Vec::new();
    for game in real_games() {
        // libriichi's ryukyoku: its deltas only (all zero when nothing is paid).
        let text = struck(&game, |e| {
            if e["type"] == "ryukyoku" {
                e.retain(|k, _| k == "type" || k == "deltas");
                e.entry("deltas").or_insert(serde_json::json!([0, 0, 0, 0]));
            }
        });
        let back = parse_game(&game.path, &text).unwrap_or_else(|e| panic!("{e}"));
        for (ours, theirs) in back.rounds.iter().zip(&game.rounds) {
            assert_eq!(ours.outcome, theirs.outcome, "{} {ours}", game.path);
            assert_eq!(
                ours,
                &Round {
                    line: ours.line,
                    ..theirs.clone()
                },
                "{} {ours}",
                game.path
            );
        }
        kinds.extend(back.rounds.iter().filter_map(|r| match r.outcome {
            Outcome::Draw { kind, .. } => Some(kind),
            Outcome::Wins(_) => None,
        }));
    }
    for kind in [
        LoggedDraw::Exhaustive,
        LoggedDraw::NoTenpai,
        LoggedDraw::Kyuushu,
        LoggedDraw::FourRiichi,
        LoggedDraw::FourWinds,
        LoggedDraw::Nagashi,
    ] {
        assert!(kinds.contains(&kind), "no {kind:?} among {kinds:?}");
    }
}

fn arena_log(seed: u32) -> Game {
    let path = format!(
        "{}/../../tests/data/mjai/arena/arena-{seed}.mjson.gz",
        env!("CARGO_MANIFEST_DIR")
    );
    crate::file::read_log(std::path::Path::new(&path)).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_arenas_fourth_riichi_ends_the_round_before_the_draw_it_deals() {
    // East 4 of seed 7: libriichi deals seat 3 a tile after the fourth riichi stick, then aborts.
    let game = arena_log(7);
    let round = game
        .rounds
        .iter()
        .find(|r| r.kyoku == 3 && r.honba == 0)
        .expect("East 4");
    assert_eq!(
        round.outcome,
        Outcome::Draw {
            kind: LoggedDraw::FourRiichi,
            deltas: None
        }
    );
    let draws: usize = round.draws.iter().map(Vec::len).sum();
    let discards: usize = round.discards.iter().map(Vec::len).sum();
    assert_eq!(draws, discards, "no draw after the last discard");
    let report = replay(&[game], Backend::Cpu).expect("the CPU env runs");
    assert!(report.all_agree(), "{report:?}");
}

#[test]
fn a_win_the_engine_does_not_make_is_refused_by_name() {
    // The arena's first win, moved to another seat: the engine ends the round otherwise.
    let text = std::fs::read(format!(
        "{}/../../tests/data/mjai/arena/arena-1.mjson.gz",
        env!("CARGO_MANIFEST_DIR")
    ))
    .expect("reads");
    let text = crate::file::log_text("a.mjson", &text).expect("unpacks");
    let moved = text.replacen(
        r#"{"type":"hora","actor":0,"target":0"#,
        r#"{"type":"hora","actor":1,"target":1"#,
        1,
    );
    assert_ne!(moved, text);
    let message = parse_game("a.mjson", &moved).expect_err("refused").to_string();
    assert!(message.contains("East 1, 0 honba"), "{message}");
    assert!(message.contains("rinshan finds by playing the round"), "{message}");
}

#[test]
fn nukidora_reads_as_kita() {
    let sanma = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/mjlog/2014091101gm-00b9-0000-5ca6b487.xml"
    );
    let game = crate::file::read_log(std::path::Path::new(sanma)).unwrap_or_else(|e| panic!("{e}"));
    let text = game_text(&game).expect("writes");
    let forks = text.replace(r#""type":"kita""#, r#""type":"nukidora""#);
    assert_ne!(forks, text);
    let back = parse_game(&game.path, &forks).unwrap_or_else(|e| panic!("{e}"));
    let lines = |g: &Game| {
        g.rounds
            .iter()
            .map(|r| Round { line: 0, ..r.clone() })
            .collect::<Vec<_>>()
    };
    assert_eq!(lines(&back), lines(&game));
    // The writer keeps writing `kita`.
    assert_eq!(game_text(&back).expect("writes"), text);
}

/// `game` as MJAI with its `start_game` replaced by `header`.
fn with_header(game: &Game, header: serde_json::Value) -> String {
    let text = game_text(game).expect("writes");
    let (_, rest) = text.split_once('\n').expect("a start_game line");
    format!("{header}\n{rest}")
}

#[test]
fn a_start_game_naming_its_rule_set_plays_under_it() {
    let rules: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/data/mjai/jansou_rules.json"
        ))
        .expect("reads"),
    )
    .expect("JSON");
    let game = real_logs().remove(0).1;
    // jansou's header: names, preset and its whole rules.
    let jansou = |preset: &str| {
        let header = serde_json::json!({"type": "start_game", "names": ["a", "b", "c", "d"],
            "preset": preset, "rules": rules[preset]});
        parse_game("j.mjson", &with_header(&game, header))
    };
    assert_eq!(jansou("m-league").map(|g| g.variant), Ok(Variant::Mleague));
    assert_eq!(jansou("mahjong-soul").map(|g| g.variant), Ok(Variant::Mjsoul));
    let refused = jansou("renmei").expect_err("refused").to_string();
    assert!(
        refused.contains("line 1: start_game's rules: rinshan does not model ura_dora false"),
        "{refused}"
    );
    // A three-player rule set for four players' rounds.
    let refused = jansou("tenhou-3p").expect_err("refused").to_string();
    assert!(
        refused.contains("4 players sit at the table, but start_game names sanma"),
        "{refused}"
    );

    // rinshan names its own: a game read under mleague writes it, and reads back under it.
    let mut mleague = game.clone();
    mleague
        .play_under(Variant::Mleague)
        .expect("a four-player rule set with red fives");
    let text = game_text(&mleague).expect("writes");
    assert!(
        text.lines()
            .next()
            .is_some_and(|l| l.contains(r#""variant":"mleague""#)),
        "{text:.200}"
    );
    assert_eq!(parse_game("m.mjson", &text).map(|g| g.variant), Ok(Variant::Mleague));
    // Tenhou's rules are the reader's default, and are not named.
    assert!(!game_text(&game)
        .expect("writes")
        .lines()
        .next()
        .unwrap_or_default()
        .contains("variant"));

    // Three players: the rule set named stays the three-player one it names.
    let sanma = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/mjlog/2014091101gm-00b9-0000-5ca6b487.xml"
    );
    let mut three = crate::file::read_log(std::path::Path::new(sanma)).unwrap_or_else(|e| panic!("{e}"));
    three
        .play_under(Variant::MjsoulSanma)
        .expect("three players with red fives");
    let text = game_text(&three).expect("writes");
    assert_eq!(
        parse_game("s.mjson", &text).map(|g| g.variant),
        Ok(Variant::MjsoulSanma)
    );
}

#[test]
fn the_arenas_logs_convert_to_either_format_and_back_to_the_same_game() {
    // What the mjai_log fuzz target holds every log to, on the arena's own logs.
    let comparable = |mut g: Game| {
        for r in &mut g.rounds {
            r.line = 0;
            if let Outcome::Wins(wins) = &mut r.outcome {
                wins.iter_mut().for_each(|w| w.computed = false);
            }
        }
        g
    };
    for seed in [1, 5, 7] {
        let game = arena_log(seed);
        let tenhou = crate::tenhou::write::game_text(&game);
        let back = crate::tenhou::log::parse_game(&game.path, &tenhou).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(comparable(back), comparable(game.clone()), "seed {seed}: tenhou.net/6");
        let mjai = game_text(&game).expect("writes");
        let back = parse_game(&game.path, &mjai).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(comparable(back), comparable(game), "seed {seed}: MJAI");
    }
}
