//! The HTTP routes: pages, the game API, the replay and review uploads and the saved games. Every error is
//! JSON `{"error": ...}` with its status: axum's own extractors' rejections too (malformed bodies
//! 400/415/422, the body limit 413; see `extract`), an unknown path 404 and a wrong method 405.

use std::convert::Infallible;
use std::str::FromStr;
use std::time::Duration;

use axum::error_handling::HandleErrorLayer;
use axum::extract::{DefaultBodyLimit, State};
use axum::http::{header, StatusCode};
use axum::response::sse::{Event, KeepAlive, Sse};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::Router;
use futures_util::Stream;
use serde::Deserialize;
use serde_json::{json, Value};

use super::extract::{network, ApiError, Client, Json, Path, Query, Text};
use super::pages;
use super::replays::NoTurn;
use super::session::{first_dealer, Opponent, Refusal, Session, Setup};
use super::store::{Limits, NotRemoved, Refused, Store};
use rinshan_engine::agents::Agent;
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_render::{sprite, TileMode};

fn unprocessable(m: impl std::fmt::Display) -> ApiError {
    ApiError(StatusCode::UNPROCESSABLE_ENTITY, m.to_string())
}

fn not_found(id: &str) -> ApiError {
    ApiError(
        StatusCode::NOT_FOUND,
        format!("no game {id} (it ended, idled out or never existed)"),
    )
}

/// The app with default limits.
pub fn app(limits: Limits) -> Router {
    app_with_store(limits).0
}

pub(super) fn app_with_store(limits: Limits) -> (Router, Store) {
    let request_timeout = limits.request_timeout;
    let store = Store::new(limits);
    let api = Router::new()
        .route("/api/agents", get(agents))
        .route("/api/games", post(create))
        .route("/api/games/{id}", get(view).delete(remove))
        .route("/api/games/{id}/actions", post(act))
        .route("/api/games/{id}/next", post(next))
        .route("/api/games/{id}/events", get(events))
        .route("/api/games/{id}/log", get(log))
        .route("/api/games/{id}/outlook", get(outlook))
        .route("/api/sprite/{mode}", get(tiles_sprite))
        .route("/api/saved", get(saved_list))
        .route("/api/saved/{name}", get(saved_log))
        .route("/api/saved/{name}/replay", get(saved_replay))
        .layer(DefaultBodyLimit::max(16 * 1024));
    // A tenhou.net/6 log of a long game is a few tens of kilobytes; a megabyte bounds the upload.
    let replay = Router::new()
        .route("/api/replay", post(replay))
        .route("/api/review", post(review))
        .layer(DefaultBodyLimit::max(1024 * 1024));
    let router = pages::routes()
        .merge(api)
        .merge(replay)
        .fallback(|| async { ApiError(StatusCode::NOT_FOUND, "no such page".into()) })
        .method_not_allowed_fallback(|| async {
            ApiError(
                StatusCode::METHOD_NOT_ALLOWED,
                "this path does not take that method".into(),
            )
        })
        .with_state(store.clone())
        // A request's body must arrive, and its answer be ready, in time: a body sent a byte at
        // a time holds its connection no longer than this. (An event stream's answer is ready at
        // once; its events are not counted.)
        .layer(
            tower::ServiceBuilder::new()
                .layer(HandleErrorLayer::new(move |_: tower::BoxError| async move {
                    ApiError(
                        StatusCode::REQUEST_TIMEOUT,
                        format!(
                            "the request took longer than {} s to arrive and be answered",
                            request_timeout.as_secs_f64()
                        ),
                    )
                }))
                .layer(tower::timeout::TimeoutLayer::new(request_timeout)),
        );
    (router, store)
}

/// `GET /api/agents`: what a new game may choose; the server's MJAI bots are agents named
/// `mjai:NAME`, its nets `net:NAME`.
async fn agents(State(store): State<Store>) -> axum::Json<Value> {
    let limits = store.limits();
    let nets = limits.nets.iter().map(|(name, _)| format!("{NET}{name}"));
    let bots = limits.bots.iter().map(|b| format!("{MJAI}{}", b.name)).chain(nets);
    axum::Json(json!({
        "agents": Agent::ALL.iter().map(|a| a.name().to_string()).chain(["search".to_string()]).chain(bots).collect::<Vec<_>>(),
        "variants": Variant::ALL.iter().map(|v| v.to_string()).collect::<Vec<_>>(),
        "variant_descriptions": Variant::ALL.iter().map(|v| (v.to_string(), Value::from(v.description()))).collect::<serde_json::Map<_, _>>(),
        // The page offers as many opponents and seats as the rule set has seats.
        "variant_seats": Variant::ALL.iter().map(|v| (v.to_string(), Value::from(v.seats()))).collect::<serde_json::Map<_, _>>(),
        "modes": Mode::ALL.iter().map(|m| m.name()).collect::<Vec<_>>(),
        "tiles": TileMode::ALL.iter().map(|m| m.name()).collect::<Vec<_>>(),
    }))
}

/// `POST /api/games`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct NewGame {
    #[serde(default = "default_variant")]
    variant: String,
    #[serde(default = "default_mode")]
    mode: String,
    /// The person's seat (the engine's seat number; the seed draws which seat deals first, so it
    /// says nothing of the person's wind). Absent or null, as `wind`: agents only (spectating).
    seat: Option<u32>,
    /// The wind the person starts as instead of a seat: 0 = East (they deal East 1), 1 = South,
    /// 2 = West, 3 = North (four players). The server seats them from the seed's first dealer.
    wind: Option<u32>,
    /// One agent per other seat with a person, one per seat without: built-in ones by name, the
    /// server's MJAI bots as `mjai:NAME`. With `wind` they sit in turn order after the person
    /// (the seat to their right first); otherwise in the other seats from seat 0 on.
    agents: Vec<String>,
    /// A spectated game's seed, as a string (a JavaScript number loses digits above 2^53); a game
    /// with a person takes none: the server draws it from the OS.
    seed: Option<String>,
    /// Milliseconds before each agent move.
    #[serde(default = "default_delay")]
    delay_ms: u64,
}

fn default_variant() -> String {
    "red".into()
}
fn default_mode() -> String {
    "half".into()
}
fn default_delay() -> u64 {
    400
}

fn parse<T: FromStr>(what: &str, s: &str) -> Result<T, ApiError>
where
    T::Err: std::fmt::Display,
{
    s.parse().map_err(|e| unprocessable(format!("{what}: {e}")))
}

/// The seed of a new game: the server's fixed one (tests), the spectator's, or the OS's.
fn seed_of(g: &NewGame, limits: &Limits) -> Result<u64, ApiError> {
    let person = g.seat.is_some() || g.wind.is_some();
    match (&g.seed, person, limits.fixed_seed) {
        (Some(_), true, _) => Err(unprocessable(
            "a game with a person takes no seed (anyone who knew it would know every hand); the game \
             shows its seed once it is over",
        )),
        (Some(text), false, _) => text
            .trim()
            .parse()
            .map_err(|_| unprocessable(format!("seed {text:?}: a whole number 0..2^64, as a string"))),
        (None, _, Some(fixed)) => Ok(fixed),
        (None, _, None) => {
            getrandom::u64().map_err(|e| ApiError(StatusCode::SERVICE_UNAVAILABLE, format!("no OS randomness: {e}")))
        }
    }
}

/// The winds a person may start as, by number.
const WINDS: [&str; 4] = ["East", "South", "West", "North"];

/// How a new game names one of the server's MJAI bots among its agents.
const MJAI: &str = "mjai:";

/// How a new game names one of the server's nets among its agents.
const NET: &str = "net:";

/// The most play-outs a look-ahead opponent may spend per decision (about 60 ms on one core at
/// 2,048, its budget in docs/strength.md's strongest runs).
pub const MAX_SEARCH_ROLLOUTS: u32 = 2048;

/// A new game's agent: a built-in one by name, the look-ahead (`search` or `search:rollouts=N`),
/// a bot the server offers as `mjai:NAME`, or a net it offers as `net:NAME`.
fn opponent(name: &str, variant: Variant, limits: &Limits) -> Result<Opponent, ApiError> {
    if let Some(wanted) = name.strip_prefix(NET) {
        let Some((_, net)) = limits.nets.iter().find(|(n, _)| n == wanted) else {
            let offered: Vec<&str> = limits.nets.iter().map(|(n, _)| n.as_str()).collect();
            return Err(unprocessable(match offered.is_empty() {
                true => format!("no net `{wanted}`: this server offers none (rinshan serve --net NAME=PATH)"),
                false => format!("no net `{wanted}`: this server offers {}", offered.join(", ")),
            }));
        };
        return rinshan_net::NetAgent::new(net.clone(), variant)
            .map(Opponent::Net)
            .map_err(unprocessable);
    }
    if name.starts_with("search") {
        let o: rinshan_search::Options = name.parse().map_err(unprocessable)?;
        if o.rollouts > MAX_SEARCH_ROLLOUTS || o.ms > 1000 {
            return Err(unprocessable(format!(
                "{name}: this server's look-ahead spends at most {MAX_SEARCH_ROLLOUTS} play-outs and 1000 ms a decision"
            )));
        }
        return Ok(Opponent::Search(o));
    }
    let Some(bot) = name.strip_prefix(MJAI) else {
        return parse("agent", name).map(Opponent::Agent);
    };
    if let Some(b) = limits.bots.iter().find(|b| b.name == bot) {
        return Ok(Opponent::Bot(b.clone()));
    }
    let offered: Vec<&str> = limits.bots.iter().map(|b| b.name.as_str()).collect();
    Err(unprocessable(match offered.is_empty() {
        true => format!("no MJAI bot `{bot}`: this server offers none (rinshan serve --mjai-bot NAME=COMMAND)"),
        false => format!("no MJAI bot `{bot}`: this server offers {}", offered.join(", ")),
    }))
}

fn setup(g: NewGame, limits: &Limits) -> Result<Setup, ApiError> {
    let variant: Variant = parse("variant", &g.variant)?;
    let table = variant.seats() as usize;
    let mode: Mode = parse("mode", &g.mode)?;
    let agents: Vec<Opponent> = g
        .agents
        .iter()
        .map(|a| opponent(a, variant, limits))
        .collect::<Result<_, _>>()?;
    let person = g.seat.is_some() || g.wind.is_some();
    let want = table - usize::from(person);
    if agents.len() != want {
        return Err(unprocessable(format!(
            "{} agents given: a game of {variant} {} needs {want}",
            agents.len(),
            if person { "with a person" } else { "to spectate" }
        )));
    }
    if let Some(h) = g.seat.filter(|&h| h as usize >= table) {
        return Err(unprocessable(format!(
            "seat {h}: {variant}'s seats are 0..{}",
            table - 1
        )));
    }
    if g.delay_ms > 10_000 {
        return Err(unprocessable(format!("delay_ms {}: at most 10000", g.delay_ms)));
    }
    let seed = seed_of(&g, limits)?;
    let human = match (g.seat, g.wind) {
        (Some(_), Some(_)) => {
            return Err(unprocessable(
                "a seat or a wind, not both: the seed draws the first dealer, so a seat fixes no wind",
            ))
        }
        (None, Some(w)) if w as usize >= table => {
            return Err(unprocessable(format!(
                "wind {w}: {variant}'s winds are {} (0..{})",
                WINDS[..table].join(", "),
                table - 1
            )))
        }
        (None, Some(w)) => {
            let first =
                first_dealer(variant, mode, seed).map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e))?;
            Some((first + w) % table as u32)
        }
        (seat, None) => seat,
    };
    let mut seats: [Option<Opponent>; 4] = Default::default();
    let mut rest = agents.into_iter();
    // With a wind the seat numbers mean nothing to the person: the agents sit in turn order after
    // them (the seat to their right first). With a seat they fill the other seats from seat 0 on,
    // as this API always did.
    let first_agent = match (g.wind, human) {
        (Some(_), Some(h)) => (h as usize + 1) % table,
        _ => 0,
    };
    for k in 0..table {
        let p = (first_agent + k) % table;
        if Some(p as u32) != human {
            seats[p] = rest.next();
        }
    }
    // The seat no one sits at (three players) is an agent that is never asked.
    for s in seats.iter_mut().skip(table) {
        *s = Some(Opponent::Agent(Agent::Random));
    }
    Ok(Setup {
        variant,
        mode,
        seats,
        seed,
        delay: Duration::from_millis(g.delay_ms),
    })
}

/// `?tiles=ja&board=0`: the tile mode of the board, or no board (light polling).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ViewQuery {
    tiles: Option<String>,
    board: Option<u8>,
}

fn view_json(id: u64, s: &Session, tiles: TileMode, board: bool) -> Result<Value, ApiError> {
    let b = s.board().map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e))?;
    let svg = board.then(|| s.svg(&b, tiles));
    let setup = s.setup();
    Ok(json!({
        "id": id.to_string(),
        "step": s.step,
        "phase": s.phase(),
        "current": b.current,
        "seat": s.human(),
        "variant": setup.variant.to_string(),
        "rules": setup.variant.description(),
        "mode": setup.mode.name(),
        "names": &s.names()[..b.seats as usize],
        "scores": &b.scores[..b.seats as usize],
        "round": b.round_name(),
        "honba": b.honba,
        "legal": s.choices(),
        "result": b.result.as_ref().map(|r| json!({
            "deltas": r.deltas,
            "uma": r.uma,
            "wins": r.wins.iter().map(|w| json!({"seat": w.seat, "from": w.from, "yaku": w.yaku, "han": w.han, "fu": w.fu, "yakuman": w.yakuman})).collect::<Vec<_>>(),
            "draw": r.draw.map(|d| format!("{d:?}")),
            "ranks": r.ranks,
            "final_scores": r.final_scores,
        })),
        "events": s.events(),
        "seed": s.shown_seed().map(|x| x.to_string()),
        "log": s.log().is_ok(),
        "svg": svg,
    }))
}

fn game_id(id: &str) -> Result<u64, ApiError> {
    id.parse().map_err(|_| not_found(id))
}

async fn create(
    State(store): State<Store>,
    Client(client): Client,
    Json(g): Json<NewGame>,
) -> Result<impl IntoResponse, ApiError> {
    // Refusing is cheap and building a game is not: the limits are checked first.
    let bots = g.agents.iter().filter(|a| a.starts_with(MJAI)).count();
    store.admit(client, bots).map_err(refused)?;
    let setup = setup(g, store.limits())?;
    let (id, held) = store.create(setup, client).map_err(refused)?;
    let body = {
        let s = held.lock();
        view_json(id, &s, TileMode::En, false)?
    };
    held.changed();
    Ok((StatusCode::CREATED, axum::Json(body)))
}

fn refused(e: Refused) -> ApiError {
    let busy = |m: String| ApiError(StatusCode::SERVICE_UNAVAILABLE, m);
    let yours = |m: String| ApiError(StatusCode::TOO_MANY_REQUESTS, m);
    match e {
        Refused::Invalid(m) => unprocessable(m),
        Refused::Full => busy("the server is holding as many games as it may, each with a person playing: try again later".into()),
        Refused::Reserved(n) => busy(format!(
            "the server is nearly full and keeps its last places for newcomers; your network holds {n} games: leave one first"
        )),
        Refused::ClientFull(n) => yours(format!("you hold {n} games, as many as one client may: leave one first")),
        Refused::NetworkFull(n) => yours(format!(
            "your network holds {n} games, as many as one network may: leave one first"
        )),
        Refused::ClientBots { running, wanted, cap } => yours(format!(
            "this game would start {wanted} MJAI bot processes and your games run {running}; one client may run {cap} at once: leave a game with bots first"
        )),
        Refused::ServerBots { running, wanted, cap } => busy(format!(
            "this game would start {wanted} MJAI bot processes and the server runs {running} of at most {cap}: try again later, or play the built-in agents"
        )),
    }
}

fn tiles_of(q: &ViewQuery) -> Result<TileMode, ApiError> {
    q.tiles.as_deref().map_or(Ok(TileMode::En), |t| parse("tiles", t))
}

async fn view(
    State(store): State<Store>,
    Path(id): Path<String>,
    Query(q): Query<ViewQuery>,
) -> Result<axum::Json<Value>, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let tiles = tiles_of(&q)?;
    let s = held.lock();
    Ok(axum::Json(view_json(game_id(&id)?, &s, tiles, q.board != Some(0))?))
}

/// `POST /api/games/{id}/actions`: the person's move at decision `step`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Move {
    action: u32,
    step: u64,
}

async fn act(
    State(store): State<Store>,
    Path(id): Path<String>,
    Json(m): Json<Move>,
) -> Result<axum::Json<Value>, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let body = {
        let mut s = held.lock();
        s.play(m.action, m.step).map_err(refusal)?;
        view_json(game_id(&id)?, &s, TileMode::En, false)?
    };
    held.changed();
    Ok(axum::Json(body))
}

fn refusal(r: Refusal) -> ApiError {
    match r {
        Refusal::Stale(m) => ApiError(StatusCode::CONFLICT, m),
        Refusal::Illegal(m) => unprocessable(m),
    }
}

async fn next(State(store): State<Store>, Path(id): Path<String>) -> Result<axum::Json<Value>, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let body = {
        let mut s = held.lock();
        s.next_round().map_err(refusal)?;
        view_json(game_id(&id)?, &s, TileMode::En, false)?
    };
    held.changed();
    Ok(axum::Json(body))
}

/// `DELETE /api/games/{id}`: only the client that started a game ends it (anyone who knows a
/// game's id may watch it).
async fn remove(
    State(store): State<Store>,
    Client(client): Client,
    Path(id): Path<String>,
) -> Result<StatusCode, ApiError> {
    match store.remove(game_id(&id)?, client) {
        Ok(()) => Ok(StatusCode::NO_CONTENT),
        Err(NotRemoved::Missing) => Err(not_found(&id)),
        Err(NotRemoved::NotYours) => Err(ApiError(
            StatusCode::FORBIDDEN,
            format!("game {id} was started by another client: only it may end the game"),
        )),
    }
}

/// Server-sent events: `data: <change count>` after every move; the page then reads the view.
/// Each stream counts against its client until it closes.
async fn events(
    State(store): State<Store>,
    Client(client): Client,
    Path(id): Path<String>,
) -> Result<Sse<impl Stream<Item = Result<Event, Infallible>>>, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let permit = store.open_stream(client).ok_or_else(|| {
        ApiError(
            StatusCode::TOO_MANY_REQUESTS,
            format!(
                "you have {} event streams open, as many as one client may: close one first",
                store.limits().streams_per_client
            ),
        )
    })?;
    let rx = held.subscribe();
    drop(held);
    let stream = futures_util::stream::unfold((rx, true, permit), |(mut rx, first, permit)| async move {
        // The first event tells a new listener where the game is; a dropped game ends the stream
        // (and drops the permit).
        if !first && rx.changed().await.is_err() {
            return None;
        }
        let n = *rx.borrow_and_update();
        Some((
            Ok(Event::default().event("change").data(n.to_string())),
            (rx, false, permit),
        ))
    });
    Ok(Sse::new(stream).keep_alive(KeepAlive::default()))
}

async fn log(State(store): State<Store>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let s = held.lock();
    let text = s.log().map_err(|m| ApiError(StatusCode::CONFLICT, m))?.to_string();
    Ok((
        [
            (header::CONTENT_TYPE, "application/json"),
            (
                header::CONTENT_DISPOSITION,
                "attachment; filename=\"rinshan-game.json\"",
            ),
        ],
        text,
    )
        .into_response())
}

async fn tiles_sprite(Path(mode): Path<String>) -> Result<Response, ApiError> {
    let mode = mode.trim_end_matches(".svg");
    let mode: TileMode = mode
        .parse()
        .map_err(|e| ApiError(StatusCode::NOT_FOUND, format!("{e}")))?;
    Ok((
        [
            (header::CONTENT_TYPE, "image/svg+xml"),
            (header::CACHE_CONTROL, "max-age=3600"),
        ],
        sprite(mode),
    )
        .into_response())
}

/// Play-outs per discard behind the page's odds: a 95% interval of at most ±2.2 points, worked
/// out in well under a tenth of a second.
pub const OUTLOOK_TRIALS: u32 = 2000;

/// `GET /api/games/{id}/outlook`: at the person's own turn, each discard's chances of tenpai and
/// of a win by each of their draws left, drawing alone from the tiles they cannot see
/// ([`rinshan_search::outlook::at_turn`]); 409 at any other time.
async fn outlook(State(store): State<Store>, Path(id): Path<String>) -> Result<axum::Json<Value>, ApiError> {
    let held = store.get(game_id(&id)?).ok_or_else(|| not_found(&id))?;
    let (turn, step, kept) = {
        let s = held.lock();
        (s.own_turn(), s.step, s.odds.clone())
    };
    let Some((state, seat, variant)) = turn else {
        return Err(ApiError(
            StatusCode::CONFLICT,
            "the odds are worked out at your own turn to discard".into(),
        ));
    };
    // Worked out once per decision: asking again, or from many tabs, costs nothing.
    if let Some((_, odds)) = kept.filter(|(at, _)| *at == step) {
        return Ok(axum::Json(odds));
    }
    // The same draws for every request at this decision: the odds do not flicker on a refresh.
    let seed = u64::from(state.next_draw) << 8 | u64::from(seat);
    let (odds, draws) = tokio::task::spawn_blocking(move || {
        rinshan_search::outlook::at_turn(variant, &state, seat, OUTLOOK_TRIALS, seed)
    })
    .await
    .map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?
    .map_err(|e| ApiError(StatusCode::CONFLICT, e))?;
    let odds = rinshan_search::outlook::to_json(&odds, draws);
    held.lock().odds = Some((step, odds.clone()));
    Ok(axum::Json(odds))
}

/// The most rounds an uploaded log may have (a long half game has about 20).
const MAX_REPLAY_ROUNDS: usize = 32;

/// `POST /api/replay` with a log as the body (tenhou.net/6, MJAI or mjlog XML): the replay page
/// of that game.
async fn replay(State(store): State<Store>, Client(client): Client, Text(body): Text) -> Result<Response, ApiError> {
    replay_page(&store, client, "upload", &body).await
}

/// The replay page of a log, drawn at `client`'s turn.
async fn replay_page(store: &Store, client: std::net::IpAddr, name: &str, body: &str) -> Result<Response, ApiError> {
    let game = replayable(name, body)?;
    at_turn(store, client, move || rinshan_render::html::replay_html(&game, 0)).await
}

/// `?seat=S`: the seat a review judges.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ReviewQuery {
    seat: u32,
}

/// `POST /api/review?seat=S` with a log as the body: the review page of that seat's decisions
/// ([`rinshan_review`]), judged at `client`'s turn like a replay (a review's cost makes the
/// network rest as long).
async fn review(
    State(store): State<Store>,
    Client(client): Client,
    Query(q): Query<ReviewQuery>,
    Text(body): Text,
) -> Result<Response, ApiError> {
    let game = replayable("upload", &body)?;
    let seats = game.variant.seats();
    if q.seat >= seats {
        return Err(ApiError(
            StatusCode::BAD_REQUEST,
            format!("seat {}: a {seats}-player game has seats 0..{}", q.seat, seats - 1),
        ));
    }
    let options = rinshan_search::Options {
        rollouts: store.limits().review_rollouts,
        ..rinshan_search::Options::default()
    };
    at_turn(&store, client, move || {
        let review = rinshan_review::review(&game, q.seat, None, options)?;
        rinshan_review::review_html(&game, &review)
    })
    .await
}

/// A log a replay or a review reads: parsed, of a length the page draws.
fn replayable(name: &str, body: &str) -> Result<rinshan_logs::tenhou::log::Game, ApiError> {
    let (game, _) = rinshan_logs::file::parse_log(name, body.as_bytes()).map_err(unprocessable)?;
    if game.rounds.is_empty() || game.rounds.len() > MAX_REPLAY_ROUNDS {
        return Err(unprocessable(format!(
            "the log has {} rounds: a game of 1 to {MAX_REPLAY_ROUNDS} is replayed",
            game.rounds.len()
        )));
    }
    Ok(game)
}

/// The page `draw` makes, drawn at `client`'s turn among the replays and reviews.
async fn at_turn(
    store: &Store,
    client: std::net::IpAddr,
    draw: impl FnOnce() -> Result<String, String> + Send + 'static,
) -> Result<Response, ApiError> {
    let turn = store.replays().turn(network(client)).await.map_err(|e| match e {
        NoTurn::Busy => ApiError(
            StatusCode::TOO_MANY_REQUESTS,
            "a replay of yours is waiting or being drawn: one at a time".into(),
        ),
        NoTurn::Resting(left) => ApiError(
            StatusCode::TOO_MANY_REQUESTS,
            format!(
                "your last replay took a while to draw: the next may start in {:.1} s",
                left.as_secs_f64()
            ),
        ),
        NoTurn::Queue(waited) => ApiError(
            StatusCode::SERVICE_UNAVAILABLE,
            format!(
                "other replays are being drawn and yours waited {} s: try again in a moment",
                waited.as_secs()
            ),
        ),
    })?;
    // Drawing every decision of a long game takes a while: keep it off the async threads. The
    // turn goes with the drawing, so a request that times out does not free the renderer early.
    let page = tokio::task::spawn_blocking(move || {
        let _turn = turn;
        draw()
    })
    .await
    .map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?
    .map_err(unprocessable)?;
    Ok(([(header::CONTENT_TYPE, "text/html; charset=utf-8")], page).into_response())
}

fn no_archive() -> ApiError {
    ApiError(
        StatusCode::NOT_FOUND,
        "this server keeps no games (it was started without a data directory)".into(),
    )
}

/// `GET /api/saved`: the finished games in the data directory, newest first.
async fn saved_list(State(store): State<Store>) -> Result<axum::Json<Value>, ApiError> {
    let archive = store.archive().ok_or_else(no_archive)?.clone();
    let list = tokio::task::spawn_blocking(move || archive.list())
        .await
        .map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
    Ok(axum::Json(json!({ "games": list })))
}

async fn saved_text(store: &Store, name: String) -> Result<String, ApiError> {
    let archive = store.archive().ok_or_else(no_archive)?.clone();
    let missing = format!("no saved game {name}");
    tokio::task::spawn_blocking(move || archive.read(&name))
        .await
        .map_err(|e| ApiError(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?
        .ok_or(ApiError(StatusCode::NOT_FOUND, missing))
}

/// `GET /api/saved/{name}`: a saved game's Tenhou log.
async fn saved_log(State(store): State<Store>, Path(name): Path<String>) -> Result<Response, ApiError> {
    let text = saved_text(&store, name).await?;
    Ok(([(header::CONTENT_TYPE, "application/json")], text).into_response())
}

/// `GET /api/saved/{name}/replay`: a saved game's replay page.
async fn saved_replay(
    State(store): State<Store>,
    Client(client): Client,
    Path(name): Path<String>,
) -> Result<Response, ApiError> {
    let text = saved_text(&store, name.clone()).await?;
    replay_page(&store, client, &name, &text).await
}
