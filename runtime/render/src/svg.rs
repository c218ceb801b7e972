//! The table as an SVG picture: the viewer's seat at the bottom, each seat laid out once in its own
//! frame and turned a quarter per seat around the centre (three players: the next seat on the
//! right, the one before on the left, the top empty).

use std::fmt::Write as _;

use super::board::{Board, LastAction, Meld, MeldKind, RoundResult};
use super::options::{Options, TileMode};
use super::tiles::{self, Place, UsedTiles};
use rinshan_engine::{Tile, TileType};

/// The picture is SIZE by SIZE.
pub const SIZE: f32 = 960.0;
const C: f32 = SIZE / 2.0;
// Tile sizes: hand, meld, river, centre (dora).
const HAND: (f32, f32) = (38.0, 52.0);
const MELD: (f32, f32) = (32.0, 44.0);
const RIVER: (f32, f32) = (30.0, 40.0);
const SMALL: (f32, f32) = (24.0, 32.0);
const BOX: f32 = 250.0;
const HAND_X: f32 = 110.0;
/// Space between the hand's last place and the melds, and between two melds.
const MELD_GAP: f32 = 12.0;
const HAND_Y: f32 = SIZE - HAND.1 - 14.0;
const RIVER_X: f32 = C - 3.0 * RIVER.0;
const RIVER_Y: f32 = C + BOX / 2.0 + 8.0;
const FONT: &str = "DejaVu Sans, Verdana, Arial, sans-serif";

const WINDS: [&str; 4] = ["East", "South", "West", "North"];
const WIND_LETTERS: [&str; 4] = ["E", "S", "W", "N"];

/// The name of the engine's round `round` at a table of `seats`: `East 1`.
pub fn round_name(round: u32, seats: u32) -> String {
    let seats = seats.max(1);
    format!("{} {}", WINDS[(round / seats % 4) as usize], round % seats + 1)
}

impl Board {
    /// The round's name: `East 1`.
    pub fn round_name(&self) -> String {
        round_name(self.round, self.seats)
    }
}

/// A seat's wind letter in the current round.
fn wind(board: &Board, seat: u32) -> &'static str {
    let n = board.seats.max(1);
    WIND_LETTERS[((seat + n - board.dealer % n) % n) as usize]
}

/// The quarter turns from the bottom of the seat `rel` places after the viewer: three players
/// leave the top (across) empty, the seat before sitting on the left.
fn quarter_turns(rel: u32, seats: u32) -> u32 {
    if seats == 3 && rel == 2 {
        3
    } else {
        rel
    }
}

fn name(board: &Board, seat: u32) -> String {
    escape(&seat_name(&board.names, seat))
}

/// What a seat is called: its player's name, or `seat N` where the name is empty.
pub fn seat_name(names: &[String; 4], seat: u32) -> String {
    match names.get(seat as usize) {
        Some(n) if !n.is_empty() => n.clone(),
        _ => format!("seat {seat}"),
    }
}

/// Text safe inside XML.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The board as a standalone SVG document (the faces it uses in its own `<defs>`), or, with
/// `opts.defs == false`, a fragment whose faces come from a page-wide sprite ([`sprite`]).
pub fn svg(board: &Board, opts: &Options) -> String {
    let mut body = String::with_capacity(48 * 1024);
    let mut used = UsedTiles::default();
    let seats = board.seats.clamp(1, 4);
    let pov = opts.pov % seats;
    let _ = write!(
        body,
        r##"<rect width="{SIZE}" height="{SIZE}" fill="#1d5b3c"/><rect x="{b}" y="{b}" width="{BOX}" height="{BOX}" rx="10" fill="#123d28" stroke="#0b2a1b"/>"##,
        b = C - BOX / 2.0
    );
    for rel in 0..seats {
        let seat = (pov + rel) % seats;
        let _ = write!(
            body,
            r#"<g class="seat" data-seat="{seat}" transform="rotate({} {C} {C})">"#,
            -90.0 * quarter_turns(rel, seats) as f32
        );
        // A round's end shows the winners' hands, or at a draw the tenpai ones.
        let shown = board
            .result
            .as_ref()
            .is_some_and(|r| r.tenpai[seat as usize] || r.wins.iter().any(|w| w.seat == seat));
        let face_up = opts.reveal || seat == pov || shown;
        seat_frame(&mut body, &mut used, board, seat, face_up);
        body.push_str("</g>");
    }
    centre(&mut body, &mut used, board);
    if let Some(r) = &board.result {
        result_panel(&mut body, &mut used, board, r);
    }
    let mut out = String::with_capacity(body.len() + 4096);
    let _ = write!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {SIZE} {SIZE}" width="{SIZE}" height="{SIZE}" font-family="{FONT}" font-weight="bold" data-round="{}" data-honba="{}" data-sticks="{}" data-actor="{}" data-pov="{pov}" data-tiles="{}">"#,
        board.round, board.honba, board.sticks, board.current, opts.tiles
    );
    if opts.defs {
        out.push_str("<defs>");
        used.write_defs(&mut out, opts.tiles);
        out.push_str("</defs>");
    }
    out.push_str(&body);
    out.push_str("</svg>");
    out
}

/// Every tile's symbol in `mode`, in a hidden SVG, for a page that shows boards drawn with
/// `defs: false` (swapping the sprite switches the mode of every board on the page).
pub fn sprite(mode: TileMode) -> String {
    let mut out = String::from(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="0" height="0" style="position:absolute" aria-hidden="true"><defs>"#,
    );
    UsedTiles::all().write_defs(&mut out, mode);
    out.push_str("</defs></svg>");
    out
}

fn place(
    x: f32,
    y: f32,
    size: (f32, f32),
    sideways: bool,
    seat: u32,
    zone: &'static str,
    flags: &'static str,
) -> Place<'static> {
    Place {
        x,
        y,
        w: size.0,
        h: size.1,
        sideways,
        seat,
        zone,
        flags,
    }
}

/// One seat in the bottom seat's frame: hand, melds, river, and its corner of the centre box.
fn seat_frame(out: &mut String, used: &mut UsedTiles, board: &Board, seat: u32, face_up: bool) {
    let s = seat as usize;
    let acting = board.current == seat && board.result.is_none() && !board.over;
    if acting {
        let _ = write!(
            out,
            r##"<rect class="actor" x="{}" y="{}" width="{}" height="{}" rx="8" fill="none" stroke="#ffd54a" stroke-width="4"/>"##,
            HAND_X - 8.0,
            HAND_Y - 8.0,
            14.0 * HAND.0 + 28.0,
            HAND.1 + 16.0
        );
    }
    // Hand, then the drawn tile set apart.
    let mut x = HAND_X;
    for &t in &board.hands[s] {
        tiles::draw(
            out,
            used,
            face_up.then_some(t),
            &place(x, HAND_Y, HAND, false, seat, "hand", ""),
        );
        x += HAND.0;
    }
    if let Some(t) = board.drawn[s] {
        tiles::draw(
            out,
            used,
            face_up.then_some(t),
            &place(x + 10.0, HAND_Y, HAND, false, seat, "drawn", ""),
        );
    }
    // Melds beside the hand, past the drawn tile's place, as on a real table: the first meld
    // rightmost, each later one to the left of it (nearer the hand).
    let width = |m: &Meld| -> f32 {
        (0..m.tiles.len())
            .map(|k| if Some(k) == m.called { MELD.1 } else { MELD.0 })
            .sum()
    };
    let melds_start = HAND_X + (board.hands[s].len() + 1) as f32 * HAND.0 + 10.0 + MELD_GAP;
    let melds_width: f32 = board.melds[s].iter().map(|m| width(m) + MELD_GAP).sum();
    let mut right = melds_start + melds_width - MELD_GAP;
    let bottom = SIZE - 14.0;
    let n_melds = board.melds[s].len();
    for (i, m) in board.melds[s].iter().enumerate() {
        let last = i + 1 == n_melds && board.last == Some(LastAction::Meld(seat));
        let width = width(m);
        let mut x = right - width;
        if last {
            let _ = write!(
                out,
                r##"<rect class="last" x="{}" y="{}" width="{}" height="{}" rx="5" fill="none" stroke="#ff8a3d" stroke-width="3"/>"##,
                x - 4.0,
                bottom - 2.0 * MELD.0 - 6.0,
                width + 8.0,
                2.0 * MELD.0 + 10.0
            );
        }
        for (k, &t) in m.tiles.iter().enumerate() {
            let called = Some(k) == m.called;
            // A closed kan shows its two outer tiles face down.
            let hidden = m.kind == MeldKind::ClosedKan && (k == 0 || k == 3);
            let tile = (!hidden).then_some(t);
            if called {
                tiles::draw(
                    out,
                    used,
                    tile,
                    &place(x, bottom - MELD.0, MELD, true, seat, "meld", "called"),
                );
                if let Some(a) = m.added {
                    tiles::draw(
                        out,
                        used,
                        Some(a),
                        &place(x, bottom - 2.0 * MELD.0, MELD, true, seat, "meld", "added"),
                    );
                }
                x += MELD.1;
            } else {
                tiles::draw(
                    out,
                    used,
                    tile,
                    &place(x, bottom - MELD.1, MELD, false, seat, "meld", ""),
                );
                x += MELD.0;
            }
        }
        right -= width + MELD_GAP;
    }
    // Norths set aside (kita), right of the river's first row.
    for k in 0..board.kita[s] {
        tiles::draw(
            out,
            used,
            Some(Tile::plain(TileType::NORTH)),
            &place(
                RIVER_X + 6.0 * RIVER.0 + 14.0 + k as f32 * RIVER.0,
                RIVER_Y,
                RIVER,
                false,
                seat,
                "kita",
                "",
            ),
        );
    }
    // River: rows of six; the riichi discard lies sideways.
    let n = board.rivers[s].len();
    let (mut col, mut row, mut x) = (0, 0, RIVER_X);
    for (i, r) in board.rivers[s].iter().enumerate() {
        if col == 6 && row < 3 {
            col = 0;
            row += 1;
            x = RIVER_X;
        }
        let y = RIVER_Y + row as f32 * RIVER.1;
        let last = i + 1 == n && board.last == Some(LastAction::Discard(seat));
        let flags = match (r.riichi, r.called, r.tsumogiri) {
            (true, true, _) => "riichi called",
            (true, false, true) => "riichi tsumogiri",
            (true, false, false) => "riichi",
            (false, true, _) => "called",
            (false, false, true) => "tsumogiri",
            _ => "",
        };
        let w = if r.riichi { RIVER.1 } else { RIVER.0 };
        let ty = if r.riichi { y + RIVER.1 - RIVER.0 } else { y };
        tiles::draw(
            out,
            used,
            Some(r.tile),
            &place(x, ty, RIVER, r.riichi, seat, "river", flags),
        );
        if r.tsumogiri {
            // A small grey corner mark: drawn from the wall and thrown straight away.
            let _ = write!(
                out,
                r##"<path d="M{} {}h8l-8 8z" fill="#8d8d8d" class="tsumogiri"/>"##,
                x + 1.0,
                ty + 1.0
            );
        }
        if last {
            let _ = write!(
                out,
                r##"<rect class="last" x="{}" y="{}" width="{w}" height="{}" rx="4" fill="none" stroke="#ff8a3d" stroke-width="3"/>"##,
                x - 1.5,
                ty - 1.5,
                if r.riichi { RIVER.0 + 3.0 } else { RIVER.1 + 3.0 }
            );
        }
        x += w;
        col += 1;
    }
    // The seat's edge of the centre box: wind, points, dealer, riichi stick, name.
    let edge = C + BOX / 2.0;
    if acting {
        let _ = write!(
            out,
            r##"<rect x="{}" y="{}" width="{}" height="5" rx="2.5" fill="#ffd54a"/>"##,
            C - 100.0,
            edge - 7.0,
            200.0
        );
    }
    let _ = write!(
        out,
        r##"<text x="{C}" y="{}" font-size="18" fill="#f5f1e3" text-anchor="middle" class="points" data-seat="{seat}">{} {}</text>"##,
        edge - 10.0,
        wind(board, seat),
        board.scores[s]
    );
    if seat == board.dealer % 4 {
        let _ = write!(
            out,
            r##"<g class="dealer"><rect x="{}" y="{}" width="18" height="18" rx="4" fill="#c62828"/><text x="{}" y="{}" font-size="13" fill="#fff" text-anchor="middle">D</text></g>"##,
            C - 74.0,
            edge - 26.0,
            C - 65.0,
            edge - 12.5
        );
    }
    if board.riichi[s] {
        let _ = write!(
            out,
            r##"<g class="riichi-stick"><rect x="{}" y="{}" width="90" height="8" rx="4" fill="#fafafa" stroke="#555"/><circle cx="{C}" cy="{}" r="3" fill="#d32f2f"/></g>"##,
            C - 45.0,
            edge - 40.0,
            edge - 36.0
        );
    }
    let _ = write!(
        out,
        r##"<text x="{HAND_X}" y="{}" font-size="14" fill="#d9e8dc" class="name">{}</text>"##,
        HAND_Y - 12.0,
        name(board, seat)
    );
}

/// The centre box: round, honba, sticks, tiles left, dora indicators.
fn centre(out: &mut String, used: &mut UsedTiles, board: &Board) {
    let _ = write!(
        out,
        r##"<text x="{C}" y="{}" font-size="24" fill="#fff" text-anchor="middle" class="round">{}</text><text x="{C}" y="{}" font-size="13" fill="#cfe3d4" text-anchor="middle">Honba {} · Sticks {}</text><text x="{C}" y="{}" font-size="13" fill="#cfe3d4" text-anchor="middle" class="left">Tiles left {}</text>"##,
        C - 40.0,
        board.round_name(),
        C - 18.0,
        board.honba,
        board.sticks,
        C + 52.0,
        board.tiles_left
    );
    let x0 = C - 2.5 * SMALL.0;
    for i in 0..5 {
        let t = board.dora.get(i).copied();
        tiles::draw(
            out,
            used,
            t,
            &place(x0 + i as f32 * SMALL.0, C - 6.0, SMALL, false, 4, "dora", ""),
        );
    }
}

/// The round's end over the table: who won what, or how it was drawn, and the payments.
fn result_panel(out: &mut String, used: &mut UsedTiles, board: &Board, r: &RoundResult) {
    let mut lines: Vec<(String, u32, &str)> = Vec::new();
    for w in &r.wins {
        let how = match w.from {
            Some(f) => format!("Ron from {} ({})", name(board, f), wind(board, f)),
            None => "Tsumo".to_string(),
        };
        lines.push((
            format!("{} ({}) wins: {how}", name(board, w.seat), wind(board, w.seat)),
            22,
            "#ffe082",
        ));
        lines.push((escape(&w.yaku.join(", ")), 16, "#ffffff"));
        let value = if w.yakuman > 0 {
            format!("Yakuman ×{}", w.yakuman)
        } else {
            format!(
                "{} han {} fu  (dora {}, red {}, ura {})",
                w.han, w.fu, w.dora, w.aka, w.ura
            )
        };
        lines.push((value, 16, "#cfe3d4"));
    }
    if let Some(d) = r.draw {
        lines.push((draw_name(d).to_string(), 22, "#ffe082"));
        let tenpai: Vec<String> = (0..4u32)
            .filter(|&p| r.tenpai[p as usize])
            .map(|p| name(board, p))
            .collect();
        if d == rinshan_engine::env::DrawKind::Exhaustive || d == rinshan_engine::env::DrawKind::Nagashi {
            let t = if tenpai.is_empty() {
                "nobody".to_string()
            } else {
                tenpai.join(", ")
            };
            lines.push((format!("Tenpai: {t}"), 16, "#ffffff"));
        }
    }
    // The payments (and at a game's end the uma and standing) in one column per seat.
    let mut columns: Vec<[String; 4]> = vec![std::array::from_fn(|p| {
        format!("{} ({})", name(board, p as u32), wind(board, p as u32))
    })];
    columns.push(r.deltas.map(|d| format!("{d:+}")));
    if let (Some(ranks), Some(scores)) = (r.ranks, r.final_scores) {
        lines.push(("Game over".to_string(), 20, "#ffe082"));
        if let Some(uma) = r.uma {
            columns.push(uma.map(|u| format!("uma {u:+}")));
        }
        columns.push(std::array::from_fn(|p| format!("{}. {}", ranks[p] + 1, scores[p])));
    }
    let height = 48.0
        + lines.iter().map(|l| l.1 as f32 + 12.0).sum::<f32>()
        + 24.0 * columns.len() as f32
        + if r.ura.is_empty() { 0.0 } else { 44.0 };
    let (w, x, y) = (700.0, C - 350.0, C - height / 2.0);
    let _ = write!(
        out,
        r##"<g class="result" data-deltas="{}"><rect x="{x}" y="{y}" width="{w}" height="{height}" rx="12" fill="#0d2a1c" fill-opacity="0.93" stroke="#ffd54a" stroke-width="2"/>"##,
        r.deltas.map(|d| d.to_string()).join(",")
    );
    let mut ty = y + 24.0;
    for (text, size, fill) in &lines {
        ty += *size as f32 + 6.0;
        let _ = write!(
            out,
            r#"<text x="{C}" y="{ty}" font-size="{size}" fill="{fill}" text-anchor="middle">{text}</text>"#
        );
        ty += 6.0;
    }
    ty += 6.0;
    let column = w / board.seats.clamp(1, 4) as f32;
    for (row, cells) in columns.iter().enumerate() {
        ty += 24.0;
        let (size, fill) = if row == 0 { (15, "#cfe3d4") } else { (17, "#ffffff") };
        for (p, cell) in cells.iter().enumerate().take(board.seats as usize) {
            let _ = write!(
                out,
                r#"<text x="{}" y="{ty}" font-size="{size}" fill="{fill}" text-anchor="middle">{cell}</text>"#,
                x + column / 2.0 + column * p as f32
            );
        }
    }
    if !r.ura.is_empty() {
        let _ = write!(
            out,
            r##"<text x="{}" y="{}" font-size="14" fill="#cfe3d4" text-anchor="end">Ura</text>"##,
            C - 8.0 - 2.5 * SMALL.0,
            ty + 28.0
        );
        for (i, &t) in r.ura.iter().enumerate() {
            tiles::draw(
                out,
                used,
                Some(t),
                &place(
                    C - 2.5 * SMALL.0 + i as f32 * SMALL.0,
                    ty + 8.0,
                    SMALL,
                    false,
                    4,
                    "ura",
                    "",
                ),
            );
        }
    }
    out.push_str("</g>");
}

fn draw_name(d: rinshan_engine::env::DrawKind) -> &'static str {
    use rinshan_engine::env::DrawKind as D;
    match d {
        D::Exhaustive => "Exhaustive draw",
        D::Nagashi => "Nagashi mangan",
        D::Kyuushu => "Abortive draw: nine terminals",
        D::FourRiichi => "Abortive draw: four riichi",
        D::TripleRon => "Abortive draw: triple ron",
        D::FourKans => "Abortive draw: four kans",
        D::FourWinds => "Abortive draw: four winds",
    }
}
