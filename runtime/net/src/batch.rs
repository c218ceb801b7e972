//! The net at chosen seats of a batch of games stepped by someone else (selfplay, the Python
//! env's opponents): all its decisions of a step in one forward pass.

use rinshan_engine::generated::kernel::GameState;

use crate::agent::NetAgent;
use crate::file::NetError;
use crate::inputs::Inputs;

/// The net at the chosen seats of every game of a batch.
#[derive(Clone)]
pub struct BatchNet {
    agent: NetAgent,
    /// Per game, the seats the net plays.
    seats: Vec<[bool; 4]>,
    states: Vec<GameState>,
    inputs: Inputs,
}

impl BatchNet {
    /// `agent` at `seats` (per game, the seats it plays) of games now in `states`.
    pub fn new(agent: NetAgent, seats: Vec<[bool; 4]>, states: Vec<GameState>) -> BatchNet {
        let inputs = agent.inputs();
        BatchNet {
            agent,
            seats,
            states,
            inputs,
        }
    }

    /// The agent.
    pub fn agent(&self) -> &NetAgent {
        &self.agent
    }

    /// Replaces the actions of the games whose seat to act is the net's by the net's.
    pub fn act(&mut self, actions: &mut [u32]) -> Result<(), NetError> {
        self.inputs.clear();
        let mut at = Vec::new();
        for (i, (s, seats)) in self.states.iter().zip(&self.seats).enumerate() {
            // A finished game's state asks nothing.
            if i < actions.len() && seats[s.current as usize % 4] && s.mask != [0; 3] {
                self.agent.push(&mut self.inputs, s);
                at.push(i);
            }
        }
        if at.is_empty() {
            return Ok(());
        }
        for (i, a) in at.into_iter().zip(self.agent.choose(&self.inputs)?) {
            actions[i] = a;
        }
        Ok(())
    }

    /// The games' states after the step (with auto-reset, a finished game's next one).
    pub fn stepped(&mut self, after: Vec<GameState>) {
        self.states = after;
    }
}
