//! The uma a game's last step paid, as the result board shows it (`Variant::uma_paid`, read back
//! from the final scores): by place, or under M-League's rules shared by the seats tied on points.
//! Checked against the rules written out here over many score lines full of ties.

use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// M-League's uma measured from the start (rules/variants/mleague.toml), in points.
const UMA: [i32; 4] = [45_000, 5_000, -15_000, -35_000];

/// Places by points, a tie to the lower seat (seat 0 is the first dealer here).
fn places(scores: [i32; 4]) -> [u8; 4] {
    std::array::from_fn(|p| {
        (0..4)
            .filter(|&q| scores[q] > scores[p] || (scores[q] == scores[p] && q < p))
            .count() as u8
    })
}

/// Tied seats share the uma of the places they hold, in whole hundreds; the hundreds that do not
/// divide go one each to the tied seats in place order.
fn shared(scores: [i32; 4], ranks: [u8; 4]) -> [i32; 4] {
    std::array::from_fn(|p| {
        let tied: Vec<usize> = (0..4).filter(|&q| scores[q] == scores[p]).collect();
        let hundreds: i32 = tied.iter().map(|&q| UMA[usize::from(ranks[q])] / 100).sum();
        let n = tied.len() as i32;
        let ahead = tied.iter().filter(|&&q| ranks[q] < ranks[p]).count() as i32;
        (hundreds.div_euclid(n) + i32::from(ahead < hundreds.rem_euclid(n))) * 100
    })
}

#[test]
fn the_paid_uma_is_read_back_from_the_final_scores() {
    let mut rng = Rng::new(26);
    let values = [18_000, 24_000, 25_000, 25_100, 31_000];
    let (mut ties, mut three) = (0, 0);
    for _ in 0..20_000 {
        let before: [i32; 4] = std::array::from_fn(|_| values[rng.below(values.len() as u32) as usize]);
        let ranks = places(before);
        let by_place = ranks.map(|r| UMA[usize::from(r)]);
        let after = std::array::from_fn(|p| before[p] + by_place[p]);
        assert_eq!(Variant::Red.uma_paid(after, ranks, UMA), by_place, "red {before:?}");
        let share = shared(before, ranks);
        assert_eq!(share.iter().sum::<i32>(), 0);
        let after = std::array::from_fn(|p| before[p] + share[p]);
        assert_eq!(
            Variant::Mleague.uma_paid(after, ranks, UMA),
            share,
            "mleague {before:?}"
        );
        let most = (0..4)
            .map(|p| before.iter().filter(|&&x| x == before[p]).count())
            .max()
            .unwrap_or(1);
        ties += usize::from(most >= 2);
        three += usize::from(most >= 3);
    }
    assert!(
        ties > 10_000 && three > 1_000,
        "{ties} lines with a tie, {three} with three or more"
    );
}
