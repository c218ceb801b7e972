//! Every complete decomposition of every suit code.
//!
//! A decomposition splits all tiles of a suit into sets (runs, triplets) plus at most one pair.
//! Rather than splitting each of the 1.95M codes, we enumerate every multiset of at most four sets
//! with an optional pair whose counts stay <= 4 (23,533 of them) and file each under the code it
//! adds up to: a code with no entry has no decomposition. Keeping all of them (not a fixed few per
//! code) is what lets hand evaluation pick the best reading. Within a code they are sorted by pair
//! position, then by the ascending list of set values, so the tables are the same on every build.

use super::code::encode;
use super::cost::MAX_SETS;

/// `word0` pair field when the suit holds no pair.
pub const NO_PAIR: u32 = 15;
/// `word0` set values below this are runs starting there; the rest are triplets at `v - RUN_KINDS`.
pub const RUN_KINDS: u32 = 7;
/// Number of set values (7 run starts + 9 triplet positions).
pub const SET_KINDS: u32 = 16;

/// `word0`: bits 0-3 pair position or [`NO_PAIR`]; bits 4-6 number of sets; set `k` at bits
/// `8 + 4k..12 + 4k`, sets ascending.
pub const W0_NSETS_SHIFT: u32 = 4;
pub const W0_SETS_SHIFT: u32 = 8;

/// `word1`: bits 0-6 run starts; bits 7-15 triplets; bits 16-17 identical-run pairs; bit 18
/// outside; bit 19 nine gates.
pub const W1_TRIPLETS_SHIFT: u32 = 7;
pub const W1_DOUBLE_RUNS_SHIFT: u32 = 16;
pub const W1_OUTSIDE_BIT: u32 = 1 << 18;
pub const W1_NINE_GATES_BIT: u32 = 1 << 19;

/// One decomposition as the tables store it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Decomp {
    /// Sort key fields first: within a code the set count and pair presence are fixed by the tile
    /// total, so (pair, sets) orders decompositions of one code completely.
    pub pair: Option<u8>,
    pub sets: [u8; MAX_SETS],
    pub n_sets: u8,
}

impl Decomp {
    fn sets(&self) -> &[u8] {
        &self.sets[..usize::from(self.n_sets)]
    }

    pub(crate) fn counts(&self) -> Option<[u8; 9]> {
        let mut c = [0u8; 9];
        for &v in self.sets() {
            if u32::from(v) < RUN_KINDS {
                c[usize::from(v)..usize::from(v) + 3].iter_mut().for_each(|x| *x += 1);
            } else {
                c[usize::from(v) - RUN_KINDS as usize] += 3;
            }
        }
        if let Some(p) = self.pair {
            c[usize::from(p)] += 2;
        }
        c.iter().all(|&x| x <= 4).then_some(c)
    }

    pub(crate) fn word0(&self) -> u32 {
        let pair = self.pair.map_or(NO_PAIR, u32::from);
        let sets = self
            .sets()
            .iter()
            .enumerate()
            .fold(0, |w, (k, &v)| w | u32::from(v) << (W0_SETS_SHIFT + 4 * k as u32));
        pair | u32::from(self.n_sets) << W0_NSETS_SHIFT | sets
    }

    /// The yaku-relevant facts of this reading, so scoring needs no decode of the sets.
    pub(crate) fn word1(&self, counts: &[u8; 9]) -> u32 {
        let mut run_mult = [0u32; RUN_KINDS as usize];
        let mut triplets = 0u32;
        for &v in self.sets() {
            match u32::from(v) {
                r if r < RUN_KINDS => run_mult[r as usize] += 1,
                t => triplets |= 1 << (t - RUN_KINDS),
            }
        }
        let runs = run_mult
            .iter()
            .enumerate()
            .fold(0, |w, (s, &n)| w | u32::from(n > 0) << s);
        let double_runs: u32 = run_mult.iter().map(|n| n / 2).sum();
        let terminal = |p: u32| p == 0 || p == 8;
        let outside = self.sets().iter().all(|&v| match u32::from(v) {
            r if r < RUN_KINDS => r == 0 || r == 6,
            t => terminal(t - RUN_KINDS),
        }) && self.pair.is_none_or(|p| terminal(u32::from(p)));
        let total: u32 = counts.iter().map(|&c| u32::from(c)).sum();
        let nine_gates = total == 14
            && counts
                .iter()
                .zip([3, 1, 1, 1, 1, 1, 1, 1, 3])
                .all(|(&c, need)| c >= need);
        runs | triplets << W1_TRIPLETS_SHIFT
            | double_runs << W1_DOUBLE_RUNS_SHIFT
            | if outside { W1_OUTSIDE_BIT } else { 0 }
            | if nine_gates { W1_NINE_GATES_BIT } else { 0 }
    }
}

/// Every decomposition of every code, sorted by (code, decomposition).
pub(crate) fn all() -> Vec<(usize, Decomp)> {
    let mut out = Vec::new();
    let mut sets = [0u8; MAX_SETS];
    collect(&mut sets, 0, 0, &mut out);
    out.sort_unstable();
    out
}

fn collect(sets: &mut [u8; MAX_SETS], n: usize, start: u8, out: &mut Vec<(usize, Decomp)>) {
    let pairs = std::iter::once(None).chain((0..9).map(Some));
    for pair in pairs {
        let d = Decomp {
            pair,
            sets: *sets,
            n_sets: n as u8,
        };
        if let Some(c) = d.counts() {
            out.push((encode(&c), d));
        }
    }
    if n == MAX_SETS {
        return;
    }
    for v in start..SET_KINDS as u8 {
        sets[n] = v;
        // Counts only grow as sets are added, so an overfull prefix ends the branch.
        let prefix = Decomp {
            pair: None,
            sets: *sets,
            n_sets: n as u8 + 1,
        };
        if prefix.counts().is_some() {
            collect(sets, n + 1, v, out);
        }
        sets[n] = 0;
    }
}
