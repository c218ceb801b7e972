//! CPU vs GPU environment parity: the same seeds and the same random legal actions give
//! identical current players, masks, rewards, terminations and observations (planes and tokens of
//! the current player at every step; those, the analysis tier and the oracle of every seat every
//! 25 steps) at every step of whole games, and identical states at the end. Hero mode (built-in
//! agents playing three seats inside a step) is compared the same way, and so are illegal action
//! ids of any size (the GPU's step reads hero mode's flags from an id's high bits). Each variant's
//! rule scenarios (tests/data/scenarios.toml) then play on both backends too.

use rinshan_engine::agents::Agent;
use rinshan_engine::env::{Backend, Config, Env, Mode, Observer};
use rinshan_engine::observe::Form;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// Games per variant. The three-player rule sets play fewer, to hold the whole CI run under 30
/// minutes on two cores (with 200 sanma's test alone took 168 s on lavapipe); 64 half games are
/// still thousands of steps.
const BATCH: usize = 200;
const SANMA_BATCH: usize = 64;

/// The forms compared at every step (for the current players); every form, the analysis tier and
/// the oracle included, is compared for every seat every 25 steps. On lavapipe (`GALLIVM_PERF=nopt`)
/// an analysis record takes about a millisecond: every step would add minutes per variant.
const EVERY_STEP: [Form; 2] = [Form::Planes, Form::Tokens];

fn parity(variant: Variant, batch: usize) {
    let test = format!("env_parity_{variant}");
    let Some(gpu) = rinshan_tests::gpu_or_skip(&test) else {
        return;
    };
    let config = Config {
        mode: Mode::Half,
        seed: 2024,
        auto_reset: false,
        threads: None,
        backend: Backend::Cpu,
        observe: EVERY_STEP.to_vec(),
        ..Config::new(variant, batch)
    };
    let mut cpu = Env::new(config.clone()).expect("cpu env");
    let software = gpu.is_software();
    let agents_on_gpu = rinshan_tests::agent_gpu_tests_run(&gpu, &format!("{test}: the agents' actions"));
    let mut gpu = Env::with_gpu(config, gpu).expect("gpu env");
    let started = std::time::Instant::now();
    let c = cpu.reset().expect("cpu reset").clone();
    let g = gpu.reset().expect("gpu reset").clone();
    assert_eq!(c, g, "{variant}: reset");
    for form in EVERY_STEP {
        assert!(
            cpu.observation(form) == gpu.observation(form),
            "{variant}: {form} observations after reset"
        );
    }
    assert_eq!(
        cpu.states_words().expect("cpu states"),
        gpu.states_words().expect("gpu states"),
        "{variant}: states after reset"
    );
    eprintln!(
        "{variant}: reset of {batch} envs identical on CPU and GPU in {:.1}s (pipeline compilation included)",
        started.elapsed().as_secs_f64()
    );
    if software {
        // Mesa's lavapipe compiles the step's five pipelines in about 2 minutes of one core the
        // first time (its shader cache makes later runs fast); the games themselves take seconds.
        eprintln!("{variant}: stepping whole games on a software adapter");
    }
    let mut rngs: Vec<Rng> = (0..batch as u64).map(|i| Rng::new(0xabc0 + i)).collect();
    let mut actions = vec![0u32; batch];
    let mut last = c;
    let mut steps = 0usize;
    while !last.terminated.iter().all(|&t| t) {
        for (i, a) in actions.iter_mut().enumerate() {
            *a = rngs[i].pick_legal(&last.legal_action_mask[i]);
        }
        let c = cpu.step(&actions).expect("cpu step").clone();
        let g = gpu.step(&actions).expect("gpu step");
        assert_eq!(
            c.current_player, g.current_player,
            "{variant}: step {steps}: current_player"
        );
        assert_eq!(
            c.legal_action_mask, g.legal_action_mask,
            "{variant}: step {steps}: mask"
        );
        assert_eq!(c.rewards, g.rewards, "{variant}: step {steps}: rewards");
        assert_eq!(c.terminated, g.terminated, "{variant}: step {steps}: terminated");
        assert_eq!(&c, g, "{variant}: step {steps}: the other fields");
        if agents_on_gpu && steps.is_multiple_of(25) {
            let seating = [[Agent::Defensive, Agent::Greedy, Agent::Rule, Agent::Random]];
            assert_eq!(
                cpu.agent_actions(&seating).expect("cpu agents"),
                gpu.agent_actions(&seating).expect("gpu agents"),
                "{variant}: step {steps}: the agents' actions"
            );
        }
        for form in EVERY_STEP {
            assert!(
                cpu.observation(form) == gpu.observation(form),
                "{variant}: step {steps}: {form} observations of the current players"
            );
        }
        if steps.is_multiple_of(25) {
            for form in Form::ALL {
                for seat in 0..variant.seats() {
                    let on_cpu = cpu.observe(form, Observer::Seat(seat)).expect("cpu observe").to_vec();
                    let on_gpu = gpu.observe(form, Observer::Seat(seat)).expect("gpu observe");
                    assert!(
                        on_cpu == on_gpu,
                        "{variant}: step {steps}: {form} observations of seat {seat}"
                    );
                }
            }
        }
        // A finished game (no auto-reset) stays finished.
        for i in 0..batch {
            assert!(!last.terminated[i] || c.terminated[i], "{variant}: env {i} restarted");
        }
        last = c;
        steps += 1;
        assert!(steps < 50_000, "{variant}: games do not end");
    }
    assert_eq!(
        cpu.states_words().expect("cpu states"),
        gpu.states_words().expect("gpu states"),
        "{variant}: final states"
    );
    eprintln!(
        "{variant}: {batch} half games, {steps} batch steps, identical on CPU and GPU ({}) in {:.1}s",
        gpu.adapter().unwrap_or_default(),
        started.elapsed().as_secs_f64()
    );
    // The rule scenarios on the same device, its pipelines compiled (minutes of one core on lavapipe).
    crate::scenarios::on_both_backends(variant, gpu.into_gpu().expect("a GPU env"));
}

#[test]
fn red_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::Red, BATCH);
}

#[test]
fn no_red_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::NoRed, BATCH);
}

#[test]
fn mjsoul_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::Mjsoul, BATCH);
}

#[test]
fn mleague_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::Mleague, BATCH);
}

#[test]
fn wrc_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::Wrc, BATCH);
}

#[test]
fn sanma_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::Sanma, SANMA_BATCH);
}

#[test]
fn mjsoul_sanma_half_games_are_identical_on_cpu_and_gpu() {
    parity(Variant::MjsoulSanma, SANMA_BATCH);
}

/// Hero mode on both backends: the caller plays one seat at random, the three agents the others.
#[test]
fn hero_mode_is_identical_on_cpu_and_gpu() {
    let Some(gpu) = rinshan_tests::agent_gpu_or_skip("hero_mode_parity") else {
        return;
    };
    const B: usize = 64;
    let seatings: Vec<[Option<Agent>; 4]> = (0..B)
        .map(|i| {
            let mut s = [
                Some(Agent::Defensive),
                Some(Agent::Greedy),
                Some(Agent::Rule),
                Some(Agent::Random),
            ];
            s[i % 4] = None;
            s
        })
        .collect();
    let config = Config {
        mode: Mode::East,
        seed: 77,
        agents: seatings,
        ..Config::new(Variant::Red, B)
    };
    let mut cpu = Env::new(config.clone()).expect("cpu env");
    let mut gpu = Env::with_gpu(config, gpu).expect("gpu env");
    let mut last = cpu.reset().expect("cpu reset").clone();
    assert_eq!(&last, gpu.reset().expect("gpu reset"));
    let mut rngs: Vec<Rng> = (0..B as u64).map(|i| Rng::new(0x4e0 + i)).collect();
    let mut steps = 0;
    while !last.terminated.iter().all(|&t| t) {
        let actions: Vec<u32> = (0..B).map(|i| rngs[i].pick_legal(&last.legal_action_mask[i])).collect();
        let c = cpu.step(&actions).expect("cpu step").clone();
        assert_eq!(&c, gpu.step(&actions).expect("gpu step"), "hero mode, step {steps}");
        last = c;
        steps += 1;
        assert!(steps < 5_000, "games do not end");
    }
    assert_eq!(
        cpu.states_words().expect("cpu"),
        gpu.states_words().expect("gpu"),
        "final states"
    );
    eprintln!("hero mode: {B} east games, {steps} batch steps, identical on CPU and GPU");
}

/// The look-ahead's play-outs on both backends (`search:backend=gpu`): the worlds of positions of
/// `defensive` self-play, every legal action played out to the round's end, give the same end
/// states, and the look-ahead the same decisions, candidate values included.
#[test]
fn play_outs_and_look_ahead_decisions_are_identical_on_cpu_and_gpu() {
    use rinshan_search::rollout::{gpu_status, play_rounds};
    use rinshan_search::{Focus, Options, Search};
    let Some(gpu) = rinshan_tests::agent_gpu_or_skip("play_out_parity") else {
        return;
    };
    // The look-ahead opens its own device, shared by every look-ahead of the process.
    drop(gpu);
    let variant = Variant::Red;
    let mut rng = Rng::new(0x5eac);
    let (mut positions, mut k) = (Vec::new(), 0);
    rinshan_search::positions::defensive_game(variant, 41, &mut |p| {
        k += 1;
        if k % 9 == 0 && p.state.mask.iter().map(|w| w.count_ones()).sum::<u32>() >= 2 {
            positions.push(p.clone());
        }
        true
    });
    assert!(positions.len() >= 20, "{} positions", positions.len());
    let mut plays = Vec::new();
    for p in &positions {
        let world = rinshan_search::world::deal(variant, &p.state, p.seat, &p.own_draws, &mut rng);
        let legal = (0..96u32).filter(|&a| world.mask[a as usize / 32] >> (a % 32) & 1 == 1);
        plays.extend(legal.map(|a| (world, a)));
    }
    let cpu = play_rounds(variant, &plays, Agent::Defensive, Backend::Cpu);
    let gpu = play_rounds(variant, &plays, Agent::Defensive, Backend::Gpu);
    assert_eq!(gpu_status(), Some(Ok(())), "the play-outs ran on the GPU");
    for (i, (c, g)) in cpu.iter().zip(&gpu).enumerate() {
        assert!(
            bytemuck::bytes_of(&c.0) == bytemuck::bytes_of(&g.0) && c.1 == g.1,
            "play-out {i} (action {}) ends otherwise on the GPU",
            plays[i].1
        );
    }
    let options = Options {
        rollouts: 48,
        focus: Focus::All,
        ..Options::default()
    };
    let on_cpu = Search::new(variant, options);
    let on_gpu = Search::new(
        variant,
        Options {
            backend: Backend::Gpu,
            ..options
        },
    );
    for (i, p) in positions.iter().enumerate().step_by(4) {
        let c = on_cpu.decide(&p.state, p.seat, &p.own_draws, i as u64);
        assert_eq!(
            c,
            on_gpu.decide(&p.state, p.seat, &p.own_draws, i as u64),
            "decision {i}"
        );
    }
    eprintln!("play-outs: {} on both backends, identical", plays.len());
}

/// Any id outside the layout is an illegal action on both backends, whatever its high bits: the
/// GPU's step entry reads hero mode's flags (`PLAY_ADD`, `PLAY_DONE`) from them.
#[test]
fn illegal_ids_of_any_size_end_the_game_alike_on_cpu_and_gpu() {
    let Some(gpu) = rinshan_tests::gpu_or_skip("illegal_ids_parity") else {
        return;
    };
    let ids = [
        86,
        255,
        0x3fff_ffff,
        0x4000_0000,
        0x4000_0005,
        0x8000_0000,
        0xffff_fffe,
        0xffff_ffff,
    ];
    let config = Config::new(Variant::Red, ids.len());
    let mut cpu = Env::new(config.clone()).expect("cpu env");
    let mut gpu = Env::with_gpu(config, gpu).expect("gpu env");
    assert_eq!(cpu.reset().expect("cpu reset"), gpu.reset().expect("gpu reset"));
    let c = cpu.step(&ids).expect("cpu step").clone();
    assert_eq!(&c, gpu.step(&ids).expect("gpu step"));
    assert!(c.terminated.iter().all(|&t| t), "every id is illegal: {c:?}");
    assert_eq!(cpu.states_words().expect("cpu"), gpu.states_words().expect("gpu"));
}
