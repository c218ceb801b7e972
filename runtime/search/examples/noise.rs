//! How noisy a look-ahead comparison is, and what common worlds buy (docs/strength.md):
//!
//!     cargo run --release -p rinshan-search --example noise -- [positions] [worlds]
//!
//! At own-turn positions of `defensive` self-play (red half games), the base agent's action and
//! another legal one are each played out in the same `worlds` worlds. Printed: the spread of one
//! play-out's value, the standard error of their difference over the worlds when the worlds are
//! shared (paired) and when they are not (independent worlds: the two variances add), and the
//! steps of a play-out to the round's end against one to the game's end.

use rinshan_engine::agents::Agent;
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Variant};
use rinshan_search::positions::defensive_game;
use rinshan_search::rollout::play_round;
use rinshan_search::value::placement_value;
use rinshan_search::world::deal;
use rinshan_search::{Focus, Options, Search};

fn variance(xs: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let m = xs.iter().sum::<f64>() / n;
    xs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0)
}

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<usize>().expect("a number"));
    let positions = args.next().unwrap_or(200);
    let worlds = args.next().unwrap_or(64);
    let variant = Variant::Red;
    // Every own-turn decision, as when the figures of docs/strength.md were taken.
    let search = Search::new(
        variant,
        Options {
            focus: Focus::All,
            ..Options::default()
        },
    );
    let (mut paired, mut independent, mut single) = (Vec::new(), Vec::new(), Vec::new());
    let (mut round_steps, mut game_steps, mut plays) = (0u64, 0u64, 0u64);
    let mut rng = Rng::new(7);
    let mut seed = 0u64;
    while paired.len() < positions {
        seed += 1;
        let mut k = 0;
        defensive_game(variant, seed, &mut |p| {
            k += 1;
            if search.looks_ahead(&p.state) && k % 23 == 0 {
                let (s, seat) = (&p.state, p.seat);
                let base = Agent::Defensive.act(variant, s);
                let legal: Vec<u32> = (0..96)
                    .filter(|&a| s.mask[a / 32] >> (a % 32) & 1 == 1)
                    .map(|a| a as u32)
                    .collect();
                let other = legal
                    .iter()
                    .copied()
                    .filter(|&a| a != base)
                    .nth(rng.below(legal.len() as u32 - 1) as usize)
                    .unwrap_or(base);
                let (mut a, mut b) = (Vec::new(), Vec::new());
                for _ in 0..worlds {
                    let w = deal(variant, s, seat, &p.own_draws, &mut rng);
                    let (end_a, n) = play_round(variant, w, base, Agent::Defensive);
                    let (end_b, _) = play_round(variant, w, other, Agent::Defensive);
                    a.push(placement_value(&end_a, seat, variant));
                    b.push(placement_value(&end_b, seat, variant));
                    round_steps += u64::from(n);
                    plays += 1;
                }
                // A play-out to the game's end, for its cost.
                let mut g = deal(variant, s, seat, &p.own_draws, &mut rng);
                game_steps += with_variant!(variant, v => {
                    v::game_step(&mut g, base);
                    let mut n = 1u64;
                    while g.terminated == 0 {
                        let x = v::seat_act(&mut g, Agent::Defensive.kernel());
                        v::game_step(&mut g, x);
                        n += 1;
                    }
                    n
                });
                let d: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x - y).collect();
                let w = worlds as f64;
                paired.push((variance(&d) / w).sqrt());
                independent.push(((variance(&a) + variance(&b)) / w).sqrt());
                single.push(variance(&a).sqrt());
            }
            paired.len() < positions
        });
    }
    let mean = |xs: &[f64]| xs.iter().sum::<f64>() / xs.len() as f64;
    println!("{positions} positions x {worlds} worlds (red, defensive play-outs)");
    println!("spread of one play-out's value (expected rank): {:.4}", mean(&single));
    println!("standard error of a difference, paired worlds: {:.4}", mean(&paired));
    println!(
        "standard error of a difference, independent worlds: {:.4}",
        mean(&independent)
    );
    println!(
        "ratio: {:.2}x (worlds needed for the same precision: {:.1}x fewer)",
        mean(&independent) / mean(&paired),
        (mean(&independent) / mean(&paired)).powi(2)
    );
    println!(
        "steps per play-out: {:.1} to the round's end, {:.1} to the game's end",
        round_steps as f64 / plays as f64,
        game_steps as f64 / positions as f64
    );
}
