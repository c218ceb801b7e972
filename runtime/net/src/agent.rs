//! The net playing a variant: the variant's action ids mapped to the net's by name, the greedy
//! choice among the legal ones (as the training example's `greedy_policy`), a batch of decisions
//! in one forward pass, and the agent as an arena entrant.

use std::sync::Arc;

use rinshan_engine::arena::{Entrant, Seat};
use rinshan_engine::env::action_names;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;

use crate::file::{Net, NetError};
use crate::inputs::{Decision, Inputs};

/// A net that plays `variant`.
#[derive(Debug, Clone)]
pub struct NetAgent {
    net: Arc<Net>,
    variant: Variant,
    /// Per net action, the variant's id for it (None: the variant has no such action).
    to_env: Vec<Option<u32>>,
}

impl NetAgent {
    /// `net` playing `variant`; an error when the variant has an action the net has no logit for.
    pub fn new(net: Arc<Net>, variant: Variant) -> Result<NetAgent, NetError> {
        let names = action_names(variant);
        let missing: Vec<&str> = names
            .iter()
            .filter(|a| !net.actions.contains(a))
            .map(String::as_str)
            .collect();
        if !missing.is_empty() {
            return Err(NetError::new(format!(
                "{} cannot play {variant}: it has no logit for {} (it was trained on another variant's actions)",
                net.name,
                missing.join(", ")
            )));
        }
        let to_env = net
            .actions
            .iter()
            .map(|a| names.iter().position(|n| n == a).map(|i| i as u32))
            .collect();
        Ok(NetAgent { net, variant, to_env })
    }

    /// The net.
    pub fn net(&self) -> &Net {
        &self.net
    }

    /// The name reports show: `net:` and the file's stem.
    pub fn name(&self) -> String {
        format!("net:{}", self.net.name)
    }

    /// An empty batch of decisions for this net.
    pub fn inputs(&self) -> Inputs {
        Inputs::new(self.net.analysis.len(), self.net.actions.len())
    }

    /// Adds the decision of the player to move in `state` to `inputs`.
    pub fn push(&self, inputs: &mut Inputs, state: &GameState) {
        inputs.push_decision(&self.decision(state), self.legal(state));
    }

    /// The observation of the player to move in `state`, as the net reads it.
    pub fn decision(&self, state: &GameState) -> Decision {
        Decision::of(self.variant, state, &self.net.analysis)
    }

    /// Whether net action `a` is legal in `state`.
    pub fn legal<'a>(&'a self, state: &'a GameState) -> impl Fn(usize) -> bool + 'a {
        |a: usize| self.to_env[a].is_some_and(|e| state.mask[e as usize / 32] >> (e % 32) & 1 == 1)
    }

    /// The variant's action ids the net plays at `inputs`' decisions.
    pub fn choose(&self, inputs: &Inputs) -> Result<Vec<u32>, NetError> {
        self.net
            .greedy(inputs)?
            .into_iter()
            .map(|a| {
                a.and_then(|a| self.to_env[a])
                    .ok_or_else(|| NetError::new("a decision with no legal action"))
            })
            .collect()
    }

    /// The action it plays in `state`, for the player to move.
    pub fn act(&self, state: &GameState) -> Result<u32, NetError> {
        let mut inputs = self.inputs();
        self.push(&mut inputs, state);
        Ok(self.choose(&inputs)?[0])
    }

    /// The actions it plays in each of `states`, in one forward pass.
    pub fn act_many(&self, states: &[GameState]) -> Result<Vec<u32>, NetError> {
        let mut inputs = self.inputs();
        for s in states {
            self.push(&mut inputs, s);
        }
        self.choose(&inputs)
    }
}

struct NetSeat<'a>(&'a NetAgent);

impl Seat for NetSeat<'_> {
    fn act(&mut self, state: &GameState) -> Result<u32, String> {
        self.0.act(state).map_err(|e| e.to_string())
    }

    fn stepped(&mut self, _: &GameState, _: u32, _: &GameState) -> Result<(), String> {
        Ok(())
    }
}

impl Entrant for NetAgent {
    fn join(&self, _seat: u32, _state: &GameState, variant: Variant) -> Box<dyn Seat + '_> {
        debug_assert_eq!(
            variant, self.variant,
            "a net agent joins games of the variant it was made for"
        );
        Box::new(NetSeat(self))
    }
}
