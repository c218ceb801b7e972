//! The game's randomness: the kernel's ChaCha8 is the rand_chacha crate's stream word for word,
//! the deal depends on every bit of the 64-bit seed, ten million games deal ten million different
//! walls, and each tile type is as likely at every wall position (chi-square over a million walls).

use std::collections::HashSet;
use std::hash::{BuildHasher, BuildHasherDefault};

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use rinshan_engine::env::env_seed;
use rinshan_engine::generated::kernel::{self as k, RNG_AGENT, RNG_DEALER, RNG_WALL};
use rinshan_engine::generated::{no_red, red};

/// The crate's stream of (seed, purpose, id): the key is the seed's two words and the purpose, the
/// stream id `a | b << 32`.
fn reference(seed: [u32; 2], purpose: u32, a: u32, b: u32) -> ChaCha8Rng {
    let mut key = [0u8; 32];
    for (i, w) in [seed[0], seed[1], purpose].iter().enumerate() {
        key[4 * i..4 * i + 4].copy_from_slice(&w.to_le_bytes());
    }
    let mut rng = ChaCha8Rng::from_seed(key);
    rng.set_stream(u64::from(a) | u64::from(b) << 32);
    rng
}

#[test]
fn the_kernel_stream_is_rand_chachas_chacha8() {
    let cases = [
        ([0, 0], RNG_WALL, 0, 0),
        ([1, 0], RNG_WALL, 0, 1),
        ([0xdead_beef, 0x0123_4567], RNG_DEALER, 7, 0),
        ([u32::MAX, u32::MAX], RNG_AGENT, 123_456, 0),
        ([42, 99], RNG_WALL, u32::MAX, u32::MAX),
    ];
    for (seed, purpose, a, b) in cases {
        let mut ours = k::rng_new(seed, purpose, a, b);
        let mut theirs = reference(seed, purpose, a, b);
        // Several blocks: the refill at each 16th word is checked too.
        for n in 0..100 {
            assert_eq!(
                k::rng_word(&mut ours),
                theirs.next_u32(),
                "word {n} of seed {seed:?} purpose {purpose} stream ({a}, {b})"
            );
        }
    }
}

/// The wall of round `round` of game `game` (tile values in dealing order).
fn wall(seed: u64, game: u32, round: u32) -> [u32; 136] {
    red::shuffled_wall([seed as u32, (seed >> 32) as u32], game, round)
}

#[test]
fn every_seed_bit_changes_the_deal() {
    for base in [0u64, 0x0123_4567_89ab_cdef, u64::MAX] {
        let w = wall(base, 0, 0);
        for bit in 0..64 {
            assert_ne!(w, wall(base ^ 1 << bit, 0, 0), "seed {base:#x}, bit {bit}");
        }
    }
    // The game and the round select their own walls too.
    assert_ne!(wall(5, 0, 0), wall(5, 1, 0));
    assert_ne!(wall(5, 0, 0), wall(5, 0, 1));
    // The two variants shuffle the same way; only the red fives differ.
    let s = [9, 10];
    let (r, n) = (red::shuffled_wall(s, 3, 4), no_red::shuffled_wall(s, 3, 4));
    let kind = |v: u32| if v >= 34 { (v - 34) * 9 + 4 } else { v };
    assert_eq!(r.map(kind), n);
}

/// A 128-bit fingerprint of a wall (two keyed hashes with fixed keys).
fn wall_hash(w: &[u32; 136]) -> u128 {
    let bytes: Vec<u8> = w.iter().map(|&v| v as u8).collect();
    let a = BuildHasherDefault::<std::collections::hash_map::DefaultHasher>::default().hash_one(&bytes);
    let b = BuildHasherDefault::<std::collections::hash_map::DefaultHasher>::default().hash_one((&bytes, 1u8));
    u128::from(a) << 64 | u128::from(b)
}

#[test]
fn ten_million_games_deal_ten_million_walls() {
    const GAMES: u64 = 10_000_000;
    // Each env's seed as Env::reset derives it, so this is what a run of ten million games deals.
    let mut hashes: Vec<u128> = (0..GAMES)
        .into_par_iter()
        .map(|i| wall_hash(&wall(env_seed(1, i, 0), 0, 0)))
        .collect();
    hashes.par_sort_unstable();
    let repeats = hashes.windows(2).filter(|p| p[0] == p[1]).count();
    assert_eq!(repeats, 0, "{repeats} repeated walls among {GAMES} games");
    // And the rounds of one game: every round draws a new wall.
    let rounds: HashSet<u128> = (0..1000).map(|r| wall_hash(&wall(7, 0, r))).collect();
    assert_eq!(rounds.len(), 1000);
}

#[test]
fn each_tile_type_is_as_likely_at_every_wall_position() {
    const WALLS: u64 = 1_000_000;
    let counts: Vec<[[u64; 34]; 136]> = (0..WALLS)
        .into_par_iter()
        .fold(
            || [[0u64; 34]; 136],
            |mut c, i| {
                let seed = env_seed(2, i, 0);
                let w = no_red::shuffled_wall([seed as u32, (seed >> 32) as u32], 0, 0);
                for (pos, &v) in w.iter().enumerate() {
                    c[pos][v as usize] += 1;
                }
                c
            },
        )
        .collect();
    let mut total = [[0u64; 34]; 136];
    for c in &counts {
        for (t, row) in total.iter_mut().zip(c) {
            for (a, b) in t.iter_mut().zip(row) {
                *a += b;
            }
        }
    }
    // 4 copies of each of 34 types: each type is expected WALLS * 4 / 136 times at each position.
    let expected = WALLS as f64 * 4.0 / 136.0;
    let mut sum = 0.0;
    for (pos, row) in total.iter().enumerate() {
        let chi2: f64 = row.iter().map(|&n| (n as f64 - expected).powi(2) / expected).sum();
        // 33 degrees of freedom: P(chi2 > 90) is about 1e-7.
        assert!(
            chi2 < 90.0,
            "position {pos}: chi-square {chi2:.1} over 33 degrees of freedom"
        );
        sum += chi2;
    }
    // All positions together: 136 * 33 = 4488 degrees of freedom (mean 4488, sd 95).
    let df: f64 = 136.0 * 33.0;
    let sd = (2.0 * df).sqrt();
    assert!(
        (sum - df).abs() < 6.0 * sd,
        "total chi-square {sum:.0} over {df} degrees of freedom"
    );
}

#[test]
fn bounded_draws_are_lemires_on_the_crates_words() {
    let mut ours = k::rng_new([3, 4], RNG_AGENT, 9, 0);
    let mut theirs = reference([3, 4], RNG_AGENT, 9, 0);
    // Small bounds as the shuffle and the agents draw, and large ones where rejection is likely.
    let bounds = (1..=136u32).chain([1 << 31, (1 << 31) + 1, u32::MAX, 3_000_000_000]);
    for bound in bounds.clone().chain(bounds) {
        let want = loop {
            let m = u64::from(theirs.next_u32()) * u64::from(bound);
            if (m as u32) >= bound.wrapping_neg() % bound {
                break (m >> 32) as u32;
            }
        };
        assert_eq!(k::random_below(&mut ours, bound), want, "bound {bound}");
    }
    for (a, b) in [
        (0, 0),
        (u32::MAX, u32::MAX),
        (0xdead_beef, 0x1234_5678),
        (1 << 16, 1 << 16),
    ] {
        let p = u64::from(a) * u64::from(b);
        assert_eq!(k::mul_wide(a, b), [(p >> 32) as u32, p as u32], "{a} * {b}");
    }
}
