//! The facts the game kernel's fast tenpai checks rest on, checked against a brute-force oracle
//! (plain recursion over tile counts, a wait counting only if the hand holds fewer than four of
//! it) on near-tenpai concealed hands:
//!
//! * riichi (`riichi_possible`): a concealed hand of 14 tiles, less three for each closed kan, has
//!   a discard leaving a hand with a wait iff its exact shanten is <= 0 (tiles in the kans do
//!   not void a wait);
//! * the not-tenpai proof (`surely_not_tenpai`): a hand with two or more isolated single tiles
//!   (three or more before a discard) and fewer than twelve kinds of terminals and honors has no
//!   wait.

use rinshan_engine::hand::shanten;
use rinshan_engine::random::Rng;

fn is_orphan(t: usize) -> bool {
    t >= 27 || t.is_multiple_of(9) || t % 9 == 8
}

fn sets(c: &mut [u8; 34], need: u32) -> bool {
    if need == 0 {
        return true;
    }
    let Some(t) = (0..34).find(|&t| c[t] > 0) else {
        return false;
    };
    if c[t] >= 3 {
        c[t] -= 3;
        let ok = sets(c, need - 1);
        c[t] += 3;
        if ok {
            return true;
        }
    }
    if t < 27 && t % 9 <= 6 && c[t + 1] > 0 && c[t + 2] > 0 {
        c[t] -= 1;
        c[t + 1] -= 1;
        c[t + 2] -= 1;
        let ok = sets(c, need - 1);
        c[t] += 1;
        c[t + 1] += 1;
        c[t + 2] += 1;
        return ok;
    }
    false
}

/// Complete with `kans` sets outside the concealed counts `c`.
fn complete(c: &[u8; 34], kans: u32) -> bool {
    let mut h = *c;
    for p in 0..34 {
        if h[p] >= 2 {
            h[p] -= 2;
            let ok = sets(&mut h, 4 - kans);
            h[p] += 2;
            if ok {
                return true;
            }
        }
    }
    if kans > 0 {
        return false;
    }
    let sevens = c.iter().all(|&x| x == 0 || x == 2);
    let orphans = (0..34).all(|t| {
        if is_orphan(t) {
            c[t] == 1 || c[t] == 2
        } else {
            c[t] == 0
        }
    }) && c.contains(&2);
    sevens || orphans
}

fn has_wait(c: &[u8; 34], kans: u32) -> bool {
    (0..34).any(|w| {
        let mut h = *c;
        h[w] += 1;
        h[w] <= 4 && complete(&h, kans)
    })
}

fn discard_to_tenpai(c: &[u8; 34], kans: u32) -> bool {
    (0..34).any(|d| {
        let mut h = *c;
        c[d] > 0 && {
            h[d] -= 1;
            has_wait(&h, kans)
        }
    })
}

fn isolated(c: &[u8; 34]) -> usize {
    (0..34)
        .filter(|&t| {
            c[t] == 1
                && (t >= 27 || {
                    let suit = t / 9 * 9;
                    !(suit..suit + 9).any(|u| u != t && u.abs_diff(t) <= 2 && c[u] > 0)
                })
        })
        .count()
}

fn orphan_kinds(c: &[u8; 34]) -> usize {
    (0..34).filter(|&t| is_orphan(t) && c[t] > 0).count()
}

/// A concealed hand of 14 - 3 x `kans` tiles near a complete one: sets and pairs of a few
/// neighbouring types (so quads and waits on one's own tiles are common), seven pairs or thirteen
/// orphans (without kans), then a few tiles moved. The kans themselves are not in the counts:
/// they take four copies of some type, but the rule under test ignores them.
fn near_complete(rng: &mut Rng, kans: u32) -> [u8; 34] {
    let mut c = [0u8; 34];
    let mut n = 0;
    let size = 14 - 3 * kans;
    match if kans == 0 { rng.below(10) } else { 2 } {
        0 => {
            while n < size {
                let t = rng.below(34) as usize;
                if c[t] <= 2 {
                    c[t] += 2;
                    n += 2;
                }
            }
        }
        1 => {
            (0..34).filter(|&t| is_orphan(t)).for_each(|t| c[t] = 1);
            c[[0, 8, 9, 17, 18, 26, 27, 28, 29, 30, 31, 32, 33][rng.below(13) as usize]] += 1;
        }
        _ => {
            let low = rng.below(34) as usize;
            let span = 4 + rng.below(9);
            while n < size {
                let t = (low + rng.below(span) as usize) % 34;
                let run = t < 27 && t % 9 <= 6 && c[t] < 4 && c[t + 1] < 4 && c[t + 2] < 4;
                match rng.below(3) {
                    0 if c[t] <= 1 && n + 3 <= size => {
                        c[t] += 3;
                        n += 3;
                    }
                    1 if run && n + 3 <= size => {
                        (t..t + 3).for_each(|u| c[u] += 1);
                        n += 3;
                    }
                    _ if c[t] < 4 => {
                        c[t] += 1;
                        n += 1;
                    }
                    _ => {}
                }
            }
        }
    }
    for _ in 0..rng.below(6) {
        let (from, to) = (rng.below(34) as usize, rng.below(34) as usize);
        if c[from] > 0 && c[to] < 4 {
            c[from] -= 1;
            c[to] += 1;
        }
    }
    c
}

#[test]
fn riichi_is_shanten_at_most_zero_with_or_without_closed_kans() {
    let mut rng = Rng::new(7);
    for kans in 0..=3 {
        let mut possible = 0;
        for _ in 0..20_000 {
            let c = near_complete(&mut rng, kans);
            let fast = shanten(&c).shanten <= 0;
            assert_eq!(fast, discard_to_tenpai(&c, kans), "{kans} kans: {c:?}");
            possible += usize::from(fast);
        }
        assert!(
            (1_000..19_000).contains(&possible),
            "{kans} kans: both answers are common: {possible}"
        );
    }
}

#[test]
fn isolated_tiles_prove_a_hand_is_not_tenpai() {
    let mut rng = Rng::new(9);
    let mut proved = 0;
    for _ in 0..30_000 {
        let c = near_complete(&mut rng, 0);
        if isolated(&c) > 2 && orphan_kinds(&c) < 12 {
            assert!(!discard_to_tenpai(&c, 0), "{c:?}");
            proved += 1;
        }
        let mut h = c;
        let d = (0..34)
            .cycle()
            .skip(rng.below(34) as usize)
            .find(|&t| h[t] > 0)
            .expect("a tile");
        h[d] -= 1;
        if isolated(&h) > 1 && orphan_kinds(&h) < 12 {
            assert!(!has_wait(&h, 0), "{h:?}");
            proved += 1;
        }
    }
    assert!(proved > 5_000, "the proof applies often: {proved}");
}
