//! The builder against an independent path (each round replayed alone, one env, its observations
//! computed from the game state by `observe::record`), and its promises: the same bytes for the
//! same inputs whatever the threads, resuming, bad logs skipped with their reasons.

use std::path::{Path, PathBuf};

use rinshan_engine::observe::{record as observe_record, Form};
use rinshan_engine::Variant;
use rinshan_logs::read_log;
use rinshan_logs::tenhou::position::round_positions;

use crate::manifest::Manifest;
use crate::record::{record, Options, Outcome, Seats, DEFAULT_VARIANT as VARIANT};
use crate::{build, Build};

fn data(dir: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data").join(dir)
}

fn logs(dir: &str, ext: &str) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(data(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    out.sort();
    out
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rinshan-dataset-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn options(forms: &[Form]) -> Options {
    Options {
        variant: VARIANT,
        forms: forms.to_vec(),
        seats: Seats::All,
        forced: false,
        search: None,
    }
}

/// Every file of `dir`, name -> bytes.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let name = p.strip_prefix(dir).unwrap().display().to_string();
                out.push((name, std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn rows_are_the_decisions_of_each_round_replayed_alone() {
    let forms = [Form::Planes, Form::Tokens];
    let paths: Vec<PathBuf> = logs("tenhou", "json")
        .into_iter()
        .take(6)
        .chain(logs("mjlog", "xml"))
        .collect();
    let games: Vec<_> = paths.iter().map(|p| read_log(p).unwrap()).collect();
    // Each game in the rules it was played under (the three-player mjlog under sanma).
    assert!(games.iter().any(|g| g.variant == Variant::Sanma));
    let mut checked = 0;
    for game in &games {
        let variant = game.variant;
        let na = rinshan_engine::env::action_names(variant).len();
        let options = Options {
            variant,
            ..options(&forms)
        };
        let outcome = &record(std::slice::from_ref(game), &options).unwrap()[0];
        let Outcome::Rows(rows) = outcome else {
            panic!("{}: {outcome:?}", game.path);
        };
        let mut row = 0;
        for r in 0..game.rounds.len() {
            for p in round_positions(game, r).unwrap() {
                let mask = p.state.mask;
                let legal = mask.iter().map(|w| w.count_ones()).sum::<u32>();
                if legal < 2 {
                    continue;
                }
                assert_eq!(rows.round[row] as usize, r);
                assert_eq!(rows.seat[row] as u32, p.seat);
                assert_eq!(
                    rows.action[row] as u32, p.action,
                    "{} round {r} step {}",
                    game.path, p.step
                );
                for a in 0..na {
                    let bit = mask[a / 32] >> (a % 32) & 1;
                    assert_eq!(u32::from(rows.mask[row * na + a]), bit);
                }
                for (f, &form) in forms.iter().enumerate() {
                    let want = observe_record(variant, form, &p.state, p.seat);
                    let got = &rows.observations[f][row * form.bytes()..(row + 1) * form.bytes()];
                    assert!(
                        got == want.as_slice(),
                        "{} round {r} step {}: {form}",
                        game.path,
                        p.step
                    );
                }
                row += 1;
            }
        }
        assert_eq!(row, rows.rows(), "{}", game.path);
        checked += row;
        // The final standings: the scores sum to the starting points (no sticks left over at the
        // end: the top seat takes them), and the ranks are a permutation ordered by score.
        let seats = variant.seats() as usize;
        let start: i32 = game.rounds[0].scores.iter().sum();
        assert_eq!(rows.scores.iter().sum::<i32>(), start, "{}", game.path);
        let mut ranks = rows.ranks[..seats].to_vec();
        ranks.sort();
        assert_eq!(ranks, (0..seats as u8).collect::<Vec<_>>());
        for a in 0..seats {
            for b in 0..seats {
                if rows.ranks[a] < rows.ranks[b] {
                    assert!(rows.scores[a] >= rows.scores[b], "{}: {rows:?}", game.path);
                }
            }
        }
    }
    assert!(checked > 5_000, "{checked}");
}

#[test]
fn seat_and_player_filters_and_forced_rows() {
    let games = vec![read_log(&logs("tenhou", "json")[0]).unwrap()];
    let all = |o: &Options| match &record(&games, o).unwrap()[0] {
        Outcome::Rows(r) => r.clone(),
        other => panic!("{other:?}"),
    };
    let every = all(&options(&[]));
    let with_forced = all(&Options {
        forced: true,
        ..options(&[])
    });
    assert!(with_forced.rows() >= every.rows());
    let seat2 = all(&Options {
        seats: Seats::Some([false, false, true, false]),
        ..options(&[])
    });
    assert!(seat2.rows() > 0 && seat2.seat.iter().all(|&s| s == 2));
    assert_eq!(seat2.rows(), every.seat.iter().filter(|&&s| s == 2).count());
    let name = games[0].names[2].clone();
    let player = all(&Options {
        seats: Seats::Players(vec![name]),
        ..options(&[])
    });
    assert_eq!(player.action, seat2.action);
    assert!(every.observations.is_empty() || every.observations.iter().all(Vec::is_empty));
}

fn run(inputs: &[PathBuf], out: &Path, threads: usize, per_shard: usize) -> Result<crate::Summary, String> {
    build(
        &Build {
            inputs: inputs.iter().map(|p| p.display().to_string()).collect(),
            out: out.to_path_buf(),
            options: options(&[Form::Planes]),
            inputs_per_shard: per_shard,
            threads,
        },
        &mut |_| {},
    )
}

#[test]
fn the_same_inputs_give_the_same_bytes_and_a_stopped_run_resumes() {
    let inputs: Vec<PathBuf> = logs("tenhou", "json").into_iter().take(5).collect();
    let (a, b) = (scratch("one-thread"), scratch("two-threads"));
    let first = run(&inputs, &a, 1, 2).unwrap();
    assert_eq!((first.shards_written, first.inputs, first.games), (3, 5, 5));
    assert!(first.skipped.is_empty(), "{:?}", first.skipped);
    run(&inputs, &b, 2, 2).unwrap();
    assert!(files(&a) == files(&b), "thread count changed the bytes");

    // A run stopped after its first shard: the manifest lists one; the later folders may hold
    // anything (here: garbage in a half-written one).
    let mut m = Manifest::load(&b).unwrap().unwrap();
    m.shards.truncate(1);
    m.save(&b).unwrap();
    std::fs::write(b.join("shard-000001/action.npy"), b"cut off").unwrap();
    let resumed = run(&inputs, &b, 2, 2).unwrap();
    assert_eq!((resumed.shards_resumed, resumed.shards_written), (1, 2));
    assert_eq!(resumed.total_rows, first.rows);
    assert!(files(&a) == files(&b), "the resumed dataset differs");

    // Other inputs, other options or a folder of something else are refused, and nothing is lost.
    let other: Vec<PathBuf> = logs("tenhou", "json").into_iter().skip(1).take(5).collect();
    let err = run(&other, &b, 1, 2).unwrap_err();
    assert!(err.contains("other inputs"), "{err}");
    let err = run(&inputs, &b, 1, 3).unwrap_err();
    assert!(err.contains("other options"), "{err}");
    assert!(files(&a) == files(&b));
    let c = scratch("occupied");
    std::fs::write(c.join("notes.txt"), "mine").unwrap();
    assert!(run(&inputs, &c, 1, 2).unwrap_err().contains("not empty"));
    for d in [a, b, c] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn bad_logs_are_skipped_with_file_and_reason_and_the_rest_is_kept() {
    let dir = scratch("bad");
    let good = logs("tenhou", "json")[0].clone();
    let text = std::fs::read_to_string(&good).unwrap();
    std::fs::copy(&good, dir.join("a-good.json")).unwrap();
    // A gzip cut in half, XML that breaks off, a discard of a tile the hand does not hold.
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    std::io::Write::write_all(&mut gz, text.as_bytes()).unwrap();
    let gz = gz.finish().unwrap();
    std::fs::write(dir.join("b-truncated.json.gz"), &gz[..gz.len() / 2]).unwrap();
    std::fs::write(
        dir.join("c-broken.xml"),
        "<mjloggm ver=\"2.3\"><GO type=\"169\" lobby=\"0\"/><UN n0=",
    )
    .unwrap();
    let four_player = logs("mjlog", "xml")
        .into_iter()
        .find(|p| read_log(p).unwrap().variant == VARIANT)
        .unwrap();
    let xml = std::fs::read_to_string(four_player).unwrap();
    let first_discard = xml.find("<D").unwrap();
    let end = xml[first_discard..].find("/>").unwrap() + first_discard;
    let illegal = format!("{}<D135{}", &xml[..first_discard], &xml[end..]);
    std::fs::write(dir.join("d-illegal.xml"), illegal).unwrap();
    let out = scratch("bad-out");
    let s = run(std::slice::from_ref(&dir), &out, 2, 2).unwrap();
    assert_eq!((s.inputs, s.games), (4, 1), "{:?}", s.skipped);
    let reasons: Vec<(String, String)> = s.skipped.iter().map(|k| (k.input.clone(), k.reason.clone())).collect();
    assert_eq!(reasons.len(), 3, "{reasons:?}");
    assert!(
        reasons[0].0.ends_with("b-truncated.json.gz") && reasons[0].1.contains("gzip"),
        "{reasons:?}"
    );
    assert!(
        reasons[1].0.ends_with("c-broken.xml") && reasons[1].1.contains("c-broken.xml"),
        "{reasons:?}"
    );
    assert!(
        reasons[2].0.ends_with("d-illegal.xml") && reasons[2].1.contains("d-illegal.xml"),
        "{reasons:?}"
    );
    let m = Manifest::load(&out).unwrap().unwrap();
    assert_eq!(m.shards[0].games.len(), 1);
    assert_eq!(m.shards.iter().map(|s| s.skipped.len()).sum::<usize>(), 3);
    std::fs::remove_dir_all(dir).unwrap();
    std::fs::remove_dir_all(out).unwrap();
}

/// A dataset holds one action layout: a game of another rule set is skipped with its reason, and
/// the red games beside it keep their rows.
#[test]
fn games_of_other_rule_sets_are_skipped() {
    let paths = logs("tenhou", "json");
    let red = read_log(&paths[0]).unwrap();
    let mleague = rinshan_logs::tenhou::log::Game {
        variant: rinshan_engine::Variant::Mleague,
        path: "other.json".into(),
        ..red.clone()
    };
    let outcomes = record(&[mleague, red], &options(&[Form::Planes])).unwrap();
    match &outcomes[0] {
        Outcome::Skipped(why) => assert!(why.contains("played under mleague"), "{why}"),
        other => panic!("{other:?}"),
    }
    assert!(matches!(outcomes[1], Outcome::Rows(_)), "{:?}", outcomes[1]);
    // The three-player mjlog is a game of sanma: skipped from a red dataset, kept in a sanma one.
    let sanma = logs("mjlog", "xml")
        .into_iter()
        .map(|p| read_log(&p).unwrap())
        .find(|g| g.variant == Variant::Sanma)
        .unwrap();
    let red_rows = record(std::slice::from_ref(&sanma), &options(&[])).unwrap();
    match &red_rows[0] {
        Outcome::Skipped(why) => assert!(
            why.contains("played under sanma, and this dataset holds games of red"),
            "{why}"
        ),
        other => panic!("{other:?}"),
    }
    let sanma_options = Options {
        variant: Variant::Sanma,
        ..options(&[])
    };
    assert!(matches!(record(&[sanma], &sanma_options).unwrap()[0], Outcome::Rows(_)));
}

/// tests/data/mjlog holds each Tenhou game as mjlog XML and as tenhou.net/6 JSON (and one
/// three-player game as XML only): the two files of a game have one key, two games never do.
#[test]
fn a_game_has_one_key_in_both_formats() {
    let mut keys: Vec<(String, crate::same::GameKey)> = std::fs::read_dir(data("mjlog"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .map(|p| {
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            (stem, crate::same::game_key(&read_log(&p).unwrap()))
        })
        .collect();
    keys.sort();
    let pairs = keys.windows(2).filter(|w| w[0].0 == w[1].0).count();
    assert_eq!(pairs, 6, "{keys:?}");
    for (i, (a, ka)) in keys.iter().enumerate() {
        for (b, kb) in &keys[i + 1..] {
            assert_eq!(a == b, ka == kb, "{a} and {b}");
        }
    }
}

/// A game that comes in two inputs gives its rows once, from the first input in order; the later
/// one is reported as its duplicate, in the summary and the manifest, with any threads, across
/// shards and across a resumed run.
#[test]
fn a_game_in_two_formats_is_kept_once() {
    let inputs = [data("mjlog")];
    let (a, b) = (scratch("dup-one-thread"), scratch("dup-two-threads"));
    let s = run(&inputs, &a, 1, 1).unwrap();
    // 13 files: 6 games twice, and a three-player game a red dataset skips.
    assert_eq!(
        (s.inputs, s.games, s.duplicates.len(), s.skipped.len()),
        (13, 6, 6, 1),
        "{s:?}"
    );
    for d in &s.duplicates {
        let stem = |n: &str| Path::new(n).file_stem().unwrap().to_string_lossy().into_owned();
        assert_eq!(stem(&d.input), stem(&d.same_as), "{d:?}");
        assert!(d.input.ends_with(".xml") && d.same_as.ends_with(".json"), "{d:?}");
    }
    let m = Manifest::load(&a).unwrap().unwrap();
    let listed: Vec<_> = m.shards.iter().flat_map(|s| s.duplicates.iter().cloned()).collect();
    assert_eq!(listed, s.duplicates);
    // The same rows as a dataset of one file per game.
    let json_only: Vec<PathBuf> = logs("mjlog", "json");
    let c = scratch("dup-json-only");
    let one = run(&json_only, &c, 1, 1).unwrap();
    assert_eq!((one.games, one.rows), (s.games, s.rows));

    run(&inputs, &b, 2, 1).unwrap();
    assert!(files(&a) == files(&b), "thread count changed the bytes");
    // Stopped after the three-player game and the first four-player game's JSON: its XML, the
    // next shard, is still its duplicate.
    let mut m = Manifest::load(&b).unwrap().unwrap();
    assert!(m.shards[1].inputs[0].ends_with("e2f6516d.json"), "{:?}", m.shards[1]);
    m.shards.truncate(2);
    m.save(&b).unwrap();
    let resumed = run(&inputs, &b, 2, 1).unwrap();
    assert_eq!((resumed.shards_resumed, resumed.games), (2, 5), "{resumed:?}");
    assert!(resumed.duplicates[0].same_as.ends_with("e2f6516d.json"), "{resumed:?}");
    assert_eq!(resumed.duplicates.len(), 6, "{resumed:?}");
    assert!(files(&a) == files(&b), "the resumed dataset differs");
    for d in [a, b, c] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

/// The look-ahead's labels on people's games: added beside rows that stay as they were, legal,
/// the base agent's choice wherever the look-ahead left a decision to it, valued where it played
/// actions out, and the same whichever games a game is replayed with.
#[test]
fn look_ahead_labels_are_legal_and_the_base_agents_where_it_looked_at_nothing() {
    let paths: Vec<PathBuf> = logs("tenhou", "json").into_iter().take(2).collect();
    let games: Vec<_> = paths.iter().map(|p| read_log(p).unwrap()).collect();
    let plain = options(&[Form::Planes]);
    let labelled = Options {
        search: Some("search:rollouts=16:focus=all".into()),
        ..plain.clone()
    };
    let base = rinshan_engine::agents::Agent::Defensive;
    let na = rinshan_engine::env::action_names(VARIANT).len();
    let without = record(&games, &plain).unwrap();
    let with = record(&games, &labelled).unwrap();
    let alone = record(&games[1..], &labelled).unwrap();
    let (mut valued, mut left) = (0, 0);
    for ((game, a), b) in games.iter().zip(&without).zip(&with) {
        let (Outcome::Rows(a), Outcome::Rows(b)) = (a, b) else {
            panic!("{}: {a:?} {b:?}", game.path);
        };
        assert_eq!(
            (&a.observations, &a.mask, &a.action),
            (&b.observations, &b.mask, &b.action)
        );
        assert!(a.search_action.is_empty() && a.search_value.is_empty());
        assert_eq!((b.search_action.len(), b.search_value.len()), (b.rows(), b.rows() * na));
        let positions: Vec<Vec<_>> = (0..game.rounds.len())
            .map(|r| round_positions(game, r).unwrap())
            .collect();
        for row in 0..b.rows() {
            let chosen = b.search_action[row] as usize;
            assert_eq!(b.mask[row * na + chosen], 1, "{} row {row}: illegal label", game.path);
            let values = &b.search_value[row * na..(row + 1) * na];
            let (round, step) = b.at[row];
            let state = &positions[round][step].state;
            if values.iter().all(|v| v.is_nan()) {
                assert_eq!(chosen as u32, base.act(VARIANT, state), "{} row {row}", game.path);
                left += 1;
                continue;
            }
            valued += 1;
            assert!(
                !values[chosen].is_nan(),
                "{} row {row}: the label has no value",
                game.path
            );
            for (action, v) in values.iter().enumerate() {
                // Minus the expected final place (0 = first), and only for legal actions.
                assert!(v.is_nan() || (b.mask[row * na + action] == 1 && (-3.0..=0.0).contains(v)));
            }
        }
    }
    assert!(
        valued > 100 && left > 100,
        "{valued} valued, {left} left to the base agent"
    );
    let (Outcome::Rows(together), Outcome::Rows(apart)) = (&with[1], &alone[0]) else {
        panic!("the second game is kept");
    };
    assert_eq!(together.search_action, apart.search_action);
    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&together.search_value), bits(&apart.search_value));
}

#[test]
fn a_bad_look_ahead_setting_is_refused_before_anything_is_written() {
    let out = scratch("bad-search");
    let b = Build {
        inputs: vec![data("tenhou").display().to_string()],
        out: out.join("ds"),
        options: Options {
            search: Some("search:rollouts=lots".into()),
            ..options(&[Form::Planes])
        },
        inputs_per_shard: 4,
        threads: 1,
    };
    let err = build(&b, &mut |_| {}).unwrap_err();
    assert!(err.contains("--search search:rollouts=lots"), "{err}");
    assert!(!out.join("ds").exists());
    let _ = std::fs::remove_dir_all(&out);
}
