//! A bounded load test of `rinshan serve` on localhost: N people play at once (default 200), each
//! in their own game against three rule agents with no delay. Every person fetches the board as
//! the page does, moves, and polls until the agents have answered; the time from the move to the
//! person's next turn (or the round's end) is the latency reported. Run with
//! `cargo run --release -p rinshan-tests --example serve_load -- [people] [seconds]`.

use std::time::{Duration, Instant};

use axum::body::Bytes;
use http_body_util::{BodyExt, Full};
use hyper_util::client::legacy::{connect::HttpConnector, Client};
use hyper_util::rt::TokioExecutor;
use rinshan_serve::{app, Limits};
use serde_json::{json, Value};

type Http = Client<HttpConnector, Full<Bytes>>;

async fn call(http: &Http, method: &str, url: &str, body: Option<Value>) -> (u16, Value) {
    let mut req = axum::http::Request::builder().method(method).uri(url);
    if body.is_some() {
        req = req.header("content-type", "application/json");
    }
    let body = body.map_or_else(Bytes::new, |b| Bytes::from(b.to_string()));
    let resp = http
        .request(req.body(Full::new(body)).expect("a request"))
        .await
        .expect("an answer");
    let status = resp.status().as_u16();
    let bytes = resp.into_body().collect().await.expect("a body").to_bytes();
    (status, serde_json::from_slice(&bytes).unwrap_or(Value::Null))
}

/// One person's session: returns the latencies of the agents' answers, in microseconds.
async fn person(http: Http, base: String, until: Instant) -> (Vec<u64>, u64) {
    let mut latencies = Vec::new();
    let mut requests = 0u64;
    'games: while Instant::now() < until {
        let (status, v) = call(
            &http,
            "POST",
            &format!("{base}/api/games"),
            Some(json!({"seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 0})),
        )
        .await;
        requests += 1;
        assert_eq!(status, 201, "{v}");
        let id = v["id"].as_str().expect("an id").to_string();
        let view_url = format!("{base}/api/games/{id}");
        let mut v = v;
        while Instant::now() < until {
            // The page draws the board after every change.
            let (_, full) = call(&http, "GET", &view_url, None).await;
            requests += 1;
            if full["phase"] != "agent" {
                v = full;
            }
            match v["phase"].as_str() {
                Some("human") => {
                    let t0 = Instant::now();
                    let step = v["step"].as_u64().unwrap_or(0);
                    let (status, _) = call(
                        &http,
                        "POST",
                        &format!("{view_url}/actions"),
                        Some(json!({"action": v["legal"][0]["id"], "step": step})),
                    )
                    .await;
                    requests += 1;
                    assert_eq!(status, 200);
                    loop {
                        let (_, light) = call(&http, "GET", &format!("{view_url}?board=0"), None).await;
                        requests += 1;
                        if light["phase"] != "agent" && light["step"].as_u64().unwrap_or(0) > step {
                            latencies.push(t0.elapsed().as_micros() as u64);
                            v = light;
                            break;
                        }
                        tokio::time::sleep(Duration::from_millis(2)).await;
                    }
                }
                Some("result") => {
                    call(&http, "POST", &format!("{view_url}/next"), None).await;
                    requests += 1;
                }
                Some("over") => {
                    call(&http, "DELETE", &view_url, None).await;
                    continue 'games;
                }
                _ => tokio::time::sleep(Duration::from_millis(2)).await,
            }
        }
        call(&http, "DELETE", &view_url, None).await;
    }
    (latencies, requests)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let people: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(200);
    let seconds: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(20);
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .expect("a runtime");
    rt.block_on(async move {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.expect("a port");
        let base = format!("http://{}", listener.local_addr().expect("an address"));
        // Every person here is one client (localhost): the per-client cap is the server's.
        let limits = Limits {
            // A quarter of the table is kept for newcomers: this one client needs the rest.
            max_games: 2 * people as usize + 32,
            games_per_client: people as usize + 16,
            games_per_network: people as usize + 16,
            ..Limits::default()
        };
        tokio::spawn(async move { axum::serve(listener, app(limits)).await });
        let http: Http = Client::builder(TokioExecutor::new())
            .pool_max_idle_per_host(people as usize)
            .build(HttpConnector::new());
        let until = Instant::now() + Duration::from_secs(seconds);
        let started = Instant::now();
        let tasks: Vec<_> = (0..people)
            .map(|_| tokio::spawn(person(http.clone(), base.clone(), until)))
            .collect();
        let mut all = Vec::new();
        let mut requests = 0;
        for t in tasks {
            let (l, r) = t.await.expect("a person");
            all.extend(l);
            requests += r;
        }
        all.sort_unstable();
        let q = |f: f64| {
            all.get(((all.len() as f64 - 1.0) * f) as usize)
                .map_or(0.0, |&us| us as f64 / 1000.0)
        };
        let elapsed = started.elapsed().as_secs_f64();
        println!(
            "{people} people for {elapsed:.1} s: {} moves answered, {:.0} requests/s",
            all.len(),
            requests as f64 / elapsed
        );
        println!(
            "agents' answer after a move (ms): p50 {:.1}  p90 {:.1}  p99 {:.1}  max {:.1}",
            q(0.5),
            q(0.9),
            q(0.99),
            q(1.0)
        );
        let within = all.iter().filter(|&&us| us <= 100_000).count();
        println!("within 100 ms: {:.2}%", 100.0 * within as f64 / all.len().max(1) as f64);
    });
}
