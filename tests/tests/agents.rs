//! The baseline agents and hero mode: agents only play legal actions and are deterministic;
//! hero mode shows the caller only its own seats' decisions, pays every reward of the decisions
//! it played in between, and plays exactly the game a step-by-step loop over the same agents
//! plays; the arena rates a stronger agent above a weaker one and counts a policy's illegal moves.

use rinshan_engine::agents::Agent;
use rinshan_engine::arena::{self, Arena, Player, Policy};
use rinshan_engine::env::{Config, Env, Mode, Observer};
use rinshan_engine::generated::kernel::{self, ResetInput};
use rinshan_engine::generated::red;
use rinshan_engine::observe::Form;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

fn hero_config(batch: usize, agents: Vec<[Option<Agent>; 4]>) -> Config {
    Config {
        mode: Mode::Half,
        seed: 11,
        auto_reset: false,
        agents,
        ..Config::new(Variant::Red, batch)
    }
}

/// The caller plays seat 0 of every game (seat 1 of the odd ones) at random against three
/// defensive agents: it is asked only for its own seats, and the rewards it receives add up to
/// the final score change of every seat.
#[test]
fn hero_mode_asks_only_the_callers_seat_and_pays_every_reward() {
    const B: usize = 24;
    let seatings: Vec<[Option<Agent>; 4]> = (0..B)
        .map(|i| {
            let mut s = [Some(Agent::Defensive); 4];
            s[i % 2] = None;
            s
        })
        .collect();
    let mut env = Env::new(hero_config(B, seatings)).expect("env");
    let mut last = env.reset().expect("reset").clone();
    let mut rng = Rng::new(3);
    let mut returns = vec![[0f64; 4]; B];
    let mut own_decisions = 0;
    let mut done = [false; B];
    let mut steps = 0;
    while !done.iter().all(|&d| d) {
        let actions: Vec<u32> = (0..B).map(|i| rng.pick_legal(&last.legal_action_mask[i])).collect();
        let caller_moved: Vec<bool> = (0..B).map(|i| last.current_player[i] as usize == i % 2).collect();
        let step = env.step(&actions).expect("step").clone();
        for i in 0..B {
            if done[i] {
                continue;
            }
            for (r, x) in returns[i].iter_mut().zip(step.rewards[i]) {
                *r += f64::from(x);
            }
            own_decisions += usize::from(caller_moved[i]);
            if step.terminated[i] {
                done[i] = true;
            } else {
                assert_eq!(
                    step.current_player[i] as usize,
                    i % 2,
                    "env {i}: the caller was asked for another seat's decision"
                );
            }
        }
        last = step;
        steps += 1;
        assert!(steps < 20_000, "games do not end");
    }
    let states = env.states_words().expect("states");
    for (i, w) in states.chunks(env.state_words()).enumerate() {
        let s: &kernel::GameState = bytemuck::from_bytes(bytemuck::cast_slice(w));
        for (p, r) in returns[i].iter().enumerate() {
            let change = f64::from(s.scores[p] - 25_000) / 100.0;
            assert!(
                (r - change).abs() < 1e-6,
                "env {i} seat {p}: rewards {r} but score change {change}"
            );
        }
    }
    assert!(own_decisions > B * 50, "the caller decided only {own_decisions} times");
}

/// With agents in every seat one step plays a whole game, and it is the game a loop over the
/// kernel's agent, one decision at a time, plays from the same seed.
#[test]
fn hero_mode_plays_the_same_game_as_a_loop_over_the_agents() {
    const B: usize = 8;
    let seating = [
        Some(Agent::Greedy),
        Some(Agent::Defensive),
        Some(Agent::Rule),
        Some(Agent::Random),
    ];
    let mut env = Env::new(hero_config(B, vec![seating])).expect("env");
    env.reset().expect("reset");
    let before = env.states_words().expect("states");
    let step = env.step(&[0; B]).expect("step").clone();
    assert!(step.terminated.iter().all(|&t| t), "one step plays the whole game");
    let after = env.states_words().expect("states");
    for i in 0..B {
        let w = &before[i * env.state_words()..(i + 1) * env.state_words()];
        let mut s: kernel::GameState = *bytemuck::from_bytes(bytemuck::cast_slice(w));
        while s.terminated == 0 {
            let agent = seating[s.current as usize].expect("agent").kernel();
            let a = red::agent_act(
                agent,
                &mut red::observe_planes(s, kernel::OBSERVE_CURRENT),
                s.mask,
                s.seed,
                s.steps,
            );
            assert!(
                s.mask[(a / 32) as usize] >> (a % 32) & 1 == 1,
                "agent {agent} played illegal action {a}"
            );
            red::game_step(&mut s, a);
        }
        let e: &kernel::GameState = bytemuck::from_bytes(bytemuck::cast_slice(
            &after[i * env.state_words()..(i + 1) * env.state_words()],
        ));
        assert_eq!(s.scores, e.scores, "env {i}: final scores");
        assert_eq!(s.steps, e.steps, "env {i}: decisions");
    }
}

/// A hero-mode step reports every decision it played: its rewards summed, its events, winners
/// and yaku merged, the last deal-in seat, and the final places and state of the last decision,
/// as plain steps (`game_step`, whose games the fingerprints pin) of the same decisions add up.
#[test]
fn hero_mode_reports_the_outputs_of_every_decision_it_played() {
    const B: usize = 16;
    let seating = [None, Some(Agent::Defensive), Some(Agent::Greedy), Some(Agent::Rule)];
    let mut env = Env::new(hero_config(B, vec![seating])).expect("env");
    let mut last = env.reset().expect("reset").clone();
    let words = env.state_words();
    let mut rng = Rng::new(5);
    let mut merged_steps = 0;
    while !last.terminated.iter().all(|&t| t) {
        let before = env.states_words().expect("states");
        let actions: Vec<u32> = (0..B).map(|i| rng.pick_legal(&last.legal_action_mask[i])).collect();
        let step = env.step(&actions).expect("step").clone();
        let after = env.states_words().expect("states");
        for i in 0..B {
            if last.terminated[i] {
                continue;
            }
            let mut s: kernel::GameState =
                *bytemuck::from_bytes(bytemuck::cast_slice(&before[i * words..(i + 1) * words]));
            let (mut rewards, mut events, mut winners, mut deal_in, mut yaku) = ([0i32; 4], 0, 0, 0, [0u32; 2]);
            // The caller's action when its seat is to move (after a reset an agent may be first).
            let agent_action = |s: &kernel::GameState, agent: Agent| {
                red::agent_act(
                    agent.kernel(),
                    &mut red::observe_planes(*s, kernel::OBSERVE_CURRENT),
                    s.mask,
                    s.seed,
                    s.steps,
                )
            };
            let mut a = seating[s.current as usize].map_or(actions[i], |agent| agent_action(&s, agent));
            let mut decisions = 0;
            loop {
                red::game_step(&mut s, a);
                decisions += 1;
                for (r, x) in rewards.iter_mut().zip(s.rewards) {
                    *r += x;
                }
                events |= s.events;
                winners |= s.winners;
                if s.deal_in != 0 {
                    deal_in = s.deal_in;
                }
                yaku = [yaku[0] | s.yaku[0], yaku[1] | s.yaku[1]];
                let Some(agent) = seating[s.current as usize] else {
                    break;
                };
                if s.terminated != 0 {
                    break;
                }
                a = agent_action(&s, agent);
            }
            merged_steps += usize::from(decisions > 1 && events != 0);
            let e: &kernel::GameState = bytemuck::from_bytes(bytemuck::cast_slice(&after[i * words..(i + 1) * words]));
            assert_eq!(s.scores, e.scores, "env {i}: scores");
            assert_eq!(s.steps, e.steps, "env {i}: decisions");
            assert_eq!(step.rewards[i], rewards.map(|r| r as f32), "env {i}: rewards");
            assert_eq!(step.events[i], events, "env {i}: events");
            assert_eq!(step.winners[i], winners, "env {i}: winners");
            assert_eq!(step.deal_in[i], deal_in, "env {i}: deal-in seat");
            assert_eq!(step.yaku[i], yaku, "env {i}: yaku");
            assert_eq!(step.terminated[i], s.terminated != 0, "env {i}: terminated");
            assert_eq!(step.ranks[i], s.ranks.to_le_bytes(), "env {i}: final places");
        }
        last = step;
    }
    assert!(
        merged_steps > B,
        "only {merged_steps} hero steps settled a round among other decisions"
    );
}

/// Observations are available in hero mode for the caller's seat.
#[test]
fn hero_mode_observes_the_callers_seat() {
    let mut config = hero_config(
        4,
        vec![[None, Some(Agent::Greedy), Some(Agent::Greedy), Some(Agent::Greedy)]],
    );
    config.observe = vec![Form::Tokens];
    let mut env = Env::new(config).expect("env");
    env.reset().expect("reset");
    let step = env.step(&[0; 4]).expect("step").clone();
    assert!(step.current_player.iter().all(|&p| p == 0));
    let tokens = env.observation(Form::Tokens).expect("tokens").to_vec();
    let seat0 = env.observe(Form::Tokens, Observer::Seat(0)).expect("observe").to_vec();
    assert_eq!(tokens, seat0);
}

/// `observe_all` gives each seat's own observation, env-major.
#[test]
fn observe_all_is_every_seat_of_every_env() {
    let mut env = Env::new(hero_config(3, Vec::new())).expect("env");
    env.reset().expect("reset");
    for form in Form::ALL {
        let all = env.observe_all(form).expect("all seats");
        let n = form.bytes();
        for seat in 0..4u32 {
            let one = env.observe(form, Observer::Seat(seat)).expect("one seat").to_vec();
            for i in 0..3 {
                let at = (i * 4 + seat as usize) * n;
                assert!(
                    all[at..at + n] == one[i * n..(i + 1) * n],
                    "{form}: env {i} seat {seat}"
                );
            }
        }
    }
}

struct FirstLegal;
impl Policy for FirstLegal {
    fn act(&self, _planes: &[u8], mask: &[u32; 3]) -> u32 {
        (0..96)
            .find(|a| mask[(a / 32) as usize] >> (a % 32) & 1 == 1)
            .unwrap_or(0)
    }
}

struct AlwaysZero;
impl Policy for AlwaysZero {
    fn act(&self, _planes: &[u8], _mask: &[u32; 3]) -> u32 {
        0
    }
}

/// Duplicate play ranks the rule player above random ones with a confidence interval clear of a
/// tie; built-in agents never play an illegal action; a policy that does is counted.
#[test]
fn arena_rates_rule_above_random_and_counts_illegal_moves() {
    let arena = Arena {
        variant: Variant::Red,
        mode: Mode::East,
        players: [
            Player::Builtin(Agent::Rule),
            Player::Builtin(Agent::Random),
            Player::Builtin(Agent::Random),
            Player::Builtin(Agent::Random),
        ],
        sets: 25,
        seed: 4,
    };
    let report = arena::run(&arena, &|_| {});
    assert_eq!(report.games, 100);
    let rule = &report.standings[0];
    assert_eq!(rule.name, "rule");
    assert!(
        rule.mean_rank + rule.rank_ci95 < 2.5,
        "rule {} ± {}",
        rule.mean_rank,
        rule.rank_ci95
    );
    assert!(report.standings.iter().all(|s| s.illegal == 0));
    assert_eq!(rule.ranks.iter().sum::<u64>(), rule.games);
    // Same seed, same report.
    assert_eq!(arena::run(&arena, &|_| {}), report);

    let policies = Arena {
        players: [
            Player::Policy {
                name: "first-legal",
                policy: &FirstLegal,
            },
            Player::Policy {
                name: "zero",
                policy: &AlwaysZero,
            },
            Player::Builtin(Agent::Greedy),
            Player::Builtin(Agent::Greedy),
        ],
        sets: 2,
        ..arena
    };
    let report = arena::run(&policies, &|_| {});
    let by = |n: &str| report.standings.iter().find(|s| s.name == n).expect("standing");
    assert_eq!(by("first-legal").illegal, 0);
    assert!(by("zero").illegal > 0, "action 0 is illegal at most decisions");
}

/// Three players: every wall set is played three times, the agents rotated over three seats; the
/// fourth player is not seated, and a game lost to an illegal action places its player third.
#[test]
fn the_arena_rates_three_players_over_three_seats() {
    let arena = Arena {
        variant: Variant::Sanma,
        mode: Mode::East,
        players: [
            Player::Builtin(Agent::Rule),
            Player::Builtin(Agent::Random),
            Player::Builtin(Agent::Random),
            Player::Builtin(Agent::Greedy),
        ],
        sets: 30,
        seed: 5,
    };
    let report = arena::run(&arena, &|_| {});
    assert_eq!(report.games, 90);
    let names: Vec<&str> = report.standings.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["rule", "random"], "the fourth player sits out");
    let rule = &report.standings[0];
    assert!(
        rule.mean_rank + rule.rank_ci95 < 2.0,
        "rule {} ± {}",
        rule.mean_rank,
        rule.rank_ci95
    );
    assert_eq!((rule.games, rule.ranks[3], rule.ranks.iter().sum::<u64>()), (90, 0, 90));
    let zero = Arena {
        players: [
            Player::Policy {
                name: "zero",
                policy: &AlwaysZero,
            },
            Player::Builtin(Agent::Rule),
            Player::Builtin(Agent::Rule),
            Player::Builtin(Agent::Rule),
        ],
        sets: 2,
        ..arena
    };
    let report = arena::run(&zero, &|_| {});
    let by = |n: &str| report.standings.iter().find(|s| s.name == n).expect("standing");
    assert_eq!(
        by("zero").ranks,
        [0, 0, 6, 0],
        "an illegal action places its player last"
    );
}

/// The agents are deterministic for a seed: the same game twice gives the same actions.
#[test]
fn agents_are_deterministic() {
    for agent in Agent::ALL {
        let inp = ResetInput {
            seed: [9, 9],
            mode: kernel::MODE_EAST,
            dealer: 4,
            use_wall: 0,
            wall: [0; 136],
            uma: [0; 4],
            penalty: -1.0,
            auto_reset: 0,
        };
        let run = || {
            let mut s = red::game_new(inp);
            let mut actions = Vec::new();
            while s.terminated == 0 {
                let a = red::agent_act(
                    agent.kernel(),
                    &mut red::observe_planes(s, kernel::OBSERVE_CURRENT),
                    s.mask,
                    s.seed,
                    s.steps,
                );
                actions.push(a);
                red::game_step(&mut s, a);
            }
            actions
        };
        assert_eq!(run(), run(), "{agent}");
    }
}
