//! The attacks of docs/serve.md against a running `rinshan serve`, and what a fresh client sees
//! meanwhile. Each kind of hostile connection is held open at `count` connections (reopened as
//! soon as the server closes one): silent, half an HTTP/2 preface, a whole preface and nothing
//! after, request headers a byte every 3 s, a body a byte every 3 s. The attackers' addresses are
//! spread over `networks` IPv4 /24s of 127/8 (one machine with one address: 1); a fresh client at
//! 127.2.0.1 asks for `/api/agents` on a new connection ten times a second.
//!
//! ```text
//! rinshan serve --port 8123 --no-data-dir &
//! ulimit -n 65536
//! cargo run --release -p rinshan-tests --example serve_attack -- 127.0.0.1:8123 [count] [seconds] [networks]
//! cargo run --release -p rinshan-tests --example serve_attack -- 127.0.0.1:8123 churn [games]
//! ```
//!
//! `churn` plays `games` single-hand spectated games to their end (each created, read until over,
//! then left, as the page does), from many clients, and says how long that took: read the
//! server's RSS after it (`ps -o rss= -p PID`).

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpSocket, TcpStream};

const KINDS: [&str; 5] = ["silent", "half-preface", "preface", "slow-headers", "slow-body"];

async fn connect(from: Ipv4Addr, to: SocketAddr) -> std::io::Result<TcpStream> {
    let socket = TcpSocket::new_v4()?;
    socket.bind(SocketAddr::new(IpAddr::V4(from), 0))?;
    socket.connect(to).await
}

/// One hostile connection of `kind`, held until the server closes it.
async fn hold(kind: &str, from: Ipv4Addr, to: SocketAddr, open: &AtomicUsize) {
    let Ok(mut c) = connect(from, to).await else {
        return;
    };
    open.fetch_add(1, Ordering::Relaxed);
    let first: &[u8] = match kind {
        "half-preface" => b"PRI * HTTP/2.0\r\n",
        "preface" => b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n\x00\x00\x00\x04\x00\x00\x00\x00\x00",
        "slow-headers" => b"GET / HTTP/1.1\r\nHost: x\r\n",
        "slow-body" => {
            b"POST /api/games HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\ncontent-length: 1000\r\n\r\n{"
        }
        _ => b"",
    };
    let mut buf = [0u8; 4096];
    if c.write_all(first).await.is_ok() {
        loop {
            // Whatever the server sends is read (and ignored); a close ends the connection.
            match tokio::time::timeout(Duration::from_secs(3), c.read(&mut buf)).await {
                Ok(Ok(0)) | Ok(Err(_)) => break,
                Ok(Ok(_)) => continue,
                Err(_) => {}
            }
            let trickle: &[u8] = match kind {
                "slow-headers" => b"x",
                "slow-body" => b" ",
                _ => continue,
            };
            if c.write_all(trickle).await.is_err() {
                break;
            }
        }
    }
    open.fetch_sub(1, Ordering::Relaxed);
}

/// A fresh client's request: its latency, or why it failed.
async fn fresh(to: SocketAddr) -> Result<Duration, String> {
    let t0 = Instant::now();
    let mut c = connect(Ipv4Addr::new(127, 2, 0, 1), to)
        .await
        .map_err(|e| e.to_string())?;
    c.write_all(b"GET /api/agents HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        .await
        .map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    c.read_to_end(&mut out).await.map_err(|e| e.to_string())?;
    match out.starts_with(b"HTTP/1.1 200") {
        true => Ok(t0.elapsed()),
        false => Err(String::from_utf8_lossy(&out[..out.len().min(40)]).into_owned()),
    }
}

async fn attack(to: SocketAddr, count: usize, seconds: u64, networks: usize) {
    let until = Instant::now() + Duration::from_secs(seconds);
    let open: Vec<Arc<AtomicUsize>> = KINDS.iter().map(|_| Arc::default()).collect();
    for (k, kind) in KINDS.iter().enumerate() {
        for i in 0..count {
            let n = i % networks.max(1);
            let from = Ipv4Addr::new(
                127,
                1 + (n / 250) as u8,
                (n % 250) as u8,
                1 + (i / networks.max(1) % 250) as u8,
            );
            let open = open[k].clone();
            tokio::spawn(async move {
                while Instant::now() < until {
                    hold(kind, from, to, &open).await;
                    // A closed connection is reopened a second later: the attacker keeps its count
                    // (a flood of new connections is a firewall's matter, not this server's).
                    tokio::time::sleep(Duration::from_secs(1)).await;
                }
            });
        }
    }
    // The attack builds up for a few seconds before the fresh client starts.
    tokio::time::sleep(Duration::from_secs(5)).await;
    let mut asked = Vec::new();
    let mut samples = vec![0usize; KINDS.len()];
    let mut ticks = 0;
    while Instant::now() < until {
        asked.push(tokio::spawn(tokio::time::timeout(Duration::from_secs(10), fresh(to))));
        tokio::time::sleep(Duration::from_millis(100)).await;
        for (s, o) in samples.iter_mut().zip(&open) {
            *s += o.load(Ordering::Relaxed);
        }
        ticks += 1;
    }
    let mut latencies = Vec::new();
    let mut errors = Vec::new();
    for t in asked {
        match t.await {
            Ok(Ok(Ok(d))) => latencies.push(d),
            Ok(Ok(Err(e))) => errors.push(e),
            Ok(Err(_)) => errors.push("no answer in 10 s".into()),
            Err(e) => errors.push(e.to_string()),
        }
    }
    latencies.sort();
    let q = |f: f64| {
        latencies
            .get(((latencies.len() as f64 - 1.0) * f) as usize)
            .map_or(0.0, |d| d.as_secs_f64() * 1000.0)
    };
    println!("{count} attackers of each kind from {networks} network(s), {seconds} s:");
    for (kind, s) in KINDS.iter().zip(&samples) {
        println!("  {kind:>12}: {:.0} open on average", *s as f64 / ticks.max(1) as f64);
    }
    println!(
        "fresh client: {} answered, {} failed; ms p50 {:.1} p99 {:.1} max {:.1}",
        latencies.len(),
        errors.len(),
        q(0.5),
        q(0.99),
        q(1.0)
    );
    if let Some(e) = errors.first() {
        println!("  first failure: {e}");
    }
}

/// A request on a new connection from `from`: status and body.
async fn call(from: Ipv4Addr, to: SocketAddr, method: &str, path: &str, body: &str) -> (u16, String) {
    let Ok(mut c) = connect(from, to).await else {
        return (0, String::new());
    };
    let req = format!(
        "{method} {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\ncontent-type: application/json\r\ncontent-length: {}\r\n\r\n{body}",
        body.len()
    );
    let mut out = Vec::new();
    if c.write_all(req.as_bytes()).await.is_err() || c.read_to_end(&mut out).await.is_err() {
        return (0, String::new());
    }
    let text = String::from_utf8_lossy(&out).into_owned();
    let status = text.get(9..12).and_then(|s| s.parse().ok()).unwrap_or(0);
    let body = text
        .split_once("\r\n\r\n")
        .map_or(String::new(), |(_, b)| b.to_string());
    (status, body)
}

async fn churn(to: SocketAddr, games: usize) {
    let t0 = Instant::now();
    let done = Arc::new(AtomicUsize::new(0));
    let clients = 32;
    let tasks: Vec<_> = (0..clients)
        .map(|k| {
            let done = done.clone();
            tokio::spawn(async move {
                let from = Ipv4Addr::new(127, 3, k as u8, 1);
                while done.fetch_add(1, Ordering::Relaxed) < games {
                    let spec = r#"{"mode": "single", "agents": ["rule", "rule", "rule", "rule"], "delay_ms": 0}"#;
                    let (status, body) = call(from, to, "POST", "/api/games", spec).await;
                    let id = serde_json::from_str::<serde_json::Value>(&body)
                        .ok()
                        .and_then(|v| v["id"].as_str().map(str::to_string));
                    let Some(id) = id.filter(|_| status == 201) else {
                        eprintln!("create: {status} {body}");
                        tokio::time::sleep(Duration::from_millis(200)).await;
                        continue;
                    };
                    let path = format!("/api/games/{id}");
                    loop {
                        let (_, v) = call(from, to, "GET", &format!("{path}?board=0"), "").await;
                        if v.contains("\"phase\":\"over\"") || v.contains("\"phase\":\"result\"") {
                            break;
                        }
                        tokio::time::sleep(Duration::from_millis(5)).await;
                    }
                    call(from, to, "DELETE", &path, "").await;
                }
            })
        })
        .collect();
    for t in tasks {
        let _ = t.await;
    }
    println!(
        "{games} games played to their end in {:.1} s",
        t0.elapsed().as_secs_f64()
    );
}

fn main() {
    let mut args = std::env::args().skip(1);
    let to: SocketAddr = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or_else(|| SocketAddr::from(([127, 0, 0, 1], 8123)));
    let rest: Vec<String> = args.collect();
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .expect("a runtime");
    if rest.first().map(String::as_str) == Some("churn") {
        let games = rest.get(1).and_then(|a| a.parse().ok()).unwrap_or(10_000);
        rt.block_on(churn(to, games));
        return;
    }
    let num = |i: usize, default: usize| rest.get(i).and_then(|a| a.parse().ok()).unwrap_or(default);
    rt.block_on(attack(to, num(0, 2000), num(1, 60) as u64, num(2, 1)));
}
