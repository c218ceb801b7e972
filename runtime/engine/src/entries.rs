// Shared by build.rs (which asks the translator for these entry points), the GPU backend and the
// tests (tests/src/lib.rs), so the three cannot disagree on the list.
/// The map entry points of every generated WGSL module: (entry point, kernel function, input
/// struct, output struct), in binding order (the k-th entry binds input 1+2k and output 2+2k).
pub const ENTRIES: [(&str, &str, &str, &str); 4] = [
    ("shanten_main", "shanten", "ShantenInput", "ShantenOutput"),
    ("score_main", "score_hand", "ScoreInput", "ScoreOutput"),
    ("game_new_main", "game_new", "ResetInput", "GameState"),
    ("game_view_main", "game_view", "GameState", "StepView"),
];

/// The in-place update entry points, after [`ENTRIES`] in binding order: (entry point, kernel
/// function `fn(&mut State, Arg)`, state struct, argument type, guard). The k-th entry point of the
/// module (k counts [`ENTRIES`] first) binds its state (read-write) at 1+2k and its arguments at
/// 2+2k. A guard `(field, function)` skips the records where `function(state.field)` is false
/// without copying them (the entry's function would leave them as they are).
/// A step is the first five, in this order (rules/kernel/game_step.rs): `game_decide` plays an
/// action id or one of hero mode's decisions, and the others, whose argument is unused, play what
/// follows it stage by stage.
pub const UPDATE_ENTRIES: [(&str, &str, &str, &str, Guard); 6] = [
    ("game_step_main", "game_decide", "GameState", "u32", None),
    (
        "game_claims_main",
        "game_claims",
        "GameState",
        "u32",
        Some(("task", "claims_pending")),
    ),
    (
        "game_flow_main",
        "game_flow",
        "GameState",
        "u32",
        Some(("task", "flow_pending")),
    ),
    (
        "game_settle_main",
        "game_settle",
        "GameState",
        "u32",
        Some(("task", "settle_pending")),
    ),
    ("game_mask_main", "game_mask", "GameState", "u32", None),
    ("game_deal_main", "game_deal", "GameState", "DealInput", None),
];

/// An update entry's guard: `(field, function)`, or none.
pub type Guard = Option<(&'static str, &'static str)>;

/// The read entry points, after [`UPDATE_ENTRIES`] in binding order: (entry point, kernel function
/// `fn(State, Arg) -> Out`, state struct, argument type, output struct). Each takes two binding
/// slots: at slot k its state (read-only) binds 1+2k, its arguments 2+2k and its output 3+2k.
pub const READ_ENTRIES: [(&str, &str, &str, &str, &str); 7] = [
    ("observe_planes_main", "observe_planes", "GameState", "u32", "ObsPlanes"),
    ("observe_tokens_main", "observe_tokens", "GameState", "u32", "ObsTokens"),
    ("observe_packed_main", "observe_packed", "GameState", "u32", "ObsPacked"),
    (
        "observe_analysis_main",
        "observe_analysis",
        "GameState",
        "u32",
        "ObsAnalysis",
    ),
    ("observe_oracle_main", "observe_oracle", "GameState", "u32", "ObsOracle"),
    ("agent_action_main", "game_agent_action", "GameState", "u32", "u32"),
    ("game_play_action_main", "game_play_action", "GameState", "u32", "u32"),
];
