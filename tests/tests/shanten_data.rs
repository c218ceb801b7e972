//! Exact shanten against the 40,000 published cases and against the xiangting crate.

use rinshan_engine::hand::shanten;
use rinshan_engine::random::{random_hand, Rng};
use rinshan_tests::test_data;

/// Each line: 14 tile ids 0..33, then the expected normal, kokushi and chiitoitsu shanten.
fn cases() -> Vec<([u8; 34], [i32; 3], String)> {
    let dir = test_data().join("shanten");
    let mut out = Vec::new();
    for name in [
        "p_normal_10000.txt",
        "p_hon_10000.txt",
        "p_tin_10000.txt",
        "p_koku_10000.txt",
    ] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        for (i, line) in text.lines().enumerate() {
            let nums: Vec<i32> = line.split_whitespace().map(|x| x.parse().expect("integer")).collect();
            assert_eq!(nums.len(), 17, "{name}:{}: 17 columns", i + 1);
            let mut counts = [0u8; 34];
            for &t in &nums[..14] {
                counts[t as usize] += 1;
            }
            out.push((counts, [nums[14], nums[15], nums[16]], format!("{name}:{}", i + 1)));
        }
    }
    out
}

#[test]
fn agrees_with_all_40000_cases() {
    let cases = cases();
    assert_eq!(cases.len(), 40_000);
    let mut wrong = Vec::new();
    for (counts, [normal, kokushi, chiitoitsu], at) in &cases {
        let s = shanten(counts);
        let got = [s.normal, s.kokushi.unwrap_or(99), s.chiitoitsu.unwrap_or(99)];
        if got != [*normal, *kokushi, *chiitoitsu] {
            wrong.push(format!(
                "{at}: expected {:?}, got {:?}",
                [normal, kokushi, chiitoitsu],
                got
            ));
        }
        assert_eq!(
            s.shanten,
            got.into_iter().min().unwrap_or(99),
            "{at}: overall = min of the three"
        );
    }
    assert!(
        wrong.is_empty(),
        "{} disagreements, first: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(5)]
    );
}

#[test]
fn agrees_with_xiangting_on_random_hands() {
    let mut rng = Rng::new(7);
    for i in 0..200_000 {
        // 14, 13, 11, 10, 8, 7, 5, 4, 2, 1 tiles: hands with 0..4 melds called.
        let n = [14, 13, 11, 10, 8, 7, 5, 4, 2, 1][i % 10];
        let counts = random_hand(&mut rng, n);
        let expected = xiangting::calculate_replacement_number(&counts, xiangting::PlayerCount::Four)
            .expect("valid hand") as i32
            - 1;
        let s = shanten(&counts);
        // xiangting reports the minimum over the three forms where they apply (13+ tiles).
        assert_eq!(s.shanten, expected, "hand {counts:?} ({n} tiles)");
    }
}

#[test]
fn small_hands_have_no_seven_pairs_or_orphans() {
    let mut counts = [0u8; 34];
    counts[0] = 2;
    counts[1] = 2;
    let s = shanten(&counts[..].try_into().expect("34"));
    assert_eq!(s.chiitoitsu, None);
    assert_eq!(s.kokushi, None);
    // Two pairs, one set to make of four tiles: one tile away from tenpai on a pair... 11m22m needs a
    // third 1m or 2m to become set + pair: tenpai already.
    assert_eq!(s.normal, 0);
}

/// The observation's and the turn's shanten read the hand's packed words straight from the game
/// state (`hand_shanten`): at every seat, the published cases' overall shanten, and those of their
/// first 13, 11, 8, 5 and 2 tiles (hands with melds) as `shanten` gives them.
#[test]
fn packed_hand_words_give_the_cases_shanten() {
    use rinshan_engine::generated::kernel::{hand_shanten, GameState};
    let mut state: GameState = bytemuck::Zeroable::zeroed();
    for (counts, expected, at) in &cases() {
        let tiles: Vec<usize> = (0..34)
            .flat_map(|t| std::iter::repeat_n(t, usize::from(counts[t])))
            .collect();
        for n in [14, 13, 11, 8, 5, 2] {
            let mut part = [0u8; 34];
            for &t in &tiles[..n] {
                part[t] += 1;
            }
            let want = if n == 14 {
                *expected.iter().min().expect("three forms")
            } else {
                shanten(&part).shanten
            };
            let seat = n % 4;
            state.hands = [0; 20];
            for (t, &c) in part.iter().enumerate() {
                state.hands[seat * 5 + t / 8] |= u32::from(c) << (t % 8 * 4);
            }
            assert_eq!(
                hand_shanten(&mut state, seat as u32),
                want,
                "{at}: first {n} tiles at seat {seat}"
            );
        }
    }
}
