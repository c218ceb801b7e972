//! rinshan-serve, behind `rinshan serve`: a web page to play against the built-in agents, watch four of them, or replay a
//! log (axum on tokio). Every game is a [`session::Session`] behind a lock; a driver task per game
//! plays the agents' moves after the chosen delay and announces each change over server-sent
//! events. The store bounds the games it keeps (count and idle time), and every bad request is a
//! 4xx with a JSON `{"error": ...}` body.
//!
//! Depends on `rinshan-engine`, `rinshan-logs` and `rinshan-render`; only the `rinshan` command
//! uses it (the Python package serves no page).

#![warn(missing_docs)]

mod api;
mod pages;
pub mod session;
mod store;

use std::net::SocketAddr;
use std::time::Duration;

pub use api::app;
pub use store::Limits;

/// Serves the page on `addr` until the process ends; prints the address it listens on.
pub async fn serve(addr: SocketAddr, limits: Limits) -> std::io::Result<()> {
    let listener = tokio::net::TcpListener::bind(addr).await?;
    let local = listener.local_addr()?;
    let (router, store) = api::app_with_store(limits);
    // Idle games are dropped even when nobody creates new ones.
    tokio::spawn(async move {
        loop {
            tokio::time::sleep(Duration::from_secs(30)).await;
            store.sweep();
        }
    });
    println!("rinshan serve: http://{local}/ (play), /spectate, /replay; Ctrl-C stops");
    axum::serve(listener, router).await
}
