use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde_json::{json, Value};

use super::moves::{parse_discard, parse_draw};
use super::*;
use rinshan_engine::hand::YakuHan;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/tenhou");
const FIRST: &str = "2010081709gm-00a9-0000-fe3371ad.json";

fn t(code: u8) -> Tile {
    Tile::from_tenhou_code(code).expect("a valid tile code in the test")
}

fn all_games() -> Vec<Game> {
    let files = collect_files(&[PathBuf::from(DATA)]).expect("the data folder lists");
    files
        .iter()
        .map(|f| read_game(f).unwrap_or_else(|e| panic!("{e}")))
        .collect()
}

/// The first record of the known file, to break in the malformed-input tests.
fn first_record() -> Value {
    let text = std::fs::read_to_string(Path::new(DATA).join(FIRST)).expect("the known file reads");
    let line = text.lines().next().expect("the known file has a first line");
    serde_json::from_str(line).expect("the first line is JSON")
}

/// Parses a good record on line 1, a blank line and the record after `edit` on line 3.
fn broken(edit: impl FnOnce(&mut Value)) -> LogError {
    let good = first_record();
    let mut bad = good.clone();
    edit(&mut bad);
    let text = format!("{good}\n\n{bad}\n");
    parse_game("test.json", &text).expect_err("the edited record must be rejected")
}

fn list(value: &mut Value) -> &mut Vec<Value> {
    match value {
        Value::Array(items) => items,
        other => panic!("not a list: {other}"),
    }
}

fn round_of(record: &mut Value) -> &mut Vec<Value> {
    list(&mut record["log"][0])
}

fn object(value: &mut Value) -> &mut serde_json::Map<String, Value> {
    match value {
        Value::Object(map) => map,
        other => panic!("not an object: {other}"),
    }
}

/// The error names the file, line 3, the first round and `field`; its message has `words`.
fn check(err: &LogError, field: &str, words: &str) {
    let text = err.to_string();
    assert_eq!(err.file, "test.json", "{text}");
    assert_eq!(err.line, Some(3), "{text}");
    assert_eq!(err.field.as_deref(), Some(field), "{text}");
    assert!(err.message.contains(words), "{text}");
    let start = format!("test.json: line 3 (East 1, 0 honba): {field}: ");
    assert!(text.starts_with(&start), "{text}");
}

#[test]
fn tenhou_codes_map_to_our_values() {
    let cases = [
        (11, 0, 0),
        (19, 8, 8),
        (21, 9, 9),
        (35, 22, 22),
        (41, 27, 27),
        (47, 33, 33),
    ];
    for (code, value, kind) in cases {
        assert_eq!(
            (t(code).value(), u8::from(t(code).kind()), t(code).is_red()),
            (value, kind, false),
            "{code}"
        );
    }
    for (code, value, kind) in [(51, 34, 4), (52, 35, 13), (53, 36, 22)] {
        assert_eq!(
            (t(code).value(), u8::from(t(code).kind()), t(code).is_red()),
            (value, kind, true),
            "{code}"
        );
    }
    for code in [0, 10, 20, 30, 40, 48, 50, 54, 58, 60] {
        assert_eq!(Tile::from_tenhou_code(code), None, "{code}");
    }
}

#[test]
fn directions_and_round_names() {
    assert_eq!([Rel::Left, Rel::Across, Rel::Right].map(|r| r.seat_of(0)), [3, 2, 1]);
    assert_eq!([Rel::Left, Rel::Across, Rel::Right].map(|r| r.seat_of(3)), [2, 1, 0]);
    // Three players sit at Tenhou's four places with the fourth empty: seat 2 is across from
    // seat 0 (the real sanma mjlog in tests/data/mjlog has seat 2 pon seat 0's discards with
    // meld code direction 2), and seat 1's across is the empty place.
    assert_eq!([Rel::Left, Rel::Across, Rel::Right].map(|r| r.seat_of(0)), [3, 2, 1]);
    assert_eq!([Rel::Left, Rel::Across, Rel::Right].map(|r| r.seat_of(2)), [1, 0, 3]);
    for me in 0..4 {
        for other in (0..4).filter(|&o| o != me) {
            assert_eq!(Rel::between(me, other).seat_of(me), other, "{me} {other}");
        }
    }
    assert_eq!(round_name(0, 0), "East 1, 0 honba");
    assert_eq!(round_name(6, 2), "South 3, 2 honba");
    assert_eq!(round_name(8, 1), "West 1, 1 honba");
}

#[test]
fn call_strings_in_every_position() {
    let draw = |s: &str| parse_draw(&json!(s)).unwrap_or_else(|e| panic!("{e}"));
    let pon = |called, own: [u8; 2], from| Draw::Pon {
        called: t(called),
        own: own.map(t),
        from,
    };
    assert_eq!(
        draw("c363453"),
        Draw::Chi {
            called: t(36),
            own: [t(34), t(53)]
        }
    );
    assert_eq!(draw("p252552"), pon(25, [25, 52], Rel::Left));
    assert_eq!(draw("35p5335"), pon(53, [35, 35], Rel::Across));
    assert_eq!(draw("2552p25"), pon(25, [25, 52], Rel::Right));
    let kan = |from| Draw::OpenKan {
        called: t(39),
        own: [t(39); 3],
        from,
    };
    assert_eq!(draw("m39393939"), kan(Rel::Left));
    assert_eq!(draw("39m393939"), kan(Rel::Across));
    assert_eq!(draw("393939m39"), kan(Rel::Right));

    let discard = |s: &str| parse_discard(&json!(s)).unwrap_or_else(|e| panic!("{e}"));
    let added = |added, pon: [u8; 3], from| Discard::AddedKan {
        added: t(added),
        pon: pon.map(t),
        from,
    };
    assert_eq!(discard("k51151515"), added(51, [15, 15, 15], Rel::Left));
    assert_eq!(discard("15k511515"), added(51, [15, 15, 15], Rel::Across));
    assert_eq!(discard("1515k1551"), added(15, [51, 15, 15], Rel::Right));
    assert_eq!(
        discard("151515a51"),
        Discard::ClosedKan {
            tiles: [t(15), t(15), t(15), t(51)]
        }
    );
    assert_eq!(discard("r24"), Discard::Riichi(Some(t(24))));
    assert_eq!(discard("r60"), Discard::Riichi(None));
    assert_eq!(parse_discard(&json!(60)), Ok(Discard::Tsumogiri));
    assert_eq!(parse_discard(&json!(0)), Ok(Discard::Nothing));
}

#[test]
fn bad_call_strings_say_why() {
    let why = |s: &str| parse_draw(&json!(s)).expect_err(s);
    assert!(
        why("p4343").contains("\"p4343\" is not a call: a pon needs 3 tiles, found 2"),
        "{}",
        why("p4343")
    );
    assert!(
        why("q434343").contains("'q' is not a call letter"),
        "{}",
        why("q434343")
    );
    assert!(
        why("434343p").contains("position 6, expected 0, 2 or 4"),
        "{}",
        why("434343p")
    );
    assert!(why("43p4344").contains("not all the same"), "{}", why("43p4344"));
    assert!(why("c131416").contains("not a run"), "{}", why("c131416"));
    assert!(why("13c1415").contains("position 2, expected 0"), "{}", why("13c1415"));
    assert!(why("393939m3939").contains("needs 4 tiles"), "{}", why("393939m3939"));
    assert!(why("3939m3939").contains("position 4"), "{}", why("3939m3939"));
    assert!(why("4p34343").contains("two-digit"), "{}", why("4p34343"));
    assert!(why("p104343").contains("10 is not a tile"), "{}", why("p104343"));
    assert!(why("pp4343").contains("second letter"), "{}", why("pp4343"));
    let discard = |s: &str| parse_discard(&json!(s)).expect_err(s);
    assert!(discard("r61").contains("not a tile or 60"), "{}", discard("r61"));
    assert!(
        discard("p434343").contains("not a discard letter"),
        "{}",
        discard("p434343")
    );
}

#[test]
fn first_round_of_the_known_file() {
    let game = read_game(&Path::new(DATA).join(FIRST)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((game.rule.as_str(), game.red_fives), ("鳳南喰赤", true));
    assert_eq!(game.names[1], "Bさん");
    let round = &game.rounds[0];
    assert_eq!(
        (round.line, round.kyoku, round.honba, round.sticks, round.dealer()),
        (1, 0, 0, 0, 0)
    );
    assert_eq!(round.to_string(), "East 1, 0 honba");
    assert_eq!(round.scores, [25000; 4]);
    assert_eq!((round.dora.clone(), round.ura.clone()), (vec![t(16)], vec![]));
    assert_eq!(round.hands[3].len(), 13);
    assert_eq!(round.hands[3][6], t(53));
    let pon = |called, from| Draw::Pon {
        called: t(called),
        own: [t(called); 2],
        from,
    };
    assert_eq!(round.draws[1][4], pon(43, Rel::Left));
    assert_eq!(round.draws[1][7], pon(42, Rel::Left));
    assert_eq!(
        round.draws[1][12],
        Draw::Chi {
            called: t(13),
            own: [t(14), t(15)]
        }
    );
    assert_eq!(round.draws[3][0], pon(44, Rel::Right));
    assert_eq!(
        round.draws[3][3],
        Draw::Chi {
            called: t(36),
            own: [t(34), t(53)]
        }
    );
    assert_eq!(round.discards[2][12], Discard::Riichi(Some(t(24))));
    assert_eq!(round.discards[0][5], Discard::Tsumogiri);
    let Outcome::Wins(wins) = &round.outcome else {
        panic!("{:?}", round.outcome)
    };
    let [win] = wins.as_slice() else { panic!("{wins:?}") };
    assert_eq!((win.winner, win.from, win.pao, win.tsumo), (1, 2, 1, false));
    assert_eq!(win.deltas, [0, 8700, -7700, 0]);
    assert_eq!((win.fu, win.han, win.limit), (Some(30), Some(4), None));
    assert_eq!(win.points, "30符4飜7700点");
    let yaku: Vec<(&str, YakuHan)> = win.yaku.iter().map(|y| (y.name, y.han)).collect();
    let expected = [("yakuhai_seat_wind", 1), ("honitsu", 2), ("dora", 1)].map(|(n, h)| (n, YakuHan::Han(h)));
    assert_eq!(yaku, expected);

    assert_eq!(
        game.rounds[1].outcome,
        Outcome::Draw {
            kind: LoggedDraw::Exhaustive,
            deltas: Some([-1500, 1500, 1500, -1500])
        }
    );
    // Seat 1 adds to its pon of 3p (23) from the left in the fifth round.
    let added = Discard::AddedKan {
        added: t(23),
        pon: [t(23); 3],
        from: Rel::Left,
    };
    assert_eq!(game.rounds[4].discards[1][11], added);
}

/// Counts over the whole folder, checked independently with a Python script over the raw JSON.
#[test]
fn every_file_parses_with_the_expected_counts() {
    let games = all_games();
    assert_eq!(games.len(), 21);
    assert!(games.iter().all(|g| g.rule == "鳳南喰赤" && g.red_fives));
    let rounds: Vec<&Round> = games.iter().flat_map(|g| &g.rounds).collect();
    assert_eq!(rounds.len(), 232);
    let mut n: BTreeMap<String, usize> = BTreeMap::new();
    let mut count = |key: String| *n.entry(key).or_default() += 1;
    for round in &rounds {
        for seat in 0..4 {
            for draw in &round.draws[seat] {
                match draw {
                    Draw::Tile(_) => {}
                    Draw::Chi { .. } => count("chi".into()),
                    Draw::Pon { from, .. } => count(format!("pon {from:?}")),
                    Draw::OpenKan { from, .. } => count(format!("open kan {from:?}")),
                }
            }
            for discard in &round.discards[seat] {
                match discard {
                    Discard::Tile(_) => {}
                    Discard::Tsumogiri => count("tsumogiri".into()),
                    Discard::Riichi(tile) => count(format!("riichi {}", tile.is_some())),
                    Discard::AddedKan { from, .. } => count(format!("added kan {from:?}")),
                    Discard::ClosedKan { .. } => count("closed kan".into()),
                    Discard::Nothing => count("nothing".into()),
                    Discard::Kita => count("kita".into()),
                }
            }
        }
        match &round.outcome {
            Outcome::Wins(wins) => {
                count(format!("win rounds with {}", wins.len()));
                for win in wins {
                    count(if win.tsumo { "tsumo" } else { "ron" }.into());
                    for yaku in &win.yaku {
                        count(yaku.name.into());
                    }
                }
            }
            Outcome::Draw { kind, deltas } => count(format!("draw {kind:?} {}", deltas.is_some())),
        }
    }
    let expected = [
        ("chi", 189),
        ("pon Left", 82),
        ("pon Across", 76),
        ("pon Right", 77),
        ("open kan Left", 1),
        ("added kan Left", 2),
        ("added kan Across", 4),
        ("added kan Right", 4),
        ("closed kan", 13),
        ("nothing", 1),
        ("tsumogiri", 4386),
        ("riichi true", 163),
        ("riichi false", 5),
        ("win rounds with 1", 186),
        ("win rounds with 2", 1),
        ("ron", 102),
        ("tsumo", 86),
        ("draw Exhaustive true", 39),
        ("draw Kyuushu false", 2),
        ("draw NoTenpai false", 1),
        ("draw FourRiichi false", 1),
        ("draw Nagashi true", 1),
        ("draw FourWinds false", 1),
        ("riichi", 74),
        ("menzen_tsumo", 52),
        ("dora", 71),
        ("aka", 91),
        ("ura", 22),
        ("yakuhai_seat_wind", 15),
        ("yakuhai_round_wind", 23),
        ("daisangen", 1),
    ];
    for (key, value) in expected {
        assert_eq!(n.get(key).copied().unwrap_or(0), value, "{key}");
    }
}

#[test]
fn a_line_that_is_not_json_gives_line_and_column() {
    let err = parse_game("test.json", &format!("{}\n\n{{\"log\": [1,}}\n", first_record())).unwrap_err();
    assert_eq!((err.line, err.column), (Some(3), Some(12)), "{err}");
    assert!(err.message.starts_with("not JSON: "), "{err}");
    assert!(
        err.to_string().starts_with("test.json: line 3, column 12: not JSON: "),
        "{err}"
    );
}

#[test]
fn an_empty_file_has_no_rounds() {
    for text in ["", "\n \n", "\u{feff}"] {
        let err = parse_game("empty.json", text).unwrap_err();
        assert_eq!((err.file.as_str(), err.line), ("empty.json", None));
        assert!(err.to_string().starts_with("empty.json: no rounds"), "{err}");
    }
}

#[test]
fn malformed_rounds_name_file_line_and_field() {
    check(
        &broken(|r| {
            round_of(r).pop();
        }),
        "round",
        "has 16 elements, expected 17",
    );
    check(
        &broken(|r| {
            list(&mut round_of(r)[7]).pop();
        }),
        "hand of seat 1",
        "has 12 tiles",
    );
    // Tables no round can be dealt from (the replay's payments would overflow; fuzz finds).
    check(
        &broken(|r| round_of(r)[0] = json!([0, 0, 8888888])),
        "[kyoku, honba, sticks] and scores",
        "0 honba and 8888888 riichi sticks: at most 10000 of each",
    );
    check(
        &broken(|r| round_of(r)[1] = json!([2000000000, 250, 250, 250])),
        "[kyoku, honba, sticks] and scores",
        "a score of 2000000000: at most 100000000 either way",
    );
    check(
        &broken(|r| round_of(r)[4][0] = json!(10)),
        "hand of seat 0",
        "10 is not a tile",
    );
    check(
        &broken(|r| round_of(r)[11][0] = json!(58)),
        "draws of seat 2, entry 0",
        "58 is not a tile",
    );
    check(
        &broken(|r| round_of(r)[15][1] = json!("x")),
        "discards of seat 3, entry 1",
        "\"x\" is not a discard",
    );
    check(
        &broken(|r| round_of(r)[8][4] = json!("q434343")),
        "draws of seat 1, entry 4",
        "not a call letter",
    );
    check(
        &broken(|r| round_of(r)[8][4] = json!("p4343")),
        "draws of seat 1, entry 4",
        "a pon needs 3 tiles",
    );
    check(
        &broken(|r| round_of(r)[1] = json!([25000, 25000, 25000])),
        "scores",
        "has 3 entries",
    );
    check(&broken(|r| round_of(r)[2] = json!([])), "dora", "has 0 tiles");
    check(
        &broken(|r| list(&mut round_of(r)[9]).push(json!(60))),
        "discards of seat 1",
        "18 discards",
    );
    check(
        &broken(|r| round_of(r)[16][0] = json!("謎")),
        "result",
        "\"謎\" is not a known result",
    );
    check(
        &broken(|r| round_of(r)[16][2][4] = json!("謎役(1飜)")),
        "result",
        "unknown yaku name \"謎役\"",
    );
    check(
        &broken(|r| round_of(r)[16][2][4] = json!("混一色(4000000000飜)")),
        "result",
        "yaku honitsu is worth 4000000000 han, more than a hand holds",
    );
    check(
        &broken(|r| {
            let first = round_of(r)[16][2][4].clone();
            round_of(r)[16][2][5] = first;
        }),
        "result",
        "is listed twice",
    );
    check(
        &broken(|r| round_of(r)[16][1] = json!([0, 8700, -7700])),
        "result",
        "win 0: deltas",
    );
    check(
        &broken(|r| round_of(r)[16][2][0] = json!(5)),
        "result",
        "winner 5 is not a seat",
    );
    check(
        &broken(|r| round_of(r)[16][2][3] = json!("30符4飜7700")),
        "result",
        "does not end in 点",
    );
    check(
        &broken(|r| round_of(r)[16][2][3] = json!("30符5飜7700点")),
        "result",
        "add up to 4 han",
    );
    check(
        &broken(|r| round_of(r)[16][2][5] = json!("混一色(2)")),
        "result",
        "neither N飜 nor 役満",
    );
    check(
        &broken(|r| round_of(r)[16] = json!(["流局", [1, 2]])),
        "result",
        "deltas 0",
    );
}

#[test]
fn malformed_records_name_file_line_and_field() {
    let at = |err: &LogError, field: &str| {
        assert_eq!(
            (err.line, err.round.as_deref(), err.field.as_deref()),
            (Some(3), None, Some(field)),
            "{err}"
        );
        assert!(
            err.to_string().starts_with(&format!("test.json: line 3: {field}: ")),
            "{err}"
        );
    };
    at(&broken(|r| r["log"] = json!([])), "log");
    at(
        &broken(|r| {
            object(r).remove("log");
        }),
        "log",
    );
    at(&broken(|r| r["rule"] = json!({"disp": "鳳南喰", "aka": 0})), "rule");
    at(
        &broken(|r| {
            object(r).remove("rule");
        }),
        "rule",
    );
    at(
        &broken(|r| round_of(r)[0] = json!([16, 0, 0])),
        "[kyoku, honba, sticks]",
    );
    at(&broken(|r| r["log"][0] = json!("round")), "round");
    at(&broken(|r| *r = json!([1, 2])), "record");
}

#[test]
fn red_fives_need_a_red_rule() {
    let mut record = first_record();
    record["rule"] = json!({"disp": "鳳南喰", "aka": 0});
    let err = parse_game("test.json", &record.to_string()).unwrap_err();
    assert_eq!(
        (err.line, err.field.as_deref()),
        (Some(1), Some("hand of seat 3")),
        "{err}"
    );
}

/// A record of another rule set names it (`"variant"`); a name rinshan does not know, a rule
/// set without red fives whose `aka` says red, or a second record of another rule set are errors
/// of the rule.
#[test]
fn the_rule_names_the_rule_set() {
    let mut record = first_record();
    assert_eq!(
        parse_game("t.json", &record.to_string()).map(|g| g.variant),
        Ok(Variant::Red)
    );
    record["rule"]["variant"] = json!("mleague");
    let game = parse_game("t.json", &record.to_string()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(game.variant, Variant::Mleague);
    let rule_error = |record: &Value, says: &str| {
        let err = parse_game("t.json", &record.to_string()).unwrap_err();
        assert_eq!(err.field.as_deref(), Some("rule"), "{err}");
        assert!(err.message.contains(says), "{err}");
    };
    record["rule"]["variant"] = json!("blue");
    rule_error(&record, "blue");
    record["rule"]["variant"] = json!(3);
    rule_error(&record, "not a name");
    record["rule"]["variant"] = json!("wrc");
    rule_error(&record, "wrc plays without them");
    let mut mleague = first_record();
    mleague["rule"]["variant"] = json!("mleague");
    let two = format!("{}\n{mleague}\n", first_record());
    let err = parse_game("two.json", &two).unwrap_err();
    assert!(
        err.message.contains("variant mleague") && err.message.contains("one file is one game"),
        "{err}"
    );
}

#[test]
fn other_layouts_of_the_same_record() {
    let record = first_record();
    // A pretty-printed record, CRLF line ends.
    let pretty = serde_json::to_string_pretty(&record)
        .expect("serializes")
        .replace('\n', "\r\n");
    let game = parse_game("pretty.json", &pretty).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((game.rounds.len(), game.rounds[0].line), (1, 1));
    // Several rounds in one `log` share the record's line; errors name the round's index.
    let mut two = record.clone();
    two["log"] = json!([record["log"][0], record["log"][0]]);
    let game = parse_game("two.json", &format!("\n{two}\r\n")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(game.rounds.iter().map(|r| r.line).collect::<Vec<_>>(), [2, 2]);
    two["log"][1][1] = json!([1]);
    let err = parse_game("two.json", &two.to_string()).unwrap_err();
    assert_eq!(err.round.as_deref(), Some("log[1], East 1, 0 honba"), "{err}");
}

#[test]
fn files_and_folders() {
    let files = collect_files(&[PathBuf::from(DATA)]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(files.len(), 21);
    assert!(files.windows(2).all(|w| w[0] < w[1]));
    assert!(files[0].ends_with(FIRST));
    let missing = PathBuf::from(DATA).join("missing.json");
    let err = collect_files(std::slice::from_ref(&missing)).unwrap_err();
    assert_eq!(err.file, missing.display().to_string());
    let err = read_game(&missing).unwrap_err();
    assert!(
        err.to_string().starts_with(&format!("{}: ", missing.display())),
        "{err}"
    );
}

/// Every truncation of a record and many one-character edits give a game or an error naming the
/// file, never a panic.
#[test]
fn mutated_input_never_panics() {
    let record: Vec<char> = first_record().to_string().chars().collect();
    let mut texts: Vec<String> = (0..record.len()).map(|n| record[..n].iter().collect()).collect();
    for at in (0..record.len()).step_by(3) {
        for replacement in ["", "\"", "1", "]", "[", "p", ",", "0", "-", "a", "k"] {
            let (head, tail): (String, String) = (record[..at].iter().collect(), record[at + 1..].iter().collect());
            texts.push(format!("{head}{replacement}{tail}"));
        }
    }
    for text in texts {
        if let Err(err) = parse_game("fuzz.json", &text) {
            assert!(err.to_string().starts_with("fuzz.json"), "{err}");
        }
    }
}

/// A three-player record: Tenhou's `三` rule, seat 3 empty with score 0, kita as `f44`.
fn sanma_record() -> Value {
    json!({"title": ["", ""], "name": ["A", "B", "C", ""], "rule": {"disp": "三鳳南喰赤", "aka": 1}, "log": [[
        [0, 0, 0], [35000, 35000, 35000, 0], [21], [],
        [11, 11, 19, 19, 21, 22, 23, 24, 25, 26, 27, 28, 29], [44, 22], ["f44", 60],
        [31, 32, 33, 34, 35, 36, 37, 38, 39, 41, 41, 42, 42], [], [],
        [43, 43, 45, 45, 46, 46, 47, 47, 11, 19, 21, 21, 31], [], [],
        [], [], [],
        ["全員不聴"]
    ]]})
}

#[test]
fn three_player_records() {
    let game = parse_game("s.json", &sanma_record().to_string()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(game.variant, Variant::Sanma);
    let r = &game.rounds[0];
    assert_eq!((r.seats, r.table_round(), r.hands[3].len()), (3, 0, 0));
    assert_eq!(r.discards[0], vec![Discard::Kita, Discard::Tsumogiri]);
    // Tenhou numbers South 1 as 4 for three players too; the engine counts three rounds a wind.
    assert_eq!(table_round(4, 3), 3);
    assert_eq!(tenhou_kyoku(3, 3), 4);
    let refused = |edit: &dyn Fn(&mut Value), words: &str| {
        let mut record = sanma_record();
        edit(&mut record);
        let err = parse_game("s.json", &record.to_string()).expect_err(words);
        assert!(err.to_string().contains(words), "{err}");
    };
    refused(
        &|r| r["log"][0][13] = json!([11, 11, 19, 19, 21, 22, 23, 24, 25, 26, 27, 28, 29]),
        "leave seat 3's hand",
    );
    refused(
        &|r| r["log"][0][1] = json!([35000, 35000, 34000, 1000]),
        "leave the fourth score 0",
    );
    refused(&|r| r["log"][0][0] = json!([3, 0, 0]), "kyoku 0-2, 4-6");
    refused(
        &|r| r["log"][0][16] = json!(["流局", [1000, -1000, -1000, 1000]]),
        "a win or a payment of the fourth place, which three players leave empty",
    );
    // Names are for display: a fourth name at three players is left out (every format writes the
    // fourth place empty), where a fourth score or hand is refused.
    let mut named = sanma_record();
    named["name"] = json!(["A", "B", "C", "D"]);
    let game = parse_game("n.json", &named.to_string()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(game.names, ["A", "B", "C", ""].map(String::from));
    // A four-player game has no one to set North aside for it, and no three-player log plays
    // under a four-player rule set.
    refused(&|r| r["log"][0][6] = json!(["f45", 60]), "not a discard letter");
    // Seat 0's place before is the empty fourth one (seat 2 sits across from it).
    refused(
        &|r| r["log"][0][5] = json!(["p191919", 22]),
        "a call from the fourth place, which three players leave empty",
    );
    refused(
        &|r| r["log"][0][5] = json!(["c212223", 22]),
        "a chi: three players have none",
    );
    let mut four = first_record();
    round_of(&mut four)[6] = json!(["f44"]);
    round_of(&mut four)[5] = json!([44]);
    let err = parse_game("f.json", &four.to_string()).expect_err("kita at four seats");
    assert!(err.to_string().contains("four players keep North"), "{err}");
    let mut game = game;
    let err = game.play_under(Variant::Red).expect_err("three players under red");
    assert!(
        err.contains("a 3-player log cannot be played under red, a 4-player game"),
        "{err}"
    );
}
