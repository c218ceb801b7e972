//! A short soak, as CI runs it: every variant, the built-in agents and the random policy, every
//! invariant after every step, observations against hidden resampling, every game's
//! Tenhou log read back and replayed under its rule set. The long run's figures are in docs/soak.md.

use rinshan_engine::agents::Agent;
use rinshan_engine::env::Mode;
use rinshan_engine::Variant;
use rinshan_soak::{Players, Soak};

#[test]
fn a_short_soak_finds_nothing() {
    for &variant in Variant::ALL {
        for players in [
            Players::Agents([Agent::Defensive, Agent::Greedy, Agent::Rule, Agent::Random]),
            Players::Uniform,
        ] {
            let soak = Soak {
                variant,
                mode: Mode::Half,
                players,
                games: 40,
                seed: 21,
                leak_every: 8,
            };
            let out = rinshan_soak::run(&soak, &|_| {});
            assert_eq!(out.games, 40);
            assert!(
                out.steps > 40 * 300 && out.leak_checks > 40 * 30,
                "{variant} {players}: {out:?}"
            );
            assert_eq!(out.replayed, 40, "{variant} {players}: every half game replays");
            assert!(out.violations.is_empty(), "{variant} {players}: {:?}", out.violations);
        }
    }
}
