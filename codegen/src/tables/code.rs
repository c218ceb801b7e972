//! Base-5 codes of per-suit tile counts.
//!
//! Digit 0 (the 1-tile, or East for honors) is the most significant, matching the reference's
//! caches so codes can be compared with it directly. A count must be 0..=4: a 5 would carry into
//! the neighbouring digit and silently name a different suit.

/// Number of number-suit codes: nine digits of 0..=4.
pub const SUIT_CODES: usize = pow5(9);
/// Number of honor codes: seven digits of 0..=4.
pub const HONOR_CODES: usize = pow5(7);

pub(crate) const fn pow5(n: usize) -> usize {
    let mut p = 1;
    let mut i = 0;
    while i < n {
        p *= 5;
        i += 1;
    }
    p
}

/// Place value of digit `i` in an `N`-digit code.
pub(crate) const fn place<const N: usize>(i: usize) -> usize {
    pow5(N - 1 - i)
}

pub(crate) fn encode<const N: usize>(counts: &[u8; N]) -> usize {
    counts.iter().fold(0, |code, &c| {
        debug_assert!(c <= 4, "count {c} does not fit a base-5 digit");
        code * 5 + c as usize
    })
}

pub(crate) fn decode<const N: usize>(mut code: usize) -> [u8; N] {
    let mut counts = [0u8; N];
    for c in counts.iter_mut().rev() {
        *c = (code % 5) as u8;
        code /= 5;
    }
    counts
}

/// Code of a number suit's nine counts (each 0..=4).
pub fn suit_code(counts: &[u8; 9]) -> usize {
    encode(counts)
}

/// Code of the seven honor counts (each 0..=4).
pub fn honor_code(counts: &[u8; 7]) -> usize {
    encode(counts)
}

/// Tile total of every code, built digit by digit so it costs one pass rather than a decode each.
pub(crate) fn digit_sums(len: usize) -> Vec<u8> {
    let mut sums = vec![0u8; len];
    for c in 1..len {
        sums[c] = sums[c / 5] + (c % 5) as u8;
    }
    sums
}
