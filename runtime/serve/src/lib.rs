//! rinshan-serve, behind `rinshan serve`: a web page to play against the built-in agents and the
//! operator's MJAI bots, watch four of them, or replay a log (axum on hyper and tokio). Every game is a [`session::Session`]
//! behind a lock; a driver task per game plays the agents' moves after the chosen delay and
//! announces each change over server-sent events. The store bounds the games it keeps (in all and
//! per client, idle time and total time) and the event streams per client; the listener bounds
//! the connections and the time a client has to send a request's headers. Games dealt to a
//! person draw their seed from the OS, never from the client. Finished games are written to the
//! data directory and listed by the replay page, also after a restart. Every bad request is a 4xx
//! with a JSON `{"error": ...}` body.
//!
//! Depends on `rinshan-engine`, `rinshan-logs` and `rinshan-render`; only the `rinshan` command
//! uses it (the Python package serves no page).

#![warn(missing_docs)]

mod api;
mod archive;
pub mod bots;
mod extract;
mod pages;
pub mod session;
mod store;

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use axum::extract::ConnectInfo;
use hyper_util::rt::{TokioExecutor, TokioIo, TokioTimer};
use hyper_util::server::conn::auto;
use hyper_util::service::TowerToHyperService;
use tower::ServiceExt as _;

pub use api::app;
pub use archive::{Archive, Saved};
pub use bots::NamedBot;
pub use store::Limits;

/// Serves the page on `addr` until the process ends; prints the address it listens on.
pub async fn serve(addr: SocketAddr, limits: Limits) -> std::io::Result<()> {
    let listener = tokio::net::TcpListener::bind(addr).await?;
    let local = listener.local_addr()?;
    println!("rinshan serve: http://{local}/ (play), /spectate, /replay; Ctrl-C stops");
    serve_on(listener, limits).await
}

/// Serves the page on a bound listener until the process ends.
pub async fn serve_on(listener: tokio::net::TcpListener, limits: Limits) -> std::io::Result<()> {
    let connections = Arc::new(tokio::sync::Semaphore::new(limits.max_connections.max(1)));
    let mut http = auto::Builder::new(TokioExecutor::new());
    // hyper closes a connection whose request headers have not all arrived in time (a client
    // that opens connections and sends nothing holds nothing for long).
    http.http1()
        .timer(TokioTimer::new())
        .header_read_timeout(limits.header_timeout);
    let http = Arc::new(http);
    let (router, store) = api::app_with_store(limits);
    // Idle and overlong games are dropped even when nobody creates new ones.
    tokio::spawn(async move {
        loop {
            tokio::time::sleep(Duration::from_secs(30)).await;
            store.sweep();
        }
    });
    loop {
        // At the cap, the next connection waits in the kernel's queue until one closes.
        let Ok(permit) = connections.clone().acquire_owned().await else {
            return Ok(());
        };
        let (stream, peer) = match listener.accept().await {
            Ok(c) => c,
            // A failed accept (a connection reset before it was taken, out of file descriptors)
            // ends that connection, not the server.
            Err(_) => continue,
        };
        let router = router.clone();
        let http = http.clone();
        tokio::spawn(async move {
            let service = tower::service_fn(move |mut req: axum::extract::Request<hyper::body::Incoming>| {
                req.extensions_mut().insert(ConnectInfo(peer));
                router.clone().oneshot(req)
            });
            // A connection's errors (a client that went away) are its own.
            let _ = http
                .serve_connection_with_upgrades(TokioIo::new(stream), TowerToHyperService::new(service))
                .await;
            drop(permit);
        });
    }
}
