//! Two groups' cost rows combined ahead of time.
//!
//! Few rows occur: 126 distinct rows among the 1,953,125 suit codes and 55 among the 78,125 honor
//! codes. So each cost word carries its row's number above its costs (bits [`ROW_SHIFT`] up), and
//! the min-plus combination of any two rows, itself a row of the same shape, is one word of a
//! table indexed by the two numbers. The shanten kernel then reads two combined rows (the two
//! number suits; the third with the honors) where it combined four rows itself.
//!
//! The combined rows are few too (180 of two suits, 165 of a suit and the honors), so the pair
//! tables' words carry their numbers the same way, and the last step, the tiles a whole hand
//! misses for each number of sets, is one word of a third table indexed by the two numbers
//! (`missing`): the kernel reads it where it unpacked two rows and took the cheapest split.

use super::cost::{pack, unpack, CostRow, MAX_SETS};

/// Bits per entry of a `missing` word.
pub const MISSING_BITS: u32 = 4;

/// Bit of a cost word where its row's number starts: the costs use the 18 bits below.
pub const ROW_SHIFT: u32 = 18;

/// The costs of a cost word, without its row's number.
pub const COST_MASK: u32 = (1 << ROW_SHIFT) - 1;

/// The distinct cost words of a region, ascending: a row's number is its index here.
pub(crate) fn distinct(words: &[u32]) -> Vec<u32> {
    let mut rows: Vec<u32> = words.to_vec();
    rows.sort_unstable();
    rows.dedup();
    rows
}

/// Tags each cost word with its row's number in `rows` (from [`distinct`]).
pub(crate) fn number(words: &mut [u32], rows: &[u32]) {
    for w in words {
        let n = rows.binary_search(w).expect("every word is among the distinct rows");
        *w |= u32::try_from(n).expect("row numbers fit a word") << ROW_SHIFT;
    }
}

/// D(m, h) of two groups together: the cheapest split of `m` sets and `h` pairs between them.
pub fn combine(a: &CostRow, b: &CostRow) -> CostRow {
    let mut out = [u8::MAX; 2 * (MAX_SETS + 1)];
    for m in 0..=MAX_SETS {
        for h in 0..2 {
            for m1 in 0..=m {
                for h1 in 0..=h {
                    let d = a[2 * m1 + h1] + b[2 * (m - m1) + h - h1];
                    out[2 * m + h] = out[2 * m + h].min(d);
                }
            }
        }
    }
    out
}

/// Fills `out` (`left.len() * right.len()` words, row-major by the left row's number) with the
/// packed combination of every pair of rows. Panics if one does not pack: a combined row is the
/// cost row of two groups taken as one, so the increments' ranges hold for it as for a group's
/// (checked here on every pair at every build).
pub(crate) fn build(left: &[u32], right: &[u32], out: &mut [u32]) {
    assert_eq!(out.len(), left.len() * right.len());
    for (i, &l) in left.iter().enumerate() {
        for (j, &r) in right.iter().enumerate() {
            let c = combine(&row(l), &row(r));
            out[i * right.len() + j] =
                pack(&c).unwrap_or_else(|| panic!("rows {l:#x} and {r:#x}: combined row {c:?} does not pack"));
        }
    }
}

/// The ten costs of a packed cost word.
fn row(w: u32) -> CostRow {
    std::array::from_fn(|i| unpack(w, i / 2, i % 2) as u8)
}

/// The `missing` table: for every row of `left` and of `right` (row-major by the left row's
/// number), D(m, 1) of the two rows combined (the tiles that complete m sets and the pair) for
/// m = 0..=4 at bits `4m..4m + 4`. Panics if a count does not fit
/// its bits: a hand of m sets and the pair has 3m + 2 tiles, and no tile already held makes a
/// completion cost more, so each count is at most 14 (checked on every entry at every build).
pub(crate) fn missing(left: &[u32], right: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(left.len() * right.len());
    for &a in left {
        for &b in right {
            let c = combine(&row(a), &row(b));
            let mut word = 0;
            for m in 0..=MAX_SETS {
                let n = u32::from(c[2 * m + 1]);
                assert!(
                    n < 1 << MISSING_BITS && n <= 3 * m as u32 + 2,
                    "rows {a:#x} and {b:#x}: {n} tiles missing for {m} sets and the pair"
                );
                word |= n << (MISSING_BITS * m as u32);
            }
            out.push(word);
        }
    }
    out
}
