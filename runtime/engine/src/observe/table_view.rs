//! What the table shows, kept up to date from the round's log: each seat's rows of the planes
//! (river, melds, the tiles safe against it), the counts of the tiles on the table, and the
//! tokens' event list. An env keeps one [`TableView`] per game; each observation in the planes,
//! the packed planes or the tokens reads only the log entries logged since the last one, then
//! copies the four seats' rows and rotates the event list to the observer's seats. Without it every
//! observation rescanned the whole round (`view_seat_planes`, `log_sets`, `table_tiles` and
//! `view_events` of `rules/kernel/view.rs`, which the GPU still runs, and which the tests below
//! hold this to).
//!
//! A view keeps the parts its forms read ([`SEAT_ROWS`] for the planes and packed planes,
//! [`EVENT_LIST`] for the tokens; the tile counts always): an env observed in the tokens alone does
//! not keep the seat blocks up to date at every discard. A form that needs a part the view has not
//! kept makes it read the round again, keeping that part too from then on.
//!
//! A view is a function of the log entries it has read and nothing else. Before reading on, it
//! checks that the state's log still begins with those entries (a new round, a new game, a
//! loaded snapshot or a forced deal all change them) and starts over where it does not, so no
//! caller has to tell it when a game changed.

use crate::generated::kernel as k;
// Where a four-player round's draws come from (every four-player variant's layout is red's):
// the views follow four-player games only, three players' observations are the kernel's own
// (`observe_cpu`).
use crate::generated::red::{WALL_LIVE_START, WALL_RINSHAN};

// The planes are written as bytes into the kernel's `u32` words: cell `i` is byte `i % 4` of word
// `i / 4` counting from the least significant, which is its address only on little-endian hosts.
const _: () = assert!(
    cfg!(target_endian = "little"),
    "the planes' byte layout assumes a little-endian host"
);

const TYPES: usize = 34;
/// The counts by type as the kernel's cells, four to a word.
const SEEN_BYTES: usize = TYPES.next_multiple_of(4);
/// Bytes of one seat block (rows `P_SEAT_*` of one seat).
const BLOCK: usize = k::P_SEAT_ROWS as usize * TYPES;
/// Discards a river holds (`GameState.rivers`: 24 per seat); later ones are not in it.
const RIVER: usize = 24;
/// Log words (two entries each).
const LOG_WORDS: usize = 60;
/// Event tokens the tokens' list holds.
const EVENTS: usize = k::TOKEN_EVENTS as usize;
/// The words of the planes before the first seat block and from the dora indicators on: 34-cell
/// rows start on word boundaries every two rows, so the blocks fill whole words.
const SEATS_FROM: usize = k::P_SEAT as usize * TYPES / 4;
const SEATS_TO: usize = k::P_DORA_INDICATORS as usize * TYPES / 4;

/// A seat block's rows of counts and turn numbers (bytes in the packed form too).
const COUNT_ROWS: [u32; 6] = [
    k::P_SEAT_DISCARDED,
    k::P_SEAT_TEDASHI,
    k::P_SEAT_FIRST_TURN,
    k::P_SEAT_LAST_TURN,
    k::P_SEAT_MELD_TILES,
    k::P_SEAT_CALLED_AWAY,
];

/// The seat blocks and the sets they are written from (the planes' and the packed planes' part).
pub(crate) const SEAT_ROWS: u8 = 1;
/// The tokens' event list.
pub(crate) const EVENT_LIST: u8 = 2;

const fn row(r: u32) -> usize {
    r as usize * TYPES
}

/// The kernel's `packed_seat_index` of every ego seat and seat block row, computed once: the
/// kernel counts the rows before it at each call.
static PACKED_SEAT_INDEX: std::sync::LazyLock<[[usize; k::P_SEAT_ROWS as usize]; 4]> = std::sync::LazyLock::new(|| {
    std::array::from_fn(|j| std::array::from_fn(|r| k::packed_seat_index(j as u32, r as u32) as usize))
});

/// Writes a 34-bit set as a yes/no row of 34 cells (the kernel's cells of the set, four to a
/// word, low byte first).
fn put_set(cells: &mut [u8], set: u64) {
    let words = k::set_cells([set as u32, (set >> 32) as u32]);
    for (four, word) in cells[..TYPES].chunks_mut(4).zip(words) {
        four.copy_from_slice(&word.to_le_bytes()[..four.len()]);
    }
}

/// What the table shows, as of the first `read` entries of a round's log.
#[derive(Clone)]
pub(crate) struct TableView {
    /// The log's words as last read: the first `read` entries are what this view is made of.
    log: [u32; LOG_WORDS],
    read: u32,
    /// The parts kept ([`SEAT_ROWS`], [`EVENT_LIST`]).
    parts: u8,
    /// Each seat's block of the planes (rows `P_SEAT_*`, bytes), by absolute seat: its rows of
    /// counts and turn numbers ([`COUNT_ROWS`]), and its yes/no rows, kept equal to the sets below
    /// (`seat_sets`) as they change. An observation copies four blocks.
    blocks: [[u8; BLOCK]; 4],
    /// Each river's last entry as the state holds it (a tile value), the entries called away (a
    /// bit each), and its length.
    last_values: [u8; 4],
    called: [u32; 4],
    river_lens: [u8; 4],
    /// The seat of the last discard (a call takes it).
    last_discarder: u8,
    /// Tile sets (bit t = type t): each seat's own discards, what was discarded since its last
    /// discard, and since its riichi declaration (seats in `riichi`).
    own: [u64; 4],
    since: [u64; 4],
    after_riichi: [u64; 4],
    riichi: u8,
    /// Each seat's yes/no rows but the safe tiles, as sets (the packed form's bits).
    riichi_tiles: [u64; 4],
    called_in: [u64; 4],
    closed_kans: [u64; 4],
    /// Counts by type of the river tiles not called away and of the melds' tiles, padded with
    /// zeros to the kernel's nine words of cells ([`TableView::tiles`] copies them whole).
    seen: [u8; SEEN_BYTES],
    /// Red fives by suit: in rivers and not called away (a count), and in any meld (a bit).
    red_in_rivers: [u8; 3],
    red_in_melds: u32,
    /// The tokens' event list with absolute seats, `events_len` of them, each draw's tile hidden
    /// (`NO_TILE_BYTE`). A draw's tile is shown to its drawer only, so it is read from the wall
    /// when written: `draw_at` holds the wall position of each draw token, and `draws_of` which
    /// tokens are each seat's draws (a bit per token). The wall positions are counted as the
    /// kernel's `view_events` counts them, as is the token of the last discard, which a call marks.
    events: [u32; EVENTS],
    events_len: u32,
    draw_at: [u8; EVENTS],
    draws_of: [[u64; EVENTS.div_ceil(64)]; 4],
    live_draws: u32,
    replacement_draws: u32,
    after_kan: bool,
    last_discard_event: Option<u32>,
}

impl Default for TableView {
    fn default() -> TableView {
        TableView {
            log: [0; LOG_WORDS],
            read: 0,
            parts: 0,
            blocks: [[0; BLOCK]; 4],
            last_values: [0; 4],
            called: [0; 4],
            river_lens: [0; 4],
            last_discarder: 0,
            own: [0; 4],
            since: [0; 4],
            after_riichi: [0; 4],
            riichi: 0,
            riichi_tiles: [0; 4],
            called_in: [0; 4],
            closed_kans: [0; 4],
            seen: [0; SEEN_BYTES],
            red_in_rivers: [0; 3],
            red_in_melds: 0,
            events: [0; EVENTS],
            events_len: 0,
            draw_at: [0; EVENTS],
            draws_of: [[0; EVENTS.div_ceil(64)]; 4],
            live_draws: 0,
            replacement_draws: 0,
            after_kan: false,
            last_discard_event: None,
        }
    }
}

fn entry_of(log: &[u32; LOG_WORDS], i: u32) -> u32 {
    (log[(i / 2) as usize] >> ((i % 2) * 16)) & 0xffff
}

impl TableView {
    /// Brings the view up to `s`'s log, with the `parts` a form reads among those it keeps: reads
    /// the entries logged since the last call, or every entry where `s` is not the round this view
    /// has read or a part was not kept.
    pub(crate) fn follow(&mut self, s: &k::GameState, parts: u8) {
        if parts & !self.parts != 0 {
            *self = TableView {
                parts: self.parts | parts,
                ..TableView::default()
            };
        }
        let n = (s.log_len & k::LOG_LEN_MASK).min(k::LOG_CAPACITY);
        // The log's words this view holds from here on (a word half read is read again).
        let mut from = (self.read / 2) as usize;
        if n < self.read || self.log[..from] != s.log[..from] || !self.continued_by(s, from) {
            if n < self.read || !self.continued_by(s, 0) {
                *self = TableView {
                    parts: self.parts,
                    ..TableView::default()
                };
            }
            from = 0;
        }
        for i in self.read..n {
            self.read_entry(entry_of(&s.log, i));
        }
        let to = n.div_ceil(2) as usize;
        self.log[from..to].copy_from_slice(&s.log[from..to]);
        self.read = n;
    }

    /// Whether `s`'s log, from word `from` on, continues the entries this view has read. The one
    /// change the game makes to an entry once logged, marking the last discard as called, is
    /// allowed: that discard's call is then among the entries still to read.
    fn continued_by(&self, s: &k::GameState, from: usize) -> bool {
        let whole = (self.read / 2) as usize;
        let called = k::LOG_CALLED << 12;
        for w in from..whole + (self.read % 2) as usize {
            let mut diff = self.log[w] ^ s.log[w];
            if w == whole {
                diff &= 0xffff;
            }
            for half in 0..2 {
                let d = (diff >> (16 * half)) & 0xffff;
                if d == 0 {
                    continue;
                }
                let e = (self.log[w] >> (16 * half)) & 0xffff;
                if d != called || k::log_kind(e) != k::EV_DISCARD {
                    return false;
                }
            }
        }
        true
    }

    fn read_entry(&mut self, e: u32) {
        let a = k::log_actor(e) as usize;
        let v = k::log_tile(e);
        let f = k::log_flags(e);
        let kind = k::log_kind(e);
        if self.parts & EVENT_LIST != 0 {
            self.add_events(kind, a as u32, v, f);
        }
        // Only the entries the view reads carry tiles; a game never logs a value past the red
        // fives, and a state that does (none loads: saved states are checked) is left unread.
        if v > 36 && kind != k::EV_RIICHI {
            return;
        }
        let rows = self.parts & SEAT_ROWS != 0;
        match kind {
            k::EV_DISCARD => self.discard(a, v, f, rows),
            kind @ (k::EV_CHI | k::EV_PON | k::EV_OPEN_KAN) => self.call(a, kind, v, f, rows),
            k::EV_CLOSED_KAN => {
                let t = k::value_type(v) as usize;
                self.meld_tiles(a, t, 4);
                if rows {
                    self.closed_kans[a] |= 1 << t;
                    self.blocks[a][row(k::P_SEAT_CLOSED_KAN) + t] = 1;
                }
                self.red_meld(t, (f & k::LOG_WITH_RED) != 0);
            }
            k::EV_ADDED_KAN => {
                let t = k::value_type(v) as usize;
                self.meld_tiles(a, t, 1);
                self.red_meld(t, v >= 34);
            }
            k::EV_RIICHI if rows => {
                self.riichi |= 1 << a;
                self.after_riichi[a] = 0;
                self.put_row(a, k::P_SEAT_SAFE, self.safe(a));
            }
            _ => {}
        }
    }

    /// The tokens of one entry: the draw before it, if any, then the entry.
    fn add_events(&mut self, kind: u32, a: u32, v: u32, f: u32) {
        if (f & k::LOG_DREW) != 0 {
            let at = if self.after_kan {
                self.replacement_draws += 1;
                WALL_RINSHAN + self.replacement_draws - 1
            } else {
                self.live_draws += 1;
                WALL_LIVE_START + self.live_draws - 1
            };
            let i = self.events_len as usize;
            if i < EVENTS {
                self.draw_at[i] = (at & 255) as u8;
                self.draws_of[a as usize][i / 64] |= 1 << (i % 64);
            }
            self.add_event(k::event_token(k::EV_DRAW, a, k::NO_TILE_BYTE, 0));
        }
        if matches!(kind, k::EV_CHI | k::EV_PON | k::EV_OPEN_KAN) {
            if let Some(i) = self.last_discard_event {
                self.events[i as usize] |= k::LOG_CALLED << k::TOKEN_FLAGS_SHIFT;
            }
        }
        if kind == k::EV_DISCARD {
            self.last_discard_event = (self.events_len < EVENTS as u32).then_some(self.events_len);
        }
        let tile = if v == k::LOG_NO_TILE { k::NO_TILE_BYTE } else { v };
        self.add_event(k::event_token(kind, a, tile, f & !k::LOG_DREW));
        if kind != k::EV_DORA {
            self.after_kan = matches!(kind, k::EV_OPEN_KAN | k::EV_CLOSED_KAN | k::EV_ADDED_KAN);
        }
    }

    fn add_event(&mut self, token: u32) {
        if let Some(slot) = self.events.get_mut(self.events_len as usize) {
            *slot = token;
            self.events_len += 1;
        }
    }

    /// A discard: the river and the tile counts, and with `rows` the seat blocks and safe tiles.
    fn discard(&mut self, a: usize, v: u32, f: u32, rows: bool) {
        let t = k::value_type(v) as usize;
        self.last_discarder = a as u8;
        if rows {
            self.safe_after_discard(a, t, f);
        }
        let i = self.river_lens[a] as usize;
        if i >= RIVER {
            return;
        }
        if rows {
            self.river_cells(a, t, i, f);
        }
        self.last_values[a] = v as u8;
        self.river_lens[a] += 1;
        self.seen[t] = self.seen[t].wrapping_add(1);
        if v >= 34 {
            self.red_in_rivers[(v - 34) as usize] += 1;
        }
    }

    /// Seat `a`'s river rows after its `i`th discard (from 0), of type `t`: before its river's
    /// last value moves on.
    fn river_cells(&mut self, a: usize, t: usize, i: usize, f: u32) {
        let before = k::value_type(u32::from(self.last_values[a])) as usize;
        let c = &mut self.blocks[a];
        let turn = i as u8 + 1;
        c[row(k::P_SEAT_DISCARDED) + t] += 1;
        c[row(k::P_SEAT_TEDASHI) + t] += u8::from((f & k::LOG_TSUMOGIRI) == 0);
        if c[row(k::P_SEAT_FIRST_TURN) + t] == 0 {
            c[row(k::P_SEAT_FIRST_TURN) + t] = turn;
        }
        c[row(k::P_SEAT_LAST_TURN) + t] = turn;
        // The last discard's row holds one cell: the previous discard's is cleared.
        if i > 0 {
            c[row(k::P_SEAT_LAST_DISCARD) + before] = 0;
        }
        c[row(k::P_SEAT_LAST_DISCARD) + t] = 1;
    }

    /// The tiles safe against each seat after seat `a` discards type `t`, and `a`'s riichi tile.
    fn safe_after_discard(&mut self, a: usize, t: usize, f: u32) {
        let bit = 1u64 << t;
        for q in 0..4 {
            self.since[q] |= bit;
            if (self.riichi >> q) & 1 != 0 {
                self.after_riichi[q] |= bit;
            }
        }
        self.since[a] = 0;
        self.own[a] |= bit;
        // Every seat's cell, the discarder's too (a branch on the discarder was mispredicted):
        // its row is then written whole from its set.
        for q in 0..4 {
            self.blocks[q][row(k::P_SEAT_SAFE) + t] = 1;
        }
        self.put_row(a, k::P_SEAT_SAFE, self.safe(a));
        if (f & k::LOG_RIICHI_TILE) != 0 {
            self.riichi_tiles[a] |= bit;
            self.blocks[a][row(k::P_SEAT_RIICHI_TILE) + t] = 1;
        }
    }

    fn call(&mut self, a: usize, kind: u32, v: u32, f: u32, rows: bool) {
        // As the game marks it: the last entry of the discarder's river is called away.
        let from = self.last_discarder as usize;
        let len = self.river_lens[from] as usize;
        if len > 0 && (self.called[from] >> (len - 1)) & 1 == 0 {
            self.called[from] |= 1 << (len - 1);
            let w = u32::from(self.last_values[from]);
            let u = k::value_type(w) as usize;
            if rows {
                let away = &mut self.blocks[from][row(k::P_SEAT_CALLED_AWAY) + u];
                *away = away.wrapping_add(1);
            }
            self.seen[u] = self.seen[u].wrapping_sub(1);
            if w >= 34 {
                self.red_in_rivers[(w - 34) as usize] -= 1;
            }
        }
        let t = k::value_type(v) as usize;
        if rows {
            self.called_in[a] |= 1 << t;
            self.blocks[a][row(k::P_SEAT_CALLED_IN) + t] = 1;
        }
        match kind {
            k::EV_CHI => {
                let low = t.saturating_sub((f & 3) as usize).min(TYPES - 3);
                for u in low..low + 3 {
                    self.meld_tiles(a, u, 1);
                }
            }
            k::EV_PON => self.meld_tiles(a, t, 3),
            _ => self.meld_tiles(a, t, 4),
        }
        self.red_meld(t, v >= 34 || (f & k::LOG_WITH_RED) != 0);
    }

    /// Writes yes/no row `r` of seat `q`'s block from its set.
    fn put_row(&mut self, q: usize, r: u32, set: u64) {
        put_set(&mut self.blocks[q][row(r)..row(r + 1)], set);
    }

    fn meld_tiles(&mut self, a: usize, t: usize, n: u8) {
        let cell = &mut self.blocks[a][row(k::P_SEAT_MELD_TILES) + t];
        *cell = cell.wrapping_add(n);
        self.seen[t] = self.seen[t].wrapping_add(n);
    }

    fn red_meld(&mut self, t: usize, red: bool) {
        self.red_in_melds |= u32::from(red) << (t / 9);
    }

    /// The tiles safe against seat `q` (genbutsu, as the kernel's `log_sets` reads them).
    fn safe(&self, q: usize) -> u64 {
        self.own[q] | self.since[q] | self.after_riichi[q]
    }

    /// The tiles on the table, as the kernel's `table_tiles` counts them.
    pub(crate) fn tiles(&self) -> k::TableTiles {
        let mut red_seen = self.red_in_melds;
        for (suit, &n) in self.red_in_rivers.iter().enumerate() {
            red_seen |= u32::from(n > 0) << suit;
        }
        // Whole words, copied as they are. Built from the 34 counts with two zero bytes stored
        // beside them, the last word could not be forwarded from the store buffer to the kernel's
        // load of it, which then waited behind the record's stores (docs/performance-history.md, a seventh pass).
        k::TableTiles {
            seen: bytemuck::cast(self.seen),
            red_seen,
        }
    }

    /// Seat `q`'s yes/no rows, as sets, with their seat block rows.
    fn seat_sets(&self, q: usize) -> [(u32, u64); 5] {
        let len = self.river_lens[q];
        let last = match len {
            0 => 0,
            _ => 1u64 << k::value_type(u32::from(self.last_values[q])),
        };
        [
            (k::P_SEAT_RIICHI_TILE, self.riichi_tiles[q]),
            (k::P_SEAT_SAFE, self.safe(q)),
            (k::P_SEAT_CALLED_IN, self.called_in[q]),
            (k::P_SEAT_CLOSED_KAN, self.closed_kans[q]),
            (k::P_SEAT_LAST_DISCARD, last),
        ]
    }

    /// Writes the four seat blocks of `observer`'s planes (ego seat j is absolute seat
    /// `observer + j`) and zeroes the planes' other rows.
    pub(crate) fn write_seats(&self, observer: u32, o: &mut k::ObsPlanes) {
        o.planes[..SEATS_FROM].fill(0);
        o.planes[SEATS_TO..].fill(0);
        let cells: &mut [u8] = bytemuck::cast_slice_mut(&mut o.planes[SEATS_FROM..SEATS_TO]);
        for (j, block) in cells.chunks_exact_mut(BLOCK).enumerate() {
            block.copy_from_slice(&self.blocks[(observer as usize + j) % 4]);
        }
    }

    /// Writes `observer`'s event tokens and their count into a record whose events are zero:
    /// seats ego-centric, a draw's tile shown to its drawer only, and the draw of the player to
    /// move last (not logged until that player acts).
    pub(crate) fn write_events(&self, s: &mut k::GameState, observer: u32, o: &mut k::ObsTokens) {
        let base = (k::T_EVENTS / 4) as usize;
        let out = &mut o.words[base..base + EVENTS];
        let n = self.events_len as usize;
        // A token's seat byte holds 0..3: adding the rotation there and clearing the byte's bit 2
        // turns seat a into (a - observer) mod 4, with no carry further.
        let observer = observer % 4;
        let turn = ((4 - observer) % 4) << k::TOKEN_SEAT_SHIFT;
        for (slot, &token) in out.iter_mut().zip(&self.events[..n]) {
            *slot = (token + turn) & !(4 << k::TOKEN_SEAT_SHIFT);
        }
        for (w, &bits) in self.draws_of[observer as usize].iter().enumerate() {
            let mut bits = bits;
            while bits != 0 {
                let i = w * 64 + bits.trailing_zeros() as usize;
                bits &= bits - 1;
                let at = u32::from(self.draw_at[i]);
                // A game draws from at most the last wall position; past it only a forged state.
                if at < 136 {
                    out[i] = (out[i] & !(0xff << k::TOKEN_TILE_SHIFT)) | (k::wall_tile(s, at) << k::TOKEN_TILE_SHIFT);
                }
            }
        }
        let mut n = n;
        let pending = (s.log_len & k::LOG_PENDING_DRAW) != 0 && s.phase != k::PHASE_OVER;
        if pending && n < EVENTS {
            let tile = if s.current == observer {
                s.drawn
            } else {
                k::NO_TILE_BYTE
            };
            out[n] = k::event_token(k::EV_DRAW, (s.current + 4 - observer) % 4, tile & 255, 0);
            n += 1;
        }
        let at = k::T_EVENTS_LEN as usize;
        o.words[at / 4] |= (n as u32) << ((at % 4) * 8);
    }

    /// Writes the seat blocks' rows of `observer`'s packed planes into a record it zeroes first.
    pub(crate) fn write_packed_seats(&self, observer: u32, o: &mut k::ObsPacked) {
        o.bits.fill(0);
        o.counts.fill(0);
        let counts: &mut [u8] = bytemuck::cast_slice_mut(&mut o.counts);
        let index = &*PACKED_SEAT_INDEX;
        for j in 0..4u32 {
            let q = (observer + j) as usize % 4;
            for r in COUNT_ROWS {
                let to = index[j as usize][r as usize] * TYPES;
                counts[to..to + TYPES].copy_from_slice(&self.blocks[q][row(r)..row(r + 1)]);
            }
            for (r, set) in self.seat_sets(q) {
                let i = index[j as usize][r as usize] * 2;
                o.bits[i] = set as u32;
                o.bits[i + 1] = (set >> 32) as u32;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::env::{Config, Env, Observer};
    use crate::observe::Form;
    use crate::random::Rng;

    /// The kernel's record of `state` seen by `arg`, rescanning the round: the oracle.
    fn kernel_record(variant: crate::Variant, form: Form, state: &k::GameState, arg: u32) -> Vec<u8> {
        let mut s = *state;
        with_variant!(variant, v => match form {
            Form::Planes => {
                let mut o: k::ObsPlanes = bytemuck::Zeroable::zeroed();
                v::planes_into(&mut s, arg, &mut o);
                bytemuck::bytes_of(&o).to_vec()
            }
            Form::Packed => {
                let mut o: k::ObsPacked = bytemuck::Zeroable::zeroed();
                v::packed_into(&mut s, arg, &mut o);
                bytemuck::bytes_of(&o).to_vec()
            }
            _ => {
                let mut o: k::ObsTokens = bytemuck::Zeroable::zeroed();
                v::tokens_into(&mut s, arg, &mut o);
                bytemuck::bytes_of(&o).to_vec()
            }
        })
    }

    fn first_difference(form: Form, a: &[u8], b: &[u8]) -> String {
        match a.iter().zip(b).position(|(x, y)| x != y) {
            Some(i) => {
                let field = form
                    .fields()
                    .iter()
                    .rev()
                    .find(|f| f.offset <= i)
                    .map_or("?", |f| f.name);
                format!("byte {i} (field {field}): {} against {}", a[i], b[i])
            }
            None => "none".into(),
        }
    }

    /// The forms written from a view.
    const FORMS: [Form; 3] = [Form::Planes, Form::Packed, Form::Tokens];

    /// Random games of every variant, observed in the planes, the packed planes or the tokens (one
    /// view serves all three) by random seats after a random share of the steps, so that a view skips steps,
    /// rounds and whole games between two reads, and once after the states were put back to an
    /// earlier save: every record equals the kernel's.
    #[test]
    fn kept_views_write_the_kernels_records() {
        const BATCH: usize = 48;
        // Three players' observations are the kernel's own: no view to check.
        for &variant in crate::Variant::ALL.iter().filter(|v| v.seats() == 4) {
            let mut config = Config::new(variant, BATCH);
            config.auto_reset = true;
            config.threads = Some(1);
            let mut env = Env::new(config).expect("env");
            env.reset().expect("reset");
            let mut rng = Rng::new(variant as u64 + 11);
            let mut saved = None;
            let mut checked = [0; 3];
            for step in 0..1500 {
                if step == 700 {
                    saved = Some(env.save_states().expect("save"));
                }
                if step == 1100 {
                    env.load_states(saved.as_deref().expect("saved")).expect("load");
                } else {
                    let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
                    env.step(&actions).expect("legal random actions");
                }
                if step % 9 != 0 && !rng.chance(40) && step != 1100 {
                    continue;
                }
                let form = FORMS[rng.below(3) as usize];
                let seats: Vec<u32> = (0..BATCH).map(|_| rng.below(5)).collect();
                let mut out = vec![0u8; BATCH * form.bytes()];
                env.observe_into(form, Observer::Seats(&seats), &mut out)
                    .expect("observe");
                let words = env.states_words().expect("states");
                let states: &[k::GameState] = bytemuck::cast_slice(&words);
                for (i, (state, record)) in states.iter().zip(out.chunks(form.bytes())).enumerate() {
                    let want = kernel_record(variant, form, state, seats[i]);
                    assert!(
                        record == want.as_slice(),
                        "{variant} {form}, step {step}, env {i}, seat {}: {}",
                        seats[i],
                        first_difference(form, record, &want)
                    );
                    checked[FORMS.iter().position(|&f| f == form).unwrap_or(0)] += 1;
                }
            }
            assert!(checked.iter().all(|&n| n > 5_000), "{variant}: {checked:?} records");
        }
    }

    /// Views kept for the tokens alone (which do not keep the seat blocks) write the kernel's
    /// planes once asked for them, mid-round, and views kept for the packed planes the kernel's
    /// tokens.
    #[test]
    fn a_view_takes_on_the_part_a_new_form_reads() {
        const BATCH: usize = 16;
        for (first, then) in [(Form::Tokens, Form::Planes), (Form::Packed, Form::Tokens)] {
            let mut env = Env::new(Config::new(crate::Variant::Red, BATCH)).expect("env");
            env.reset().expect("reset");
            let mut rng = Rng::new(3);
            for step in 0..400 {
                let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
                env.step(&actions).expect("legal random actions");
                let form = if step < 300 { first } else { then };
                let out = env.observe(form, Observer::Current).expect("observe").to_vec();
                let words = env.states_words().expect("states");
                let states: &[k::GameState] = bytemuck::cast_slice(&words);
                for (i, (state, record)) in states.iter().zip(out.chunks(form.bytes())).enumerate() {
                    let want = kernel_record(crate::Variant::Red, form, state, k::OBSERVE_CURRENT);
                    assert!(
                        record == want.as_slice(),
                        "{form} after {first}, step {step}, env {i}: {}",
                        first_difference(form, record, &want)
                    );
                }
            }
        }
    }

    /// The view's split of a seat block into rows of counts (bytes) and yes/no rows (sets) is the
    /// kernel's (`plane_row_binary`), row for row.
    #[test]
    fn count_rows_are_the_kernels_rows_of_counts() {
        let view = TableView::default();
        let sets: Vec<u32> = view.seat_sets(0).iter().map(|&(r, _)| r).collect();
        for r in 0..k::P_SEAT_ROWS {
            let binary = k::plane_row_binary(k::P_SEAT + r);
            assert_eq!(COUNT_ROWS.contains(&r), !binary, "seat row {r}");
            assert_eq!(sets.contains(&r), binary, "seat row {r}");
        }
    }

    /// A record of one position (no view kept) is the kernel's too.
    #[test]
    fn a_fresh_view_writes_the_kernels_records() {
        let mut env = Env::new(Config::new(crate::Variant::Red, 8)).expect("env");
        env.reset().expect("reset");
        let mut rng = Rng::new(5);
        for _ in 0..300 {
            let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
            env.step(&actions).expect("legal random actions");
            let words = env.states_words().expect("states");
            let states: &[k::GameState] = bytemuck::cast_slice(&words);
            for state in states {
                let seat = rng.below(5);
                for form in FORMS {
                    let got = crate::observe::record(crate::Variant::Red, form, state, seat);
                    assert_eq!(got, kernel_record(crate::Variant::Red, form, state, seat), "{form}");
                }
            }
        }
    }
}
