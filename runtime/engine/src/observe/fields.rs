//! The one table that documents every field of every form: name, dtype, shape, meaning, scale.

use crate::generated::kernel as k;

/// Element type of a field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dtype {
    /// Unsigned byte.
    U8,
    /// Signed byte (-1 = none).
    I8,
    /// Signed 16-bit, little-endian.
    I16,
    /// Unsigned 64-bit, little-endian (the packed form's bit-rows).
    U64,
}

impl Dtype {
    /// numpy's name for it.
    pub fn name(self) -> &'static str {
        match self {
            Dtype::U8 => "uint8",
            Dtype::I8 => "int8",
            Dtype::I16 => "int16",
            Dtype::U64 => "uint64",
        }
    }

    /// Bytes per element.
    pub fn size(self) -> usize {
        match self {
            Dtype::U8 | Dtype::I8 => 1,
            Dtype::I16 => 2,
            Dtype::U64 => 8,
        }
    }
}

/// One field of a form: a typed array at a byte offset of the record.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Field {
    /// The key (`planes`, `hand`, `events` ...).
    pub name: &'static str,
    /// Byte offset in the record.
    pub offset: usize,
    /// Element type.
    pub dtype: Dtype,
    /// Array shape (row-major).
    pub shape: &'static [usize],
    /// What it holds and in what units.
    pub doc: &'static str,
    /// Each element is a yes/no flag (0 or 1), printed as a word in the text form.
    pub flag: bool,
}

impl Field {
    /// Bytes the field spans.
    pub fn len(&self) -> usize {
        self.shape.iter().product::<usize>() * self.dtype.size()
    }

    /// Whether the field has no elements (never, for the built-in forms).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

const fn u(x: u32) -> usize {
    x as usize
}

const PLANE_BYTES: usize = u(k::PLANE_ROWS) * 34;

/// The fields of [`Form::Planes`](crate::observe::Form::Planes).
pub static PLANES_FIELDS: [Field; 2] = [
    Field {
        name: "planes",
        offset: 0,
        dtype: Dtype::U8,
        shape: &[u(k::PLANE_ROWS), 34],
        doc: "rows of 34 tile types; see the plane rows",
        flag: false,
    },
    Field {
        name: "scalars",
        offset: PLANE_BYTES,
        dtype: Dtype::I16,
        shape: &[u(k::SCALARS)],
        doc: "see the scalars",
        flag: false,
    },
];

/// The fields of [`Form::Packed`](crate::observe::Form::Packed).
pub static PACKED_FIELDS: [Field; 3] = [
    Field {
        name: "bits",
        offset: 0,
        dtype: Dtype::U64,
        shape: &[u(k::PACKED_BITS)],
        doc:
            "the planes' yes/no rows, bit t of each for tile type t (34 bits used); see the plane rows' `packed` column",
        flag: false,
    },
    Field {
        name: "counts",
        offset: u(k::PACKED_BITS) * 8,
        dtype: Dtype::U8,
        shape: &[u(k::PACKED_COUNTS), 34],
        doc: "the planes' other rows (counts, turn numbers), as in the planes; see the plane rows' `packed` column",
        flag: false,
    },
    Field {
        name: "scalars",
        offset: u(k::PACKED_BITS) * 8 + u(k::PACKED_COUNTS) * 34,
        dtype: Dtype::I16,
        shape: &[u(k::SCALARS)],
        doc: "see the scalars (same as the planes form)",
        flag: false,
    },
];

/// The fields of [`Form::Tokens`](crate::observe::Form::Tokens).
pub static TOKENS_FIELDS: [Field; 10] = [
    Field {
        name: "hand",
        offset: u(k::T_HAND),
        dtype: Dtype::U8,
        shape: &[34],
        doc: "own concealed tiles, count per type (red fives counted as fives)",
        flag: false,
    },
    Field {
        name: "hand_red",
        offset: u(k::T_HAND_RED),
        dtype: Dtype::U8,
        shape: &[3],
        doc: "own concealed red 5m, 5p, 5s (0/1)",
        flag: true,
    },
    Field {
        name: "drawn",
        offset: u(k::T_DRAWN),
        dtype: Dtype::I8,
        shape: &[],
        doc: "the tile the observer just drew (0..36), when it is deciding its turn; -1 otherwise",
        flag: false,
    },
    Field {
        name: "target",
        offset: u(k::T_TARGET),
        dtype: Dtype::I8,
        shape: &[],
        doc: "the tile (0..36) of the discard (or the kan, at a chankan prompt) the observer is asked to claim; -1 otherwise",
        flag: false,
    },
    Field {
        name: "events_len",
        offset: u(k::T_EVENTS_LEN),
        dtype: Dtype::U8,
        shape: &[],
        doc: "number of valid rows of `events`",
        flag: false,
    },
    Field {
        name: "melds",
        offset: u(k::T_MELDS),
        dtype: Dtype::I8,
        shape: &[4, 4, 4],
        doc: "ego seat x meld slot x [kind (0 chi, 1 pon, 2 open kan, 3 closed kan, 4 added kan), lowest tile type, red fives in it, called from (ego seat relative to the meld's owner: 1 right, 2 across, 3 left; -1 closed kan)]; all -1 for an empty slot",
        flag: false,
    },
    Field {
        name: "dora_indicators",
        offset: u(k::T_DORA),
        dtype: Dtype::I8,
        shape: &[5],
        doc: "revealed dora indicators in order (0..36), -1 for those not revealed",
        flag: false,
    },
    Field {
        name: "tiles_seen",
        offset: u(k::T_SEEN),
        dtype: Dtype::U8,
        shape: &[34],
        doc: "copies of each type the observer can see: own hand, rivers, melds, indicators, Norths set aside (0..4)",
        flag: false,
    },
    Field {
        name: "scalars",
        offset: u(k::T_SCALARS),
        dtype: Dtype::I16,
        shape: &[u(k::SCALARS)],
        doc: "see the scalars (same as the planes form)",
        flag: false,
    },
    Field {
        name: "events",
        offset: u(k::T_EVENTS),
        dtype: Dtype::I8,
        shape: &[u(k::TOKEN_EVENTS), 4],
        doc: "this round's public events in order, one row each: [kind, actor (ego seat), tile (0..36, -1 none or hidden), flags]; rows past `events_len` are 0. See the event kinds",
        flag: false,
    },
];

const fn field(name: &'static str, offset: u32, dtype: Dtype, shape: &'static [usize], doc: &'static str) -> Field {
    Field {
        name,
        offset: offset as usize,
        dtype,
        shape,
        doc,
        flag: false,
    }
}

/// A [`field`] of yes/no flags.
const fn flags(name: &'static str, offset: u32, shape: &'static [usize], doc: &'static str) -> Field {
    Field {
        flag: true,
        ..field(name, offset, Dtype::U8, shape, doc)
    }
}

/// The fields of [`Form::Analysis`](crate::observe::Form::Analysis).
pub static ANALYSIS_FIELDS: [Field; 4] = [
    field(
        "discard_shanten",
        k::A_DISCARD_SHANTEN,
        Dtype::I8,
        &[34],
        "at a turn (3k+2 tiles): shanten after discarding one of the type; -1 where the type is not held or at a claim",
    ),
    field(
        "discard_ukeire",
        k::A_DISCARD_UKEIRE,
        Dtype::U8,
        &[34],
        "at a turn: unseen copies of the tiles that would lower that shanten (0..136)",
    ),
    field(
        "waits",
        k::A_WAITS,
        Dtype::U8,
        &[34],
        "tiles completing the observer's 13-tile hand (as the planes' waits row)",
    ),
    field(
        "improving",
        k::A_IMPROVING,
        Dtype::U8,
        &[34],
        "with 3k+1 tiles (waiting for a draw or a claim): unseen copies of each type that would lower the shanten",
    ),
];

/// The fields of [`Form::Oracle`](crate::observe::Form::Oracle).
pub static ORACLE_FIELDS: [Field; 9] = [
    field(
        "others_hand",
        k::O_HANDS,
        Dtype::U8,
        &[3, 34],
        "concealed counts of the right, across and left seats",
    ),
    field(
        "others_red",
        k::O_RED,
        Dtype::U8,
        &[3, 3],
        "their concealed red 5m, 5p, 5s",
    ),
    field("others_shanten", k::O_SHANTEN, Dtype::I8, &[3], "their exact shanten"),
    flags("others_furiten", k::O_FURITEN, &[3], "whether each is furiten"),
    field(
        "others_waits",
        k::O_WAITS,
        Dtype::U8,
        &[3, 34],
        "tiles completing each one's 13-tile hand",
    ),
    field(
        "wall",
        k::O_WALL,
        Dtype::I8,
        &[70],
        "the live wall in draw order (tile values); -1 once drawn or given to the dead wall by a kan",
    ),
    field(
        "rinshan",
        k::O_RINSHAN,
        Dtype::I8,
        &[4],
        "the replacement tiles in order; -1 once drawn",
    ),
    field(
        "dora_indicators",
        k::O_DORA,
        Dtype::I8,
        &[5],
        "all five dora indicator positions, revealed or not",
    ),
    field(
        "ura_indicators",
        k::O_URA,
        Dtype::I8,
        &[5],
        "the five ura dora indicators",
    ),
];

/// One row (or block of rows) of the planes, with its scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rows {
    /// First row.
    pub row: u32,
    /// Rows in the block.
    pub count: u32,
    /// Name of the row (or block).
    pub name: &'static str,
    /// Largest value a cell takes (divide by it to scale to 0..1).
    pub max: u32,
    /// What a cell holds.
    pub doc: &'static str,
}

const fn rows(row: u32, count: u32, name: &'static str, max: u32, doc: &'static str) -> Rows {
    Rows {
        row,
        count,
        name,
        max,
        doc,
    }
}

/// The rows of `planes` before the per-seat block, in order.
pub static PLANE_ROWS: [Rows; 17] = [
    rows(
        k::P_HAND,
        4,
        "hand",
        1,
        "own concealed hand, thermometer: row k is 1 where the count is > k",
    ),
    rows(k::P_RED, 1, "red", 1, "own concealed red five, at its type's column"),
    rows(
        k::P_DRAWN,
        1,
        "drawn",
        1,
        "the tile just drawn, when the observer decides its turn",
    ),
    rows(
        k::P_TARGET,
        1,
        "target",
        1,
        "the tile the observer is asked to claim (a discard, or a kan's tile at a chankan prompt)",
    ),
    rows(
        k::P_WAITS,
        1,
        "waits",
        1,
        "tiles that complete the observer's 13-tile hand (none right after a call)",
    ),
    rows(
        k::P_LEGAL_DISCARD,
        1,
        "legal_discard",
        1,
        "types the observer may discard now (kuikae and riichi applied)",
    ),
    rows(
        k::P_CHI_LOW,
        1,
        "chi_low",
        1,
        "at the target: a chi with it as the lowest tile is legal",
    ),
    rows(
        k::P_CHI_MIDDLE,
        1,
        "chi_middle",
        1,
        "at the target: a chi with it as the middle tile is legal",
    ),
    rows(
        k::P_CHI_HIGH,
        1,
        "chi_high",
        1,
        "at the target: a chi with it as the highest tile is legal",
    ),
    rows(k::P_PON, 1, "pon", 1, "at the target: pon is legal"),
    rows(k::P_OPEN_KAN, 1, "open_kan", 1, "at the target: an open kan is legal"),
    rows(k::P_SELF_KAN, 1, "self_kan", 1, "types of a legal closed or added kan"),
    rows(
        k::P_YAKUHAI,
        1,
        "yakuhai",
        2,
        "han a triplet of the type is worth as yakuhai for the observer (dragons, round and seat wind)",
    ),
    rows(
        k::P_DORA_INDICATORS,
        1,
        "dora_indicators",
        4,
        "revealed dora indicators of the type",
    ),
    rows(
        k::P_DORA,
        1,
        "dora",
        4,
        "dora per copy of the type (han each copy adds)",
    ),
    rows(
        k::P_SEEN,
        1,
        "seen",
        4,
        "copies the observer can see: own hand, rivers, melds, indicators, Norths set aside",
    ),
    rows(
        k::P_RED_SEEN,
        1,
        "red_seen",
        1,
        "the type's red five is visible outside the own hand (river, meld, indicator)",
    ),
];

/// The rows of each seat's block (`P_SEAT + ego_seat * P_SEAT_ROWS + offset`).
pub static SEAT_ROWS: [Rows; 11] = [
    rows(k::P_SEAT_DISCARDED, 1, "discarded", 4, "copies of the type in the seat's river (called ones included)"),
    rows(k::P_SEAT_TEDASHI, 1, "tedashi", 4, "of those, discarded from the hand (not the tile just drawn)"),
    rows(k::P_SEAT_FIRST_TURN, 1, "first_turn", 24, "1-based place in the river of the first copy (0 = none)"),
    rows(k::P_SEAT_LAST_TURN, 1, "last_turn", 24, "1-based place in the river of the last copy (0 = none)"),
    rows(k::P_SEAT_RIICHI_TILE, 1, "riichi_tile", 1, "the tile discarded with the seat's riichi declaration"),
    rows(k::P_SEAT_SAFE, 1, "safe", 1, "genbutsu: a ron on the type by this seat is impossible (its own discards, anything discarded since its last discard or after its riichi)"),
    rows(k::P_SEAT_MELD_TILES, 1, "meld_tiles", 4, "tiles of the type in the seat's melds (three players: and its Norths set aside)"),
    rows(k::P_SEAT_CALLED_IN, 1, "called_in", 1, "types the seat took from another's discard for a meld"),
    rows(k::P_SEAT_CLOSED_KAN, 1, "closed_kan", 1, "types of the seat's closed kans"),
    rows(k::P_SEAT_LAST_DISCARD, 1, "last_discard", 1, "the seat's latest discard"),
    rows(k::P_SEAT_CALLED_AWAY, 1, "called_away", 4, "copies of the type in its river that others called"),
];

/// One scalar (or block of 4, one per ego seat).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Scalar {
    /// Index in `scalars`.
    pub index: u32,
    /// 4 for a per-ego-seat block, else 1.
    pub count: u32,
    /// Name.
    pub name: &'static str,
    /// What it holds, with its unit.
    pub doc: &'static str,
    /// A yes/no flag (0 or 1), printed as a word in the text form.
    pub flag: bool,
}

const fn sc(index: u32, count: u32, name: &'static str, doc: &'static str) -> Scalar {
    Scalar {
        index,
        count,
        name,
        doc,
        flag: false,
    }
}

/// An [`sc`] that is a yes/no flag.
const fn flag(index: u32, count: u32, name: &'static str, doc: &'static str) -> Scalar {
    Scalar {
        flag: true,
        ..sc(index, count, name, doc)
    }
}

/// The scalars, in order.
pub static SCALARS: [Scalar; 27] = [
    sc(k::S_SCORE, 4, "score", "points / 100, per ego seat"),
    sc(k::S_RANK, 4, "rank", "0 = first, per ego seat (ties to the seat nearer the first dealer)"),
    sc(k::S_ROUND, 1, "round", "0 = East 1, 4 = South 1, 8 = West 1 (three players: 3 = South 1, 6 = West 1)"),
    sc(k::S_ROUND_WIND, 1, "round_wind", "0 E, 1 S, 2 W, 3 N"),
    sc(k::S_SEAT_WIND, 1, "seat_wind", "the observer's wind, 0 E .. 3 N"),
    sc(k::S_DEALER, 1, "dealer", "the dealer's ego seat"),
    sc(k::S_HONBA, 1, "honba", "repeat counters"),
    sc(k::S_STICKS, 1, "sticks", "riichi sticks on the table"),
    sc(k::S_TILES_LEFT, 1, "tiles_left", "live wall tiles left to draw (69 at the dealer's first decision, 54 with three players)"),
    sc(k::S_KANS, 1, "kans", "kans made this round (a kan counts once it stands: not yet at its chankan prompt)"),
    sc(k::S_DORA_REVEALED, 1, "dora_revealed", "dora indicators revealed (1..5)"),
    sc(k::S_RIICHI, 4, "riichi", "per ego seat: 0 none, 1 declared (not yet accepted), 2 accepted, 3 double riichi"),
    flag(k::S_IPPATSU, 4, "ippatsu", "per ego seat: ippatsu still possible (0/1)"),
    flag(k::S_CONCEALED, 4, "concealed", "per ego seat: no open meld (closed kans keep it) (0/1)"),
    sc(k::S_DISCARDS, 4, "discards", "per ego seat: tiles in its river (its turns so far)"),
    sc(k::S_MELDS, 4, "melds", "per ego seat: melds declared"),
    sc(k::S_SHANTEN, 1, "shanten", "the observer's exact shanten (-1 = complete hand)"),
    flag(k::S_FURITEN, 1, "furiten", "the observer is furiten (0/1)"),
    sc(k::S_DECISION, 1, "decision", "what the observer is asked: 0 nothing, 1 its turn, 2 the discard after riichi, 3 a claim on a discard, 4 a claim on a kan's tile (chankan: an added kan, or a closed kan for thirteen orphans where the rules allow it) or on a North set aside (kita, three players: ron only)"),
    sc(k::S_CLAIM_FROM, 1, "claim_from", "ego seat whose tile is claimed (-1 when not a claim)"),
    flag(k::S_FIRST_GO_AROUND, 1, "first_go_around", "no call or kan yet this round (0/1)"),
    sc(k::S_MODE, 1, "mode", "0 single hand, 1 east, 2 half (east + south)"),
    sc(k::S_ROUNDS_LEFT, 1, "rounds_left", "planned last round minus this round (negative in an extension)"),
    sc(k::S_OWN_DORA, 1, "own_dora", "dora and red fives in the observer's hand and melds, and its Norths set aside (three players; revealed indicators)"),
    sc(k::S_OWN_RED, 1, "own_red", "red fives in the observer's hand and melds"),
    sc(k::S_EVENTS, 1, "events", "public events logged this round (without draws)"),
    sc(k::S_RESERVED, 1, "reserved", "always 0, kept for a later field"),
];

/// The `kind` of a row of the tokens' `events`, with its flags.
pub static EVENT_KINDS: [(u32, &str, &str); 11] = [
    (k::EV_DRAW, "draw", "tile shown to the drawer only"),
    (k::EV_DISCARD, "discard", "flags: 1 tsumogiri, 2 riichi declaration tile, 4 later called"),
    (k::EV_CHI, "chi", "tile: the called tile; flags: its place in the run (0 lowest, 1 middle, 2 highest) + 4 with a red five from the hand"),
    (k::EV_PON, "pon", "tile: the called tile; flags: 4 with a red five from the hand"),
    (k::EV_OPEN_KAN, "open_kan", "tile: the called tile; flags: 4 with a red five from the hand"),
    (k::EV_CLOSED_KAN, "closed_kan", "tile: its type; flags: 4 with a red five"),
    (k::EV_ADDED_KAN, "added_kan", "tile: the tile added; flags: 4 when it is a red five"),
    (k::EV_RIICHI, "riichi", "declared (the next discard is its tile)"),
    (k::EV_RIICHI_ACCEPTED, "riichi_accepted", "the stick is paid"),
    (k::EV_DORA, "dora", "tile: the new indicator"),
    (k::EV_KITA, "kita", "three players: a North set aside (tile: North); a replacement draw follows"),
];
