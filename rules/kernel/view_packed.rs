// The planes packed (layout in view_layout.rs): their yes/no rows as 34-bit sets, their rows of
// counts and turn numbers as bytes, 1,336 bytes instead of 2,272, for learners that move
// observations to a device and unpack them there. The same facts as `write_planes`, from the same
// helpers where a row is a set.

fn put_bit_row(o: &mut ObsPacked, i: u32, set: [u32; 2]) {
    o.bits[(i * 2u32) as usize] |= set[0];
    o.bits[(i * 2u32 + 1u32) as usize] |= set[1];
}

fn put_bits(o: &mut ObsPacked, row: u32, set: [u32; 2]) {
    put_bit_row(o, packed_index(row), set);
}

fn put_seat_bits(o: &mut ObsPacked, j: u32, r: u32, set: [u32; 2]) {
    put_bit_row(o, packed_seat_index(j, r), set);
}

// Adds `v` to cell t of byte row i (cells stay below 256: no carry into the next).
fn add_count(o: &mut ObsPacked, i: u32, t: u32, v: u32) {
    let at: u32 = i * 34u32 + t;
    o.counts[(at / 4u32) as usize] += v << ((at % 4u32) * 8u32);
}

// Writes packed cells (`pack_cells`) into zeroed byte row i.
fn put_count_row(o: &mut ObsPacked, i: u32, p: [u32; 9]) {
    let w: u32 = i * 34u32 / 4u32;
    let q: [u32; 9] = at_row(p, i);
    for j in 0u32..9u32 {
        o.counts[(w + j) as usize] |= q[j as usize];
    }
}

fn set_count(o: &mut ObsPacked, i: u32, t: u32, v: u32) {
    let at: u32 = i * 34u32 + t;
    o.counts[(at / 4u32) as usize] = with_byte(o.counts[(at / 4u32) as usize], at % 4u32, v);
}

fn one_type(t: u32) -> [u32; 2] {
    [bit_lo(t), bit_hi(t)]
}

pub fn observe_packed(state: GameState, arg: u32) -> ObsPacked {
    let mut s: GameState = state;
    let mut o: ObsPacked = ObsPacked {
        bits: [0u32; 72],
        counts: [0u32; 238],
        scalars: [0u32; 24],
    };
    write_packed(&mut s, arg, &mut o);
    o
}

// `observe_packed` written in place, as `planes_into` is (the host's tests' oracle).
pub fn packed_into(s: &mut GameState, arg: u32, o: &mut ObsPacked) {
    o.bits = [0u32; 72];
    o.counts = [0u32; 238];
    write_packed(s, arg, o);
}

// Writes the packed planes into a zeroed record.
fn write_packed(s: &mut GameState, arg: u32, o: &mut ObsPacked) {
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather(s, seat);
    write_own_packed(s, &mut v, o);
    packed_seat_rows(s, seat, o);
    o.scalars = view_scalars(s, &mut v);
}

// The host's form for a game whose seat rows it keeps up to date, as `planes_but_seats_into`:
// every row but the seat blocks' (which the host writes first, into a zeroed record), and the
// scalars.
pub fn packed_but_seats_into(s: &mut GameState, arg: u32, table: TableTiles, o: &mut ObsPacked) {
    let seat: u32 = observer(s, arg);
    let mut v: Seen = gather_with(s, seat, table);
    write_own_packed(s, &mut v, o);
    o.scalars = view_scalars(s, &mut v);
}

// Every row but the seat blocks', into zeroed rows.
fn write_own_packed(s: &mut GameState, v: &mut Seen, o: &mut ObsPacked) {
    let seat: u32 = v.seat;
    let held: [u32; 8] = held_sets(hand_counts(s, seat));
    for k in 0u32..4u32 {
        put_bits(o, P_HAND + k, [held[(k * 2u32) as usize], held[(k * 2u32 + 1u32) as usize]]);
    }
    let seen: u32 = packed_index(P_SEEN);
    let dora: u32 = packed_index(P_DORA);
    put_count_row(o, seen, v.seen_cells);
    put_count_row(o, dora, v.dora_cells);
    // Red fives are at their type's column: 4, 13, 22 (all in the low word).
    let mut red: u32 = 0u32;
    let mut red_seen: u32 = 0u32;
    for suit in 0u32..3u32 {
        red |= (holds_red(s, seat, suit) as u32) << (suit * 9u32 + 4u32);
        red_seen |= ((v.red_seen >> suit) & 1u32) << (suit * 9u32 + 4u32);
    }
    put_bits(o, P_RED, [red, 0u32]);
    put_bits(o, P_RED_SEEN, [red_seen, 0u32]);
    if v.decision == DECISION_TURN || v.decision == DECISION_RIICHI_DISCARD {
        if s.drawn != NO_TILE_VALUE {
            put_bits(o, P_DRAWN, one_type(value_type(s.drawn)));
        }
        put_bits(o, P_LEGAL_DISCARD, legal_discards(s));
        put_bits(o, P_SELF_KAN, legal_self_kans(s));
    }
    if v.decision == DECISION_CLAIM || v.decision == DECISION_CHANKAN {
        let t: u32 = value_type(s.claim_tile);
        put_bits(o, P_TARGET, one_type(t));
        let claims: [u32; 5] = claims_offered(s);
        for i in 0u32..5u32 {
            let on: u32 = claims[i as usize];
            put_bits(o, P_CHI_LOW + i, [bit_lo(t) * on, bit_hi(t) * on]);
        }
    }
    put_bits(o, P_WAITS, own_waits(s, seat));
    let yakuhai: u32 = packed_index(P_YAKUHAI);
    let round_wind: u32 = EAST + round_wind_of(s.round);
    let seat_wind: u32 = EAST + rel(s.dealer, seat);
    add_count(o, yakuhai, round_wind, 1u32);
    add_count(o, yakuhai, seat_wind, 1u32);
    for t in FIRST_DRAGON..34u32 {
        add_count(o, yakuhai, t, 1u32);
    }
    let indicators: u32 = packed_index(P_DORA_INDICATORS);
    for i in 0u32..s.dora_revealed {
        add_count(o, indicators, value_type(wall_tile(s, WALL_DORA + i)), 1u32);
    }
}

// Rows P_SEAT.. : each seat's river, melds and the tiles safe against it.
fn packed_seat_rows(s: &mut GameState, seat: u32, o: &mut ObsPacked) {
    let sets: [u32; 24] = log_sets(s);
    for j in 0u32..SEATS {
        let q: u32 = (seat + j) % SEATS;
        let discarded: u32 = packed_seat_index(j, P_SEAT_DISCARDED);
        let tedashi: u32 = packed_seat_index(j, P_SEAT_TEDASHI);
        let first_turn: u32 = packed_seat_index(j, P_SEAT_FIRST_TURN);
        let last_turn: u32 = packed_seat_index(j, P_SEAT_LAST_TURN);
        let called_away: u32 = packed_seat_index(j, P_SEAT_CALLED_AWAY);
        let meld_tiles: u32 = packed_seat_index(j, P_SEAT_MELD_TILES);
        let len: u32 = byte_of(s.river_lens, q);
        let mut before: [u32; 2] = [0u32; 2];
        let mut last: u32 = 0u32;
        for i in 0u32..len {
            let e: u32 = river_entry(s, q, i);
            let t: u32 = value_type(e & 63u32);
            last = t;
            add_count(o, discarded, t, 1u32);
            add_count(o, tedashi, t, ((e & 128u32) == 0u32) as u32);
            let first: bool = ((before[0] & bit_lo(t)) | (before[1] & bit_hi(t))) == 0u32;
            add_count(o, first_turn, t, (i + 1u32) * (first as u32));
            before[0] |= bit_lo(t);
            before[1] |= bit_hi(t);
            add_count(o, called_away, t, (e >> 6u32) & 1u32);
            set_count(o, last_turn, t, i + 1u32);
        }
        if len > 0u32 {
            put_seat_bits(o, j, P_SEAT_LAST_DISCARD, one_type(last));
        }
        let mut closed_kans: [u32; 2] = [0u32; 2];
        for i in 0u32..meld_count(s, q) {
            let m: u32 = s.melds[(q * 4u32 + i) as usize];
            let k: u32 = meld_kind(m);
            let t: u32 = meld_tile(m);
            if k == MELD_CHI {
                add_count(o, meld_tiles, t, 1u32);
                add_count(o, meld_tiles, t + 1u32, 1u32);
                add_count(o, meld_tiles, t + 2u32, 1u32);
            } else if k == MELD_PON {
                add_count(o, meld_tiles, t, 3u32);
            } else {
                add_count(o, meld_tiles, t, 4u32);
            }
            if k == MELD_CLOSED_KAN {
                set_add(&mut closed_kans, t);
            }
        }
        // As the planes: three players' Norths set aside count with the seat's melds.
        if SEATS == 3u32 {
            add_count(o, meld_tiles, NORTH, kita_count(s, q));
        }
        put_seat_bits(o, j, P_SEAT_CLOSED_KAN, closed_kans);
        for r in 0u32..3u32 {
            let i: u32 = r * 8u32 + q * 2u32;
            put_seat_bits(o, j, log_set_row(r), [sets[i as usize], sets[(i + 1u32) as usize]]);
        }
    }
}
