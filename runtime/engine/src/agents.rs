//! The built-in baseline agents (`rules/kernel/agents.rs`): they read only the planes observation
//! of the seat they play and its legal mask, run in the kernel on both backends, and are
//! deterministic for a game's seed. They play seats inside [`crate::env::Env::step`] (hero mode,
//! [`crate::env::Config::agents`]) and in the [`crate::arena`].

use crate::generated::kernel as k;

/// A built-in agent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Agent {
    /// Uniform over the legal actions.
    Random,
    /// MahJax's rule-based player, its bugs fixed: win > riichi > yakuhai pon > discard by
    /// shanten, wait count, then a static tile order; folds onto safe tiles against a riichi at
    /// two or more shanten.
    Rule,
    /// Shanten, then ukeire over unseen tiles, then tile value; yakuhai pons that keep shanten, no
    /// chi, kans that keep shanten.
    Greedy,
    /// Greedy, folding by tile danger (genbutsu, suji, kabe, visible honors, dora) against a
    /// riichi or an open hand with three melds or three dora when far from tenpai.
    Defensive,
}

impl Agent {
    /// Every agent, weakest first.
    pub const ALL: [Agent; 4] = [Agent::Random, Agent::Rule, Agent::Greedy, Agent::Defensive];

    /// The name users write.
    pub fn name(self) -> &'static str {
        match self {
            Agent::Random => "random",
            Agent::Rule => "rule",
            Agent::Greedy => "greedy",
            Agent::Defensive => "defensive",
        }
    }

    /// The kernel's `AGENT_*` id.
    pub fn kernel(self) -> u32 {
        match self {
            Agent::Random => k::AGENT_RANDOM,
            Agent::Rule => k::AGENT_RULE,
            Agent::Greedy => k::AGENT_GREEDY,
            Agent::Defensive => k::AGENT_DEFENSIVE,
        }
    }

    /// The action this agent plays for the player to move in `state`, a game of `variant`'s
    /// rules (the kernel's `game_agent_action`), for hosts that hold one state rather than an env.
    pub fn act(self, variant: crate::Variant, state: &k::GameState) -> u32 {
        let seats = seats_word(&[Some(self); 4]);
        with_variant!(variant, v => v::game_agent_action(*state, seats))
    }
}

impl std::fmt::Display for Agent {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Agent {
    type Err = crate::names::UnknownName;

    fn from_str(name: &str) -> Result<Agent, crate::names::UnknownName> {
        crate::names::UnknownName::find("agent", name, &Agent::ALL)
    }
}

/// The kernel's word for who plays each seat: 4 bits per seat, `AGENT_CALLER` (0) for the caller.
pub fn seats_word(seats: &[Option<Agent>; 4]) -> u32 {
    seats
        .iter()
        .enumerate()
        .map(|(p, a)| a.map_or(k::AGENT_CALLER, Agent::kernel) << (4 * p))
        .fold(0, |w, x| w | x)
}

/// Hero mode's argument (the kernel's `game_play`): the caller's action in the low byte (an id
/// that high is illegal, and stays so), `seats` ([`seats_word`]) above it.
pub fn hero_arg(action: u32, seats: u32) -> u32 {
    action.min(255) | seats << 8
}
