// The layout of the observation records that rules/kernel/view.rs writes: one fact each, read by
// the view, the host's field table (rinshan_engine::observe) and the GPU entry points.

// `arg` of the observe functions: the observing seat 0..3, or OBSERVE_CURRENT for the player to move.
pub const OBSERVE_CURRENT: u32 = 4;

pub const NO_TILE_BYTE: u32 = 255;

// Planes: rows of 34 tile types.
pub const PLANE_ROWS: u32 = 64;
pub const PLANE_WORDS: u32 = 544;
pub const P_HAND: u32 = 0;
pub const P_RED: u32 = 4;
pub const P_DRAWN: u32 = 5;
pub const P_TARGET: u32 = 6;
pub const P_WAITS: u32 = 7;
pub const P_LEGAL_DISCARD: u32 = 8;
pub const P_CHI_LOW: u32 = 9;
pub const P_CHI_MIDDLE: u32 = 10;
pub const P_CHI_HIGH: u32 = 11;
pub const P_PON: u32 = 12;
pub const P_OPEN_KAN: u32 = 13;
pub const P_SELF_KAN: u32 = 14;
pub const P_YAKUHAI: u32 = 15;
// Per ego seat, P_SEAT + seat * P_SEAT_ROWS + one of the P_SEAT_* offsets.
pub const P_SEAT: u32 = 16;
pub const P_SEAT_ROWS: u32 = 11;
pub const P_SEAT_DISCARDED: u32 = 0;
pub const P_SEAT_TEDASHI: u32 = 1;
pub const P_SEAT_FIRST_TURN: u32 = 2;
pub const P_SEAT_LAST_TURN: u32 = 3;
pub const P_SEAT_RIICHI_TILE: u32 = 4;
pub const P_SEAT_SAFE: u32 = 5;
pub const P_SEAT_MELD_TILES: u32 = 6;
pub const P_SEAT_CALLED_IN: u32 = 7;
pub const P_SEAT_CLOSED_KAN: u32 = 8;
pub const P_SEAT_LAST_DISCARD: u32 = 9;
pub const P_SEAT_CALLED_AWAY: u32 = 10;
pub const P_DORA_INDICATORS: u32 = 60;
pub const P_DORA: u32 = 61;
pub const P_SEEN: u32 = 62;
pub const P_RED_SEEN: u32 = 63;

// Scalars: 48 int16, two per word.
pub const SCALARS: u32 = 48;
pub const SCALAR_WORDS: u32 = 24;
pub const S_SCORE: u32 = 0;
pub const S_RANK: u32 = 4;
pub const S_ROUND: u32 = 8;
pub const S_ROUND_WIND: u32 = 9;
pub const S_SEAT_WIND: u32 = 10;
pub const S_DEALER: u32 = 11;
pub const S_HONBA: u32 = 12;
pub const S_STICKS: u32 = 13;
pub const S_TILES_LEFT: u32 = 14;
pub const S_KANS: u32 = 15;
pub const S_DORA_REVEALED: u32 = 16;
pub const S_RIICHI: u32 = 17;
pub const S_IPPATSU: u32 = 21;
pub const S_CONCEALED: u32 = 25;
pub const S_DISCARDS: u32 = 29;
pub const S_MELDS: u32 = 33;
pub const S_SHANTEN: u32 = 37;
pub const S_FURITEN: u32 = 38;
pub const S_DECISION: u32 = 39;
pub const S_CLAIM_FROM: u32 = 40;
pub const S_FIRST_GO_AROUND: u32 = 41;
pub const S_MODE: u32 = 42;
pub const S_ROUNDS_LEFT: u32 = 43;
pub const S_OWN_DORA: u32 = 44;
pub const S_OWN_RED: u32 = 45;
pub const S_EVENTS: u32 = 46;
// 47: reserved (0).
pub const S_RESERVED: u32 = 47;

// S_DECISION values.
pub const DECISION_NONE: u32 = 0;
pub const DECISION_TURN: u32 = 1;
pub const DECISION_RIICHI_DISCARD: u32 = 2;
pub const DECISION_CLAIM: u32 = 3;
pub const DECISION_CHANKAN: u32 = 4;

// S_RIICHI values.
pub const RIICHI_DECLARED: u32 = 1;
pub const RIICHI_ACCEPTED: u32 = 2;
pub const RIICHI_DOUBLE: u32 = 3;

// The tiles every seat sees on the table, by type as packed cells (`pack_cells`: byte t % 4 of word
// t / 4): river tiles not called away and the melds' tiles; and the suits (a bit each) with a red
// five among them.
#[derive(Clone, Copy)]
pub struct TableTiles {
    pub seen: [u32; 9],
    pub red_seen: u32,
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ObsPlanes {
    pub planes: [u32; 544],
    pub scalars: [u32; 24],
}

// Packed planes: the planes' yes/no rows as 34-bit sets (bit t = tile type t), one u64 each (two
// words, low first), and their rows of counts and turn numbers as bytes, each kind in planes order
// (`packed_index`). Unpacked they are the planes' bytes exactly.
pub const PACKED_BITS: u32 = 36;
pub const PACKED_COUNTS: u32 = 28;
// A seat block's rows of each kind.
pub const PACKED_SEAT_BITS: u32 = 5;
pub const PACKED_SEAT_COUNTS: u32 = 6;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ObsPacked {
    pub bits: [u32; 72],
    pub counts: [u32; 238],
    pub scalars: [u32; 24],
}

// Whether the cells of row `o` of a seat block are yes/no.
fn seat_row_binary(o: u32) -> bool {
    o == P_SEAT_RIICHI_TILE || o == P_SEAT_SAFE || o == P_SEAT_CALLED_IN || o == P_SEAT_CLOSED_KAN || o == P_SEAT_LAST_DISCARD
}

// Whether the cells of planes row `row` are yes/no (a bit each in the packed form).
pub fn plane_row_binary(row: u32) -> bool {
    if row >= P_SEAT && row < P_DORA_INDICATORS {
        return seat_row_binary((row - P_SEAT) % P_SEAT_ROWS);
    }
    row < P_YAKUHAI || row == P_RED_SEEN
}

// Where planes row `row` is in the packed form: its index among the rows of its kind (bit-rows if
// `plane_row_binary`, else rows of bytes).
pub fn packed_index(row: u32) -> u32 {
    if row >= P_SEAT && row < P_DORA_INDICATORS {
        return packed_seat_index((row - P_SEAT) / P_SEAT_ROWS, (row - P_SEAT) % P_SEAT_ROWS);
    }
    if row < P_YAKUHAI {
        return row;
    }
    if row == P_YAKUHAI {
        return 0u32;
    }
    if row == P_RED_SEEN {
        return P_YAKUHAI + 4u32 * PACKED_SEAT_BITS;
    }
    1u32 + 4u32 * PACKED_SEAT_COUNTS + row - P_DORA_INDICATORS
}

// `packed_index` of row `o` of ego seat `j`'s block: the writer names `o` as a constant, so this
// folds to a constant plus a multiple of `j`.
pub fn packed_seat_index(j: u32, o: u32) -> u32 {
    let binary: bool = seat_row_binary(o);
    let mut n: u32 = 0u32;
    for i in 0u32..o {
        n += (seat_row_binary(i) == binary) as u32;
    }
    if binary {
        return P_YAKUHAI + j * PACKED_SEAT_BITS + n;
    }
    1u32 + j * PACKED_SEAT_COUNTS + n
}

// Tokens: byte offsets of the fields in ObsTokens.words.
pub const TOKEN_WORDS: u32 = 254;
pub const T_HAND: u32 = 0;
pub const T_HAND_RED: u32 = 36;
pub const T_DRAWN: u32 = 39;
pub const T_TARGET: u32 = 40;
pub const T_EVENTS_LEN: u32 = 41;
pub const T_MELDS: u32 = 44;
pub const T_DORA: u32 = 108;
pub const T_SEEN: u32 = 116;
pub const T_SCALARS: u32 = 152;
pub const T_EVENTS: u32 = 248;
// Events of the token form: draws are tokens of their own, so a round needs at most 118 + 70.
pub const TOKEN_EVENTS: u32 = 192;
// An event token is a word of four bytes: its kind (EV_*), the actor's ego seat, the tile (a value,
// NO_TILE_BYTE for none or hidden) and the log's flags. The seat's byte holds 0..3 only, so a
// rotation of seats can be added to a token without a carry past the byte.
pub const TOKEN_SEAT_SHIFT: u32 = 8;
pub const TOKEN_TILE_SHIFT: u32 = 16;
pub const TOKEN_FLAGS_SHIFT: u32 = 24;

pub fn event_token(kind: u32, seat: u32, tile: u32, flags: u32) -> u32 {
    kind | (seat << TOKEN_SEAT_SHIFT) | (tile << TOKEN_TILE_SHIFT) | (flags << TOKEN_FLAGS_SHIFT)
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ObsTokens {
    pub words: [u32; 254],
}


// The analysis tier (opt-in, same knowledge as the observation): byte offsets in ObsAnalysis.
pub const ANALYSIS_WORDS: u32 = 34;
pub const A_DISCARD_SHANTEN: u32 = 0;
pub const A_DISCARD_UKEIRE: u32 = 34;
pub const A_WAITS: u32 = 68;
pub const A_IMPROVING: u32 = 102;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ObsAnalysis {
    pub words: [u32; 34],
}

// The oracle (opt-in, hidden information, never part of an observation): byte offsets in
// ObsOracle. Other seats in ego order (right, across, left).
pub const ORACLE_WORDS: u32 = 78;
pub const O_HANDS: u32 = 0;
pub const O_RED: u32 = 102;
pub const O_SHANTEN: u32 = 112;
pub const O_FURITEN: u32 = 115;
pub const O_WAITS: u32 = 120;
pub const O_WALL: u32 = 224;
pub const O_RINSHAN: u32 = 296;
pub const O_DORA: u32 = 300;
pub const O_URA: u32 = 305;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ObsOracle {
    pub words: [u32; 78],
}
