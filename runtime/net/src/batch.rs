//! The net at chosen seats of a batch of games stepped by someone else (selfplay, the Python
//! env's opponents): all its decisions of a step in one forward pass.

use rayon::prelude::*;
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

    /// Replaces the actions of the games whose seat to act is the net's by the net's.
    pub fn act(&mut self, actions: &mut [u32]) -> Result<(), NetError> {
        self.inputs.clear();
        let at: Vec<usize> = (0..self.states.len().min(actions.len()))
            .filter(|&i| {
                let s = &self.states[i];
                // A finished game's state asks nothing.
                self.seats[i][s.current as usize % 4] && s.mask != [0; 3]
            })
            .collect();
        if at.is_empty() {
            return Ok(());
        }
        // The observations (the analysis form's shanten and waits above all) are most of the
        // work outside the forward pass: built in parallel, then batched in order.
        let decisions: Vec<_> = at.par_iter().map(|&i| self.agent.decision(&self.states[i])).collect();
        for (&i, d) in at.iter().zip(&decisions) {
            self.inputs.push_decision(d, self.agent.legal(&self.states[i]));
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
