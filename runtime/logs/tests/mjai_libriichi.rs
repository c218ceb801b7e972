//! rinshan's MJAI seats against an independent implementation of the protocol: the `mjai`
//! package of PyPI (0.2.1, mjai.app's; its `mlibriichi` is Mortal's rules engine). It is AGPL-3.0,
//! so it lives only in a test virtualenv (`.ci/mjai-venv` builds one in target/mjai-venv) whose
//! Python `RINSHAN_MJAI_PYTHON` names. Without it the tests say so and pass, except under
//! `CI=true`, where a missing virtualenv is a failure.
//!
//! * `RulebaseBot` seats in mjai.app's dialect play duplicate games with no protocol error (see
//!   `assert_clean` for the one rule it breaks);
//! * in Mortal's dialect, a `PlayerState` follows every event rinshan sends the seat, and the bot
//!   fails the game unless rinshan asks it exactly where libriichi says it can act
//!   (tests/data/mjai/bots/checked_bot.py).

use std::time::Duration;

use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Player, Report};
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::{BotSpec, Dialect};
use rinshan_logs::mjai::seat::MjaiEntrant;

fn mjai_python() -> Option<String> {
    match std::env::var("RINSHAN_MJAI_PYTHON") {
        Ok(p) if !p.is_empty() => Some(p),
        _ if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("RINSHAN_MJAI_PYTHON is not set: .ci/run builds the mjai virtualenv for these tests")
        }
        _ => {
            eprintln!("RINSHAN_MJAI_PYTHON is not set: the libriichi checks do not run here");
            None
        }
    }
}

fn entrant(command: String, dialect: Dialect) -> MjaiEntrant {
    MjaiEntrant {
        spec: BotSpec {
            command,
            dialect,
            timeout: Duration::from_secs(10),
            startup: Duration::from_secs(60),
        },
    }
}

fn play(bot: &MjaiEntrant, others: [Agent; 2], sets: usize) -> Report {
    let arena = Arena {
        variant: Variant::Red,
        mode: Mode::Half,
        players: [
            Player::Entrant {
                name: "bot",
                entrant: bot,
            },
            Player::Builtin(others[0]),
            Player::Entrant {
                name: "bot",
                entrant: bot,
            },
            Player::Builtin(others[1]),
        ],
        sets,
        seed: 17,
    };
    arena::run(&arena, &|_| {})
}

/// No protocol error. The one fault a RulebaseBot may commit is a rule's, not the protocol's:
/// after `reach` it sometimes discards a tile that breaks its tenpai, which libriichi's
/// `validate_reaction` lets through and Tenhou's rules (rinshan's) do not.
fn assert_clean(report: &Report) {
    for f in &report.faults {
        assert!(
            f.message.contains(r#"illegal reaction {"type":"dahai""#)
                && f.message.contains("the riichi discard; legal:"),
            "{f:?}"
        );
    }
    for s in &report.standings {
        let faults = report.faults.iter().filter(|f| f.player == s.name).count() as u64;
        assert_eq!(s.illegal, faults, "{s:?}");
    }
    let bot = report
        .standings
        .iter()
        .find(|s| s.name == "bot")
        .expect("the bot played");
    assert_eq!(bot.games, 8);
    // Real games: the bots win, call and declare riichi.
    assert!(
        bot.win_rate > 0.0 && bot.call_rate > 0.0 && bot.riichi_rate > 0.0,
        "{bot:?}"
    );
}

#[test]
fn rulebase_bots_play_duplicate_games_in_mjai_apps_dialect() {
    let Some(python) = mjai_python() else { return };
    let command = format!(
        "{python} -c 'import sys; from mjai.bot.rulebase import RulebaseBot; RulebaseBot(int(sys.argv[1])).start()'"
    );
    assert_clean(&play(
        &entrant(command, Dialect::App),
        [Agent::Defensive, Agent::Greedy],
        1,
    ));
}

#[test]
fn libriichi_follows_every_event_and_agrees_when_a_seat_can_act() {
    let Some(python) = mjai_python() else { return };
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/bots/checked_bot.py");
    let command = format!("{python} {script}");
    assert_clean(&play(
        &entrant(command, Dialect::Stdio),
        [Agent::Rule, Agent::Defensive],
        1,
    ));
}
