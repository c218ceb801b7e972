//! rinshan-serve, behind `rinshan serve`: a web page to play against the built-in agents and the
//! operator's MJAI bots, watch four of them, or replay a log (axum on hyper and tokio). Every game is a [`session::Session`]
//! behind a lock; a driver task per game plays the agents' moves after the chosen delay and
//! announces each change over server-sent events. The store bounds the games it keeps (in all, per
//! client and per network, idle time and total time, the MJAI bot processes they run) and the
//! event streams per client; the listener bounds the connections (in all and per network) and
//! gives every phase of a connection a deadline; the replay renderer takes turns, fairly between
//! networks; the data directory keeps a budget. Games dealt to a
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
mod counted;
mod extract;
mod listener;
mod pages;
mod replays;
pub mod session;
mod store;

use std::net::SocketAddr;

pub use api::{app, OUTLOOK_TRIALS};
pub use archive::{Archive, Saved};
pub use bots::NamedBot;
pub use listener::{connection_cap, serve_on};
pub use store::Limits;

/// Serves the page on `addr` until the process ends; prints the address it listens on.
pub async fn serve(addr: SocketAddr, limits: Limits) -> std::io::Result<()> {
    let listener = tokio::net::TcpListener::bind(addr).await?;
    let local = listener.local_addr()?;
    println!("rinshan serve: http://{local}/ (play), /spectate, /replay; Ctrl-C stops");
    serve_on(listener, limits).await
}
