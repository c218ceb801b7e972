// The scoring kernel's input and output, and the reading-independent facts about a hand.

// Meld word: kind in bits 0-3, tile type in bits 4-9 (for a chi: the lowest tile of the run).
// The meld kinds, flags and statuses are `pub`: hosts build inputs and read outputs with them.
pub const MELD_CHI: u32 = 0;
pub const MELD_PON: u32 = 1;
pub const MELD_OPEN_KAN: u32 = 2;
pub const MELD_CLOSED_KAN: u32 = 3;
pub const MELD_ADDED_KAN: u32 = 4;
pub const MELD_TILE_SHIFT: u32 = 4;
// In the game state a meld word also holds the seat it was called from (relative, bits 10-11)
// and its red fives (bits 12-14); the scoring input masks them off.
pub const MELD_FROM_SHIFT: u32 = 10;
pub const MELD_REDS_SHIFT: u32 = 12;

// Situation flags of a win.
pub const FLAG_TSUMO: u32 = 1;
pub const FLAG_RIICHI: u32 = 2;
pub const FLAG_DOUBLE_RIICHI: u32 = 4;
pub const FLAG_IPPATSU: u32 = 8;
pub const FLAG_HAITEI: u32 = 16;
pub const FLAG_HOUTEI: u32 = 32;
pub const FLAG_RINSHAN: u32 = 64;
pub const FLAG_CHANKAN: u32 = 128;
pub const FLAG_TENHOU: u32 = 256;
pub const FLAG_CHIIHOU: u32 = 512;
pub const FLAG_DEALER: u32 = 1024;

pub const STATUS_WIN: u32 = 0;
pub const STATUS_NOT_COMPLETE: u32 = 1;
pub const STATUS_NO_YAKU: u32 = 2;
pub const STATUS_BAD_INPUT: u32 = 3;

// Which set of the reading the winning tile completed.
const SLOT_PAIR: u32 = 0;
const SLOT_TRIPLET: u32 = 1;
const SLOT_RUN: u32 = 2;

const NO_PAIR: u32 = 15;
const NO_TILE: u32 = 99;
const MANGAN: u32 = 2000;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ScoreInput {
    // Concealed tiles, the winning tile included.
    pub hand: [u32; 34],
    pub win_tile: u32,
    pub melds: [u32; 4],
    pub n_melds: u32,
    pub flags: u32,
    // 0..3 = E S W N
    pub round_wind: u32,
    pub seat_wind: u32,
    pub dora: [u32; 5],
    pub n_dora: u32,
    pub ura: [u32; 5],
    pub n_ura: u32,
    // Red fives among all of the winner's tiles, melds included.
    pub aka: u32,
    // North tiles the winner set aside (kita, three players): each a dora, and one more for each
    // dora or ura indicator that points at North.
    pub kita: u32,
    pub honba: u32,
    pub sticks: u32,
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ScoreOutput {
    pub status: u32,
    pub han: u32,
    pub fu: u32,
    pub yakuman: u32,
    pub yaku_lo: u32,
    pub yaku_hi: u32,
    pub dora: u32,
    pub aka: u32,
    pub ura: u32,
    pub base: u32,
    // Ron: what the discarder pays, honba included.
    pub ron: u32,
    // Tsumo: what the dealer pays (non-dealer win) and what each other payer pays.
    pub dealer_pays: u32,
    pub others_pay: u32,
    // The winner's whole gain, riichi sticks included.
    pub gain: u32,
    // 1 when no meld was called (closed kans allowed): selects the closed han of each yaku.
    pub concealed: u32,
}

// What does not depend on the reading.
#[derive(Clone, Copy)]
struct HandInfo {
    full: [u32; 34],
    concealed: bool,
    meld_runs: [u32; 3],
    meld_triplets: [u32; 3],
    n_meld_runs: u32,
    n_meld_triplets: u32,
    kans: u32,
    closed_kans: u32,
    meld_fu: u32,
    melds_outside: bool,
    // bit i = a triplet or quad of honor 27 + i, concealed or called
    honor_sets: u32,
}

fn flag(inp: ScoreInput, f: u32) -> bool {
    (inp.flags & f) != 0u32
}

pub fn meld_kind(m: u32) -> u32 {
    m & 15u32
}

pub fn meld_tile(m: u32) -> u32 {
    (m >> MELD_TILE_SHIFT) & 63u32
}

// Adds the tiles of meld `m` to the counts by type (a kan counts four).
pub fn meld_types(m: u32, c: &mut [u32; 34]) {
    let k: u32 = meld_kind(m);
    let t: u32 = meld_tile(m);
    if k == MELD_CHI {
        c[t as usize] += 1u32;
        c[(t + 1u32) as usize] += 1u32;
        c[(t + 2u32) as usize] += 1u32;
    } else if k == MELD_PON {
        c[t as usize] += 3u32;
    } else {
        c[t as usize] += 4u32;
    }
}

pub fn meld_word(kind: u32, tile: u32) -> u32 {
    kind | (tile << MELD_TILE_SHIFT)
}

fn empty_output(status: u32) -> ScoreOutput {
    ScoreOutput {
        status: status,
        han: 0u32,
        fu: 0u32,
        yakuman: 0u32,
        yaku_lo: 0u32,
        yaku_hi: 0u32,
        dora: 0u32,
        aka: 0u32,
        ura: 0u32,
        base: 0u32,
        ron: 0u32,
        dealer_pays: 0u32,
        others_pay: 0u32,
        gain: 0u32,
        concealed: 0u32,
    }
}

fn input_is_valid(inp: ScoreInput) -> bool {
    if inp.n_melds > 4u32 || inp.win_tile >= N_TYPES || inp.round_wind > 3u32 || inp.seat_wind > 3u32 {
        return false;
    }
    if inp.n_dora > 5u32 || inp.n_ura > 5u32 || inp.aka > 4u32 || inp.kita > 4u32 {
        return false;
    }
    let mut all: [u32; 34] = inp.hand;
    let mut concealed_tiles: u32 = 0u32;
    for t in 0u32..N_TYPES {
        concealed_tiles += inp.hand[t as usize];
    }
    for i in 0u32..inp.n_melds {
        let m: u32 = inp.melds[i as usize];
        let kind: u32 = meld_kind(m);
        let t: u32 = meld_tile(m);
        if kind > MELD_ADDED_KAN || t >= N_TYPES {
            return false;
        }
        if kind == MELD_CHI {
            if is_honor(t) || t % 9u32 > 6u32 {
                return false;
            }
        }
        meld_types(m, &mut all);
    }
    for t in 0u32..N_TYPES {
        if all[t as usize] > 4u32 {
            return false;
        }
    }
    for i in 0u32..inp.n_dora {
        if inp.dora[i as usize] >= N_TYPES {
            return false;
        }
    }
    for i in 0u32..inp.n_ura {
        if inp.ura[i as usize] >= N_TYPES {
            return false;
        }
    }
    concealed_tiles + 3u32 * inp.n_melds == 14u32 && inp.hand[inp.win_tile as usize] >= 1u32
}

fn hand_info(inp: ScoreInput) -> HandInfo {
    let mut h: HandInfo = HandInfo {
        full: inp.hand,
        concealed: true,
        meld_runs: [0u32; 3],
        meld_triplets: [0u32; 3],
        n_meld_runs: 0u32,
        n_meld_triplets: 0u32,
        kans: 0u32,
        closed_kans: 0u32,
        meld_fu: 0u32,
        melds_outside: true,
        honor_sets: 0u32,
    };
    for i in 0u32..inp.n_melds {
        let m: u32 = inp.melds[i as usize];
        let kind: u32 = meld_kind(m);
        let t: u32 = meld_tile(m);
        if kind != MELD_CLOSED_KAN {
            h.concealed = false;
        }
        if kind == MELD_CHI {
            h.full[t as usize] += 1u32;
            h.full[(t + 1u32) as usize] += 1u32;
            h.full[(t + 2u32) as usize] += 1u32;
            h.meld_runs[(t / 9u32) as usize] |= 1u32 << (t % 9u32);
            h.n_meld_runs += 1u32;
            if t % 9u32 != 0u32 && t % 9u32 != 6u32 {
                h.melds_outside = false;
            }
        } else {
            let mut fu: u32 = 2u32;
            if kind == MELD_PON {
                h.full[t as usize] += 3u32;
            } else {
                h.full[t as usize] += 4u32;
                h.kans += 1u32;
                fu = 8u32;
                if kind == MELD_CLOSED_KAN {
                    h.closed_kans += 1u32;
                    fu = 16u32;
                }
            }
            if is_terminal_or_honor(t) {
                fu = fu * 2u32;
            } else {
                h.melds_outside = false;
            }
            h.meld_fu += fu;
            h.n_meld_triplets += 1u32;
            if is_honor(t) {
                h.honor_sets |= 1u32 << (t - FIRST_HONOR);
            } else {
                h.meld_triplets[(t / 9u32) as usize] |= 1u32 << (t % 9u32);
            }
        }
    }
    for i in 0u32..7u32 {
        if inp.hand[(FIRST_HONOR + i) as usize] >= 3u32 {
            h.honor_sets |= 1u32 << i;
        }
    }
    h
}
