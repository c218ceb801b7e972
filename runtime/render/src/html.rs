//! A whole game as one self-contained HTML page: every decision's board (drawn once, mode-free:
//! the tile symbols come from a sprite the page swaps), gzipped and inlined with a small stepping
//! script, like mjai-reviewer's single-file reports.

use std::io::Write as _;

use base64::Engine as _;
use serde::Serialize;

use super::board::Board;
use super::options::{Options, TileMode};
use super::svg::{escape, seat_name, sprite, svg};
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::position::round_replay;

const PAGE: &str = include_str!("replay.html");

#[derive(Serialize)]
struct Frame {
    caption: String,
    svg: String,
}

#[derive(Serialize)]
struct RoundStart {
    name: String,
    frame: usize,
}

#[derive(Serialize)]
struct Data {
    rounds: Vec<RoundStart>,
    frames: Vec<Frame>,
    sprites: Vec<(String, String)>,
}

/// The boards of every decision of `game` (a tenhou.net/6 log), with a result board after each
/// round.
pub fn frames(game: &Game) -> Result<Vec<(String, Board)>, String> {
    let mut out = Vec::new();
    for r in 0..game.rounds.len() {
        let (positions, end) = round_replay(game, r)?;
        let name = game.names.clone();
        for p in &positions {
            let mut board = Board::from_state(&p.state, game.variant);
            board.names = name.clone();
            let who = seat_name(&name, p.seat);
            let caption = format!(
                "{}, {} honba: decision {} of {}, {who}: {}",
                board.round_name(),
                board.honba,
                p.step + 1,
                positions.len(),
                p.what
            );
            out.push((caption, board));
        }
        if let (Some(last), Some(end)) = (positions.last(), end) {
            if let Some(mut board) = Board::logged_round_end(last, &end) {
                board.names = name.clone();
                out.push((format!("{}, {} honba: result", board.round_name(), board.honba), board));
            }
        }
    }
    Ok(out)
}

/// `data` as JSON, gzipped and in base64: how a self-contained page carries its boards (its
/// script unpacks them with the browser's `DecompressionStream`).
pub fn pack(data: &impl Serialize) -> Result<String, String> {
    let json = serde_json::to_vec(data).map_err(|e| e.to_string())?;
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(&json).map_err(|e| e.to_string())?;
    let packed = gz.finish().map_err(|e| e.to_string())?;
    Ok(base64::engine::general_purpose::STANDARD.encode(packed))
}

/// The replay page of `game`.
pub fn replay_html(game: &Game, pov: u32) -> Result<String, String> {
    let boards = frames(game)?;
    let opts = Options {
        tiles: TileMode::En,
        pov,
        reveal: true,
        defs: false,
    };
    let mut rounds = Vec::new();
    let mut frames = Vec::with_capacity(boards.len());
    let mut last_round = None;
    for (caption, board) in &boards {
        let key = (board.round, board.honba);
        if last_round != Some(key) {
            last_round = Some(key);
            rounds.push(RoundStart {
                name: format!("{} ({} honba)", board.round_name(), board.honba),
                frame: frames.len(),
            });
        }
        frames.push(Frame {
            caption: caption.clone(),
            svg: svg(board, &opts),
        });
    }
    let data = Data {
        rounds,
        frames,
        sprites: TileMode::ALL.iter().map(|&m| (m.to_string(), sprite(m))).collect(),
    };
    let b64 = pack(&data)?;
    let title = escape(&format!(
        "rinshan replay: {}",
        game.path.rsplit('/').next().unwrap_or(&game.path)
    ));
    Ok(PAGE.replace("{{TITLE}}", &title).replace("{{DATA}}", &b64))
}
