//! Exact per-suit shanten costs.
//!
//! D(m, h)(c) is the fewest tiles to add to `c` so that it holds `m` sets and `h` pairs (tiles may
//! also go unused). Writing `t` for a target (m sets + h pairs, every count <= 4),
//! `sum_i max(t_i - c_i, 0) = |t| - |min(c, t)|`, so D = 3m + 2h - max_t |min(c, t)|. The maximum is
//! over every `s <= c` that is also `<= some t` ("partial"), which two monotone transforms over
//! the whole code space give exactly, instead of a search per code:
//! 1. mark every target, then close the marks downwards one digit at a time;
//! 2. take `|s|` on partial codes and propagate the maximum upwards one digit at a time.
//!
//! Closing one digit at a time is enough because "<=" on count vectors is the product of the
//! per-digit orders, so the closure (and the running maximum) factors into per-digit sweeps.

use super::code::{digit_sums, encode, place, pow5};

/// Sets a hand can need from one suit: a complete hand has four.
pub(crate) const MAX_SETS: usize = 4;
/// Bits per increment in a packed word.
const INC_BITS: usize = 2;
/// Bit of the first pair increment, D(0, 1) - D(0, 0); the set increments sit below it.
pub(crate) const PAIR_INC_SHIFT: usize = INC_BITS * MAX_SETS;
/// Largest set increment D(m, 0) - D(m - 1, 0).
pub(crate) const MAX_SET_INC: u8 = 3;
/// Largest pair increment D(m, 1) - D(m, 0).
pub(crate) const MAX_PAIR_INC: u8 = 2;

/// D(m, h) of one code at index `2m + h`.
pub type CostRow = [u8; 2 * (MAX_SETS + 1)];

/// Set shapes of a number suit: runs first, then triplets.
pub(crate) fn suit_sets() -> Vec<[u8; 9]> {
    let runs = (0..7).map(|s| {
        let mut t = [0; 9];
        t[s..s + 3].fill(1);
        t
    });
    let triplets = (0..9).map(|p| {
        let mut t = [0; 9];
        t[p] = 3;
        t
    });
    runs.chain(triplets).collect()
}

/// Honors have no runs.
pub(crate) fn honor_sets() -> Vec<[u8; 7]> {
    (0..7)
        .map(|p| {
            let mut t = [0; 7];
            t[p] = 3;
            t
        })
        .collect()
}

/// D(m, h) of every code, unpacked.
pub(crate) fn rows<const N: usize>(sets: &[[u8; N]]) -> Vec<CostRow> {
    let len = pow5(N);
    let sums = digit_sums(len);
    let combos: Vec<(usize, usize)> = (0..=MAX_SETS)
        .flat_map(|m| [(m, 0), (m, 1)])
        .filter(|&(m, h)| m + h > 0)
        .collect();
    // The columns are independent; threads only shorten the build, the result is the same.
    let sums = &sums;
    let columns: Vec<Vec<u8>> = std::thread::scope(|scope| {
        let handles: Vec<_> = combos
            .iter()
            .map(|&(m, h)| scope.spawn(move || column::<N>(sets, m, h, sums)))
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("cost column thread panicked"))
            .collect()
    });
    // D(0, 0) is 0 everywhere, so starting from zeroed rows leaves it in place.
    let mut rows = vec![[0u8; 2 * (MAX_SETS + 1)]; len];
    for (&(m, h), col) in combos.iter().zip(&columns) {
        for (row, &d) in rows.iter_mut().zip(col) {
            row[2 * m + h] = d;
        }
    }
    rows
}

/// Packs a row into one word: bits `2(m-1)..2m` hold D(m, 0) - D(m-1, 0) for m = 1..=4 and bits
/// `8 + 2m..10 + 2m` hold D(m, 1) - D(m, 0) for m = 0..=4 (D(0, 0) is 0). `None` if the row is not
/// of that shape: D(0, 0) != 0, or an increment outside 0..=3 (sets) or 0..=2 (pair).
pub fn pack(row: &CostRow) -> Option<u32> {
    if row[0] != 0 {
        return None;
    }
    let mut word = 0u32;
    for m in 0..=MAX_SETS {
        if m > 0 {
            let inc = row[2 * m].checked_sub(row[2 * (m - 1)]).filter(|&i| i <= MAX_SET_INC)?;
            word |= u32::from(inc) << (INC_BITS * (m - 1));
        }
        let inc = row[2 * m + 1].checked_sub(row[2 * m]).filter(|&i| i <= MAX_PAIR_INC)?;
        word |= u32::from(inc) << (PAIR_INC_SHIFT + INC_BITS * m);
    }
    Some(word)
}

/// D(m, h) out of a packed word (prefix sums of the increments).
pub fn unpack(word: u32, m: usize, h: usize) -> u32 {
    let field = |shift: usize| word >> shift & ((1 << INC_BITS) - 1);
    let sets: u32 = (1..=m).map(|k| field(INC_BITS * (k - 1))).sum();
    sets + if h == 1 {
        field(PAIR_INC_SHIFT + INC_BITS * m)
    } else {
        0
    }
}

/// Packs every row into `out`, one word per code. Panics if a row does not pack: the ranges are a
/// theorem (dropping a set or the pair from a target never costs a tile; adding one costs at most
/// its size, and some shape always fits), and this check, run on every code at every build, is its
/// proof.
pub(crate) fn build<const N: usize>(sets: &[[u8; N]], out: &mut [u32]) {
    assert_eq!(out.len(), pow5(N));
    for (code, (row, word)) in rows::<N>(sets).iter().zip(out.iter_mut()).enumerate() {
        *word = pack(row).unwrap_or_else(|| panic!("code {code}: cost row {row:?} does not pack"));
    }
}

/// D(m, h) for every code.
fn column<const N: usize>(sets: &[[u8; N]], m: usize, h: usize, sums: &[u8]) -> Vec<u8> {
    let mut best = vec![0u8; pow5(N)];
    for_each_target(sets, m, h, &mut |t| best[encode(t)] = 1);
    for i in 0..N {
        close_down(&mut best, place::<N>(i));
    }
    for (b, &s) in best.iter_mut().zip(sums) {
        *b *= s;
    }
    for i in 0..N {
        max_up(&mut best, place::<N>(i));
    }
    let size = (3 * m + 2 * h) as u8;
    for b in best.iter_mut() {
        *b = size - *b;
    }
    best
}

/// `a[c - e_i] |= a[c]` for every `c` with digit `i` > 0, highest digit value first so marks
/// travel all the way down. `stride` is the place value of digit `i`.
fn close_down(a: &mut [u8], stride: usize) {
    for block in a.chunks_exact_mut(5 * stride) {
        for d in (0..4).rev() {
            let (lo, hi) = block[d * stride..(d + 2) * stride].split_at_mut(stride);
            for (x, &y) in lo.iter_mut().zip(hi.iter()) {
                *x |= y;
            }
        }
    }
}

/// `a[c] = max(a[c], a[c - e_i])`, lowest digit value first so maxima travel all the way up.
fn max_up(a: &mut [u8], stride: usize) {
    for block in a.chunks_exact_mut(5 * stride) {
        for d in 1..5 {
            let (lo, hi) = block[(d - 1) * stride..(d + 1) * stride].split_at_mut(stride);
            for (&x, y) in lo.iter().zip(hi.iter_mut()) {
                *y = (*y).max(x);
            }
        }
    }
}

/// Calls `f` on every target: a multiset of `m` shapes from `sets` plus `h` pairs, counts <= 4.
/// Each multiset is visited once (shapes in non-decreasing index order); counts only grow along
/// the recursion, so a branch is cut as soon as one exceeds 4.
pub(crate) fn for_each_target<const N: usize>(sets: &[[u8; N]], m: usize, h: usize, f: &mut impl FnMut(&[u8; N])) {
    fn rec<const N: usize>(
        sets: &[[u8; N]],
        start: usize,
        left: usize,
        pairs: usize,
        acc: &mut [u8; N],
        f: &mut impl FnMut(&[u8; N]),
    ) {
        if left > 0 {
            for (k, shape) in sets.iter().enumerate().skip(start) {
                add(acc, shape);
                if acc.iter().all(|&c| c <= 4) {
                    rec(sets, k, left - 1, pairs, acc, f);
                }
                sub(acc, shape);
            }
        } else if pairs > 0 {
            for p in 0..N {
                if acc[p] <= 2 {
                    acc[p] += 2;
                    rec(sets, 0, 0, pairs - 1, acc, f);
                    acc[p] -= 2;
                }
            }
        } else {
            f(acc);
        }
    }
    rec(sets, 0, m, h, &mut [0; N], f);
}

fn add<const N: usize>(acc: &mut [u8; N], shape: &[u8; N]) {
    acc.iter_mut().zip(shape).for_each(|(a, &s)| *a += s);
}

fn sub<const N: usize>(acc: &mut [u8; N], shape: &[u8; N]) {
    acc.iter_mut().zip(shape).for_each(|(a, &s)| *a -= s);
}
