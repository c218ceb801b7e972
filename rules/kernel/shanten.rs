// Exact shanten from the per-group cost tables. A group's table row gives, for m sets and h pairs,
// the fewest tiles that must be added to that group; combining the four groups by min-plus over
// (m, h) gives the exact number of tiles missing for the whole hand, and shanten = missing - 1.

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
const SHANTEN_NOT_APPLICABLE: i32 = 99;

// Costs of one group, index m * 2 + h; unpacked from two table words of 4-bit fields.
fn group_costs(base: u32, code: u32) -> [u32; 10] {
    let w0: u32 = table(base + code * 2u32);
    let w1: u32 = table(base + code * 2u32 + 1u32);
    let mut c: [u32; 10] = [0u32; 10];
    for m in 0u32..5u32 {
        c[(m * 2u32) as usize] = (w0 >> (m * 4u32)) & 15u32;
        c[(m * 2u32 + 1u32) as usize] = (w1 >> (m * 4u32)) & 15u32;
    }
    c
}

fn combine_costs(a: [u32; 10], b: [u32; 10]) -> [u32; 10] {
    let mut out: [u32; 10] = [255u32; 10];
    for m1 in 0u32..5u32 {
        for h1 in 0u32..2u32 {
            for m2 in 0u32..5u32 - m1 {
                for h2 in 0u32..2u32 - h1 {
                    let i: u32 = (m1 + m2) * 2u32 + h1 + h2;
                    let v: u32 = a[(m1 * 2u32 + h1) as usize] + b[(m2 * 2u32 + h2) as usize];
                    if v < out[i as usize] {
                        out[i as usize] = v;
                    }
                }
            }
        }
    }
    out
}

fn shanten_normal(hand: [u32; 34], tiles: u32) -> i32 {
    let sets: u32 = tiles / 3u32;
    let mut acc: [u32; 10] = group_costs(T_SUIT_COST, suit_code(hand, 0u32));
    acc = combine_costs(acc, group_costs(T_SUIT_COST, suit_code(hand, 1u32)));
    acc = combine_costs(acc, group_costs(T_SUIT_COST, suit_code(hand, 2u32)));
    // Only one entry of the last combination is needed: `sets` sets and the pair in all.
    let honors: [u32; 10] = group_costs(T_HONOR_COST, honor_code(hand));
    let mut best: u32 = 255u32;
    for m in 0u32..sets + 1u32 {
        for h in 0u32..2u32 {
            let v: u32 = acc[(m * 2u32 + h) as usize] + honors[((sets - m) * 2u32 + 1u32 - h) as usize];
            best = best.min(v);
        }
    }
    (best as i32) - 1i32
}

// Seven pairs and thirteen orphans in one pass over the hand.
fn shanten_pairs_and_orphans(hand: [u32; 34]) -> [i32; 2] {
    let mut pairs: i32 = 0i32;
    let mut kinds: i32 = 0i32;
    let mut orphan_kinds: i32 = 0i32;
    let mut orphan_pair: i32 = 0i32;
    for t in 0u32..N_TYPES {
        let c: u32 = hand[t as usize];
        if c >= 1u32 {
            kinds += 1i32;
            if c >= 2u32 {
                pairs += 1i32;
            }
            if is_terminal_or_honor(t) {
                orphan_kinds += 1i32;
                if c >= 2u32 {
                    orphan_pair = 1i32;
                }
            }
        }
    }
    let missing_kinds: i32 = (7i32 - kinds).max(0i32);
    [6i32 - pairs.min(7i32) + missing_kinds, 13i32 - orphan_kinds - orphan_pair]
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
        let special: [i32; 2] = shanten_pairs_and_orphans(inp.hand);
        chiitoitsu = special[0];
        kokushi = special[1];
    }
    ShantenOutput {
        shanten: normal.min(chiitoitsu).min(kokushi),
        normal: normal,
        chiitoitsu: chiitoitsu,
        kokushi: kokushi,
    }
}
