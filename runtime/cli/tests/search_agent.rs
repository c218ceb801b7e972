//! The look-ahead agent where the command line seats it: the arena (with its totals in the
//! report), self-play, `mjai-bot --agent search`, the reviewer (`review`), and clear errors for a
//! bad setting or a backend that cannot seat it.

mod common;

use common::rinshan;
use std::io::Write;
use std::process::{Command, Stdio};

#[test]
fn the_arena_seats_the_look_ahead_and_reports_its_totals() {
    let out = rinshan(&[
        "arena",
        "--agents",
        "search:rollouts=8:focus=all,defensive,defensive,defensive",
        "--games",
        "4",
        "--mode",
        "single",
        "--json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let names: Vec<&str> = report["standings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["agent"].as_str().unwrap())
        .collect();
    assert!(names.contains(&"search:rollouts=8:focus=all"), "{names:?}");
    let totals = &report["search"][0];
    let decisions = totals["decisions"].as_u64().unwrap();
    let searched = totals["searched"].as_u64().unwrap();
    assert!(searched > 0 && searched <= decisions, "{totals}");
    assert!(totals["rollouts"].as_u64().unwrap() >= searched * 4, "{totals}");
    assert!(report["faults"].as_array().unwrap().is_empty());
}

#[test]
fn a_bad_search_setting_is_refused_with_what_is_wrong() {
    let out = rinshan(&["arena", "--agents", "search:depth=3,defensive,defensive,defensive"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown search option `depth`"));
    let out = rinshan(&[
        "selfplay",
        "--backend",
        "gpu",
        "--agents",
        "search,defensive,defensive,defensive",
        "--games",
        "1",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--backend cpu"));
}

/// Self-play seats the look-ahead where --agents puts it: one that all but never overrides its base
/// agent plays `defensive`'s games exactly, and one that follows every play-out's verdict plays
/// others. (A margin of 1,000 standard errors still lets through a gain that every duel world
/// agrees on to the last digit, whose spread is 0; at 8 play-outs, two duel worlds, one such
/// decision in these games does.)
#[test]
fn selfplay_seats_the_look_ahead() {
    let run = |first: &str| -> serde_json::Value {
        let agents = format!("{first},defensive,defensive,defensive");
        let out = rinshan(&[
            "selfplay", "--agents", &agents, "--games", "8", "--batch", "4", "--mode", "single", "--seed", "3",
            "--json",
        ]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice(&out.stdout).expect("JSON")
    };
    let base = run("defensive");
    let never = run("search:rollouts=64:focus=all:margin=1000");
    let eager = run("search:rollouts=64:focus=all:margin=0");
    for key in ["steps", "rounds", "avg_final_score", "yaku"] {
        assert_eq!(never[key], base[key], "{key}");
    }
    assert_ne!(
        (&eager["steps"], &eager["avg_final_score"]),
        (&base["steps"], &base["avg_final_score"])
    );
    let first = &eager["per_agent"][0];
    assert_eq!(first["agent"], "search:rollouts=64:margin=0:focus=all");
    // Env i seats the list rotated by i: over 4 envs the look-ahead plays every seat.
    assert_eq!(first["games"], 8);
}

#[test]
fn mjai_bot_decides_with_the_look_ahead() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .args(["mjai-bot", "--agent", "search:rollouts=16:focus=all"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run rinshan");
    let hand = r#"["1m","2m","3m","4p","5p","6p","7s","8s","9s","E","E","P","P"]"#;
    let q = r#"["?","?","?","?","?","?","?","?","?","?","?","?","?"]"#;
    let lines = [
        r#"[{"type":"start_game","id":1,"names":["a","b","c","d"]}]"#.to_string(),
        format!(
            r#"[{{"type":"start_kyoku","bakaze":"E","dora_marker":"1s","kyoku":1,"honba":0,"kyotaku":0,"oya":0,"scores":[25000,25000,25000,25000],"tehais":[{q},{hand},{q},{q}]}},{{"type":"tsumo","actor":0,"pai":"?"}},{{"type":"dahai","actor":0,"pai":"9m","tsumogiri":true}}]"#
        ),
        r#"[{"type":"tsumo","actor":1,"pai":"N"}]"#.to_string(),
    ];
    let mut stdin = child.stdin.take().unwrap();
    for line in &lines {
        writeln!(stdin, "{line}").unwrap();
    }
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success());
    let replies: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(replies.len(), lines.len(), "one reply per line");
    // Its own draw, tenpai on E and P: riichi, or a discard (the North keeps the hand).
    assert_eq!(replies[2]["actor"], 1, "{replies:?}");
    assert!(
        ["dahai", "reach"].contains(&replies[2]["type"].as_str().unwrap()),
        "{replies:?}"
    );
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn review_judges_a_players_decisions_in_a_real_log() {
    let log = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/tenhou/2019060813gm-00a9-0000-08bb0ec3.json"
    );
    let html = std::env::temp_dir().join(format!("rinshan-review-{}.html", std::process::id()));
    let html_arg = html.display().to_string();
    let out = rinshan(&[
        "review",
        log,
        "--player",
        "Aさん",
        "--round",
        "0",
        "--search",
        "search:rollouts=32",
        "--json",
        "-o",
        &html_arg,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let review: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(review["seat"], 0);
    assert_eq!(review["search"], "search:rollouts=32");
    let decisions = review["decisions"].as_array().expect("decisions");
    assert_eq!(decisions.len() as u64, review["game"]["decisions"].as_u64().unwrap());
    assert!(decisions.len() >= 10, "{} decisions", decisions.len());
    for d in decisions {
        let candidates = d["candidates"].as_array().expect("candidates");
        assert!(candidates.len() >= 2, "{d}");
        assert!(candidates.iter().any(|c| c["action"] == d["played"]), "{d}");
    }
    let page = std::fs::read_to_string(&html).expect("the report is written");
    let _ = std::fs::remove_file(&html);
    assert!(page.starts_with("<!doctype html>") && page.contains("Aさん"));

    // The text form lists the rounds.
    let out = rinshan(&[
        "review",
        log,
        "--seat",
        "0",
        "--round",
        "0",
        "--search",
        "search:rollouts=16",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("East 1, 0 honba"));

    // Bad input: an unknown player (the players are listed), a bad budget, a seat past the table.
    for (args, says) in [
        (vec!["--player", "nobody"], "seat 0 `Aさん`"),
        (vec!["--seat", "0", "--search", "search:rollouts=0"], "needs a budget"),
        (vec!["--seat", "5"], "seats 0..3"),
        (vec!["--seat", "0", "--round", "99"], "no round 99"),
    ] {
        let out = rinshan(&[&["review", log][..], &args].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

#[test]
fn observe_adds_the_deciding_seats_outlook() {
    let log = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/tenhou/2019060813gm-00a9-0000-08bb0ec3.json"
    );
    // Step 0 of East 1: the dealer's first discard.
    let out = rinshan(&["observe", log, "--step", "0", "--outlook", "--worlds", "16", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let alone = &v["outlook"]["alone"];
    assert_eq!(alone["draws"], 18, "{alone}");
    let discards = alone["discards"].as_array().expect("discards");
    let in_play = v["outlook"]["in_play"].as_array().expect("in play");
    assert!(!discards.is_empty() && in_play.len() >= discards.len(), "{v}");
    for o in in_play {
        assert_eq!(o["worlds"], 16, "{o}");
        let (win, deal_in) = (o["win"].as_f64().unwrap(), o["deal_in"].as_f64().unwrap());
        assert!((0.0..=1.0).contains(&(win + deal_in)), "{o}");
    }
    let text = rinshan(&["observe", log, "--step", "0", "--outlook", "--worlds", "8"]);
    assert!(String::from_utf8_lossy(&text.stdout).contains("outlook with every seat played by defensive"));
    // Another seat's odds are not the deciding seat's to give.
    let out = rinshan(&["observe", log, "--step", "0", "--seat", "2", "--outlook"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("deciding seat"));
}
