//! MJAI logs against the real Tenhou logs in tests/data/tenhou: each converts to MJAI and back
//! to the file's own bytes, replays through the engine as its tenhou.net/6 form does, and its
//! events come in the order the engines emit them. Then the reader's refusals.

use rinshan_engine::env::Backend;

use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;

use super::event::Event;
use super::live::{view, Live};
use super::read::{is_mjai, parse_game};
use super::write::{game_events, game_text};
use super::yaku::{DRAGONS, MJAI_YAKU};
use crate::tenhou::log::{Game, LoggedDraw, Outcome};
use crate::tenhou::replay::replay;
use crate::tenhou::write::game_text as tenhou_text;
use crate::tenhou::write::tests::real_logs;

fn records(text: &str) -> Vec<&str> {
    text.lines().filter(|l| !l.trim().is_empty()).collect()
}

#[test]
fn real_logs_convert_to_mjai_and_back_to_their_own_bytes() {
    let mut rounds = 0;
    for (text, game) in real_logs() {
        let mjai = game_text(&game).unwrap_or_else(|e| panic!("{e}"));
        assert!(is_mjai(&mjai), "{}", game.path);
        let back = parse_game(&game.path, &mjai).unwrap_or_else(|e| panic!("{}: {e}\n{mjai}", game.path));
        let written = tenhou_text(&back);
        assert_eq!(records(&written), records(&text), "{}", game.path);
        // And the MJAI text is a fixed point: read and written again, it is the same.
        assert_eq!(game_text(&back).expect("writes"), mjai, "{}", game.path);
        rounds += game.rounds.len();
    }
    assert!(rounds > 150, "only {rounds} real rounds");
}

#[test]
fn real_logs_read_from_mjai_replay_exactly() {
    let games: Vec<Game> = real_logs()
        .into_iter()
        .map(|(_, g)| parse_game(&g.path, &game_text(&g).expect("writes")).expect("reads back"))
        .collect();
    let report = replay(&games, Backend::Cpu).expect("the CPU env runs");
    assert!(report.all_agree(), "{report:?}");
    assert_eq!(report.games, games.len());
}

#[test]
fn the_original_mjai_yaku_names_read_as_ours() {
    // The real logs with every yaku renamed as the original mjai server (and the Tenhou-to-MJAI
    // converters) name them: the dragon yakuhai summed into one `sangenpai`.
    let ours_to_mjai = |name: &str| MJAI_YAKU.iter().find(|(_, ours)| *ours == name).map(|(m, _)| *m);
    let mut sangenpai = 0;
    for (text, game) in real_logs() {
        let mut lines = Vec::new();
        for line in game_text(&game).expect("writes").lines() {
            let mut event: serde_json::Value = serde_json::from_str(line).expect("JSON");
            if let Some(yakus) = event.get_mut("yakus").and_then(|y| y.as_array_mut()) {
                let mut renamed: Vec<serde_json::Value> = Vec::new();
                let mut dragons = 0;
                for y in yakus.iter() {
                    let name = y[0].as_str().expect("a name");
                    if DRAGONS.iter().any(|(d, _)| *d == name) {
                        if dragons == 0 {
                            renamed.push(serde_json::json!(["sangenpai", 0]));
                        }
                        dragons += 1;
                        continue;
                    }
                    renamed.push(serde_json::json!([ours_to_mjai(name).unwrap_or(name), y[1]]));
                }
                for y in renamed.iter_mut().filter(|y| y[0] == "sangenpai") {
                    y[1] = dragons.into();
                    sangenpai += 1;
                }
                *yakus = renamed;
            }
            lines.push(event.to_string());
        }
        let back = parse_game(&game.path, &lines.join("\n")).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(records(&tenhou_text(&back)), records(&text), "{}", game.path);
    }
    assert!(sangenpai > 0, "the real logs hold dragon yakuhai");
}

/// The events after position `i`, by kind.
fn kinds(events: &[Event], from: usize, n: usize) -> Vec<&'static str> {
    events.iter().skip(from).take(n).map(Event::kind).collect()
}

#[test]
fn events_come_in_the_engines_order() {
    let mut seen = [0usize; 4];
    for (_, game) in real_logs() {
        let events = game_events(&game).expect("writes");
        assert_eq!(events.first().map(Event::kind), Some("start_game"));
        assert_eq!(events.last().map(Event::kind), Some("end_game"));
        for (i, e) in events.iter().enumerate() {
            match e {
                // A closed kan shows its dora at once, before the replacement draw.
                Event::Ankan { actor, .. } => {
                    seen[0] += 1;
                    assert_eq!(kinds(&events, i + 1, 2), ["dora", "tsumo"], "{}", game.path);
                    assert!(matches!(events[i + 2], Event::Tsumo { actor: a, .. } if a == *actor));
                }
                // An open kan's dora comes with the kanner's discard (or a further kan).
                Event::Daiminkan { actor, .. } | Event::Kakan { actor, .. } => {
                    seen[1] += 1;
                    let next = kinds(&events, i + 1, 3);
                    let ok = matches!(next.as_slice(), ["tsumo", "dora", "dahai"] | ["tsumo", "hora", ..])
                        || (next[0] == "tsumo" && matches!(next[1], "ankan" | "kakan" | "dora"));
                    assert!(ok || next[0] == "hora", "{}: {next:?}", game.path);
                    if next[0] == "tsumo" {
                        assert!(matches!(events[i + 1], Event::Tsumo { actor: a, .. } if a == *actor));
                    }
                }
                // reach, the same seat's discard, then the deposit unless the discard is ronned.
                Event::Reach { actor } => {
                    seen[2] += 1;
                    assert!(matches!(events[i + 1], Event::Dahai { actor: a, .. } if a == *actor));
                    let after = &events[i + 2];
                    match after {
                        Event::ReachAccepted { actor: a, deltas, .. } => {
                            assert_eq!(a, actor);
                            assert_eq!(deltas.map(|d| d[usize::from(*a)]), Some(-1000));
                        }
                        Event::Hora { target, .. } => assert_eq!(target, actor, "{}", game.path),
                        other => panic!("{}: {other:?} after a riichi discard", game.path),
                    }
                }
                // A double ron: two hora on one discard, then the round ends.
                Event::Hora { target, actor, .. } if matches!(events[i + 1], Event::Hora { .. }) => {
                    seen[3] += 1;
                    assert_ne!(target, actor, "a double win is on a discard");
                    assert!(matches!(events[i + 1], Event::Hora { target: t, .. } if t == *target));
                }
                _ => {}
            }
        }
    }
    // The real logs hold every case checked above.
    assert!(
        seen.iter().all(|&n| n > 0),
        "closed kans, open kans, riichi, double rons: {seen:?}"
    );
}

/// Reads `lines` (after a start_game and a start_kyoku of a plain deal) and returns the error.
fn refusal(lines: &[&str]) -> String {
    let hand = r#"["1m","2m","3m","4m","5m","6m","7m","8m","9m","1p","2p","3p","4p"]"#;
    let start = format!(
        r#"{{"type":"start_kyoku","bakaze":"E","dora_marker":"1s","kyoku":1,"honba":0,"kyotaku":0,"oya":0,"scores":[25000,25000,25000,25000],"tehais":[{hand},{hand},{hand},{hand}]}}"#
    );
    let mut text = format!("{{\"type\":\"start_game\"}}\n{start}\n");
    for l in lines {
        text.push_str(l);
        text.push('\n');
    }
    match parse_game("t.mjson", &text) {
        Ok(g) => panic!("read {lines:?} as {g:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_events_are_refused_with_their_line() {
    let cases: [(&[&str], &str); 17] = [
        (
            &[
                r#"{"type":"ryukyoku","reason":"fanpai","tenpais":[true,false,false,false],"deltas":[0,0,0,0]}"#,
                r#"{"type":"end_kyoku"}"#,
            ],
            "1 seats tenpai, but the deltas pay them nothing",
        ),
        (
            &[
                r#"{"type":"ryukyoku","tenpais":[false,true,true,true],"deltas":[3000,-1000,-1000,-1000]}"#,
                r#"{"type":"end_kyoku"}"#,
            ],
            "contradict the deltas",
        ),
        (
            &[r#"{"type":"dora","dora_marker":"1m"}"#],
            "dora 1m: no kan is left to reveal it",
        ),
        (&["{\"type\":\"tsumo\",\"actor\":0"], "line 3, column"),
        (
            &[r#"{"type":"tsumo_x","actor":0,"pai":"1m"}"#],
            "unknown variant `tsumo_x`",
        ),
        (
            &[r#"{"type":"tsumo","actor":4,"pai":"1m"}"#],
            "line 3 (East 1, 0 honba): seat 4 is not 0-3",
        ),
        (&[r#"{"type":"tsumo","actor":0,"pai":"0m"}"#], "an MJAI tile"),
        (&[r#"{"type":"tsumo","actor":0,"pai":"?"}"#], "one seat's view"),
        (
            &[
                r#"{"type":"tsumo","actor":0,"pai":"1m"}"#,
                r#"{"type":"dahai","actor":0,"pai":"2m","tsumogiri":true}"#,
            ],
            "line 4",
        ),
        (
            &[
                r#"{"type":"dahai","actor":0,"pai":"2m","tsumogiri":false}"#,
                r#"{"type":"chi","actor":2,"target":0,"pai":"2m","consumed":["3m","4m"]}"#,
            ],
            "not the seat before it",
        ),
        (
            &[
                r#"{"type":"dahai","actor":0,"pai":"2m","tsumogiri":false}"#,
                r#"{"type":"pon","actor":2,"target":0,"pai":"3m","consumed":["3m","3m"]}"#,
            ],
            "not the discard just made",
        ),
        (
            &[r#"{"type":"kakan","actor":1,"pai":"3m","consumed":["3m","3m","3m"]}"#],
            "a pon it does not have",
        ),
        (
            &[r#"{"type":"hora","actor":1,"target":0}"#, r#"{"type":"end_kyoku"}"#],
            "hora without deltas",
        ),
        (
            &[r#"{"type":"ryukyoku","reason":"tired"}"#, r#"{"type":"end_kyoku"}"#],
            "unknown ryukyoku reason",
        ),
        (&[r#"{"type":"end_kyoku"}"#], "neither hora nor ryukyoku"),
        (
            &[r#"{"type":"ryukyoku"}"#, r#"{"type":"tsumo","actor":0,"pai":"1m"}"#],
            "after ryukyoku",
        ),
        (&[], "stops inside a round"),
    ];
    for (lines, expected) in cases {
        let message = refusal(lines);
        assert!(message.contains(expected), "{lines:?}: {message}");
        assert!(message.starts_with("t.mjson"), "{message}");
    }
    let no_game = parse_game("t.mjson", "{\"type\":\"end_game\"}\n").expect_err("no start");
    assert!(no_game.to_string().contains("no start_game"), "{no_game}");
    let twice = parse_game(
        "t.mjson",
        "{\"type\":\"start_game\"}\n{\"type\":\"end_game\"}\n{\"type\":\"start_game\"}\n",
    );
    assert!(twice.expect_err("two games").to_string().contains("after end_game"));
}

#[test]
fn a_dora_list_longer_than_the_kans_allow_is_refused_in_either_format() {
    // East 1 of the first real log has no kan: a second indicator would name a tile no kan showed.
    let (text, _) = real_logs().into_iter().next().expect("a real log");
    let mut record: serde_json::Value = serde_json::from_str(records(&text)[0]).expect("JSON");
    let first = record["log"][0][2][0].clone();
    record["log"][0][2] = serde_json::json!([first, 11]);
    let err = crate::tenhou::log::parse_game("t.json", &record.to_string()).expect_err("refused");
    assert!(
        err.to_string().contains("dora: 2 indicators, but the round has 0 kans"),
        "{err}"
    );
}

#[test]
fn unknown_fields_and_none_events_are_ignored() {
    let hand = r#"["1m","9m","1p","9p","1s","9s","E","S","W","N","P","F","C"]"#;
    let text = format!(
        "{{\"type\":\"start_game\",\"names\":[\"a\",\"b\",\"c\",\"d\"],\"seed\":[1,2],\"kyoku_first\":4,\"aka_flag\":false}}\n\
         {{\"type\":\"start_kyoku\",\"bakaze\":\"E\",\"dora_marker\":\"1s\",\"kyoku\":1,\"honba\":0,\"kyotaku\":0,\"oya\":0,\"scores\":[25000,25000,25000,25000],\"tehais\":[{hand},{hand},{hand},{hand}],\"extra\":1}}\n\
         {{\"type\":\"tsumo\",\"actor\":0,\"pai\":\"2m\",\"meta\":{{\"shanten\":3}}}}\n\
         {{\"type\":\"none\",\"meta\":{{\"q_values\":[1.0]}}}}\n\
         {{\"type\":\"ryukyoku\",\"reason\":\"kyushukyuhai\",\"deltas\":[0,0,0,0]}}\n\
         {{\"type\":\"end_kyoku\"}}\n{{\"type\":\"end_game\",\"scores\":[1,2,3,4]}}\n"
    );
    let game = parse_game("t.mjson", &text).expect("reads");
    assert_eq!(game.names, ["a", "b", "c", "d"].map(String::from));
    assert_eq!(game.rule, "東喰", "an East-only game without red fives");
    assert!(!game.red_fives);
    assert_eq!(game.rounds.len(), 1);
    let draw = Outcome::Draw {
        kind: LoggedDraw::Kyuushu,
        deltas: None,
    };
    assert_eq!(game.rounds[0].outcome, draw, "an abortive draw pays nothing");
    let empty = parse_game("t.mjson", "{\"type\":\"start_game\"}\n{\"type\":\"end_game\"}\n");
    assert!(empty.expect_err("no round").to_string().contains("no round"));
}

/// Plays `games` half games of `variant` with the built-in agents (a mix, so games have calls,
/// kans, riichi and every ending), following each live; returns the live streams.
fn live_games(variant: Variant, games: u64, check_each_step: impl Fn(&Live, &GameState)) -> Vec<Live> {
    use rinshan_engine::agents::Agent;
    use rinshan_engine::env::Mode;
    let agents = [Agent::Rule, Agent::Greedy, Agent::Defensive, Agent::Random];
    (0..games)
        .map(|g| {
            rinshan_engine::with_variant!(variant, v => {
                let mut s: GameState = variant.new_game((5 << 32) | (g + 11), Mode::Half);
                let names = ["a", "b", "c", "d"].map(String::from);
                let mut live = Live::new(&s, names, variant).expect("a fresh game is followed");
                while s.terminated == 0 {
                    check_each_step(&live, &s);
                    let agent = agents[(s.current as usize + g as usize) % 4];
                    let a = agent.act(variant, &s);
                    let before = s;
                    v::game_step(&mut s, a);
                    live.step(&before, a, &s).unwrap_or_else(|e| panic!("game {g}: {e}"));
                }
                assert!(live.is_over());
                live
            })
        })
        .collect()
}

#[test]
fn a_game_followed_live_sends_exactly_its_mjai_log() {
    for variant in [Variant::Red, Variant::Sanma] {
        let mut kinds = std::collections::BTreeSet::new();
        for live in live_games(variant, 40, |_, _| {}) {
            let game = live.game().expect("the game ended by the rules");
            assert_eq!(live.events(), game_events(game).expect("the game writes").as_slice());
            kinds.extend(
                live.events()
                    .iter()
                    .map(|e| serde_json::to_value(e).unwrap()["type"].to_string()),
            );
        }
        // The games cover what the live order has to get right.
        let three = variant.seats() == 3;
        let calls = if three { "kita" } else { "chi" };
        for kind in [
            calls,
            "pon",
            "daiminkan",
            "kakan",
            "ankan",
            "dora",
            "reach",
            "reach_accepted",
            "hora",
            "ryukyoku",
        ] {
            assert!(
                kinds.contains(&format!("\"{kind}\"")),
                "{variant}: no {kind} in the games: {kinds:?}"
            );
        }
        assert_eq!(kinds.contains("\"chi\""), !three);
    }
}

#[test]
fn at_each_decision_the_stream_ends_where_the_engines_ask() {
    use rinshan_engine::generated::kernel::{PHASE_CLAIM, PHASE_RIICHI_DISCARD};
    for variant in [Variant::Red, Variant::Sanma] {
        live_games(variant, 10, |live, s| {
            let p = u64::from(live.mjai_seat(s.current));
            let last = serde_json::to_value(live.events().last().expect("a stream has events")).unwrap();
            let kind = last["type"].as_str().unwrap();
            let actor = last["actor"].as_u64();
            if s.phase == PHASE_CLAIM {
                // A claim is asked on a discard, or on an added kan's tile (chankan), or on a North
                // set aside (three players).
                assert!(matches!(kind, "dahai" | "kakan" | "kita"), "claim asked after {last}");
                assert_ne!(actor, Some(p));
            } else if s.phase == PHASE_RIICHI_DISCARD {
                assert_eq!((kind, actor), ("reach", Some(p)));
            } else {
                // The seat's own turn: after its draw (a replacement after a closed kan comes after
                // the kan's dora), or after its call.
                assert!(matches!(kind, "tsumo" | "chi" | "pon"), "turn asked after {last}");
                assert_eq!(actor, Some(p), "{last}");
            }
        });
    }
}

#[test]
fn a_seat_sees_only_its_own_hand_and_draws() {
    let live = live_games(Variant::Red, 1, |_, _| {}).remove(0);
    for seat in 0..4u8 {
        for e in live.events() {
            match view(e, seat) {
                Event::StartKyoku { tehais, .. } => {
                    for (s, hand) in tehais.iter().enumerate() {
                        assert_eq!(hand.len(), 13);
                        assert_eq!(hand.iter().all(|t| t.0.is_some()), s == usize::from(seat));
                    }
                }
                Event::Tsumo { actor, pai } => assert_eq!(pai.0.is_some(), actor == seat),
                Event::StartGame { id, .. } => assert_eq!(id, Some(seat)),
                other => assert_eq!(&other, e),
            }
        }
    }
}

/// Seat `seat`'s player, told the game so far in its own view.
fn told(live: &Live, seat: u8) -> super::player::Player {
    let mut player = super::player::Player::new(None);
    for e in live.events() {
        player
            .update(view(e, seat))
            .unwrap_or_else(|err| panic!("seat {seat}: {err} at {e:?}"));
    }
    player
}

#[test]
fn a_seat_rebuilt_from_its_view_sees_and_may_do_what_the_engine_shows_it() {
    use rinshan_engine::generated::kernel::{OBSERVE_CURRENT, PHASE_CLAIM};
    use rinshan_engine::generated::red as v;
    let decisions = std::cell::Cell::new(0);
    live_games(Variant::Red, 40, |live, s| {
        let p = live.mjai_seat(s.current);
        let player = told(live, p);
        let r = player
            .decision()
            .unwrap_or_else(|e| {
                let evs = live.events();
                let start = evs
                    .iter()
                    .rposition(|e| matches!(e, Event::StartKyoku { .. }))
                    .unwrap_or(0);
                let round: Vec<String> = evs[start..]
                    .iter()
                    .map(|e| serde_json::to_string(&view(e, p)).unwrap())
                    .collect();
                panic!("seat {p}: {e}\n{}", round.join("\n"))
            })
            .unwrap_or_else(|| panic!("seat {p} is asked, but its rebuilt state has no decision"));
        assert_eq!(r.mask, s.mask, "seat {p}: legal actions");
        let (seen, truth) = (
            v::observe_planes(r, OBSERVE_CURRENT),
            v::observe_planes(*s, OBSERVE_CURRENT),
        );
        assert!(
            bytemuck::bytes_of(&seen) == bytemuck::bytes_of(&truth),
            "seat {p}: planes differ"
        );
        let (seen, truth) = (
            v::observe_tokens(r, OBSERVE_CURRENT),
            v::observe_tokens(*s, OBSERVE_CURRENT),
        );
        assert!(
            bytemuck::bytes_of(&seen) == bytemuck::bytes_of(&truth),
            "seat {p}: tokens differ"
        );
        // On a turn nobody else has anything to decide.
        if s.phase != PHASE_CLAIM {
            for q in (0..4).filter(|&q| q != p) {
                let other = told(live, q).decision().unwrap();
                assert!(
                    other.is_none(),
                    "seat {q} on seat {p}'s turn: phase {} current {} mask {:?}; truth phase {} mask {:?}; last {:?}",
                    other.map_or(9, |o| o.phase),
                    other.map_or(9, |o| o.current),
                    other.map(|o| o.mask),
                    s.phase,
                    s.mask,
                    &live.events()[live.events().len().saturating_sub(4)..]
                );
            }
        }
        decisions.set(decisions.get() + 1);
    });
    assert!(decisions.get() > 1000);
}

#[test]
fn the_player_says_it_does_not_sit_at_three_player_tables() {
    let mut player = super::player::Player::new(Some(0));
    let mut said = Vec::new();
    let line = r#"[{"type":"start_game","names":["A","B","C"],"id":0}]"#;
    let reply = player.respond(line, super::bot::Dialect::App, &mut |_| Ok(0), &mut |m| said.push(m));
    assert_eq!(reply.as_deref(), Some(r#"{"type":"none"}"#));
    assert!(said[0].contains("an event of a three-player game"), "{said:?}");
}
