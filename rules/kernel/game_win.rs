// Wins and draws: judging a win with the scoring kernel, paying it, and the ends of a round that
// come without a win.

fn seat_wind_of(s: &mut GameState, seat: u32) -> u32 {
    (seat + SEATS - s.dealer) % SEATS
}

// The scoring kernel's input for `seat` winning on tile value `v`.
fn win_input(s: &mut GameState, seat: u32, v: u32, tsumo: bool, chankan: bool) -> ScoreInput {
    let mut hand: [u32; 34] = hand_counts(s, seat);
    let mut aka: u32 = 0u32;
    for suit in 0u32..3u32 {
        if holds_red(s, seat, suit) {
            aka += 1u32;
        }
    }
    if !tsumo {
        hand[value_type(v) as usize] += 1u32;
        if v >= 34u32 {
            aka += 1u32;
        }
    }
    let mut melds: [u32; 4] = [0u32; 4];
    let n: u32 = meld_count(s, seat);
    for i in 0u32..n {
        let m: u32 = s.melds[(seat * 4u32 + i) as usize];
        melds[i as usize] = m & ((1u32 << MELD_FROM_SHIFT) - 1u32);
        aka += (m >> MELD_REDS_SHIFT) & 7u32;
    }
    let f: u32 = s.seat_flags[seat as usize];
    let mut flags: u32 = 0u32;
    if tsumo {
        flags |= FLAG_TSUMO;
        if s.rinshan != 0u32 {
            flags |= FLAG_RINSHAN;
        } else if s.next_draw >= s.live_end {
            flags |= FLAG_HAITEI;
        }
        if s.uninterrupted != 0u32 && (f & SEAT_DISCARDED) == 0u32 {
            if seat == s.dealer {
                flags |= FLAG_TENHOU;
            } else {
                flags |= FLAG_CHIIHOU;
            }
        }
    } else if chankan {
        flags |= FLAG_CHANKAN;
    } else if s.next_draw >= s.live_end {
        flags |= FLAG_HOUTEI;
    }
    if (f & SEAT_RIICHI) != 0u32 {
        flags |= FLAG_RIICHI;
        if (f & SEAT_DOUBLE_RIICHI) != 0u32 {
            flags |= FLAG_DOUBLE_RIICHI;
        }
        if (f & SEAT_IPPATSU) != 0u32 {
            flags |= FLAG_IPPATSU;
        }
    }
    if seat == s.dealer {
        flags |= FLAG_DEALER;
    }
    let mut dora: [u32; 5] = [0u32; 5];
    let mut ura: [u32; 5] = [0u32; 5];
    for k in 0u32..s.dora_revealed {
        dora[k as usize] = value_type(wall_tile(s, WALL_DORA + k));
        ura[k as usize] = value_type(wall_tile(s, WALL_URA + k));
    }
    ScoreInput {
        hand: hand,
        win_tile: value_type(v),
        melds: melds,
        n_melds: n,
        flags: flags,
        round_wind: round_wind_of(s.round),
        seat_wind: seat_wind_of(s, seat),
        dora: dora,
        n_dora: s.dora_revealed,
        ura: ura,
        n_ura: s.dora_revealed,
        aka: aka,
        kita: kita_count(s, seat),
        honba: s.honba,
        sticks: s.sticks,
    }
}

fn can_win(s: &mut GameState, seat: u32, v: u32, tsumo: bool, chankan: bool) -> bool {
    if !waits_include(s, seat, value_type(v)) {
        return false;
    }
    score_hand(win_input(s, seat, v, tsumo, chankan)).status == STATUS_WIN
}

fn pay(s: &mut GameState, from: u32, to: u32, points: u32) {
    s.scores[from as usize] -= points as i32;
    s.scores[to as usize] += points as i32;
    s.rewards[from as usize] -= (points / 100u32) as i32;
    s.rewards[to as usize] += (points / 100u32) as i32;
}

fn collect_sticks(s: &mut GameState, to: u32) {
    let points: u32 = s.sticks * RIICHI_STICK_POINTS;
    s.scores[to as usize] += points as i32;
    s.rewards[to as usize] += (points / 100u32) as i32;
    s.sticks = 0u32;
}

// The yakuman the winner's liable seat pays for (pao), or YAKU_COUNT for none: big dragons or big
// winds fed by a call, else (PAO_SUUKANTSU) four kans whose fourth was an open kan. A hand with
// both, fed by two seats, charges the first only. The log writer reads it too.
pub fn pao_yaku(s: &mut GameState, winner: u32, out: ScoreOutput) -> u32 {
    let p: u32 = byte_of(s.pao, winner);
    if !PAO || p == 0u32 {
        return YAKU_COUNT;
    }
    if (p & 15u32) != 0u32 {
        if has_yaku(out.yaku_lo, out.yaku_hi, YAKU_DAISANGEN) {
            return YAKU_DAISANGEN;
        }
        if has_yaku(out.yaku_lo, out.yaku_hi, YAKU_DAISUUSHI) {
            return YAKU_DAISUUSHI;
        }
    }
    if PAO_SUUKANTSU && (p >> 4u32) != 0u32 && has_yaku(out.yaku_lo, out.yaku_hi, YAKU_SUUKANTSU) {
        return YAKU_SUUKANTSU;
    }
    YAKU_COUNT
}

// The seat liable for the winner's `pao` yakuman (see `pao_yaku`), or 4 for none.
pub fn liable_seat(s: &mut GameState, winner: u32, pao: u32) -> u32 {
    if pao == YAKU_COUNT {
        return 4u32;
    }
    let p: u32 = byte_of(s.pao, winner);
    if pao == YAKU_SUUKANTSU {
        return (p >> 4u32) - 1u32;
    }
    (p & 15u32) - 1u32
}

// The part of a hand of `yakuman` yakuman the liable seat covers, as [numerator, denominator]:
// the whole hand, or with PAO_SHARE_ONLY the `pao` yakuman's weight over the hand's yakuman total
// (daisangen in a daisangen + tsuuiisou double: half). The log writer reads it too.
pub fn pao_share(yakuman: u32, pao: u32) -> [u32; 2] {
    if !PAO_SHARE_ONLY || yakuman == 0u32 || pao == YAKU_COUNT {
        return [1u32, 1u32];
    }
    let mut weight: u32 = YAKU_YAKUMAN[pao as usize];
    if !DOUBLE_YAKUMAN {
        weight = 1u32;
    }
    [weight.min(yakuman), yakuman]
}

fn note_win(s: &mut GameState, seat: u32, out: ScoreOutput) {
    s.winners |= 1u32 << seat;
    s.yaku[0] |= out.yaku_lo;
    s.yaku[1] |= out.yaku_hi;
    s.win_yaku[(seat * 2u32) as usize] = out.yaku_lo;
    s.win_yaku[(seat * 2u32 + 1u32) as usize] = out.yaku_hi;
    s.win_score[(seat * 2u32) as usize] = out.han
        | (out.fu << WIN_FU_SHIFT)
        | (out.yakuman << WIN_YAKUMAN_SHIFT)
        | (out.concealed << WIN_CONCEALED_SHIFT);
    s.win_score[(seat * 2u32 + 1u32) as usize] = out.dora | (out.aka << WIN_AKA_SHIFT) | (out.ura << WIN_URA_SHIFT);
}

// Pays a ron; `first` is the winner nearest the discarder, who also takes honba and sticks.
fn settle_ron(s: &mut GameState, winner: u32, from: u32, v: u32, chankan: bool, first: bool) {
    let mut inp: ScoreInput = win_input(s, winner, v, false, chankan);
    if !first {
        inp.honba = 0u32;
        inp.sticks = 0u32;
    }
    let out: ScoreOutput = score_hand(inp);
    let pao: u32 = pao_yaku(s, winner, out);
    let liable: u32 = liable_seat(s, winner, pao);
    if liable < 4u32 && liable != from {
        // The liable seat pays half of what it covers; the discarder the rest, and the honba
        // unless PAO_PAYS_HONBA puts them on the liable seat.
        let honba: u32 = inp.honba * HONBA_RON_POINTS;
        let value: u32 = out.ron - honba;
        let share: [u32; 2] = pao_share(out.yakuman, pao);
        let covered: u32 = value / share[1] * share[0];
        let liable_honba: u32 = honba * PAO_PAYS_HONBA as u32;
        pay(s, liable, winner, covered / 2u32 + liable_honba);
        pay(s, from, winner, value - covered / 2u32 + honba - liable_honba);
    } else {
        pay(s, from, winner, out.ron);
    }
    if first {
        collect_sticks(s, winner);
    }
    note_win(s, winner, out);
    s.events |= EVENT_RON;
    s.deal_in = from + 1u32;
}

fn settle_tsumo(s: &mut GameState, winner: u32) {
    let inp: ScoreInput = win_input(s, winner, s.drawn, true, false);
    let out: ScoreOutput = score_hand(inp);
    let pao: u32 = pao_yaku(s, winner, out);
    let liable: u32 = liable_seat(s, winner, pao);
    let share: [u32; 2] = pao_share(out.yakuman, pao);
    // Three players pay a tsumo at four-player rates, the absent seat's share lost (tsumo loss).
    for p in 0u32..SEATS {
        if p != winner {
            let mut amount: u32 = out.others_pay;
            if p == s.dealer && winner != s.dealer {
                amount = out.dealer_pays;
            }
            if liable < 4u32 && share[0] < share[1] {
                // A composite hand: the liable seat pays the pao yakuman's part of each payment,
                // the payer the rest, and its honba unless PAO_PAYS_HONBA puts them on the liable
                // seat.
                let honba: u32 = inp.honba * HONBA_TSUMO_POINTS;
                let covered: u32 = (amount - honba) / share[1] * share[0] + honba * PAO_PAYS_HONBA as u32;
                pay(s, liable, winner, covered);
                pay(s, p, winner, amount - covered);
            } else if liable < 4u32 {
                pay(s, liable, winner, amount);
            } else {
                pay(s, p, winner, amount);
            }
        }
    }
    collect_sticks(s, winner);
    note_win(s, winner, out);
    s.events |= EVENT_TSUMO;
}

// The wall ran out: nagashi mangan (if the variant has it) replaces the tenpai payments.
fn settle_exhaustive_draw(s: &mut GameState) -> bool {
    let mut tenpai: u32 = 0u32;
    let mut n_tenpai: u32 = 0u32;
    let mut nagashi: u32 = 0u32;
    for p in 0u32..SEATS {
        if seat_tenpai(s, p) {
            tenpai |= 1u32 << p;
            n_tenpai += 1u32;
        }
        let f: u32 = s.seat_flags[p as usize];
        if NAGASHI_MANGAN && (f & SEAT_NAGASHI) != 0u32 && (f & SEAT_DISCARDED) != 0u32 {
            nagashi |= 1u32 << p;
        }
    }
    if nagashi != 0u32 {
        for w in 0u32..SEATS {
            if ((nagashi >> w) & 1u32) != 0u32 {
                for p in 0u32..SEATS {
                    if p != w {
                        let mut amount: u32 = 2000u32;
                        if p == s.dealer || w == s.dealer {
                            amount = 4000u32;
                        }
                        pay(s, p, w, amount);
                    }
                }
            }
        }
        s.events |= EVENT_NAGASHI;
        s.draw_kind = DRAW_NAGASHI | (tenpai << DRAW_TENPAI_SHIFT) | (nagashi << DRAW_NAGASHI_SHIFT);
    } else if n_tenpai > 0u32 && n_tenpai < SEATS {
        let gain: u32 = NOTEN_POOL_POINTS / n_tenpai;
        let loss: u32 = NOTEN_POOL_POINTS / (SEATS - n_tenpai);
        for p in 0u32..SEATS {
            if ((tenpai >> p) & 1u32) != 0u32 {
                s.scores[p as usize] += gain as i32;
                s.rewards[p as usize] += (gain / 100u32) as i32;
            } else {
                s.scores[p as usize] -= loss as i32;
                s.rewards[p as usize] -= (loss / 100u32) as i32;
            }
        }
    }
    if nagashi == 0u32 {
        s.draw_kind = DRAW_EXHAUSTIVE | (tenpai << DRAW_TENPAI_SHIFT);
    }
    s.events |= EVENT_EXHAUSTIVE_DRAW;
    ((tenpai >> s.dealer) & 1u32) != 0u32
}
