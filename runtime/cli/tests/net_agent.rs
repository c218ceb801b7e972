//! Trained nets where the command line seats them (`net:PATH`): the arena, self-play, `mjai-bot`
//! (playing exactly as the net seated directly) and the web server's `--net`, with clear errors
//! for a file that cannot be played. The nets here have random weights: the point is the seating.

mod common;

use std::path::PathBuf;

use common::{json, rinshan};
use rinshan_net::random::{net_file, Shape};

/// A random net's file, written once per name.
fn net(name: &str, seed: u64) -> PathBuf {
    net_of(name, seed, Shape::default())
}

fn net_of(name: &str, seed: u64, shape: Shape) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rinshan-cli-net-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(format!("{name}.safetensors"));
    std::fs::write(&path, net_file(shape, seed)).expect("write the net");
    path
}

/// Per player, its name and the rest of its standing (ranks, scores, per-round rates).
fn standings(v: &serde_json::Value) -> Vec<(String, serde_json::Value)> {
    v["standings"]
        .as_array()
        .expect("standings")
        .iter()
        .map(|s| {
            let mut rest = s.clone();
            rest["agent"] = serde_json::Value::Null;
            assert!(rest["mean_rank"].is_number(), "{s}");
            (s["agent"].as_str().unwrap_or_default().to_string(), rest)
        })
        .collect()
}

#[test]
fn the_arena_seats_a_net_and_its_games_do_not_depend_on_the_threads() {
    let path = net("arena", 1);
    let agents = format!("net:{},defensive,rule,greedy", path.display());
    let run = |threads: &str| {
        json(&rinshan(&[
            "arena",
            "--agents",
            &agents,
            "--games",
            "8",
            "--mode",
            "east",
            "--seed",
            "2",
            "--threads",
            threads,
            "--json",
        ]))
    };
    let one = run("1");
    let names: Vec<String> = standings(&one).into_iter().map(|(n, _)| n).collect();
    assert!(names.contains(&format!("net:{}", path.display())), "{names:?}");
    assert_eq!(one["faults"], serde_json::json!([]));
    assert_eq!(standings(&one), standings(&run("2")));
}

#[test]
fn mjai_bot_plays_a_net_exactly_as_the_arena_seats_it() {
    // The bot rebuilds the state from what its seat saw; the net reads only that seat's
    // observation, so its decisions, and the games, are the same ones.
    let exe = env!("CARGO_BIN_EXE_rinshan");
    let path = net("mjai", 4);
    let base = ["--games", "4", "--mode", "east", "--seed", "6", "--json"];
    let direct = format!("net:{},defensive,greedy,rule", path.display());
    let seated = json(&rinshan(&[&["arena", "--agents", &direct], &base[..]].concat()));
    let bot = format!(
        "mjai:{exe} mjai-bot --agent net:{},defensive,greedy,rule",
        path.display()
    );
    let v = json(&rinshan(&[&["arena", "--agents", &bot], &base[..]].concat()));
    assert_eq!(v["faults"], serde_json::json!([]));
    let rest = |v: &serde_json::Value| standings(v).into_iter().map(|(_, r)| r).collect::<Vec<_>>();
    assert_eq!(rest(&v), rest(&seated));
}

#[test]
fn a_net_sits_at_a_three_player_table() {
    // The nets' actions hold kita, so the same file plays sanma's three seats.
    let path = net("sanma", 8);
    let agents = format!("net:{},defensive,rule", path.display());
    let v = json(&rinshan(&[
        "arena",
        "--variant",
        "sanma",
        "--agents",
        &agents,
        "--games",
        "6",
        "--mode",
        "east",
        "--seed",
        "3",
        "--json",
    ]));
    assert_eq!(v["faults"], serde_json::json!([]));
    let me = standings(&v)
        .into_iter()
        .find(|(n, _)| n == &format!("net:{}", path.display()))
        .expect("the net's standing");
    assert_eq!((me.1["games"].as_u64(), me.1["illegal"].as_u64()), (Some(6), Some(0)));
}

#[test]
fn selfplay_seats_a_net() {
    let path = net("selfplay", 5);
    let agents = format!("net:{},rule,rule,rule", path.display());
    let v = json(&rinshan(&[
        "selfplay", "--agents", &agents, "--games", "8", "--batch", "4", "--mode", "single", "--json",
    ]));
    assert_eq!(v["games"], 8);
    let text = v.to_string();
    assert!(text.contains(&format!("net:{}", path.display())), "{text}");
}

#[test]
fn a_net_that_cannot_be_played_is_refused_with_the_reason() {
    let missing = "/nonexistent/rinshan/net.safetensors";
    let out = rinshan(&["arena", "--agents", &format!("net:{missing},rule,rule,rule")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains(missing));
    let out = rinshan(&["arena", "--agents", "net:,rule,rule,rule"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("`net:` needs the path"));
    // A net saved in red's actions alone (before kita joined the nets' layout) cannot play sanma.
    let path = net_of("red-only", 6, Shape::red_only());
    let out = rinshan(&[
        "arena",
        "--variant",
        "sanma",
        "--agents",
        &format!("net:{},rule,rule", path.display()),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no logit for kita"));
    let out = rinshan(&[
        "selfplay",
        "--backend",
        "gpu",
        "--agents",
        &format!("net:{},rule,rule,rule", path.display()),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--backend cpu"));
    let out = rinshan(&["serve", "--net", &format!("a={missing}")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--net a:"));
    let out = rinshan(&["serve", "--net", "a b=x"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("a net's name is letters"));
}
