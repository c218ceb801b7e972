// The state of one game as plain data (Pgx style): every field is a 32-bit word so the same struct
// lives in a GPU storage buffer and in a CPU array. Small counts are packed into words; the
// accessors below are the only code that knows the packing.

// Game modes (ResetInput.mode). `pub`: hosts pass them.
pub const MODE_SINGLE: u32 = 0;
pub const MODE_EAST: u32 = 1;
pub const MODE_HALF: u32 = 2;

// What the current player is deciding.
const PHASE_TURN: u32 = 0; // after a draw or a call: discard, tsumo, kan, riichi, kyuushu
pub const PHASE_RIICHI_DISCARD: u32 = 1; // riichi declared: discard a tile that keeps tenpai
pub const PHASE_CLAIM: u32 = 2; // a discard (or an added kan) waits for each claimant's decision
pub const PHASE_OVER: u32 = 3; // the game has ended

// Per-seat flags.
pub const SEAT_RIICHI: u32 = 1; // riichi accepted (stick paid)
const SEAT_DOUBLE_RIICHI: u32 = 2;
const SEAT_IPPATSU: u32 = 4;
const SEAT_RIICHI_PENDING: u32 = 8; // declared; accepted once the declaring discard is not ronned
pub const SEAT_FURITEN_TEMP: u32 = 16; // a winning tile passed by since the last own draw or discard
pub const SEAT_FURITEN_RIICHI: u32 = 32; // a winning tile passed by in riichi: furiten for the rest of the round
const SEAT_NAGASHI: u32 = 64; // every discard so far was a terminal or honor, none called
const SEAT_CONCEALED: u32 = 128; // no open meld
const SEAT_DISCARDED: u32 = 256; // has discarded at least once this round
// North tiles the seat has set aside this round (kita, three players only): a count in 3 bits.
pub const SEAT_KITA_SHIFT: u32 = 16;

pub const NO_TILE_VALUE: u32 = 255;
pub const NO_CHOICE: u32 = 255; // a claimant has not chosen yet (claim_choices)

// Claim options of one seat on a discard (or an added kan).
const CLAIM_RON: u32 = 1;
const CLAIM_PON: u32 = 2;
const CLAIM_PON_RED: u32 = 4;
const CLAIM_KAN: u32 = 8;
const CLAIM_CHI_LEFT: u32 = 16;
const CLAIM_CHI_LEFT_RED: u32 = 32;
const CLAIM_CHI_MIDDLE: u32 = 64;
const CLAIM_CHI_MIDDLE_RED: u32 = 128;
const CLAIM_CHI_RIGHT: u32 = 256;
const CLAIM_CHI_RIGHT_RED: u32 = 512;

// What a step settled (StepView.events). `pub`: hosts read these numbers (rinshan_engine::env::events).
pub const EVENT_RON: u32 = 1;
pub const EVENT_TSUMO: u32 = 2;
pub const EVENT_EXHAUSTIVE_DRAW: u32 = 4;
pub const EVENT_ABORTIVE_DRAW: u32 = 8;
pub const EVENT_GAME_OVER: u32 = 16;
pub const EVENT_NAGASHI: u32 = 32;
// Any of the events of a step that ends a round.
pub const EVENT_ROUND_OVER: u32 = EVENT_RON | EVENT_TSUMO | EVENT_EXHAUSTIVE_DRAW | EVENT_ABORTIVE_DRAW;
// Bits per seat in StepView.ranks.
pub const RANK_SHIFT: u32 = 8;

// How a round ended without a win (GameState.draw_kind, low byte); the tenpai seats follow from
// bit DRAW_TENPAI_SHIFT and, for nagashi, the nagashi seats from bit DRAW_NAGASHI_SHIFT (a bit
// per seat).
pub const DRAW_EXHAUSTIVE: u32 = 1;
pub const DRAW_NAGASHI: u32 = 2;
pub const DRAW_KYUUSHU: u32 = 3;
pub const DRAW_FOUR_RIICHI: u32 = 4;
pub const DRAW_TRIPLE_RON: u32 = 5;
pub const DRAW_FOUR_KANS: u32 = 6;
pub const DRAW_FOUR_WINDS: u32 = 7;
pub const DRAW_KIND_MASK: u32 = 255;
pub const DRAW_TENPAI_SHIFT: u32 = 8;
pub const DRAW_NAGASHI_SHIFT: u32 = 12;

// The two `win_score` words of a winning seat: han | fu | yakuman | concealed, and dora | aka |
// ura, each field WIN_FIELD_MASK wide at its shift. `pub`: hosts unpack them (log replay).
pub const WIN_FIELD_MASK: u32 = 255;
pub const WIN_FU_SHIFT: u32 = 8;
pub const WIN_YAKUMAN_SHIFT: u32 = 16;
pub const WIN_CONCEALED_SHIFT: u32 = 24;
pub const WIN_AKA_SHIFT: u32 = 8;
pub const WIN_URA_SHIFT: u32 = 16;

// The continuations of a step (GameState.task; the passes of game_step.rs): each piece of the
// game that can follow an action runs from one place, so the GPU compiler inlines each heavy
// function once.
const TASK_DONE: u32 = 0;
const TASK_OPEN_CLAIMS: u32 = 1;
const TASK_RESOLVE: u32 = 2;
const TASK_AFTER_DISCARD: u32 = 3;
const TASK_REPLACEMENT: u32 = 4;
const TASK_ABORTIVE: u32 = 5;
const TASK_TSUMO: u32 = 6;
const TASK_END_ROUND: u32 = 7;
// The game ended in this step: with auto-reset the next one starts.
const TASK_NEW_GAME: u32 = 8;
// The step changes nothing more, not even the mask (a finished game; hero mode done).
const TASK_IDLE: u32 = 9;
// End-of-round arguments (GameState.task_flags).
const END_DEALER_CONTINUES: u32 = 1;
const END_DRAWN: u32 = 2;
const END_ABORTIVE: u32 = 4;

// GameState.claim_kan of a claim window on a North set aside (kita): ron only, not a chankan.
const CLAIM_WINDOW_KITA: u32 = 3;
// TASK_REPLACEMENT's argument (GameState.task_flags): the replacement tile follows a kita, not a kan.
const REPLACE_KITA: u32 = 1;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ResetInput {
    pub seed: [u32; 2],
    // MODE_*
    pub mode: u32,
    // First dealer 0..3, or 4: drawn from the seed.
    pub dealer: u32,
    // 1: deal `wall` instead of shuffling (tests, log replay); the first round only.
    pub use_wall: u32,
    // Tile values in dealing order (see `wall_tile`): 0..33, 34..36 = red 5m 5p 5s; WALL_TILES of
    // them (108 for three players).
    pub wall: [u32; 136],
    // Uma by final rank, in points; paid with the leftover riichi sticks in the last step.
    pub uma: [i32; 4],
    // Reward of the seat that plays an illegal action (the others get 0).
    pub penalty: f32,
    // 1: a finished game is replaced by a new one (next seed) in the same step.
    pub auto_reset: u32,
}

// A deal forced on a game in progress (log replay, tests): the next round is played from this
// table and wall instead of the one the game reached by itself.
#[derive(Clone, Copy)]
#[repr(C)]
pub struct DealInput {
    // 1: deal; 0: leave this game as it is.
    pub deal: u32,
    // Round (0 = East 1, 4 = South 1, ...), dealer seat, honba and riichi sticks on the table.
    pub round: u32,
    pub dealer: u32,
    pub honba: u32,
    pub sticks: u32,
    pub scores: [i32; 4],
    // Tile values in dealing order, as in ResetInput.
    pub wall: [u32; 136],
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct StepView {
    pub current_player: u32,
    // Legal actions as a bitset over the variant's action ids.
    pub mask: [u32; 3],
    // This step's score change per seat in units of 100 points (uma included at the end).
    pub rewards: [f32; 4],
    pub terminated: u32,
    // Always 0: a game always ends by the rules (or an illegal action); kept for the
    // terminated/truncated pair RL APIs expect.
    pub truncated: u32,
    // 1 when this step's action was illegal (the game ended with the penalty).
    pub illegal: u32,
    // What this step settled: EVENT_* bits, the winners (bit per seat), the seat that dealt in + 1
    // (0 = none) and the yaku of the winners' hands (OR of their yaku bitmasks).
    pub events: u32,
    pub winners: u32,
    pub deal_in: u32,
    pub yaku: [u32; 2],
    // Rounds played in this game so far.
    pub rounds: u32,
    // Where the game ended by the rules in this step: each seat's final place (0 = first), a byte
    // per seat, read with RANK_SHIFT; 0 otherwise (an illegal action ends a game unranked).
    pub ranks: u32,
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct GameState {
    pub seed: [u32; 2],
    pub games: u32,
    pub mode: u32,
    pub uma: [i32; 4],
    pub penalty: f32,
    pub auto_reset: u32,
    // Round: 0 = East 1, 4 = South 1, 8 = West 1...
    pub round: u32,
    pub dealer: u32,
    pub honba: u32,
    pub sticks: u32,
    pub scores: [i32; 4],
    // WALL_TILES tile values, 4 per word (8 bits each).
    pub wall: [u32; 34],
    // Index of the next live draw, counting up from WALL_LIVE_START (after the deal).
    pub next_draw: u32,
    // Live draws end before this index; each kan or kita moves it down by one (a replacement tile).
    pub live_end: u32,
    pub kans: u32,
    // Dora indicators revealed (1 + kan dora).
    pub dora_revealed: u32,
    // Kan dora waiting to be revealed (open and added kans reveal after the replacement discard).
    pub dora_pending: u32,
    // Concealed tile counts: 4 bits per type, 8 types per word, 5 words per seat.
    pub hands: [u32; 20],
    // Red fives held: bit seat * 3 + suit.
    pub red: u32,
    // Melds: 4 per seat (`meld_word` with MELD_FROM_SHIFT / MELD_REDS_SHIFT fields); counts 8 bits per seat.
    pub melds: [u32; 16],
    pub meld_counts: u32,
    // Rivers: 24 discards per seat, 8 bits each (value | 64 called | 128 tsumogiri); lengths 8 bits per seat.
    pub rivers: [u32; 24],
    pub river_lens: u32,
    // Tile types each seat has discarded (furiten): 2 words per seat.
    pub discarded: [u32; 8],
    // Each seat's waits (34-bit set, 2 words per seat) for its 13-tile hand, refreshed whenever
    // that hand changes (deal, discard, kan): claims, tsumo checks and tenpai read them.
    pub waits: [u32; 8],
    pub seat_flags: [u32; 4],
    // Liable seat + 1 for pao, 8 bits per seat: the low nibble for big dragons / big winds, the
    // high one for four kans (PAO_SUUKANTSU); 0 = none.
    pub pao: u32,
    pub phase: u32,
    pub current: u32,
    // Tile drawn this turn (value) or NO_TILE_VALUE; 1 if it came from the dead wall.
    pub drawn: u32,
    pub rinshan: u32,
    // No call, kan or abortive interruption yet this round (double riichi, tenhou, kyuushu...).
    pub uninterrupted: u32,
    // Kuikae: up to two tile types the caller may not discard now, 8 bits each (255 = none).
    pub kuikae: u32,
    // Claim window: the tile (value), who discarded it, whether it is an added kan (chankan).
    pub claim_tile: u32,
    pub claim_from: u32,
    pub claim_kan: u32,
    // Per seat: the claim options offered (CLAIM_* bits) and the action chosen (NO_CHOICE until then).
    pub claim_options: [u32; 4],
    pub claim_choices: [u32; 4],
    // The pending task of a step between its passes (TASK_DONE between steps), and its
    // arguments: a seat, and END_* flags for TASK_END_ROUND.
    pub task: u32,
    pub task_seat: u32,
    pub task_flags: u32,
    // Outputs of the last step (see StepView).
    pub mask: [u32; 3],
    pub rewards: [i32; 4],
    pub terminated: u32,
    pub illegal: u32,
    pub events: u32,
    pub winners: u32,
    pub deal_in: u32,
    pub yaku: [u32; 2],
    pub rounds: u32,
    // Final places of the game that ended in this step (StepView.ranks); set before an
    // auto-reset deals the next game, which is why the view cannot recompute them.
    pub ranks: u32,
    pub steps: u32,
    // What the last settlement scored, per winning seat (valid for the seats in `winners`): the
    // yaku bits (2 words) and the two packed words of WIN_* fields. Written only when a hand
    // wins, so the hot path pays nothing for it; hosts read it (log replay).
    pub win_yaku: [u32; 8],
    pub win_score: [u32; 8],
    // DRAW_* of the last round that ended without a win, with its tenpai / nagashi seats.
    pub draw_kind: u32,
    // The round's public events (game_log.rs): 16 bits each, 2 per word; count and flags.
    pub log: [u32; 60],
    pub log_len: u32,
}

pub fn hand_count(s: &mut GameState, seat: u32, t: u32) -> u32 {
    (s.hands[(seat * 5u32 + t / 8u32) as usize] >> ((t % 8u32) * 4u32)) & 15u32
}

fn hand_add(s: &mut GameState, seat: u32, t: u32) {
    s.hands[(seat * 5u32 + t / 8u32) as usize] += 1u32 << ((t % 8u32) * 4u32);
}

fn hand_remove(s: &mut GameState, seat: u32, t: u32) {
    s.hands[(seat * 5u32 + t / 8u32) as usize] -= 1u32 << ((t % 8u32) * 4u32);
}

// One read of each packed word (not one per tile type).
pub fn hand_counts(s: &mut GameState, seat: u32) -> [u32; 34] {
    let mut c: [u32; 34] = [0u32; 34];
    for w in 0u32..5u32 {
        let word: u32 = s.hands[(seat * 5u32 + w) as usize];
        for i in 0u32..8u32 {
            let t: u32 = w * 8u32 + i;
            if t < 34u32 {
                c[t as usize] = (word >> (i * 4u32)) & 15u32;
            }
        }
    }
    c
}

// Tiles in the seat's concealed hand: the byte sums of its packed words.
fn hand_size(s: &mut GameState, seat: u32) -> u32 {
    let mut n: u32 = 0u32;
    for w in 0u32..5u32 {
        let word: u32 = s.hands[(seat * 5u32 + w) as usize];
        let bytes: u32 = (word & 0x0f0f0f0fu32) + ((word >> 4u32) & 0x0f0f0f0fu32);
        n += bytes.wrapping_mul(0x01010101u32) >> 24u32;
    }
    n
}

// Bits 0, 4, ..., 28 of `x` gathered into bits 0..7.
fn gather_nibble_bits(x: u32) -> u32 {
    let mut y: u32 = (x | (x >> 3u32)) & 0x03030303u32;
    y = (y | (y >> 6u32)) & 0x000f000fu32;
    (y | (y >> 12u32)) & 255u32
}

// The tile types whose count in the seat's hand has one of `bits` set, as a 34-bit set, straight
// from the packed words: counts are at most 4, so bits 7 means "held" and bits 4 "all four held".
fn hand_types_with(s: &mut GameState, seat: u32, bits: u32) -> [u32; 2] {
    let mut set: [u32; 2] = [0u32; 2];
    let mut masked: [u32; 5] = [0u32; 5];
    let mut any: u32 = 0u32;
    for w in 0u32..5u32 {
        masked[w as usize] = s.hands[(seat * 5u32 + w) as usize] & (bits * 0x11111111u32);
        any |= masked[w as usize];
    }
    // Most hands hold no four of a kind: settled before the bits are gathered.
    if any == 0u32 {
        return set;
    }
    for w in 0u32..5u32 {
        let x: u32 = masked[w as usize];
        let g: u32 = gather_nibble_bits((x | (x >> 1u32) | (x >> 2u32)) & 0x11111111u32);
        if w < 4u32 {
            set[0] |= g << (w * 8u32);
        } else {
            set[1] = g;
        }
    }
    set
}

// Single tiles with no other tile of their suit within two steps (any single honor): tiles that
// no set or partial set of the hand can use; and the kinds of terminals and honors held (thirteen
// orphans). One pass over the packed words.
fn isolated_and_orphans(s: &mut GameState, seat: u32) -> [u32; 2] {
    let mut held: [u32; 2] = [0u32; 2];
    let mut single: [u32; 2] = [0u32; 2];
    for w in 0u32..5u32 {
        let word: u32 = s.hands[(seat * 5u32 + w) as usize];
        let h: u32 = gather_nibble_bits((word | (word >> 1u32) | (word >> 2u32)) & 0x11111111u32);
        let one: u32 = gather_nibble_bits(word & !(word >> 1u32) & !(word >> 2u32) & 0x11111111u32);
        if w < 4u32 {
            held[0] |= h << (w * 8u32);
            single[0] |= one << (w * 8u32);
        } else {
            held[1] = h;
            single[1] = one;
        }
    }
    // The suits' tiles held within two steps, the three suits at once: each shift drops the bits it
    // carries from one suit into the next (a suit's first types from the one before, its last from
    // the one after). Any single honor (types 27-31 here) stays isolated.
    let h: u32 = held[0] & 0x07ffffffu32;
    let firsts: u32 = 1u32 | (1u32 << 9u32) | (1u32 << 18u32);
    let lasts: u32 = firsts << 8u32;
    let near: u32 = ((h << 1u32) & !firsts)
        | ((h << 2u32) & !(firsts | (firsts << 1u32)))
        | ((h >> 1u32) & !lasts)
        | ((h >> 2u32) & !(lasts | (lasts >> 1u32)));
    let isolated: u32 = (single[0] & !(near & 0x07ffffffu32)).count_ones() + single[1].count_ones();
    let terminals: u32 = 1u32 | (1u32 << 8u32) | (1u32 << 9u32) | (1u32 << 17u32) | (1u32 << 18u32) | (1u32 << 26u32);
    let orphans: u32 = (held[0] & (terminals | (31u32 << 27u32))).count_ones() + held[1].count_ones();
    [isolated, orphans]
}

pub fn wall_tile(s: &mut GameState, i: u32) -> u32 {
    (s.wall[(i / 4u32) as usize] >> ((i % 4u32) * 8u32)) & 255u32
}

pub fn byte_of(word: u32, i: u32) -> u32 {
    (word >> (i * 8u32)) & 255u32
}

fn with_byte(word: u32, i: u32, v: u32) -> u32 {
    (word & !(255u32 << (i * 8u32))) | ((v & 255u32) << (i * 8u32))
}
