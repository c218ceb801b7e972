//! What holds of every state of every game, whatever the rules and the players do: the tests and
//! the soak (`rinshan soak`) check it after every step.

use crate::generated::kernel::{self as k, GameState};
use crate::Variant;

/// Tiles held (hands, melds, uncalled river tiles, North set aside) and tiles drawn from the wall
/// (live draws and replacement tiles), per type, read with the kernel's accessors.
pub fn tiles_held_and_drawn(state: &GameState, variant: Variant) -> ([u32; 34], [u32; 34]) {
    let mut s = *state;
    let mut held = [0u32; 34];
    for seat in 0..4u32 {
        held[30] += with_variant!(variant, v => v::kita_count(&mut s, seat));
        for (h, n) in held.iter_mut().zip(k::hand_counts(&mut s, seat)) {
            *h += n;
        }
        for i in 0..k::meld_count(&mut s, seat) {
            let m = s.melds[(seat * 4 + i) as usize];
            let t = k::meld_tile(m);
            match k::meld_kind(m) {
                k::MELD_CHI => (0..3).for_each(|d| held[((t + d) as usize).min(33)] += 1),
                k::MELD_PON => held[(t as usize).min(33)] += 3,
                _ => held[(t as usize).min(33)] += 4,
            }
        }
        // River entries: a tile value, 64 when called away (then held by the caller's meld).
        for i in 0..k::byte_of(s.river_lens, seat).min(24) {
            let e = k::byte_of(s.rivers[(seat * 6 + i / 4) as usize], i % 4);
            if e & 64 == 0 {
                held[(k::value_type(e & 63) as usize).min(33)] += 1;
            }
        }
    }
    let mut drawn = [0u32; 34];
    for i in 0..s.next_draw.min(136) {
        drawn[(k::value_type(k::wall_tile(&mut s, i)) as usize).min(33)] += 1;
    }
    for i in variant.drawn_replacements(&s).into_iter().take(8) {
        drawn[(k::value_type(k::wall_tile(&mut s, i)) as usize).min(33)] += 1;
    }
    (held, drawn)
}

/// Checks one state of a game of `variant` (each seat starting with its `starting_points`): tiles conserved,
/// points conserved (with the riichi sticks on the table), the round's event log not full, and
/// while the game runs one seat to act with a legal action: at a claim prompt a seat with a
/// claim, on a turn the seat holding a tile more than the others (14 counting each meld as 3).
pub fn check(state: &GameState, variant: Variant) -> Result<(), String> {
    let (held, drawn) = tiles_held_and_drawn(state, variant);
    let seats = variant.seats();
    let starting_points = variant.starting_points() as i32;
    if held != drawn {
        let t = (0..34).find(|&t| held[t] != drawn[t]).unwrap_or(0);
        return Err(format!(
            "tiles held differ from tiles drawn: type {t} held {} times, drawn {}",
            held[t], drawn[t]
        ));
    }
    let points = state.scores.iter().map(|&x| i64::from(x)).sum::<i64>() + i64::from(state.sticks) * 1000;
    let total = i64::from(seats) * i64::from(starting_points);
    if points != total {
        return Err(format!("points plus sticks on the table are {points}, not {total}"));
    }
    let mut s = *state;
    let logged = k::log_count(&mut s);
    if logged >= k::LOG_CAPACITY {
        return Err(format!("{logged} events logged in one round: the log is full"));
    }
    if s.terminated != 0 || s.phase == k::PHASE_OVER {
        return Ok(());
    }
    if s.current >= seats {
        return Err(format!("seat {} is to act", s.current));
    }
    if s.mask == [0; 3] {
        return Err(format!("seat {} is to act with no legal action", s.current));
    }
    let sizes: Vec<u32> = (0..seats)
        .map(|q| k::hand_counts(&mut s, q).iter().sum::<u32>() + 3 * k::meld_count(&mut s, q))
        .collect();
    if s.phase == k::PHASE_CLAIM {
        if s.claim_options[s.current as usize] == 0 {
            return Err(format!("seat {} is asked to claim with no claim", s.current));
        }
        if sizes.iter().any(|&n| n != 13) {
            return Err(format!("hands at a claim prompt are {sizes:?} tiles, not 13 each"));
        }
    } else {
        let want: Vec<u32> = (0..seats).map(|q| if q == s.current { 14 } else { 13 }).collect();
        if sizes != want {
            return Err(format!(
                "seat {} is on its turn with hands of {sizes:?} tiles, not {want:?}",
                s.current
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generated::red;

    fn dealt() -> GameState {
        red::game_new(k::ResetInput {
            seed: [3, 4],
            mode: k::MODE_HALF,
            dealer: 4,
            use_wall: 0,
            wall: [0; 136],
            uma: [0; 4],
            penalty: -1.0,
            auto_reset: 0,
        })
    }

    #[test]
    fn a_dealt_game_holds_and_broken_ones_do_not() {
        let s = dealt();
        assert_eq!(check(&s, Variant::Red), Ok(()));
        let mut points = s;
        points.scores[1] += 100;
        assert!(check(&points, Variant::Red).is_err_and(|e| e.contains("points")));
        let mut tile = s;
        // One more tile of the first seat's first type: held no longer matches drawn.
        tile.hands[0] += 1;
        assert!(check(&tile, Variant::Red).is_err_and(|e| e.contains("tiles held")));
        let mut nobody = s;
        nobody.mask = [0; 3];
        assert!(check(&nobody, Variant::Red).is_err_and(|e| e.contains("no legal action")));
        let mut turn = s;
        turn.current = (s.current + 1) % 4;
        assert!(check(&turn, Variant::Red).is_err_and(|e| e.contains("on its turn")));
    }
}
