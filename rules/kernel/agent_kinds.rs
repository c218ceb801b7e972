// Who plays a seat in hero mode (`game_play`, rules/kernel/agents.rs): the caller or a built-in
// agent. Hosts pass these ids, and the flags of hero mode's decisions below.

pub const AGENT_CALLER: u32 = 0;
pub const AGENT_RANDOM: u32 = 1;
pub const AGENT_RULE: u32 = 2;
pub const AGENT_GREEDY: u32 = 3;
pub const AGENT_DEFENSIVE: u32 = 4;
pub const AGENT_KINDS: u32 = 5;

// Decisions one call of hero mode plays at most (a guard; a game ends long before).
pub const PLAY_LIMIT: u32 = 20001;
// In the argument of hero mode's next decision: this is the call's first decision.
pub const PLAY_FIRST: u32 = 0x80000000;
// In hero mode's argument: a play-out (the look-ahead's), whose first decision plays the caller's
// action whoever is to move, and which ends with the round.
pub const PLAY_ROUND: u32 = 0x01000000;
// In the argument of game_advance: add the step's outputs to those of the decisions before it.
pub const PLAY_ADD: u32 = 0x40000000;
// game_advance's argument once hero mode's call is over: nothing to play.
pub const PLAY_DONE: u32 = 0xffffffff;
