//! Worlds a seat cannot tell from the real game: the tiles it cannot see dealt afresh.
//!
//! The tiles come from [`resample_hidden`], the observation leak tests' oracle of what a seat may
//! not see. It deals the other seats uniformly random hands, which real hands are not: a seat
//! that has discarded twelve tiles has kept the tiles it wanted, and is tenpai about half the time
//! in `defensive` self-play, where a uniform hand almost never is (the `belief` example measures
//! it: docs/strength.md). Worlds of such hands have no threats in them, and a look-ahead in them
//! pushes into deal-ins. So each other seat's hand is built as it was in the real game: once per
//! tile the seat has discarded, it draws a tile from the unseen wall and lets go of the tile that
//! leaves its hand the fewest steps from tenpai (the tile goes back to the wall's place). What the
//! oracle scrambles with noise (waits, furiten, claim prompts) is then recomputed from the new
//! hands. A seat in riichi holds a tenpai hand: its hand is built on past its discards, draw after
//! draw from every wall place no seat has seen, until it is (an early riichi's hand built by six
//! draws is tenpai one time in five; late in a round the live wall alone may not hold its tiles).
//! Dealt again instead, up to 16 times, a riichi seat was still tenpai in only 71% of the worlds
//! (the `belief` example), and the worlds underrated the danger of dealing in (docs/strength.md).
//! Where building on fails (no tile left to help), the world is dealt again; so is a world where a
//! tenpai seat waits on a tile of its own river. Built without a look at the river, 35% of the
//! riichi hands were furiten (2% of the real ones): unable to win on a discard, they made the
//! worlds' deal-ins 12% fewer than self-play's (4% with them dealt again).

use rinshan_engine::generated::kernel::{
    self, GameState, ShantenInput, NO_CHOICE, NO_TILE_VALUE, SEAT_FURITEN_RIICHI, SEAT_FURITEN_TEMP, SEAT_RIICHI,
};
use rinshan_engine::observe::{hidden_wall_places, resample_hidden};
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// Deals of a world before one whose riichi seats could not all be built to tenpai, or whose
/// tenpai seats are not all free of furiten, is kept.
pub const RIICHI_TRIES: u32 = 16;

/// Draws a riichi seat's hand may be built on by: a hand one step from tenpai takes a few, and
/// the bound ends the search where no unseen tile would help (late in a round), which then deals
/// the world again.
const TENPAI_DRAWS: u32 = 200;

/// A world for `observer` at `s` (its decision): the hidden tiles dealt afresh from `rng`, each
/// other seat's hand built by as many draws as it has discarded tiles, their waits recomputed,
/// their furiten and claim prompts cleared (what made them is hidden: the world starts them
/// fresh; at a claim window the others pass), and each riichi seat's hand built on until it is
/// tenpai (dealt again where that fails, or where a seat waits on its own discards, up to
/// [`RIICHI_TRIES`] times). `own_draws` are the wall
/// places `observer` drew from this round ([`rinshan_engine::observe::OwnDraws`]).
pub fn deal(variant: Variant, s: &GameState, observer: u32, own_draws: &[u32], rng: &mut Rng) -> GameState {
    let seats = variant.seats();
    let replacements = variant.drawn_replacements(s);
    let live: Vec<u32> = (s.next_draw..variant.wall().live_end)
        .filter(|i| !replacements.contains(i))
        .collect();
    let unseen = hidden_wall_places(variant, s);
    let mut world = *s;
    for _ in 0..RIICHI_TRIES {
        world = resample_hidden(variant, s, observer, own_draws, rng);
        let mut plausible = true;
        for q in (0..seats).filter(|&q| q != observer) {
            // The seat that has just drawn holds one tile more than its discards account for.
            if !(s.current == q && s.drawn != NO_TILE_VALUE) {
                let riichi = s.seat_flags[q as usize] & SEAT_RIICHI != 0;
                let to_tenpai = riichi.then_some(unseen.as_slice());
                build_hand(&mut world, q, kernel::byte_of(s.river_lens, q), &live, to_tenpai, rng);
            }
            kernel::update_waits(&mut world, q);
            let flags = &mut world.seat_flags[q as usize];
            *flags &= !(SEAT_FURITEN_TEMP | SEAT_FURITEN_RIICHI);
            // At a claim window the others are taken to pass on the tile: their options, and the
            // choices of those asked before the observer, are hidden.
            world.claim_options[q as usize] = 0;
            world.claim_choices[q as usize] = NO_CHOICE;
            let (w0, w1) = (world.waits[(q * 2) as usize], world.waits[(q * 2 + 1) as usize]);
            let tenpai = w0 | w1 != 0;
            let furiten = w0 & world.discarded[(q * 2) as usize] | w1 & world.discarded[(q * 2 + 1) as usize] != 0;
            plausible &= (*flags & SEAT_RIICHI == 0 || tenpai) && !furiten;
        }
        if plausible {
            break;
        }
    }
    world
}

fn wall_set(s: &mut GameState, i: u32, v: u32) {
    let w = &mut s.wall[(i / 4) as usize];
    *w = (*w & !(255 << ((i % 4) * 8))) | (v << ((i % 4) * 8));
}

fn shanten(counts: [u32; 34]) -> i32 {
    kernel::shanten(ShantenInput { hand: counts }).shanten
}

/// Seat `q`'s hand improved by `draws` draws from the `live` wall places, each followed by the
/// discard that keeps the fewest steps from tenpai (the first such tile type; the drawn tile
/// itself where it is among them, so a hand that is as good as it gets is left alone); with
/// `to_tenpai` (the places no seat has seen), by more draws from them until it is tenpai (at most
/// [`TENPAI_DRAWS`] in all).
fn build_hand(s: &mut GameState, q: u32, draws: u32, live: &[u32], to_tenpai: Option<&[u32]>, rng: &mut Rng) {
    // The hand's shanten, kept up to date: a draw that does not lower the whole hand's shanten
    // has no discard that does (a tile more never adds a step), so most draws cost one shanten
    // instead of one per tile type held.
    let mut now = shanten(kernel::hand_counts(s, q));
    for k in 0.. {
        let from = match (k < draws, to_tenpai) {
            (true, _) => live,
            (false, Some(unseen)) if now > 0 && k < TENPAI_DRAWS.max(draws) => unseen,
            _ => break,
        };
        if from.is_empty() {
            break;
        }
        let place = from[rng.below(from.len() as u32) as usize];
        let drawn = kernel::wall_tile(s, place);
        let drawn_type = kernel::value_type(drawn);
        let mut counts = kernel::hand_counts(s, q);
        counts[drawn_type as usize] += 1;
        if shanten(counts) >= now {
            continue;
        }
        let mut best = (now, drawn_type);
        for t in (0..34u32).filter(|&t| counts[t as usize] > 0 && t != drawn_type) {
            let x = shanten_without(counts, t);
            if x < best.0 {
                best = (x, t);
            }
        }
        let out = best.1;
        if out == drawn_type {
            continue;
        }
        now = best.0;
        // The tile let go: a plain copy where the seat holds one, else its red five.
        let suit = out / 9;
        let red = out < 27 && out % 9 == 4 && kernel::holds_red(s, q, suit);
        let out_value = match red && counts[out as usize] - u32::from(drawn_type == out) == 1 {
            true => 34 + suit,
            false => out,
        };
        set_count(s, q, drawn_type, 1);
        if drawn >= 34 {
            s.red |= 1 << (q * 3 + drawn - 34);
        }
        set_count(s, q, out, -1);
        if out_value >= 34 {
            s.red &= !(1 << (q * 3 + out_value - 34));
        }
        wall_set(s, place, out_value);
    }
}

fn shanten_without(mut counts: [u32; 34], t: u32) -> i32 {
    counts[t as usize] -= 1;
    shanten(counts)
}

fn set_count(s: &mut GameState, q: u32, t: u32, by: i32) {
    let word = &mut s.hands[(q * 5 + t / 8) as usize];
    let shift = (t % 8) * 4;
    *word = match by > 0 {
        true => *word + (1 << shift),
        false => *word - (1 << shift),
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `build_hand` skips its search on: no discard from a hand with one tile more is fewer
    /// steps from tenpai than that whole hand (brute force over random hands of every size).
    #[test]
    fn a_tile_more_never_adds_a_step() {
        let mut rng = Rng::new(7);
        for i in 0..20_000u32 {
            let size = [2, 5, 8, 11, 14][(i % 5) as usize];
            let mut counts = [0u32; 34];
            let mut n = 0;
            while n < size {
                let t = rng.below(34) as usize;
                if counts[t] < 4 {
                    counts[t] += 1;
                    n += 1;
                }
            }
            let whole = shanten(counts);
            for t in (0..34).filter(|&t| counts[t as usize] > 0) {
                assert!(whole <= shanten_without(counts, t), "{counts:?} without {t}");
            }
        }
    }
}
