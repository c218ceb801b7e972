//! What a round's outcome is worth to a seat over the whole game: its expected final place.
//!
//! Points are not the goal of a half game, the place is (Suphx's global reward predictor makes
//! the same point): 8,000 points matter little in East 1 and decide the game in South 4. The
//! value of a state after a round is minus the seat's expected final rank, each other seat
//! ahead at the end with the probability that a normal spread of the rounds left does not close
//! the gap between them: `P(j ahead of i) = Phi((s_j - s_i) / (SPREAD * sqrt(rounds left)))`. At
//! the game's end the rank is exact. `SPREAD`, a round's typical change in the gap between two
//! seats, is set by hand, not fitted: calibrating it against self-play is left to do.

use rinshan_engine::generated::kernel::{GameState, MODE_EAST, MODE_SINGLE, RANK_SHIFT};

/// A round's typical change in the gap between two seats' scores (points; set by hand).
pub const SPREAD: f64 = 5600.0;

/// Minus `seat`'s expected final rank (0 = first) from state `s` after a round, in a game of
/// `seats` players: exact once the game is over.
pub fn placement_value(s: &GameState, seat: u32, seats: u32) -> f64 {
    if s.terminated != 0 {
        return -f64::from((s.ranks >> (seat * RANK_SHIFT)) & 255);
    }
    let last = match s.mode {
        MODE_SINGLE => 0,
        MODE_EAST => seats - 1,
        _ => 2 * seats - 1,
    };
    // The round about to be played counts; past the last (an extension) at least one more.
    let left = f64::from(last.saturating_sub(s.round) + 1);
    let scale = SPREAD * left.sqrt();
    let mine = f64::from(s.scores[seat as usize]);
    let mut rank = 0.0;
    for q in (0..seats).filter(|&q| q != seat) {
        rank += normal_cdf((f64::from(s.scores[q as usize]) - mine) / scale);
    }
    -rank
}

/// The standard normal distribution function (Abramowitz and Stegun 7.1.26 for erf, error under
/// 1.5e-7: far below the noise of any look-ahead).
pub fn normal_cdf(x: f64) -> f64 {
    let z = x / std::f64::consts::SQRT_2;
    let t = 1.0 / (1.0 + 0.327_591_1 * z.abs());
    let poly =
        t * (0.254_829_592 + t * (-0.284_496_736 + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    let erf = 1.0 - poly * (-z * z).exp();
    0.5 * (1.0 + if z >= 0.0 { erf } else { -erf })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_cdf_matches_its_known_values() {
        // Tables of the normal distribution.
        for (x, p) in [(0.0, 0.5), (1.0, 0.841_344_7), (-1.96, 0.024_997_9), (2.5, 0.993_790_3)] {
            assert!((normal_cdf(x) - p).abs() < 1e-6, "{x}: {} vs {p}", normal_cdf(x));
        }
    }
}
