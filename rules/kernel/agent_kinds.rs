// Who plays a seat in hero mode (`game_play`, rules/kernel/agents.rs): the caller or a built-in
// agent. Hosts pass these ids.

pub const AGENT_CALLER: u32 = 0;
pub const AGENT_RANDOM: u32 = 1;
pub const AGENT_RULE: u32 = 2;
pub const AGENT_GREEDY: u32 = 3;
pub const AGENT_DEFENSIVE: u32 = 4;
pub const AGENT_KINDS: u32 = 5;
