//! The reviewer against what must hold whatever its estimates: a win in hand is the best action,
//! a tenpai hand is not thrown away, random play loses far more than `defensive` play on the same
//! walls, a review does not depend on the log's format nor on the tiles the player could not see.

use std::path::Path;

use rinshan_engine::agents::Agent;
use rinshan_engine::env::{action_names, Mode};
use rinshan_engine::generated::kernel::{self, ShantenInput};
use rinshan_engine::observe::resample_hidden;
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Variant};
use rinshan_logs::file::{game_text, parse_log, Format};
use rinshan_logs::read_log;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::write::GameRecorder;
use rinshan_review::{review, review_html, review_spots, spots, Review};
use rinshan_search::{Focus, Options};

/// Play-outs per decision in these tests: enough for a duel of 256 worlds (a standard error of
/// about 0.05 places on a paired difference).
const BUDGET: u32 = 1024;

fn options(rollouts: u32) -> Options {
    Options {
        rollouts,
        focus: Focus::All,
        ..Options::default()
    }
}

/// An east game of `variant` from `seed` with `agent` in every seat, as its log.
fn play(variant: Variant, agent: Agent, seed: u64) -> Game {
    let mut s = variant.new_game(seed, Mode::East);
    let mut recorder = GameRecorder::for_variant(&s, variant).expect("east games are logged");
    with_variant!(variant, v => loop {
        let a = v::seat_act(&mut { s }, agent.kernel());
        let before = s;
        v::game_step(&mut s, a);
        if let Some(game) = recorder.record(&before, a, &s).expect("recorded") {
            return game;
        }
    })
}

fn legal(mask: &[u32; 3], a: u32) -> bool {
    mask[a as usize / 32] >> (a % 32) & 1 == 1
}

/// The first legal action for which `pick` holds.
fn first_legal(mask: &[u32; 3], pick: impl Fn(u32) -> bool) -> Option<u32> {
    (0..96).find(|&a| legal(mask, a) && pick(a))
}

#[test]
fn a_win_in_hand_is_the_best_action() {
    // Each decision with a win in hand is judged twice: as played (the agents here always take
    // the win) and as if the player had let it go (discarded or passed instead).
    let variant = Variant::Red;
    let names = action_names(variant);
    let (tsumo, ron) = with_variant!(variant, v => (v::ACTION_TSUMO, v::ACTION_RON));
    let mut wins = 0;
    for (agent, seed) in [
        (Agent::Defensive, 1),
        (Agent::Defensive, 2),
        (Agent::Rule, 3),
        (Agent::Rule, 4),
    ] {
        let game = play(variant, agent, seed);
        for seat in 0..4 {
            // East 4 is left out: there a win can end the game in last place, and the look-ahead
            // may rightly prefer to play on.
            let found: Vec<_> = spots(&game, seat, None)
                .expect("replays")
                .into_iter()
                .filter(|s| {
                    game.rounds[s.round].kyoku < 3 && (legal(&s.state.mask, tsumo) || legal(&s.state.mask, ron))
                })
                .collect();
            let declined: Vec<_> = found
                .iter()
                .cloned()
                .map(|mut s| {
                    s.action = first_legal(&s.state.mask, |a| a != tsumo && a != ron).expect("another action");
                    s
                })
                .collect();
            let as_played = review_spots(&game, seat, &found, options(BUDGET), &|| ());
            let let_go = review_spots(&game, seat, &declined, options(BUDGET), &|| ());
            for (d, gone) in as_played.decisions.iter().zip(&let_go.decisions) {
                let win = if legal(&d.state.mask, tsumo) { tsumo } else { ron };
                let win = &names[win as usize];
                let at = format!("{agent} seed {seed} seat {seat}, {} step {}", d.round_name, d.step);
                wins += 1;
                assert_eq!(&d.played, win, "{at}: the agents take their wins");
                assert!(!d.mistake, "{at}");
                assert_eq!(&d.best, win, "{at}");
                assert_eq!(&d.candidates[0].action, win, "{at}");
                assert_eq!(&gone.best, win, "{at}: {} instead", gone.played);
                assert!(gone.mistake && gone.loss > 0.0, "{at}: declining a win is a mistake");
            }
        }
    }
    assert!(wins >= 10, "{wins} wins in hand");
}

fn shanten(counts: [u32; 34]) -> i32 {
    kernel::shanten(ShantenInput { hand: counts }).shanten
}

#[test]
fn a_tenpai_hand_is_not_thrown_away() {
    // Decisions with riichi legal (a closed tenpai hand), judged as if the player had discarded
    // out of tenpai; with no riichi against it in the first rounds, the look-ahead keeps tenpai.
    let variant = Variant::Red;
    let names = action_names(variant);
    let riichi = with_variant!(variant, v => v::ACTION_RIICHI);
    // The discard block's ids run over the tile values (red fives last).
    let first_discard = names.iter().position(|n| n.starts_with("discard_")).expect("discards") as u32;
    let discards = first_discard..first_discard + names.iter().filter(|n| n.starts_with("discard_")).count() as u32;
    let tsumogiri = names.iter().position(|n| n == "tsumogiri").expect("tsumogiri") as u32;
    let (mut cases, mut kept) = (0, 0);
    for (agent, seed) in [
        (Agent::Defensive, 10),
        (Agent::Defensive, 11),
        (Agent::Rule, 12),
        (Agent::Rule, 13),
        (Agent::Greedy, 14),
    ] {
        let game = play(variant, agent, seed);
        for seat in 0..4 {
            let mut found: Vec<_> = spots(&game, seat, None)
                .expect("replays")
                .into_iter()
                .filter(|s| {
                    let threat = (0..4).any(|q| s.state.seat_flags[q] & kernel::SEAT_RIICHI != 0);
                    game.rounds[s.round].kyoku < 2 && legal(&s.state.mask, riichi) && !threat
                })
                .collect();
            let keeps = |s: &rinshan_review::Spot, a: u32| -> bool {
                // The concealed tiles, the one just drawn among them.
                let mut hand = kernel::hand_counts(&mut s.state.clone(), seat);
                let t = match a {
                    _ if a == riichi => return true,
                    _ if a == tsumogiri => s.state.drawn,
                    _ if discards.contains(&a) => a - first_discard,
                    _ => return false,
                };
                hand[kernel::value_type(t) as usize] -= 1;
                shanten(hand) == 0
            };
            found.retain_mut(|s| {
                match first_legal(&s.state.mask, |a| {
                    (a == tsumogiri || discards.contains(&a)) && !keeps(s, a)
                }) {
                    Some(a) => {
                        s.action = a;
                        true
                    }
                    None => false,
                }
            });
            let r = review_spots(&game, seat, &found, options(BUDGET), &|| ());
            for (d, spot) in r.decisions.iter().zip(&found) {
                let best = names.iter().position(|n| *n == d.best).expect("an action") as u32;
                cases += 1;
                kept += usize::from(keeps(spot, best));
            }
        }
    }
    eprintln!("{cases} tenpai hands thrown away, the review keeps {kept}");
    assert!(cases >= 10, "{cases} cases");
    assert!(kept * 10 >= cases * 9, "the review keeps tenpai in {kept} of {cases}");
}

#[test]
fn random_play_loses_more_than_defensive_play_on_the_same_walls() {
    let mut totals = Vec::new();
    for agent in [Agent::Random, Agent::Defensive] {
        let mut sum = rinshan_review::Summary::default();
        let mut variance = 0.0;
        for seed in 20..26 {
            let game = play(Variant::Red, agent, seed);
            let g = review(&game, 0, Some(0), options(BUDGET)).expect("reviews").game;
            sum.decisions += g.decisions;
            sum.mistakes += g.mistakes;
            sum.loss += g.loss;
            sum.edge += g.edge;
            variance += g.edge_stderr * g.edge_stderr;
        }
        let n = sum.decisions as f64;
        let edge = (sum.edge / n, variance.sqrt() / n);
        eprintln!(
            "{agent}: {} decisions, {} mistakes losing {:.4} places per decision, edge {:+.4} ± {:.4} per decision",
            sum.decisions,
            sum.mistakes,
            sum.loss / n,
            edge.0,
            1.96 * edge.1
        );
        totals.push((sum.mistakes as f64 / n, sum.loss / n, edge));
    }
    let (random, defensive) = (totals[0], totals[1]);
    assert!(
        random.0 > 3.0 * defensive.0,
        "mistakes per decision {random:?} vs {defensive:?}"
    );
    assert!(
        random.1 > 2.0 * defensive.1,
        "loss per decision {random:?} vs {defensive:?}"
    );
    let (r, d) = (random.2, defensive.2);
    assert!(d.0 - r.0 > 3.0 * (r.1 * r.1 + d.1 * d.1).sqrt(), "edge {r:?} vs {d:?}");
}

fn same_review(a: &Review, b: &Review) {
    let strip = |r: &Review| {
        let mut v = serde_json::to_value(r).expect("serializes");
        v["log"] = serde_json::Value::Null;
        v
    };
    assert_eq!(strip(a), strip(b));
}

#[test]
fn a_review_is_the_same_in_every_format_of_the_log() {
    // The same worlds whatever the format: a small budget shows it as well as a large one.
    let small = options(64);
    // A game played here, written as tenhou.net/6 and as MJAI.
    let game = play(Variant::Red, Agent::Rule, 30);
    let reviewed = review(&game, 1, None, small).expect("reviews");
    assert!(reviewed.game.decisions >= 20, "{} decisions", reviewed.game.decisions);
    for format in [Format::Tenhou, Format::Mjai] {
        let text = game_text(&game, format).expect("writes");
        let (back, _) = parse_log("converted", text.as_bytes()).expect("reads back");
        same_review(&review(&back, 1, None, small).expect("reviews"), &reviewed);
    }
    // A real game from Tenhou's mjlog and its tenhou.net/6 conversion.
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/mjlog");
    let xml = read_log(&data.join("2019080322gm-00a9-0000-81e85e04.xml")).expect("reads");
    let json = read_log(&data.join("2019080322gm-00a9-0000-81e85e04.json")).expect("reads");
    let a = review(&xml, 2, None, small).expect("reviews");
    same_review(&a, &review(&json, 2, None, small).expect("reviews"));
    assert!(a.game.decisions >= 20, "{} decisions", a.game.decisions);
}

#[test]
fn the_report_holds_every_decision_and_opens_offline() {
    let game = play(Variant::Sanma, Agent::Defensive, 40);
    let r = review(&game, 2, Some(0), options(16)).expect("three-player games review");
    assert!(r.game.decisions >= 5);
    let page = review_html(&game, &r).expect("renders");
    assert!(page.contains("rinshan review: C in"), "the title names the player");
    assert!(!page.contains("{{"), "every placeholder filled");
    assert!(
        !page.contains("http://") && !page.contains("https://"),
        "nothing fetched from outside"
    );
    let bad = review(&game, 3, None, options(16)).err().unwrap_or_default();
    assert!(bad.contains("seats 0..2"), "{bad}");
}

#[test]
fn a_review_does_not_see_what_the_player_could_not() {
    // The same decisions with the tiles the player could not see dealt afresh (the observation
    // leak tests' resampler): the same values, the same verdicts.
    let game = play(Variant::Red, Agent::Defensive, 50);
    let found = spots(&game, 3, Some(0)).expect("replays");
    assert!(found.len() >= 5);
    let small = options(32);
    let seen = serde_json::to_value(review_spots(&game, 3, &found, small, &|| ()).decisions).expect("JSON");
    let mut rng = Rng::new(50);
    let shuffled: Vec<_> = found
        .iter()
        .cloned()
        .map(|mut s| {
            s.state = resample_hidden(Variant::Red, &s.state, 3, &s.own_draws, &mut rng);
            s
        })
        .collect();
    let other = serde_json::to_value(review_spots(&game, 3, &shuffled, small, &|| ()).decisions).expect("JSON");
    assert_eq!(seen, other);
}
