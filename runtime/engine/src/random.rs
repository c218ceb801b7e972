//! Deterministic random hands and random legal actions for benchmarks, tests and self-play (not the environment's wall shuffle, which
//! lives in the kernels with their counter-based RNG).

use crate::hand::{Win, WinContext};
use crate::notation::{Meld, MeldKind};
use crate::tile::TileType;

/// splitmix64: small, fast and good enough to sample test hands.
#[derive(Debug, Clone)]
pub struct Rng(u64);

impl Rng {
    /// A stream seeded with `seed` (the same seed, the same numbers).
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in 0..n (n > 0), without modulo bias.
    pub fn below(&mut self, n: u32) -> u32 {
        (((self.next_u64() >> 32) * u64::from(n)) >> 32) as u32
    }

    /// True with probability `percent` / 100.
    pub fn chance(&mut self, percent: u32) -> bool {
        self.below(100) < percent
    }

    /// A uniformly random action among the set bits of a legal-action mask (0 when none is set):
    /// the kernel's `nth_legal` of a uniform draw below their count.
    pub fn pick_legal(&mut self, mask: &[u32; 3]) -> u32 {
        let n = mask.iter().map(|w| w.count_ones()).sum();
        if n == 0 {
            return 0;
        }
        crate::generated::kernel::nth_legal(*mask, self.below(n))
    }
}

/// A uniformly shuffled wall's first `n` tiles as counts (n <= 136).
pub fn random_hand(rng: &mut Rng, n: usize) -> [u8; 34] {
    let mut wall: Vec<u8> = (0..136).map(|i| (i / 4) as u8).collect();
    let mut counts = [0u8; 34];
    for i in 0..n.min(136) {
        let j = i + rng.below((136 - i) as u32) as usize;
        wall.swap(i, j);
        counts[wall[i] as usize] += 1;
    }
    counts
}

const TERMINALS_AND_HONORS: [u8; 13] = [0, 8, 9, 17, 18, 26, 27, 28, 29, 30, 31, 32, 33];

/// The type of index `t`, for indices this file draws below 34.
fn tile_type(t: u32) -> TileType {
    TileType::new(t as u8).unwrap_or_else(|| unreachable!("tile index {t} drawn below 34"))
}

/// A random winning hand (it may still lack a yaku): four sets and a pair with 0-4 melds, or now
/// and then seven pairs or thirteen orphans, with random circumstances.
pub fn random_win(rng: &mut Rng) -> Win {
    loop {
        if let Some(w) = try_random_win(rng) {
            return w;
        }
    }
}

fn try_random_win(rng: &mut Rng) -> Option<Win> {
    let mut hand = [0u8; 34];
    let mut melds = Vec::new();
    let shape = rng.below(100);
    if shape < 6 {
        let mut picked = 0;
        while picked < 7 {
            let t = rng.below(34) as usize;
            if hand[t] == 0 {
                hand[t] = 2;
                picked += 1;
            }
        }
    } else if shape < 8 {
        for &t in &TERMINALS_AND_HONORS {
            hand[t as usize] = 1;
        }
        hand[TERMINALS_AND_HONORS[rng.below(13) as usize] as usize] += 1;
    } else {
        // Concentrating on one suit now and then reaches chinitsu, ittsu, chuuren and many readings.
        let one_suit = rng.chance(20).then(|| rng.below(3));
        let n_melds = if rng.chance(50) { 0 } else { 1 + rng.below(4) as usize };
        for k in 0..4 {
            let suit = one_suit.unwrap_or_else(|| rng.below(3));
            let run = rng.chance(60);
            let tile = if run {
                suit * 9 + rng.below(7)
            } else if one_suit.is_some() {
                suit * 9 + rng.below(9)
            } else {
                rng.below(34)
            };
            let tiles: Vec<u32> = if run {
                vec![tile, tile + 1, tile + 2]
            } else {
                vec![tile; 3]
            };
            if k < n_melds {
                let kind = if run {
                    MeldKind::Chi
                } else {
                    [
                        MeldKind::Pon,
                        MeldKind::Pon,
                        MeldKind::Kan,
                        MeldKind::Ankan,
                        MeldKind::Kakan,
                    ][rng.below(5) as usize]
                };
                melds.push(Meld {
                    kind,
                    tile: tile_type(tile),
                    red: 0,
                });
            } else {
                for t in tiles {
                    hand[t as usize] += 1;
                }
            }
        }
        let pair = match one_suit {
            Some(s) if rng.chance(80) => s * 9 + rng.below(9),
            _ => rng.below(34),
        } as usize;
        hand[pair] += 2;
    }
    let mut all = hand;
    for m in &melds {
        for t in m.tiles() {
            all[t.index()] += 1;
        }
    }
    if all.iter().any(|&n| n > 4) {
        return None;
    }
    let concealed: Vec<TileType> = TileType::all()
        .flat_map(|t| std::iter::repeat_n(t, usize::from(hand[t.index()])))
        .collect();
    let win = concealed[rng.below(concealed.len() as u32) as usize];
    let has_kan = melds
        .iter()
        .any(|m| matches!(m.kind, MeldKind::Kan | MeldKind::Ankan | MeldKind::Kakan));
    let closed = melds.iter().all(|m| m.kind == MeldKind::Ankan);
    let dealer = rng.chance(25);
    let tsumo = rng.chance(45);
    let riichi = closed && rng.chance(40);
    let mut c = WinContext {
        tsumo,
        riichi,
        double_riichi: riichi && rng.chance(5),
        ippatsu: riichi && rng.chance(15),
        haitei: tsumo && rng.chance(3),
        houtei: !tsumo && rng.chance(3),
        rinshan: false,
        chankan: false,
        tenhou: false,
        chiihou: false,
        dealer,
        round_wind: rng.below(2) as u8,
        seat_wind: if dealer { 0 } else { 1 + rng.below(3) as u8 },
        dora: (0..1 + rng.below(3)).map(|_| tile_type(rng.below(34))).collect(),
        ura: Vec::new(),
        honba: if rng.chance(20) { rng.below(4) } else { 0 },
        sticks: if rng.chance(20) { rng.below(3) } else { 0 },
    };
    if c.riichi {
        c.ura = (0..c.dora.len()).map(|_| tile_type(rng.below(34))).collect();
    }
    if tsumo && has_kan && !c.haitei && rng.chance(20) {
        c.rinshan = true;
    }
    if !tsumo && !c.houtei && all[win.index()] == 1 && rng.chance(3) {
        c.chankan = true;
    }
    if tsumo && melds.is_empty() && !c.riichi && !c.haitei && rng.chance(2) {
        if dealer {
            c.tenhou = true;
        } else {
            c.chiihou = true;
        }
    }
    let fives = [all[4], all[13], all[22]];
    let aka = fives.iter().filter(|&&n| n > 0 && rng.chance(50)).count() as u8;
    Some(Win {
        hand,
        win,
        melds,
        aka,
        context: c,
    })
}

#[cfg(test)]
mod tests {
    use super::Rng;

    /// The set bits of the mask as action ids, in order: the brute-force list `pick_legal` picks
    /// from.
    fn legal_ids(mask: &[u32; 3]) -> Vec<u32> {
        (0..96)
            .filter(|&a| (mask[a as usize / 32] >> (a % 32)) & 1 != 0)
            .collect()
    }

    #[test]
    fn pick_legal_takes_the_drawn_index_among_the_set_bits() {
        let mut masks = Rng::new(7);
        for case in 0..20_000u64 {
            // Sparse and dense words, and whole words empty, as legal-action masks are.
            let mut mask = [0u32; 3];
            for w in &mut mask {
                let density = masks.below(4);
                *w = (0..density).fold(u32::MAX, |x, _| x & masks.next_u64() as u32);
                if masks.chance(30) {
                    *w = 0;
                }
            }
            let ids = legal_ids(&mask);
            let mut rng = Rng::new(case);
            let mut twin = rng.clone();
            let picked = rng.pick_legal(&mask);
            if ids.is_empty() {
                assert_eq!(picked, 0);
            } else {
                let k = twin.below(ids.len() as u32);
                assert_eq!(picked, ids[k as usize], "mask {mask:08x?}, k {k}");
            }
        }
    }
}
