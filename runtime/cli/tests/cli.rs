//! The `rinshan` binary as a user calls it: output shapes, exit codes and error messages.

mod common;

use common::{json, rinshan};
use std::process::Command;

#[test]
fn shanten_json_reports_every_form() {
    let v = json(&rinshan(&["shanten", "19m19p19s1234567z", "--json"]));
    assert_eq!(
        v,
        serde_json::json!({"shanten": 0, "normal": 8, "chiitoitsu": 6, "kokushi": 0})
    );
    let v = json(&rinshan(&["shanten", "123m456p789s11222z", "--json"]));
    assert_eq!(v["shanten"], -1);
}

#[test]
fn shanten_plain_prints_the_number() {
    let out = rinshan(&["shanten", "123m456p789s1122z"]);
    assert!(out.status.success());
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "0");
}

#[test]
fn score_tsumo_json_has_yaku_and_payments() {
    // riichi, menzen tsumo, pinfu, tanyao + dora 4m (indicator 3m): 5 han mangan, 2000/4000.
    let v = json(&rinshan(&[
        "score",
        "234567m234p456s66s",
        "--win",
        "6s",
        "--tsumo",
        "--riichi",
        "--dora",
        "3m",
        "--json",
    ]));
    assert_eq!(v["han"], 5);
    assert_eq!(v["fu"], 20);
    assert_eq!(v["yakuman"], 0);
    let names: Vec<&str> = v["yaku"]
        .as_array()
        .unwrap()
        .iter()
        .map(|y| y["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["riichi", "menzen_tsumo", "pinfu", "tanyao", "dora"]);
    assert_eq!(
        v["points"],
        serde_json::json!({"dealer_pays": 4000, "others_pay": 2000, "total": 8000})
    );
}

/// Three players: a tsumo is paid by two (tsumo loss), and the 1m indicator shows 9m.
#[test]
fn score_in_sanma_pays_a_tsumo_from_two_seats() {
    let hand = |variant: &str| {
        json(&rinshan(&[
            "score",
            "123p456p789s23s99m",
            "--win",
            "4s",
            "--tsumo",
            "--riichi",
            "--dora",
            "1m",
            "--variant",
            variant,
            "--json",
        ]))
    };
    // riichi, menzen tsumo, pinfu + dora 99m (indicator 1m, so 9m): 5 han mangan, 2000/4000.
    let v = hand("sanma");
    assert_eq!((v["han"].as_u64(), v["fu"].as_u64()), (Some(5), Some(20)), "{v}");
    assert_eq!(
        v["points"],
        serde_json::json!({"dealer_pays": 4000, "others_pay": 2000, "total": 6000})
    );
    // The same hand with four players: 2m is the dora, 8,000 in all for a mangan.
    let v = hand("red");
    assert_eq!(v["han"].as_u64(), Some(3), "{v}");
}

#[test]
fn score_ron_with_melds_honba_and_sticks() {
    // Dealer, hatsu pon + chi 123m, 123p 789s, tanki on haku: yakuhai 1 + open chanta 1 = 2 han;
    // fu 20 + 4 (open honor triplet) + 2 (dragon pair) + 2 (tanki) = 28 -> 30; 2 han 30 fu dealer
    // ron 2900 + 300 honba; the winner also takes 2 sticks.
    let v = json(&rinshan(&[
        "score",
        "123p789s5z",
        "--win",
        "5z",
        "--meld",
        "chi:123m",
        "--meld",
        "pon:666z",
        "--dealer",
        "--honba",
        "1",
        "--sticks",
        "2",
        "--json",
    ]));
    assert_eq!(v["han"], 2);
    assert_eq!(v["fu"], 30);
    assert_eq!(
        v["yaku"],
        serde_json::json!([{"name": "yakuhai_green", "han": 1}, {"name": "chanta", "han": 1}])
    );
    assert_eq!(v["points"], serde_json::json!({"ron": 3200, "total": 5200}));
}

#[test]
fn variant_changes_red_five_value() {
    let args = ["score", "234067m234p456s66s", "--win", "6s", "--tsumo", "--json"];
    let red = json(&rinshan(&args));
    let mut no_red_args = args.to_vec();
    no_red_args.extend(["--variant", "no-red"]);
    let no_red = json(&rinshan(&no_red_args));
    assert_eq!(
        red["han"].as_u64().unwrap(),
        no_red["han"].as_u64().unwrap() + 1,
        "aka counts only with red fives"
    );
}

#[test]
fn malformed_hands_exit_with_2_and_say_why() {
    for (args, needle) in [
        (vec!["shanten", "123x"], "unexpected `x`"),
        (vec!["shanten", "123"], "suit letter"),
        (vec!["shanten", "11111m"], "only 4"),
        (vec!["score", "123m", "--win", "1m"], "concealed tiles"),
        (vec!["score", "234567m234p456s66s", "--win", "9z"], "1z-7z"),
        (
            vec!["score", "234567m234p456s66s", "--win", "6s", "--meld", "pon:123m"],
            "identical",
        ),
        (
            vec!["score", "234567m234p456s66s", "--win", "6s", "--variant", "mystery"],
            "unknown variant",
        ),
        (
            vec!["score", "234567m234p456s66s", "--win", "6s", "--houtei", "--tsumo"],
            "houtei",
        ),
    ] {
        let out = rinshan(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn hands_that_do_not_win_exit_with_1() {
    let out = rinshan(&["score", "123456m123p456s1z", "--win", "2z"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a winning hand"));
    // Complete but open without a yaku.
    let out = rinshan(&[
        "score", "22m123s", "--win", "3s", "--meld", "chi:789m", "--meld", "chi:456p", "--meld", "pon:666p",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no yaku"));
}

#[test]
fn selfplay_with_the_same_seed_gives_the_same_summary() {
    let args = ["selfplay", "--games", "20", "--batch", "8", "--json", "--seed", "5"];
    let strip = |mut v: serde_json::Value| {
        let map = v.as_object_mut().expect("an object");
        for timing in ["seconds", "steps_per_second"] {
            assert!(map.remove(timing).is_some(), "{timing} reported");
        }
        v
    };
    let a = strip(json(&rinshan(&args)));
    let b = strip(json(&rinshan(&args)));
    assert_eq!(a, b);
    assert_eq!(a["games"], 20);
    assert_eq!(a["variant"], "red");
    assert!(a["avg_steps_per_game"].as_f64().unwrap() > 100.0, "{a}");
    assert!(a["rounds"].as_u64().unwrap() >= 20, "{a}");
    let scores: f64 = a["avg_final_score"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .sum();
    // Points are conserved; uma adds up to 0 and leftover sticks go to the winner.
    assert!((scores - 100_000.0).abs() < 1e-6, "{a}");
    let c = strip(json(&rinshan(&[
        "selfplay", "--games", "20", "--batch", "8", "--json", "--seed", "6",
    ])));
    assert_ne!(a, c, "another seed plays other games");
}

#[test]
fn selfplay_reports_each_agent_over_the_seats_it_played() {
    let v = json(&rinshan(&[
        "selfplay",
        "--games",
        "24",
        "--batch",
        "8",
        "--json",
        "--seed",
        "3",
        "--agents",
        "rule,greedy,rule,random",
    ]));
    let agents = v["per_agent"].as_array().expect("per_agent");
    let names: Vec<&str> = agents.iter().map(|a| a["agent"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        ["rule", "greedy", "random"],
        "one row per distinct agent, in --agents order"
    );
    let games: Vec<u64> = agents.iter().map(|a| a["games"].as_u64().unwrap()).collect();
    // rule sits in two of the four seats of every game.
    assert_eq!(games, [48, 24, 24]);
    // Every game hands out each place once.
    for place in 0..4 {
        let n: u64 = agents.iter().map(|a| a["ranks"][place].as_u64().unwrap()).sum();
        assert_eq!(n, 24, "place {place}: {v}");
    }
    for a in agents {
        let ranks: Vec<f64> = (0..4).map(|p| a["ranks"][p].as_f64().unwrap()).collect();
        let mean = ranks.iter().enumerate().map(|(p, n)| (p as f64 + 1.0) * n).sum::<f64>() / ranks.iter().sum::<f64>();
        assert!((a["mean_rank"].as_f64().unwrap() - mean).abs() < 1e-9, "{a}");
    }
    // The agents' scores and rates are the seats' ones regrouped: the same totals.
    let seat_scores: f64 = v["avg_final_score"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() * 24.0)
        .sum();
    let agent_scores: f64 = agents
        .iter()
        .map(|a| a["mean_score"].as_f64().unwrap() * a["games"].as_f64().unwrap())
        .sum();
    assert!((seat_scores - agent_scores).abs() < 1e-6, "{v}");
    let rounds = v["rounds"].as_f64().unwrap();
    let per_agent_sum = |key: &str| -> f64 {
        agents
            .iter()
            .map(|a| a[key].as_f64().unwrap() * a["rounds"].as_f64().unwrap())
            .sum()
    };
    // Each round has at most one ron victim and counts four seat-rounds.
    let deal_ins = v["deal_in_rate"].as_f64().unwrap() * rounds;
    assert!((per_agent_sum("deal_in_rate") - deal_ins).abs() < 1e-6, "{v}");
    let seat_rounds: f64 = agents.iter().map(|a| a["rounds"].as_f64().unwrap()).sum();
    assert!((seat_rounds - 4.0 * rounds).abs() < 1e-9, "{v}");
    // A double ron has two winners in one round: at least as many seat wins as winning rounds.
    let wins = v["win_rate"].as_f64().unwrap() * rounds;
    assert!(per_agent_sum("win_rate") >= wins - 1e-6, "{v}");
    // The text form has the table too.
    let out = rinshan(&[
        "selfplay",
        "--games",
        "8",
        "--batch",
        "8",
        "--agents",
        "rule,greedy,rule,random",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("per agent") && text.contains("greedy"), "{text}");
}

/// Three players: the rotation of four agents sits one out of each game; each game hands out
/// three places, and the points stay with the three seats.
#[test]
fn selfplay_plays_three_player_games() {
    let v = json(&rinshan(&[
        "selfplay",
        "--variant",
        "sanma",
        "--mode",
        "east",
        "--games",
        "24",
        "--batch",
        "8",
        "--json",
        "--seed",
        "5",
        "--agents",
        "rule,greedy,defensive,random",
    ]));
    assert_eq!(v["variant"], "sanma", "{v}");
    let agents = v["per_agent"].as_array().expect("per_agent");
    // Three of the four agents play each game.
    let games: Vec<u64> = agents.iter().map(|a| a["games"].as_u64().unwrap()).collect();
    assert!(
        games.len() == 4 && games.iter().sum::<u64>() == 72 && games.iter().all(|&n| n > 0),
        "{v}"
    );
    for place in 0..3 {
        let n: u64 = agents.iter().map(|a| a["ranks"][place].as_u64().unwrap()).sum();
        assert_eq!(n, 24, "place {place}: {v}");
    }
    assert!(
        agents
            .iter()
            .all(|a| a["ranks"].as_array().is_some_and(|r| r.len() == 3)),
        "{v}"
    );
    // Three seats of 35,000: the average final scores (uma included) share 105,000.
    let scores: Vec<f64> = v["avg_final_score"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(scores.len(), 3, "{v}");
    assert!((scores.iter().sum::<f64>() - 105_000.0).abs() < 1e-6, "{v}");
    assert!(v["win_rate"].as_f64().unwrap() > 0.3, "{v}");
    // A sanma log is written in both formats, replays (`selfplay_exports_games_that_replay` for
    // tenhou.net/6) and is drawn; the arena asks for three agents.
    let dir = std::env::temp_dir().join(format!("rinshan-sanma-export-{}", std::process::id()));
    let mjai = dir.join("mjai");
    let (log, mjai_log) = (dir.join("game-1.json"), mjai.join("game-1.mjson"));
    for (args, format) in [(&dir, "tenhou"), (&mjai, "mjai")] {
        let line = format!("selfplay --variant sanma --games 2 --batch 2 --export-format {format} --export");
        let args: Vec<&str> = line.split(' ').chain([args.to_str().unwrap()]).collect();
        let out = rinshan(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let v = json(&rinshan(&["replay", mjai.to_str().unwrap(), "--json"]));
    assert_eq!(
        (&v["all_agree"], &v["report"]["games"]),
        (&serde_json::json!(true), &serde_json::json!(2)),
        "{v}"
    );
    // The two exports played the same games: the MJAI one converts to the tenhou.net/6 one.
    let converted = rinshan(&["convert", &mjai_log.to_string_lossy(), "--to", "tenhou"]);
    let written = std::fs::read_to_string(&log).expect("the tenhou.net/6 export");
    assert_eq!(String::from_utf8_lossy(&converted.stdout), written);
    // The board draws three seats, from the log and from a seed.
    for args in [
        vec!["render", log.to_str().unwrap(), "--step", "20"],
        vec!["render", "--variant", "sanma", "--seed", "3", "--step", "40"],
    ] {
        let out = rinshan(&args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let svg = String::from_utf8_lossy(&out.stdout);
        let seats = svg.matches(r#"<g class="seat""#).count();
        assert_eq!(seats, 3, "{args:?}");
    }
    for (args, words) in [
        (
            vec!["arena", "--variant", "sanma", "--games", "4"],
            "not a positive multiple of 3",
        ),
        (
            vec![
                "arena",
                "--variant",
                "sanma",
                "--games",
                "3",
                "--agents",
                "rule,rule,rule,rule",
            ],
            "exactly 3 agents",
        ),
    ] {
        let out = rinshan(&args);
        let (err, text) = (
            String::from_utf8_lossy(&out.stderr),
            String::from_utf8_lossy(&out.stdout),
        );
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(words) || text.contains(words), "{args:?}: {err} {text}");
    }
    std::fs::remove_dir_all(&dir).ok();
    // The duplicate arena rotates three agents over three seats.
    let v = json(&rinshan(&[
        "arena",
        "--variant",
        "sanma",
        "--games",
        "30",
        "--mode",
        "east",
        "--json",
    ]));
    assert_eq!(
        (&v["games"], &v["variant"]),
        (&serde_json::json!(30), &serde_json::json!("sanma")),
        "{v}"
    );
    let standings = v["standings"].as_array().expect("standings");
    let names: Vec<&str> = standings.iter().filter_map(|s| s["agent"].as_str()).collect();
    assert_eq!(names.len(), 3, "{v}");
    for name in ["defensive", "greedy", "rule"] {
        assert!(names.contains(&name), "{v}");
    }
    for s in standings {
        let ranks: Vec<u64> = s["ranks"]
            .as_array()
            .expect("ranks")
            .iter()
            .filter_map(|r| r.as_u64())
            .collect();
        assert_eq!((ranks.len(), ranks.iter().sum::<u64>()), (3, 30), "{s}");
    }
    let mean: f64 = standings.iter().filter_map(|s| s["mean_rank"].as_f64()).sum::<f64>() / 3.0;
    assert!((mean - 2.0).abs() < 1e-9, "three places average 2: {v}");
}

#[test]
fn selfplay_help_says_who_plays() {
    for args in [&["--help"][..], &["selfplay", "--help"]] {
        let out = rinshan(args);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(!text.contains("Random-policy"), "{text}");
        assert!(text.contains("built-in agents"), "{text}");
    }
}

#[test]
fn selfplay_rejects_bad_options() {
    for (args, needle) in [
        (vec!["selfplay", "--mode", "long"], "unknown mode"),
        (vec!["selfplay", "--backend", "tpu"], "unknown backend"),
        (vec!["selfplay", "--batch", "0"], "batch size"),
        (vec!["selfplay", "--variant", "blue"], "unknown variant"),
    ] {
        let out = rinshan(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// Three players take three agents (each then plays every game) or four (each sits out one game in
/// four); any other count is refused.
#[test]
fn selfplay_seats_three_agents_at_three_player_tables() {
    let line = "selfplay --variant sanma --games 6 --batch 3 --seed 4 --json --agents rule,greedy,defensive";
    let v = json(&rinshan(&line.split(' ').collect::<Vec<_>>()));
    let agents = v["per_agent"].as_array().expect("per agent");
    assert_eq!(agents.len(), 3, "{v}");
    assert!(agents.iter().all(|a| a["games"] == 6), "{v}");
    let four = json(&rinshan(&[
        "selfplay",
        "--variant",
        "sanma",
        "--games",
        "8",
        "--batch",
        "4",
        "--seed",
        "4",
        "--json",
    ]));
    let games: Vec<u64> = four["per_agent"]
        .as_array()
        .expect("per agent")
        .iter()
        .filter_map(|a| a["games"].as_u64())
        .collect();
    // Three seats a game: 24 seat-games among four agents, each sitting some games out.
    assert_eq!((games.len(), games.iter().sum::<u64>()), (4, 24), "{four}");
    assert!(games.iter().all(|&g| g < 8), "{four}");
    let out = rinshan(&["selfplay", "--variant", "sanma", "--agents", "rule,greedy"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--agents needs 3 agents"), "{err}");
}

/// Games of each rule set exported as tenhou.net/6 replay under that rule set, one folder at a
/// time and all together.
#[test]
fn selfplay_exports_games_that_replay() {
    let root = std::env::temp_dir().join(format!("rinshan-export-{}", std::process::id()));
    for variant in ["red", "mleague", "no-red", "sanma"] {
        let dir = root.join(variant);
        let path = dir.to_str().expect("utf-8 path");
        let line = format!("selfplay --games 6 --batch 4 --json --seed 9 --variant {variant}");
        let args: Vec<&str> = line.split(' ').collect();
        let plain = json(&rinshan(&args));
        let exported = json(&rinshan(&[&args[..], &["--export", path]].concat()));
        // Exporting plays the same games.
        assert_eq!(plain["rounds"], exported["rounds"]);
        let mut files: Vec<String> = std::fs::read_dir(&dir)
            .expect("the export folder")
            .map(|e| e.expect("an entry").file_name().to_string_lossy().into_owned())
            .collect();
        files.sort();
        let mut expected: Vec<String> = (1..=6).map(|n| format!("game-{n}.json")).collect();
        expected.sort();
        assert_eq!(files, expected);
        let texts: Vec<String> = files
            .iter()
            .map(|f| std::fs::read_to_string(dir.join(f)).expect("a game"))
            .collect();
        let rounds: usize = texts.iter().map(|t| t.lines().count()).sum();
        assert_eq!(serde_json::json!(rounds), plain["rounds"], "one line per round");
        let named = texts.iter().all(|t| t.contains(&format!("\"variant\":\"{variant}\"")));
        assert_eq!(named, variant != "red", "{variant}: {}", texts[0]);
        let v = json(&rinshan(&["replay", path, "--json"]));
        assert_eq!(v["all_agree"], true, "{v}");
    }
    let dirs: Vec<String> = ["red", "mleague", "no-red", "sanma"]
        .iter()
        .map(|v| root.join(v).to_string_lossy().into_owned())
        .collect();
    let args: Vec<&str> = ["replay", "--json"]
        .into_iter()
        .chain(dirs.iter().map(String::as_str))
        .collect();
    let all = json(&rinshan(&args));
    assert_eq!(
        (&all["all_agree"], &all["report"]["games"]),
        (&serde_json::json!(true), &serde_json::json!(24)),
        "{all}"
    );
    std::fs::remove_dir_all(&root).ok();
}

/// `replay --variant` plays logs that do not name their rule set (a converted Mahjong Soul log)
/// under the rule set given: M-League games without their name disagree with Tenhou's rules
/// and agree with M-League's; a log with red fives is refused for a rule set without them.
#[test]
fn replay_under_a_rule_set_the_logs_do_not_name() {
    let root = std::env::temp_dir().join(format!("rinshan-unnamed-{}", std::process::id()));
    let (named, unnamed) = (root.join("named"), root.join("unnamed"));
    let path = |p: &std::path::Path| p.to_str().expect("utf-8 path").to_string();
    let args: Vec<&str> = "selfplay --games 6 --batch 4 --seed 9 --variant mleague"
        .split(' ')
        .collect();
    let out = rinshan(&[&args[..], &["--export", &path(&named)]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    std::fs::create_dir_all(&unnamed).expect("a folder");
    for entry in std::fs::read_dir(&named).expect("the export") {
        let file = entry.expect("an entry").path();
        let text = std::fs::read_to_string(&file).expect("a log");
        let stripped = text.replace(",\"variant\":\"mleague\"", "");
        assert_ne!(stripped, text);
        std::fs::write(unnamed.join(file.file_name().expect("a name")), stripped).expect("written");
    }
    let out = rinshan(&["replay", &path(&unnamed), "--json"]);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let as_red: serde_json::Value = serde_json::from_slice(&out.stdout).expect("a JSON report");
    assert_eq!(as_red["all_agree"], false, "{as_red}");
    let as_mleague = json(&rinshan(&["replay", &path(&unnamed), "--variant", "mleague", "--json"]));
    assert_eq!(as_mleague["all_agree"], true, "{as_mleague}");
    // MJAI names it too (start_game's "variant"): the same games as MJAI replay under it as they are.
    let mjai = root.join("mjai");
    let out = rinshan(&[&args[..], &["--export", &path(&mjai), "--export-format", "mjai"]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let as_mleague = json(&rinshan(&["replay", &path(&mjai), "--json"]));
    assert_eq!(as_mleague["all_agree"], true, "{as_mleague}");
    let out = rinshan(&["replay", &path(&unnamed), "--variant", "wrc"]);
    assert_eq!(out.status.code(), Some(2));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("the log plays red fives, wrc has none"), "{text}");
    std::fs::remove_dir_all(&root).ok();
}

#[test]
fn selfplay_export_says_what_it_needs() {
    for (options, needle) in [
        (&["--backend", "gpu"][..], "--backend cpu"),
        (&["--mode", "single"][..], "east or half"),
    ] {
        let args = [&["selfplay", "--games", "1"][..], options, &["--export", "/tmp/unused"]].concat();
        let out = rinshan(&args);
        assert_eq!(out.status.code(), Some(2), "{options:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{options:?}: {err}");
    }
}

const LOGS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/tenhou");

#[test]
fn replay_of_the_real_logs_agrees_everywhere() {
    let out = rinshan(&["replay", LOGS]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("replayed 21 games"), "{text}");
    assert!(
        text.contains("every round and every win agrees with the logs"),
        "{text}"
    );
    let v = json(&rinshan(&["replay", LOGS, "--json"]));
    assert_eq!(v["all_agree"], true);
    assert_eq!(v["report"]["rounds"], 232);
    assert_eq!(v["report"]["rounds_replayed"], 232);
    assert_eq!(v["report"]["mismatches"], serde_json::json!([]));
}

#[test]
fn replay_lists_each_mismatch_with_file_round_and_step() {
    let dir = std::env::temp_dir().join(format!("rinshan-replay-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let source = std::fs::read_to_string(format!("{LOGS}/2010081709gm-00a9-0000-fe3371ad.json")).expect("log");
    // East 1: a 7700 ron from the seat whose riichi stick went too (-8700 in all); the edited
    // result says 8700 for the ron, so the log has -9700 for that seat.
    let edited = source.replacen("[0,8700,-7700,0]", "[0,8700,-8700,0]", 1);
    let file = dir.join("edited.json");
    std::fs::write(&file, edited).expect("write");
    let out = rinshan(&["replay", file.to_str().expect("utf-8 path")]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains(
            "edited.json:1 (East 1, 0 honba), step 89: score changes: log says [0, 8700, -9700, 0]; rinshan says [0, 8700, -8700, 0]"
        ),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn replay_rejects_unreadable_logs_with_exit_2() {
    let out = rinshan(&["replay", "/no/such/log.json"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/no/such/log.json"));
    let dir = std::env::temp_dir().join(format!("rinshan-replay-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("bad.json");
    std::fs::write(&file, "{\"log\": [[[0,0,0]]]}\n").expect("write");
    let out = rinshan(&["replay", file.to_str().expect("utf-8 path")]);
    assert_eq!(out.status.code(), Some(2));
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("bad.json: line 1"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}

const MJLOGS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjlog");

#[test]
fn convert_goes_between_the_formats_and_each_replays() {
    let dir = std::env::temp_dir().join(format!("rinshan-convert-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let xml = format!("{MJLOGS}/2019021004gm-00a9-0000-e2f6516d.xml");
    let twin = std::fs::read_to_string(format!("{MJLOGS}/2019021004gm-00a9-0000-e2f6516d.json")).expect("log");
    // mjlog XML -> MJAI (gzipped, by the name) -> tenhou.net/6 on standard output.
    let mjai = dir.join("game.mjson.gz");
    let out = rinshan(&["convert", &xml, "-o", mjai.to_str().expect("utf-8 path")]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&mjai).expect("written");
    assert_eq!(bytes[..2], [0x1f, 0x8b], "gzipped");
    let v = json(&rinshan(&["replay", mjai.to_str().expect("utf-8 path"), "--json"]));
    assert_eq!(v["all_agree"], true, "{v}");
    let out = rinshan(&["convert", mjai.to_str().expect("utf-8 path")]);
    assert!(out.status.success());
    let tenhou = String::from_utf8_lossy(&out.stdout).into_owned();
    // Tenhou's own JSON of the game holds every round in one record; the converted text has a
    // line per round, with the same rounds.
    let rounds: Vec<serde_json::Value> = tenhou
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).expect("a record")["log"][0].clone())
        .collect();
    let original: serde_json::Value = serde_json::from_str(&twin).expect("JSON");
    assert_eq!(serde_json::Value::from(rounds), original["log"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn convert_of_a_folder_reports_bad_files_and_writes_the_rest() {
    let dir = std::env::temp_dir().join(format!("rinshan-convert-dir-{}", std::process::id()));
    let input = dir.join("in");
    std::fs::create_dir_all(&input).expect("temp dir");
    std::fs::copy(
        format!("{LOGS}/2010081709gm-00a9-0000-fe3371ad.json"),
        input.join("a.json"),
    )
    .expect("copy");
    std::fs::copy(
        format!("{MJLOGS}/2019103023gm-00a9-0000-f90e0fe9.xml"),
        input.join("b.xml"),
    )
    .expect("copy");
    std::fs::write(
        input.join("c.mjson"),
        "{\"type\":\"start_game\"}\n{\"type\":\"dahai\"}\n",
    )
    .expect("write");
    let output = dir.join("out");
    let out = rinshan(&[
        "convert",
        input.to_str().expect("utf-8 path"),
        "-o",
        output.to_str().expect("utf-8 path"),
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(text.contains("converted 2 of 3 logs"), "{text}");
    assert!(text.contains("c.mjson: line 2"), "{text}");
    let mut written: Vec<String> = std::fs::read_dir(&output)
        .expect("the output folder")
        .map(|e| e.expect("an entry").file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    // tenhou.net/6 becomes MJAI, mjlog becomes tenhou.net/6.
    assert_eq!(written, ["a.mjson", "b.json"]);
    let v = json(&rinshan(&["replay", output.to_str().expect("utf-8 path"), "--json"]));
    assert_eq!(v["all_agree"], true, "{v}");
    assert_eq!(v["report"]["games"], 2);
    std::fs::remove_dir_all(&dir).ok();
}

/// The Python of the test virtualenv with PyPI's `mjai` and `riichienv` (`.ci/mjai-venv`; see
/// runtime/logs/tests/mjai_libriichi.rs); `None` says so outside CI, where it may be missing.
fn mjai_python() -> Option<String> {
    match std::env::var("RINSHAN_MJAI_PYTHON") {
        Ok(p) if !p.is_empty() => Some(p),
        _ if std::env::var("CI").is_ok_and(|v| v == "true") => panic!("RINSHAN_MJAI_PYTHON is not set"),
        _ => {
            eprintln!("RINSHAN_MJAI_PYTHON is not set: the checks against mjai and riichienv do not run here");
            None
        }
    }
}

/// `rinshan arena --json` for 4 games with `agents`, bots spoken to in `dialect`.
fn arena_json(agents: &str, dialect: &str, mode: &str) -> serde_json::Value {
    // A bot that faults in every game still gets its report here (the exit status for a faulting
    // bot is tests/arena_faults.rs's).
    json(&rinshan(&[
        "arena",
        "--agents",
        agents,
        "--mjai-dialect",
        dialect,
        "--games",
        "4",
        "--mode",
        mode,
        "--max-fault-rate",
        "1",
        "--json",
    ]))
}

/// The standing of `name` in an arena report.
fn standing<'a>(v: &'a serde_json::Value, name: &str) -> &'a serde_json::Value {
    v["standings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["agent"] == name)
        .expect("the agent played")
}

fn simple_bot(extra: &str) -> String {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/bots/simple_bot.py");
    format!("mjai:python3 {script} {extra}")
}

#[test]
fn arena_seats_an_mjai_bot_and_reports_its_faults() {
    let bot = simple_bot("--dialect stdio");
    let v = arena_json(&format!("defensive,{bot},rule,greedy"), "stdio", "east");
    assert_eq!(v["faults"], serde_json::json!([]));
    let me = standing(&v, &bot);
    assert_eq!((me["games"].as_u64(), me["illegal"].as_u64()), (Some(4), Some(0)));

    let bot = simple_bot("--dialect app --mode garbage");
    let v = arena_json(&format!("defensive,{bot},rule,greedy"), "app", "east");
    let faults = v["faults"].as_array().unwrap();
    assert_eq!(faults.len(), 4);
    assert!(
        faults[0]["message"].as_str().unwrap().contains("not JSON"),
        "{faults:?}"
    );
    assert_eq!(standing(&v, &bot)["ranks"], serde_json::json!([0, 0, 0, 4]));
}

#[test]
fn arena_seats_an_mjai_bot_at_three_player_tables() {
    let bot = simple_bot("--dialect app");
    let agents = format!("{bot},rule,greedy");
    let v = json(&rinshan(&[
        "arena",
        "--variant",
        "sanma",
        "--agents",
        &agents,
        "--mjai-dialect",
        "app",
        "--games",
        "3",
        "--mode",
        "east",
        "--json",
    ]));
    assert_eq!(v["faults"], serde_json::json!([]));
    let me = standing(&v, &bot);
    assert_eq!((me["games"].as_u64(), me["illegal"].as_u64()), (Some(3), Some(0)));
}

#[test]
fn arena_refuses_bad_mjai_seats() {
    for (args, says) in [
        (
            vec!["--agents", "defensive,mjai:,rule,greedy"],
            "needs the bot's command line",
        ),
        (
            vec!["--agents", "defensive,mjai:x,rule,greedy", "--mode", "single"],
            "east or half games",
        ),
        (
            vec!["--agents", "defensive,mjai:x,rule,greedy", "--variant", "no-red"],
            "--variant red",
        ),
        (
            vec!["--agents", "defensive,mjai:x,rule,greedy", "--mjai-timeout", "0"],
            "--mjai-timeout 0",
        ),
        (
            vec!["--agents", "defensive,mjai:x,rule,greedy", "--mjai-dialect", "tcp"],
            "unknown MJAI dialect",
        ),
        (vec!["--agents", "defensive,mjia:x,rule,greedy"], "mjai:COMMAND"),
    ] {
        let out = rinshan(&[&["arena", "--games", "4"], args.as_slice()].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

#[test]
fn serve_refuses_bad_mjai_bots() {
    // Refused before the server listens: nothing starts.
    for (args, says) in [
        (vec!["--mjai-bot", "nocommand"], "give NAME=COMMAND"),
        (vec!["--mjai-bot", "=x"], "give NAME=COMMAND"),
        (vec!["--mjai-bot", "a b=x"], "a bot's name is letters"),
        (vec!["--mjai-bot", "a=x", "--mjai-bot", "a=y"], "two bots are named `a`"),
        (vec!["--mjai-bot", "a=x", "--mjai-timeout", "0"], "--mjai-timeout 0"),
    ] {
        let out = rinshan(&[&["serve", "--no-data-dir", "--port", "0"], args.as_slice()].concat());
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

/// The arena's report without the names: standings by average rank, then the faults.
fn standings_of(v: &serde_json::Value) -> Vec<serde_json::Value> {
    v["standings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            let mut s = s.clone();
            s["agent"] = serde_json::Value::Null;
            s
        })
        .collect()
}

#[test]
fn mjai_bot_plays_exactly_as_the_built_in_agent_in_both_dialects() {
    // The bot rebuilds the engine's state from what its seat saw; an agent that draws no random
    // numbers (greedy, defensive) then makes the decisions it makes in the engine, so the games
    // are the same ones.
    let exe = env!("CARGO_BIN_EXE_rinshan");
    let base = ["--games", "8", "--mode", "half", "--seed", "4", "--json"];
    let builtin = json(&rinshan(
        &[&["arena", "--agents", "random,defensive,greedy,rule"], &base[..]].concat(),
    ));
    for dialect in ["app", "stdio"] {
        let agents = format!("random,mjai:{exe} mjai-bot --agent defensive --dialect {dialect},greedy,rule");
        let args = [&["arena", "--agents", &agents, "--mjai-dialect", dialect], &base[..]].concat();
        let v = json(&rinshan(&args));
        assert_eq!(v["faults"], serde_json::json!([]), "{dialect}");
        assert_eq!(standings_of(&v), standings_of(&builtin), "{dialect}");
    }
}

#[test]
fn mjai_bot_answers_every_line_and_says_what_it_could_not_read() {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .args(["mjai-bot", "--agent", "greedy"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run rinshan");
    let hand = r#"["1m","2m","3m","4p","5p","6p","7s","8s","9s","E","E","P","P"]"#;
    let q = r#"["?","?","?","?","?","?","?","?","?","?","?","?","?"]"#;
    let lines = [
        r#"[{"type":"start_game","id":1,"names":["a","b","c","d"]}]"#.to_string(),
        "this is not JSON".to_string(),
        r#"[{"type":"teleport","actor":1}]"#.to_string(),
        format!(
            r#"[{{"type":"start_kyoku","bakaze":"E","dora_marker":"1s","kyoku":1,"honba":0,"kyotaku":0,"oya":0,"scores":[25000,25000,25000,25000],"tehais":[{q},{hand},{q},{q}]}},{{"type":"tsumo","actor":0,"pai":"?"}},{{"type":"dahai","actor":0,"pai":"9m","tsumogiri":true}}]"#
        ),
        r#"[{"type":"tsumo","actor":1,"pai":"N"}]"#.to_string(),
        r#"[{"type":"dahai","actor":1,"pai":"N","tsumogiri":true},{"type":"tsumo","actor":2,"pai":"?"},{"type":"dahai","actor":2,"pai":"P","tsumogiri":false}]"#.to_string(),
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
    // Nothing to decide at the start, on garbage, or on a 9m it cannot call.
    assert!(replies[..4].iter().all(|r| r["type"] == "none"), "{replies:?}");
    // Its own draw: tenpai (123m 456p 789s EE PP waits on E and P), so riichi or a discard.
    assert_eq!(replies[4]["actor"], 1, "{replies:?}");
    assert!(
        ["dahai", "reach"].contains(&replies[4]["type"].as_str().unwrap()),
        "{replies:?}"
    );
    // A P from seat 2 completes the hand (haku): ron.
    assert_eq!(
        replies[5],
        serde_json::json!({"type": "hora", "actor": 1, "target": 2, "pai": "P"})
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("not JSON") && err.contains("not an MJAI event"), "{err}");
}

#[test]
fn mjai_bot_reactions_pass_libriichi() {
    // The `mjai` package of PyPI in its test virtualenv (see runtime/logs/tests/mjai_libriichi.rs).
    let Some(python) = mjai_python() else { return };
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/bots/checked_bot.py");
    let inner = format!(
        "{} mjai-bot --dialect stdio --agent defensive",
        env!("CARGO_BIN_EXE_rinshan")
    );
    let bot = format!("mjai:{python} {script} --inner '{inner}'");
    let v = arena_json(&format!("{bot},greedy,{bot},rule"), "stdio", "half");
    assert_eq!(v["faults"], serde_json::json!([]));
    let me = standing(&v, &bot);
    assert_eq!((me["games"].as_u64(), me["illegal"].as_u64()), (Some(8), Some(0)));
}

#[test]
fn mjai_logs_replay_in_riichienv_with_every_decision_legal_and_every_win_scored_alike() {
    riichienv_replays("red", "tenhou");
}

/// Mahjong Soul's rules against RiichiEnv's `default_mjsoul()` preset.
#[test]
fn mjsoul_mjai_logs_replay_in_riichienv_under_its_mahjong_soul_rules() {
    riichienv_replays("mjsoul", "mjsoul");
}

/// Three players: RiichiEnv replays them under its Tenhou preset, scoring with its three-player
/// evaluator (kita as nukidora, tsumo loss).
#[test]
fn sanma_mjai_logs_replay_in_riichienv_with_every_kita_legal_and_every_win_scored_alike() {
    let stats = riichienv_replays("sanma", "tenhou");
    if stats.is_null() {
        return;
    }
    assert_eq!(stats["3-player games"], 40, "{stats}");
    assert!(stats["kitas"].as_u64() > Some(200), "{stats}");
}

/// Mahjong Soul's three-player rules under RiichiEnv's `default_mjsoul()` preset.
#[test]
fn mjsoul_sanma_mjai_logs_replay_in_riichienv_under_its_mahjong_soul_rules() {
    let stats = riichienv_replays("mjsoul-sanma", "mjsoul");
    if !stats.is_null() {
        assert_eq!(stats["3-player games"], 40, "{stats}");
    }
}

/// 40 half games of `variant` exported as MJAI and replayed in RiichiEnv under its `rule` preset;
/// the check's counts (`serde_json::Value::Null` where the test virtualenv is missing).
fn riichienv_replays(variant: &str, rule: &str) -> serde_json::Value {
    // PyPI's riichienv in the test virtualenv (see runtime/logs/tests/mjai_libriichi.rs); the
    // check and RiichiEnv's replay quirks it corrects: tests/data/mjai/riichienv_check.py.
    let Some(python) = mjai_python() else {
        return serde_json::Value::Null;
    };
    let dir = std::env::temp_dir().join(format!("rinshan-riichienv-{variant}-{}", std::process::id()));
    let export = dir.to_string_lossy().to_string();
    let out = rinshan(&[
        "selfplay",
        "--variant",
        variant,
        "--games",
        "40",
        "--batch",
        "8",
        "--seed",
        "3",
        "--export",
        &export,
        "--export-format",
        "mjai",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/riichienv_check.py");
    let out = Command::new(python)
        .args([script, &export, rule])
        .output()
        .expect("run python");
    let _ = std::fs::remove_dir_all(&dir);
    let report: serde_json::Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|_| panic!("no report: {}", String::from_utf8_lossy(&out.stderr)));
    assert!(out.status.success(), "{report}");
    assert_eq!(report["rule"], rule);
    let stats = &report["stats"];
    assert_eq!(stats["games"], 40);
    assert!(
        stats["decisions"].as_u64() > Some(10_000) && stats["wins"].as_u64() > Some(100),
        "{report}"
    );
    stats.clone()
}

#[test]
fn selfplay_seats_mjai_bots_that_play_the_same_games_as_the_agents_they_run() {
    let exe = env!("CARGO_BIN_EXE_rinshan");
    let base = [
        "selfplay", "--games", "8", "--batch", "4", "--mode", "east", "--seed", "9", "--json",
    ];
    let summary = |agents: &str, extra: &[&str]| json(&rinshan(&[&base[..], &["--agents", agents], extra].concat()));
    let builtin = summary("greedy,rule,defensive,random", &[]);
    for dialect in ["app", "stdio"] {
        let bot = format!("mjai:{exe} mjai-bot --agent defensive --dialect {dialect}");
        let v = summary(&format!("greedy,rule,{bot},random"), &["--mjai-dialect", dialect]);
        assert_eq!(v["bot_faults"], 0, "{dialect}");
        for field in ["steps", "rounds", "avg_final_score", "yaku"] {
            assert_eq!(v[field], builtin[field], "{dialect}: {field}");
        }
        let by_name = |v: &serde_json::Value, name: &str| {
            let a = v["per_agent"]
                .as_array()
                .unwrap()
                .iter()
                .find(|a| a["agent"] == name)
                .cloned();
            a.map(|mut a| {
                a["agent"] = serde_json::Value::Null;
                a
            })
        };
        assert_eq!(by_name(&v, &bot), by_name(&builtin, "defensive"), "{dialect}");
    }
    let out = rinshan(
        &[
            &base[..],
            &["--agents", "greedy,rule,mjai:x,random", "--backend", "gpu"],
        ]
        .concat(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--backend cpu"));
}

/// The connection cap leaves room under the process's descriptor limit (for bots' pipes and saved
/// games): lowered to fit, or refused with what to do when nothing fits.
#[cfg(unix)]
#[test]
fn serve_fits_its_connections_to_the_descriptor_limit() {
    use std::io::BufRead as _;
    let exe = env!("CARGO_BIN_EXE_rinshan");
    let under = |n: u32| {
        let mut c = Command::new("sh");
        c.args([
            "-c",
            &format!("ulimit -n {n} && exec \"$0\" serve --no-data-dir --port 0"),
            exe,
        ]);
        c
    };
    let out = under(150).output().expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("descriptor limit (150)") && err.contains("ulimit -n"),
        "{err}"
    );

    let mut child = under(400).stdout(std::process::Stdio::piped()).spawn().expect("starts");
    let stdout = child.stdout.take().expect("its output");
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stdout).lines().map_while(Result::ok) {
            let _ = tx.send(line);
        }
    });
    let mut said = Vec::new();
    while let Ok(line) = rx.recv_timeout(std::time::Duration::from_secs(20)) {
        let done = line.contains("connections at once");
        said.push(line);
        if done {
            break;
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    // 400 descriptors, 64 kept for the process and 3 for each of the 48 bot processes.
    assert!(
        said.iter().any(|l| l.contains("192 connections at once, not 16384")),
        "{said:?}"
    );
}

#[test]
fn outlook_ranks_the_discard_that_keeps_tenpai_first() {
    let out = rinshan(&[
        "outlook",
        "123456789m1145p9s",
        "--draws",
        "12",
        "--trials",
        "4000",
        "--json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let first = &v["discards"][0];
    assert_eq!(
        (first["discard"].as_str(), first["shanten"].as_i64()),
        (Some("9s"), Some(0))
    );
    // Eight winning tiles among 122 unseen, 12 draws: 1 - C(114,12)/C(122,12) = 0.5745.
    let win = first["win"][11].as_f64().expect("a chance");
    assert!((win - 0.5745).abs() < 0.04, "{win}");
    let out = rinshan(&["outlook", "123m"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("3k+2"));
    let out = rinshan(&["outlook", "123456789m1145p9s", "--seen", "99999s"]);
    assert_eq!(out.status.code(), Some(2));
}
