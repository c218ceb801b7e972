//! `rinshan bench hands`: evaluations per second of the generated kernels on the CPU (one thread,
//! all threads) and on the GPU, beside the `xiangting` crate's shanten on the same hands.

use std::time::Instant;

use rinshan::gpu::{Gpu, Kernel};
use rinshan::hand::{self, SCORE_IN_WORDS, SCORE_OUT_WORDS, SHANTEN_IN_WORDS, SHANTEN_OUT_WORDS};
use rinshan::random::{random_hand, random_win, Rng};
use rinshan::Variant;

use super::CliError;

#[derive(clap::Subcommand)]
pub enum What {
    /// Shanten and hand-scoring evaluations per second: CPU (1 thread, all threads), GPU, xiangting
    Hands {
        /// Hands per measurement
        #[arg(long, default_value_t = 200_000)]
        hands: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Rule variant for scoring: red or no-red
        #[arg(long, default_value = "red")]
        variant: String,
        /// Skip the GPU backend
        #[arg(long)]
        no_gpu: bool,
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
    let What::Hands {
        hands,
        seed,
        variant,
        no_gpu,
    } = what;
    let variant =
        Variant::from_name(&variant).ok_or_else(|| CliError::input(format!("unknown variant `{variant}`")))?;
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
        rate(hands, || hand::shanten_batch(variant, &shanten_in, &mut out)),
        base,
    );
    let one_thread = out.clone();
    row(
        &format!("rinshan cpu, {threads} threads"),
        rate(hands, || hand::shanten_batch_par(variant, &shanten_in, &mut out)),
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
