// The player to move after a draw or a call: what is legal, and discards, riichi, kans, tsumo and
// kyuushu.

fn mask_set(m: &mut [u32; 3], a: u32) {
    if a != ACTION_ABSENT {
        m[(a / 32u32) as usize] |= 1u32 << (a % 32u32);
    }
}

fn mask_has(m: [u32; 3], a: u32) -> bool {
    a < 96u32 && ((m[(a / 32u32) as usize] >> (a % 32u32)) & 1u32) != 0u32
}

fn kuikae_banned(s: &mut GameState, t: u32) -> bool {
    ((byte_of(s.kuikae, 0u32) == t) as u32 | (byte_of(s.kuikae, 1u32) == t) as u32) != 0u32
}

fn discard_allowed(s: &mut GameState, p: u32, v: u32) -> bool {
    let n: u32 = value_count(s, p, v);
    if n == 0u32 || kuikae_banned(s, value_type(v)) {
        return false;
    }
    // The drawn tile itself goes by TSUMOGIRI; this id then needs another copy of the same value.
    !(v == s.drawn && n < 2u32)
}

// Sets the action `base + t` for every type t in the 34-bit set: each of the set's words is the
// mask's bits from `base` on, shifted into place. A loop over the set bits ended at a count of
// types that varies from hand to hand, and its exit was mispredicted on most turns.
fn mask_set_types(m: &mut [u32; 3], base: u32, set: [u32; 2]) {
    if base == ACTION_ABSENT {
        return;
    }
    for i in 0u32..2u32 {
        let at: u32 = base + i * 32u32;
        let w: u32 = at / 32u32;
        let shift: u32 = at % 32u32;
        m[w as usize] |= set[i as usize] << shift;
        if shift != 0u32 && w + 1u32 < 3u32 {
            m[(w + 1u32) as usize] |= set[i as usize] >> (32u32 - shift);
        }
    }
}

fn set_remove(set: &mut [u32; 2], t: u32) {
    set[(t / 32u32) as usize] &= !(1u32 << (t % 32u32));
}

// The discards of the player to move, from the set of types held rather than a count per value:
// a value is discardable if held, not banned by kuikae, and not the drawn tile's only copy (that
// one goes by TSUMOGIRI).
fn discard_mask(s: &mut GameState, p: u32, m: &mut [u32; 3]) {
    let mut black: [u32; 2] = hand_types_with(s, p, 7u32);
    for k in 0u32..2u32 {
        let t: u32 = byte_of(s.kuikae, k);
        if t < 34u32 {
            set_remove(&mut black, t);
        }
    }
    if ACTION_DISCARD_COUNT > 34u32 {
        for suit in 0u32..3u32 {
            if holds_red(s, p, suit) {
                let t: u32 = suit * 9u32 + 4u32;
                if hand_count(s, p, t) == 1u32 {
                    set_remove(&mut black, t);
                }
                if !kuikae_banned(s, t) && s.drawn != 34u32 + suit {
                    mask_set(m, ACTION_DISCARD + 34u32 + suit);
                }
            }
        }
    }
    if s.drawn < 34u32 && value_count(s, p, s.drawn) < 2u32 {
        set_remove(&mut black, s.drawn);
    }
    mask_set_types(m, ACTION_DISCARD, black);
}

fn riichi_possible(s: &mut GameState, p: u32) -> bool {
    if surely_not_tenpai(s, p, 1u32) {
        return false;
    }
    // A 14-tile hand (less three a closed kan) at shanten <= 0 has a discard leaving a hand at
    // shanten 0, and (the shanten's targets respecting the four copies of a concealed tile, as
    // `waits_of` does) such a hand has a wait that counts: no per-discard waits search.
    hand_shanten(s, p) <= 0i32
}

// In riichi a closed kan is allowed only of the drawn tile and only if the waits stay the same.
fn riichi_kan_keeps_waits(s: &mut GameState, p: u32, t: u32) -> bool {
    let mut before: [u32; 34] = hand_counts(s, p);
    before[value_type(s.drawn) as usize] -= 1u32;
    let w0: [u32; 2] = waits_of(before);
    let mut after: [u32; 34] = hand_counts(s, p);
    after[t as usize] -= 4u32;
    let w1: [u32; 2] = waits_of(after);
    w0[0] == w1[0] && w0[1] == w1[1] && (w0[0] | w0[1]) != 0u32
}

// Kita (three players): after a draw, a North may be set aside for a replacement tile while the
// live wall has tiles left; in riichi only the North just drawn (the waits stay those of the hand).
fn kita_allowed(s: &mut GameState, p: u32, riichi: bool) -> bool {
    if SEATS != 3u32 || s.next_draw >= s.live_end || hand_count(s, p, NORTH) == 0u32 {
        return false;
    }
    !riichi || s.drawn == NORTH
}

// Sets the drawn North aside: it may be ronned (ron only, no chankan), then a replacement tile
// follows (TASK_REPLACEMENT with REPLACE_KITA). It interrupts the first go-round (double riichi,
// tenhou, chiihou, kyuushu); ippatsu ends once it stands (see `resolve_claims`).
fn do_kita(s: &mut GameState) -> u32 {
    let p: u32 = s.current;
    take_tile(s, p, NORTH);
    s.seat_flags[p as usize] += 1u32 << SEAT_KITA_SHIFT;
    s.uninterrupted = 0u32;
    s.drawn = NO_TILE_VALUE;
    log_push(s, EV_KITA, p, NORTH, 0u32);
    // The kan dora of an open or added kan whose replacement tile is this North shows now, before
    // the kita's own replacement draw, as after a discard: Tenhou's three-player mjlogs write the
    // `<DORA>` right after the kita's `<N>` and before the next `<T>`; RiichiEnv does the same
    // for Mahjong Soul.
    reveal_pending_dora(s);
    update_waits(s, p);
    set_claim(s, p, NORTH, CLAIM_WINDOW_KITA)
}

fn turn_mask(s: &mut GameState) -> [u32; 3] {
    let p: u32 = s.current;
    let mut m: [u32; 3] = [0u32; 3];
    let f: u32 = s.seat_flags[p as usize];
    let riichi: bool = (f & SEAT_RIICHI) != 0u32;
    let drew: bool = s.drawn != NO_TILE_VALUE;
    if s.phase == PHASE_RIICHI_DISCARD {
        for v in 0u32..ACTION_DISCARD_COUNT {
            if discard_allowed(s, p, v) && tenpai_after_discard(s, p, value_type(v)) {
                mask_set(&mut m, ACTION_DISCARD + v);
            }
        }
        if drew && tenpai_after_discard(s, p, value_type(s.drawn)) {
            mask_set(&mut m, ACTION_TSUMOGIRI);
        }
        return m;
    }
    if !riichi {
        discard_mask(s, p, &mut m);
    }
    if !drew {
        return m;
    }
    mask_set(&mut m, ACTION_TSUMOGIRI);
    if can_win(s, p, s.drawn, true, false) {
        mask_set(&mut m, ACTION_TSUMO);
    }
    if s.kans < 4u32 && s.next_draw < s.live_end {
        let fours: [u32; 2] = hand_types_with(s, p, 4u32);
        if riichi {
            let t: u32 = value_type(s.drawn);
            if in_set(fours, t) && riichi_kan_keeps_waits(s, p, t) {
                mask_set(&mut m, ACTION_SELF_KAN + t);
            }
        } else {
            mask_set_types(&mut m, ACTION_SELF_KAN, fours);
            for i in 0u32..meld_count(s, p) {
                let meld: u32 = s.melds[(p * 4u32 + i) as usize];
                if meld_kind(meld) == MELD_PON && hand_count(s, p, meld_tile(meld)) > 0u32 {
                    mask_set(&mut m, ACTION_SELF_KAN + meld_tile(meld));
                }
            }
        }
    }
    if kita_allowed(s, p, riichi) {
        mask_set(&mut m, ACTION_KITA);
    }
    let concealed: bool = (f & SEAT_CONCEALED) != 0u32;
    // A minimum of 0 is no minimum: where no one busts (M-League), a seat below zero may riichi.
    let enough_points: bool = RIICHI_MIN_POINTS == 0u32 || s.scores[p as usize] >= RIICHI_MIN_POINTS as i32;
    // Riichi needs a draw left for every seat (four tiles, three with three players), unless the
    // rule set allows riichi with no draw left.
    let draws_left: bool = RIICHI_WITH_NO_DRAW_LEFT || s.live_end - s.next_draw >= SEATS;
    if !riichi && concealed && enough_points && draws_left && riichi_possible(s, p) {
        mask_set(&mut m, ACTION_RIICHI);
    }
    // Kyuushu: nine kinds of terminals and honors, counted from the hand's words at once.
    if ABORTIVE_DRAWS && s.uninterrupted != 0u32 && (f & SEAT_DISCARDED) == 0u32 && isolated_and_orphans(s, p)[1] >= 9u32 {
        mask_set(&mut m, ACTION_KYUUSHU);
    }
    m
}

fn river_push(s: &mut GameState, p: u32, entry: u32) {
    let len: u32 = byte_of(s.river_lens, p);
    if len < 24u32 {
        s.rivers[(p * 6u32 + len / 4u32) as usize] |= (entry & 255u32) << ((len % 4u32) * 8u32);
        s.river_lens = with_byte(s.river_lens, p, len + 1u32);
    }
}

fn do_discard(s: &mut GameState, v: u32, tsumogiri: bool) -> u32 {
    let p: u32 = s.current;
    take_tile(s, p, v);
    let t: u32 = value_type(v);
    let mut entry: u32 = v;
    let mut flags: u32 = 0u32;
    if tsumogiri {
        entry |= 128u32;
        flags |= LOG_TSUMOGIRI;
    }
    if s.phase == PHASE_RIICHI_DISCARD {
        flags |= LOG_RIICHI_TILE;
    }
    river_push(s, p, entry);
    log_push(s, EV_DISCARD, p, v, flags);
    // The cached waits are those of the hand before the draw; discarding a tile of the drawn
    // tile's type gives that hand back.
    if s.drawn == NO_TILE_VALUE || value_type(s.drawn) != t {
        update_waits(s, p);
    }
    s.discarded[(p * 2u32 + t / 32u32) as usize] |= 1u32 << (t % 32u32);
    let mut f: u32 = s.seat_flags[p as usize];
    if !is_terminal_or_honor(t) {
        f &= !SEAT_NAGASHI;
    }
    f |= SEAT_DISCARDED;
    // A riichi player's ippatsu ends with their next discard. So does temporary furiten, also
    // on the discard that follows a chi or pon (riichi.wiki, Furiten: "until the player's next
    // discard"; Mortal's libriichi); the seat's draw has lifted it already on a plain turn.
    f &= !(SEAT_IPPATSU | SEAT_FURITEN_TEMP);
    s.seat_flags[p as usize] = f;
    s.drawn = NO_TILE_VALUE;
    s.rinshan = 0u32;
    s.kuikae = 0xffffu32;
    // The kan dora of an open or added kan appears once its replacement tile is discarded.
    reveal_pending_dora(s);
    set_claim(s, p, v, 0u32)
}

fn take_all_of_type(s: &mut GameState, p: u32, t: u32, n: u32) -> u32 {
    let mut reds: u32 = 0u32;
    for i in 0u32..n {
        if take_type(s, p, t, false) >= 34u32 {
            reds += 1u32;
        }
    }
    reds
}

fn do_self_kan(s: &mut GameState, t: u32) -> u32 {
    let p: u32 = s.current;
    reveal_pending_dora(s);
    // Ippatsu ends once the kan stands (see `resolve_claims`): a chankan still counts it.
    s.uninterrupted = 0u32;
    s.drawn = NO_TILE_VALUE;
    if hand_count(s, p, t) == 4u32 {
        let reds: u32 = take_all_of_type(s, p, t, 4u32);
        let n: u32 = meld_count(s, p);
        s.melds[(p * 4u32 + n) as usize] = meld_word(MELD_CLOSED_KAN, t) | (reds << MELD_REDS_SHIFT);
        s.meld_counts = with_byte(s.meld_counts, p, n + 1u32);
        log_push(s, EV_CLOSED_KAN, p, t, LOG_WITH_RED * (reds > 0u32) as u32);
        // A closed kan shows its dora at once.
        reveal_dora(s, 1u32);
        update_waits(s, p);
        return set_claim(s, p, t, 2u32);
    }
    let v: u32 = take_type(s, p, t, false);
    for i in 0u32..meld_count(s, p) {
        let m: u32 = s.melds[(p * 4u32 + i) as usize];
        if meld_kind(m) == MELD_PON && meld_tile(m) == t {
            let mut red: u32 = 0u32;
            if v >= 34u32 {
                red = 1u32 << 12u32;
            }
            s.melds[(p * 4u32 + i) as usize] = ((m & !15u32) | MELD_ADDED_KAN) + red;
        }
    }
    log_push(s, EV_ADDED_KAN, p, v, LOG_WITH_RED * (v >= 34u32) as u32);
    s.dora_pending += 1u32;
    update_waits(s, p);
    set_claim(s, p, v, 1u32)
}

// Applies a legal action of the player to move; returns the task that follows.
fn do_turn_action(s: &mut GameState, a: u32) -> u32 {
    let p: u32 = s.current;
    if a == ACTION_TSUMOGIRI {
        let v: u32 = s.drawn;
        return do_discard(s, v, true);
    }
    if a >= ACTION_DISCARD && a < ACTION_DISCARD + ACTION_DISCARD_COUNT {
        return do_discard(s, a - ACTION_DISCARD, false);
    }
    if a == ACTION_RIICHI {
        s.seat_flags[p as usize] |= SEAT_RIICHI_PENDING;
        log_push(s, EV_RIICHI, p, LOG_NO_TILE, 0u32);
        s.phase = PHASE_RIICHI_DISCARD;
        return TASK_DONE;
    }
    if a == ACTION_TSUMO {
        s.task_seat = p;
        return TASK_TSUMO;
    }
    if a == ACTION_KYUUSHU {
        s.draw_kind = DRAW_KYUUSHU;
        return TASK_ABORTIVE;
    }
    if a == ACTION_KITA {
        return do_kita(s);
    }
    do_self_kan(s, a - ACTION_SELF_KAN)
}
