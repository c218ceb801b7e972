//! Board pictures: real logs are the oracle for what the board shows (the dealt hands, the river
//! with its riichi and tsumogiri marks, the melds with their called tile), every tile names itself
//! in `data-` attributes, the markup of fixed positions and each tile mode's symbols are pinned
//! by snapshots, and every picture rasterises.

use std::collections::BTreeSet;
use std::path::PathBuf;

use rinshan_engine::{Tile, Variant};
use rinshan_logs::tenhou::log::{collect_files, read_game, Discard, Draw, Game, Rel};
use rinshan_logs::tenhou::position::{round_replay, Position, RoundEnd};
use rinshan_render::{Board, MeldKind, Options, TileMode};

fn games() -> Vec<Game> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/tenhou");
    collect_files(&[dir])
        .expect("the logs")
        .iter()
        .map(|p| read_game(p).expect("a log"))
        .collect()
}

/// A meld as the log writes it: its tiles, and the called tile with its source.
type LoggedMeld = (Vec<Tile>, Option<(Tile, Rel)>);

type Replayed = (usize, usize, Vec<Position>, Option<RoundEnd>);

fn rounds(games: &[Game]) -> Vec<Replayed> {
    let mut out = Vec::new();
    for (g, game) in games.iter().enumerate() {
        for r in 0..game.rounds.len() {
            let (ps, end) = round_replay(game, r).expect("the round replays");
            out.push((g, r, ps, end));
        }
    }
    out
}

fn sorted(mut v: Vec<Tile>) -> Vec<Tile> {
    v.sort();
    v
}

/// Each `<g class="tile">` of an SVG: (data-tile, data-seat, data-zone, data-flags, has a title).
fn tiles_of(svg: &str) -> Vec<(String, String, String, String, bool)> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is well-formed XML");
    doc.descendants()
        .filter(|n| n.attribute("class") == Some("tile"))
        .map(|n| {
            let a = |k: &str| n.attribute(k).unwrap_or("").to_string();
            let titled = n
                .children()
                .any(|c| c.has_tag_name("title") && !c.text().unwrap_or("").is_empty());
            (a("data-tile"), a("data-seat"), a("data-zone"), a("data-flags"), titled)
        })
        .collect()
}

fn revealed(pov: u32) -> Options {
    Options {
        tiles: TileMode::En,
        pov,
        reveal: true,
        defs: true,
    }
}

#[test]
fn the_dealt_hands_are_the_logged_ones() {
    let games = games();
    for (g, r, ps, _) in rounds(&games) {
        let round = &games[g].rounds[r];
        let board = Board::from_state(&ps[0].state, Variant::Red);
        let dealer = round.dealer();
        for p in 0..4 {
            let mut shown = board.hands[p].clone();
            shown.extend(board.drawn[p]);
            let mut dealt = round.hands[p].clone();
            if p == dealer {
                let Some(Draw::Tile(t)) = round.draws[p].first() else {
                    panic!("the dealer draws first")
                };
                dealt.push(*t);
                assert_eq!(
                    board.drawn[p],
                    Some(*t),
                    "{} round {r}: the dealer's draw is set apart",
                    games[g].path
                );
            }
            assert_eq!(sorted(shown), sorted(dealt), "{} round {r} seat {p}", games[g].path);
        }
        // The SVG shows the same tiles, face up for every seat when revealed.
        let svg = rinshan_render::svg(&board, &revealed(0));
        for p in 0..4 {
            let mut drawn: Vec<String> = tiles_of(&svg)
                .into_iter()
                .filter(|t| t.1 == p.to_string() && (t.2 == "hand" || t.2 == "drawn"))
                .map(|t| t.0)
                .collect();
            drawn.sort();
            let mut want: Vec<String> = board.hands[p].iter().chain(&board.drawn[p]).map(|t| t.name()).collect();
            want.sort();
            assert_eq!(drawn, want, "seat {p}");
        }
    }
}

#[test]
fn rivers_and_melds_follow_the_log() {
    let games = games();
    let (mut riichi_seen, mut called_seen, mut kans_seen) = (0, 0, 0);
    let mut draws_seen = 0;
    for (g, r, ps, end) in rounds(&games) {
        let round = &games[g].rounds[r];
        let last = ps.last().expect("a round has decisions");
        let board = Board::from_state(&last.state, Variant::Red);
        // A round the wall ended shows every logged discard, the last one included.
        let drawn_out = end.as_ref().and_then(|e| Board::logged_round_end(last, e)).filter(|b| {
            b.result
                .as_ref()
                .is_some_and(|r| r.draw == Some(rinshan_engine::env::DrawKind::Exhaustive))
        });
        if let Some(end_board) = &drawn_out {
            draws_seen += 1;
            for p in 0..4 {
                let logged = round.discards[p]
                    .iter()
                    .filter(|d| matches!(d, Discard::Tile(_) | Discard::Tsumogiri | Discard::Riichi(_)))
                    .count();
                assert_eq!(
                    end_board.rivers[p].len(),
                    logged,
                    "{} round {r} seat {p}",
                    games[g].path
                );
                let held = end_board.hands[p].len() + end_board.drawn[p].iter().count() + 3 * end_board.melds[p].len();
                assert_eq!(
                    held, 13,
                    "{} round {r} seat {p}: 13 tiles after the last discard",
                    games[g].path
                );
            }
        }
        let path = &games[g].path;
        for p in 0..4 {
            // The log's discards in order: (named tile, riichi, tsumogiri).
            let logged: Vec<(Option<Tile>, bool, bool)> = round.discards[p]
                .iter()
                .filter_map(|d| match *d {
                    Discard::Tile(t) => Some((Some(t), false, false)),
                    Discard::Tsumogiri => Some((None, false, true)),
                    Discard::Riichi(t) => Some((t, true, t.is_none())),
                    _ => None,
                })
                .collect();
            let river = &board.rivers[p];
            // The last decision may be the round's last discard.
            assert!(
                river.len() + 1 >= logged.len() && river.len() <= logged.len(),
                "{path} round {r} seat {p}"
            );
            for (i, (rt, (tile, riichi, tsumogiri))) in river.iter().zip(&logged).enumerate() {
                if let Some(t) = tile {
                    assert_eq!(rt.tile, *t, "{path} round {r} seat {p} discard {i}");
                }
                assert_eq!(
                    (rt.riichi, rt.tsumogiri),
                    (*riichi, *tsumogiri),
                    "{path} round {r} seat {p} discard {i}"
                );
                riichi_seen += usize::from(rt.riichi);
            }
            // The log's melds in the order they were made.
            let mut logged_melds: Vec<LoggedMeld> = Vec::new();
            for i in 0..round.draws[p].len().max(round.discards[p].len()) {
                match round.draws[p].get(i) {
                    Some(Draw::Chi { called, own }) => {
                        logged_melds.push((vec![*called, own[0], own[1]], Some((*called, Rel::Left))))
                    }
                    Some(Draw::Pon { called, own, from }) => {
                        logged_melds.push((vec![*called, own[0], own[1]], Some((*called, *from))))
                    }
                    Some(Draw::OpenKan { called, own, from }) => {
                        logged_melds.push((vec![*called, own[0], own[1], own[2]], Some((*called, *from))))
                    }
                    _ => {}
                }
                if let Some(Discard::ClosedKan { tiles }) = round.discards[p].get(i) {
                    logged_melds.push((tiles.to_vec(), None));
                }
            }
            let melds = &board.melds[p];
            assert!(melds.len() <= logged_melds.len(), "{path} round {r} seat {p}");
            for (m, (tiles, called)) in melds.iter().zip(&logged_melds) {
                let mut shown = m.tiles.clone();
                if m.kind == MeldKind::AddedKan {
                    shown.extend(m.added);
                    shown.pop();
                }
                let base: Vec<Tile> = tiles.clone();
                if m.kind != MeldKind::AddedKan {
                    assert_eq!(sorted(shown), sorted(base), "{path} round {r} seat {p}");
                }
                match called {
                    Some((t, from)) => {
                        let slot = m.called.expect("a called meld shows its called tile");
                        assert_eq!(m.tiles[slot], *t, "{path} round {r} seat {p}");
                        // Tenhou's convention: the called tile points at its source.
                        let want = match from {
                            Rel::Left => 0,
                            Rel::Across => 1,
                            Rel::Right => m.tiles.len() - 1,
                        };
                        assert_eq!(slot, want, "{path} round {r} seat {p}: {m:?}");
                        called_seen += 1;
                    }
                    None => {
                        assert_eq!(m.kind, MeldKind::ClosedKan);
                        assert_eq!(m.called, None);
                        kans_seen += 1;
                    }
                }
            }
        }
        // One indicator per kan, plus the first.
        let kans: usize = board
            .melds
            .iter()
            .flatten()
            .filter(|m| matches!(m.kind, MeldKind::OpenKan | MeldKind::ClosedKan | MeldKind::AddedKan))
            .count();
        assert!(
            board.dora.len() == kans + 1 || board.dora.len() == kans,
            "{path} round {r}: {} dora, {kans} kans",
            board.dora.len()
        );
        assert_eq!(board.dora.first(), round.dora.first(), "{path} round {r}");
    }
    assert!(
        riichi_seen > 20 && called_seen > 50 && kans_seen > 0,
        "{riichi_seen} {called_seen} {kans_seen}"
    );
    assert!(draws_seen > 3, "{draws_seen} drawn rounds");
}

/// Each tile of seat `seat` in its own frame (before the seat's quarter turn): (zone, left x,
/// right x), a sideways tile as wide as a standing one is tall.
fn seat_tiles(svg: &str, seat: u32) -> Vec<(String, f32, f32)> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is well-formed XML");
    let group = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("seat") && n.attribute("data-seat") == Some(&seat.to_string()));
    let Some(group) = group else {
        return Vec::new();
    };
    group
        .descendants()
        .filter(|n| n.attribute("class") == Some("tile"))
        .map(|n| {
            let transform = n.attribute("transform").unwrap_or("");
            let x: f32 = transform
                .trim_start_matches("translate(")
                .split(' ')
                .next()
                .and_then(|x| x.parse().ok())
                .expect("a translated tile");
            let face = n.children().find(|c| c.has_tag_name("use") || c.has_tag_name("rect"));
            let size = |k: &str| face.and_then(|f| f.attribute(k)).and_then(|v| v.parse::<f32>().ok());
            let width = if transform.contains("rotate") {
                size("height")
            } else {
                size("width")
            };
            let zone = n.attribute("data-zone").unwrap_or("").to_string();
            (zone, x, x + width.unwrap_or(0.0))
        })
        .collect()
}

#[test]
fn melds_lie_beside_their_hand() {
    let games = games();
    let mut seats_with_melds = 0;
    for (g, r, ps, _) in rounds(&games) {
        let last = ps.last().expect("a round has decisions");
        let board = Board::from_state(&last.state, Variant::Red);
        let svg = rinshan_render::svg(&board, &revealed(0));
        for seat in 0..4u32 {
            if board.melds[seat as usize].is_empty() {
                continue;
            }
            seats_with_melds += 1;
            let tiles = seat_tiles(&svg, seat);
            let zone_span = |zones: &[&str]| {
                let xs: Vec<(f32, f32)> = tiles
                    .iter()
                    .filter(|t| zones.contains(&t.0.as_str()))
                    .map(|t| (t.1, t.2))
                    .collect();
                let lo = xs.iter().map(|x| x.0).fold(f32::INFINITY, f32::min);
                let hi = xs.iter().map(|x| x.1).fold(f32::NEG_INFINITY, f32::max);
                (lo, hi)
            };
            let (_, hand_end) = zone_span(&["hand"]);
            let (melds_start, _) = zone_span(&["meld"]);
            let (_, with_drawn_end) = zone_span(&["hand", "drawn"]);
            let at = format!("{} round {r} seat {seat}", games[g].path);
            // Right of the hand and of its drawn tile, with at most the drawn tile's place and
            // two gaps between (about one tile and a half).
            assert!(melds_start >= with_drawn_end, "{at}: a meld overlaps the hand");
            assert!(
                melds_start - hand_end <= 1.6 * 38.0,
                "{at}: the melds start {} after the hand's last tile",
                melds_start - hand_end
            );
        }
    }
    assert!(seats_with_melds > 50, "{seats_with_melds} seats with melds");
}

#[test]
fn every_tile_names_itself() {
    let names: BTreeSet<String> = (0..37u8)
        .filter_map(Tile::from_value)
        .map(|t| t.name())
        .chain(["back".to_string()])
        .collect();
    let games = games();
    let all = rounds(&games);
    for (_, _, ps, _) in all.iter().take(12) {
        for (i, p) in ps.iter().enumerate().step_by(7) {
            let board = Board::from_state(&p.state, Variant::Red);
            let pov = (i % 4) as u32;
            let svg = rinshan_render::svg(
                &board,
                &Options {
                    reveal: false,
                    ..revealed(pov)
                },
            );
            let tiles = tiles_of(&svg);
            for (tile, seat, zone, _, titled) in &tiles {
                assert!(names.contains(tile), "{tile}");
                assert!(titled, "{tile} has a title");
                assert!(
                    ["hand", "drawn", "meld", "river", "dora", "ura"].contains(&zone.as_str()),
                    "{zone}"
                );
                // Hidden hands stay hidden; the viewer's shows.
                if zone == "hand" || zone == "drawn" {
                    assert_eq!(*seat == pov.to_string(), tile != "back", "seat {seat} {zone} {tile}");
                }
            }
            let in_hand = |s: u32| {
                tiles
                    .iter()
                    .filter(|t| t.1 == s.to_string() && (t.2 == "hand" || t.2 == "drawn"))
                    .count()
            };
            for s in 0..4u32 {
                let melds = board.melds[s as usize].len();
                let n = in_hand(s) + 3 * melds;
                assert!(n == 13 || n == 14, "seat {s}: {n} tiles");
            }
            let dora = tiles.iter().filter(|t| t.2 == "dora" && t.0 != "back").count();
            assert_eq!(dora, board.dora.len());
        }
    }
}

/// Markup with a line per tile, so a snapshot diff reads tile by tile.
fn lines(svg: &str) -> String {
    svg.replace("<g class=\"tile\"", "\n<g class=\"tile\"")
        .replace("<g class=\"seat\"", "\n<g class=\"seat\"")
}

/// A tile symbol sheet with the face art (FluffyStuff's paths, pinned by their files) cut out.
fn symbols(sprite: &str) -> String {
    let mut out = String::new();
    let mut rest = sprite;
    while let Some(i) = rest.find("<svg x=") {
        let head = &rest[..i];
        let Some(end) = rest[i..].find("</svg>") else { break };
        let open_end = rest[i..].find('>').map_or(0, |e| e + 1);
        out.push_str(head);
        out.push_str(&rest[i..i + open_end]);
        out.push_str("…art…</svg>");
        rest = &rest[i + end + "</svg>".len()..];
    }
    out.push_str(rest);
    out.replace("<symbol", "\n<symbol")
}

#[test]
fn snapshots_of_fixed_positions_and_tile_modes() {
    let games = games();
    let all = rounds(&games);
    type Pick = Box<dyn Fn(&Board) -> bool>;
    let cases: Vec<(&str, Pick)> = vec![
        ("start", Box::new(|b| b.rivers.iter().all(Vec::is_empty))),
        (
            "riichi_and_calls",
            Box::new(|b| b.riichi.iter().any(|&r| r) && b.melds.iter().any(|m| !m.is_empty())),
        ),
        (
            "added_kan",
            Box::new(|b| b.melds.iter().flatten().any(|m| m.kind == MeldKind::AddedKan)),
        ),
        (
            "closed_kan",
            Box::new(|b| b.melds.iter().flatten().any(|m| m.kind == MeldKind::ClosedKan)),
        ),
        (
            "claim_prompt",
            Box::new(|b| b.claim.is_some() && b.melds.iter().any(|m| m.len() >= 2)),
        ),
    ];
    for (name, pick) in &cases {
        let board = all
            .iter()
            .flat_map(|(g, _, ps, _)| ps.iter().map(move |p| (*g, p)))
            .map(|(g, p)| {
                let mut b = Board::from_state(&p.state, Variant::Red);
                b.names = games[g].names.clone();
                b
            })
            .find(|b| pick(b))
            .unwrap_or_else(|| panic!("no position for {name}"));
        let svg = rinshan_render::svg(
            &board,
            &Options {
                defs: false,
                reveal: false,
                ..revealed(1)
            },
        );
        insta::assert_snapshot!(format!("board_{name}"), lines(&svg));
    }
    // Round ends: a riichi hand won by ron (ura shown), and a drawn round.
    let mut ends = all.iter().filter_map(|(g, _, ps, end)| {
        let (last, end) = (ps.last()?, end.as_ref()?);
        let mut b = Board::logged_round_end(last, end)?;
        b.names = games[*g].names.clone();
        Some(b)
    });
    let ron = ends
        .clone()
        .find(|b| {
            b.result
                .as_ref()
                .is_some_and(|r| r.wins.iter().any(|w| w.from.is_some()) && !r.ura.is_empty())
        })
        .expect("a riichi ron");
    let draw = ends
        .find(|b| b.result.as_ref().is_some_and(|r| r.draw.is_some()))
        .expect("a drawn round");
    for (name, b) in [("ron_with_ura", &ron), ("drawn_round", &draw)] {
        let r = b.result.as_ref().expect("a result");
        // Payments balance once the riichi sticks a winner takes from the table are counted.
        let sticks_taken = if r.wins.is_empty() { 0 } else { 1000 * b.sticks as i32 };
        assert_eq!(r.deltas.iter().sum::<i32>(), sticks_taken, "{name}: {:?}", r.deltas);
        let svg = rinshan_render::svg(
            b,
            &Options {
                defs: false,
                ..revealed(0)
            },
        );
        insta::assert_snapshot!(format!("board_{name}"), lines(&svg));
    }
    for mode in TileMode::ALL {
        insta::assert_snapshot!(format!("tiles_{mode}"), symbols(&rinshan_render::sprite(mode)));
    }
}

#[test]
fn pictures_rasterise_in_every_mode() {
    let games = games();
    let (ps, _) = round_replay(&games[0], 0).expect("a round");
    let board = Board::from_state(&ps[ps.len() / 2].state, Variant::Red);
    for mode in TileMode::ALL {
        let svg = rinshan_render::svg(
            &board,
            &Options {
                tiles: mode,
                ..revealed(0)
            },
        );
        let png = rinshan_render::png::png(&svg, 0.5).expect("a PNG");
        let img = image_size_and_colours(&png);
        assert_eq!((img.0, img.1), (480, 480), "{mode}");
        assert!(
            img.2 > 1000,
            "{mode}: the tiles' light bodies are drawn ({} pixels)",
            img.2
        );
    }
    assert!(rinshan_render::png::png("<svg", 1.0).is_err());
}

/// Width, height and the count of light (tile-body) pixels of a PNG, decoded by resvg's own
/// tiny-skia.
fn image_size_and_colours(png: &[u8]) -> (u32, u32, usize) {
    let pixmap = resvg::tiny_skia::Pixmap::decode_png(png).expect("a PNG");
    let light = pixmap
        .pixels()
        .iter()
        .filter(|p| p.red() > 230 && p.green() > 225 && p.blue() > 200)
        .count();
    (pixmap.width(), pixmap.height(), light)
}

#[test]
fn the_replay_page_holds_every_decision_and_each_result() {
    use base64::Engine as _;
    use std::io::Read as _;
    let games = games();
    let game = &games[0];
    let page = rinshan_render::html::replay_html(game, 0).expect("a page");
    let data = page
        .split("const DATA = \"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .expect("the inlined game");
    let packed = base64::engine::general_purpose::STANDARD.decode(data).expect("base64");
    let mut json = String::new();
    flate2::read::GzDecoder::new(&packed[..])
        .read_to_string(&mut json)
        .expect("gzip");
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let mut want = 0;
    for r in 0..game.rounds.len() {
        let (ps, end) = round_replay(game, r).expect("the round replays");
        want += ps.len() + usize::from(end.is_some());
    }
    let frames = v["frames"].as_array().expect("frames");
    assert_eq!(frames.len(), want, "a frame per decision and one result per round");
    assert_eq!(v["rounds"].as_array().map(Vec::len), Some(game.rounds.len()));
    let results = frames
        .iter()
        .filter(|f| f["svg"].as_str().is_some_and(|s| s.contains("class=\"result\"")))
        .count();
    assert_eq!(results, game.rounds.len());
    for f in frames.iter().step_by(50) {
        let svg = f["svg"].as_str().expect("an SVG");
        assert!(!tiles_of(svg).is_empty());
        // Faces come from the page's sprite: a frame carries no art of its own.
        assert!(!svg.contains("<symbol"));
    }
    let sprites = v["sprites"].as_array().expect("sprites");
    assert_eq!(sprites.len(), 3);
    for s in sprites {
        let sheet = s[1].as_str().expect("a sprite");
        roxmltree::Document::parse(sheet).expect("the sprite parses");
        assert_eq!(sheet.matches("<symbol").count(), 38, "37 tiles and the back");
    }
}

/// Three players' tables, from self-play sanma games written as logs and replayed: three seats
/// (the next one on the right, the one before on the left, none across), each seat's dealt hand,
/// and the Norths each seat has set aside (kita) beside its river, as many as the log lists.
#[test]
fn three_player_tables_show_three_seats_and_their_kita() {
    let games = crate::tenhou_roundtrip::play_variant(Variant::Sanma, rinshan_engine::env::Mode::East, 4, 21);
    let mut kitas = 0;
    let north = Tile::plain(rinshan_engine::TileType::NORTH);
    for (g, r, ps, end) in rounds(&games) {
        let round = &games[g].rounds[r];
        let first = Board::from_state(&ps[0].state, Variant::Sanma);
        assert_eq!((first.seats, first.hands[3].len()), (3, 0));
        for p in 0..3 {
            let mut shown = first.hands[p].clone();
            shown.extend(first.drawn[p]);
            let mut dealt = round.hands[p].clone();
            if p == round.dealer() {
                dealt.extend(round.draws[p].first().and_then(|d| d.tiles().first().copied()));
            }
            assert_eq!(sorted(shown), sorted(dealt), "round {r} seat {p}");
        }
        let mut most = [0u32; 4];
        for p in &ps {
            let board = Board::from_state(&p.state, Variant::Sanma);
            let svg = rinshan_render::svg(&board, &revealed(0));
            let doc = roxmltree::Document::parse(&svg).expect("the SVG is well-formed XML");
            let turns: Vec<(String, String)> = doc
                .descendants()
                .filter(|n| n.attribute("class") == Some("seat"))
                .map(|n| {
                    let a = |k: &str| n.attribute(k).unwrap_or("").to_string();
                    (a("data-seat"), a("transform"))
                })
                .collect();
            assert_eq!(
                turns,
                [
                    ("0".into(), "rotate(-0 480 480)".into()),
                    ("1".into(), "rotate(-90 480 480)".into()),
                    ("2".into(), "rotate(-270 480 480)".into())
                ]
            );
            let tiles = tiles_of(&svg);
            for (q, most) in most.iter_mut().enumerate().take(3) {
                let kita = tiles
                    .iter()
                    .filter(|t| t.1 == q.to_string() && t.2 == "kita" && t.0 == north.name())
                    .count();
                assert_eq!(kita as u32, board.kita[q], "round {r} seat {q}");
                *most = (*most).max(board.kita[q]);
            }
        }
        // The last decision may itself be a kita (ronned), after which no position is asked.
        let ronned_kita = end.is_some() && ps.last().is_some_and(|p| p.what.starts_with("ron on a kita"));
        for q in 0..3 {
            let logged = round.discards[q].iter().filter(|d| matches!(d, Discard::Kita)).count() as u32;
            assert!(
                most[q] == logged || ronned_kita && most[q] + 1 >= logged,
                "round {r} seat {q}: {most:?}"
            );
            kitas += logged;
        }
    }
    assert!(kitas > 20, "{kitas} kita in the games");
    let (_, _, ps, _) = rounds(&games).swap_remove(0);
    let board = Board::from_state(&ps[ps.len() / 2].state, Variant::Sanma);
    let png = rinshan_render::png::png(&rinshan_render::svg(&board, &revealed(1)), 0.5).expect("rasterises");
    assert_eq!(&png[1..4], b"PNG");
}

/// A Japanese player's name is drawn in a PNG (it came out as blanks: the bundled font had ASCII
/// only and no system font is read), and a name of characters no bundled font has (Hangul) is
/// drawn as `?`, one per character, rather than as nothing.
#[test]
fn japanese_names_are_drawn_in_pngs_and_others_as_question_marks() {
    let games = games();
    let (ps, _) = round_replay(&games[0], 0).expect("a round");
    let named = |name: &str| {
        let mut b = Board::from_state(&ps[0].state, Variant::Red);
        b.names = [name, "B", "C", "D"].map(String::from);
        let png = rinshan_render::png::png(&rinshan_render::svg(&b, &revealed(0)), 1.0).expect("a PNG");
        resvg::tiny_skia::Pixmap::decode_png(&png).expect("a PNG")
    };
    let differ = |a: &resvg::tiny_skia::Pixmap, b: &resvg::tiny_skia::Pixmap| {
        a.pixels().iter().zip(b.pixels()).filter(|(p, q)| p != q).count()
    };
    let blank = named(" ");
    let japanese = named("麻雀太郎");
    let ascii = named("Mahjong");
    // Four kanji at 14 px ink more pixels than a few dozen: a blank or a lone box would not.
    let inked = differ(&japanese, &blank);
    assert!(inked > 150, "the Japanese name drew {inked} pixels");
    assert!(differ(&ascii, &blank) > 150, "the ASCII name is drawn too");
    assert!(rinshan_render::png::drawable('麻') && !rinshan_render::png::drawable('김'));
    assert_eq!(differ(&named("김철수"), &named("???")), 0, "Hangul is drawn as `?`");
}
