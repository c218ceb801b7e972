//! The oracle of what a seat may not see: a state with everything hidden from one seat
//! reshuffled or scrambled. An observation that changes under it leaks; the tests and the soak
//! check every observation form against it.

use crate::generated::kernel::{self, GameState, SEAT_FURITEN_RIICHI, SEAT_FURITEN_TEMP};
use crate::random::Rng;
use crate::Variant;

fn wall_set(s: &mut GameState, i: u32, v: u32) {
    let w = &mut s.wall[(i / 4) as usize];
    *w = (*w & !(255 << ((i % 4) * 8))) | (v << ((i % 4) * 8));
}

/// The wall positions the observer drew from this round, kept up to date step by step from the
/// engine's counters (not from the event log under test).
#[derive(Debug, Clone, Default)]
pub struct OwnDraws {
    round_key: Option<(u32, u32, u32)>,
    /// The positions, in the order drawn.
    pub positions: Vec<u32>,
}

impl OwnDraws {
    /// Follows one step of a game of `variant` from `before` to `after` for `observer`.
    pub fn update(&mut self, variant: Variant, before: &GameState, after: &mut GameState, observer: u32) {
        let key = Some((after.games, after.rounds, after.round * 64 + after.honba));
        let drew_now = after.drawn != kernel::NO_TILE_VALUE && after.current == observer;
        if key != self.round_key || after.next_draw < before.next_draw {
            self.round_key = key;
            self.positions.clear();
            if after.dealer == observer {
                self.positions.push(variant.wall().live_start);
            }
            return;
        }
        if after.next_draw == before.next_draw + 1 && drew_now {
            self.positions.push(after.next_draw - 1);
        }
        let (now, then) = (variant.drawn_replacements(after), variant.drawn_replacements(before));
        if now.len() == then.len() + 1 && drew_now && after.rinshan == 1 {
            self.positions.extend(now.last());
        }
    }
}

/// The wall places whose tiles no seat has seen at `s`: the live wall still to be drawn, the dora
/// and ura indicators not revealed, and the replacement tiles not drawn (live wall first, in
/// place order).
pub fn hidden_wall_places(variant: Variant, s: &GameState) -> Vec<u32> {
    let wall = variant.wall();
    let drawn_replacements = variant.drawn_replacements(s);
    // The live wall's end is where three players' replacement tiles past the fourth come from.
    let live = (s.next_draw..wall.live_end).filter(|i| !drawn_replacements.contains(i));
    let dora = wall.dora + s.dora_revealed..wall.dora + 5;
    let ura = wall.ura..wall.ura + 5;
    let rinshan = (wall.rinshan..wall.rinshan + 4).filter(|i| !drawn_replacements.contains(i));
    live.chain(dora).chain(ura).chain(rinshan).collect()
}

/// A copy of `s` in which everything `observer` cannot see is reshuffled or scrambled: the tiles
/// of the other hands, the live wall and the hidden dead wall permuted among themselves, the wall
/// places of tiles that left it unseen scrambled, the other seats' waits, furiten, claim options
/// and choices, and the seeds and the step counter. `own_draws` are the wall places the observer
/// drew from this round ([`OwnDraws`]).
pub fn resample_hidden(variant: Variant, s: &GameState, observer: u32, own_draws: &[u32], rng: &mut Rng) -> GameState {
    let mut r = *s;
    let wall = variant.wall();
    let seats = variant.seats();
    let mut pool: Vec<u32> = Vec::new();
    let hidden_positions = hidden_wall_places(variant, s);
    for &i in &hidden_positions {
        pool.push(kernel::wall_tile(&mut r, i));
    }
    let mut sizes = [0usize; 4];
    for q in (0..seats).filter(|&q| q != observer) {
        let counts = kernel::hand_counts(&mut r, q);
        for t in 0..34u32 {
            let mut n = counts[t as usize];
            if t < 27 && t % 9 == 4 && kernel::holds_red(&mut r, q, t / 9) {
                pool.push(34 + t / 9);
                n -= 1;
            }
            for _ in 0..n {
                pool.push(t);
            }
            sizes[q as usize] += counts[t as usize] as usize;
        }
    }
    // In one order whatever the hidden tiles' places were: the same seed then deals the same
    // tiles from every state with this view (the look-ahead's worlds depend on the view alone).
    pool.sort_unstable();
    for i in (1..pool.len()).rev() {
        pool.swap(i, rng.below(i as u32 + 1) as usize);
    }
    let mut next = pool.into_iter();
    for &i in &hidden_positions {
        if let Some(v) = next.next() {
            wall_set(&mut r, i, v);
        }
    }
    for q in (0..seats).filter(|&q| q != observer) {
        for w in 0..5 {
            r.hands[(q * 5 + w) as usize] = 0;
        }
        r.red &= !(7 << (q * 3));
        let mut given = Vec::new();
        for _ in 0..sizes[q as usize] {
            // The pool holds exactly the hidden tiles; a state that is not a game's runs short.
            let Some(v) = next.next() else { break };
            let t = kernel::value_type(v);
            r.hands[(q * 5 + t / 8) as usize] += 1 << ((t % 8) * 4);
            if v >= 34 {
                r.red |= 1 << (q * 3 + v - 34);
            }
            given.push(v);
        }
        if s.current == q && s.drawn != kernel::NO_TILE_VALUE && !given.is_empty() {
            r.drawn = given[rng.below(given.len() as u32) as usize];
        }
        // Waits, furiten and claim prompts of another seat follow from its hand.
        r.waits[(q * 2) as usize] = rng.next_u64() as u32;
        r.waits[(q * 2 + 1) as usize] = (rng.next_u64() as u32) & 3;
        r.seat_flags[q as usize] ^= (SEAT_FURITEN_TEMP | SEAT_FURITEN_RIICHI) & rng.next_u64() as u32;
        r.claim_options[q as usize] = (rng.next_u64() as u32) & 1023;
        r.claim_choices[q as usize] = rng.below(256);
    }
    // Tiles that left the wall into other hands: their positions tell nothing now.
    let dealt_by = |i: u32| (s.dealer + i / 13) % seats;
    for i in 0..wall.live_start {
        if dealt_by(i) != observer {
            wall_set(&mut r, i, rng.below(37));
        }
    }
    for i in wall.live_start..s.next_draw {
        if !own_draws.contains(&i) {
            wall_set(&mut r, i, rng.below(37));
        }
    }
    for i in variant.drawn_replacements(s) {
        if !own_draws.contains(&i) {
            wall_set(&mut r, i, rng.below(37));
        }
    }
    if s.current != observer {
        r.mask = [
            (rng.next_u64() as u32),
            (rng.next_u64() as u32),
            (rng.next_u64() as u32),
        ];
    }
    r.seed = [(rng.next_u64() as u32), (rng.next_u64() as u32)];
    r.steps = rng.next_u64() as u32;
    r
}
