//! How the opponents' hands of the look-ahead's worlds compare with the real ones
//! (docs/strength.md):
//!
//!     cargo run --release -p rinshan-search --example belief -- [positions] [worlds]
//!
//! At own-turn positions of `defensive` self-play (red half games), each other seat's shanten in
//! the real game and in worlds dealt by `world::deal`, by how many tiles that seat has discarded,
//! how many kinds of tile a tenpai hand among them waits on (what decides how often it is dealt
//! into) and how many of those kinds are honors, how often a seat in riichi is tenpai in the
//! worlds (always in the real game), and how often a closed seat not in riichi is (never in the
//! real game: `defensive` declares riichi whenever it can).

use rinshan_engine::generated::kernel::{self, GameState, ShantenInput, SEAT_RIICHI};
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;
use rinshan_search::positions::defensive_game;
use rinshan_search::world::deal;
use rinshan_search::{Focus, Options, Search};

fn shanten(s: &GameState, q: u32) -> i32 {
    kernel::shanten(ShantenInput {
        hand: kernel::hand_counts(&mut s.clone(), q),
    })
    .shanten
}

/// Adds seat `q`'s waits at `s`, if it is tenpai, to `into` with weight `w`: the hand, its kinds
/// of winning tile, those that are honors, and whether one of them is in its own river (furiten:
/// it cannot win on another seat's discard).
fn count_waits(into: &mut [f64; 4], s: &GameState, q: u32, w: f64) {
    let pair = |x: &[u32]| u64::from(x[(q * 2) as usize]) | u64::from(x[(q * 2 + 1) as usize]) << 32;
    let mask = pair(&s.waits);
    if mask != 0 {
        into[0] += w;
        into[1] += w * f64::from(mask.count_ones());
        into[2] += w * f64::from((mask >> 27).count_ones());
        into[3] += w * f64::from(u8::from(mask & pair(&s.discarded) != 0));
    }
}

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<usize>().expect("a number"));
    let positions = args.next().unwrap_or(300);
    let worlds = args.next().unwrap_or(16);
    let variant = Variant::Red;
    // Every own-turn decision, as when the figures of docs/strength.md were taken.
    let search = Search::new(
        variant,
        Options {
            focus: Focus::All,
            ..Options::default()
        },
    );
    // Per bucket of discards made (0-5, 6-11, 12+): (real shanten sum, real tenpai, world shanten
    // sum, world tenpai, count).
    let mut buckets = [[0f64; 5]; 3];
    // Over tenpai hands, real and in the worlds: (hands, wait kinds, honor wait kinds, furiten),
    // then the same over seats in riichi.
    let mut waits = [[0f64; 4]; 4];
    // Seats in riichi, and the share of worlds in which they are tenpai.
    let mut riichi = [0f64; 2];
    // Closed seats not in riichi (which `defensive` would have declared if tenpai): (seats, real
    // tenpai, world tenpai).
    let mut dama = [0f64; 3];
    let mut rng = Rng::new(3);
    let (mut seed, mut found) = (0u64, 0usize);
    while found < positions {
        seed += 1;
        let mut k = 0;
        // The seed's high word is 1: the games the figures in docs/strength.md came from.
        defensive_game(variant, seed | 1 << 32, &mut |p| {
            k += 1;
            if search.looks_ahead(&p.state) && k % 17 == 0 {
                found += 1;
                let (s, seat) = (&p.state, p.seat);
                let ws: Vec<GameState> = (0..worlds)
                    .map(|_| deal(variant, s, seat, &p.own_draws, &mut rng))
                    .collect();
                for q in (0..4).filter(|&q| q != seat) {
                    let discards = kernel::byte_of(s.river_lens, q);
                    let b = &mut buckets[(discards as usize / 6).min(2)];
                    let real = shanten(s, q);
                    b[0] += f64::from(real);
                    b[1] += f64::from(u8::from(real == 0));
                    for w in &ws {
                        let x = shanten(w, q);
                        b[2] += f64::from(x) / worlds as f64;
                        b[3] += f64::from(u8::from(x == 0)) / worlds as f64;
                    }
                    b[4] += 1.0;
                    count_waits(&mut waits[0], s, q, 1.0);
                    let in_riichi = s.seat_flags[q as usize] & SEAT_RIICHI != 0;
                    if in_riichi {
                        count_waits(&mut waits[2], s, q, 1.0);
                    }
                    if s.seat_flags[q as usize] & SEAT_RIICHI == 0 && kernel::byte_of(s.meld_counts, q) == 0 {
                        dama[0] += 1.0;
                        dama[1] += f64::from(u8::from(real == 0));
                        for w in &ws {
                            dama[2] += f64::from(u8::from(shanten(w, q) == 0)) / worlds as f64;
                        }
                    }
                    if s.seat_flags[q as usize] & SEAT_RIICHI != 0 {
                        riichi[0] += 1.0;
                        for w in &ws {
                            riichi[1] += f64::from(u8::from(shanten(w, q) == 0)) / worlds as f64;
                        }
                    }
                    for w in &ws {
                        count_waits(&mut waits[1], w, q, 1.0 / worlds as f64);
                        if in_riichi {
                            count_waits(&mut waits[3], w, q, 1.0 / worlds as f64);
                        }
                    }
                }
            }
            found < positions
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
    for (i, w) in waits.iter().enumerate() {
        let n = w[0].max(1e-9);
        println!(
            "{} tenpai hands: {:.1}, wait kinds {:.2}, of them honors {:.2}, furiten {:.1}%",
            ["real ", "world", "real riichi ", "world riichi"][i],
            w[0],
            w[1] / n,
            w[2] / n,
            100.0 * w[3] / n
        );
    }
    println!(
        "seats in riichi: {}, tenpai in {:.1}% of their worlds",
        riichi[0],
        100.0 * riichi[1] / riichi[0].max(1.0)
    );
    println!(
        "closed seats not in riichi: {}, tenpai {:.1}% real, {:.1}% in the worlds",
        dama[0],
        100.0 * dama[1] / dama[0].max(1.0),
        100.0 * dama[2] / dama[0].max(1.0)
    );
}
