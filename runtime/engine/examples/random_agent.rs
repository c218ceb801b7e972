//! A random legal policy driving a batch of games through `rinshan_engine::env`: the smallest complete
//! use of the environment API. Run with `cargo run --release --example random_agent`.

use rinshan_engine::env::{Backend, Config, Env, Mode};
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut config = Config::new(Variant::Red, 64); // a batch of 64 games
    config.mode = Mode::Half;
    config.backend = Backend::Cpu; // or Backend::Gpu
    let mut env = Env::new(config)?;
    let batch = env.batch();
    let mut rng = Rng::new(1);
    let mut totals = vec![[0f32; 4]; batch];
    let mut step = env.reset()?.clone();
    while !step.terminated.iter().all(|&t| t) {
        // One decision per game: the current player's action (finished games ignore theirs).
        let actions: Vec<u32> = (0..batch)
            .map(|i| {
                let legal: Vec<u32> = step.legal_actions(i).collect();
                legal
                    .get(rng.below(legal.len().max(1) as u32) as usize)
                    .copied()
                    .unwrap_or(0)
            })
            .collect();
        step = env.step(&actions)?.clone();
        for (total, r) in totals.iter_mut().zip(&step.rewards) {
            for seat in 0..4 {
                total[seat] += r[seat];
            }
        }
    }
    println!(
        "final score change of game 0 (units of 100 points, uma included): {:?}",
        totals[0]
    );
    Ok(())
}
