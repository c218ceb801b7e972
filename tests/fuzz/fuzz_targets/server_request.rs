//! Any request to the web server's router: whatever the method, path, content type and body, the
//! answer is never a 5xx (a full server's 503 aside) and never a panic.
#![no_main]

use std::sync::OnceLock;

use arbitrary::Arbitrary;
use axum::body::Body;
use axum::http::{Method, Request};
use axum::Router;
use libfuzzer_sys::fuzz_target;
use rinshan_serve::{app, Limits};
use tower::ServiceExt;

#[derive(Debug, Arbitrary)]
struct Input {
    method: u8,
    /// A known path (with the id of the game the run made) or the fuzzer's own.
    path: Result<u8, String>,
    json: bool,
    body: Vec<u8>,
}

const PATHS: [&str; 12] = [
    "/api/games",
    "/api/games/{id}",
    "/api/games/{id}/actions",
    "/api/games/{id}/next",
    "/api/games/{id}/events",
    "/api/games/{id}/log",
    "/api/games/{id}?tiles=ja&board=0",
    "/api/replay",
    "/api/saved",
    "/api/saved/1-2.json",
    "/api/sprite/ascii",
    "/api/agents",
];

struct Server {
    runtime: tokio::runtime::Runtime,
    app: Router,
    game: String,
}

fn server() -> &'static Server {
    static SERVER: OnceLock<Server> = OnceLock::new();
    SERVER.get_or_init(|| {
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_time()
            .build()
            .expect("a runtime");
        let app = runtime.block_on(async {
            app(Limits {
                max_games: 64,
                games_per_client: 64,
                fixed_seed: Some(1),
                ..Limits::default()
            })
        });
        let body = r#"{"mode": "single", "seat": 0, "agents": ["rule", "rule", "rule"], "delay_ms": 0}"#;
        let req = Request::post("/api/games")
            .header("content-type", "application/json")
            .body(Body::from(body))
            .expect("a request");
        let game = runtime.block_on(async {
            let resp = app.clone().oneshot(req).await.expect("an answer");
            let bytes = axum::body::to_bytes(resp.into_body(), 1 << 20).await.expect("a body");
            let text = String::from_utf8_lossy(&bytes).to_string();
            text.split("\"id\":\"")
                .nth(1)
                .and_then(|t| t.split('"').next())
                .unwrap_or("1")
                .to_string()
        });
        Server { runtime, app, game }
    })
}

fuzz_target!(|input: Input| {
    let s = server();
    let methods = [
        Method::GET,
        Method::POST,
        Method::DELETE,
        Method::PUT,
        Method::PATCH,
        Method::HEAD,
    ];
    let method = methods[usize::from(input.method) % methods.len()].clone();
    let path = match &input.path {
        Ok(i) => PATHS[usize::from(*i) % PATHS.len()].replace("{id}", &s.game),
        Err(p) => format!("/{}", p.trim_start_matches('/')),
    };
    let Ok(uri) = path.parse::<axum::http::Uri>() else {
        return;
    };
    let mut req = Request::builder().method(method).uri(uri);
    if input.json {
        req = req.header("content-type", "application/json");
    }
    let Ok(req) = req.body(Body::from(input.body)) else {
        return;
    };
    let status = s.runtime.block_on(async {
        let resp = s.app.clone().oneshot(req).await.expect("the router answers");
        // An event stream never ends by itself: its status is all there is to check.
        resp.status()
    });
    assert!(!status.is_server_error() || status == 503, "{path}: answered {status}");
});
