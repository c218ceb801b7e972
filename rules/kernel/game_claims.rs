// Claims on a discard (or on the tile of a kan): every seat with an option decides in turn order,
// then the highest-priority claims apply: ron > pon/kan > chi.

fn furiten(s: &mut GameState, q: u32) -> bool {
    let f: u32 = s.seat_flags[q as usize];
    if (f & (SEAT_FURITEN_TEMP | SEAT_FURITEN_RIICHI)) != 0u32 {
        return true;
    }
    (s.waits[(q * 2u32) as usize] & s.discarded[(q * 2u32) as usize]) != 0u32
        || (s.waits[(q * 2u32 + 1u32) as usize] & s.discarded[(q * 2u32 + 1u32) as usize]) != 0u32
}

// A winning tile of the seat's passed by (declined, or not offered: furiten, or no yaku): furiten
// until its next own draw, or for the rest of the round in riichi.
fn miss_win(s: &mut GameState, q: u32) {
    if (s.seat_flags[q as usize] & SEAT_RIICHI) != 0u32 {
        s.seat_flags[q as usize] |= SEAT_FURITEN_RIICHI;
    } else {
        s.seat_flags[q as usize] |= SEAT_FURITEN_TEMP;
    }
}

fn red_count(s: &mut GameState, q: u32, t: u32) -> u32 {
    if t < 27u32 && t % 9u32 == 4u32 && holds_red(s, q, t / 9u32) {
        return 1u32;
    }
    0u32
}

// Chi options for one shape: the two hand tiles a, b (types); plain and red forms. `size`: tiles
// in the hand; after the call some tile outside the kuikae ban (types ban_a, ban_b, 255 = none,
// neither of them a or b) must be left to discard.
fn chi_options(s: &mut GameState, q: u32, size: u32, a: u32, b: u32, ban_a: u32, ban_b: u32, plain: u32, red: u32) -> u32 {
    let na: u32 = hand_count(s, q, a);
    let nb: u32 = hand_count(s, q, b);
    if na == 0u32 || nb == 0u32 {
        return 0u32;
    }
    let mut banned: u32 = hand_count(s, q, ban_a);
    if ban_b != 255u32 {
        banned += hand_count(s, q, ban_b);
    }
    if size - 2u32 <= banned {
        return 0u32;
    }
    let ra: u32 = red_count(s, q, a);
    let rb: u32 = red_count(s, q, b);
    let mut o: u32 = 0u32;
    if na > ra && nb > rb {
        o |= plain;
    }
    if ra + rb > 0u32 {
        o |= red;
    }
    o
}

// Reads only the few counts a claim on type t depends on: most seats on most discards hold fewer
// than two copies and are not the chi seat, and are done after one read.
fn claim_options_for(s: &mut GameState, q: u32, from: u32, v: u32, kan: u32) -> u32 {
    let t: u32 = value_type(v);
    let mut o: u32 = 0u32;
    if waits_include(s, q, t) && !furiten(s, q) && (kan != 2u32 || KOKUSHI_ROBS_CLOSED_KAN) {
        let out: ScoreOutput = score_hand(win_input(s, q, v, false, kan == 1u32));
        let orphans: bool = has_yaku(out.yaku_lo, out.yaku_hi, YAKU_KOKUSHI)
            || has_yaku(out.yaku_lo, out.yaku_hi, YAKU_KOKUSHI_13);
        if out.status == STATUS_WIN && (kan != 2u32 || orphans) {
            o |= CLAIM_RON;
        }
    }
    let riichi: bool = (s.seat_flags[q as usize] & SEAT_RIICHI) != 0u32;
    if kan != 0u32 || riichi || s.next_draw >= s.live_end {
        return o;
    }
    let n: u32 = hand_count(s, q, t);
    let chi_seat: bool = SEATS == 4u32 && q == (from + 1u32) % SEATS && t < 27u32;
    if n < 2u32 && !chi_seat {
        return o;
    }
    let size: u32 = hand_size(s, q);
    let r: u32 = red_count(s, q, t);
    // A pon must leave a tile of another type to discard (kuikae bans the called type).
    if n >= 2u32 && size > n {
        if n - r >= 2u32 {
            o |= CLAIM_PON;
        }
        if r == 1u32 {
            o |= CLAIM_PON_RED;
        }
    }
    if n == 3u32 && s.kans < 4u32 {
        o |= CLAIM_KAN;
    }
    if chi_seat {
        let pos: u32 = t % 9u32;
        if pos <= 6u32 {
            let mut swap: u32 = 255u32;
            if pos <= 5u32 {
                swap = t + 3u32;
            }
            o |= chi_options(s, q, size, t + 1u32, t + 2u32, t, swap, CLAIM_CHI_LEFT, CLAIM_CHI_LEFT_RED);
        }
        if pos >= 1u32 && pos <= 7u32 {
            o |= chi_options(s, q, size, t - 1u32, t + 1u32, t, 255u32, CLAIM_CHI_MIDDLE, CLAIM_CHI_MIDDLE_RED);
        }
        if pos >= 2u32 {
            let mut swap: u32 = 255u32;
            if pos >= 3u32 {
                swap = t - 3u32;
            }
            o |= chi_options(s, q, size, t - 2u32, t - 1u32, t, swap, CLAIM_CHI_RIGHT, CLAIM_CHI_RIGHT_RED);
        }
    }
    o
}

// Opens a claim window on tile value `v` from seat `from`. `kan`: 0 a discard, 1 an added kan
// (chankan), 2 a closed kan (only thirteen orphans may rob it, where the rules allow), 3 a North
// set aside (CLAIM_WINDOW_KITA: ron only, no chankan).
fn set_claim(s: &mut GameState, from: u32, v: u32, kan: u32) -> u32 {
    s.claim_tile = v;
    s.claim_from = from;
    s.claim_kan = kan;
    TASK_OPEN_CLAIMS
}

fn open_claims(s: &mut GameState) -> u32 {
    let from: u32 = s.claim_from;
    let v: u32 = s.claim_tile;
    let kan: u32 = s.claim_kan;
    let mut any: bool = false;
    for j in 1u32..SEATS {
        let q: u32 = (from + j) % SEATS;
        let o: u32 = claim_options_for(s, q, from, v, kan);
        // Furiten does not depend on yaku: a wait passing by unclaimable still binds the seat
        // (a declined ron does so in do_claim_decision). Only thirteen orphans may rob a closed
        // kan, so another hand waiting on its tile is not furiten.
        if (o & CLAIM_RON) == 0u32 && kan != 2u32 && waits_include(s, q, value_type(v)) {
            miss_win(s, q);
        }
        s.claim_options[q as usize] = o;
        s.claim_choices[q as usize] = NO_CHOICE;
        if o != 0u32 && !any {
            any = true;
            s.current = q;
        }
    }
    s.claim_options[from as usize] = 0u32;
    s.claim_choices[from as usize] = NO_CHOICE;
    if any {
        s.phase = PHASE_CLAIM;
        return TASK_DONE;
    }
    TASK_RESOLVE
}

fn claim_mask(s: &mut GameState) -> [u32; 3] {
    let o: u32 = s.claim_options[s.current as usize];
    let mut m: [u32; 3] = [0u32; 3];
    mask_set(&mut m, ACTION_PASS);
    let actions: [u32; 10] = [
        ACTION_RON,
        ACTION_PON,
        ACTION_PON_RED,
        ACTION_OPEN_KAN,
        ACTION_CHI_LEFT,
        ACTION_CHI_LEFT_RED,
        ACTION_CHI_MIDDLE,
        ACTION_CHI_MIDDLE_RED,
        ACTION_CHI_RIGHT,
        ACTION_CHI_RIGHT_RED,
    ];
    for i in 0u32..10u32 {
        if ((o >> i) & 1u32) != 0u32 {
            mask_set(&mut m, actions[i as usize]);
        }
    }
    m
}

fn do_claim_decision(s: &mut GameState, a: u32) -> u32 {
    let q: u32 = s.current;
    s.claim_choices[q as usize] = a;
    if (s.claim_options[q as usize] & CLAIM_RON) != 0u32 && a != ACTION_RON {
        miss_win(s, q);
    }
    let from: u32 = s.claim_from;
    let mut j: u32 = (q + SEATS - from) % SEATS + 1u32;
    while j < SEATS {
        let next: u32 = (from + j) % SEATS;
        if s.claim_options[next as usize] != 0u32 {
            s.current = next;
            return TASK_DONE;
        }
        j += 1u32;
    }
    TASK_RESOLVE
}

fn accept_riichi(s: &mut GameState, p: u32) {
    let f: u32 = s.seat_flags[p as usize];
    if (f & SEAT_RIICHI_PENDING) == 0u32 {
        return;
    }
    let mut g: u32 = (f & !SEAT_RIICHI_PENDING) | SEAT_RIICHI | SEAT_IPPATSU;
    if s.uninterrupted != 0u32 && byte_of(s.river_lens, p) == 1u32 {
        g |= SEAT_DOUBLE_RIICHI;
    }
    s.seat_flags[p as usize] = g;
    log_push(s, EV_RIICHI_ACCEPTED, p, LOG_NO_TILE, 0u32);
    s.scores[p as usize] -= RIICHI_STICK_POINTS as i32;
    s.rewards[p as usize] -= (RIICHI_STICK_POINTS / 100u32) as i32;
    s.sticks += 1u32;
}

fn clear_claims(s: &mut GameState) {
    s.claim_options = [0u32; 4];
    s.claim_choices = [NO_CHOICE; 4];
    s.claim_tile = NO_TILE_VALUE;
    s.claim_kan = 0u32;
}

fn resolve_claims(s: &mut GameState) -> u32 {
    let from: u32 = s.claim_from;
    let v: u32 = s.claim_tile;
    let kan: u32 = s.claim_kan;
    let mut rons: u32 = 0u32;
    for j in 1u32..SEATS {
        if s.claim_choices[((from + j) % SEATS) as usize] == ACTION_RON {
            rons += 1u32;
        }
    }
    if rons > 0u32 {
        if rons == 3u32 && TRIPLE_RON_ABORT && DOUBLE_RON {
            clear_claims(s);
            s.draw_kind = DRAW_TRIPLE_RON;
            return TASK_ABORTIVE;
        }
        let mut first: bool = true;
        let mut dealer_won: bool = false;
        for j in 1u32..SEATS {
            let q: u32 = (from + j) % SEATS;
            if s.claim_choices[q as usize] == ACTION_RON && (first || DOUBLE_RON) {
                settle_ron(s, q, from, v, kan != 0u32 && kan != CLAIM_WINDOW_KITA, first);
                if q == s.dealer {
                    dealer_won = true;
                }
                first = false;
            }
        }
        clear_claims(s);
        s.task_flags = 0u32;
        if dealer_won {
            s.task_flags = END_DEALER_CONTINUES;
        }
        return TASK_END_ROUND;
    }
    s.task_seat = from;
    if kan != 0u32 {
        // The kan (or kita) stands: it breaks every ippatsu (a hand that robbed it kept its
        // ippatsu; Tenhou scores riichi + ippatsu + chankan).
        for p in 0u32..SEATS {
            s.seat_flags[p as usize] &= !SEAT_IPPATSU;
        }
        s.task_flags = 0u32;
        if kan == CLAIM_WINDOW_KITA {
            s.task_flags = REPLACE_KITA;
        }
        clear_claims(s);
        return TASK_REPLACEMENT;
    }
    accept_riichi(s, from);
    if ABORTIVE_DRAWS && four_riichi(s) {
        clear_claims(s);
        s.draw_kind = DRAW_FOUR_RIICHI;
        return TASK_ABORTIVE;
    }
    let mut caller: u32 = 4u32;
    let mut call: u32 = 0u32;
    for j in 1u32..SEATS {
        let q: u32 = (from + j) % SEATS;
        let a: u32 = s.claim_choices[q as usize];
        if a == ACTION_PON || a == ACTION_PON_RED || a == ACTION_OPEN_KAN {
            caller = q;
            call = a;
        }
    }
    if caller == 4u32 {
        for j in 1u32..SEATS {
            let q: u32 = (from + j) % SEATS;
            let a: u32 = s.claim_choices[q as usize];
            if a != NO_CHOICE && a != ACTION_PASS && a != ACTION_RON {
                caller = q;
                call = a;
            }
        }
    }
    clear_claims(s);
    if caller < 4u32 {
        return do_call(s, caller, from, v, call);
    }
    TASK_AFTER_DISCARD
}

fn four_riichi(s: &mut GameState) -> bool {
    let mut n: u32 = 0u32;
    for p in 0u32..SEATS {
        if (s.seat_flags[p as usize] & SEAT_RIICHI) != 0u32 {
            n += 1u32;
        }
    }
    n == 4u32
}

fn kan_seats(s: &mut GameState) -> u32 {
    let mut n: u32 = 0u32;
    for p in 0u32..SEATS {
        let mut has: bool = false;
        for i in 0u32..meld_count(s, p) {
            let k: u32 = meld_kind(s.melds[(p * 4u32 + i) as usize]);
            if k == MELD_OPEN_KAN || k == MELD_CLOSED_KAN || k == MELD_ADDED_KAN {
                has = true;
            }
        }
        if has {
            n += 1u32;
        }
    }
    n
}

// Four players only: three cannot discard four winds in the first go-round.
fn four_winds(s: &mut GameState) -> bool {
    if SEATS != 4u32 || s.uninterrupted == 0u32 {
        return false;
    }
    let first: u32 = s.rivers[0] & 63u32;
    if first < 27u32 || first > 30u32 {
        return false;
    }
    for p in 0u32..4u32 {
        if byte_of(s.river_lens, p) != 1u32 || (s.rivers[(p * 6u32) as usize] & 63u32) != first {
            return false;
        }
    }
    true
}

// The discard of `task_seat` stands: abortive checks, then the next draw or the exhaustive draw.
fn after_discard(s: &mut GameState) -> u32 {
    let from: u32 = s.task_seat;
    if ABORTIVE_DRAWS && s.kans == 4u32 && kan_seats(s) >= 2u32 {
        s.draw_kind = DRAW_FOUR_KANS;
        return TASK_ABORTIVE;
    }
    if ABORTIVE_DRAWS && four_winds(s) {
        s.draw_kind = DRAW_FOUR_WINDS;
        return TASK_ABORTIVE;
    }
    if s.next_draw >= s.live_end {
        s.task_flags = END_DRAWN;
        if settle_exhaustive_draw(s) {
            s.task_flags |= END_DEALER_CONTINUES;
        }
        return TASK_END_ROUND;
    }
    draw(s, (from + 1u32) % SEATS);
    TASK_DONE
}

fn take_for_chi(s: &mut GameState, q: u32, t: u32, red: bool) -> u32 {
    let v: u32 = take_type(s, q, t, red);
    (v >= 34u32) as u32
}

fn do_call(s: &mut GameState, q: u32, from: u32, v: u32, a: u32) -> u32 {
    let t: u32 = value_type(v);
    let len: u32 = byte_of(s.river_lens, from);
    if len > 0u32 {
        let i: u32 = len - 1u32;
        s.rivers[(from * 6u32 + i / 4u32) as usize] |= 64u32 << ((i % 4u32) * 8u32);
    }
    s.seat_flags[from as usize] &= !SEAT_NAGASHI;
    for p in 0u32..SEATS {
        s.seat_flags[p as usize] &= !SEAT_IPPATSU;
    }
    s.seat_flags[q as usize] &= !SEAT_CONCEALED;
    s.uninterrupted = 0u32;
    let mut reds: u32 = (v >= 34u32) as u32;
    let mut kind: u32 = MELD_PON;
    let mut low: u32 = t;
    let mut ban_b: u32 = 255u32;
    if a == ACTION_PON {
        take_tile(s, q, t);
        take_tile(s, q, t);
    } else if a == ACTION_PON_RED {
        take_tile(s, q, t);
        take_tile(s, q, 34u32 + t / 9u32);
        reds += 1u32;
    } else if a == ACTION_OPEN_KAN {
        kind = MELD_OPEN_KAN;
        reds += take_all_of_type(s, q, t, 3u32);
    } else {
        kind = MELD_CHI;
        let red: bool = a == ACTION_CHI_LEFT_RED || a == ACTION_CHI_MIDDLE_RED || a == ACTION_CHI_RIGHT_RED;
        if a == ACTION_CHI_LEFT || a == ACTION_CHI_LEFT_RED {
            reds += take_for_chi(s, q, t + 1u32, red) + take_for_chi(s, q, t + 2u32, red);
            if t % 9u32 <= 5u32 {
                ban_b = t + 3u32;
            }
        } else if a == ACTION_CHI_MIDDLE || a == ACTION_CHI_MIDDLE_RED {
            low = t - 1u32;
            reds += take_for_chi(s, q, t - 1u32, red) + take_for_chi(s, q, t + 1u32, red);
        } else {
            low = t - 2u32;
            reds += take_for_chi(s, q, t - 2u32, red) + take_for_chi(s, q, t - 1u32, red);
            if t % 9u32 >= 3u32 {
                ban_b = t - 3u32;
            }
        }
    }
    log_mark_called(s);
    let mut ev: u32 = EV_PON;
    let mut ev_flags: u32 = 0u32;
    if kind == MELD_OPEN_KAN {
        ev = EV_OPEN_KAN;
    } else if kind == MELD_CHI {
        ev = EV_CHI;
        ev_flags = t - low;
    }
    if reds > (v >= 34u32) as u32 {
        ev_flags |= LOG_WITH_RED;
    }
    log_push(s, ev, q, v, ev_flags);
    let n: u32 = meld_count(s, q);
    // The discarder's place from the caller: 1 the next seat, SEATS - 1 the one before.
    let src: u32 = (from + SEATS - q) % SEATS;
    s.melds[(q * 4u32 + n) as usize] = meld_word(kind, low) | (src << MELD_FROM_SHIFT) | (reds << MELD_REDS_SHIFT);
    s.meld_counts = with_byte(s.meld_counts, q, n + 1u32);
    if PAO && kind != MELD_CHI && t >= FIRST_HONOR {
        note_liability(s, q, from, t);
    }
    if PAO_SUUKANTSU && kind == MELD_OPEN_KAN && kan_melds(s, q) == 4u32 {
        // The seat that fed a fourth kan by an open kan pays for four kans.
        s.pao = with_byte(s.pao, q, (byte_of(s.pao, q) & 15u32) | ((from + 1u32) << 4u32));
    }
    if kind == MELD_OPEN_KAN {
        // The replacement draw may win: its tsumo check reads the new 13-tile waits.
        update_waits(s, q);
        reveal_pending_dora(s);
        s.dora_pending += 1u32;
        s.task_seat = q;
        s.task_flags = 0u32;
        return TASK_REPLACEMENT;
    }
    s.kuikae = t | (ban_b << 8u32);
    s.current = q;
    s.phase = PHASE_TURN;
    s.drawn = NO_TILE_VALUE;
    s.rinshan = 0u32;
    TASK_DONE
}

fn kan_melds(s: &mut GameState, q: u32) -> u32 {
    let mut kans: u32 = 0u32;
    for i in 0u32..meld_count(s, q) {
        let kind: u32 = meld_kind(s.melds[(q * 4u32 + i) as usize]);
        if kind == MELD_OPEN_KAN || kind == MELD_CLOSED_KAN || kind == MELD_ADDED_KAN {
            kans += 1u32;
        }
    }
    kans
}

// Pao: the seat that fed the third dragon set (or the fourth wind set) pays for the yakuman.
fn note_liability(s: &mut GameState, q: u32, from: u32, t: u32) {
    let mut dragons: u32 = 0u32;
    let mut winds: u32 = 0u32;
    for i in 0u32..meld_count(s, q) {
        let m: u32 = s.melds[(q * 4u32 + i) as usize];
        let mt: u32 = meld_tile(m);
        if meld_kind(m) != MELD_CHI {
            if is_dragon(mt) {
                dragons += 1u32;
            } else if is_wind(mt) {
                winds += 1u32;
            }
        }
    }
    if (is_dragon(t) && dragons == 3u32) || (is_wind(t) && winds == 4u32) {
        s.pao = with_byte(s.pao, q, (byte_of(s.pao, q) & 0xf0u32) | (from + 1u32));
    }
}
