//! How the opponents' hands of the look-ahead's worlds compare with the real ones
//! (docs/strength.md):
//!
//!     cargo run --release -p rinshan-search --example belief -- [positions] [worlds]
//!
//! At own-turn positions of `defensive` self-play (red half games), each other seat's shanten in
//! the real game and in worlds dealt by `world::deal`, by how many tiles that seat has discarded.

use rinshan_engine::agents::Agent;
use rinshan_engine::generated::kernel::{self, GameState, ResetInput, ShantenInput, MODE_HALF};
use rinshan_engine::observe::OwnDraws;
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Variant};
use rinshan_search::world::deal;
use rinshan_search::{Options, Search};

fn shanten(s: &GameState, q: u32) -> i32 {
    kernel::shanten(ShantenInput {
        hand: kernel::hand_counts(&mut s.clone(), q),
    })
    .shanten
}

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<usize>().expect("a number"));
    let positions = args.next().unwrap_or(300);
    let worlds = args.next().unwrap_or(16);
    let variant = Variant::Red;
    let search = Search::new(variant, Options::default());
    // Per bucket of discards made (0-5, 6-11, 12+): (real shanten sum, real tenpai, world shanten
    // sum, world tenpai, count).
    let mut buckets = [[0f64; 5]; 3];
    let mut rng = Rng::new(3);
    let (mut seed, mut found) = (0u64, 0usize);
    while found < positions {
        seed += 1;
        with_variant!(variant, v => {
            let mut s: GameState = v::game_new(ResetInput {
                seed: [seed as u32, 1],
                mode: MODE_HALF,
                dealer: 4,
                use_wall: 0,
                wall: [0; 136],
                uma: [0; 4],
                penalty: v::host::ILLEGAL_ACTION_PENALTY,
                auto_reset: 0,
            });
            let mut own: Vec<OwnDraws> = vec![OwnDraws::default(); 4];
            for q in 0..4 {
                own[q as usize].update(variant, &s, &mut s.clone(), q);
            }
            let mut k = 0;
            while s.terminated == 0 && found < positions {
                k += 1;
                if search.looks_ahead(&s) && k % 17 == 0 {
                    found += 1;
                    let seat = s.current;
                    let ws: Vec<GameState> =
                        (0..worlds).map(|_| deal(variant, &s, seat, &own[seat as usize].positions, &mut rng)).collect();
                    for q in (0..4).filter(|&q| q != seat) {
                        let discards = kernel::byte_of(s.river_lens, q);
                        let b = &mut buckets[(discards as usize / 6).min(2)];
                        let real = shanten(&s, q);
                        b[0] += f64::from(real);
                        b[1] += f64::from(u8::from(real == 0));
                        for w in &ws {
                            let x = shanten(w, q);
                            b[2] += f64::from(x) / worlds as f64;
                            b[3] += f64::from(u8::from(x == 0)) / worlds as f64;
                        }
                        b[4] += 1.0;
                    }
                }
                let x = v::seat_act(&mut s, Agent::Defensive.kernel());
                let before = s;
                v::game_step(&mut s, x);
                for q in 0..4 {
                    own[q as usize].update(variant, &before, &mut s.clone(), q);
                }
            }
        });
    }
    println!("{positions} positions, {worlds} worlds each (red, defensive self-play)");
    println!(
        "{:>10} {:>8} {:>13} {:>13} {:>12} {:>12}",
        "discards", "seats", "real shanten", "world shanten", "real tenpai", "world tenpai"
    );
    for (i, b) in buckets.iter().enumerate() {
        let n = b[4].max(1.0);
        println!(
            "{:>10} {:>8} {:>13.2} {:>13.2} {:>11.1}% {:>11.1}%",
            ["0-5", "6-11", "12+"][i],
            b[4],
            b[0] / n,
            b[2] / n,
            100.0 * b[1] / n,
            100.0 * b[3] / n
        );
    }
}
