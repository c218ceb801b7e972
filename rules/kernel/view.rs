// What one seat may see of a game: the observation, in two forms read from the same facts.
// Planes (C x 34 bytes, row-major, 4 bytes per word little-endian) for MLP/CNN agents, and tokens
// (hand, melds, dora, the round's public events in order, ...) for Transformers; both carry the
// same scalars. Seats are ego-centric: 0 = the observer, 1 = right, 2 = across, 3 = left.
// Everything here reads only what the observer may know: its own hand, draws and waits, the
// public record, and the decision it is asked for. Other seats' hands, waits, furiten, claim
// options and choices, the wall and the hidden dead wall are never read (a test permutes them).
// Field meanings, scales and dtypes are documented once, on the host (rinshan_engine::observe).

// What the view needs about one observer, gathered once.
#[derive(Clone, Copy)]
struct Seen {
    seat: u32,
    // The rows below are packed cells (`pack_cells`: four types to a word), the form the writers
    // put them in: the hand; counts by type of everything visible to the observer (own hand,
    // rivers not called, melds, indicators); dora multiplicity by type (revealed indicators).
    hand_cells: [u32; 9],
    seen_cells: [u32; 9],
    dora_cells: [u32; 9],
    // Red fives seen outside the own hand, by suit.
    red_seen: u32,
    // The decision asked of the observer (DECISION_*).
    decision: u32,
}

// Seat q as seen from `seat`: 0 itself, 1 the next seat, SEATS - 1 the one before.
fn rel(seat: u32, q: u32) -> u32 {
    (q + SEATS - seat) % SEATS
}

// A seat past the table's (three players) observes as the player to move, as OBSERVE_CURRENT
// does; hosts refuse such seats before they get here.
pub fn observer(s: &mut GameState, arg: u32) -> u32 {
    if arg >= SEATS {
        return s.current;
    }
    arg
}

fn decision_of(s: &mut GameState, seat: u32) -> u32 {
    if s.current != seat {
        return DECISION_NONE;
    }
    if s.phase == PHASE_TURN {
        return DECISION_TURN;
    }
    if s.phase == PHASE_RIICHI_DISCARD {
        return DECISION_RIICHI_DISCARD;
    }
    if s.phase == PHASE_CLAIM {
        if s.claim_kan != 0u32 {
            return DECISION_CHANKAN;
        }
        return DECISION_CLAIM;
    }
    DECISION_NONE
}

fn river_entry(s: &mut GameState, q: u32, i: u32) -> u32 {
    byte_of(s.rivers[(q * 6u32 + i / 4u32) as usize], i % 4u32)
}

fn gather(s: &mut GameState, seat: u32) -> Seen {
    let t: TableTiles = table_tiles(s);
    gather_with(s, seat, t)
}

// The tiles on the table: every river tile not called away (those are counted in the caller's
// meld), every meld's, and the Norths set aside (three players).
fn table_tiles(s: &mut GameState) -> TableTiles {
    let mut seen: [u32; 34] = [0u32; 34];
    let mut red_seen: u32 = 0u32;
    for q in 0u32..4u32 {
        seen[NORTH as usize] += kita_count(s, q);
        for i in 0u32..byte_of(s.river_lens, q) {
            let e: u32 = river_entry(s, q, i);
            let v: u32 = e & 63u32;
            let kept: u32 = 1u32 - ((e >> 6u32) & 1u32);
            seen[value_type(v) as usize] += kept;
            if v >= 34u32 {
                red_seen |= kept << (v - 34u32);
            }
        }
        for i in 0u32..meld_count(s, q) {
            let m: u32 = s.melds[(q * 4u32 + i) as usize];
            meld_types(m, &mut seen);
            if ((m >> MELD_REDS_SHIFT) & 3u32) != 0u32 {
                red_seen |= 1u32 << (meld_tile(m) / 9u32);
            }
        }
    }
    TableTiles {
        seen: pack_cells(seen),
        red_seen: red_seen,
    }
}

// The observer's facts, given the tiles on the table: the indicators and its own hand are added
// here, as packed cells a word of four at a time. Each count stays below 256 in any state (at most
// 160 of a type in the rivers and melds, 15 in a hand's 4 bits, 5 indicators), so no cell carries
// into the next.
fn gather_with(s: &mut GameState, seat: u32, table: TableTiles) -> Seen {
    let hand: [u32; 9] = hand_cells(s, seat);
    let mut seen: [u32; 9] = table.seen;
    let mut red_seen: u32 = table.red_seen;
    let mut dora: [u32; 9] = [0u32; 9];
    for i in 0u32..s.dora_revealed {
        let v: u32 = wall_tile(s, WALL_DORA + i);
        let t: u32 = value_type(v);
        let d: u32 = dora_of(t);
        seen[(t / 4u32) as usize] += cell_one(t);
        dora[(d / 4u32) as usize] += cell_one(d);
        if v >= 34u32 {
            red_seen |= 1u32 << (v - 34u32);
        }
    }
    for j in 0u32..9u32 {
        seen[j as usize] = cells_at_most_4(seen[j as usize] + hand[j as usize]);
    }
    Seen {
        seat: seat,
        hand_cells: hand,
        seen_cells: seen,
        dora_cells: dora,
        red_seen: red_seen,
        decision: decision_of(s, seat),
    }
}

fn put_byte(o: &mut ObsPlanes, i: u32, v: u32) {
    o.planes[(i / 4u32) as usize] |= (v & 255u32) << ((i % 4u32) * 8u32);
}

fn put_tok(o: &mut ObsTokens, i: u32, v: u32) {
    o.words[(i / 4u32) as usize] |= (v & 255u32) << ((i % 4u32) * 8u32);
}

fn put_plane(o: &mut ObsPlanes, row: u32, t: u32, v: u32) {
    put_byte(o, row * 34u32 + t, v);
}

// Adds to a cell that stays below 256 (counts, turn numbers): no carry into the next byte.
fn add_plane(o: &mut ObsPlanes, row: u32, t: u32, v: u32) {
    let i: u32 = row * 34u32 + t;
    o.planes[(i / 4u32) as usize] += v << ((i % 4u32) * 8u32);
}

fn set_plane(o: &mut ObsPlanes, row: u32, t: u32, v: u32) {
    let i: u32 = row * 34u32 + t;
    o.planes[(i / 4u32) as usize] = with_byte(o.planes[(i / 4u32) as usize], i % 4u32, v);
}

fn put_scalar(sc: &mut [u32; 24], i: u32, v: i32) {
    sc[(i / 2u32) as usize] |= ((v as u32) & 65535u32) << ((i % 2u32) * 16u32);
}

// The observer's own waits: those of its 13-tile hand (cached by the engine at each change of
// that hand); none right after a call, when the hand has no 13-tile form yet.
fn own_waits(s: &mut GameState, seat: u32) -> [u32; 2] {
    let after_call: bool = s.current == seat && s.phase == PHASE_TURN && s.drawn == NO_TILE_VALUE;
    if after_call {
        return [0u32; 2];
    }
    [s.waits[(seat * 2u32) as usize], s.waits[(seat * 2u32 + 1u32) as usize]]
}

fn riichi_state(s: &mut GameState, q: u32) -> u32 {
    let f: u32 = s.seat_flags[q as usize];
    if (f & SEAT_DOUBLE_RIICHI) != 0u32 {
        return RIICHI_DOUBLE;
    }
    if (f & SEAT_RIICHI) != 0u32 {
        return RIICHI_ACCEPTED;
    }
    if (f & SEAT_RIICHI_PENDING) != 0u32 {
        return RIICHI_DECLARED;
    }
    0u32
}

fn view_scalars(s: &mut GameState, v: &mut Seen) -> [u32; 24] {
    let seat: u32 = v.seat;
    let mut sc: [u32; 24] = [0u32; 24];
    let ranks: [u32; 4] = seat_ranks(s);
    for j in 0u32..SEATS {
        let p: u32 = (seat + j) % SEATS;
        let f: u32 = s.seat_flags[p as usize];
        put_scalar(&mut sc, S_SCORE + j, s.scores[p as usize] / 100i32);
        put_scalar(&mut sc, S_RANK + j, ranks[p as usize] as i32);
        put_scalar(&mut sc, S_RIICHI + j, riichi_state(s, p) as i32);
        put_scalar(&mut sc, S_IPPATSU + j, ((f & SEAT_IPPATSU) != 0u32) as i32);
        put_scalar(&mut sc, S_CONCEALED + j, ((f & SEAT_CONCEALED) != 0u32) as i32);
        put_scalar(&mut sc, S_DISCARDS + j, byte_of(s.river_lens, p) as i32);
        put_scalar(&mut sc, S_MELDS + j, meld_count(s, p) as i32);
    }
    put_scalar(&mut sc, S_ROUND, s.round as i32);
    put_scalar(&mut sc, S_ROUND_WIND, round_wind_of(s.round) as i32);
    put_scalar(&mut sc, S_SEAT_WIND, rel(s.dealer, seat) as i32);
    put_scalar(&mut sc, S_DEALER, rel(seat, s.dealer) as i32);
    put_scalar(&mut sc, S_HONBA, s.honba as i32);
    put_scalar(&mut sc, S_STICKS, s.sticks as i32);
    put_scalar(&mut sc, S_TILES_LEFT, (s.live_end - s.next_draw) as i32);
    put_scalar(&mut sc, S_KANS, s.kans as i32);
    put_scalar(&mut sc, S_DORA_REVEALED, s.dora_revealed as i32);
    put_scalar(&mut sc, S_SHANTEN, hand_shanten(s, seat));
    let w: [u32; 2] = own_waits(s, seat);
    let f: u32 = s.seat_flags[seat as usize];
    let furiten_now: bool = (f & (SEAT_FURITEN_TEMP | SEAT_FURITEN_RIICHI)) != 0u32
        || (w[0] & s.discarded[(seat * 2u32) as usize]) != 0u32
        || (w[1] & s.discarded[(seat * 2u32 + 1u32) as usize]) != 0u32;
    put_scalar(&mut sc, S_FURITEN, furiten_now as i32);
    put_scalar(&mut sc, S_DECISION, v.decision as i32);
    let mut from: i32 = -1i32;
    if v.decision == DECISION_CLAIM || v.decision == DECISION_CHANKAN {
        from = rel(seat, s.claim_from) as i32;
    }
    put_scalar(&mut sc, S_CLAIM_FROM, from);
    put_scalar(&mut sc, S_FIRST_GO_AROUND, s.uninterrupted as i32);
    put_scalar(&mut sc, S_MODE, s.mode as i32);
    let mut last: i32 = 0i32;
    if s.mode != MODE_SINGLE {
        last = last_round(s) as i32;
    }
    put_scalar(&mut sc, S_ROUNDS_LEFT, last - (s.round as i32));
    let mut reds: u32 = 0u32;
    for suit in 0u32..3u32 {
        reds += holds_red(s, seat, suit) as u32;
    }
    for i in 0u32..meld_count(s, seat) {
        reds += (s.melds[(seat * 4u32 + i) as usize] >> MELD_REDS_SHIFT) & 3u32;
    }
    // Each indicator counts the seat's copies of its dora: at most five reads, where a count by
    // type would sum 34 products.
    let mut dora: u32 = reds;
    for i in 0u32..s.dora_revealed {
        let d: u32 = dora_of(value_type(wall_tile(s, WALL_DORA + i)));
        dora += own_count(s, seat, d);
    }
    // Each North set aside (three players) is a dora, and one more per indicator showing North.
    dora += kita_count(s, seat) * (1u32 + cell_of(v.dora_cells, NORTH));
    put_scalar(&mut sc, S_OWN_DORA, dora as i32);
    put_scalar(&mut sc, S_OWN_RED, reds as i32);
    put_scalar(&mut sc, S_EVENTS, log_count(s) as i32);
    sc
}

// Copies of type `t` in the seat's hand and melds.
fn own_count(s: &mut GameState, seat: u32, t: u32) -> u32 {
    let mut n: u32 = hand_count(s, seat, t);
    for i in 0u32..meld_count(s, seat) {
        let m: u32 = s.melds[(seat * 4u32 + i) as usize];
        let k: u32 = meld_kind(m);
        let u: u32 = meld_tile(m);
        if k == MELD_CHI {
            n += (t >= u && t <= u + 2u32) as u32;
        } else if k == MELD_PON {
            n += 3u32 * ((t == u) as u32);
        } else {
            n += 4u32 * ((t == u) as u32);
        }
    }
    n
}

fn set_has(set: [u32; 2], t: u32) -> bool {
    ((set[(t / 32u32) as usize] >> (t % 32u32)) & 1u32) != 0u32
}

fn set_add(set: &mut [u32; 2], t: u32) {
    set[(t / 32u32) as usize] |= 1u32 << (t % 32u32);
}

// A type's bit in the low and the high word of a 34-bit set. Sets updated in a loop are kept as
// two words indexed by constants, not as [u32; 2] indexed by `t / 32`: a variable index keeps the
// set in memory, and the CPU then stalls reading a word just written as part of a wider store.
fn bit_lo(t: u32) -> u32 {
    (1u32 << (t % 32u32)) * ((t < 32u32) as u32)
}

fn bit_hi(t: u32) -> u32 {
    (1u32 << (t % 32u32)) * ((t >= 32u32) as u32)
}

// One pass over the round's log, as 34-bit sets by absolute seat q (low word at 2q, high at
// 2q + 1): the tiles safe against each seat (genbutsu: its own discards, anything discarded since
// its last discard, and anything discarded after its riichi declaration) at 0..8, its riichi tile
// at 8..16, and the tiles it called in at 16..24. The pass runs backwards, gathering what was
// discarded after each entry: a seat's last discard and its riichi declaration then each read
// that union once, instead of every discard updating every seat. The union after a declaration
// holds the declarer's own later discards too, which its own discards (`s.discarded`) hold anyway.
fn log_sets(s: &mut GameState) -> [u32; 24] {
    let mut out: [u32; 24] = [0u32; 24];
    let mut since: [u32; 8] = [0u32; 8];
    let mut after_riichi: [u32; 8] = [0u32; 8];
    let mut after_lo: u32 = 0u32;
    let mut after_hi: u32 = 0u32;
    // Seats whose last discard the pass has met.
    let mut met: u32 = 0u32;
    let n: u32 = log_count(s);
    for j in 0u32..n {
        let e: u32 = log_entry(s, n - 1u32 - j);
        let k: u32 = log_kind(e);
        let a: u32 = log_actor(e);
        let t: u32 = value_type(log_tile(e));
        let lo: u32 = bit_lo(t);
        let hi: u32 = bit_hi(t);
        if k == EV_RIICHI {
            after_riichi[(a * 2u32) as usize] = after_lo;
            after_riichi[(a * 2u32 + 1u32) as usize] = after_hi;
        }
        if k == EV_CHI || k == EV_PON || k == EV_OPEN_KAN {
            out[(16u32 + a * 2u32) as usize] |= lo;
            out[(17u32 + a * 2u32) as usize] |= hi;
        }
        if k == EV_DISCARD {
            if (log_flags(e) & LOG_RIICHI_TILE) != 0u32 {
                out[(8u32 + a * 2u32) as usize] |= lo;
                out[(9u32 + a * 2u32) as usize] |= hi;
            }
            if ((met >> a) & 1u32) == 0u32 {
                since[(a * 2u32) as usize] = after_lo;
                since[(a * 2u32 + 1u32) as usize] = after_hi;
                met |= 1u32 << a;
            }
            after_lo |= lo;
            after_hi |= hi;
        }
    }
    for q in 0u32..4u32 {
        // A seat that has not discarded: everything discarded so far.
        let none: u32 = 1u32 - ((met >> q) & 1u32);
        since[(q * 2u32) as usize] |= after_lo * none;
        since[(q * 2u32 + 1u32) as usize] |= after_hi * none;
    }
    for i in 0u32..8u32 {
        out[i as usize] = s.discarded[i as usize] | since[i as usize] | after_riichi[i as usize];
    }
    out
}

// The planes row (offset in a seat block) of `log_sets`' r-th group of sets.
fn log_set_row(r: u32) -> u32 {
    if r == 0u32 {
        return P_SEAT_SAFE;
    }
    if r == 1u32 {
        return P_SEAT_RIICHI_TILE;
    }
    P_SEAT_CALLED_IN
}

// The claims of the target the observer may make, as 0/1 in the order of the planes rows
// P_CHI_LOW, P_CHI_MIDDLE, P_CHI_HIGH, P_PON, P_OPEN_KAN (with or without a red five).
fn claims_offered(s: &mut GameState) -> [u32; 5] {
    let m: [u32; 3] = s.mask;
    [
        (mask_has(m, ACTION_CHI_LEFT) || mask_has(m, ACTION_CHI_LEFT_RED)) as u32,
        (mask_has(m, ACTION_CHI_MIDDLE) || mask_has(m, ACTION_CHI_MIDDLE_RED)) as u32,
        (mask_has(m, ACTION_CHI_RIGHT) || mask_has(m, ACTION_CHI_RIGHT_RED)) as u32,
        (mask_has(m, ACTION_PON) || mask_has(m, ACTION_PON_RED)) as u32,
        mask_has(m, ACTION_OPEN_KAN) as u32,
    ]
}

pub fn observe_planes(state: GameState, arg: u32) -> ObsPlanes {
    let mut s: GameState = state;
    planes_of(&mut s, arg)
}

fn planes_of(s: &mut GameState, arg: u32) -> ObsPlanes {
    let mut o: ObsPlanes = ObsPlanes {
        planes: [0u32; 544],
        scalars: [0u32; 24],
    };
    write_planes(s, arg, &mut o);
    o
}

// `observe_planes` written in place into a record (any contents), rescanning the round as the GPU
// does: the host's tests hold its `TableView` writer (`planes_but_seats_into` below) to this.
pub fn planes_into(s: &mut GameState, arg: u32, o: &mut ObsPlanes) {
    o.planes = [0u32; 544];
    write_planes(s, arg, o);
}

// The hand as a thermometer, row k (sets at 2k, 2k + 1) holding the types held more than k times.
// No branch per type: which are held is hard to predict.
fn held_sets(hand: [u32; 34]) -> [u32; 8] {
    let mut held: [u32; 8] = [0u32; 8];
    for t in 0u32..34u32 {
        let c: u32 = hand[t as usize];
        for k in 0u32..4u32 {
            held[(k * 2u32) as usize] |= bit_lo(t) * ((c > k) as u32);
            held[(k * 2u32 + 1u32) as usize] |= bit_hi(t) * ((c > k) as u32);
        }
    }
    held
}

// The 32 bits of the action mask from bit `at` on. The sets below are read a word at a time: a
// loop over the actions that sets one bit per action, at an index known only at run time, kept
// the set in memory and stalled on it (a quarter of the planes' own rows).
fn mask_word(m: [u32; 3], at: u32) -> u32 {
    let w: u32 = at / 32u32;
    let sh: u32 = at % 32u32;
    if w >= 3u32 {
        return 0u32;
    }
    let mut x: u32 = m[w as usize] >> sh;
    if sh != 0u32 && w < 2u32 {
        x |= m[(w + 1u32) as usize] << (32u32 - sh);
    }
    x
}

// The types the player to move may discard (a red and a black five are one type here).
fn legal_discards(s: &mut GameState) -> [u32; 2] {
    let m: [u32; 3] = s.mask;
    let mut lo: u32 = mask_word(m, ACTION_DISCARD);
    let mut hi: u32 = mask_word(m, ACTION_DISCARD + 32u32) & 3u32;
    // The red fives' ids, after the 34 types' (their types are 4, 13 and 22).
    for a in 34u32..ACTION_DISCARD_COUNT {
        lo |= (mask_has(m, ACTION_DISCARD + a) as u32) << value_type(a);
    }
    if mask_has(m, ACTION_TSUMOGIRI) {
        let t: u32 = value_type(s.drawn);
        lo |= bit_lo(t);
        hi |= bit_hi(t);
    }
    [lo, hi]
}

// The types of the closed or added kans the player to move may declare.
fn legal_self_kans(s: &mut GameState) -> [u32; 2] {
    let m: [u32; 3] = s.mask;
    [mask_word(m, ACTION_SELF_KAN), mask_word(m, ACTION_SELF_KAN + 32u32) & 3u32]
}

// Writes the planes into a zeroed record.
fn write_planes(s: &mut GameState, arg: u32, o: &mut ObsPlanes) {
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather(s, seat);
    write_own_planes(s, &mut v, o);
    view_seat_planes(s, seat, o);
    o.scalars = view_scalars(s, &mut v);
}

// The host's form of the planes for a game whose seat blocks and table tiles it keeps up to date
// from the round's log (rinshan_engine::observe's `TableView`): every row but the seat blocks
// (rows P_SEAT..P_DORA_INDICATORS, which the host writes; this leaves them as they are, and
// expects the other rows zeroed), and the scalars.
pub fn planes_but_seats_into(s: &mut GameState, arg: u32, table: TableTiles, o: &mut ObsPlanes) {
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather_with(s, seat, table);
    write_own_planes(s, &mut v, o);
    o.scalars = view_scalars(s, &mut v);
}

// Every planes row but the seat blocks, into zeroed rows.
fn write_own_planes(s: &mut GameState, v: &mut Seen, o: &mut ObsPlanes) {
    let seat: u32 = v.seat;
    for k in 0u32..4u32 {
        put_row(o, P_HAND + k, cells_above(v.hand_cells, k));
    }
    put_row(o, P_SEEN, v.seen_cells);
    put_row(o, P_DORA, v.dora_cells);
    for suit in 0u32..3u32 {
        put_plane(o, P_RED, suit * 9u32 + 4u32, holds_red(s, seat, suit) as u32);
        put_plane(o, P_RED_SEEN, suit * 9u32 + 4u32, (v.red_seen >> suit) & 1u32);
    }
    if v.decision == DECISION_TURN || v.decision == DECISION_RIICHI_DISCARD {
        if s.drawn != NO_TILE_VALUE {
            put_plane(o, P_DRAWN, value_type(s.drawn), 1u32);
        }
        put_set(o, P_LEGAL_DISCARD, legal_discards(s));
        put_set(o, P_SELF_KAN, legal_self_kans(s));
    }
    if v.decision == DECISION_CLAIM || v.decision == DECISION_CHANKAN {
        let t: u32 = value_type(s.claim_tile);
        put_plane(o, P_TARGET, t, 1u32);
        let claims: [u32; 5] = claims_offered(s);
        for i in 0u32..5u32 {
            put_plane(o, P_CHI_LOW + i, t, claims[i as usize]);
        }
    }
    put_set(o, P_WAITS, own_waits(s, seat));
    let round_wind: u32 = EAST + round_wind_of(s.round);
    let seat_wind: u32 = EAST + rel(s.dealer, seat);
    put_plane(o, P_YAKUHAI, round_wind, 1u32 + (round_wind == seat_wind) as u32);
    if round_wind != seat_wind {
        put_plane(o, P_YAKUHAI, seat_wind, 1u32);
    }
    for t in FIRST_DRAGON..34u32 {
        put_plane(o, P_YAKUHAI, t, 1u32);
    }
    for i in 0u32..s.dora_revealed {
        let t: u32 = value_type(wall_tile(s, WALL_DORA + i));
        let at: u32 = P_DORA_INDICATORS * 34u32 + t;
        o.planes[(at / 4u32) as usize] += 1u32 << ((at % 4u32) * 8u32);
    }
}

// Rows P_SEAT.. : each seat's river, melds and the tiles safe against it.
fn view_seat_planes(s: &mut GameState, seat: u32, o: &mut ObsPlanes) {
    let sets: [u32; 24] = log_sets(s);
    for j in 0u32..SEATS {
        let q: u32 = (seat + j) % SEATS;
        let base: u32 = P_SEAT + j * P_SEAT_ROWS;
        // One pass, straight into the (zeroed) rows: counts add up in their bytes (at most 4 or
        // 24), the first turn is written once, the last turn overwritten by each later discard.
        let len: u32 = byte_of(s.river_lens, q);
        let mut before_lo: u32 = 0u32;
        let mut before_hi: u32 = 0u32;
        let mut last: u32 = 0u32;
        for i in 0u32..len {
            let e: u32 = river_entry(s, q, i);
            let t: u32 = value_type(e & 63u32);
            last = t;
            add_plane(o, base + P_SEAT_DISCARDED, t, 1u32);
            add_plane(o, base + P_SEAT_TEDASHI, t, ((e & 128u32) == 0u32) as u32);
            let lo: u32 = bit_lo(t);
            let hi: u32 = bit_hi(t);
            let first: bool = ((before_lo & lo) | (before_hi & hi)) == 0u32;
            add_plane(o, base + P_SEAT_FIRST_TURN, t, (i + 1u32) * (first as u32));
            before_lo |= lo;
            before_hi |= hi;
            add_plane(o, base + P_SEAT_CALLED_AWAY, t, (e >> 6u32) & 1u32);
            set_plane(o, base + P_SEAT_LAST_TURN, t, i + 1u32);
        }
        if len > 0u32 {
            put_plane(o, base + P_SEAT_LAST_DISCARD, last, 1u32);
        }
        for i in 0u32..meld_count(s, q) {
            let m: u32 = s.melds[(q * 4u32 + i) as usize];
            let k: u32 = meld_kind(m);
            let t: u32 = meld_tile(m);
            if k == MELD_CHI {
                add_plane(o, base + P_SEAT_MELD_TILES, t, 1u32);
                add_plane(o, base + P_SEAT_MELD_TILES, t + 1u32, 1u32);
                add_plane(o, base + P_SEAT_MELD_TILES, t + 2u32, 1u32);
            } else if k == MELD_PON {
                add_plane(o, base + P_SEAT_MELD_TILES, t, 3u32);
            } else {
                add_plane(o, base + P_SEAT_MELD_TILES, t, 4u32);
            }
            if k == MELD_CLOSED_KAN {
                add_plane(o, base + P_SEAT_CLOSED_KAN, t, 1u32);
            }
        }
        // Three players' Norths set aside lie beside the seat's melds, where the tables show them.
        if SEATS == 3u32 {
            add_plane(o, base + P_SEAT_MELD_TILES, NORTH, kita_count(s, q));
        }
        for r in 0u32..3u32 {
            let i: u32 = r * 8u32 + q * 2u32;
            put_set(o, base + log_set_row(r), [sets[i as usize], sets[(i + 1u32) as usize]]);
        }
    }
}

pub fn observe_tokens(state: GameState, arg: u32) -> ObsTokens {
    let mut s: GameState = state;
    tokens_of(&mut s, arg)
}

fn tokens_of(s: &mut GameState, arg: u32) -> ObsTokens {
    let mut o: ObsTokens = ObsTokens { words: [0u32; 254] };
    write_tokens(s, arg, &mut o);
    o
}

// `observe_tokens` written in place, as `planes_into` is (the host's tests' oracle).
pub fn tokens_into(s: &mut GameState, arg: u32, o: &mut ObsTokens) {
    o.words = [0u32; 254];
    write_tokens(s, arg, o);
}

// Writes the tokens into a zeroed record.
fn write_tokens(s: &mut GameState, arg: u32, o: &mut ObsTokens) {
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather(s, seat);
    write_tokens_but_events(s, &mut v, o);
    let n: u32 = view_events(s, seat, o);
    put_tok(o, T_EVENTS_LEN, n);
}

// The host's form of the tokens for a game whose table and event list it keeps up to date (as
// `planes_but_seats_into`): every token but the events and their count, which the host writes
// after this zeroes the record.
pub fn tokens_but_events_into(s: &mut GameState, arg: u32, table: TableTiles, o: &mut ObsTokens) {
    o.words = [0u32; 254];
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather_with(s, seat, table);
    write_tokens_but_events(s, &mut v, o);
}

fn write_tokens_but_events(s: &mut GameState, v: &mut Seen, o: &mut ObsTokens) {
    let seat: u32 = v.seat;
    // Both fields start on a word boundary (view_layout.rs).
    for j in 0u32..9u32 {
        o.words[(T_HAND / 4u32 + j) as usize] |= v.hand_cells[j as usize];
        o.words[(T_SEEN / 4u32 + j) as usize] |= v.seen_cells[j as usize];
    }
    for suit in 0u32..3u32 {
        put_tok(o, T_HAND_RED + suit, holds_red(s, seat, suit) as u32);
    }
    let mut drawn: u32 = NO_TILE_BYTE;
    if (v.decision == DECISION_TURN || v.decision == DECISION_RIICHI_DISCARD) && s.drawn != NO_TILE_VALUE {
        drawn = s.drawn;
    }
    put_tok(o, T_DRAWN, drawn);
    let mut target: u32 = NO_TILE_BYTE;
    if v.decision == DECISION_CLAIM || v.decision == DECISION_CHANKAN {
        target = s.claim_tile;
    }
    put_tok(o, T_TARGET, target);
    // A meld's four tokens fill one word (T_MELDS starts on a word boundary): kind, tile, red
    // fives, and whom it was called from; an empty slot is all 255.
    for j in 0u32..SEATS {
        let q: u32 = (seat + j) % SEATS;
        for i in 0u32..4u32 {
            let at: u32 = T_MELDS / 4u32 + j * 4u32 + i;
            let mut word: u32 = 0xffffffffu32;
            if i < meld_count(s, q) {
                let m: u32 = s.melds[(q * 4u32 + i) as usize];
                let mut from: u32 = NO_TILE_BYTE;
                if meld_kind(m) != MELD_CLOSED_KAN {
                    from = (m >> MELD_FROM_SHIFT) & 3u32;
                }
                word = meld_kind(m) | (meld_tile(m) << 8u32) | (((m >> MELD_REDS_SHIFT) & 3u32) << 16u32) | (from << 24u32);
            }
            o.words[at as usize] = word;
        }
    }
    for i in 0u32..5u32 {
        let mut ind: u32 = NO_TILE_BYTE;
        if i < s.dora_revealed {
            ind = wall_tile(s, WALL_DORA + i);
        }
        put_tok(o, T_DORA + i, ind);
    }
    let sc: [u32; 24] = view_scalars(s, v);
    for i in 0u32..24u32 {
        o.words[(T_SCALARS / 4u32 + i) as usize] = sc[i as usize];
    }
}

// The round's public events as tokens [kind, actor (ego), tile or 255, flags], one word each,
// with each draw as a token of its own (its tile shown to the drawer only).
fn view_events(s: &mut GameState, seat: u32, o: &mut ObsTokens) -> u32 {
    let mut n: u32 = 0u32;
    let mut live: u32 = 0u32;
    let mut replacement: u32 = 0u32;
    let mut after_kan: bool = false;
    let base: u32 = T_EVENTS / 4u32;
    for i in 0u32..log_count(s) {
        let e: u32 = log_entry(s, i);
        let k: u32 = log_kind(e);
        let a: u32 = log_actor(e);
        let f: u32 = log_flags(e);
        if (f & LOG_DREW) != 0u32 {
            let mut pos: u32 = WALL_LIVE_START + live;
            if after_kan {
                pos = replacement_index(replacement);
                replacement += 1u32;
            } else {
                live += 1u32;
            }
            let mut tile: u32 = NO_TILE_BYTE;
            if a == seat {
                tile = wall_tile(s, pos);
            }
            if n < TOKEN_EVENTS {
                o.words[(base + n) as usize] = event_token(EV_DRAW, rel(seat, a), tile, 0u32);
                n += 1u32;
            }
        }
        let mut tile: u32 = log_tile(e);
        if tile == LOG_NO_TILE {
            tile = NO_TILE_BYTE;
        }
        if n < TOKEN_EVENTS {
            o.words[(base + n) as usize] = event_token(k, rel(seat, a), tile, f & !LOG_DREW);
            n += 1u32;
        }
        if k != EV_DORA {
            // A kan or a kita is followed by a replacement tile.
            after_kan = k == EV_OPEN_KAN || k == EV_CLOSED_KAN || k == EV_ADDED_KAN || k == EV_KITA;
        }
    }
    if (s.log_len & LOG_PENDING_DRAW) != 0u32 && s.phase != PHASE_OVER && n < TOKEN_EVENTS {
        let mut tile: u32 = NO_TILE_BYTE;
        if s.current == seat {
            tile = s.drawn;
        }
        o.words[(base + n) as usize] = event_token(EV_DRAW, rel(seat, s.current), tile, 0u32);
        n += 1u32;
    }
    n
}
