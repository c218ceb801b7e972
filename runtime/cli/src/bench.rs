//! `rinshan bench hands`: evaluations per second of the generated kernels on the CPU (one thread,
//! all threads) and on the GPU, beside the `xiangting` crate's shanten on the same hands.
//! `rinshan bench env`: environment steps per second of random self-play by batch size.
//! `rinshan bench render`: boards drawn per second (decode, SVG, PNG) from self-play positions.

use std::time::{Duration, Instant};

use rinshan_engine::env::{Backend, Config, Env};
use rinshan_engine::gpu::{Gpu, Kernel};
use rinshan_engine::hand::{self, SCORE_IN_WORDS, SCORE_OUT_WORDS, SHANTEN_IN_WORDS, SHANTEN_OUT_WORDS};
use rinshan_engine::observe::Form;
use rinshan_engine::random::{random_hand, random_win, Rng};
use rinshan_engine::Variant;

use crate::args::{GameArgs, VariantArg};
use crate::error::CliError;
use crate::selfplay::policy_rng;

#[derive(clap::Subcommand)]
pub enum What {
    /// Shanten and hand-scoring evaluations per second: CPU (1 thread, all threads), GPU, xiangting
    Hands {
        /// Hands per measurement
        #[arg(long, default_value_t = 200_000)]
        hands: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        #[command(flatten)]
        variant: VariantArg,
        /// Skip the GPU backend
        #[arg(long)]
        no_gpu: bool,
    },
    /// Environment steps per second of random-policy self-play (auto-reset) by batch size: on the
    /// CPU with 1 thread, then with --threads (default all cores)
    Env {
        #[command(flatten)]
        game: GameArgs,
        /// Seconds measured per batch size
        #[arg(long, default_value_t = 0.5)]
        seconds_per_point: f64,
        /// Batch sizes to measure (comma-separated)
        #[arg(long, value_delimiter = ',', default_values_t = [1usize, 4, 16, 64, 256, 1024, 4096, 16384])]
        batches: Vec<usize>,
        /// Also write these observations (planes, tokens, analysis, oracle; comma-separated) of the
        /// current players every step, measured beside the same batch without them
        #[arg(long, value_delimiter = ',')]
        observe: Vec<Form>,
        /// Microseconds the calling thread sleeps between steps, as a learner does while it
        /// updates: on a machine whose idle cores wake slowly (virtual machines) the next
        /// parallel step pays for the wake-up; not counted in either figure
        #[arg(long, default_value_t = 0)]
        idle_us: u64,
    },
    /// Boards drawn per second on one thread: decoding a state, writing the SVG (page fragment
    /// and standalone file), rasterising the PNG; positions from rule-agent self-play
    Render {
        /// Positions measured
        #[arg(long, default_value_t = 2000)]
        positions: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
}

fn rate(n: usize, f: impl FnOnce()) -> f64 {
    let t = Instant::now();
    f();
    n as f64 / t.elapsed().as_secs_f64()
}

fn row(name: &str, per_s: f64, baseline: f64) {
    println!("  {name:<34} {:>14.0} /s   {:>7.2}x", per_s, per_s / baseline);
}

pub fn run(what: What) -> Result<(), CliError> {
    match what {
        What::Render { positions, seed } => render_bench(positions, seed),
        What::Hands {
            hands,
            seed,
            variant,
            no_gpu,
        } => hands_bench(hands, seed, variant.variant, no_gpu),
        What::Env {
            game,
            seconds_per_point,
            batches,
            observe,
            idle_us,
        } => env_bench(
            &game,
            seconds_per_point,
            &batches,
            &observe,
            Duration::from_micros(idle_us),
        ),
    }
}

/// Env steps per second at one batch size: (env only, env + policy). The policy (uniform over the
/// mask's set bits) runs on the calling thread between steps, then it sleeps `idle`; `env only`
/// times the `step` calls, `env + policy` all but the sleeps.
fn env_point(config: Config, seconds: f64, idle: Duration) -> Result<(f64, f64), CliError> {
    let b = config.batch;
    let seed = config.seed;
    let mut env = Env::new(config).map_err(CliError::failure)?;
    let mut rngs: Vec<Rng> = (0..b).map(|i| policy_rng(seed, i)).collect();
    let mut actions = vec![0u32; b];
    let mut step = env.reset().map_err(CliError::failure)?;
    let mut warm = 0;
    let mut env_time = 0.0;
    let mut idle_time = 0.0;
    let mut steps = 0u64;
    let mut started = Instant::now();
    loop {
        for (i, a) in actions.iter_mut().enumerate() {
            *a = rngs[i].pick_legal(&step.legal_action_mask[i]);
        }
        if !idle.is_zero() {
            let t = Instant::now();
            std::thread::sleep(idle);
            idle_time += t.elapsed().as_secs_f64();
        }
        let t = Instant::now();
        step = env.step(&actions).map_err(CliError::failure)?;
        let dt = t.elapsed().as_secs_f64();
        // The first steps warm up caches (and on the GPU the pipelines): not measured.
        if warm < 3 {
            warm += 1;
            started = Instant::now();
            idle_time = 0.0;
            continue;
        }
        env_time += dt;
        steps += b as u64;
        let total = started.elapsed().as_secs_f64() - idle_time;
        if total >= seconds {
            return Ok((steps as f64 / env_time, steps as f64 / total));
        }
    }
}

fn env_bench(
    game: &GameArgs,
    seconds: f64,
    batches: &[usize],
    observe: &[Form],
    idle: Duration,
) -> Result<(), CliError> {
    if seconds.is_nan() || seconds <= 0.0 || batches.is_empty() || batches.contains(&0) {
        return Err(CliError::input(
            "--seconds-per-point must be positive and --batches positive sizes",
        ));
    }
    let base = game.config(1);
    let (variant, mode, backend, threads) = (base.variant, base.mode, base.backend, base.threads);
    let all = threads.unwrap_or_else(rayon::current_num_threads);
    let config = |batch: usize, threads: Option<usize>| Config {
        batch,
        threads,
        ..base.clone()
    };
    let runs: Vec<(String, Option<usize>)> = match backend {
        Backend::Cpu => vec![
            ("cpu, 1 thread".to_string(), Some(1)),
            (format!("cpu, {all} threads"), threads),
        ],
        Backend::Gpu => {
            let gpu = Gpu::new().map_err(CliError::failure)?;
            let adapter = gpu.adapter();
            if gpu.is_software() {
                println!("{}", crate::selfplay::software_adapter_note(&adapter));
            }
            vec![(format!("gpu ({adapter})"), None)]
        }
    };
    println!(
        "rinshan bench env: variant {variant}, {mode} games with auto-reset, random legal policy, {seconds} s per point"
    );
    println!(
        "  env steps/s time the step calls only (state update, view, readback); +policy includes choosing the actions"
    );
    println!("  ratio = env steps/s over the batch-1 figure of the first row");
    if !idle.is_zero() {
        println!(
            "  the calling thread sleeps {} us between steps (not counted)",
            idle.as_micros()
        );
    }
    if !observe.is_empty() {
        let names: Vec<&str> = observe.iter().map(|f| f.name()).collect();
        let bytes: usize = observe.iter().map(|f| f.bytes()).sum();
        println!(
            "  observed: {} ({bytes} bytes per observation) of the current player every step; with/without = same batch, same run",
            names.join(" + ")
        );
    }
    let mut base = None;
    for (name, threads) in runs {
        println!("{name}");
        if observe.is_empty() {
            println!(
                "  {:>7} {:>14} {:>9} {:>16}",
                "batch", "env steps/s", "ratio", "+policy steps/s"
            );
        } else {
            println!(
                "  {:>7} {:>14} {:>9} {:>16} {:>16} {:>13}",
                "batch", "env steps/s", "ratio", "+policy steps/s", "observed steps/s", "with/without"
            );
        }
        for &b in batches {
            let (env_rate, with_policy) = env_point(config(b, threads), seconds, idle)?;
            let base = *base.get_or_insert(env_rate);
            if observe.is_empty() {
                println!(
                    "  {b:>7} {env_rate:>14.0} {:>8.2}x {with_policy:>16.0}",
                    env_rate / base
                );
            } else {
                let observed = Config {
                    observe: observe.to_vec(),
                    ..config(b, threads)
                };
                let (obs_rate, _) = env_point(observed, seconds, idle)?;
                println!(
                    "  {b:>7} {env_rate:>14.0} {:>8.2}x {with_policy:>16.0} {obs_rate:>16.0} {:>12.2}x",
                    env_rate / base,
                    obs_rate / env_rate
                );
            }
        }
    }
    Ok(())
}

fn hands_bench(hands: usize, seed: u64, variant: Variant, no_gpu: bool) -> Result<(), CliError> {
    if hands == 0 {
        return Err(CliError::input("--hands must be positive"));
    }
    let mut rng = Rng::new(seed);
    let counts: Vec<[u8; 34]> = (0..hands)
        .map(|i| random_hand(&mut rng, if i % 2 == 0 { 14 } else { 13 }))
        .collect();
    let shanten_in: Vec<u32> = counts.iter().flat_map(hand::shanten_input).collect();
    let wins: Vec<_> = (0..hands).map(|_| random_win(&mut rng)).collect();
    let score_in: Vec<u32> = wins
        .iter()
        .map(|w| hand::score_input(w).map_err(CliError::failure))
        .collect::<Result<Vec<_>, _>>()?
        .concat();
    let threads = rayon::current_num_threads();
    println!("rinshan bench hands: {hands} hands, variant {variant}, {threads} threads");

    println!("shanten (random 13/14-tile hands), baseline = xiangting 1 thread");
    let mut xt = vec![0u8; hands];
    let base = rate(hands, || {
        for (c, o) in counts.iter().zip(xt.iter_mut()) {
            *o = xiangting::calculate_replacement_number(c, xiangting::PlayerCount::Four).unwrap_or(u8::MAX);
        }
    });
    row("xiangting, 1 thread", base, base);
    let mut out = vec![0u32; hands * SHANTEN_OUT_WORDS];
    row(
        "rinshan cpu, 1 thread",
        rate(hands, || hand::shanten_batch(&shanten_in, &mut out)),
        base,
    );
    let one_thread = out.clone();
    row(
        &format!("rinshan cpu, {threads} threads"),
        rate(hands, || hand::shanten_batch_par(&shanten_in, &mut out)),
        base,
    );
    let disagree = (0..hands)
        .filter(|&i| out[i * SHANTEN_OUT_WORDS] as i32 != i32::from(xt[i]) - 1)
        .count();
    println!("  agreement with xiangting: {}/{hands} hands", hands - disagree);

    let mut gpu = if no_gpu {
        None
    } else {
        match Gpu::new() {
            Ok(g) => Some(g),
            Err(e) => {
                println!("  gpu: skipped: {e}");
                None
            }
        }
    };
    if let Some(g) = gpu.as_mut() {
        let warm = g
            .run(variant, Kernel::Shanten, &shanten_in[..SHANTEN_IN_WORDS])
            .map_err(CliError::failure)?;
        drop(warm);
        let mut res = Ok(Vec::new());
        let r = rate(hands, || res = g.run(variant, Kernel::Shanten, &shanten_in));
        let gpu_out = res.map_err(CliError::failure)?;
        row(&format!("rinshan gpu ({})", g.adapter()), r, base);
        println!("  gpu == cpu: {}", gpu_out == one_thread);
    }

    println!("hand scoring (random winning hands, every reading), baseline = rinshan cpu 1 thread");
    let mut out = vec![0u32; hands * SCORE_OUT_WORDS];
    let base = rate(hands, || hand::score_batch(variant, &score_in, &mut out));
    row("rinshan cpu, 1 thread", base, base);
    let one_thread = out.clone();
    row(
        &format!("rinshan cpu, {threads} threads"),
        rate(hands, || hand::score_batch_par(variant, &score_in, &mut out)),
        base,
    );
    if let Some(g) = gpu.as_mut() {
        g.run(variant, Kernel::Score, &score_in[..SCORE_IN_WORDS])
            .map_err(CliError::failure)?;
        let mut res = Ok(Vec::new());
        let r = rate(hands, || res = g.run(variant, Kernel::Score, &score_in));
        let gpu_out = res.map_err(CliError::failure)?;
        row(&format!("rinshan gpu ({})", g.adapter()), r, base);
        println!("  gpu == cpu: {}", gpu_out == one_thread);
    }
    Ok(())
}

/// Times each stage of drawing a board over `n` self-play positions (the PNG on a tenth of them:
/// it is thousands of times slower).
fn render_bench(n: usize, seed: u64) -> Result<(), CliError> {
    use rinshan_engine::agents::Agent;
    use rinshan_engine::generated::kernel::GameState;
    use rinshan_render::{Board, Options, TileMode};
    let mut env = Env::new(Config {
        seed,
        threads: Some(1),
        auto_reset: true,
        ..Config::new(Variant::Red, 1)
    })
    .map_err(CliError::failure)?;
    env.reset().map_err(CliError::failure)?;
    let mut states: Vec<GameState> = Vec::with_capacity(n);
    while states.len() < n.max(1) {
        states.extend(env.game_states().map_err(CliError::failure)?);
        let a = env.agent_actions(&[[Agent::Rule; 4]]).map_err(CliError::failure)?;
        env.step(&a).map_err(CliError::failure)?;
    }
    let boards: Vec<Board> = states.iter().map(|s| Board::from_state(s, Variant::Red)).collect();
    let decode = rate(states.len(), || {
        for s in &states {
            std::hint::black_box(Board::from_state(s, Variant::Red));
        }
    });
    let mut bytes = [0usize; 2];
    let mut svg_rate = |defs: bool| {
        let opts = Options {
            tiles: TileMode::En,
            defs,
            ..Options::default()
        };
        rate(boards.len(), || {
            for b in &boards {
                bytes[usize::from(defs)] += std::hint::black_box(rinshan_render::svg(b, &opts)).len();
            }
        })
    };
    let fragment = svg_rate(false);
    let standalone = svg_rate(true);
    let few: Vec<&Board> = boards.iter().step_by(10).collect();
    let mut failed = None;
    let png = rate(few.len(), || {
        for b in &few {
            if let Err(e) = rinshan_render::png::png(&rinshan_render::svg(b, &Options::default()), 1.0) {
                failed = Some(e);
            }
        }
    });
    if let Some(e) = failed {
        return Err(CliError::failure(e));
    }
    println!(
        "render bench: {} self-play positions (rule agents, red half games, seed {seed}), one thread",
        boards.len()
    );
    let per = |r: f64| 1e6 / r;
    println!(
        "  decode state -> Board          {:>10.0} /s  {:>8.2} us each",
        decode,
        per(decode)
    );
    println!(
        "  SVG, page fragment (no defs)   {:>10.0} /s  {:>8.2} us each  {:>6.1} KB",
        fragment,
        per(fragment),
        bytes[0] as f64 / boards.len() as f64 / 1024.0
    );
    println!(
        "  SVG, standalone (faces inline) {:>10.0} /s  {:>8.2} us each  {:>6.1} KB",
        standalone,
        per(standalone),
        bytes[1] as f64 / boards.len() as f64 / 1024.0
    );
    println!(
        "  PNG 960x960 (resvg)            {:>10.1} /s  {:>8.0} us each",
        png,
        per(png)
    );
    Ok(())
}
