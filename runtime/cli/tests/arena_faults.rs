//! `rinshan arena` fails the run when an MJAI bot faulted in most of its games: a bot that cannot
//! start (its Python lacked numpy) lost 8 of 8 games by penalty and the arena still exited 0, so
//! a script or CI job took the penalty's standing for the bot's play.

mod common;

use common::rinshan;
use std::process::Output;

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// An arena of 4 east games with `bot` in seat 1, spoken to over stdio.
fn arena(bot: &str, extra: &[&str]) -> Output {
    let agents = format!("defensive,{bot},rule,greedy");
    let base = [
        "arena",
        "--agents",
        &agents,
        "--mjai-dialect",
        "stdio",
        "--games",
        "4",
        "--mode",
        "east",
    ];
    rinshan(&[&base[..], extra].concat())
}

#[test]
fn a_bot_that_faults_in_every_game_fails_the_run_and_says_why() {
    // `false` exits at once: every game ends with the bot's penalty.
    let out = arena("mjai:false", &[]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("mjai:false faulted in 4 of its 4 games"), "{err}");
    assert!(err.contains("--max-fault-rate 0.5"), "{err}");
    // The report is still printed, faults included.
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(report.contains("4 bot faults"), "{report}");

    // The JSON report too, with the same status.
    let out = arena("mjai:false", &["--json"]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("the JSON report on stdout");
    assert_eq!(v["faults"].as_array().map(Vec::len), Some(4), "{v:#}");

    // A threshold of 1 never fails the run; one outside 0..1 is refused as bad input.
    let out = arena("mjai:false", &["--max-fault-rate", "1"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let out = arena("mjai:false", &["--max-fault-rate", "1.5"]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--max-fault-rate 1.5"), "{}", stderr(&out));
}

#[test]
fn a_bot_that_plays_every_game_passes() {
    let exe = env!("CARGO_BIN_EXE_rinshan");
    let out = arena(
        &format!("mjai:{exe} mjai-bot --agent defensive --dialect stdio"),
        &["--json"],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("the JSON report on stdout");
    assert_eq!(v["faults"], serde_json::json!([]));
}
