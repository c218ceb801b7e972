//! A table as a picture sees it: each seat's hand, melds and river, the dora indicators and the
//! counters, decoded once from a game state so that the drawing code never reads packed words.

use rinshan_engine::env::{DrawKind, Step, Table};
use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::{with_variant, Tile, TileType, Variant};

/// How a meld was formed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeldKind {
    /// A run called from the seat on the left.
    Chi,
    /// A triplet called from another seat.
    Pon,
    /// A called quad (daiminkan).
    OpenKan,
    /// A concealed quad (ankan).
    ClosedKan,
    /// A pon completed with the fourth tile from the hand (kakan).
    AddedKan,
}

/// One meld as it lies on the table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Meld {
    /// How it was formed.
    pub kind: MeldKind,
    /// Its tiles in the order they lie, left to right from the owner's side (the called tile in
    /// the slot that points at the seat it came from; an added kan's fourth tile is not here).
    pub tiles: Vec<Tile>,
    /// The slot of `tiles` holding the called tile (turned sideways); none for a closed kan.
    pub called: Option<usize>,
    /// The tile an added kan stacked on the called one.
    pub added: Option<Tile>,
}

/// One discard in a river.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RiverTile {
    /// The tile.
    pub tile: Tile,
    /// The discard that declared riichi (drawn sideways).
    pub riichi: bool,
    /// Another seat called it (drawn dimmed).
    pub called: bool,
    /// It was the tile just drawn (tsumogiri).
    pub tsumogiri: bool,
}

/// The last public event of the round, for the highlight.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LastAction {
    /// The seat's last river tile was just discarded.
    Discard(u32),
    /// The seat's last meld was just made (or an added kan just stacked).
    Meld(u32),
    /// The seat declared riichi.
    Riichi(u32),
}

/// A winning hand in a round result.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WinLine {
    /// The winner.
    pub seat: u32,
    /// The seat that dealt in; `None` for tsumo.
    pub from: Option<u32>,
    /// Yaku names (with their han where the spec says), in id order.
    pub yaku: Vec<String>,
    /// Han of yaku and dora (0 for yakuman).
    pub han: u32,
    /// Fu.
    pub fu: u32,
    /// Yakuman weight (0 = none).
    pub yakuman: u32,
    /// Han from dora, red fives and ura-dora.
    pub dora: u32,
    /// Han from red fives.
    pub aka: u32,
    /// Han from ura-dora.
    pub ura: u32,
}

/// How a round ended: the panel drawn over the table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RoundResult {
    /// The winning hands (none for a draw).
    pub wins: Vec<WinLine>,
    /// The draw, for a round without a win.
    pub draw: Option<DrawKind>,
    /// Seats tenpai at an exhaustive draw.
    pub tenpai: [bool; 4],
    /// Each seat's change of points in the round (sticks and honba included, uma not).
    pub deltas: [i32; 4],
    /// The uma paid by final place, where the game ended with this round.
    pub uma: Option<[i32; 4]>,
    /// Ura-dora indicators, shown where a riichi hand won.
    pub ura: Vec<Tile>,
    /// Final places (0 = first) where the game ended with this round.
    pub ranks: Option<[u8; 4]>,
    /// Final points where the game ended with this round.
    pub final_scores: Option<[i32; 4]>,
}

/// Everything a picture of one table shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Board {
    /// Players at the table: 4, or 3 (seat 3 is empty).
    pub seats: u32,
    /// The engine's round: `seats` rounds per wind (0 = East 1; South 1 is 4, or 3 for three
    /// players).
    pub round: u32,
    /// The dealer's seat.
    pub dealer: u32,
    /// Repeat counters.
    pub honba: u32,
    /// Riichi sticks on the table.
    pub sticks: u32,
    /// Each seat's points.
    pub scores: [i32; 4],
    /// The seat to act.
    pub current: u32,
    /// The current seat is deciding on another seat's discard (or added kan).
    pub claim: Option<Tile>,
    /// Live tiles left to draw.
    pub tiles_left: u32,
    /// Revealed dora indicators.
    pub dora: Vec<Tile>,
    /// Each seat's concealed tiles, sorted, without the tile just drawn.
    pub hands: [Vec<Tile>; 4],
    /// The tile each seat has just drawn (only the current seat's, in its turn).
    pub drawn: [Option<Tile>; 4],
    /// Melds in the order they were made.
    pub melds: [Vec<Meld>; 4],
    /// Norths each seat has set aside (kita, three players).
    pub kita: [u32; 4],
    /// Discards in order.
    pub rivers: [Vec<RiverTile>; 4],
    /// Riichi declared (its stick on the table).
    pub riichi: [bool; 4],
    /// The highlight.
    pub last: Option<LastAction>,
    /// The game is over.
    pub over: bool,
    /// Player names by seat (empty = `seat N`).
    pub names: [String; 4],
    /// The round's result, where the picture shows its end.
    pub result: Option<RoundResult>,
}

fn tile_of(value: u32) -> Option<Tile> {
    u8::try_from(value).ok().and_then(Tile::from_value)
}

/// A tile value's type (a red five is its suit's five).
fn value_type(v: u32) -> u32 {
    kernel::value_type(v)
}

fn plain(t: u32) -> Tile {
    TileType::new(t as u8).map_or_else(|| Tile::plain(TileType::new(0).expect("1m")), Tile::plain)
}

impl Board {
    /// The table of `state`, a game of `variant`, as it stands before its current player decides.
    pub fn from_state(state: &GameState, variant: Variant) -> Board {
        let mut s = *state;
        let seats = variant.seats();
        let mut hands: [Vec<Tile>; 4] = Default::default();
        let mut drawn = [None; 4];
        let turn = s.phase != kernel::PHASE_CLAIM;
        for seat in 0..4u32 {
            let counts = kernel::hand_counts(&mut s, seat);
            let mut tiles = Vec::with_capacity(14);
            for (t, &n) in counts.iter().enumerate() {
                let five = TileType::new(t as u8).filter(|k| k.is_five());
                let red = five
                    .and_then(|k| k.suit())
                    .is_some_and(|suit| kernel::holds_red(&mut s, seat, u32::from(suit)));
                for i in 0..n {
                    let kind = plain(t as u32);
                    tiles.push(if red && i == 0 {
                        Tile::red(kind.kind()).unwrap_or(kind)
                    } else {
                        kind
                    });
                }
            }
            tiles.sort_by_key(|t| (t.kind(), !t.is_red()));
            if turn && seat == s.current {
                if let Some(d) = tile_of(s.drawn) {
                    if let Some(i) = tiles.iter().rposition(|&t| t == d) {
                        drawn[seat as usize] = Some(tiles.remove(i));
                    }
                }
            }
            hands[seat as usize] = tiles;
        }
        let (melds, rivers, last) = public_record(&mut s, seats);
        let first_dora = variant.wall().dora;
        let dora = (0..s.dora_revealed.min(5))
            .filter_map(|i| tile_of(kernel::wall_tile(&mut s, first_dora + i)))
            .collect();
        let kita = std::array::from_fn(|p| with_variant!(variant, v => v::kita_count(&mut s, p as u32)));
        let riichi =
            std::array::from_fn(|p| s.seat_flags[p] & kernel::SEAT_RIICHI != 0 || rivers[p].iter().any(|r| r.riichi));
        Board {
            seats,
            round: s.round,
            dealer: s.dealer,
            honba: s.honba,
            sticks: s.sticks,
            scores: s.scores,
            current: s.current,
            claim: if turn { None } else { tile_of(s.claim_tile) },
            tiles_left: s.live_end.saturating_sub(s.next_draw),
            dora,
            hands,
            drawn,
            melds,
            kita,
            rivers,
            riichi,
            last,
            over: s.phase == kernel::PHASE_OVER,
            names: Default::default(),
            result: None,
        }
    }

    /// The table at the end of the round that `end.action`, played from `before`, ended (`None`
    /// if it did not end one): the last discard in its river, the winners' hands (with the
    /// winning tile) face up, and the result panel.
    pub fn round_end(before: &GameState, end: &RoundEndInput) -> Option<Board> {
        use rinshan_engine::env::events as e;
        let RoundEndInput {
            action,
            step,
            env,
            table,
            variant,
            uma,
        } = *end;
        let ev = *step.events.get(env)?;
        if ev & ROUND_OVER == 0 {
            return None;
        }
        let mut board = Board::from_state(before, variant);
        board.place_last_discard(before, action, variant);
        let winners = step.winners[env];
        let names = rinshan_engine::env::yaku_names(variant);
        let mut s = *before;
        let wins: Vec<WinLine> = (0..4u32)
            .filter(|p| winners >> p & 1 == 1)
            .map(|p| {
                let w = table.wins[p as usize];
                let from = if ev & e::RON != 0 {
                    step.deal_in[env].checked_sub(1)
                } else {
                    None
                };
                if let (Some(_), Some(t)) = (from, tile_of(s.claim_tile)) {
                    board.drawn[p as usize] = Some(t);
                }
                WinLine {
                    seat: p,
                    from,
                    yaku: w
                        .yaku_ids()
                        .filter_map(|y| names.get(y as usize))
                        .map(|n| n.replace('_', " "))
                        .collect(),
                    han: w.han,
                    fu: w.fu,
                    yakuman: w.yakuman,
                    dora: w.dora,
                    aka: w.aka,
                    ura: w.ura,
                }
            })
            .collect();
        let riichi_won = wins.iter().any(|w| board.riichi[w.seat as usize]);
        let ura = if riichi_won {
            (0..s.dora_revealed.min(5))
                .filter_map(|i| tile_of(kernel::wall_tile(&mut s, variant.wall().ura + i)))
                .collect()
        } else {
            Vec::new()
        };
        let draw = if wins.is_empty() { table.draw.kind } else { None };
        let over = step.terminated[env];
        let ranks = step.ranks.get(env).copied().filter(|_| over && !step.illegal[env]);
        // A replay pays no uma (it compares logged payments): nothing to show apart then.
        let paid = ranks
            .map(|r| variant.uma_paid(table.scores, r, uma))
            .filter(|u: &[i32; 4]| u.iter().any(|&x| x != 0));
        let rewards = step.rewards[env].map(|r| (r * 100.0).round() as i32);
        board.result = Some(RoundResult {
            wins,
            draw,
            tenpai: if draw.is_some() { table.draw.tenpai } else { [false; 4] },
            deltas: std::array::from_fn(|p| rewards[p] - paid.map_or(0, |u: [i32; 4]| u[p])),
            uma: paid,
            ura,
            final_scores: ranks.map(|_| table.scores),
            ranks,
        });
        board.over = over;
        Some(board)
    }
}

/// What [`Board::round_end`] needs besides the state before the step: the action played, the
/// step's report for env `env`, the env's table after it (its win records), the variant (yaku
/// names, action names) and the uma the env pays by final place (the step's rewards include it in
/// a game's last step; the result shows it apart).
#[derive(Clone, Copy)]
pub struct RoundEndInput<'a> {
    /// The action that ended the round.
    pub action: u32,
    /// The step it made.
    pub step: &'a Step,
    /// The env's index in the step.
    pub env: usize,
    /// The env's table after the step.
    pub table: &'a Table,
    /// The rules.
    pub variant: Variant,
    /// Uma by final place, in points.
    pub uma: [i32; 4],
}

impl Board {
    /// The result board of a replayed log round: its last decision and how the round ended.
    pub fn logged_round_end(
        last: &rinshan_logs::tenhou::position::Position,
        end: &rinshan_logs::tenhou::position::RoundEnd,
    ) -> Option<Board> {
        let input = RoundEndInput {
            action: last.action,
            step: &end.step,
            env: 0,
            table: &end.table,
            variant: end.variant,
            uma: end.uma,
        };
        Board::round_end(&last.state, &input)
    }
}

use rinshan_engine::env::events::ROUND_OVER;

impl Board {
    /// A round ended by a discard (an exhaustive or abortive draw) shows that discard in the
    /// river, as the table saw it; a ron on an added kan (chankan) shows the pon it robbed.
    fn place_last_discard(&mut self, before: &GameState, action: u32, variant: Variant) {
        let seat = before.current as usize;
        if before.phase == kernel::PHASE_CLAIM {
            if before.claim_kan != 0 {
                let from = before.claim_from as usize;
                let robbed = self
                    .melds
                    .get_mut(from)
                    .and_then(|ms| ms.iter_mut().rev().find(|m| m.kind == MeldKind::AddedKan));
                if let Some(m) = robbed {
                    m.kind = MeldKind::Pon;
                    m.added = None;
                }
            }
            return;
        }
        let names = rinshan_engine::env::action_names(variant);
        let tile = match names.get(action as usize).map(String::as_str) {
            Some("tsumogiri") => self.drawn[seat].take().map(|t| (t, true)),
            Some(name) => name
                .strip_prefix("discard_")
                .and_then(|t| rinshan_engine::notation::parse_tile(t).ok())
                .and_then(|t| {
                    let Some(i) = self.hands[seat].iter().position(|&h| h == t) else {
                        return self.drawn[seat].take().filter(|&d| d == t).map(|d| (d, true));
                    };
                    let tile = self.hands[seat].remove(i);
                    // The drawn tile joins the hand the discard came from.
                    if let Some(d) = self.drawn[seat].take() {
                        self.hands[seat].push(d);
                        self.hands[seat].sort_by_key(|t| (t.kind(), !t.is_red()));
                    }
                    Some((tile, false))
                }),
            None => None,
        };
        if let Some((tile, tsumogiri)) = tile {
            self.rivers[seat].push(RiverTile {
                tile,
                riichi: before.phase == kernel::PHASE_RIICHI_DISCARD,
                called: false,
                tsumogiri,
            });
            self.last = Some(LastAction::Discard(seat as u32));
        }
    }
}

/// Melds, rivers and the last event, read from the round's public log (which says which tile of
/// a meld was called and which discard declared riichi) beside the state's meld words.
type Record = ([Vec<Meld>; 4], [Vec<RiverTile>; 4], Option<LastAction>);

// A river byte, as `GameState.rivers` documents it (the kernel writes these bits as literals).
const RIVER_VALUE: u32 = 63;
const RIVER_CALLED: u32 = 64;
const RIVER_TSUMOGIRI: u32 = 128;

fn public_record(s: &mut GameState, seats: u32) -> Record {
    let mut melds: [Vec<Meld>; 4] = Default::default();
    let mut rivers: [Vec<RiverTile>; 4] = Default::default();
    for seat in 0..4u32 {
        let len = kernel::byte_of(s.river_lens, seat);
        for i in 0..len.min(24) {
            let b = kernel::byte_of(s.rivers[(seat * 6 + i / 4) as usize], i % 4);
            if let Some(tile) = tile_of(b & RIVER_VALUE) {
                rivers[seat as usize].push(RiverTile {
                    tile,
                    riichi: false,
                    called: b & RIVER_CALLED != 0,
                    tsumogiri: b & RIVER_TSUMOGIRI != 0,
                });
            }
        }
    }
    // The log names each call's tile and, for a chi, the called tile's place in the run.
    let mut calls: [Vec<(u32, u32)>; 4] = Default::default();
    let mut added: [Vec<u32>; 4] = Default::default();
    let mut discards = [0usize; 4];
    let mut last = None;
    for i in 0..kernel::log_count(s) {
        let e = kernel::log_entry(s, i);
        let (kind, actor, tile, flags) = (
            kernel::log_kind(e),
            kernel::log_actor(e),
            kernel::log_tile(e),
            kernel::log_flags(e),
        );
        let a = actor as usize;
        match kind {
            kernel::EV_DISCARD => {
                if flags & kernel::LOG_RIICHI_TILE != 0 {
                    if let Some(r) = rivers[a].get_mut(discards[a]) {
                        r.riichi = true;
                    }
                }
                discards[a] += 1;
                last = Some(LastAction::Discard(actor));
            }
            kernel::EV_CHI | kernel::EV_PON | kernel::EV_OPEN_KAN | kernel::EV_CLOSED_KAN => {
                calls[a].push((tile, flags));
                last = Some(LastAction::Meld(actor));
            }
            kernel::EV_ADDED_KAN => {
                added[a].push(tile);
                last = Some(LastAction::Meld(actor));
            }
            kernel::EV_RIICHI => last = Some(LastAction::Riichi(actor)),
            _ => {}
        }
    }
    for seat in 0..4u32 {
        let n = kernel::byte_of(s.meld_counts, seat).min(4);
        for i in 0..n {
            let word = s.melds[(seat * 4 + i) as usize];
            let call = calls[seat as usize].get(i as usize).copied();
            let low = kernel::meld_tile(word);
            let fourth = added[seat as usize].iter().copied().find(|&v| value_type(v) == low);
            melds[seat as usize].push(meld_of(word, call, fourth, seats));
        }
    }
    (melds, rivers, last)
}

/// A meld word (kind, lowest type, source seat, red fives) as tiles in table order, at a table of
/// `seats`.
fn meld_of(word: u32, call: Option<(u32, u32)>, added_value: Option<u32>, seats: u32) -> Meld {
    let kind = match kernel::meld_kind(word) {
        kernel::MELD_CHI => MeldKind::Chi,
        kernel::MELD_PON => MeldKind::Pon,
        kernel::MELD_OPEN_KAN => MeldKind::OpenKan,
        kernel::MELD_CLOSED_KAN => MeldKind::ClosedKan,
        _ => MeldKind::AddedKan,
    };
    let low = kernel::meld_tile(word);
    let from = word >> kernel::MELD_FROM_SHIFT & 3;
    // Red fives in the meld: one bit count per suit's five, at most one per meld in practice.
    let mut reds = word >> kernel::MELD_REDS_SHIFT & 7;
    let called_value = call.map(|(t, _)| t);
    let called_red = called_value.is_some_and(|v| v >= 34);
    let called_type = called_value.map(value_type);
    let size = match kind {
        MeldKind::Chi | MeldKind::Pon => 3,
        _ => 4,
    };
    // The tiles from the hand, lowest first; the called one is placed below.
    let mut types: Vec<u32> = match kind {
        MeldKind::Chi => (0..3).map(|k| low + k).collect(),
        _ => vec![low; size],
    };
    let mut called_tile = None;
    if kind != MeldKind::ClosedKan {
        let t = called_type.unwrap_or(low);
        if let Some(i) = types.iter().position(|&x| x == t) {
            types.remove(i);
        }
        let mut tile = plain(t);
        if called_red {
            tile = Tile::red(tile.kind()).unwrap_or(tile);
            reds = reds.saturating_sub(1);
        }
        called_tile = Some(tile);
    }
    // An added kan's fourth tile is the one the log names (it may be the red five).
    let mut added = None;
    if kind == MeldKind::AddedKan {
        types.pop();
        let tile = tile_of(added_value.unwrap_or(low)).unwrap_or_else(|| plain(low));
        if tile.is_red() {
            reds = reds.saturating_sub(1);
        }
        added = Some(tile);
    }
    let mut tiles: Vec<Tile> = types
        .iter()
        .map(|&t| {
            let tile = plain(t);
            if reds > 0 && tile.kind().is_five() {
                reds -= 1;
                Tile::red(tile.kind()).unwrap_or(tile)
            } else {
                tile
            }
        })
        .collect();
    let Some(called) = called_tile else {
        return Meld {
            kind,
            tiles,
            called: None,
            added,
        };
    };
    // The called tile points at its source: the seat before (`seats - 1`) first, across (2, four
    // players) second, the next seat (1) last.
    let slot = match from {
        f if f == seats - 1 => 0,
        2 => 1,
        _ => tiles.len(),
    };
    let slot = slot.min(tiles.len());
    tiles.insert(slot, called);
    Meld {
        kind,
        tiles,
        called: Some(slot),
        added,
    }
}
