//! Steps per second of the native game kernels alone (no batch, no threads): random-policy `half`
//! games played by calling `game_step` and `game_view` in a loop, one game after another, on one
//! core. The same games every run, so the printed fingerprint (a hash of every action and reward)
//! tells whether a kernel change kept the games identical.
//!
//! `cargo run --release -p rinshan --example kernel_steps -- [games] [red|no-red|both]`

use std::time::Instant;

use rinshan_engine::random::Rng;

macro_rules! play {
    ($v:ident, $games:expr) => {{
        use rinshan_engine::generated::$v as k;
        let mut rng = Rng::new(42);
        let mut steps = 0u64;
        let mut hash = 0xcbf2_9ce4_8422_2325u64;
        let started = Instant::now();
        for g in 0..$games {
            let input = rinshan_engine::generated::kernel::ResetInput {
                seed: [g, 0x5eed],
                mode: 2,
                dealer: 4,
                use_wall: 0,
                wall: [0; 136],
                uma: [30000, 10000, -10000, -30000],
                penalty: -1.0,
                auto_reset: 0,
            };
            let mut s = k::game_new(input);
            let mut view = k::game_view(s);
            while view.terminated == 0 {
                let a = rng.pick_legal(&view.mask);
                k::game_step(&mut s, a);
                view = k::game_view(s);
                steps += 1;
                for w in [
                    a,
                    view.rewards[0].to_bits(),
                    view.rewards[1].to_bits(),
                    view.rewards[2].to_bits(),
                ] {
                    hash = (hash ^ u64::from(w)).wrapping_mul(0x0100_0000_01b3);
                }
            }
        }
        (steps, started.elapsed().as_secs_f64(), hash)
    }};
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let games: u32 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(2000);
    let which = args.get(2).map(String::as_str).unwrap_or("both");
    let report = |name: &str, (steps, secs, hash): (u64, f64, u64)| {
        println!(
            "{name:<7} {games} games  {steps:>9} steps  {secs:6.3} s  {:>10.0} steps/s  fingerprint {hash:016x}",
            steps as f64 / secs
        );
    };
    if which != "no-red" {
        report("red", play!(red, games));
    }
    if which != "red" {
        report("no-red", play!(no_red, games));
    }
}
