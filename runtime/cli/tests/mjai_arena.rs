//! MJAI logs written by libriichi's arena (mjai.app's and Mortal's engine), whose `hora` carries
//! no yaku, fu or han and whose `ryukyoku` no reason: `replay` agrees on every round, `convert`
//! goes to tenhou.net/6 (with the yaku rinshan scored) and back, and `dataset` skips nothing.
//!
//! The logs are the fixtures in tests/data/mjai/arena (made by tests/data/mjai/arena_logs.py),
//! and, where the test virtualenv is (`RINSHAN_MJAI_PYTHON`, see
//! runtime/logs/tests/mjai_libriichi.rs), games the arena plays in the test itself.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn rinshan(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .args(args)
        .output()
        .expect("run rinshan")
}

fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "stdout: {}\nstderr: {}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

fn data(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data")
        .join(path)
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rinshan-arena-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

fn text(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 path")
}

/// `rinshan replay --json` of `logs`: the report, after checking that every log was read and
/// every round agrees.
fn replay(logs: &Path) -> serde_json::Value {
    let v = json(&rinshan(&["replay", text(logs), "--json"]));
    assert_eq!(v["unreadable"], serde_json::json!([]), "{v:#}");
    assert_eq!(v["all_agree"], true, "{v:#}");
    let r = &v["report"];
    assert_eq!(r["rounds_replayed"], r["rounds"], "{r:#}");
    assert_eq!(r["score_changes_matching"], r["rounds"], "{r:#}");
    assert_eq!(r["tables_matching"], r["tables"], "{r:#}");
    r.clone()
}

fn count(r: &serde_json::Value, key: &str) -> u64 {
    r[key].as_u64().unwrap_or_else(|| panic!("{key} in {r:#}"))
}

/// The whole round trip over the MJAI logs in `logs` (`games` of them), written by the arena.
fn check_arena_logs(logs: &Path, games: u64, name: &str) {
    let r = replay(logs);
    assert_eq!(count(&r, "games"), games);
    assert_eq!(count(&r, "games_ended_right"), games);
    // The arena names no yaku: every win is judged by its score changes and the next round.
    assert!(count(&r, "wins") > 0);
    assert_eq!(count(&r, "wins_matching"), 0);
    assert_eq!(count(&r, "wins_yaku_not_logged"), count(&r, "wins"));
    assert_eq!(count(&r, "draws_matching"), count(&r, "draws"));

    // tenhou.net/6 needs each win's yaku: it gets rinshan's, which then agree as logged yaku.
    let tenhou = scratch(&format!("{name}-tenhou"));
    let out = rinshan(&["convert", text(logs), "-o", text(&tenhou), "--to", "tenhou"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let t = replay(&tenhou);
    assert_eq!(
        (count(&t, "wins_matching"), count(&t, "wins")),
        (count(&r, "wins"), count(&r, "wins"))
    );
    assert_eq!(count(&t, "rounds"), count(&r, "rounds"));

    let back = scratch(&format!("{name}-back"));
    let out = rinshan(&["convert", text(&tenhou), "-o", text(&back), "--to", "mjai"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let b = replay(&back);
    assert_eq!(
        (count(&b, "wins_matching"), count(&b, "rounds")),
        (count(&r, "wins"), count(&r, "rounds"))
    );

    let dataset = scratch(&format!("{name}-dataset"));
    let out = text(&dataset).to_string() + "/out";
    let d = json(&rinshan(&[
        "dataset",
        text(logs),
        "-o",
        &out,
        "--quiet",
        "--json",
        "--threads",
        "1",
    ]));
    assert_eq!(d["skipped"], serde_json::json!([]), "{d:#}");
    assert_eq!(d["games"], games, "{d:#}");
    assert!(d["rows"].as_u64().is_some_and(|n| n > 1000), "{d:#}");
    for dir in [tenhou, back, dataset] {
        let _ = std::fs::remove_dir_all(dir);
    }
}

#[test]
fn the_arena_fixtures_replay_convert_both_ways_and_make_datasets() {
    check_arena_logs(&data("mjai/arena"), 3, "fixtures");
}

/// The Python of the test virtualenv with PyPI's `mjai`; `None` says so outside CI.
fn mjai_python() -> Option<String> {
    match std::env::var("RINSHAN_MJAI_PYTHON") {
        Ok(p) if !p.is_empty() => Some(p),
        _ if std::env::var("CI").is_ok_and(|v| v == "true") => panic!("RINSHAN_MJAI_PYTHON is not set"),
        _ => {
            eprintln!("RINSHAN_MJAI_PYTHON is not set: the arena's fresh logs are not made here");
            None
        }
    }
}

#[test]
fn logs_the_arena_writes_now_replay_convert_both_ways_and_make_datasets() {
    let Some(python) = mjai_python() else { return };
    let logs = scratch("fresh");
    let seeds = ["2", "3", "4", "6", "8", "9", "10", "11"];
    let out = Command::new(python)
        .arg(data("mjai/arena_logs.py"))
        .arg(&logs)
        .args(seeds)
        .output()
        .expect("run arena_logs.py");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // Real games: wins, riichi, calls and draws.
    let mut kinds = std::collections::BTreeMap::<String, usize>::new();
    for entry in std::fs::read_dir(&logs).expect("the logs") {
        let path = entry.expect("a log").path();
        let bytes = std::fs::read(&path).expect("read a log");
        let unpacked = rinshan_logs::file::log_text(text(&path), &bytes).expect("a gzipped log");
        for line in unpacked.lines() {
            let event: serde_json::Value = serde_json::from_str(line).expect("an event");
            *kinds
                .entry(event["type"].as_str().unwrap_or_default().to_string())
                .or_default() += 1;
        }
    }
    for kind in ["hora", "reach", "pon", "chi", "ryukyoku"] {
        assert!(kinds.get(kind).is_some_and(|&n| n > 0), "no {kind}: {kinds:?}");
    }
    check_arena_logs(&logs, seeds.len() as u64, "fresh");
    let _ = std::fs::remove_dir_all(logs);
}
