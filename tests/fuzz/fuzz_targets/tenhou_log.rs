//! A tenhou.net/6 log as a user gives it (`rinshan replay`, the replay page's upload, Python's
//! `rinshan.tenhou.read`): read, each round planned in turn order and stepped through for the
//! replay page, the game replayed through the engine, written back. An error or a mismatch in the
//! report, never a panic; a log that reads writes out as a log that reads back the same.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rinshan_engine::env::Backend;
use rinshan_logs::tenhou::log::parse_game;
use rinshan_logs::tenhou::plan::plan;
use rinshan_logs::tenhou::position::round_replay;
use rinshan_logs::tenhou::replay::replay;
use rinshan_logs::tenhou::write::game_text;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(game) = parse_game("fuzz", text) else { return };
    for (i, round) in game.rounds.iter().enumerate() {
        let _ = plan(round);
        let _ = round_replay(&game, i);
    }
    let _ = replay(std::slice::from_ref(&game), Backend::Cpu);
    let written = game_text(&game);
    let mut back = parse_game("fuzz", &written).expect("a log that was read writes out as one that reads");
    // A round's line says where it stood in its source text, which the writer lays out anew.
    let mut game = game;
    for round in game.rounds.iter_mut().chain(back.rounds.iter_mut()) {
        round.line = 0;
    }
    assert_eq!(back, game, "the written log reads back as the game read");
});
