//! The pages and their script and style, compiled into the binary.

use axum::http::header;
use axum::response::{Html, IntoResponse};
use axum::routing::get;
use axum::Router;

use super::store::Store;

const SHELL: &str = include_str!("page/shell.html");
const PLAY: &str = include_str!("page/play.html");
const SPECTATE: &str = include_str!("page/spectate.html");
const REPLAY: &str = include_str!("page/replay.html");
const SCRIPT: &str = include_str!("page/app.js");
const STYLE: &str = include_str!("page/style.css");
const ICON: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 30 40"><rect x="1" y="1" width="28" height="38" rx="4" fill="#fffdf5" stroke="#6d6250" stroke-width="2"/><circle cx="15" cy="20" r="8" fill="none" stroke="#1f3f99" stroke-width="3"/><circle cx="15" cy="20" r="3" fill="#b71c1c"/></svg>"##;

fn page(name: &str, title: &str, body: &str) -> Html<String> {
    Html(
        SHELL
            .replace("{{PAGE}}", name)
            .replace("{{TITLE}}", title)
            .replace("{{BODY}}", body),
    )
}

pub(super) fn routes() -> Router<Store> {
    Router::new()
        .route("/", get(|| async { page("play", "Play", PLAY) }))
        .route("/spectate", get(|| async { page("spectate", "Spectate", SPECTATE) }))
        .route("/replay", get(|| async { page("replay", "Replay", REPLAY) }))
        .route(
            "/static/app.js",
            get(|| async { ([(header::CONTENT_TYPE, "text/javascript; charset=utf-8")], SCRIPT).into_response() }),
        )
        .route(
            "/static/style.css",
            get(|| async { ([(header::CONTENT_TYPE, "text/css; charset=utf-8")], STYLE).into_response() }),
        )
        .route(
            "/favicon.ico",
            get(|| async { ([(header::CONTENT_TYPE, "image/svg+xml")], ICON).into_response() }),
        )
}
