//! MJAI bots at the web page's table (`rinshan serve --mjai-bot NAME=COMMAND`): a visitor names a
//! bot the server offers, never a command; a game with bot seats plays to its end with every move
//! of those seats the bot's (the test bot's own policy shows in the log); a bot that fails loses
//! its game by the penalty, said on the page; and a bot that thinks does not hold the page.
//!
//! The bot is tests/data/mjai/bots/simple_bot.py (Python's standard library only): it discards
//! what it draws and pons every pair it can.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use axum::http::StatusCode;
use rinshan_logs::mjai::bot::{BotSpec, Dialect};
use rinshan_logs::tenhou::log::{Discard, Draw};
use rinshan_serve::{app, Limits, NamedBot};
use serde_json::{json, Value};

use super::serve_http::{get, new_game, parsed, play_to_the_end, post, replayed_log, settled};

fn simple_bot(name: &str, dialect: Dialect, mode: &str, timeout: Duration) -> NamedBot {
    let script: PathBuf = [env!("CARGO_MANIFEST_DIR"), "data", "mjai", "bots", "simple_bot.py"]
        .iter()
        .collect();
    let d = match dialect {
        Dialect::App => "app",
        Dialect::Stdio => "stdio",
    };
    NamedBot {
        name: name.to_string(),
        spec: BotSpec {
            command: format!("python3 {} --dialect {d} --mode {mode}", script.display()),
            dialect,
            timeout,
            startup: Duration::from_secs(20),
        },
    }
}

fn limits(bots: Vec<NamedBot>) -> Limits {
    Limits {
        fixed_seed: Some(11),
        idle: Duration::from_secs(600),
        bots,
        ..Limits::default()
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bots_play_a_whole_game_with_a_person() {
    let second = Duration::from_secs(5);
    let app = app(limits(vec![
        simple_bot("plain", Dialect::App, "play", second),
        simple_bot("stdio", Dialect::Stdio, "play", second),
    ]));
    let (_, text) = get(&app, "/api/agents").await;
    let agents = parsed(&text)["agents"].clone();
    for name in ["rule", "mjai:plain", "mjai:stdio"] {
        assert!(agents.as_array().is_some_and(|a| a.contains(&json!(name))), "{agents}");
    }
    let v = new_game(
        &app,
        json!({"mode": "east", "seat": 0, "agents": ["mjai:plain", "rule", "mjai:stdio"], "delay_ms": 0}),
    )
    .await;
    assert_eq!(v["names"], json!(["You", "plain 1", "rule 2", "stdio 3"]), "{v}");
    let id = v["id"].as_str().expect("an id").to_string();
    let deadline = Instant::now() + Duration::from_secs(300);
    let last = loop {
        assert!(Instant::now() < deadline, "the game did not end");
        let v = settled(&app, &id).await;
        let uri = match v["phase"].as_str() {
            Some("human") => {
                let first = &v["legal"][0];
                let body = json!({"action": first["id"], "step": v["step"]});
                let (status, text) = post(&app, &format!("/api/games/{id}/actions"), &body).await;
                assert_eq!(status, StatusCode::OK, "{text}");
                continue;
            }
            Some("result") => format!("/api/games/{id}/next"),
            Some("over") => break v,
            other => panic!("phase {other:?}: {v}"),
        };
        let (status, text) = post(&app, &uri, &json!(null)).await;
        assert_eq!(status, StatusCode::OK, "{text}");
    };
    assert!(!last["events"].to_string().contains("failed"), "{}", last["events"]);
    // The log replays through the engine, and the bots' seats played the bot's policy: every
    // drawn tile discarded at once, a tile from the hand after each pon, no other call.
    let (_, game) = replayed_log(&app, &id).await;
    let mut pons = 0;
    for round in &game.rounds {
        for seat in [1, 3] {
            for (draw, discard) in round.draws[seat].iter().zip(&round.discards[seat]) {
                match (draw, discard) {
                    (Draw::Tile(_), Discard::Tsumogiri) => {}
                    (Draw::Pon { .. }, Discard::Tile(_)) => pons += 1,
                    other => panic!("seat {seat} of round {}: {other:?}", round.kyoku),
                }
            }
        }
    }
    // A bot's call is asked out of sight of the page and played like an agent's.
    assert!(pons > 0, "the bots never called");
}

/// A three-player game with bots: they are told three seats and set North aside (`kita`), and
/// the log replays with their seats playing the bot's policy.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bots_play_a_three_player_game() {
    let second = Duration::from_secs(5);
    let app = app(limits(vec![
        simple_bot("plain", Dialect::App, "play", second),
        simple_bot("stdio", Dialect::Stdio, "play", second),
    ]));
    let body =
        json!({"variant": "sanma", "mode": "half", "seat": 0, "agents": ["mjai:plain", "mjai:stdio"], "delay_ms": 0});
    let v = new_game(&app, body).await;
    assert_eq!(v["names"], json!(["You", "plain 1", "stdio 2"]), "{v}");
    let id = v["id"].as_str().expect("an id").to_string();
    let last = play_to_the_end(&app, &id).await;
    assert!(!last["events"].to_string().contains("failed"), "{}", last["events"]);
    let (_, game) = replayed_log(&app, &id).await;
    assert_eq!(game.variant, rinshan_engine::Variant::Sanma);
    let north = rinshan_engine::tile::Tile::plain(rinshan_engine::tile::TileType::NORTH);
    let mut kitas = 0;
    // The log numbers seats from the first dealer: the bots' are found by their names.
    let bots: Vec<usize> = (0..3).filter(|&s| game.names[s] != "You").collect();
    assert_eq!(bots.len(), 2, "{:?}", game.names);
    for round in &game.rounds {
        for &seat in &bots {
            for (draw, discard) in round.draws[seat].iter().zip(&round.discards[seat]) {
                match (draw, discard) {
                    (Draw::Tile(_), Discard::Tsumogiri) | (Draw::Pon { .. }, Discard::Tile(_)) => {}
                    (Draw::Tile(t), Discard::Kita) if *t == north => kitas += 1,
                    other => panic!("seat {seat} of round {}: {other:?}", round.kyoku),
                }
            }
        }
    }
    assert!(kitas > 0, "the bots never set North aside");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_failing_bot_loses_its_game_and_a_thinking_bot_holds_nothing() {
    let app = app(limits(vec![
        simple_bot("dies", Dialect::App, "die", Duration::from_secs(5)),
        simple_bot("sleeps", Dialect::Stdio, "sleep", Duration::from_secs(3)),
    ]));
    for (bot, words) in [("dies", "dying on purpose"), ("sleeps", "no reply within 3.0 s")] {
        let v = new_game(
            &app,
            json!({"mode": "east", "agents": [format!("mjai:{bot}"), "rule", "rule", "rule"], "delay_ms": 0}),
        )
        .await;
        let id = v["id"].as_str().expect("an id").to_string();
        let deadline = Instant::now() + Duration::from_secs(60);
        let last = loop {
            assert!(Instant::now() < deadline, "{bot}: the game did not end");
            let asked = Instant::now();
            let (status, text) = get(&app, &format!("/api/games/{id}?board=0")).await;
            // The page is answered at once, also while the bot sleeps on its move.
            assert!(asked.elapsed() < Duration::from_secs(1), "{bot}: {:?}", asked.elapsed());
            assert_eq!(status, StatusCode::OK, "{text}");
            let v = parsed(&text);
            if v["phase"] == "over" {
                break v;
            }
            if v["phase"] == "result" {
                let (status, text) = post(&app, &format!("/api/games/{id}/next"), &json!(null)).await;
                assert!(status == StatusCode::OK || status == StatusCode::CONFLICT, "{text}");
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        };
        let events = last["events"].to_string();
        assert!(
            events.contains(&format!("{bot} 0 failed")) && events.contains(words),
            "{events}"
        );
        let (status, text) = get(&app, &format!("/api/games/{id}/log")).await;
        assert_eq!(status, StatusCode::CONFLICT, "{text}");
        assert!(text.contains("illegal action"), "{text}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_visitor_names_only_the_servers_bots() {
    let none = app(limits(Vec::new()));
    let one = app(limits(vec![simple_bot(
        "plain",
        Dialect::App,
        "play",
        Duration::from_secs(5),
    )]));
    for (server, body, words) in [
        (
            &none,
            json!({"agents": ["mjai:python3 evil.py", "rule", "rule", "rule"]}),
            "this server offers none",
        ),
        (
            &one,
            json!({"agents": ["mjai:other", "rule", "rule", "rule"]}),
            "no MJAI bot `other`: this server offers plain",
        ),
        (
            &one,
            json!({"variant": "no-red", "agents": ["mjai:plain", "rule", "rule", "rule"]}),
            "MJAI bots play Tenhou's rules",
        ),
        (
            &one,
            json!({"mode": "single", "agents": ["mjai:plain", "rule", "rule", "rule"]}),
            "MJAI bots play Tenhou's rules",
        ),
    ] {
        let (status, text) = post(server, "/api/games", &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {text}");
        let error = parsed(&text)["error"].as_str().map(str::to_string).unwrap_or_default();
        assert!(error.contains(words), "{body}: {error}");
    }
    let (_, text) = get(&none, "/api/agents").await;
    assert!(!text.contains("mjai:"), "{text}");
    let _: Value = parsed(&text);
}
