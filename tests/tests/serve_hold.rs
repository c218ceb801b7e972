//! The web server against a stranger who would hold, starve or read it: every phase of a
//! connection has a deadline (over a real socket: silent, half a preface, a whole HTTP/2 preface,
//! an idle keep-alive, a body a byte at a time), one network holds only its share of connections
//! and games, a full table makes way by dropping games nobody plays in and keeps places for
//! newcomers, MJAI bot processes are capped, replays take fair turns, limits are checked before a
//! game is built, hyper's own answers are JSON, and a saved game's name is no handle to a live one.

use std::time::{Duration, Instant};

use axum::http::{Method, StatusCode};
use rinshan_serve::{app, Limits};
use serde_json::{json, Value};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

use super::serve_http::{get, parsed, play_to_the_end, post, send_from};

fn error(text: &str) -> String {
    parsed(text)["error"].as_str().map(str::to_string).unwrap_or_default()
}

async fn server(limits: Limits) -> std::net::SocketAddr {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.expect("a port");
    let addr = listener.local_addr().expect("an address");
    tokio::spawn(rinshan_serve::serve_on(listener, limits));
    addr
}

/// Reads until the server closes the connection (or `within` passes: `None`).
async fn closed_within(c: &mut TcpStream, within: Duration) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    match tokio::time::timeout(within, c.read_to_end(&mut out)).await {
        Ok(_) => Some(out),
        Err(_) => None,
    }
}

async fn fresh_get(addr: std::net::SocketAddr, path: &str) -> String {
    let mut c = TcpStream::connect(addr).await.expect("a connection");
    let req = format!("GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    c.write_all(req.as_bytes()).await.expect("written");
    let out = closed_within(&mut c, Duration::from_secs(10)).await.expect("answered");
    String::from_utf8_lossy(&out).into_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_phase_of_a_connection_has_a_deadline() {
    let addr = server(Limits {
        header_timeout: Duration::from_millis(800),
        request_timeout: Duration::from_millis(1500),
        ..Limits::default()
    })
    .await;
    let opened = Instant::now();
    let mut silent = TcpStream::connect(addr).await.expect("a connection");
    let mut half_preface = TcpStream::connect(addr).await.expect("a connection");
    half_preface.write_all(b"PRI * HTTP/2.0\r\n").await.expect("written");
    let mut preface = TcpStream::connect(addr).await.expect("a connection");
    preface
        .write_all(b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n\x00\x00\x00\x04\x00\x00\x00\x00\x00")
        .await
        .expect("written");
    let mut idle = TcpStream::connect(addr).await.expect("a connection");
    idle.write_all(b"GET /api/agents HTTP/1.1\r\nHost: x\r\n\r\n")
        .await
        .expect("written");
    let mut trickle = TcpStream::connect(addr).await.expect("a connection");
    trickle
        .write_all(
            b"POST /api/games HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\ncontent-length: 100\r\n\r\n{",
        )
        .await
        .expect("written");
    // While they are open a fresh client is served.
    assert!(fresh_get(addr, "/api/agents").await.starts_with("HTTP/1.1 200"));
    let trickled = tokio::spawn(async move {
        let mut buf = [0u8; 4096];
        let mut got = Vec::new();
        for _ in 0..40 {
            // A byte every 300 ms: the body would take 30 s.
            if trickle.write_all(b" ").await.is_err() {
                break;
            }
            if let Ok(Ok(n)) = tokio::time::timeout(Duration::from_millis(300), trickle.read(&mut buf)).await {
                got.extend_from_slice(&buf[..n]);
                if n == 0 || got.windows(4).any(|w| w == b"\r\n\r\n") {
                    break;
                }
            }
        }
        String::from_utf8_lossy(&got).into_owned()
    });
    for (what, c) in [
        ("silent", &mut silent),
        ("half an HTTP/2 preface", &mut half_preface),
        ("an HTTP/2 preface and nothing after", &mut preface),
        ("idle after its request", &mut idle),
    ] {
        assert!(
            closed_within(c, Duration::from_secs(10)).await.is_some(),
            "{what}: still open after {:?}",
            opened.elapsed()
        );
    }
    let answer = trickled.await.expect("joined");
    assert!(answer.starts_with("HTTP/1.1 408"), "{answer}");
    assert!(answer.contains("application/json"), "{answer}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn one_network_holds_its_share_of_connections() {
    let addr = server(Limits {
        connections_per_network: 3,
        ..Limits::default()
    })
    .await;
    let mut held = Vec::new();
    for _ in 0..3 {
        let mut c = TcpStream::connect(addr).await.expect("a connection");
        c.write_all(b"GET / HT").await.expect("written");
        held.push(c);
    }
    tokio::time::sleep(Duration::from_millis(200)).await;
    // The fourth from the same network is closed at once, unanswered.
    let mut fourth = TcpStream::connect(addr).await.expect("the kernel takes it");
    let shut = closed_within(&mut fourth, Duration::from_secs(5)).await;
    assert_eq!(shut.as_deref(), Some(&b""[..]), "the fourth connection was kept");
    drop(held);
    tokio::time::sleep(Duration::from_millis(200)).await;
    assert!(fresh_get(addr, "/api/agents").await.starts_with("HTTP/1.1 200"));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn requests_hyper_cannot_read_get_json_errors() {
    let addr = server(Limits::default()).await;
    let huge = format!(
        "GET /api/agents HTTP/1.1\r\nHost: x\r\nx-big: {}\r\n\r\n",
        "a".repeat(80 * 1024)
    );
    for (request, status) in [
        (huge.as_bytes(), "431"),
        (&b"GARBAGE\x01 / HTTP/1.1\r\n\r\n"[..], "400"),
    ] {
        let mut c = TcpStream::connect(addr).await.expect("a connection");
        // The server may answer and close before all of it is written.
        let _ = c.write_all(request).await;
        let out = closed_within(&mut c, Duration::from_secs(10)).await.expect("answered");
        let text = String::from_utf8_lossy(&out);
        assert!(text.starts_with(&format!("HTTP/1.1 {status}")), "{text}");
        let body = text.split_once("\r\n\r\n").map_or("", |(_, b)| b);
        assert!(!error(body).is_empty(), "{status}: not a JSON error: {text}");
    }
}

const PERSON: &str = r#"{"seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 10000}"#;
const SPECTATE: &str = r#"{"agents": ["rule", "rule", "rule", "rule"], "delay_ms": 10000}"#;

async fn create(app: &axum::Router, from: &str, body: &str) -> (StatusCode, String) {
    send_from(app, from, Method::POST, "/api/games", Some(body), true).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn one_network_cannot_fill_the_table() {
    let app = app(Limits {
        max_games: 8,
        games_per_client: 2,
        games_per_network: 4,
        ..Limits::default()
    });
    // Many addresses of one /24: the network's share, then 429.
    for k in 1..=4 {
        let (status, text) = create(&app, &format!("10.1.1.{k}:1"), PERSON).await;
        assert_eq!(status, StatusCode::CREATED, "{text}");
    }
    let (status, text) = create(&app, "10.1.1.9:1", PERSON).await;
    assert_eq!(status, StatusCode::TOO_MANY_REQUESTS, "{text}");
    assert!(error(&text).contains("your network holds 4 games"), "{text}");
    // A second network fills the table up to its last quarter, kept for newcomers.
    for k in 1..=2 {
        let (status, text) = create(&app, &format!("10.1.2.{k}:1"), PERSON).await;
        assert_eq!(status, StatusCode::CREATED, "{text}");
    }
    let (status, text) = create(&app, "10.1.2.3:1", PERSON).await;
    assert_eq!(status, StatusCode::SERVICE_UNAVAILABLE, "{text}");
    assert!(error(&text).contains("newcomers"), "{text}");
    for net in [3, 4] {
        let (status, text) = create(&app, &format!("10.1.{net}.1:1"), PERSON).await;
        assert_eq!(status, StatusCode::CREATED, "a newcomer: {text}");
    }
    // Full of games with a person: nobody gets one now.
    let (status, text) = create(&app, "10.1.5.1:1", PERSON).await;
    assert_eq!(status, StatusCode::SERVICE_UNAVAILABLE, "{text}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_full_table_drops_its_idlest_game_without_a_person() {
    let app = app(Limits {
        max_games: 3,
        ..Limits::default()
    });
    let id = |text: &str| parsed(text)["id"].as_str().expect("an id").to_string();
    let (_, played) = create(&app, "10.2.1.1:1", PERSON).await;
    let (_, watched) = create(&app, "10.2.2.1:1", SPECTATE).await;
    let (_, left) = create(&app, "10.2.3.1:1", SPECTATE).await;
    // A request refused for its setup makes nobody's game make way.
    let bad = r#"{"variant": "blue", "seat": 0, "agents": ["rule", "rule", "rule"]}"#;
    for _ in 0..3 {
        let (status, _) = create(&app, "10.2.5.1:1", bad).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY);
    }
    for text in [&played, &left, &watched] {
        let (status, _) = get(&app, &format!("/api/games/{}?board=0", id(text))).await;
        assert_eq!(status, StatusCode::OK, "a refused request dropped a game");
    }
    tokio::time::sleep(Duration::from_millis(50)).await;
    // Someone still watches the first spectated game; nobody the second.
    let (status, _) = get(&app, &format!("/api/games/{}?board=0", id(&watched))).await;
    assert_eq!(status, StatusCode::OK);
    let (status, text) = create(&app, "10.2.4.1:1", PERSON).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    for (text, kept) in [(&played, true), (&watched, true), (&left, false)] {
        let (status, _) = get(&app, &format!("/api/games/{}?board=0", id(text))).await;
        assert_eq!(status == StatusCode::OK, kept, "{text}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn limits_are_checked_before_a_game_is_built() {
    let app = app(Limits {
        games_per_client: 1,
        ..Limits::default()
    });
    let (status, _) = create(&app, "10.3.1.1:1", PERSON).await;
    assert_eq!(status, StatusCode::CREATED);
    // A client at its limit is told so whatever it asks for: the setup is not even read.
    let bad = r#"{"variant": "blue", "seat": 0, "agents": ["rule", "rule", "rule"]}"#;
    let (status, text) = create(&app, "10.3.1.1:1", bad).await;
    assert_eq!(status, StatusCode::TOO_MANY_REQUESTS, "{text}");
    let (status, _) = create(&app, "10.3.2.1:1", bad).await;
    assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bot_processes_are_capped_per_client_and_in_all() {
    // The bots are never started: every game waits 10 s before its first move and is dropped
    // when the test ends.
    let bot = rinshan_serve::NamedBot {
        name: "b".into(),
        spec: rinshan_logs::mjai::bot::BotSpec {
            command: "true".into(),
            dialect: rinshan_logs::mjai::bot::Dialect::App,
            timeout: Duration::from_secs(1),
            startup: Duration::from_secs(1),
        },
    };
    let app = app(Limits {
        bots: vec![bot],
        bot_processes: 5,
        bot_processes_per_client: 3,
        ..Limits::default()
    });
    let with_bots = |n: usize| {
        let agents: Vec<&str> = (0..3).map(|k| if k < n { "mjai:b" } else { "rule" }).collect();
        json!({"seat": 0, "agents": agents, "delay_ms": 10000}).to_string()
    };
    let (status, text) = create(&app, "10.4.1.1:1", &with_bots(2)).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    let (status, text) = create(&app, "10.4.1.1:1", &with_bots(2)).await;
    assert_eq!(status, StatusCode::TOO_MANY_REQUESTS, "{text}");
    assert!(error(&text).contains("one client may run 3"), "{text}");
    let (status, text) = create(&app, "10.4.1.1:1", &with_bots(1)).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    let (status, text) = create(&app, "10.4.2.1:1", &with_bots(3)).await;
    assert_eq!(status, StatusCode::SERVICE_UNAVAILABLE, "{text}");
    assert!(error(&text).contains("runs 3 of at most 5"), "{text}");
    let (status, text) = create(&app, "10.4.2.1:1", &with_bots(2)).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    let (status, text) = create(&app, "10.4.3.1:1", PERSON).await;
    assert_eq!(status, StatusCode::CREATED, "built-in agents need no process: {text}");
}

fn a_log() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/tenhou/2010081709gm-00a9-0000-fe3371ad.json"
    );
    std::fs::read_to_string(path).expect("a known log")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn replays_take_fair_turns() {
    let app = app(Limits::default());
    let log = a_log();
    // One client asks on four connections at once, another once.
    let ask = |from: &'static str| {
        let (app, log) = (app.clone(), log.clone());
        tokio::spawn(async move {
            send_from(&app, from, Method::POST, "/api/replay", Some(&log), false)
                .await
                .0
        })
    };
    let greedy: Vec<_> = (0..4).map(|_| ask("10.5.1.1:1")).collect();
    let other = ask("10.5.2.1:1");
    let mut statuses = Vec::new();
    for g in greedy {
        statuses.push(g.await.expect("joined"));
    }
    assert_eq!(other.await.expect("joined"), StatusCode::OK);
    statuses.sort();
    assert_eq!(
        statuses,
        [
            StatusCode::OK,
            StatusCode::TOO_MANY_REQUESTS,
            StatusCode::TOO_MANY_REQUESTS,
            StatusCode::TOO_MANY_REQUESTS
        ]
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_saved_game_names_no_live_game_and_only_its_client_ends_one() {
    let data = std::env::temp_dir().join(format!("rinshan-serve-hold-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&data);
    let app = app(Limits {
        data_dir: Some(data.clone()),
        ..Limits::default()
    });
    let owner = "10.6.1.1:1";
    // (A half game: a single hand has no Tenhou log to save.)
    let body = json!({"seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 0});
    let (status, text) = create(&app, owner, &body.to_string()).await;
    assert_eq!(status, StatusCode::CREATED, "{text}");
    let id = parsed(&text)["id"].as_str().expect("an id").to_string();
    let v: Value = play_to_the_end(&app, &id).await;
    assert_eq!(v["phase"], "over", "{v}");
    let deadline = Instant::now() + Duration::from_secs(20);
    let name = loop {
        let (_, list) = get(&app, "/api/saved").await;
        if let Some(n) = parsed(&list)["games"][0]["name"].as_str() {
            break n.to_string();
        }
        assert!(Instant::now() < deadline, "never saved");
        tokio::time::sleep(Duration::from_millis(20)).await;
    };
    // The name says when, and nothing of the game's id.
    let number = name.trim_end_matches(".json").split('-').nth(1).expect("a number");
    assert_ne!(number, id);
    let (status, _) = get(&app, &format!("/api/games/{number}")).await;
    assert_eq!(status, StatusCode::NOT_FOUND);
    // Another client cannot end the game; its own client can.
    let uri = format!("/api/games/{id}");
    let (status, text) = send_from(&app, "10.6.2.1:1", Method::DELETE, &uri, None, false).await;
    assert_eq!(status, StatusCode::FORBIDDEN, "{text}");
    assert!(error(&text).contains("another client"), "{text}");
    let (status, _) = send_from(&app, owner, Method::DELETE, &uri, None, false).await;
    assert_eq!(status, StatusCode::NO_CONTENT);
    let (status, _) = post(&app, &format!("{uri}/next"), &json!({})).await;
    assert_eq!(status, StatusCode::NOT_FOUND);
    let _ = std::fs::remove_dir_all(&data);
}
