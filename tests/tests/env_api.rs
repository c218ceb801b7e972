//! The batched environment's public API on the CPU backend: determinism whatever the thread
//! count, dealing a given wall, typed errors for bad input, and illegal actions as outcomes.

use rinshan_engine::env::{Config, Deal, Env, EnvError, Mode, Observer, Step};
use rinshan_engine::observe::Form;
use rinshan_engine::random::Rng;
use rinshan_engine::{Tile, TileType, Variant};

fn config(variant: Variant, batch: usize, threads: Option<usize>) -> Config {
    Config {
        seed: 11,
        auto_reset: true,
        threads,
        ..Config::new(variant, batch)
    }
}

/// Plays `steps` random legal steps and returns every step's outcome and the final states.
fn play(cfg: Config, steps: usize) -> (Vec<Step>, Vec<u32>) {
    let b = cfg.batch;
    let mut env = Env::new(cfg).expect("env");
    let mut rngs: Vec<Rng> = (0..b as u64).map(|i| Rng::new(1000 + i)).collect();
    let mut out = vec![env.reset().expect("reset").clone()];
    let mut actions = vec![0u32; b];
    for _ in 0..steps {
        let last = out.last().expect("a step");
        for (i, a) in actions.iter_mut().enumerate() {
            *a = rngs[i].pick_legal(&last.legal_action_mask[i]);
        }
        out.push(env.step(&actions).expect("step").clone());
    }
    (out, env.states_words().expect("states"))
}

#[test]
fn same_seeds_give_the_same_games_on_one_and_two_threads() {
    for &v in Variant::ALL {
        let (one, s1) = play(config(v, 64, Some(1)), 1500);
        let (two, s2) = play(config(v, 64, Some(2)), 1500);
        let (all, s3) = play(config(v, 64, None), 1500);
        for (k, ((a, b), c)) in one.iter().zip(&two).zip(&all).enumerate() {
            assert_eq!(a, b, "{v}: step {k} differs between 1 and 2 threads");
            assert_eq!(a, c, "{v}: step {k} differs between 1 thread and all threads");
        }
        assert_eq!(s1, s2);
        assert_eq!(s1, s3);
        let games: usize = one.iter().map(|s| s.terminated.iter().filter(|&&t| t).count()).sum();
        assert!(games > 0, "{v}: some games ended in 1500 steps");
        // A second reset deals new games; a new env with the same seed deals the first ones again.
        let mut env = Env::new(config(v, 64, Some(1))).expect("env");
        let first = env.reset().expect("reset").clone();
        let second = env.reset().expect("reset").clone();
        assert_eq!(first, one[0]);
        assert_ne!(first.legal_action_mask, second.legal_action_mask);
    }
}

/// The kernel's observation writers take each game's state by `&mut` (WGSL's pointers), and an
/// optimiser may hand them the state itself rather than a copy: observing must not change a game.
/// Every form, of every seat and of the current player every step, on one and two threads: the
/// games stay those of an env that observes nothing.
#[test]
fn observing_leaves_every_game_as_it_was() {
    for &v in Variant::ALL {
        for threads in [Some(1), Some(2)] {
            let mut plain = Env::new(config(v, 16, threads)).expect("env");
            let mut watched = Env::new(Config {
                observe: Form::OBSERVATIONS.to_vec(),
                ..config(v, 16, threads)
            })
            .expect("env");
            let mut rngs: Vec<Rng> = (0..16).map(|i| Rng::new(500 + i)).collect();
            let mut last = plain.reset().expect("reset").clone();
            assert_eq!(&last, watched.reset().expect("reset"));
            for k in 0..300 {
                let actions: Vec<u32> = (0..16)
                    .map(|i| rngs[i].pick_legal(&last.legal_action_mask[i]))
                    .collect();
                last = plain.step(&actions).expect("step").clone();
                assert_eq!(&last, watched.step(&actions).expect("step"), "{v}: step {k}");
                for form in Form::ALL {
                    let all = watched.observe_all(form).expect("every seat");
                    assert_eq!(
                        all.len(),
                        16 * v.seats() as usize * form.bytes(),
                        "{v}: a record a seat"
                    );
                    watched.observe(form, Observer::Current).expect("the player to move");
                }
                assert_eq!(
                    plain.states_words().expect("states"),
                    watched.states_words().expect("states"),
                    "{v}, {threads:?} threads: observing at step {k} changed a game"
                );
            }
        }
    }
}

#[test]
fn reset_with_seeds_is_reproducible() {
    let v = Variant::Red;
    let mut a = Env::new(config(v, 8, Some(1))).expect("env");
    let mut b = Env::new(Config {
        seed: 999,
        ..config(v, 8, Some(2))
    })
    .expect("env");
    let seeds: Vec<u64> = (0..8).map(|i| 77 + i).collect();
    let sa = a.reset_with_seeds(&seeds).expect("reset").clone();
    let sb = b.reset_with_seeds(&seeds).expect("reset").clone();
    assert_eq!(sa, sb);
    assert_eq!(a.states_words().expect("states"), b.states_words().expect("states"));
}

fn tile_type(index: u8) -> TileType {
    TileType::new(index).expect("a type index below 34")
}

/// A wall in tile order: every type four times, the first copy of each five red when `red`.
fn sorted_wall(red: bool) -> [Tile; 136] {
    std::array::from_fn(|i| {
        let t = tile_type((i / 4) as u8);
        match Tile::red(t) {
            Some(five) if red && i % 4 == 0 => five,
            _ => Tile::plain(t),
        }
    })
}

fn hand_of(s: &rinshan_engine::generated::kernel::GameState, seat: usize) -> [u32; 34] {
    std::array::from_fn(|t| (s.hands[seat * 5 + t / 8] >> ((t % 8) * 4)) & 15)
}

#[test]
fn reset_with_walls_deals_exactly_those_hands() {
    let mut env = Env::new(config(Variant::Red, 2, Some(1))).expect("env");
    // Env 0: the sorted wall, dealer 2. Env 1: the same wall reversed, dealer 0.
    let sorted = sorted_wall(true);
    let mut reversed = sorted;
    reversed.reverse();
    let step = env
        .reset_with_walls(&[sorted, reversed], &[2, 0])
        .expect("reset")
        .clone();
    assert_eq!(step.current_player, [2, 0], "the dealer acts first");
    let words = env.states_words().expect("states");
    let states: &[rinshan_engine::generated::kernel::GameState] = bytemuck::cast_slice(&words);
    for (e, (wall, dealer)) in [(sorted, 2usize), (reversed, 0usize)].into_iter().enumerate() {
        let s = &states[e];
        for j in 0..4 {
            let seat = (dealer + j) % 4;
            let mut expected = [0u32; 34];
            let take = if j == 0 { 14 } else { 13 };
            for k in 0..take {
                // The dealer's 14th tile is the first live draw (index 52).
                let i = if k == 13 { 52 } else { j * 13 + k };
                expected[wall[i].kind().index()] += 1;
            }
            assert_eq!(hand_of(s, seat), expected, "env {e} seat {seat}");
        }
    }
    // Env 0's dealer holds 0000 1111 2222 3 (1m-4m) and draws wall[52] = red 5p (value 35):
    // it may discard those tiles only, and may declare closed kans on 1m, 2m and 3m.
    let legal: Vec<u32> = step.legal_actions(0).collect();
    let discards: Vec<u32> = legal.iter().copied().filter(|&a| a < 37).collect();
    assert!(
        discards.iter().all(|a| [0, 1, 2, 3, 13, 35].contains(a)),
        "discards {discards:?}"
    );
    for t in 0..4 {
        assert!(discards.contains(&t), "discard {t} legal: {legal:?}");
    }
    for t in 0..3 {
        assert!(legal.contains(&(37 + t)), "closed kan on type {t} legal: {legal:?}");
    }
    assert!(!legal.contains(&(37 + 3)), "only three of type 3");
}

#[test]
fn bad_input_is_a_typed_error() {
    assert_eq!(Env::new(Config::new(Variant::Red, 0)).err(), Some(EnvError::EmptyBatch));
    assert!(matches!(
        Env::new(config(Variant::Red, 4, Some(0))).err(),
        Some(EnvError::BadThreads(_))
    ));
    assert!(matches!(
        Env::new(Config {
            penalty: Some(f32::NAN),
            ..Config::new(Variant::Red, 4)
        })
        .err(),
        Some(EnvError::BadPenalty(_))
    ));

    let mut env = Env::new(config(Variant::Red, 4, Some(1))).expect("env");
    env.reset().expect("reset");
    let e = env.step(&[0, 0, 0]).expect_err("3 actions for 4 envs");
    assert_eq!(
        e,
        EnvError::WrongLength {
            what: "actions",
            expected: 4,
            got: 3
        }
    );
    assert!(e.to_string().contains("3 actions for a batch of 4"), "{e}");
    assert!(matches!(
        env.reset_with_seeds(&[1, 2]),
        Err(EnvError::WrongLength { what: "seeds", .. })
    ));
    // The look-ahead's play-outs: one first action per env, one seating per env or one for all,
    // one state per env; a wrong count changes nothing.
    let before = env.states_words().expect("states");
    let defensive = [rinshan_engine::agents::Agent::Defensive; 4];
    assert!(matches!(
        env.play_rounds(&[0; 3], &[defensive]),
        Err(EnvError::WrongLength {
            what: "first actions",
            ..
        })
    ));
    assert!(matches!(
        env.play_rounds(&[0; 4], &[defensive; 2]),
        Err(EnvError::WrongLength {
            what: "agent seatings",
            ..
        })
    ));
    let states = env.game_states().expect("states");
    assert!(matches!(
        env.load_game_states(&states[..3]),
        Err(EnvError::WrongLength {
            what: "game states",
            ..
        })
    ));
    assert_eq!(env.states_words().expect("states"), before);

    let good = sorted_wall(true);
    let mut five_copies = good;
    five_copies[0] = Tile::plain(tile_type(1)); // 1m x3, 2m x5
    let mut no_red_in_red = good;
    no_red_in_red[16] = Tile::plain(tile_type(4)); // the red 5m replaced by a plain one
    for (wall, needle) in [
        (five_copies, "3 copies of tile type 0"),
        (no_red_in_red, "0 red fives of suit 0"),
    ] {
        let e = env
            .reset_with_walls(&[good, good, wall, good], &[0; 4])
            .expect_err("bad wall");
        assert!(matches!(e, EnvError::BadWall { env: 2, .. }), "{e:?}");
        assert!(e.to_string().contains(needle), "{e}");
    }
    assert!(matches!(
        env.reset_with_walls(&[good; 4], &[0, 1, 2, 4]),
        Err(EnvError::BadDealer {
            env: 3,
            dealer: 4,
            seats: 4
        })
    ));
    assert!(matches!(
        env.reset_with_walls(&[good; 3], &[0; 3]),
        Err(EnvError::WrongLength { what: "walls", .. })
    ));

    let mut no_red = Env::new(config(Variant::NoRed, 1, Some(1))).expect("env");
    let e = no_red.reset_with_walls(&[good], &[0]).expect_err("red fives in no-red");
    assert!(e.to_string().contains("has none"), "{e}");
    assert!(no_red.reset_with_walls(&[sorted_wall(false)], &[0]).is_ok());

    // A forced deal from a table whose payments would overflow the kernel's points is refused.
    let deal = Deal {
        round: 0,
        dealer: 0,
        honba: 0,
        sticks: 0,
        scores: [25_000; 4],
        wall: good,
    };
    for (bad, needle) in [
        (
            Deal {
                round: 16,
                ..deal.clone()
            },
            "round 16 is not 0-15",
        ),
        (
            Deal {
                honba: 10_001,
                ..deal.clone()
            },
            "10001 honba and 0 riichi sticks: at most 10000",
        ),
        (
            Deal {
                sticks: u32::MAX,
                ..deal.clone()
            },
            "riichi sticks: at most 10000",
        ),
        (
            Deal {
                scores: [i32::MIN, 0, 0, 0],
                ..deal.clone()
            },
            "at most 100000000 either way",
        ),
    ] {
        let e = env.deal(&[None, Some(bad), None, None]).expect_err("bad table");
        assert!(matches!(e, EnvError::BadDeal { env: 1, .. }), "{e:?}");
        assert!(e.to_string().contains(needle), "{needle}: {e}");
    }
    assert!(env.deal(&[None, Some(deal), None, None]).is_ok());
}

#[test]
fn an_illegal_action_ends_only_that_game_with_the_penalty() {
    for &v in Variant::ALL {
        let mut env = Env::new(Config {
            penalty: Some(-3.5),
            auto_reset: false,
            mode: Mode::Half,
            ..config(v, 4, Some(1))
        })
        .expect("env");
        let first = env.reset().expect("reset").clone();
        let mut rng = Rng::new(5);
        let mut actions: Vec<u32> = (0..4).map(|i| rng.pick_legal(&first.legal_action_mask[i])).collect();
        let illegal = (0..env.num_actions())
            .find(|&a| first.legal_action_mask[1][(a / 32) as usize] >> (a % 32) & 1 == 0)
            .expect("some action is illegal");
        actions[1] = illegal;
        let actor = first.current_player[1] as usize;
        let step = env.step(&actions).expect("step").clone();
        assert_eq!(step.illegal, [false, true, false, false], "{v}");
        assert_eq!(step.terminated, [false, true, false, false], "{v}");
        let mut expected = [0.0f32; 4];
        expected[actor] = -3.5;
        assert_eq!(step.rewards[1], expected, "{v}");
        assert_eq!(step.legal_action_mask[1], [0; 3]);
        assert_eq!(step.ranks[1], [0; 4], "an illegal action ends a game unranked");
        // Out-of-range ids are illegal too, and a finished game stays finished without reward.
        actions = (0..4).map(|i| rng.pick_legal(&step.legal_action_mask[i])).collect();
        actions[3] = 1_000;
        let next = env.step(&actions).expect("step").clone();
        assert!(next.illegal[3] && next.terminated[3]);
        assert!(next.terminated[1] && !next.illegal[1]);
        assert_eq!(next.rewards[1], [0.0; 4]);
        assert!(!next.terminated[0] && !next.terminated[2]);
    }
}

#[test]
fn defaults_come_from_the_spec() {
    let env = Env::new(Config::new(Variant::Red, 3)).expect("env");
    assert_eq!(env.num_actions(), 87);
    assert_eq!(env.batch(), 3);
    assert_eq!(env.variant(), Variant::Red);
    let env = Env::new(Config::new(Variant::NoRed, 1)).expect("env");
    assert_eq!(env.num_actions(), 79);
}

#[test]
fn final_ranks_order_the_final_scores() {
    for &v in Variant::ALL {
        // Without auto-reset the finished game stays in the state, so its table is the oracle.
        let mut env = Env::new(Config {
            auto_reset: false,
            ..config(v, 64, Some(1))
        })
        .expect("env");
        let mut step = env.reset().expect("reset").clone();
        let mut sums = vec![[0.0f64; 4]; 64];
        let mut rng = Rng::new(9);
        let mut ranks = vec![None; 64];
        while ranks.iter().any(Option::is_none) {
            let actions: Vec<u32> = (0..64).map(|i| rng.pick_legal(&step.legal_action_mask[i])).collect();
            step = env.step(&actions).expect("step").clone();
            for i in 0..64 {
                if ranks[i].is_none() {
                    for (s, r) in sums[i].iter_mut().zip(step.rewards[i]) {
                        *s += f64::from(r);
                    }
                    if step.terminated[i] {
                        ranks[i] = Some(step.ranks[i]);
                    }
                }
            }
        }
        let start = f64::from(v.starting_points());
        let seats = v.seats() as usize;
        for (i, table) in env.tables().expect("tables").iter().enumerate() {
            let r = ranks[i].expect("finished");
            let mut places = r;
            places.sort_unstable();
            assert_eq!(places, [0, 1, 2, 3], "{v} env {i}: {r:?}");
            // A seat a three-player game lacks holds the place no one does, and nothing.
            for p in seats..4 {
                assert_eq!((r[p], table.scores[p], sums[i][p]), (3, 0, 0.0), "{v} env {i}");
            }
            for p in 0..seats {
                // The rewards add up to the final score, uma included.
                assert_eq!(start + sums[i][p] * 100.0, f64::from(table.scores[p]), "{v} env {i}");
                for q in 0..seats {
                    if table.scores[p] > table.scores[q] {
                        assert!(r[p] < r[q], "{v} env {i}: {:?} ranked {r:?}", table.scores);
                    }
                }
            }
        }
    }
}

#[test]
fn saved_states_replay_the_same_games_and_edits_are_refused() {
    for &v in Variant::ALL {
        let mut env = Env::new(config(v, 16, Some(1))).expect("env");
        let mut step = env.reset().expect("reset").clone();
        let mut rng = Rng::new(3);
        for _ in 0..150 {
            let actions: Vec<u32> = (0..16).map(|i| rng.pick_legal(&step.legal_action_mask[i])).collect();
            step = env.step(&actions).expect("step").clone();
        }
        let saved = env.save_states().expect("save");
        assert_eq!(saved.len(), 16 * env.saved_words());
        let at_save = step.clone();
        let mut after = Vec::new();
        let mut played = Vec::new();
        for _ in 0..200 {
            let actions: Vec<u32> = (0..16).map(|i| rng.pick_legal(&step.legal_action_mask[i])).collect();
            step = env.step(&actions).expect("step").clone();
            after.push(step.clone());
            played.push(actions);
        }
        // A fresh env takes the saved games and plays them on identically.
        let mut other = Env::new(config(v, 16, None)).expect("env");
        assert_eq!(*other.load_states(&saved).expect("load"), at_save, "{v}");
        for (actions, expected) in played.iter().zip(&after) {
            assert_eq!(other.step(actions).expect("step"), expected, "{v}");
        }
        // An edited word, a short input or another variant's state is refused, and the env keeps
        // its games.
        let before = other.states_words().expect("states");
        let mut edited = saved.clone();
        edited[40] ^= 1;
        let e = other.load_states(&edited).expect_err("edited");
        assert!(matches!(e, EnvError::BadState { env: 0, .. }), "{e}");
        assert!(e.to_string().contains("check words do not match"), "{e}");
        let e = other.load_states(&saved[1..]).expect_err("short");
        assert!(matches!(e, EnvError::WrongLength { .. }), "{e}");
        let w = Variant::ALL.iter().find(|&&o| o != v).copied().expect("two variants");
        let e = Env::new(config(w, 16, None))
            .expect("env")
            .load_states(&saved)
            .expect_err("other variant");
        assert!(matches!(e, EnvError::BadState { env: 0, .. }), "{e}");
        assert_eq!(other.states_words().expect("states"), before);
    }
}

#[test]
fn action_names_follow_the_layout() {
    for &v in Variant::ALL {
        let names = rinshan_engine::env::action_names(v);
        let env = Env::new(Config::new(v, 1)).expect("env");
        assert_eq!(names.len(), env.num_actions() as usize, "{v}");
        let mut unique = names.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{v}: {names:?}");
        // MahJax's ids: discards by tile type first, then self kans.
        assert_eq!(names[0], "discard_1m");
        assert_eq!(names[33], "discard_7z");
    }
    let red = rinshan_engine::env::action_names(Variant::Red);
    assert_eq!(&red[34..37], ["discard_0m", "discard_0p", "discard_0s"]);
    assert_eq!(red[37], "self_kan_1m");
    assert_eq!(&red[71..75], ["tsumogiri", "riichi", "tsumo", "ron"]);
    assert_eq!(red[84], "pass");
}
