//! Every decision of a half game of `defensive` agents, with what the deciding seat drew itself:
//! the positions the look-ahead's tests and measurements (the `belief` and `noise` examples) are
//! taken from.

use rinshan_engine::agents::Agent;
use rinshan_engine::env::Mode;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::observe::OwnDraws;
use rinshan_engine::{with_variant, Variant};

/// A decision of a game: the state, the seat to act, and the wall places that seat drew this round.
#[derive(Clone)]
pub struct Position {
    /// The state at the decision.
    pub state: GameState,
    /// The seat to act.
    pub seat: u32,
    /// The wall places `seat` drew this round ([`OwnDraws`]).
    pub own_draws: Vec<u32>,
}

/// Plays a half game of `variant` from `seed` (its two words: low, high) with `defensive` in every
/// seat, showing `visit` each decision before it is played, until the game ends or `visit` returns
/// false. Returns the state then: the game's end (its ranks), or the decision `visit` stopped at.
pub fn defensive_game(variant: Variant, seed: u64, visit: &mut dyn FnMut(&Position) -> bool) -> GameState {
    with_variant!(variant, v => {
        let mut s: GameState = variant.new_game(seed, Mode::Half);
        let seats = variant.seats();
        let mut own: Vec<OwnDraws> = vec![OwnDraws::default(); 4];
        for q in 0..seats {
            own[q as usize].update(variant, &s, &mut s.clone(), q);
        }
        while s.terminated == 0 {
            let seat = s.current;
            let position = Position { state: s, seat, own_draws: own[seat as usize].positions.clone() };
            if !visit(&position) {
                return s;
            }
            let a = v::seat_act(&mut { s }, Agent::Defensive.kernel());
            let before = s;
            v::game_step(&mut s, a);
            for q in 0..seats {
                own[q as usize].update(variant, &before, &mut s.clone(), q);
            }
        }
        s
    })
}
