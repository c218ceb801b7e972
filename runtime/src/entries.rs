// Shared by build.rs (which asks the translator for these entry points) and the GPU backend.
/// The kernel entry points of every generated WGSL module: (entry point, kernel function, input
/// struct, output struct), in binding order (the k-th entry binds input 1+2k and output 2+2k).
pub const ENTRIES: [(&str, &str, &str, &str); 4] = [
    ("shanten_main", "shanten", "ShantenInput", "ShantenOutput"),
    ("score_main", "score_hand", "ScoreInput", "ScoreOutput"),
    ("game_new_main", "game_new", "ResetInput", "GameState"),
    ("game_view_main", "game_view", "GameState", "StepView"),
];
