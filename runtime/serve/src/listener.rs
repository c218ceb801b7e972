//! The listener: which connections are taken and how long each may take. Every phase of a
//! connection has a deadline, set where the stack has a setting for it: the first bytes and the
//! HTTP/2 preface here (hyper-util's protocol sniffing waits for them without one), HTTP/1 headers
//! and idle keep-alive by hyper's header read timeout, an HTTP/2 peer that stops answering by
//! hyper's keep-alive pings, and a request's body and answer by a tower timeout (see `api`).
//! Connections are capped in all (no more than the process's descriptors allow) and per network
//! (an IPv4 /24, an IPv6 /64), and a failing `accept` backs off instead of spinning.

use std::pin::Pin;
use std::sync::Arc;
use std::task::{Context, Poll};
use std::time::Duration;

use axum::extract::ConnectInfo;
use hyper::rt::{Read, ReadBufCursor, Write};
use hyper_util::rt::{TokioExecutor, TokioIo, TokioTimer};
use hyper_util::server::conn::auto;
use hyper_util::service::TowerToHyperService;
use tokio::io::AsyncReadExt as _;
use tokio::net::TcpStream;
use tower::ServiceExt as _;

use super::counted::PerAddress;
use super::extract::network;
use super::store::{Limits, Store};

/// What the process keeps besides connections: the runtime's own descriptors, the log, saved
/// games being written, and three pipes per MJAI bot process.
fn reserved(limits: &Limits) -> u64 {
    64 + 3 * limits.bot_processes as u64
}

/// The connections served at once: the configured cap, lowered to what the descriptor limit
/// leaves (the soft limit is first raised as far as the hard one allows). A limit too low to
/// serve anyone is an error that says so.
pub fn connection_cap(limits: &Limits) -> std::io::Result<usize> {
    let want = limits.max_connections as u64 + reserved(limits);
    let nofile = rlimit::increase_nofile_limit(want)?;
    let room = nofile.saturating_sub(reserved(limits));
    if room < 16 {
        return Err(std::io::Error::other(format!(
            "the descriptor limit ({nofile}) leaves room for {room} connections once {} are kept for \
             bots and saved games: raise `ulimit -n`",
            reserved(limits)
        )));
    }
    Ok(limits.max_connections.min(room as usize).max(1))
}

/// hyper's settings: every deadline it has, and bounds on what one connection may hold.
fn http(header_timeout: Duration) -> auto::Builder<TokioExecutor> {
    let mut http = auto::Builder::new(TokioExecutor::new());
    // The header read timeout also runs while a kept-alive connection waits for its next
    // request, so it is the idle limit too.
    http.http1()
        .timer(TokioTimer::new())
        .header_read_timeout(header_timeout)
        .max_buf_size(MAX_HEAD);
    // A peer that stops answering pings is closed; one that answers holds at most this many
    // streams, each under the request timeout.
    http.http2()
        .timer(TokioTimer::new())
        .keep_alive_interval(header_timeout)
        .keep_alive_timeout(header_timeout)
        .max_concurrent_streams(32)
        .max_header_list_size(MAX_HEAD as u32);
    http
}

/// The most a request's line and headers may take (hyper answers 431 past it).
const MAX_HEAD: usize = 64 * 1024;

/// The deadline for a request's headers while the server is under pressure.
const PRESSED: Duration = Duration::from_secs(1);

const H2_PREFACE: &[u8] = b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n";

/// Reads a connection's first bytes: until they are not an HTTP/2 preface, or are all of one.
/// `None` when the client closed first.
async fn first_bytes(stream: &mut TcpStream) -> std::io::Result<Option<Vec<u8>>> {
    let mut got = Vec::with_capacity(H2_PREFACE.len());
    let mut buf = [0u8; 24];
    loop {
        let n = stream.read(&mut buf[..H2_PREFACE.len() - got.len()]).await?;
        if n == 0 {
            return Ok(None);
        }
        got.extend_from_slice(&buf[..n]);
        if got.len() == H2_PREFACE.len() || !H2_PREFACE.starts_with(&got) {
            return Ok(Some(got));
        }
    }
}

/// Serves the page on a bound listener until the process ends.
pub async fn serve_on(listener: tokio::net::TcpListener, limits: Limits) -> std::io::Result<()> {
    let cap = connection_cap(&limits)?;
    if cap < limits.max_connections {
        println!(
            "rinshan serve: {cap} connections at once, not {}: the descriptor limit allows no more",
            limits.max_connections
        );
    }
    let connections = Arc::new(tokio::sync::Semaphore::new(cap));
    // Open connections per network.
    let networks = PerAddress::default();
    let per_network = limits.connections_per_network.max(1);
    // Under pressure (three quarters of the connections taken) a new connection gets a second,
    // not the usual deadline, to send its request: a client sends its headers within a round
    // trip or two, and many networks holding connections open turn over ten times as fast.
    let calm = (limits.header_timeout, Arc::new(http(limits.header_timeout)));
    let pressed_timeout = limits.header_timeout.min(PRESSED);
    let pressed = (pressed_timeout, Arc::new(http(pressed_timeout)));
    let (router, store) = super::api::app_with_store(limits);
    sweep_forever(store);
    let mut backoff = Duration::ZERO;
    loop {
        // At the cap, the next connection waits in the kernel's queue until one closes.
        let Ok(permit) = connections.clone().acquire_owned().await else {
            return Ok(());
        };
        let (mut stream, peer) = match listener.accept().await {
            Ok(c) => {
                backoff = Duration::ZERO;
                c
            }
            Err(e) => {
                // A connection reset before it was taken is that connection's end. Anything else
                // (out of descriptors or memory) lasts until something closes: retrying at once
                // would spin a core, so wait, longer each time, up to a second.
                if !matches!(
                    e.kind(),
                    std::io::ErrorKind::ConnectionAborted
                        | std::io::ErrorKind::ConnectionReset
                        | std::io::ErrorKind::Interrupted
                ) {
                    backoff = (backoff * 2).clamp(Duration::from_millis(10), Duration::from_secs(1));
                    tokio::time::sleep(backoff).await;
                }
                continue;
            }
        };
        // Past its network's share a connection is closed at once: one machine cannot fill the
        // table of connections however many it opens.
        let Some(counted) = networks.take(network(peer.ip()), per_network) else {
            continue;
        };
        let router = router.clone();
        let under_pressure = connections.available_permits() < cap / 4;
        let (header_timeout, http) = match under_pressure {
            true => (pressed.0, pressed.1.clone()),
            false => (calm.0, calm.1.clone()),
        };
        tokio::spawn(async move {
            let _held = (permit, counted);
            let first = match tokio::time::timeout(header_timeout, first_bytes(&mut stream)).await {
                Ok(Ok(Some(first))) => first,
                // Silent, closed or too slow to say which protocol it speaks.
                _ => return,
            };
            let service = tower::service_fn(move |mut req: axum::extract::Request<hyper::body::Incoming>| {
                req.extensions_mut().insert(ConnectInfo(peer));
                router.clone().oneshot(req)
            });
            let io = Conn {
                io: TokioIo::new(stream),
                first,
                read: 0,
                rewritten: None,
            };
            // A connection's errors (a client that went away) are its own.
            let _ = http
                .serve_connection_with_upgrades(io, TowerToHyperService::new(service))
                .await;
        });
    }
}

/// Idle and overlong games are dropped even when nobody creates new ones.
fn sweep_forever(store: Store) {
    tokio::spawn(async move {
        loop {
            tokio::time::sleep(Duration::from_secs(30)).await;
            store.sweep();
        }
    });
}

/// A connection as hyper sees it: the bytes read to tell its protocol handed back first, and
/// hyper's own answers to requests it could not parse (400, 414, 431, which it writes with an
/// empty body) given the JSON body every other error has.
struct Conn {
    io: TokioIo<TcpStream>,
    first: Vec<u8>,
    read: usize,
    /// A rewritten answer still being written: its bytes, how many are out, and the length of
    /// hyper's original (what the write reports once it is all out).
    rewritten: Option<(Vec<u8>, usize, usize)>,
}

impl Read for Conn {
    fn poll_read(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        mut buf: ReadBufCursor<'_>,
    ) -> Poll<std::io::Result<()>> {
        if self.read < self.first.len() {
            let n = (self.first.len() - self.read).min(buf.remaining());
            let from = self.read;
            buf.put_slice(&self.first[from..from + n]);
            self.read += n;
            return Poll::Ready(Ok(()));
        }
        Pin::new(&mut self.io).poll_read(cx, buf)
    }
}

/// hyper's answer to an unparsable request, with a JSON body in place of its empty one; `None`
/// for everything else it writes.
pub(crate) fn json_error_answer(head: &[u8]) -> Option<Vec<u8>> {
    let text = std::str::from_utf8(head).ok()?;
    let rest = text.strip_prefix("HTTP/1.1 ")?;
    let message = match rest.get(..4)? {
        "400 " => "the request is not HTTP this server reads",
        "414 " => "the request's path is too long",
        "431 " => "the request's line and headers are too large (at most 64 KiB)",
        _ => return None,
    };
    let head = text.strip_suffix("\r\n\r\n")?;
    if head.contains("\r\n\r\n") {
        return None;
    }
    let lines: Vec<&str> = head.split("\r\n").collect();
    if !lines.iter().any(|l| l.eq_ignore_ascii_case("content-length: 0")) {
        return None;
    }
    let body = serde_json::json!({ "error": message }).to_string();
    let mut out = String::new();
    for line in lines {
        if line.eq_ignore_ascii_case("content-length: 0") {
            out.push_str(&format!(
                "content-type: application/json\r\ncontent-length: {}\r\n",
                body.len()
            ));
        } else {
            out.push_str(line);
            out.push_str("\r\n");
        }
    }
    out.push_str("\r\n");
    out.push_str(&body);
    Some(out.into_bytes())
}

impl Write for Conn {
    fn poll_write(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<std::io::Result<usize>> {
        if self.rewritten.is_none() {
            match json_error_answer(buf) {
                Some(answer) => self.rewritten = Some((answer, 0, buf.len())),
                None => return Pin::new(&mut self.io).poll_write(cx, buf),
            }
        }
        let this = &mut *self;
        if let Some((answer, out, original)) = &mut this.rewritten {
            while *out < answer.len() {
                match Pin::new(&mut this.io).poll_write(cx, &answer[*out..]) {
                    Poll::Ready(Ok(0)) => return Poll::Ready(Err(std::io::ErrorKind::WriteZero.into())),
                    Poll::Ready(Ok(n)) => *out += n,
                    other => return other,
                }
            }
            let n = *original;
            this.rewritten = None;
            return Poll::Ready(Ok(n));
        }
        Poll::Ready(Ok(0))
    }

    fn poll_flush(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Pin::new(&mut self.io).poll_flush(cx)
    }

    fn poll_shutdown(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<std::io::Result<()>> {
        Pin::new(&mut self.io).poll_shutdown(cx)
    }

    // Written whole: an answer to rewrite arrives in one buffer, not split across slices.
    fn is_write_vectored(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::json_error_answer;

    #[test]
    fn hyper_answers_to_unparsable_requests_get_json_bodies() {
        let head = b"HTTP/1.1 431 Request Header Fields Too Large\r\ncontent-length: 0\r\ndate: x\r\n\r\n";
        let out = String::from_utf8(json_error_answer(head).expect("rewritten")).expect("text");
        let (head, body) = out.split_once("\r\n\r\n").expect("a head and a body");
        assert!(head.starts_with("HTTP/1.1 431 "), "{head}");
        assert!(head.contains(&format!("content-length: {}", body.len())), "{head}");
        assert!(head.contains("content-type: application/json"), "{head}");
        let v: serde_json::Value = serde_json::from_str(body).expect("JSON");
        assert!(v["error"].as_str().is_some_and(|e| e.contains("64 KiB")), "{v}");
        // The server's own answers, with bodies, and those that are not errors pass as they are.
        for other in [
            &b"HTTP/1.1 200 OK\r\ncontent-length: 0\r\n\r\n"[..],
            b"HTTP/1.1 404 Not Found\r\ncontent-length: 30\r\n\r\n",
            b"HTTP/1.1 400 Bad Request\r\ncontent-length: 0\r\n\r\n{\"a\":1}",
            b"{\"error\": \"x\"}",
        ] {
            assert_eq!(json_error_answer(other), None, "{}", String::from_utf8_lossy(other));
        }
    }
}
