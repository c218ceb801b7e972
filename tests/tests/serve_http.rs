//! The web server in process (no socket): every refusal has its status and a JSON message, nothing
//! answers 5xx to anything a visitor sends, a whole game played through the API ends with a
//! Tenhou log that replays through the engine exactly and is kept in the data directory, a person
//! never chooses their game's seed, and no client can hold the server (games and event streams per
//! client, idle and total time). Over a real socket: the header read timeout and the connection cap.

use std::net::SocketAddr;
use std::time::{Duration, Instant};

use axum::body::Body;
use axum::extract::ConnectInfo;
use axum::http::{Method, Request, StatusCode};
use axum::Router;
use rinshan_serve::{app, Limits};
use serde_json::{json, Value};
use tower::ServiceExt;

pub(crate) async fn send(
    app: &Router,
    method: Method,
    uri: &str,
    body: Option<&str>,
    json_type: bool,
) -> (StatusCode, String) {
    send_from(app, "127.0.0.1:1", method, uri, body, json_type).await
}

/// As [`send`], from the client at `from` (what the listener tells the app).
pub(crate) async fn send_from(
    app: &Router,
    from: &str,
    method: Method,
    uri: &str,
    body: Option<&str>,
    json_type: bool,
) -> (StatusCode, String) {
    let from: SocketAddr = from.parse().expect("an address");
    let mut req = Request::builder().method(method).uri(uri).extension(ConnectInfo(from));
    if json_type {
        req = req.header("content-type", "application/json");
    }
    let req = req
        .body(body.map_or_else(Body::empty, |b| Body::from(b.to_string())))
        .expect("a request");
    let resp = app.clone().oneshot(req).await.expect("the router answers");
    let status = resp.status();
    let bytes = axum::body::to_bytes(resp.into_body(), 64 << 20).await.expect("a body");
    (status, String::from_utf8_lossy(&bytes).into_owned())
}

pub(crate) async fn get(app: &Router, uri: &str) -> (StatusCode, String) {
    send(app, Method::GET, uri, None, false).await
}

pub(crate) async fn post(app: &Router, uri: &str, body: &Value) -> (StatusCode, String) {
    send(app, Method::POST, uri, Some(&body.to_string()), true).await
}

pub(crate) fn parsed(body: &str) -> Value {
    serde_json::from_str(body).unwrap_or_else(|e| panic!("JSON ({e}): {body}"))
}

pub(crate) async fn new_game(app: &Router, body: Value) -> Value {
    let (status, text) = post(app, "/api/games", &body).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    parsed(&text)
}

/// Waits until the agents have moved up to a state the test acts on.
pub(crate) async fn settled(app: &Router, id: &str) -> Value {
    for _ in 0..2000 {
        let (status, text) = get(app, &format!("/api/games/{id}?board=0")).await;
        assert_eq!(status, StatusCode::OK, "{text}");
        let v = parsed(&text);
        if v["phase"] != "agent" {
            return v;
        }
        tokio::time::sleep(Duration::from_millis(2)).await;
    }
    panic!("the agents did not move");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_whole_game_through_the_api_replays_from_its_log() {
    let data = std::env::temp_dir().join(format!("rinshan-serve-data-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&data);
    let limits = Limits {
        data_dir: Some(data.clone()),
        fixed_seed: Some(11),
        // The review below must be drawn within the request's timeout on a loaded machine too.
        review_rollouts: 32,
        ..Limits::default()
    };
    let app = app(limits.clone());
    let v = new_game(
        &app,
        json!({"mode": "east", "seat": 2, "agents": ["rule", "greedy", "defensive"], "delay_ms": 0}),
    )
    .await;
    // A game with a person shows no seed while it runs.
    assert_eq!(v["seed"], Value::Null, "{v}");
    // Before the first move East 1's dealer, the first dealer, is to discard.
    assert_eq!(v["step"], 0, "{v}");
    let first = v["current"].as_u64().expect("a seat to move") as usize;
    let id = v["id"].as_str().expect("an id").to_string();
    let (mut moves, mut rounds) = (0, 0);
    let last = loop {
        let v = settled(&app, &id).await;
        match v["phase"].as_str() {
            Some("human") => {
                if moves == 0 {
                    // The person's board shows their own hand and nobody else's.
                    let (_, text) = get(&app, &format!("/api/games/{id}?tiles=ascii")).await;
                    let svg = parsed(&text)["svg"].as_str().expect("a board").to_string();
                    let doc = roxmltree::Document::parse(&svg).expect("the board parses");
                    let hands = doc.descendants().filter(|n| {
                        n.attribute("class") == Some("tile")
                            && matches!(n.attribute("data-zone"), Some("hand" | "drawn"))
                    });
                    for t in hands {
                        let mine = t.attribute("data-seat") == Some("2");
                        assert_eq!(
                            t.attribute("data-tile") != Some("back"),
                            mine,
                            "{:?}",
                            t.attributes().collect::<Vec<_>>()
                        );
                    }
                }
                let first = &v["legal"][0];
                let (status, text) = post(
                    &app,
                    &format!("/api/games/{id}/actions"),
                    &json!({"action": first["id"], "step": v["step"]}),
                )
                .await;
                assert_eq!(status, StatusCode::OK, "{text}");
                moves += 1;
            }
            Some("result") => {
                let r = &v["result"];
                assert!(
                    r["wins"].as_array().is_some_and(|w| !w.is_empty()) || r["draw"].is_string(),
                    "{r}"
                );
                let (status, text) = send(&app, Method::POST, &format!("/api/games/{id}/next"), None, false).await;
                assert_eq!(status, StatusCode::OK, "{text}");
                rounds += 1;
            }
            Some("over") => break v,
            other => panic!("phase {other:?}"),
        }
    };
    // Over, the game shows the seed it was dealt from, as a string.
    assert_eq!(last["seed"], "11", "{last}");
    assert!(moves > 20 && rounds >= 3, "{moves} moves, {rounds} rounds");
    let r = &last["result"];
    let scores: Vec<i64> = r["final_scores"]
        .as_array()
        .expect("final scores")
        .iter()
        .filter_map(Value::as_i64)
        .collect();
    assert_eq!(scores.iter().sum::<i64>(), 100_000, "{r}");
    let mut ranks: Vec<i64> = r["ranks"]
        .as_array()
        .expect("ranks")
        .iter()
        .filter_map(Value::as_i64)
        .collect();
    ranks.sort();
    assert_eq!(ranks, [0, 1, 2, 3]);
    // The downloaded log replays through the engine and agrees with it everywhere.
    let (text, game) = replayed_log(&app, &id).await;
    // The log numbers seats from the first dealer: the person's seat 2 is seat 2 - first there.
    assert_eq!(
        game.names[(2 + 4 - first) % 4],
        "You",
        "first dealer {first}: {:?}",
        game.names
    );
    // The replay page of that log.
    // (Each replay from a client of its own: one network waits out the cost of its last replay.)
    let (status, page) = send_from(&app, "10.0.1.1:1", Method::POST, "/api/replay", Some(&text), false).await;
    assert_eq!(status, StatusCode::OK);
    assert!(page.starts_with("<!doctype html>") && page.contains("DecompressionStream"));
    // The same game as MJAI events makes the same page.
    let mjai = rinshan_logs::file::game_text(&game, rinshan_logs::Format::Mjai).expect("MJAI");
    let (status, mjai_page) = send_from(&app, "10.0.2.1:1", Method::POST, "/api/replay", Some(&mjai), false).await;
    assert_eq!(status, StatusCode::OK, "{mjai_page}");
    assert_eq!(mjai_page, page);
    // The review page of the person's seat (a review takes its turn like a replay).
    let person = (2 + 4 - first) % 4;
    let (status, review) = send_from(
        &app,
        "10.0.5.1:1",
        Method::POST,
        &format!("/api/review?seat={person}"),
        Some(&text),
        false,
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{review}");
    assert!(review.starts_with("<!doctype html>") && review.contains("rinshan review: You in"));
    assert_eq!(
        inlined(&review)["rollouts_per_decision"],
        json!(32),
        "the server's review budget"
    );
    for (query, says) in [("seat=4", "seats 0..3"), ("", "seat"), ("seat=x", "seat")] {
        let (status, error) = send_from(
            &app,
            "10.0.6.1:1",
            Method::POST,
            &format!("/api/review?{query}"),
            Some(&text),
            false,
        )
        .await;
        assert_eq!(status, StatusCode::BAD_REQUEST, "{query}: {error}");
        assert!(
            parsed(&error)["error"].as_str().is_some_and(|e| e.contains(says)),
            "{query}: {error}"
        );
    }
    // The finished game was written to the data directory; a restarted server lists it too.
    let deadline = Instant::now() + Duration::from_secs(20);
    let saved = loop {
        let (status, list) = get(&app, "/api/saved").await;
        assert_eq!(status, StatusCode::OK, "{list}");
        let games = parsed(&list)["games"].as_array().cloned().unwrap_or_default();
        if let Some(g) = games.first() {
            assert_eq!(games.len(), 1, "{list}");
            break g["name"].as_str().expect("a name").to_string();
        }
        assert!(Instant::now() < deadline, "the game was not saved");
        tokio::time::sleep(Duration::from_millis(20)).await;
    };
    let restarted = rinshan_serve::app(limits);
    for server in [&app, &restarted] {
        let (status, kept) = get(server, &format!("/api/saved/{saved}")).await;
        assert_eq!((status, kept.as_str()), (StatusCode::OK, text.as_str()));
        let uri = format!("/api/saved/{saved}/replay");
        let (status, page) = send_from(server, "10.0.3.1:1", Method::GET, &uri, None, false).await;
        assert_eq!(status, StatusCode::OK);
        assert!(page.starts_with("<!doctype html>"));
    }
    for bad in ["..%2F..%2FCargo.toml", "1-2.json", "x"] {
        let (status, text) = get(&restarted, &format!("/api/saved/{bad}")).await;
        assert_eq!(status, StatusCode::NOT_FOUND, "{bad}: {text}");
        assert!(parsed(&text)["error"].is_string(), "{text}");
    }
    let _ = std::fs::remove_dir_all(&data);
    let (status, _) = send(&app, Method::DELETE, &format!("/api/games/{id}"), None, false).await;
    assert_eq!(status, StatusCode::NO_CONTENT);
    let (status, _) = get(&app, &format!("/api/games/{id}")).await;
    assert_eq!(status, StatusCode::NOT_FOUND);
}

/// Every spec of rules/variants/ is offered to the page with its description and its seat count,
/// and a game of a rule set other than Tenhou's starts.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_rule_set_is_offered_with_its_description() {
    let app = app(Limits::default());
    let (status, text) = get(&app, "/api/agents").await;
    assert_eq!(status, StatusCode::OK, "{text}");
    let info = parsed(&text);
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../rules/variants");
    let mut specs = 0;
    for entry in std::fs::read_dir(&dir).expect("rules/variants") {
        let path = entry.expect("an entry").path();
        let spec: toml::Table = toml::from_str(&std::fs::read_to_string(&path).expect("a spec")).expect("TOML");
        let name = spec["variant"]["name"].as_str().expect("a name").replace('_', "-");
        assert_eq!(
            info["variant_seats"][&name].as_i64(),
            spec["game"]["seats"].as_integer(),
            "{name}: {info}"
        );
        assert!(
            info["variants"].as_array().is_some_and(|v| v.contains(&json!(name))),
            "{name}: {info}"
        );
        assert_eq!(
            info["variant_descriptions"][&name],
            spec["variant"]["description"].as_str().expect("text")
        );
        specs += 1;
    }
    assert!(
        specs >= 4 && info["variants"].as_array().is_some_and(|v| v.len() == specs),
        "{info}"
    );
    let v = new_game(
        &app,
        json!({"variant": "mleague", "seat": 0, "agents": ["rule", "rule", "rule"]}),
    )
    .await;
    assert_eq!(v["variant"], "mleague", "{v}");
    assert_eq!(v["rules"], info["variant_descriptions"]["mleague"], "{v}");
}

/// A three-player game in the browser's API: three seats in the view, a North set aside drawn on
/// the board, and a log that names sanma and replays.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_sanma_game_is_played_and_logged() {
    let app = app(Limits {
        fixed_seed: Some(6),
        ..Limits::default()
    });
    let body = json!({"variant": "sanma", "mode": "east", "seat": 2, "agents": ["rule", "greedy"], "delay_ms": 0});
    let v = new_game(&app, body).await;
    assert_eq!(v["names"], json!(["rule 0", "greedy 1", "You"]), "{v}");
    assert_eq!(v["scores"], json!([35000, 35000, 35000]), "{v}");
    assert!(!v["svg"]
        .as_str()
        .unwrap_or("")
        .contains(r#"class="seat" data-seat="3""#));
    let id = v["id"].as_str().expect("an id").to_string();
    let last = play_to_the_end(&app, &id).await;
    assert_eq!(last["scores"].as_array().map(Vec::len), Some(3), "{last}");
    let (_, game) = replayed_log(&app, &id).await;
    assert_eq!(game.variant, rinshan_engine::Variant::Sanma);
}

/// Game `id`'s downloaded Tenhou log, checked to replay through the engine exactly.
pub(crate) async fn replayed_log(app: &Router, id: &str) -> (String, rinshan_logs::tenhou::log::Game) {
    let (status, text) = get(app, &format!("/api/games/{id}/log")).await;
    assert_eq!(status, StatusCode::OK, "{text}");
    let game = rinshan_logs::tenhou::log::parse_game("download", &text).expect("a Tenhou log");
    let report = rinshan_logs::tenhou::replay::replay(std::slice::from_ref(&game), rinshan_engine::env::Backend::Cpu)
        .expect("it replays");
    assert!(report.all_agree(), "the log replays exactly: {report:?}");
    (text, game)
}

/// Plays game `id` to its end, the person taking the first legal action; the last view.
pub(crate) async fn play_to_the_end(app: &Router, id: &str) -> Value {
    loop {
        let v = settled(app, id).await;
        match v["phase"].as_str() {
            Some("human") => {
                let body = json!({"action": v["legal"][0]["id"], "step": v["step"]});
                let (status, text) = post(app, &format!("/api/games/{id}/actions"), &body).await;
                assert_eq!(status, StatusCode::OK, "{text}");
            }
            Some("result") => {
                let (status, text) = send(app, Method::POST, &format!("/api/games/{id}/next"), None, false).await;
                assert_eq!(status, StatusCode::OK, "{text}");
            }
            Some("over") => return v,
            other => panic!("phase {other:?}"),
        }
    }
}

/// The look-ahead as an opponent: it thinks its own turns out on a blocking thread and plays a
/// whole game that replays from its log; its budget is bounded.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_look_ahead_plays_as_an_opponent() {
    let app = app(Limits {
        fixed_seed: Some(8),
        ..Limits::default()
    });
    let (_, agents) = get(&app, "/api/agents").await;
    assert!(
        parsed(&agents)["agents"]
            .as_array()
            .is_some_and(|a| a.contains(&json!("search"))),
        "{agents}"
    );
    let body = json!({"variant": "red", "mode": "east", "wind": 0, "agents": ["search:rollouts=16:focus=all", "defensive", "search"], "delay_ms": 0});
    let v = new_game(&app, body).await;
    let seat = v["seat"].as_u64().expect("a seat") as usize;
    assert_eq!(
        v["names"][(seat + 1) % 4],
        "search:rollouts=16:focus=all 1".replace(" 1", &format!(" {}", (seat + 1) % 4))
    );
    let id = v["id"].as_str().expect("an id").to_string();
    let last = play_to_the_end(&app, &id).await;
    assert_eq!(last["phase"], "over", "{last}");
    replayed_log(&app, &id).await;
    for (agent, says) in [
        ("search:rollouts=100000", "at most 2048"),
        ("search:depth=3", "unknown search option"),
    ] {
        let body = json!({"wind": 0, "agents": [agent, "rule", "rule"]});
        let (status, text) = post(&app, "/api/games", &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{agent}: {text}");
        assert!(
            parsed(&text)["error"].as_str().is_some_and(|e| e.contains(says)),
            "{agent}: {text}"
        );
    }
}

/// A net the server offers (`--net NAME=PATH`) as an opponent: listed as `net:NAME`, it plays a
/// whole game that replays from its log; a net the server lacks, or one that cannot play the rule
/// set, is refused with the reason.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_net_plays_as_an_opponent() {
    use rinshan_net::random::{net_file, Shape};
    let net = rinshan_net::Net::from_bytes(&net_file(Shape::default(), 2), "small.safetensors", "small".into())
        .expect("a random net");
    // A net saved in red's actions alone, before kita joined the nets' layout.
    let old = rinshan_net::Net::from_bytes(&net_file(Shape::red_only(), 2), "old.safetensors", "old".into())
        .expect("a random net");
    let app = app(Limits {
        fixed_seed: Some(9),
        nets: vec![
            ("small".into(), std::sync::Arc::new(net)),
            ("old".into(), std::sync::Arc::new(old)),
        ],
        ..Limits::default()
    });
    let (_, agents) = get(&app, "/api/agents").await;
    assert!(
        parsed(&agents)["agents"]
            .as_array()
            .is_some_and(|a| a.contains(&json!("net:small"))),
        "{agents}"
    );
    let body = json!({"variant": "red", "mode": "east", "wind": 0, "agents": ["net:small", "defensive", "net:small"], "delay_ms": 0});
    let v = new_game(&app, body).await;
    let id = v["id"].as_str().expect("an id").to_string();
    let last = play_to_the_end(&app, &id).await;
    assert_eq!(last["phase"], "over", "{last}");
    replayed_log(&app, &id).await;
    let body = json!({"variant": "sanma", "mode": "east", "seat": 1, "agents": ["net:small", "rule"], "delay_ms": 0});
    let v = new_game(&app, body).await;
    let id = v["id"].as_str().expect("an id").to_string();
    assert_eq!(play_to_the_end(&app, &id).await["phase"], "over");
    replayed_log(&app, &id).await;
    for (variant, agent, says) in [
        ("red", "net:large", "no net `large`: this server offers small, old"),
        ("sanma", "net:old", "no logit for kita"),
    ] {
        let body = json!({"variant": variant, "wind": 0, "agents": [agent, "rule", "rule", "rule"]});
        let (status, text) = post(&app, "/api/games", &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{agent}: {text}");
        assert!(
            parsed(&text)["error"].as_str().is_some_and(|e| e.contains(says)),
            "{agent}: {text}"
        );
    }
}

/// A game of another rule set is logged too: the log names it and replays under it.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_wrc_game_is_logged_under_its_rules() {
    let app = app(Limits {
        fixed_seed: Some(4),
        ..Limits::default()
    });
    let body = json!({"variant": "wrc", "mode": "east", "seat": 1, "agents": ["rule", "rule", "rule"], "delay_ms": 0});
    let id = new_game(&app, body).await["id"].as_str().expect("an id").to_string();
    play_to_the_end(&app, &id).await;
    let (text, game) = replayed_log(&app, &id).await;
    assert!(text.contains("\"variant\":\"wrc\""), "{text}");
    assert_eq!((game.variant, game.red_fives), (rinshan_engine::Variant::Wrc, false));
}

/// The page asks for the wind a person starts as, not a seat: the seed draws the first dealer, so
/// "seat 0" sat South in one game and North in another. Whatever the seed, East deals East 1 and
/// West sits two turns after the dealer; the agents follow the person in turn order.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_person_starts_as_the_wind_they_chose() {
    let mut dealers = std::collections::BTreeSet::new();
    for seed in 1..=6u64 {
        let app = app(Limits {
            fixed_seed: Some(seed),
            ..Limits::default()
        });
        for (variant, table, wind) in [
            ("red", 4, 0),
            ("red", 4, 1),
            ("red", 4, 3),
            ("sanma", 3, 0),
            ("sanma", 3, 2),
        ] {
            let agents = &["rule", "greedy", "defensive"][..table - 1];
            // Agents that wait 10 s: the game is still at its first decision when looked at.
            let body = json!({"variant": variant, "mode": "east", "wind": wind, "agents": agents, "delay_ms": 10000});
            let v = new_game(&app, body.clone()).await;
            assert_eq!(v["step"], 0, "{v}");
            let first = v["current"].as_u64().expect("the dealer to move") as usize;
            let seat = v["seat"].as_u64().expect("the person's seat") as usize;
            assert_eq!(seat, (first + wind) % table, "seed {seed}, {body}: {v}");
            for (k, agent) in agents.iter().enumerate() {
                let name = v["names"][(seat + 1 + k) % table].as_str().unwrap_or_default();
                assert!(
                    name.starts_with(agent),
                    "seed {seed}, {body}: turn {k} after the person: {v}"
                );
            }
            if variant == "red" {
                dealers.insert(first);
            }
            let id = v["id"].as_str().expect("an id");
            let (status, _) = send(&app, Method::DELETE, &format!("/api/games/{id}"), None, false).await;
            assert_eq!(status, StatusCode::NO_CONTENT);
        }
    }
    assert!(
        dealers.len() > 1,
        "the seeds drew one first dealer ({dealers:?}): nothing tells a wind from a seat"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_odds_are_offered_at_the_persons_own_turn() {
    let app = app(Limits {
        fixed_seed: Some(4),
        ..Limits::default()
    });
    for (variant, agents, draws) in [
        ("red", &["rule", "rule", "rule"][..], 18),
        ("sanma", &["rule", "rule"][..], 18),
    ] {
        // The person deals first; the agents would wait 10 s: the game stays at its first decision.
        let body = json!({"variant": variant, "mode": "east", "wind": 0, "agents": agents, "delay_ms": 10000});
        let v = new_game(&app, body).await;
        let id = v["id"].as_str().expect("an id").to_string();
        assert_eq!(v["phase"], "human", "{v}");
        let (status, text) = get(&app, &format!("/api/games/{id}/outlook")).await;
        assert_eq!(status, StatusCode::OK, "{text}");
        let o = parsed(&text);
        assert_eq!(o["draws"], draws, "{variant}: {o}");
        let discards = o["discards"].as_array().expect("discards");
        // One line per tile type the person may discard (a red five's line is its type's).
        let legal: std::collections::BTreeSet<String> = v["legal"]
            .as_array()
            .expect("legal")
            .iter()
            .filter_map(|c| c["tile"].as_str())
            .map(|t| t.replace('0', "5"))
            .collect();
        let offered: std::collections::BTreeSet<String> = discards
            .iter()
            .map(|d| d["discard"].as_str().unwrap_or_default().to_string())
            .collect();
        // Discarding the tile just drawn is tsumogiri, not a discard_ choice, when no other copy is held.
        let tsumogiri = v["legal"]
            .as_array()
            .is_some_and(|l| l.iter().any(|c| c["name"] == "tsumogiri"));
        assert!(
            legal.is_subset(&offered) && offered.len() <= legal.len() + usize::from(tsumogiri),
            "{variant}: {offered:?} vs {legal:?}"
        );
        for d in discards {
            assert_eq!(d["win"].as_array().map(Vec::len), Some(draws), "{d}");
            assert_eq!(d["trials"], rinshan_serve::OUTLOOK_TRIALS, "{d}");
        }
        // The same odds on a second look (the same draws).
        assert_eq!(get(&app, &format!("/api/games/{id}/outlook")).await.1, text);
    }
    // Not the person's turn: refused with the reason.
    let body =
        json!({"variant": "red", "mode": "east", "wind": 1, "agents": ["rule", "rule", "rule"], "delay_ms": 10000});
    let v = new_game(&app, body).await;
    let id = v["id"].as_str().expect("an id");
    let (status, text) = get(&app, &format!("/api/games/{id}/outlook")).await;
    assert_eq!(status, StatusCode::CONFLICT, "{text}");
    assert!(
        parsed(&text)["error"]
            .as_str()
            .is_some_and(|e| e.contains("your own turn")),
        "{text}"
    );
    let (status, _) = get(&app, "/api/games/123456789/outlook").await;
    assert_eq!(status, StatusCode::NOT_FOUND);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_refusal_has_its_status_and_a_message() {
    let app = app(Limits {
        max_games: 3,
        idle: Duration::from_secs(600),
        fixed_seed: Some(1),
        ..Limits::default()
    });
    let error = |text: &str| parsed(text)["error"].as_str().map(str::to_string).unwrap_or_default();
    // Bad setups: 422 with what is wrong.
    for (body, words) in [
        (json!({"seat": 0, "agents": ["rule", "rule"]}), "2 agents"),
        (json!({"seat": 7, "agents": ["rule", "rule", "rule"]}), "seat 7"),
        (
            json!({"seat": 0, "agents": ["rule", "magic", "rule"]}),
            "unknown agent `magic`",
        ),
        (
            json!({"variant": "blue", "seat": 0, "agents": ["rule", "rule", "rule"]}),
            "unknown variant",
        ),
        (
            json!({"variant": "sanma", "seat": 0, "agents": ["rule", "rule", "rule"]}),
            "a game of sanma with a person needs 2",
        ),
        (
            json!({"variant": "sanma", "seat": 3, "agents": ["rule", "rule"]}),
            "seat 3: sanma's seats are 0..2",
        ),
        (
            json!({"variant": "sanma", "wind": 3, "agents": ["rule", "rule"]}),
            "wind 3: sanma's winds are East, South, West",
        ),
        (
            json!({"seat": 0, "wind": 0, "agents": ["rule", "rule", "rule"]}),
            "a seat or a wind, not both",
        ),
        (
            json!({"mode": "long", "agents": ["rule", "rule", "rule", "rule"]}),
            "unknown mode",
        ),
        (
            json!({"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 99999}),
            "delay_ms",
        ),
    ] {
        let (status, text) = post(&app, "/api/games", &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {text}");
        assert!(error(&text).contains(words), "{body}: {text}");
    }
    // Malformed bodies, rejected by axum's extractors, answered in JSON like everything else.
    let big = format!(r#"{{"agents": ["{}"]}}"#, "r".repeat(64 * 1024));
    for (body, json_type, want) in [
        ("{not json", true, StatusCode::BAD_REQUEST),
        ("{}", false, StatusCode::UNSUPPORTED_MEDIA_TYPE),
        (r#"{"agents": 3}"#, true, StatusCode::UNPROCESSABLE_ENTITY),
        (r#"{"agents": [], "extra": 1}"#, true, StatusCode::UNPROCESSABLE_ENTITY),
        // A seed is a string: a JSON number would lose digits in a JavaScript client.
        (
            r#"{"agents": ["rule","rule","rule","rule"], "seed": 5}"#,
            true,
            StatusCode::UNPROCESSABLE_ENTITY,
        ),
        (&big, true, StatusCode::PAYLOAD_TOO_LARGE),
    ] {
        let (status, text) = send(&app, Method::POST, "/api/games", Some(body), json_type).await;
        assert_eq!(status, want, "{body:.60}: {text}");
        assert!(!error(&text).is_empty(), "{body:.60}: not JSON: {text}");
    }
    for (body, words) in [
        (
            json!({"seat": 0, "agents": ["rule", "rule", "rule"], "seed": "5"}),
            "takes no seed",
        ),
        (
            json!({"wind": 0, "agents": ["rule", "rule", "rule"], "seed": "5"}),
            "takes no seed",
        ),
        (
            json!({"agents": ["rule", "rule", "rule", "rule"], "seed": "five"}),
            "a whole number",
        ),
        (
            json!({"agents": ["rule", "rule", "rule", "rule"], "seed": "18446744073709551616"}),
            "a whole number",
        ),
    ] {
        let (status, text) = post(&app, "/api/games", &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {text}");
        assert!(error(&text).contains(words), "{body}: {text}");
    }
    let (status, text) = send(&app, Method::POST, "/api/replay", Some("\u{ff}"), false).await;
    assert!(status.is_client_error() && !error(&text).is_empty(), "{status}: {text}");
    // Unknown games and routes.
    for uri in [
        "/api/games/123",
        "/api/games/abc",
        "/api/games/123/log",
        "/nowhere",
        "/api/sprite/klingon",
    ] {
        let (status, text) = get(&app, uri).await;
        assert_eq!(status, StatusCode::NOT_FOUND, "{uri}: {text}");
        assert!(!error(&text).is_empty(), "{uri}");
    }
    let (status, _) = post(&app, "/api/games/123/actions", &json!({"action": 0, "step": 0})).await;
    assert_eq!(status, StatusCode::NOT_FOUND);
    let (status, text) = send(&app, Method::PUT, "/api/games", Some("{}"), true).await;
    assert_eq!(status, StatusCode::METHOD_NOT_ALLOWED);
    assert!(!error(&text).is_empty(), "{text}");
    let (status, text) = get(&app, "/api/games/1?board=x").await;
    assert_eq!(status, StatusCode::BAD_REQUEST);
    assert!(!error(&text).is_empty(), "{text}");
    // A game where the agents never move (10 s each): seat 3 waits for the dealer.
    let v = new_game(
        &app,
        json!({"mode": "east", "seat": 3, "agents": ["rule", "rule", "rule"], "delay_ms": 10000}),
    )
    .await;
    let slow = v["id"].as_str().expect("an id").to_string();
    assert_eq!(
        v["phase"], "agent",
        "the server's seed 1 deals seat 3 no first turn: {v}"
    );
    let (status, text) = post(
        &app,
        &format!("/api/games/{slow}/actions"),
        &json!({"action": 0, "step": 0}),
    )
    .await;
    assert_eq!(
        (status, error(&text).contains("not your turn")),
        (StatusCode::CONFLICT, true),
        "{text}"
    );
    let (status, _) = send(&app, Method::POST, &format!("/api/games/{slow}/next"), None, false).await;
    assert_eq!(status, StatusCode::CONFLICT);
    let (status, text) = get(&app, &format!("/api/games/{slow}/log")).await;
    assert_eq!(
        (status, error(&text).contains("when the game is over")),
        (StatusCode::CONFLICT, true),
        "{text}"
    );
    // A game where the person moves first (the dealer's seat 0): illegal and stale moves.
    let v = new_game(
        &app,
        json!({"mode": "single", "seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 0}),
    )
    .await;
    let id = v["id"].as_str().expect("an id").to_string();
    let v = settled(&app, &id).await;
    assert_eq!(v["phase"], "human", "{v}");
    let legal: Vec<u64> = v["legal"]
        .as_array()
        .expect("legal")
        .iter()
        .filter_map(|c| c["id"].as_u64())
        .collect();
    let illegal = (0..87).find(|a| !legal.contains(a)).expect("an illegal id");
    let (status, text) = post(
        &app,
        &format!("/api/games/{id}/actions"),
        &json!({"action": illegal, "step": v["step"]}),
    )
    .await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{text}");
    assert!(error(&text).contains("is not legal now; legal:"), "{text}");
    let (status, text) = post(
        &app,
        &format!("/api/games/{id}/actions"),
        &json!({"action": 5000, "step": v["step"]}),
    )
    .await;
    assert_eq!(
        (status, error(&text).contains("does not exist")),
        (StatusCode::UNPROCESSABLE_ENTITY, true),
        "{text}"
    );
    // The refusals changed nothing: the same decision is still open.
    let again = settled(&app, &id).await;
    assert_eq!(again["step"], v["step"]);
    let stale = v["step"].as_u64().expect("a step") + 1;
    let (status, text) = post(
        &app,
        &format!("/api/games/{id}/actions"),
        &json!({"action": legal[0], "step": stale}),
    )
    .await;
    assert_eq!(status, StatusCode::CONFLICT, "{text}");
    let (status, text) = post(
        &app,
        &format!("/api/games/{id}/actions"),
        &json!({"action": legal[0], "step": v["step"]}),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{text}");
    // The same click again is stale.
    let (status, _) = post(
        &app,
        &format!("/api/games/{id}/actions"),
        &json!({"action": legal[0], "step": v["step"]}),
    )
    .await;
    assert_eq!(status, StatusCode::CONFLICT);
    let (status, text) = get(&app, &format!("/api/games/{id}/log")).await;
    assert_eq!(status, StatusCode::CONFLICT, "single games have no Tenhou log: {text}");
    // The store is bounded: a full table makes way by dropping a game nobody plays in, but once
    // a person plays in every game a new one waits.
    let person = json!({"seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 10000});
    let mut refused = None;
    for _ in 0..4 {
        let (status, text) = post(&app, "/api/games", &person).await;
        if status != StatusCode::CREATED {
            refused = Some((status, text));
            break;
        }
    }
    let (status, text) = refused.expect("a full table refuses");
    assert_eq!(status, StatusCode::SERVICE_UNAVAILABLE, "{text}");
    assert!(error(&text).contains("each with a person"), "{text}");
    // A bad upload.
    let (status, text) = send(&app, Method::POST, "/api/replay", Some("{\"log\": 3}"), false).await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{text}");
    // The pages and their assets.
    for (uri, kind) in [
        ("/", "text/html"),
        ("/spectate", "text/html"),
        ("/replay", "text/html"),
        ("/static/app.js", "javascript"),
        ("/static/style.css", "text/css"),
        ("/favicon.ico", "svg"),
        ("/api/sprite/ascii", "svg"),
    ] {
        let req = Request::builder().uri(uri).body(Body::empty()).expect("a request");
        let resp = app.clone().oneshot(req).await.expect("an answer");
        assert_eq!(resp.status(), StatusCode::OK, "{uri}");
        let ct = resp
            .headers()
            .get("content-type")
            .and_then(|v| v.to_str().ok())
            .unwrap_or("");
        assert!(ct.contains(kind), "{uri}: {ct}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn idle_games_are_dropped() {
    let app = app(Limits {
        max_games: 1,
        idle: Duration::from_millis(200),
        ..Limits::default()
    });
    // Games with a person: those make way for nobody until they idle out.
    let person = json!({"seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 10000});
    new_game(&app, person.clone()).await;
    let (status, _) = post(&app, "/api/games", &person).await;
    assert_eq!(status, StatusCode::SERVICE_UNAVAILABLE);
    tokio::time::sleep(Duration::from_millis(300)).await;
    new_game(&app, person).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn no_request_gets_a_server_error() {
    let app = app(Limits::default());
    let v = new_game(
        &app,
        json!({"mode": "single", "seat": 0, "agents": ["random", "random", "random"], "delay_ms": 0}),
    )
    .await;
    let id = v["id"].as_str().expect("an id").to_string();
    // A deterministic stream of odd requests: paths, methods, bodies and content types.
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let paths = [
        format!("/api/games/{id}"),
        format!("/api/games/{id}/actions"),
        format!("/api/games/{id}/next"),
        format!("/api/games/{id}?tiles=zz"),
        format!("/api/games/{id}?board=7&tiles=ja"),
        format!("/api/games/{id}?unknown=1"),
        "/api/games".to_string(),
        "/api/replay".to_string(),
        "/api/games/%ff%fe".to_string(),
        "/api/games/99999999999999999999999".to_string(),
        "/static/../Cargo.toml".to_string(),
    ];
    let bodies = [
        "",
        "null",
        "[]",
        "{}",
        r#"{"action": -1, "step": 0}"#,
        r#"{"action": 4294967295, "step": 18446744073709551615}"#,
        r#"{"action": 1.5, "step": "x"}"#,
        r#"{"seat": null, "agents": ["rule","rule","rule","rule"], "seed": "-4"}"#,
        "\u{0}\u{1}garbage",
        r#"{"mode": "single", "agents": ["rule","rule","rule","rule"], "delay_ms": 0, "seed": "18446744073709551615"}"#,
    ];
    let methods = [Method::GET, Method::POST, Method::DELETE, Method::PATCH];
    for _ in 0..300 {
        let path = &paths[(next() % paths.len() as u64) as usize];
        let body = bodies[(next() % bodies.len() as u64) as usize];
        let method = methods[(next() % methods.len() as u64) as usize].clone();
        let (status, text) = send(&app, method.clone(), path, Some(body), next() % 2 == 0).await;
        assert!(!status.is_server_error(), "{method} {path} {body:?}: {status} {text}");
    }
}

/// Finding 3 of the audit: slow spectated games, their agents moving, held a `--max-games 5`
/// server for minutes. Now one client gets at most its share, the agents' moves keep no game
/// alive, and no game outlives the longest game.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn one_client_cannot_hold_the_server() {
    let app = app(Limits {
        max_games: 5,
        games_per_client: 2,
        idle: Duration::from_millis(400),
        ..Limits::default()
    });
    let spectate = json!({"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 20}).to_string();
    let create = |from: &'static str| {
        let app = app.clone();
        let body = spectate.clone();
        async move { send_from(&app, from, Method::POST, "/api/games", Some(&body), true).await }
    };
    for _ in 0..2 {
        let (status, text) = create("10.0.0.1:5000").await;
        assert_eq!(status, StatusCode::CREATED, "{text}");
    }
    // The same client from another port is the same client.
    let (status, text) = create("10.0.0.1:6000").await;
    assert_eq!(status, StatusCode::TOO_MANY_REQUESTS, "{text}");
    assert!(
        parsed(&text)["error"].as_str().is_some_and(|e| e.contains("2 games")),
        "{text}"
    );
    // Everyone else still gets games.
    let (status, text) = create("10.0.0.2:5000").await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    let watched = parsed(&text)["id"].as_str().expect("an id").to_string();
    // Nobody asks about the first client's games while their agents play on: they are dropped
    // once idle, and the client may start new ones.
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        // The second client keeps watching its game: its requests keep it.
        let (status, _) = send_from(
            &app,
            "10.0.0.2:5000",
            Method::GET,
            &format!("/api/games/{watched}?board=0"),
            None,
            false,
        )
        .await;
        assert_eq!(status, StatusCode::OK, "a watched game is kept");
        let (status, _) = create("10.0.0.1:5000").await;
        if status == StatusCode::CREATED {
            break;
        }
        assert_eq!(status, StatusCode::TOO_MANY_REQUESTS);
        assert!(Instant::now() < deadline, "the idle games were never dropped");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }

    // A game watched all along still ends at the longest game's time.
    let app = rinshan_serve::app(Limits {
        max_duration: Duration::from_millis(500),
        ..Limits::default()
    });
    let v = new_game(
        &app,
        json!({"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 20}),
    )
    .await;
    let id = v["id"].as_str().expect("an id").to_string();
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        // A new game's creation sweeps the store.
        new_game(
            &app,
            json!({"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 10000}),
        )
        .await;
        let (status, _) = get(&app, &format!("/api/games/{id}?board=0")).await;
        if status == StatusCode::NOT_FOUND {
            break;
        }
        assert!(Instant::now() < deadline, "the game outlived its longest time");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn event_streams_are_counted_per_client() {
    let app = app(Limits {
        streams_per_client: 2,
        ..Limits::default()
    });
    let v = new_game(
        &app,
        json!({"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 10000}),
    )
    .await;
    let uri = format!("/api/games/{}/events", v["id"].as_str().expect("an id"));
    let open = |from: &str| {
        let req = Request::builder()
            .uri(&uri)
            .extension(ConnectInfo(from.parse::<SocketAddr>().expect("an address")))
            .body(Body::empty())
            .expect("a request");
        app.clone().oneshot(req)
    };
    let first = open("10.0.0.1:1").await.expect("an answer");
    let second = open("10.0.0.1:2").await.expect("an answer");
    assert_eq!((first.status(), second.status()), (StatusCode::OK, StatusCode::OK));
    let third = open("10.0.0.1:3").await.expect("an answer");
    assert_eq!(third.status(), StatusCode::TOO_MANY_REQUESTS);
    let body = axum::body::to_bytes(third.into_body(), 1 << 16).await.expect("a body");
    assert!(String::from_utf8_lossy(&body).contains("event streams"));
    // Another client is not affected; a closed stream frees its place.
    assert_eq!(open("10.0.0.9:1").await.expect("an answer").status(), StatusCode::OK);
    drop(first);
    assert_eq!(open("10.0.0.1:4").await.expect("an answer").status(), StatusCode::OK);
}

/// Over a real socket: a connection that sends no request is closed once the header timeout
/// passes, and past the connection cap a new connection is served only when one closes.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn slow_connections_are_closed_and_counted() {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.expect("a port");
    let addr = listener.local_addr().expect("an address");
    tokio::spawn(rinshan_serve::serve_on(
        listener,
        Limits {
            max_connections: 2,
            header_timeout: Duration::from_millis(1500),
            ..Limits::default()
        },
    ));
    // Half a request line, then nothing: the server closes the connection.
    let mut silent = tokio::net::TcpStream::connect(addr).await.expect("a connection");
    silent.write_all(b"GET / HT").await.expect("written");
    let mut buf = [0u8; 256];
    let closed = tokio::time::timeout(Duration::from_secs(20), silent.read(&mut buf)).await;
    assert!(
        matches!(closed, Ok(Ok(0)) | Ok(Err(_))),
        "the silent connection was not closed: {closed:?}"
    );
    // Two held connections fill the cap; a third is served only after they close.
    let mut held = Vec::new();
    for _ in 0..2 {
        let mut c = tokio::net::TcpStream::connect(addr).await.expect("a connection");
        c.write_all(b"GET / HT").await.expect("written");
        held.push(c);
    }
    let mut third = tokio::net::TcpStream::connect(addr)
        .await
        .expect("the kernel queues it");
    third
        .write_all(b"GET /api/agents HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        .await
        .expect("written");
    let early = tokio::time::timeout(Duration::from_millis(500), third.read(&mut buf)).await;
    assert!(early.is_err(), "served past the connection cap: {early:?}");
    drop(held);
    let mut answer = Vec::new();
    tokio::time::timeout(Duration::from_secs(20), third.read_to_end(&mut answer))
        .await
        .expect("served once a place is free")
        .expect("read");
    let text = String::from_utf8_lossy(&answer);
    assert!(text.starts_with("HTTP/1.1 200"), "{text}");
}

/// The data a generated page inlines (gzip, then base64, in `const DATA`).
fn inlined(page: &str) -> Value {
    use base64::Engine as _;
    use std::io::Read as _;
    let data = page
        .split("const DATA = \"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .expect("the inlined data");
    let packed = base64::engine::general_purpose::STANDARD.decode(data).expect("base64");
    let mut json = String::new();
    flate2::read::GzDecoder::new(&packed[..])
        .read_to_string(&mut json)
        .expect("gzip");
    serde_json::from_str(&json).expect("JSON")
}
