//! The round being played, entry by entry: a step's action and the state around it become the
//! draws, calls, discards and kans Tenhou writes, in Tenhou's seats (East 1's dealer is seat 0)
//! and tile order.

use crate::tenhou::log::{tenhou_kyoku, Discard, Draw, LoggedDraw, Outcome, Rel, Round};
use crate::tenhou::plan::Played;
use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::generated::red as k;
use rinshan_engine::tile::{Tile, TileType};
use rinshan_engine::Variant;

/// The round being played.
#[derive(Debug, Clone)]
pub(super) struct Current {
    /// The round so far; its result is filled in at its end.
    pub(super) round: Round,
    /// The wall it was dealt from, in the engine's dealing order, as kernel tile values.
    pub(super) wall: [u8; 136],
    /// East 1's dealer: the engine's seat `p` is the log's seat `p - first`.
    pub(super) first: u32,
    /// Players at the table.
    pub(super) seats: u32,
    /// Declared riichi whose discard has not been made yet, and riichi discards made (log seats).
    pub(super) riichi_next: [bool; 4],
    pub(super) riichi_made: [bool; 4],
    /// Each pon (log seat, tile type, its three tiles with the called one first, where it came
    /// from): an added kan is written from its pon.
    pub(super) pons: Vec<(usize, TileType, [Tile; 3], Rel)>,
    /// Dora indicators revealed so far.
    pub(super) dora: usize,
    /// The round's entries in the order of play (what an event stream such as MJAI sends live).
    pub(super) order: Vec<Played>,
}

pub(super) fn tile(v: u32) -> Result<Tile, String> {
    u8::try_from(v)
        .ok()
        .and_then(Tile::from_value)
        .ok_or_else(|| format!("tile value {v} is not a tile"))
}

/// The black and the red copy of type `t` (the red one only for a five of a suit).
fn copies(t: u32) -> Result<(Tile, Option<Tile>), String> {
    let red = (t < 27 && t % 9 == 4).then(|| tile(34 + t / 9)).transpose()?;
    Ok((tile(t)?, red))
}

// The kernel's accessors take the state by `&mut` (the kernel subset has no shared
// references); these read a copy.
fn wall_of(s: &GameState) -> [u8; 136] {
    let mut s = *s;
    std::array::from_fn(|i| kernel::wall_tile(&mut s, i as u32) as u8)
}

fn holds_red(s: &GameState, seat: u32, t: u32) -> bool {
    t < 27 && t % 9 == 4 && kernel::holds_red(&mut { *s }, seat, t / 9)
}

pub(super) fn meld_count(s: &GameState, seat: u32) -> u32 {
    kernel::meld_count(&mut { *s }, seat)
}

/// Tenhou sorts a hand by tile, a red five after the black ones.
fn sort_tiles(tiles: &mut [Tile]) {
    tiles.sort_by_key(|t| (t.kind(), t.is_red()));
}

impl Current {
    /// The round `s`, a game of `variant`, has just dealt (the dealer has drawn its first tile and
    /// not acted yet).
    pub(super) fn start(s: &GameState, variant: Variant) -> Result<Current, String> {
        let wall = wall_of(s);
        let dealer = s.dealer;
        let seats = variant.seats();
        let live_start = variant.wall().live_start as usize;
        if s.next_draw != live_start as u32 + 1 || s.drawn != u32::from(wall[live_start]) || s.current != dealer {
            return Err("the state is not at the start of a round (record from a reset or a deal)".into());
        }
        let first = (dealer + seats - s.round % seats) % seats;
        let at = |p: u32| ((p + seats - first) % seats) as usize;
        let mut hands: [Vec<Tile>; 4] = Default::default();
        for j in 0..seats as usize {
            let mut hand = (0..13)
                .map(|i| tile(u32::from(wall[j * 13 + i])))
                .collect::<Result<Vec<_>, _>>()?;
            sort_tiles(&mut hand);
            hands[at((dealer + j as u32) % seats)] = hand;
        }
        let mut draws: [Vec<Draw>; 4] = Default::default();
        draws[at(dealer)].push(Draw::Tile(tile(u32::from(wall[live_start]))?));
        let n = seats as usize;
        let scores = std::array::from_fn(|i| if i < n { s.scores[(i + first as usize) % n] } else { 0 });
        let round = Round {
            line: 0,
            seats: n,
            kyoku: tenhou_kyoku(s.round, n),
            honba: s.honba,
            sticks: s.sticks,
            scores,
            dora: Vec::new(),
            ura: Vec::new(),
            hands,
            draws,
            discards: Default::default(),
            // Until the round ends.
            outcome: Outcome::Draw {
                kind: LoggedDraw::Exhaustive,
                deltas: None,
            },
        };
        Ok(Current {
            round,
            wall,
            first,
            seats,
            riichi_next: [false; 4],
            riichi_made: [false; 4],
            pons: Vec::new(),
            dora: s.dora_revealed as usize,
            order: vec![Played::Draw {
                seat: at(dealer),
                draw: Draw::Tile(tile(u32::from(wall[live_start]))?),
                replacement: false,
            }],
        })
    }

    /// The log's seat of engine seat `p`.
    pub(super) fn at(&self, p: u32) -> usize {
        ((p + self.seats - self.first) % self.seats) as usize
    }

    pub(super) fn wall_tile(&self, i: usize) -> Result<Tile, String> {
        tile(u32::from(self.wall[i]))
    }

    /// Engine seat `p` drew wall tile `i` (a replacement tile after a kan), which the state
    /// says is value `drawn`.
    pub(super) fn draw(&mut self, p: u32, i: usize, replacement: bool, drawn: u32) -> Result<(), String> {
        let t = self.wall_tile(i)?;
        if u32::from(t.value()) != drawn {
            return Err(format!("seat {p} drew wall[{i}] = {t}, but the state says {drawn}"));
        }
        let seat = self.at(p);
        self.draw_entry(seat, Draw::Tile(t), replacement);
        Ok(())
    }

    fn draw_entry(&mut self, seat: usize, draw: Draw, replacement: bool) {
        self.round.draws[seat].push(draw);
        self.order.push(Played::Draw {
            seat,
            draw,
            replacement,
        });
    }

    fn discard_entry(&mut self, seat: usize, discard: Discard) {
        self.round.discards[seat].push(discard);
        self.order.push(Played::Discard { seat, discard });
    }

    /// A discard of value `v`, or of the drawn tile (`None`).
    pub(super) fn discard(&mut self, p: usize, v: Option<u32>) -> Result<(), String> {
        let t = v.map(tile).transpose()?;
        let entry = if std::mem::take(&mut self.riichi_next[p]) {
            self.riichi_made[p] = true;
            Discard::Riichi(t)
        } else {
            t.map_or(Discard::Tsumogiri, Discard::Tile)
        };
        self.discard_entry(p, entry);
        Ok(())
    }

    /// A kita (North set aside) by log seat `p`.
    pub(super) fn kita(&mut self, p: usize) {
        self.discard_entry(p, Discard::Kita);
    }

    /// A closed or added kan of type `t` by engine seat `p`.
    pub(super) fn self_kan(&mut self, b: &GameState, p: u32, t: u32) -> Result<(), String> {
        let (black, red) = copies(t)?;
        let seat = self.at(p);
        let last = if holds_red(b, p, t) {
            red.unwrap_or(black)
        } else {
            black
        };
        let entry = match self
            .pons
            .iter()
            .position(|&(s, kind, ..)| s == seat && u32::from(kind) == t)
        {
            Some(i) => {
                let (_, _, pon, from) = self.pons.remove(i);
                Discard::AddedKan { added: last, pon, from }
            }
            None => Discard::ClosedKan {
                tiles: [black, black, black, last],
            },
        };
        self.discard_entry(seat, entry);
        Ok(())
    }

    /// The call `choice` of engine seat `q` on the claim window of state `b`.
    pub(super) fn call(&mut self, b: &GameState, q: u32, choice: u32) -> Result<(), String> {
        let called = tile(b.claim_tile)?;
        let t = u32::from(called.kind());
        let seat = self.at(q);
        let from = Rel::between(seat, self.at(b.claim_from));
        let (black, red) = copies(t)?;
        let entry = match choice {
            k::ACTION_PON | k::ACTION_PON_RED => {
                let second = if choice == k::ACTION_PON_RED {
                    red.unwrap_or(black)
                } else {
                    black
                };
                self.pons.push((seat, called.kind(), [called, black, second], from));
                Draw::Pon {
                    called,
                    own: [black, second],
                    from,
                }
            }
            k::ACTION_OPEN_KAN => {
                let last = if holds_red(b, q, t) {
                    red.unwrap_or(black)
                } else {
                    black
                };
                self.discard_entry(seat, Discard::Nothing);
                Draw::OpenKan {
                    called,
                    own: [black, black, last],
                    from,
                }
            }
            _ => {
                let low = match choice {
                    k::ACTION_CHI_LEFT | k::ACTION_CHI_LEFT_RED => t,
                    k::ACTION_CHI_MIDDLE | k::ACTION_CHI_MIDDLE_RED => t - 1,
                    k::ACTION_CHI_RIGHT | k::ACTION_CHI_RIGHT_RED => t - 2,
                    other => return Err(format!("seat {q}'s call {other} is not a call")),
                };
                let red_chi = matches!(
                    choice,
                    k::ACTION_CHI_LEFT_RED | k::ACTION_CHI_MIDDLE_RED | k::ACTION_CHI_RIGHT_RED
                );
                let own = (low..low + 3).filter(|&x| x != t).map(|x| match copies(x)? {
                    (_, Some(r)) if red_chi => Ok(r),
                    (black, _) => Ok(black),
                });
                let own = own.collect::<Result<Vec<Tile>, String>>()?;
                Draw::Chi {
                    called,
                    own: [own[0], own[1]],
                }
            }
        };
        self.draw_entry(seat, entry, false);
        Ok(())
    }
}
