//! Games played in rinshan, written as tenhou.net/6 logs (`tenhou::write`), read back
//! (`tenhou::log`) and replayed (`tenhou::replay`): every round must replay as it was played.
//!
//! * random half games with a policy that takes every win, riichi, kan and many calls;
//! * the scenarios' prepared rounds for what random play rarely reaches (triple ron, nagashi,
//!   pao, four kans, four riichi, four winds, kyuushu), each the first round of a half game;
//! * the Tenhou logs themselves: each logged round played on the kernel and recorded must give
//!   back the logged line.

use std::collections::BTreeMap;

use rinshan_engine::env::{Backend, Config, Env, Mode};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::generated::red as k;
use rinshan_engine::hand::YakuHan;
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Tile, Variant};
use rinshan_logs::mjai::read::parse_game as parse_mjai;
use rinshan_logs::mjai::write::game_text as mjai_text;
use rinshan_logs::tenhou::log::{collect_files, parse_game, read_game, Discard, Draw, Game, Outcome, Round};
use rinshan_logs::tenhou::plan::plan;
use rinshan_logs::tenhou::replay::replay;
use rinshan_logs::tenhou::write::{game_text, GameRecorder, Recorder, WriteError};
use rinshan_tests::policy::{legal, VariantPolicy};
use rinshan_tests::scenario::{build_wall, load, Actions, Scenario};
use rinshan_tests::test_data;

fn env(mode: Mode, batch: usize, seed: u64, auto_reset: bool) -> Env {
    variant_env(Variant::Red, mode, batch, seed, auto_reset)
}

fn variant_env(variant: Variant, mode: Mode, batch: usize, seed: u64, auto_reset: bool) -> Env {
    let mut config = Config::new(variant, batch);
    config.mode = mode;
    config.seed = seed;
    config.auto_reset = auto_reset;
    config.threads = Some(1);
    Env::new(config).expect("a cpu env")
}

fn states(env: &Env) -> Vec<GameState> {
    let words = env.states_words().expect("states");
    bytemuck::cast_slice::<u32, GameState>(&words).to_vec()
}

/// Writes each game, reads it back (it must read as what was recorded) and replays them all.
fn round_trip(games: &[Game]) {
    let read: Vec<Game> = games
        .iter()
        .enumerate()
        .map(|(n, g)| {
            let path = format!("game-{n}.json");
            let back = parse_game(&path, &game_text(g)).unwrap_or_else(|e| panic!("{e}"));
            let recorded = Game { path, ..g.clone() };
            assert_eq!(back, recorded, "game {n} reads back as something else");
            back
        })
        .collect();
    let report = replay(&read, Backend::Cpu).expect("cpu replay");
    for m in &report.mismatches {
        eprintln!("{m}");
        if let Some(g) = read.iter().find(|g| g.path == m.file) {
            eprintln!("{}", game_text(g).lines().nth(m.line - 1).unwrap_or_default());
        }
    }
    assert!(
        report.all_agree(),
        "{} mismatches (listed above): {report:?}",
        report.mismatches.len()
    );
    assert_eq!((report.games, report.games_ended_right), (games.len(), games.len()));
}

/// How often each situation the format can hold came up.
fn tally(games: &[Game]) -> BTreeMap<&'static str, usize> {
    let mut n: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut add = |what: &'static str, yes: bool| *n.entry(what).or_default() += usize::from(yes);
    for r in games.iter().flat_map(|g| &g.rounds) {
        for seat in 0..4 {
            for d in &r.draws[seat] {
                add("chi", matches!(d, Draw::Chi { .. }));
                add("pon", matches!(d, Draw::Pon { .. }));
                add("open kan", matches!(d, Draw::OpenKan { .. }));
            }
            for d in &r.discards[seat] {
                add("closed kan", matches!(d, Discard::ClosedKan { .. }));
                add("added kan", matches!(d, Discard::AddedKan { .. }));
                add("riichi", matches!(d, Discard::Riichi(_)));
                add("tsumogiri riichi (r60)", matches!(d, Discard::Riichi(None)));
                add("kita", matches!(d, Discard::Kita));
            }
        }
        add("kan dora", r.dora.len() > 1);
        match &r.outcome {
            Outcome::Wins(ws) => {
                add("double ron", ws.len() == 2);
                for w in ws {
                    add("tsumo", w.tsumo);
                    add("ron", !w.tsumo);
                    let robbed = (!w.tsumo).then(|| r.discards[w.from].last()).flatten();
                    add("robbed closed kan", matches!(robbed, Some(Discard::ClosedKan { .. })));
                    add("ronned riichi discard", matches!(robbed, Some(Discard::Riichi(_))));
                    add("ronned kita", matches!(robbed, Some(Discard::Kita)));
                    add("yakuman", w.yaku.iter().any(|y| matches!(y.han, YakuHan::Yakuman(_))));
                    add("pao", w.pao != w.winner);
                    add("limit hand", w.limit.is_some());
                    for (yaku, name) in [
                        ("chankan", "chankan"),
                        ("rinshan", "rinshan"),
                        ("haitei", "haitei"),
                        ("houtei", "houtei"),
                        ("ura dora", "ura"),
                        ("ippatsu", "ippatsu"),
                    ] {
                        add(yaku, w.yaku.iter().any(|y| y.name == name));
                    }
                }
            }
            Outcome::Draw { kind, .. } => add(kind.tenhou_name(), true),
        }
    }
    n.retain(|_, v| *v > 0);
    n
}

/// `games` games of `mode` played by the policy, as the recorder wrote them.
fn play(mode: Mode, games: usize, seed: u64) -> Vec<Game> {
    play_variant(Variant::Red, mode, games, seed)
}

/// `games` games of `variant` and `mode` played by the policy, as the recorder wrote them (the
/// render tests draw three-player tables from them too).
pub(crate) fn play_variant(variant: Variant, mode: Mode, games: usize, seed: u64) -> Vec<Game> {
    let batch = 48;
    let mut env = variant_env(variant, mode, batch, seed, true);
    env.reset().expect("reset");
    let mut recorder = Recorder::new(&env).expect("recorder");
    let mut policies: Vec<VariantPolicy> = (0..batch as u64)
        .map(|i| VariantPolicy::new(variant, Rng::new(seed * 1000 + i)))
        .collect();
    let mut done = Vec::new();
    while done.len() < games {
        let masks = env.last().legal_action_mask.clone();
        let actions: Vec<u32> = states(&env)
            .iter()
            .zip(&masks)
            .zip(&mut policies)
            .map(|((s, m), policy)| policy.act(s, m))
            .collect();
        env.step(&actions).expect("step");
        recorder.observe(&env, &actions).expect("recorded");
        done.extend(recorder.take_finished().into_iter().map(|f| f.game));
    }
    assert_eq!(recorder.dropped(), 0);
    done
}

#[test]
fn random_half_games_round_trip() {
    let games = play(Mode::Half, 400, 7);
    let counts = tally(&games);
    let rounds: usize = games.iter().map(|g| g.rounds.len()).sum();
    eprintln!("{} half games, {rounds} rounds: {counts:?}", games.len());
    let common = [
        "closed kan",
        "added kan",
        "open kan",
        "chankan",
        "double ron",
        "kan dora",
        "ura dora",
    ];
    let draws = ["流局", "全員不聴", "全員聴牌", "九種九牌", "四槓散了"];
    for what in common.iter().chain(&draws) {
        assert!(counts.contains_key(what), "no {what} in {} random games", games.len());
    }
    round_trip(&games);
}

#[test]
fn random_east_games_round_trip() {
    let games = play(Mode::East, 60, 3);
    assert!(games.iter().all(|g| g.rule == "鳳東喰赤"));
    assert!(
        games.iter().all(|g| g.rounds.iter().all(|r| r.kyoku < 8)),
        "east games end in the South round at the latest"
    );
    round_trip(&games);
}

/// Every rule set's games are written naming it, read back as the same games and replayed under
/// its own rules: every decision legal, every score change, win and draw as written.
fn rule_set_round_trip(variant: Variant, seed: u64) -> (BTreeMap<&'static str, usize>, Vec<Game>) {
    let games = play_variant(variant, Mode::Half, 400, seed);
    let counts = tally(&games);
    let rounds: usize = games.iter().map(|g| g.rounds.len()).sum();
    eprintln!("{variant}: {} half games, {rounds} rounds: {counts:?}", games.len());
    let rule = match (variant.seats(), variant.red_fives()) {
        (4, true) => "鳳南喰赤",
        (4, false) => "鳳南喰",
        (_, true) => "三鳳南喰赤",
        (_, false) => "三鳳南喰",
    };
    assert!(games.iter().all(|g| g.variant == variant && g.rule == rule));
    let first = game_text(&games[0]);
    assert_eq!(
        first.contains(&format!("\"variant\":\"{variant}\"")),
        variant != Variant::Red,
        "{first}"
    );
    round_trip(&games);
    // As MJAI too: its start_game names the rule set, so each game reads back under it.
    for (n, g) in games.iter().enumerate() {
        let mjai = mjai_text(g).unwrap_or_else(|e| panic!("{e}"));
        let read = parse_mjai(&format!("game-{n}.mjson"), &mjai).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(read.variant, variant, "game {n}");
        assert_eq!(game_text(&read), game_text(g), "game {n}");
    }
    (counts, games)
}

#[test]
fn no_red_games_round_trip() {
    let (counts, games) = rule_set_round_trip(Variant::NoRed, 11);
    // One winner per discard, and no abortive draws.
    assert!(!counts.contains_key("double ron") && !counts.contains_key("九種九牌"));
    // Without the rule set's name the logs are Tenhou's (no red fives in the room): replayed
    // under red, a round that shows all four black copies of a five cannot be dealt, and is
    // reported, not an error of the whole replay.
    let tenhou: Vec<Game> = games
        .iter()
        .enumerate()
        .map(|(n, g)| {
            let text = game_text(g).replace(",\"variant\":\"no-red\"", "");
            parse_game(&format!("game-{n}.json"), &text).unwrap_or_else(|e| panic!("{e}"))
        })
        .collect();
    assert!(tenhou.iter().all(|g| g.variant == Variant::Red && !g.red_fives));
    let report = replay(&tenhou, Backend::Cpu).expect("the replay runs");
    let four = report
        .mismatches
        .iter()
        .filter(|m| m.log.contains("four black"))
        .count();
    assert!(
        four > 0 && report.rounds_replayed > 0,
        "{four} rounds with four black fives: {report:?}"
    );
}

#[test]
fn mjsoul_games_round_trip() {
    let (counts, _) = rule_set_round_trip(Variant::Mjsoul, 12);
    assert!(counts.contains_key("double ron"));
}

#[test]
fn mleague_games_round_trip() {
    let (counts, _) = rule_set_round_trip(Variant::Mleague, 13);
    // Head bump, no abortive draws; kan dora shown at once.
    assert!(!counts.contains_key("double ron") && !counts.contains_key("九種九牌"));
    assert!(counts.contains_key("kan dora"));
}

#[test]
fn wrc_games_round_trip() {
    let (counts, _) = rule_set_round_trip(Variant::Wrc, 14);
    assert!(!counts.contains_key("double ron") && !counts.contains_key("流し満貫"));
}

#[test]
fn sanma_games_round_trip() {
    let (counts, games) = rule_set_round_trip(Variant::Sanma, 15);
    // No chi at three seats; North set aside, its replacement draws (rinshan kaihou among them)
    // and the rest of what the format holds for three players.
    assert!(!counts.contains_key("chi"));
    for what in ["kita", "pon", "closed kan", "tsumo", "ron", "流局", "全員不聴"] {
        assert!(counts.contains_key(what), "sanma: no {what}: {counts:?}");
    }
    for r in games.iter().flat_map(|g| &g.rounds) {
        assert_eq!((r.seats, r.scores[3], r.hands[3].len()), (3, 0, 0), "{r}");
        assert!(r.kyoku % 4 < 3, "{r}: kyoku {} is no three-player round", r.kyoku);
    }
    // The same games as MJAI (three seats, `kita`): read back, they write the same tenhou.net/6
    // text and the same MJAI text, and replay exactly.
    let back: Vec<Game> = games
        .iter()
        .enumerate()
        .map(|(n, g)| {
            let mjai = mjai_text(g).unwrap_or_else(|e| panic!("{e}"));
            assert!(
                mjai.starts_with("{\"type\":\"start_game\",\"names\":[\"A\",\"B\",\"C\"],"),
                "{mjai}"
            );
            let read = parse_mjai(&format!("game-{n}.mjson"), &mjai).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(read.variant, Variant::Sanma);
            assert_eq!(game_text(&read), game_text(g), "game {n}");
            assert_eq!(mjai_text(&read).expect("writes"), mjai, "game {n}");
            read
        })
        .collect();
    let report = replay(&back, Backend::Cpu).expect("cpu replay");
    assert!(report.all_agree() && report.games == games.len(), "{report:?}");
}

#[test]
fn mjsoul_sanma_games_round_trip() {
    let (counts, _) = rule_set_round_trip(Variant::MjsoulSanma, 16);
    assert!(counts.contains_key("kita") && !counts.contains_key("chi"), "{counts:?}");
}

/// The first round of each of these scenarios, then the rest of a half game by the policy.
const PREPARED: [(&str, &str); 12] = [
    ("triple_ron_aborts", "三家和了"),
    ("triple_ron_after_a_go_around", "三家和了"),
    ("triple_ron_keeps_an_accepted_riichi_stick", "三家和了"),
    ("nagashi_mangan", "流し満貫"),
    ("pao_daisangen_ron_split", "pao"),
    ("pao_daisangen_tsumo_liable_pays_all", "pao"),
    ("four_kans_two_players", "四槓散了"),
    ("four_riichi", "四家立直"),
    ("four_winds", "四風連打"),
    ("kyuushu_kyuuhai", "九種九牌"),
    ("chankan_on_added_kan", "chankan"),
    ("closed_kan_not_robbed_by_kokushi", "closed kan"),
];

#[test]
fn prepared_rounds_round_trip() {
    let all = load();
    let scenarios: Vec<&Scenario> = PREPARED
        .iter()
        .map(|(name, _)| {
            all.iter()
                .find(|s| s.name == *name)
                .unwrap_or_else(|| panic!("no scenario {name}"))
        })
        .collect();
    let games = play_prepared(Variant::Red, &scenarios);
    for ((name, what), g) in PREPARED.iter().zip(&games) {
        let g = g
            .as_ref()
            .unwrap_or_else(|| panic!("{name} ended with an illegal action"));
        let first = tally(std::slice::from_ref(&Game {
            rounds: g.rounds[..1].to_vec(),
            ..g.clone()
        }));
        assert!(
            first.contains_key(what),
            "{name}: its first round has no {what}: {first:?}"
        );
    }
    let games: Vec<Game> = games.into_iter().flatten().collect();
    eprintln!("prepared games: {:?}", tally(&games));
    round_trip(&games);
}

/// Every scenario of the other rule sets (each pins one of its rules) that starts a game from East
/// 1's table: its round played as scripted, the rest of a half game by the policy, recorded and
/// replayed under the rule set.
#[test]
fn every_rule_sets_scenarios_round_trip() {
    let all = load();
    let mut played = 0;
    for &variant in Variant::ALL.iter().filter(|&&v| v != Variant::Red) {
        let name = variant.to_string().replace('-', "_");
        let scenarios: Vec<&Scenario> = all
            .iter()
            .filter(|sc| sc.variant == name && sc.start.is_none())
            .filter(|sc| sc.expect.illegal != Some(true) && !sc.steps.iter().any(|s| s.illegal))
            .collect();
        if scenarios.is_empty() {
            continue;
        }
        played += scenarios.len();
        let games: Vec<Game> = play_prepared(variant, &scenarios).into_iter().flatten().collect();
        assert_eq!(
            games.len(),
            scenarios.len(),
            "{variant}: a scenario's game was not recorded"
        );
        eprintln!("{variant}: {} scenarios: {:?}", scenarios.len(), tally(&games));
        round_trip(&games);
    }
    // mjsoul, mleague, wrc and sanma have such scenarios (no-red's one starts from its own table).
    assert!(played >= 20, "{played} scenarios played");
}

/// The first round of each scenario as scripted, then the rest of a half game of `variant` by the
/// policy, as the recorder wrote them (`None` for a game an illegal action ended).
fn play_prepared(variant: Variant, scenarios: &[&Scenario]) -> Vec<Option<Game>> {
    let acts = Actions {
        blocks: with_variant!(variant, v => v::host::ACTION_BLOCKS.to_vec()),
        red: variant.red_fives(),
    };
    let (tsumogiri, pass) = with_variant!(variant, v => (v::ACTION_TSUMOGIRI, v::ACTION_PASS));
    let walls: Vec<[Tile; 136]> = scenarios
        .iter()
        .map(|sc| {
            assert!(
                sc.start.is_none(),
                "{}: a prepared round starts from East 1's table",
                sc.name
            );
            build_wall(sc, variant)
                .unwrap_or_else(|e| panic!("{}: {e}", sc.name))
                .map(|v| u8::try_from(v).ok().and_then(Tile::from_value).expect("a tile value"))
        })
        .collect();
    let dealers: Vec<u32> = scenarios.iter().map(|sc| sc.dealer).collect();
    let n = scenarios.len();
    let mut env = variant_env(variant, Mode::Half, n, 11, false);
    env.reset_with_walls(&walls, &dealers).expect("walls");
    let mut recorder = Recorder::new(&env).expect("recorder");
    let mut policies: Vec<VariantPolicy> = (0..n as u64)
        .map(|i| VariantPolicy::new(variant, Rng::new(77 + i)))
        .collect();
    let mut next_step = vec![0usize; n];
    let mut games: Vec<Option<Game>> = vec![None; n];
    let mut over = vec![false; n];
    while over.iter().any(|o| !o) {
        let step = env.last().clone();
        let now = states(&env);
        let mut actions = vec![pass; n];
        for (i, sc) in scenarios.iter().enumerate() {
            let mask = &step.legal_action_mask[i];
            let scripted = loop {
                let Some(s) = sc.steps.get(next_step[i]).filter(|_| now[i].rounds == 0 && !over[i]) else {
                    break None;
                };
                // An auto step ends where the scenario's next step begins: `until_wall_left` tiles
                // left, a seat to act on its draw.
                let left = now[i].live_end.saturating_sub(now[i].next_draw);
                match s.until_wall_left {
                    Some(until) if s.auto.is_some() && left <= until && !legal(mask, pass) => next_step[i] += 1,
                    _ => break Some(s),
                }
            };
            actions[i] = match scripted {
                Some(s) if s.auto.is_some() => {
                    if legal(mask, tsumogiri) {
                        tsumogiri
                    } else {
                        pass
                    }
                }
                Some(s) => {
                    let action = s.action.as_deref().unwrap_or_default();
                    if let Some(seat) = s.seat {
                        assert_eq!(step.current_player[i], seat, "{}: step {}", sc.name, next_step[i]);
                    }
                    next_step[i] += 1;
                    acts.id(action).unwrap_or_else(|e| panic!("{}: {e}", sc.name))
                }
                None => policies[i].act(&now[i], mask),
            };
        }
        let after = env.step(&actions).expect("step").clone();
        recorder.observe(&env, &actions).expect("recorded");
        for (i, o) in over.iter_mut().enumerate() {
            *o |= after.terminated[i];
        }
        for f in recorder.take_finished() {
            games[f.env] = Some(f.game);
        }
    }
    games
}

/// Plays a logged round on the kernel from the wall the planner rebuilds, records it, and
/// returns the recorded round.
fn record_logged(r: &Round) -> Round {
    let p = plan(r).unwrap_or_else(|e| panic!("{r}: {e}"));
    let wall = p.wall.map(|t| u32::from(t.value()));
    let dealer = r.dealer() as u32;
    let mut s = k::game_new(rinshan_engine::generated::kernel::ResetInput {
        seed: [1, 2],
        mode: 2,
        dealer,
        use_wall: 1,
        wall,
        uma: [0; 4],
        penalty: -1.0,
        auto_reset: 0,
    });
    let (round, honba, sticks, scores) = (r.kyoku, r.honba, r.sticks, r.scores);
    k::game_deal(
        &mut s,
        rinshan_engine::generated::kernel::DealInput {
            deal: 1,
            round,
            dealer,
            honba,
            sticks,
            scores,
            wall,
        },
    );
    let mut recorder = GameRecorder::new(&s).unwrap_or_else(|e| panic!("{r}: {e}"));
    let mut moves = p.moves.iter().peekable();
    loop {
        let claim = legal(&s.mask, k::ACTION_PASS);
        let action = match moves.peek() {
            Some(m) if m.seat == s.current as usize && m.claim == claim => moves.next().map_or(0, |m| m.action),
            _ if claim => k::ACTION_PASS,
            m => panic!("{r}: the log's {m:?} does not fit seat {}", s.current),
        };
        let before = s;
        k::game_step(&mut s, action);
        let game = recorder
            .record(&before, action, &s)
            .unwrap_or_else(|e| panic!("{r}: {e}"));
        if let Some(round) = game
            .map(|g| g.rounds[0].clone())
            .or_else(|| recorder.rounds().first().cloned())
        {
            return round;
        }
    }
}

#[test]
fn logged_rounds_are_recorded_as_tenhou_wrote_them() {
    let files = collect_files(&[test_data().join("tenhou")]).expect("the log folder lists");
    let mut rounds = 0;
    for f in &files {
        let game = read_game(f).unwrap_or_else(|e| panic!("{e}"));
        for r in &game.rounds {
            let mut ours = record_logged(r);
            ours.line = r.line;
            let mut theirs = r.clone();
            // Tenhou lists yakuhai in the order of the hand's sets (two wins of the logs): compare
            // the yaku as sets.
            for outcome in [&mut ours.outcome, &mut theirs.outcome] {
                if let Outcome::Wins(ws) = outcome {
                    ws.iter_mut().for_each(|w| w.yaku.sort_by_key(|y| y.name));
                }
            }
            let text = |round: &Round| {
                game_text(&Game {
                    rounds: vec![round.clone()],
                    ..game.clone()
                })
            };
            assert_eq!(
                ours,
                theirs,
                "{}: {r}:\n ours {}\n log  {}",
                f.display(),
                text(&ours),
                text(&theirs)
            );
            rounds += 1;
        }
    }
    assert_eq!(rounds, 232);
}

#[test]
fn the_recorder_says_what_it_cannot_follow() {
    let mut single = env(Mode::Single, 2, 1, false);
    single.reset().expect("reset");
    let err = Recorder::new(&single).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(err.contains("one-hand"), "{err}");

    let mut env = env(Mode::Half, 2, 1, false);
    env.reset().expect("reset");
    let mut recorder = Recorder::new(&env).expect("recorder");
    assert!(matches!(
        recorder.observe(&env, &[0]),
        Err(WriteError::WrongLength { expected: 2, got: 1 })
    ));
    let first_legal = |env: &Env| {
        (0..2)
            .map(|i| env.last().legal_actions(i).next().unwrap_or(0))
            .collect::<Vec<u32>>()
    };
    let actions = first_legal(&env);
    env.step(&actions).expect("step");
    let later = first_legal(&env);
    env.step(&later).expect("step");
    // The recorder missed a step.
    let err = recorder
        .observe(&env, &later)
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(err.contains("without the recorder"), "{err}");
    // A game already under way cannot be picked up.
    let err = Recorder::new(&env).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(err.contains("not at the start of a round"), "{err}");
}
