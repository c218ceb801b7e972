//! One world played to the end of its round.

use rinshan_engine::agents::Agent;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::{with_variant, Variant};

/// Steps a round may take before a play-out gives up (a round is about 60; none comes near).
pub const MAX_STEPS: u32 = 2000;

/// Plays `first` in `world`, then `agent` for every seat, until the round ends (the next one is
/// dealt, or the game is over). Returns the state then and the steps played.
pub fn play_round(variant: Variant, mut world: GameState, first: u32, agent: Agent) -> (GameState, u32) {
    with_variant!(variant, v => {
        let rounds = world.rounds;
        v::game_step(&mut world, first);
        let mut steps = 1;
        let kernel = agent.kernel();
        while world.rounds == rounds && world.terminated == 0 && steps < MAX_STEPS {
            let a = v::seat_act(&mut world, kernel);
            v::game_step(&mut world, a);
            steps += 1;
        }
        (world, steps)
    })
}
