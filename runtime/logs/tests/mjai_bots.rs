//! MJAI bots as arena seats, driven over their stdin and stdout in both dialects: a bot that
//! plays by the protocol finishes every game with no fault, and one that misbehaves (garbage,
//! silence, a crash, a flood, another seat's reaction, an illegal discard) loses that game by the
//! illegal-action penalty with the reason and its stderr reported, without stopping the others.
//!
//! The bot is tests/data/mjai/bots/simple_bot.py (Python's standard library only).

use std::path::PathBuf;
use std::time::{Duration, Instant};

use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Player, Report};
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::{BotSpec, Dialect};
use rinshan_logs::mjai::seat::MjaiEntrant;

fn bot(dialect: Dialect, mode: &str) -> MjaiEntrant {
    let script: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "tests",
        "data",
        "mjai",
        "bots",
        "simple_bot.py",
    ]
    .iter()
    .collect();
    let name = match dialect {
        Dialect::App => "app",
        Dialect::Stdio => "stdio",
    };
    MjaiEntrant {
        spec: BotSpec {
            command: format!("python3 {} --dialect {name} --mode {mode}", script.display()),
            dialect,
            timeout: Duration::from_secs(2),
            startup: Duration::from_secs(20),
        },
    }
}

fn play(entrant: &MjaiEntrant, mode: Mode, sets: usize) -> Report {
    play_in(Variant::Red, entrant, mode, sets)
}

fn play_in(variant: Variant, entrant: &dyn arena::Entrant, mode: Mode, sets: usize) -> Report {
    let arena = Arena {
        variant,
        mode,
        players: [
            Player::Entrant { name: "bot", entrant },
            Player::Builtin(Agent::Defensive),
            Player::Builtin(Agent::Rule),
            Player::Builtin(Agent::Greedy),
        ],
        sets,
        seed: 3,
    };
    arena::run(&arena, &|_| {})
}

fn standing<'a>(report: &'a Report, name: &str) -> &'a arena::Standing {
    report
        .standings
        .iter()
        .find(|s| s.name == name)
        .expect("the player is in the report")
}

#[test]
fn a_bot_that_keeps_the_protocol_plays_every_game_in_both_dialects() {
    for dialect in [Dialect::App, Dialect::Stdio] {
        let report = play(&bot(dialect, "play"), Mode::Half, 1);
        assert_eq!(report.faults, vec![], "{dialect:?}");
        let me = standing(&report, "bot");
        assert_eq!((me.games, me.illegal), (4, 0), "{dialect:?}");
        // It pons (its only call) and the games run their course.
        assert!(me.call_rate > 0.0 && me.rounds >= 4 * 4, "{dialect:?}: {me:?}");
    }
}

/// Counts the `kita` actions of the seats it plays (sanma's action id).
struct CountingKita<'a> {
    inner: &'a MjaiEntrant,
    kitas: std::sync::atomic::AtomicUsize,
}

struct CountingSeat<'a> {
    inner: Box<dyn arena::Seat + 'a>,
    kitas: &'a std::sync::atomic::AtomicUsize,
}

impl arena::Entrant for CountingKita<'_> {
    fn join(
        &self,
        seat: u32,
        state: &rinshan_engine::generated::kernel::GameState,
        variant: Variant,
    ) -> Box<dyn arena::Seat + '_> {
        Box::new(CountingSeat {
            inner: self.inner.join(seat, state, variant),
            kitas: &self.kitas,
        })
    }
}

impl arena::Seat for CountingSeat<'_> {
    fn act(&mut self, state: &rinshan_engine::generated::kernel::GameState) -> Result<u32, String> {
        let a = self.inner.act(state)?;
        if a == rinshan_engine::generated::sanma::ACTION_KITA {
            self.kitas.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        }
        Ok(a)
    }

    fn stepped(
        &mut self,
        before: &rinshan_engine::generated::kernel::GameState,
        action: u32,
        after: &rinshan_engine::generated::kernel::GameState,
    ) -> Result<(), String> {
        self.inner.stepped(before, action, after)
    }
}

/// At a three-player table the bot is told three seats' lists and sets North aside with `kita`,
/// which plays as the engine's kita; a misbehaving one is penalised as at four.
#[test]
fn a_bot_plays_three_player_games_and_sets_north_aside() {
    for dialect in [Dialect::App, Dialect::Stdio] {
        let entrant = bot(dialect, "play");
        let counting = CountingKita {
            inner: &entrant,
            kitas: Default::default(),
        };
        let report = play_in(Variant::Sanma, &counting, Mode::Half, 1);
        assert_eq!(report.faults, vec![], "{dialect:?}");
        let me = standing(&report, "bot");
        assert_eq!((me.games, me.illegal), (3, 0), "{dialect:?}: {me:?}");
        assert!(me.rounds >= 3 * 3, "{dialect:?}: {me:?}");
        let kitas = counting.kitas.load(std::sync::atomic::Ordering::Relaxed);
        assert!(kitas >= 3, "{dialect:?}: {kitas} kita");
        let report = play_in(Variant::Sanma, &bot(dialect, "illegal"), Mode::East, 1);
        let me = standing(&report, "bot");
        assert_eq!((me.games, me.illegal, me.ranks[2]), (3, 3, 3), "{dialect:?}: {me:?}");
        assert!(report.faults.iter().all(|f| f.message.contains("is not legal here")));
    }
}

#[test]
fn a_bot_that_misbehaves_loses_that_game_by_the_penalty_and_is_reported() {
    let cases = [
        ("garbage", "the reply is not JSON"),
        ("sleep", "no reply within 2.0 s"),
        ("die", "closed its output"),
        ("flood", "a line over 1048576 bytes"),
        ("wrong-actor", "the reaction is for actor"),
        ("illegal", "is not legal here"),
    ];
    for dialect in [Dialect::App, Dialect::Stdio] {
        for (mode, why) in cases {
            let started = Instant::now();
            let report = play(&bot(dialect, mode), Mode::East, 1);
            let me = standing(&report, "bot");
            // Each of the 4 games ends at the bot's third turn, with the penalty: it places last.
            assert_eq!(
                (me.games, me.illegal, me.ranks),
                (4, 4, [0, 0, 0, 4]),
                "{dialect:?} {mode}"
            );
            assert_eq!(report.faults.len(), 4, "{dialect:?} {mode}: {:?}", report.faults);
            for f in &report.faults {
                assert_eq!(f.player, "bot");
                assert!(f.message.contains(why), "{dialect:?} {mode}: {}", f.message);
            }
            if mode == "die" {
                assert!(
                    report.faults[0].message.contains("dying on purpose"),
                    "{}",
                    report.faults[0].message
                );
            }
            // The other seats finished their games as the rules say: nobody else was penalised.
            for s in report.standings.iter().filter(|s| s.name != "bot") {
                assert_eq!(s.illegal, 0, "{dialect:?} {mode}: {s:?}");
            }
            assert!(
                started.elapsed() < Duration::from_secs(60),
                "{dialect:?} {mode}: no hang"
            );
        }
    }
}

/// The `mjai_player` fuzz target's corpus (a seat's view of a game in either dialect, and
/// garbage) through the player as the target drives it: an answer to every line in mjai.app's
/// dialect, every answer an MJAI event, and in Mortal's a reaction at each of the seat's turns.
#[test]
fn the_player_answers_its_fuzz_corpus() {
    use rinshan_engine::generated::kernel::GameState;
    use rinshan_logs::mjai::player::Player;
    use rinshan_logs::mjai::Event;
    let dir: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "tests",
        "fuzz",
        "corpus",
        "mjai_player",
    ]
    .iter()
    .collect();
    let mut decide = |s: &GameState| Ok(Agent::Defensive.act(Variant::Red, s));
    for entry in std::fs::read_dir(&dir).expect("the corpus") {
        let data = std::fs::read(entry.expect("an entry").path()).expect("a corpus file");
        let (&first, rest) = data.split_first().expect("a dialect byte");
        let dialect = if first & 1 == 0 { Dialect::App } else { Dialect::Stdio };
        let seat = (first >> 1) % 5;
        let mut player = Player::new((seat < 4).then_some(seat));
        let (mut lines, mut replies, mut own_turns) = (0, 0, 0);
        for line in String::from_utf8_lossy(rest).lines() {
            lines += 1;
            let value: Option<serde_json::Value> = serde_json::from_str(line).ok();
            let own_tsumo = value.as_ref().is_some_and(|e| {
                e["type"] == "tsumo" && e["actor"].as_u64() == player.seat().map(u64::from) && e["pai"] != "?"
            });
            own_turns += u32::from(own_tsumo && dialect == Dialect::Stdio);
            if let Some(reply) = player.respond(line, dialect, &mut decide, &mut |_| {}) {
                replies += 1;
                let reply: Event = serde_json::from_str(&reply).expect("an MJAI event");
                if own_tsumo {
                    assert!(
                        matches!(
                            reply,
                            Event::Dahai { .. }
                                | Event::Reach { .. }
                                | Event::Hora { .. }
                                | Event::Ankan { .. }
                                | Event::Kakan { .. }
                        ),
                        "{reply:?}"
                    );
                }
            }
        }
        match dialect {
            Dialect::App => assert_eq!(replies, lines),
            Dialect::Stdio => assert!(
                replies >= own_turns && own_turns > 0 || lines < 10,
                "{replies} {own_turns}"
            ),
        }
    }
}

#[test]
fn a_seat_that_cannot_follow_its_game_is_one_fault_per_game() {
    // A one-hand game has no MJAI form (the recorder follows east and half games): each game
    // reports it once, at the bot's first decision, and ends with the penalty.
    let report = play(&bot(Dialect::Stdio, "play"), Mode::Single, 1);
    assert_eq!(report.faults.len(), 4, "{:?}", report.faults);
    assert!(
        report.faults.iter().all(|f| f.message.contains("one-hand game")),
        "{:?}",
        report.faults
    );
    assert_eq!(standing(&report, "bot").illegal, 4);
}
