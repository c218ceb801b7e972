//! A log file as a user gives it to `rinshan replay`, `rinshan convert` or Python's
//! `rinshan.mjai.read`: bytes that may be gzipped, then MJAI events, Tenhou's mjlog XML or
//! tenhou.net/6 JSON, which the reader tells apart. Read, each round planned and stepped through, the game replayed,
//! written in both formats and read back: an error or a mismatch in the report, never a panic;
//! a game that reads converts to either format and back to the same game.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rinshan_engine::env::Backend;
use rinshan_logs::file::{game_text, parse_log, Format};
use rinshan_logs::tenhou::log::{Game, Outcome};
use rinshan_logs::tenhou::plan::plan;
use rinshan_logs::tenhou::position::round_replay;
use rinshan_logs::tenhou::replay::replay;

fn without_lines(mut game: Game) -> Game {
    // A round's line says where it stood in its source text, which each writer lays out anew;
    // which wins rinshan scored (their log gave no yaku) no format writes.
    for round in &mut game.rounds {
        round.line = 0;
        if let Outcome::Wins(wins) = &mut round.outcome {
            wins.iter_mut().for_each(|w| w.computed = false);
        }
    }
    game
}

fuzz_target!(|data: &[u8]| {
    let Ok((game, _)) = parse_log("fuzz", data) else { return };
    let mut plannable = true;
    for (i, round) in game.rounds.iter().enumerate() {
        plannable &= plan(round).is_ok();
        let _ = round_replay(&game, i);
    }
    let _ = replay(std::slice::from_ref(&game), Backend::Cpu);
    let game = without_lines(game);
    // tenhou.net/6 holds every game the reader gives.
    let tenhou = game_text(&game, Format::Tenhou).expect("a game writes as tenhou.net/6");
    let (back, _) = parse_log("fuzz", tenhou.as_bytes()).expect("its tenhou.net/6 text reads");
    assert_eq!(without_lines(back), game, "tenhou.net/6 reads back as the game");
    // MJAI lists events in the order of play, so a round must be plannable to be written.
    match game_text(&game, Format::Mjai) {
        Ok(mjai) => {
            let (back, format) = parse_log("fuzz", mjai.as_bytes()).expect("its MJAI text reads");
            assert_eq!(format, Format::Mjai);
            assert_eq!(without_lines(back), game, "MJAI reads back as the game");
        }
        Err(e) => assert!(!plannable, "every round plans, yet MJAI writing failed: {e}"),
    }
});
