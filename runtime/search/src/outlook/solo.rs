//! Win odds drawing alone: for a hand of 14 concealed tiles, per
//! candidate discard, the chance of being tenpai and of completing the hand by each number of own
//! draws left, when the seat draws from the tiles it cannot see and nobody else plays. Each play-out
//! deals the draws afresh from the unseen pool (all four copies of each tile but those the seat
//! sees); after each draw the seat keeps what lowers its shanten and otherwise discards the tile
//! drawn. Every candidate sees the same draws (common random numbers), so their odds compare
//! paired. A completed closed hand always has a yaku (menzen tsumo); an open hand's yaku is not
//! checked here, nor are the other seats' wins that would end the round first.

use rinshan_engine::generated::kernel::{self, GameState, S_TILES_LEFT};
use rinshan_engine::hand::shanten;
use rinshan_engine::notation::parse_tiles;
use rinshan_engine::observe::{field_values, record, Form};
use rinshan_engine::random::Rng;
use rinshan_engine::tile::TileType;
use rinshan_engine::Variant;
use serde_json::{json, Value};

/// One candidate discard's odds.
#[derive(Debug, Clone, PartialEq)]
pub struct Odds {
    /// The tile discarded.
    pub discard: TileType,
    /// Shanten after the discard (0: tenpai).
    pub shanten: i32,
    /// `tenpai[k]`: the chance of being tenpai (or complete) after `k + 1` draws.
    pub tenpai: Vec<f64>,
    /// `win[k]`: the chance of having completed the hand within `k + 1` draws.
    pub win: Vec<f64>,
    /// Play-outs behind the figures; a chance `p` has the standard error `sqrt(p(1-p)/n)`.
    pub trials: u32,
}

impl Odds {
    /// The half width of the 95% interval of a chance this candidate reports.
    pub fn interval(&self, p: f64) -> f64 {
        1.96 * (p * (1.0 - p) / f64::from(self.trials.max(1))).sqrt()
    }
}

/// Why the odds cannot be worked out.
fn check(hand: &[u8; 34], unseen: &[u8; 34], draws: usize) -> Result<(), String> {
    let n: u32 = hand.iter().map(|&c| u32::from(c)).sum();
    if n == 0 || n > 14 || n % 3 != 2 {
        return Err(format!(
            "{n} tiles: the odds are of a hand to discard from (3k+2 tiles, 14 closed)"
        ));
    }
    if let Some(t) = (0..34).find(|&t| hand[t] + unseen[t] > 4) {
        return Err(format!(
            "{} of the tile {t} in the hand and the unseen pool: there are 4",
            hand[t] + unseen[t]
        ));
    }
    let pool: usize = unseen.iter().map(|&c| usize::from(c)).sum();
    if draws > pool {
        return Err(format!("{draws} draws from an unseen pool of {pool} tiles"));
    }
    Ok(())
}

/// How much a tile of type `x` works with the rest of `h` (its copies, and suited neighbours
/// within two): the tile with the least is the one to let go.
fn company(h: &[u8; 34], x: usize) -> u32 {
    let mut n = 2 * u32::from(h[x].saturating_sub(1));
    if x < 27 {
        let (suit, number) = (x / 9, x % 9);
        for y in number.saturating_sub(2)..=(number + 2).min(8) {
            if y != number {
                let weight = if y.abs_diff(number) == 1 { 2 } else { 1 };
                n += weight * u32::from(h[suit * 9 + y].min(1));
            }
        }
    }
    n
}

/// The tiles the seat cannot see when it sees only `hand` (and `seen` besides: rivers, melds,
/// dora indicators), as counts per type.
pub fn unseen(hand: &[u8; 34], seen: &[u8; 34]) -> [u8; 34] {
    std::array::from_fn(|t| 4u8.saturating_sub(hand[t] + seen[t]))
}

/// The odds of each distinct discard of `hand` (14 concealed tiles, or 3k+2 with melds called),
/// over `draws` own draws from `unseen`, by `trials` play-outs from `seed`; best first (highest
/// chance of completing by the last draw, then lowest shanten).
pub fn solo(hand: &[u8; 34], unseen: &[u8; 34], draws: usize, trials: u32, seed: u64) -> Result<Vec<Odds>, String> {
    check(hand, unseen, draws)?;
    let candidates: Vec<usize> = (0..34).filter(|&t| hand[t] > 0).collect();
    let mut tenpai = vec![vec![0u32; draws]; candidates.len()];
    let mut win = vec![vec![0u32; draws]; candidates.len()];
    let pool: Vec<u8> = (0..34u8)
        .flat_map(|t| std::iter::repeat_n(t, usize::from(unseen[usize::from(t)])))
        .collect();
    let mut rng = Rng::new(seed);
    let mut order = pool.clone();
    for _ in 0..trials {
        // The same draws for every candidate: a shuffle's first `draws` tiles.
        for i in 0..draws {
            let j = i + rng.below((order.len() - i) as u32) as usize;
            order.swap(i, j);
        }
        for (c, &d) in candidates.iter().enumerate() {
            let mut h = *hand;
            h[d] -= 1;
            let mut s = shanten(&h).shanten;
            for (k, &t) in order[..draws].iter().enumerate() {
                h[usize::from(t)] += 1;
                let with = shanten(&h).shanten;
                if with < 0 {
                    for n in &mut win[c][k..] {
                        *n += 1;
                    }
                    for n in &mut tenpai[c][k..] {
                        *n += 1;
                    }
                    break;
                }
                if with < s {
                    // Keep the draw: let go of the loneliest tile whose loss keeps the better
                    // shanten.
                    let mut keep: Option<(u32, usize)> = None;
                    for x in 0..34 {
                        if h[x] == 0 {
                            continue;
                        }
                        h[x] -= 1;
                        let ok = shanten(&h).shanten == with;
                        h[x] += 1;
                        let c = company(&h, x);
                        if ok && keep.is_none_or(|(best, _)| c < best) {
                            keep = Some((c, x));
                        }
                    }
                    let keep = keep.map(|(_, x)| x);
                    if let Some(x) = keep {
                        h[x] -= 1;
                        s = with;
                    } else {
                        h[usize::from(t)] -= 1;
                    }
                } else {
                    h[usize::from(t)] -= 1;
                }
                if s == 0 {
                    tenpai[c][k] += 1;
                }
            }
        }
        order.copy_from_slice(&pool);
    }
    let share = |n: &u32| f64::from(*n) / f64::from(trials.max(1));
    let mut out: Vec<Odds> = candidates
        .iter()
        .enumerate()
        .map(|(c, &d)| {
            let mut h = *hand;
            h[d] -= 1;
            Odds {
                discard: TileType::try_from(d as u8).unwrap_or_else(|_| unreachable!("a tile type below 34")),
                shanten: shanten(&h).shanten,
                tenpai: tenpai[c].iter().map(share).collect(),
                win: win[c].iter().map(share).collect(),
                trials,
            }
        })
        .collect();
    out.sort_by(|a, b| {
        let last = |o: &Odds| o.win.last().copied().unwrap_or(0.0);
        last(b).total_cmp(&last(a)).then(a.shanten.cmp(&b.shanten))
    });
    Ok(out)
}

/// [`solo`] from tiles in notation, as `rinshan outlook` and Python's `rinshan.outlook` take
/// them: `hand` to discard from (`123456789m1145p9s`, 0 = a red five) and `seen`, the tiles the
/// seat sees elsewhere (rivers, melds, dora indicators; may be empty).
pub fn of_notation(hand: &str, seen: &str, draws: usize, trials: u32, seed: u64) -> Result<Vec<Odds>, String> {
    let hand = parse_tiles(hand).map_err(|e| format!("hand: {e}"))?.counts();
    let seen = match seen.trim() {
        "" => [0; 34],
        s => parse_tiles(s).map_err(|e| format!("seen: {e}"))?.counts(),
    };
    if let Some(t) = (0..34).find(|&t| hand[t] + seen[t] > 4) {
        let name = TileType::new(t as u8).map_or_else(|| t.to_string(), |t| t.name());
        return Err(format!(
            "{} copies of {name} in the hand and the tiles seen: there are only 4",
            hand[t] + seen[t]
        ));
    }
    if trials == 0 || draws == 0 {
        return Err("trials and draws must be at least 1".into());
    }
    solo(&hand, &unseen(&hand, &seen), draws, trials, seed)
}

/// `odds` (of `draws` draws) as JSON: `{"draws": k, "discards": [{"discard", "shanten", "tenpai",
/// "win", "trials"}]}`, best first, `tenpai[i]` and `win[i]` the chances by draw `i + 1`.
pub fn to_json(odds: &[Odds], draws: usize) -> Value {
    let discards: Vec<Value> = odds
        .iter()
        .map(|o| {
            json!({
                "discard": o.discard.name(),
                "shanten": o.shanten,
                "tenpai": o.tenpai,
                "win": o.win,
                "trials": o.trials,
            })
        })
        .collect();
    json!({ "draws": draws, "discards": discards })
}

/// The odds of `seat`'s hand at `s`, its own turn with a tile to discard, from what the seat
/// sees there (the observation's `tiles_seen`; the types a three-player game does not play are
/// never drawn). Its draws are the live tiles left shared among the seats, rounded up. Returns the
/// odds and that number of draws.
pub fn at_turn(
    variant: Variant,
    s: &GameState,
    seat: u32,
    trials: u32,
    seed: u64,
) -> Result<(Vec<Odds>, usize), String> {
    if s.current != seat {
        return Err(format!("seat {seat} is not the one to act"));
    }
    // The concealed tiles, the one just drawn among them.
    let mut hand = [0u8; 34];
    for (h, c) in hand.iter_mut().zip(kernel::hand_counts(&mut s.clone(), seat)) {
        *h = c as u8;
    }
    let view = record(variant, Form::Tokens, s, seat);
    let seen = field_values(Form::Tokens, &view, "tiles_seen");
    let mut unseen = [0u8; 34];
    for (t, u) in unseen.iter_mut().enumerate() {
        let seen = seen.get(t).copied().unwrap_or(4).clamp(0, 4) as u8;
        *u = if variant.tile_in_play(t as u32) { 4 - seen } else { 0 };
    }
    let left = field_values(Form::Tokens, &view, "scalars")
        .get(S_TILES_LEFT as usize)
        .copied()
        .unwrap_or(0)
        .max(0) as usize;
    let draws = left.div_ceil(variant.seats() as usize);
    if draws == 0 {
        return Err("no draws are left".into());
    }
    solo(&hand, &unseen, draws, trials, seed).map(|odds| (odds, draws))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn counts(hand: &str) -> [u8; 34] {
        parse_tiles(hand).expect("a hand").counts()
    }

    /// C(n, k) as a float.
    fn choose(n: u32, k: u32) -> f64 {
        (0..k).fold(1.0, |acc, i| acc * f64::from(n - i) / f64::from(i + 1))
    }

    #[test]
    fn a_tenpai_hand_wins_as_the_closed_form_says() {
        // 123m 456m 789m 11p 45p + a 9s to discard: waiting on 3p and 6p, all 8 unseen. With w
        // winning tiles among n unseen, the chance of drawing one within k draws is
        // 1 - C(n - w, k) / C(n, k).
        let hand = counts("123456789m1145p9s");
        let pool = unseen(&hand, &[0; 34]);
        let (n, w) = (pool.iter().map(|&c| u32::from(c)).sum::<u32>(), 8);
        let trials = 20_000;
        let odds = solo(&hand, &pool, 12, trials, 7).expect("odds");
        let nine = odds.iter().find(|o| o.discard.name() == "9s").expect("the 9s");
        assert_eq!(nine.shanten, 0);
        for k in [1u32, 4, 12] {
            let exact = 1.0 - choose(n - w, k) / choose(n, k);
            let got = nine.win[k as usize - 1];
            assert!(
                (got - exact).abs() < 4.0 * (exact * (1.0 - exact) / f64::from(trials)).sqrt() + 1e-9,
                "{k} draws: {got} against {exact}"
            );
            assert_eq!(nine.tenpai[k as usize - 1], 1.0, "a tenpai hand stays tenpai");
        }
        // Discarding the 9s is the best: every other discard breaks the tenpai, and a hand that
        // is not tenpai cannot win on the next draw.
        assert_eq!(odds[0].discard.name(), "9s");
        assert!(odds[1..].iter().all(|o| o.shanten > 0 && o.win[0] == 0.0));
    }

    #[test]
    fn odds_repeat_for_a_seed_and_grow_with_draws() {
        let hand = counts("13m4679p1358s1225z");
        let pool = unseen(&hand, &[0; 34]);
        let a = solo(&hand, &pool, 10, 500, 3).expect("odds");
        assert_eq!(a, solo(&hand, &pool, 10, 500, 3).expect("odds"));
        for o in &a {
            assert!(o.win.windows(2).all(|w| w[0] <= w[1]), "{o:?}");
            assert!(o.win.iter().zip(&o.tenpai).all(|(w, t)| w <= t), "{o:?}");
        }
        // Each draw lowers the shanten by one at most: no win before shanten + 1 draws.
        for o in &a {
            let first = usize::try_from(o.shanten).unwrap_or(0);
            assert!(o.win[..first.min(10)].iter().all(|&p| p == 0.0), "{o:?}");
        }
    }

    #[test]
    fn bad_hands_are_refused_with_the_reason() {
        let pool = unseen(&[0; 34], &[0; 34]);
        assert!(solo(&counts("123m"), &pool, 5, 10, 1).is_err_and(|e| e.contains("3k+2")));
        let hand = counts("11112345678999m");
        assert!(solo(&hand, &pool, 5, 10, 1).is_err_and(|e| e.contains("there are 4")));
        let hand = counts("123456789m1145p9s");
        assert!(solo(&hand, &unseen(&hand, &[0; 34]), 200, 10, 1).is_err_and(|e| e.contains("200 draws")));
    }

    #[test]
    fn at_the_dealers_first_turn_every_discard_is_judged_from_its_view() {
        for variant in [Variant::Red, Variant::Sanma] {
            let s = variant.new_game(3, rinshan_engine::env::Mode::Half);
            let (odds, draws) = at_turn(variant, &s, s.current, 500, 1).expect("odds");
            // 69 live tiles for four players, 54 for three: each seat's share, rounded up.
            assert_eq!(draws, 18, "{variant}");
            let mut hand = [0u8; 34];
            for (h, c) in hand.iter_mut().zip(kernel::hand_counts(&mut s.clone(), s.current)) {
                *h = c as u8;
            }
            assert_eq!(
                hand.iter().map(|&c| u32::from(c)).sum::<u32>(),
                14,
                "the drawn tile is held"
            );
            let kinds = hand.iter().filter(|&&c| c > 0).count();
            assert_eq!(odds.len(), kinds, "{variant}: one line per tile type held");
            let best = (0..34)
                .filter(|&t| hand[t] > 0)
                .map(|t| {
                    let mut h = hand;
                    h[t] -= 1;
                    shanten(&h).shanten
                })
                .min();
            assert_eq!(odds.iter().map(|o| o.shanten).min(), best, "{variant}");
        }
        let s = Variant::Red.new_game(3, rinshan_engine::env::Mode::Half);
        assert!(at_turn(Variant::Red, &s, (s.current + 1) % 4, 10, 1).is_err());
    }
}
