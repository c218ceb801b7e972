//! Real games are the judge of the red rules: every round of the Phoenix-room logs in
//! `tests/data/tenhou` replays through rinshan with every logged action legal and every score
//! change, win (han, fu, yaku) and draw as the log has it, on the CPU and on the GPU.

use std::path::PathBuf;

use rinshan_engine::env::Backend;
use rinshan_logs::tenhou::log::{collect_files, parse_game, read_game, Game};
use rinshan_logs::tenhou::plan::plan;
use rinshan_logs::tenhou::replay::{replay, replay_on_gpu, Report};
use rinshan_tests::test_data;

fn data_dir() -> PathBuf {
    test_data().join("tenhou")
}

fn all_games() -> Vec<Game> {
    let files = collect_files(&[data_dir()]).expect("the log folder lists");
    assert_eq!(files.len(), 21, "the log folder holds 21 games");
    files
        .iter()
        .map(|f| read_game(f).unwrap_or_else(|e| panic!("{e}")))
        .collect()
}

fn assert_all_agree(r: &Report) {
    for m in &r.mismatches {
        eprintln!("{m}");
    }
    // Counted from the files independently of rinshan (python over the JSON): 232 rounds, 188
    // wins in 187 rounds (one double ron), 45 drawn rounds.
    assert_eq!((r.games, r.rounds), (21, 232));
    assert_eq!((r.wins, r.draws), (188, 45));
    assert!(
        r.mismatches.is_empty(),
        "{} mismatches (listed above)",
        r.mismatches.len()
    );
    assert!(r.all_agree(), "{r:?}");
    assert_eq!(r.tables, 232 - 21);
}

#[test]
fn every_logged_round_agrees_on_the_cpu() {
    let report = replay(&all_games(), Backend::Cpu).expect("cpu replay");
    assert_all_agree(&report);
}

#[test]
fn every_logged_round_agrees_on_the_gpu() {
    let Some(gpu) = rinshan_tests::gpu_or_skip("tenhou_replay_gpu") else {
        return;
    };
    let games = all_games();
    let cpu = replay(&games, Backend::Cpu).expect("cpu replay");
    let gpu = replay_on_gpu(&games, gpu).expect("gpu replay");
    assert_all_agree(&gpu);
    assert_eq!(cpu, gpu);
}

/// The first game's text with one substitution in its `line`-th line (1-based).
fn edited(line: usize, from: &str, to: &str) -> Game {
    let path = data_dir().join("2010081709gm-00a9-0000-fe3371ad.json");
    let text = std::fs::read_to_string(&path).expect("log file");
    let lines: Vec<String> = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            if i + 1 == line {
                assert!(l.contains(from), "line {line} has `{from}`");
                l.replacen(from, to, 1)
            } else {
                l.to_string()
            }
        })
        .collect();
    parse_game("edited.json", &lines.join("\n")).expect("still a readable log")
}

#[test]
fn a_wrong_score_in_a_log_is_reported_with_file_and_round() {
    // East 1 is a 7700 ron by seat 1 from seat 2; claim 8700 instead.
    let game = edited(1, "[0,8700,-7700,0]", "[0,8700,-8700,0]");
    let r = replay(&[game], Backend::Cpu).expect("replay");
    assert!(!r.all_agree());
    let m = r
        .mismatches
        .iter()
        .find(|m| m.what == "score changes")
        .expect("a score mismatch");
    assert_eq!((m.file.as_str(), m.line), ("edited.json", 1));
    assert!(m.round.starts_with("East 1"), "{m}");
    // Only the edited round disagrees: the next round is dealt from its own logged table.
    assert_eq!(r.score_changes_matching, r.rounds - 1, "{:?}", r.mismatches);
}

#[test]
fn a_wrong_han_count_is_reported() {
    // The log's text and its yaku must add up, so both say one han more.
    let game = edited(
        1,
        "30符4飜7700点\",\"自風 南(1飜)\",\"混一色(2飜)",
        "30符5飜7700点\",\"自風 南(1飜)\",\"混一色(3飜)",
    );
    let r = replay(&[game], Backend::Cpu).expect("replay");
    let m = r
        .mismatches
        .iter()
        .find(|m| m.what == "han, fu and yaku")
        .expect("a yaku mismatch");
    assert!(m.log.contains("honitsu 3") && m.rinshan.contains("honitsu 2"), "{m}");
    assert_eq!(r.wins_matching, r.wins - 1);
}

#[test]
fn an_action_the_rules_forbid_is_reported_and_the_game_goes_on() {
    // The dealer's second discard (29 = 9p) becomes 27 (7p), a tile it does not hold.
    let game = edited(1, "[44,29,19,46,11,60", "[44,27,19,46,11,60");
    let r = replay(&[game], Backend::Cpu).expect("replay");
    let m = r.mismatches.first().expect("a mismatch");
    assert_eq!(m.what, "illegal logged action", "{m}");
    assert!(m.log.contains("discard 7p"), "{m}");
    assert_eq!(r.rounds_replayed, r.rounds - 1);
    assert_eq!(r.games_ended_right, 1, "the later rounds replay from their own tables");
}

/// Rounds of self-play games recorded as tenhou.net/6 logs where a seat passed a call and made
/// the same call on a later discard of the same tile from the same seat without drawing in
/// between (a pon elsewhere skipped its turn): the planner must find that the first discard was
/// not called.
#[test]
fn a_call_passed_and_made_on_a_later_discard_replays() {
    let text = std::fs::read_to_string(test_data().join("tenhou_passed_calls.json")).expect("test data");
    for (n, line) in text.lines().enumerate() {
        let game = parse_game(&format!("line {}", n + 1), line).unwrap_or_else(|e| panic!("{e}"));
        plan(&game.rounds[0]).unwrap_or_else(|e| panic!("line {}: {e}", n + 1));
        let report = replay(std::slice::from_ref(&game), Backend::Cpu).expect("cpu replay");
        // The games go on after these rounds; everything else must agree.
        assert_eq!(report.mismatches.len(), 1, "{:?}", report.mismatches);
        assert_eq!(report.mismatches[0].what, "game end");
        let r = &report;
        assert_eq!(
            (r.rounds_replayed, r.score_changes_matching, r.actions_accepted),
            (1, 1, r.actions)
        );
    }
}
