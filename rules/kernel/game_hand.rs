// Tiles in and out of hands, and what a hand can do: completeness, waits, tenpai.
// Tile values 0..33 are the types; 34, 35, 36 are the red fives of m, p, s (types 4, 13, 22).

pub fn value_type(v: u32) -> u32 {
    if v >= 34u32 {
        return (v - 34u32) * 9u32 + 4u32;
    }
    v
}

fn red_bit(seat: u32, suit: u32) -> u32 {
    1u32 << (seat * 3u32 + suit)
}

pub fn holds_red(s: &mut GameState, seat: u32, suit: u32) -> bool {
    (s.red & red_bit(seat, suit)) != 0u32
}

fn give_tile(s: &mut GameState, seat: u32, v: u32) {
    hand_add(s, seat, value_type(v));
    if v >= 34u32 {
        s.red |= red_bit(seat, v - 34u32);
    }
}

fn take_tile(s: &mut GameState, seat: u32, v: u32) {
    hand_remove(s, seat, value_type(v));
    if v >= 34u32 {
        s.red &= !red_bit(seat, v - 34u32);
    }
}

// Copies of value `v` the seat holds (a red five is its own value; a black five excludes it).
fn value_count(s: &mut GameState, seat: u32, v: u32) -> u32 {
    if v >= 34u32 {
        return holds_red(s, seat, v - 34u32) as u32;
    }
    let n: u32 = hand_count(s, seat, v);
    if v % 9u32 == 4u32 && v < 27u32 && holds_red(s, seat, v / 9u32) {
        return n - 1u32;
    }
    n
}

// Takes one copy of type `t`, preferring a black tile; returns the value taken.
fn take_type(s: &mut GameState, seat: u32, t: u32, prefer_red: bool) -> u32 {
    let mut v: u32 = t;
    if t < 27u32 && t % 9u32 == 4u32 && holds_red(s, seat, t / 9u32) {
        if prefer_red || hand_count(s, seat, t) == 1u32 {
            v = 34u32 + t / 9u32;
        }
    }
    take_tile(s, seat, v);
    v
}

pub fn meld_count(s: &mut GameState, seat: u32) -> u32 {
    byte_of(s.meld_counts, seat)
}

// Tile types that complete the hand, as a 34-bit set. A wait on a tile whose four copies are all
// in the concealed hand does not count (that tile can never arrive); copies in the seat's own
// melds do not void a wait (Tenhou: a tanki on the fourth tile of one's pon is tenpai).
fn waits_of(c: [u32; 34]) -> [u32; 2] {
    let mut w: [u32; 2] = [0u32; 2];
    // Exact shanten (whose targets respect the four copies of a concealed tile, as this rule
    // does) says at once whether any tile can complete the hand; most hands are not tenpai,
    // and then 34 trials are saved.
    if shanten(ShantenInput { hand: c }).shanten > 0i32 {
        return w;
    }
    // A type held four times reads SHANTEN_NOT_APPLICABLE; a hand one tile completes reads -1 (in
    // any of the three forms: the seven pairs and thirteen orphans count only for a closed hand,
    // the only one with 13 tiles).
    let after: [i32; 34] = shanten_after_draws(c);
    for t in 0u32..34u32 {
        if after[t as usize] < 0i32 {
            w[(t / 32u32) as usize] |= 1u32 << (t % 32u32);
        }
    }
    w
}

fn in_set(set: [u32; 2], t: u32) -> bool {
    ((set[(t / 32u32) as usize] >> (t % 32u32)) & 1u32) != 0u32
}

// Proof without the shanten tables that no tile completes the seat's hand, nor any hand left by
// one of `discards` (0 or 1) discards: in a hand that one tile completes, every tile but the
// single waiting for its pair shares a set, pair or partial set with another tile, so at most
// one tile is isolated, unless the hand is twelve or more kinds of thirteen orphans. A discard
// removes at most one isolated tile.
fn surely_not_tenpai(s: &mut GameState, seat: u32, discards: u32) -> bool {
    let io: [u32; 2] = isolated_and_orphans(s, seat);
    io[0] > 1u32 + discards && io[1] < 12u32
}

fn seat_waits(s: &mut GameState, seat: u32) -> [u32; 2] {
    // Most hands in play are far from tenpai: settled here, before the shanten's table reads.
    if surely_not_tenpai(s, seat, 0u32) {
        return [0u32; 2];
    }
    waits_of(hand_counts(s, seat))
}

pub fn update_waits(s: &mut GameState, seat: u32) {
    let w: [u32; 2] = seat_waits(s, seat);
    s.waits[(seat * 2u32) as usize] = w[0];
    s.waits[(seat * 2u32 + 1u32) as usize] = w[1];
}

fn waits_include(s: &mut GameState, seat: u32, t: u32) -> bool {
    ((s.waits[(seat * 2u32 + t / 32u32) as usize] >> (t % 32u32)) & 1u32) != 0u32
}

fn seat_tenpai(s: &mut GameState, seat: u32) -> bool {
    (s.waits[(seat * 2u32) as usize] | s.waits[(seat * 2u32 + 1u32) as usize]) != 0u32
}

// Discarding one tile of type `t` leaves the seat tenpai (the hand holds 14 - 3 x melds tiles).
fn tenpai_after_discard(s: &mut GameState, seat: u32, t: u32) -> bool {
    let mut c: [u32; 34] = hand_counts(s, seat);
    if c[t as usize] == 0u32 {
        return false;
    }
    c[t as usize] -= 1u32;
    let w: [u32; 2] = waits_of(c);
    (w[0] | w[1]) != 0u32
}
