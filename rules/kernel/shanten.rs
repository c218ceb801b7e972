// Exact shanten from the per-group cost tables. A group's table row gives, for m sets and h pairs,
// the fewest tiles that must be added to that group; combining the four groups by min-plus over
// (m, h) gives the exact number of tiles missing for the whole hand, and shanten = missing - 1.
// The combinations are tables too (codegen's `tables::pairs`): the two suits' rows and the third
// suit's with the honors' each give a combined row, and the two combined rows the tiles missing.

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ShantenInput {
    pub hand: [u32; 34],
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ShantenOutput {
    pub shanten: i32,
    pub normal: i32,
    pub chiitoitsu: i32,
    pub kokushi: i32,
}

// Reported for chiitoitsu and kokushi when the hand has too few tiles for them (it has melds).
pub const SHANTEN_NOT_APPLICABLE: i32 = 99;

// The combined row of two suits' cost words (the min-plus combination of their rows, packed as a
// cost word with its own number above), read by the rows' numbers that the words carry.
fn suit_pair(a: u32, b: u32) -> u32 {
    table(T_SUIT_PAIRS + (a >> T_ROW_SHIFT) * T_SUIT_ROWS + (b >> T_ROW_SHIFT))
}

// The same for a suit's and the honors' cost words.
fn suit_honor_pair(a: u32, b: u32) -> u32 {
    table(T_SUIT_HONOR_PAIRS + (a >> T_ROW_SHIFT) * T_HONOR_ROWS + (b >> T_ROW_SHIFT))
}

fn shanten_normal(hand: [u32; 34], tiles: u32) -> i32 {
    normal_of_codes(suit_code(hand, 0u32), suit_code(hand, 1u32), suit_code(hand, 2u32), honor_code(hand), tiles)
}

// The tiles a hand misses for `sets` sets and the pair, given the combined rows of its two suits
// (`suit_pair`) and of its third suit with the honors (`suit_honor_pair`): one word of the
// `missing` table, read by the two rows' numbers.
fn pairs_missing(a: u32, b: u32, sets: u32) -> i32 {
    let m: u32 = table(T_MISSING + (a >> T_ROW_SHIFT) * T_SUIT_HONOR_PAIR_ROWS + (b >> T_ROW_SHIFT));
    ((m >> (sets * T_MISSING_BITS)) & ((1u32 << T_MISSING_BITS) - 1u32)) as i32
}

// The sets a hand of `tiles` tiles is built of with its pair (at most 4: a forged hand with more
// tiles reads the table's last count).
fn sets_of(tiles: u32) -> u32 {
    (tiles / 3u32).min(4u32)
}

// The normal form's shanten of `tiles` tiles whose three suits and honors have these codes.
fn normal_of_codes(c0: u32, c1: u32, c2: u32, c3: u32, tiles: u32) -> i32 {
    // All four loads first, so their cache misses overlap.
    let w0: u32 = table(T_SUIT_COST + c0);
    let w1: u32 = table(T_SUIT_COST + c1);
    let w2: u32 = table(T_SUIT_COST + c2);
    let w3: u32 = table(T_HONOR_COST + c3);
    pairs_missing(suit_pair(w0, w1), suit_honor_pair(w2, w3), sets_of(tiles)) - 1i32
}

// Kinds held (at most one per type) and of those, kinds held twice or more; straight-line counting
// with no branch on the (random) counts.
fn kinds_and_pairs(hand: [u32; 34], first: u32, last: u32) -> [u32; 2] {
    let mut kinds: u32 = 0u32;
    let mut pairs: u32 = 0u32;
    for t in first..last {
        let c: u32 = hand[t as usize];
        kinds += c.min(1u32);
        pairs += (c >> 1u32).min(1u32);
    }
    [kinds, pairs]
}

// Kinds of terminal and honor tiles held, and of those, kinds held twice or more.
fn orphan_kinds_and_pairs(hand: [u32; 34]) -> [u32; 2] {
    let honors: [u32; 2] = kinds_and_pairs(hand, FIRST_HONOR, N_TYPES);
    let mut kinds: u32 = honors[0];
    let mut pairs: u32 = honors[1];
    for s in 0u32..3u32 {
        let low: u32 = hand[(s * 9u32) as usize];
        let high: u32 = hand[(s * 9u32 + 8u32) as usize];
        kinds += low.min(1u32) + high.min(1u32);
        pairs += (low >> 1u32).min(1u32) + (high >> 1u32).min(1u32);
    }
    [kinds, pairs]
}

// Thirteen orphans: 13 less the orphan kinds held, less one if any of them is a pair.
fn orphans_shanten(kinds: u32, pairs: u32) -> i32 {
    13i32 - (kinds as i32) - (pairs.min(1u32) as i32)
}

// Seven pairs: 6 less the pairs, plus the kinds missing for seven different pairs.
fn chiitoitsu_shanten(kinds: u32, pairs: u32) -> i32 {
    6i32 - (pairs as i32).min(7i32) + (7i32 - (kinds as i32)).max(0i32)
}

pub fn shanten(inp: ShantenInput) -> ShantenOutput {
    let mut tiles: u32 = 0u32;
    for t in 0u32..N_TYPES {
        tiles += inp.hand[t as usize];
    }
    let normal: i32 = shanten_normal(inp.hand, tiles);
    let mut chiitoitsu: i32 = SHANTEN_NOT_APPLICABLE;
    let mut kokushi: i32 = SHANTEN_NOT_APPLICABLE;
    if tiles >= 13u32 {
        let kp: [u32; 2] = kinds_and_pairs(inp.hand, 0u32, N_TYPES);
        chiitoitsu = chiitoitsu_shanten(kp[0], kp[1]);
        let op: [u32; 2] = orphan_kinds_and_pairs(inp.hand);
        kokushi = orphans_shanten(op[0], op[1]);
    }
    ShantenOutput {
        shanten: normal.min(chiitoitsu).min(kokushi),
        normal: normal,
        chiitoitsu: chiitoitsu,
        kokushi: kokushi,
    }
}

// Eight types' counts, a packed word's nibbles (the first type lowest), as a code with the first
// type most significant, as `suit_code` counts: neighbouring digits are merged in every lane of the
// word at once. No lane carries into the next for any nibbles (15 x 5 + 15 < 256, 90 x 25 + 90 <
// 65536), so the code is `suit_code`'s for any counts, as on the GPU.
fn code_of_nibbles(x: u32) -> u32 {
    let two: u32 = (x & 0x0f0f0f0fu32) * 5u32 + ((x >> 4u32) & 0x0f0f0f0fu32);
    let four: u32 = (two & 0x00ff00ffu32) * 25u32 + ((two >> 8u32) & 0x00ff00ffu32);
    (four & 0xffffu32) * 625u32 + (four >> 16u32)
}

// The sum of a word's nibbles, each at most 5 (bits gathered from five words): at most 40, so the
// bytes' sum fits the top byte.
fn nibble_sum(x: u32) -> u32 {
    (((x & 0x0f0f0f0fu32) + ((x >> 4u32) & 0x0f0f0f0fu32)).wrapping_mul(0x01010101u32)) >> 24u32
}

// `shanten(ShantenInput { hand: hand_counts(s, seat) }).shanten`, read from the hand's packed words
// without the 34 counts between: the groups' codes are merged a word at a time, and the tiles,
// kinds and pairs that the seven pairs and thirteen orphans count are nibble sums of whole words.
pub fn hand_shanten(s: &mut GameState, seat: u32) -> i32 {
    let mut h: [u32; 5] = [0u32; 5];
    let mut tiles: u32 = 0u32;
    // Bit 0 of each nibble, summed over the words: the type is held; held twice or more; the same
    // for the terminals and honors.
    let mut kinds: u32 = 0u32;
    let mut pairs: u32 = 0u32;
    let mut orphan_kinds: u32 = 0u32;
    let mut orphan_pairs: u32 = 0u32;
    for w in 0u32..5u32 {
        let mut x: u32 = s.hands[(seat * 5u32 + w) as usize];
        // The last word holds types 32 and 33 only.
        let mut orphans: u32 = 0x11u32;
        if w == 4u32 {
            x &= 0xffu32;
        } else if w == 0u32 {
            orphans = 0x1u32;
        } else if w == 2u32 {
            orphans = 0x110u32;
        } else if w == 3u32 {
            orphans = 0x11111100u32;
        }
        h[w as usize] = x;
        let bytes: u32 = (x & 0x0f0f0f0fu32) + ((x >> 4u32) & 0x0f0f0f0fu32);
        tiles += bytes.wrapping_mul(0x01010101u32) >> 24u32;
        let held: u32 = (x | (x >> 1u32) | (x >> 2u32) | (x >> 3u32)) & 0x11111111u32;
        let two: u32 = ((x >> 1u32) | (x >> 2u32) | (x >> 3u32)) & 0x11111111u32;
        kinds += held;
        pairs += two;
        orphan_kinds += held & orphans;
        orphan_pairs += two & orphans;
    }
    // Types 0-8, 9-17 and 18-26 start at nibbles 0, 9 and 18 (words 0, 1 and 2); the honors, 27-33,
    // are read with a zero digit before them.
    let c0: u32 = code_of_nibbles(h[0]) * 5u32 + (h[1] & 15u32);
    let c1: u32 = code_of_nibbles((h[1] >> 4u32) | (h[2] << 28u32)) * 5u32 + ((h[2] >> 4u32) & 15u32);
    let c2: u32 = code_of_nibbles((h[2] >> 8u32) | (h[3] << 24u32)) * 5u32 + ((h[3] >> 8u32) & 15u32);
    let c3: u32 = code_of_nibbles((((h[3] >> 12u32) | (h[4] << 20u32)) & 0x0fffffffu32) << 4u32);
    let normal: i32 = normal_of_codes(c0, c1, c2, c3, tiles);
    if tiles < 13u32 {
        return normal;
    }
    let chiitoitsu: i32 = chiitoitsu_shanten(nibble_sum(kinds), nibble_sum(pairs));
    normal.min(chiitoitsu).min(orphans_shanten(nibble_sum(orphan_kinds), nibble_sum(orphan_pairs)))
}

// The shanten of `hand` with one more tile of each type, as `shanten` would compute it for each
// (SHANTEN_NOT_APPLICABLE for a type held four times): the analysis tier's improving tiles and the
// agents' ukeire.
fn shanten_after_draws(hand: [u32; 34]) -> [i32; 34] {
    shanten_after_each(hand, true)
}

// The shanten of `hand` with one tile of each type let go, as `shanten` would compute it for each
// (SHANTEN_NOT_APPLICABLE for a type not held): the agents' discards.
fn shanten_after_discards(hand: [u32; 34]) -> [i32; 34] {
    shanten_after_each(hand, false)
}

// One tile more (`adding`) or less of each type: the tile changes one group's table word and the
// kind counts only, so its group is paired again with the group it shares a pair table with, and
// the other pair's row is the hand's; each type costs three table reads (the new group's cost
// word, its pair word, the `missing` word) instead of a whole `shanten`. The agents ask this for
// every discard of every play-out.
fn shanten_after_each(hand: [u32; 34], adding: bool) -> [i32; 34] {
    let mut tiles: u32 = 0u32;
    for t in 0u32..N_TYPES {
        tiles += hand[t as usize];
    }
    // The hand's tiles after the change (a discard from an empty hand changes nothing: no type is
    // held).
    let mut after_tiles: u32 = tiles + 1u32;
    if !adding {
        after_tiles = tiles.max(1u32) - 1u32;
    }
    let sets: u32 = sets_of(after_tiles);
    let c0: u32 = suit_code(hand, 0u32);
    let c1: u32 = suit_code(hand, 1u32);
    let c2: u32 = suit_code(hand, 2u32);
    let c3: u32 = honor_code(hand);
    let w0: u32 = table(T_SUIT_COST + c0);
    let w1: u32 = table(T_SUIT_COST + c1);
    let w2: u32 = table(T_SUIT_COST + c2);
    let w3: u32 = table(T_HONOR_COST + c3);
    let p01: u32 = suit_pair(w0, w1);
    let p23: u32 = suit_honor_pair(w2, w3);
    // Kinds and pairs of the whole hand and of its terminals and honors, for the other two forms.
    let kp: [u32; 2] = kinds_and_pairs(hand, 0u32, N_TYPES);
    let op: [u32; 2] = orphan_kinds_and_pairs(hand);
    let mut out: [i32; 34] = [SHANTEN_NOT_APPLICABLE; 34];
    for g in 0u32..4u32 {
        // The group's code, and the place value of its first type in the code.
        let mut code: u32 = T_HONOR_COST + c3;
        let mut place: u32 = 15625u32;
        let mut n: u32 = 7u32;
        if g == 0u32 {
            code = T_SUIT_COST + c0;
        } else if g == 1u32 {
            code = T_SUIT_COST + c1;
        } else if g == 2u32 {
            code = T_SUIT_COST + c2;
        }
        if g < 3u32 {
            place = 390625u32;
            n = 9u32;
        }
        for i in 0u32..n {
            let t: u32 = g * 9u32 + i;
            let c: u32 = hand[t as usize];
            if (adding && c < 4u32) || (!adding && c > 0u32) {
                // The group's code with the tile (held when let go: no underflow).
                let mut changed: u32 = code + place;
                if !adding {
                    changed = code - place;
                }
                let w: u32 = table(changed);
                let mut a: u32 = p01;
                let mut b: u32 = p23;
                if g == 0u32 {
                    a = suit_pair(w, w1);
                } else if g == 1u32 {
                    a = suit_pair(w0, w);
                } else if g == 2u32 {
                    b = suit_honor_pair(w, w3);
                } else {
                    b = suit_honor_pair(w2, w);
                }
                let mut best: i32 = pairs_missing(a, b, sets) - 1i32;
                if after_tiles >= 13u32 {
                    // A drawn tile is a new kind if none was held, a new pair if one was; a tile
                    // let go loses its kind if it was the only one, its pair if there were two.
                    let orphan: u32 = is_terminal_or_honor(t) as u32;
                    if adding {
                        let new_kind: u32 = (c == 0u32) as u32;
                        let new_pair: u32 = (c == 1u32) as u32;
                        best = best.min(chiitoitsu_shanten(kp[0] + new_kind, kp[1] + new_pair));
                        best = best.min(orphans_shanten(op[0] + orphan * new_kind, op[1] + orphan * new_pair));
                    } else {
                        let lost_kind: u32 = (c == 1u32) as u32;
                        let lost_pair: u32 = (c == 2u32) as u32;
                        best = best.min(chiitoitsu_shanten(kp[0] - lost_kind, kp[1] - lost_pair));
                        best = best.min(orphans_shanten(op[0] - orphan * lost_kind, op[1] - orphan * lost_pair));
                    }
                }
                out[t as usize] = best;
            }
            place = place / 5u32;
        }
    }
    out
}
