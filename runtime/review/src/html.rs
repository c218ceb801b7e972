//! A review as one self-contained page, viewable offline: each decision's board as its player saw
//! it (drawn by the render crate), every legal action's value, the mistakes ranked by loss and the
//! totals per round.

use rinshan_logs::tenhou::log::Game;
use rinshan_render::html::pack;
use rinshan_render::svg::{escape, seat_name};
use rinshan_render::{sprite, svg, Board, Options, TileMode};
use serde::Serialize;

use crate::review::{Review, Reviewed, RoundSummary, Summary};

const PAGE: &str = include_str!("review.html");

#[derive(Serialize)]
struct Frame<'a> {
    caption: String,
    svg: String,
    #[serde(flatten)]
    decision: &'a Reviewed,
}

#[derive(Serialize)]
struct Data<'a> {
    player: String,
    search: &'a str,
    rollouts_per_decision: u32,
    game: &'a Summary,
    rounds: &'a [RoundSummary],
    frames: Vec<Frame<'a>>,
    sprites: Vec<(String, String)>,
}

/// The page of `review`, a review of `game`.
pub fn review_html(game: &Game, review: &Review) -> Result<String, String> {
    let opts = Options {
        tiles: TileMode::En,
        pov: review.seat,
        reveal: false,
        defs: false,
    };
    let player = seat_name(&game.names, review.seat);
    let frames = review
        .decisions
        .iter()
        .map(|d| {
            let mut board = Board::from_state(&d.state, game.variant);
            board.names = game.names.clone();
            Frame {
                caption: format!("{}: decision {}, {player}: {}", d.round_name, d.step + 1, d.logged),
                svg: svg(&board, &opts),
                decision: d,
            }
        })
        .collect();
    let data = Data {
        player: player.clone(),
        search: &review.search,
        rollouts_per_decision: review.rollouts_per_decision,
        game: &review.game,
        rounds: &review.rounds,
        frames,
        sprites: TileMode::ALL.iter().map(|&m| (m.to_string(), sprite(m))).collect(),
    };
    let title = escape(&format!(
        "rinshan review: {player} in {}",
        game.path.rsplit('/').next().unwrap_or(&game.path)
    ));
    Ok(PAGE.replace("{{TITLE}}", &title).replace("{{DATA}}", &pack(&data)?))
}
