//! Worlds a seat cannot tell from the real game: the tiles it cannot see dealt afresh.
//!
//! The tiles come from [`resample_hidden`], the observation leak tests' oracle of what a seat may
//! not see. That oracle scrambles what follows from the other hands (their waits, furiten, claim
//! prompts) with noise, as only observations are read from it; a world is played on, so those are
//! recomputed here from the new hands. A seat in riichi holds a tenpai hand, so a world where one
//! does not is dealt again (a few tries; the last is kept otherwise): the cheapest belief there is,
//! and the one that matters most, as a riichi seat is the danger a look-ahead must see.

use rinshan_engine::generated::kernel::{self, GameState, SEAT_FURITEN_RIICHI, SEAT_FURITEN_TEMP, SEAT_RIICHI};
use rinshan_engine::observe::resample_hidden;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// Deals of a world before one whose riichi seats are all tenpai is given up on.
pub const RIICHI_TRIES: u32 = 16;

/// A world for `observer` at `s` (its decision): the hidden tiles dealt afresh from `rng`, the
/// other seats' waits recomputed from their new hands, their furiten and claim prompts cleared
/// (what made them is hidden: the world starts them fresh), and each riichi seat tenpai where
/// [`RIICHI_TRIES`] deals allow. `own_draws` are the wall places `observer` drew from this round
/// ([`rinshan_engine::observe::OwnDraws`]).
pub fn deal(variant: Variant, s: &GameState, observer: u32, own_draws: &[u32], rng: &mut Rng) -> GameState {
    let seats = variant.seats();
    let mut world = *s;
    for _ in 0..RIICHI_TRIES {
        world = resample_hidden(variant, s, observer, own_draws, rng);
        let mut riichi_tenpai = true;
        for q in (0..seats).filter(|&q| q != observer) {
            kernel::update_waits(&mut world, q);
            let flags = &mut world.seat_flags[q as usize];
            *flags &= !(SEAT_FURITEN_TEMP | SEAT_FURITEN_RIICHI);
            world.claim_options[q as usize] = 0;
            world.claim_choices[q as usize] = 0;
            let tenpai = world.waits[(q * 2) as usize] | world.waits[(q * 2 + 1) as usize] != 0;
            riichi_tenpai &= *flags & SEAT_RIICHI == 0 || tenpai;
        }
        if riichi_tenpai {
            break;
        }
    }
    world
}
