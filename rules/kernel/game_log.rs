// The round's public record: every event the table sees, in order, so that an observation can
// replay the round (token form) and tell which discards are safe against whom (planes form).
// Draws are not entries of their own: the first event a seat logs after drawing carries
// LOG_DREW, and the drawn tile is read back from the wall position when the observer is the
// drawer (a live draw is the next live wall tile; the draw after a kan is the next replacement).
// One entry is 16 bits: kind | actor << 4 | tile << 6 | flags << 12. A round logs at most 118
// events: 86 discards (70 draws in all, replacements included, and 16 chi or pon), 20 calls and
// kans (16 melds, 4 of them possibly added kans), 8 riichi events, 4 kan dora; so 120 entries
// always suffice, and keep the state within 1 KiB.

pub const LOG_CAPACITY: u32 = 120;
// GameState.log_len: the entry count in the low byte; a draw not yet followed by an event.
pub const LOG_LEN_MASK: u32 = 255;
pub const LOG_PENDING_DRAW: u32 = 256;

// Event kinds (also the token form's `kind` byte; 0 = padding, 10 = a draw, token form only).
pub const EV_DISCARD: u32 = 1;
pub const EV_CHI: u32 = 2;
pub const EV_PON: u32 = 3;
pub const EV_OPEN_KAN: u32 = 4;
pub const EV_CLOSED_KAN: u32 = 5;
pub const EV_ADDED_KAN: u32 = 6;
pub const EV_RIICHI: u32 = 7;
pub const EV_RIICHI_ACCEPTED: u32 = 8;
pub const EV_DORA: u32 = 9;
pub const EV_DRAW: u32 = 10;
// North set aside (kita, three players).
pub const EV_KITA: u32 = 11;

// Flags of a discard.
pub const LOG_TSUMOGIRI: u32 = 1;
pub const LOG_RIICHI_TILE: u32 = 2;
pub const LOG_CALLED: u32 = 4;
// Any event: the actor drew just before it.
pub const LOG_DREW: u32 = 8;
// Flags of a chi: the called tile's place in the run (0 lowest, 1 middle, 2 highest); of any
// call or kan: LOG_WITH_RED when a red five from the hand went into it.
pub const LOG_WITH_RED: u32 = 4;

pub const LOG_NO_TILE: u32 = 63;

pub fn log_entry(s: &mut GameState, i: u32) -> u32 {
    (s.log[(i / 2u32) as usize] >> ((i % 2u32) * 16u32)) & 65535u32
}

pub fn log_kind(e: u32) -> u32 {
    e & 15u32
}

pub fn log_actor(e: u32) -> u32 {
    (e >> 4u32) & 3u32
}

pub fn log_tile(e: u32) -> u32 {
    (e >> 6u32) & 63u32
}

pub fn log_flags(e: u32) -> u32 {
    (e >> 12u32) & 15u32
}

pub fn log_count(s: &mut GameState) -> u32 {
    s.log_len & LOG_LEN_MASK
}

fn log_clear(s: &mut GameState) {
    s.log = [0u32; 60];
    s.log_len = 0u32;
}

fn log_push(s: &mut GameState, kind: u32, actor: u32, tile: u32, flags: u32) {
    let n: u32 = s.log_len & LOG_LEN_MASK;
    let mut f: u32 = flags;
    if (s.log_len & LOG_PENDING_DRAW) != 0u32 && actor == s.current && kind != EV_DORA {
        f |= LOG_DREW;
        s.log_len &= !LOG_PENDING_DRAW;
    }
    if n < LOG_CAPACITY {
        let e: u32 = kind | (actor << 4u32) | ((tile & 63u32) << 6u32) | ((f & 15u32) << 12u32);
        s.log[(n / 2u32) as usize] |= e << ((n % 2u32) * 16u32);
        s.log_len += 1u32;
    }
}

fn log_draw(s: &mut GameState) {
    s.log_len |= LOG_PENDING_DRAW;
}

// The last discard was called: its entry gets LOG_CALLED.
fn log_mark_called(s: &mut GameState) {
    let mut i: u32 = s.log_len & LOG_LEN_MASK;
    while i > 0u32 {
        i -= 1u32;
        if log_kind(log_entry(s, i)) == EV_DISCARD {
            s.log[(i / 2u32) as usize] |= (LOG_CALLED << 12u32) << ((i % 2u32) * 16u32);
            return;
        }
    }
}
