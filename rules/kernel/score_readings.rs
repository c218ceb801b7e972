// Every reading of a complete hand: each decomposition from the suit tables with each place the
// winning tile can sit, seven pairs and thirteen orphans.

// One standard reading: the three suit decompositions (word pairs) and the winning slot.
fn judge_standard(inp: ScoreInput, h: HandInfo, common: Features, w0: [u32; 3], w1: [u32; 3], slot: u32, slot_tile: u32) -> Judged {
    let mut f: Features = common;
    let tsumo: bool = f.tsumo;
    let win: u32 = inp.win_tile;
    f.standard = true;
    f.runs = h.n_meld_runs;
    f.triplets = h.n_meld_triplets;
    f.concealed_triplets = h.closed_kans;
    f.outside = h.melds_outside;
    let mut fu: u32 = 20u32 + h.meld_fu;
    if f.concealed && !tsumo {
        fu += 10u32;
    }
    let mut pair_tile: u32 = NO_TILE;
    let mut run_masks: [u32; 3] = h.meld_runs;
    let mut triplet_masks: [u32; 3] = h.meld_triplets;
    for s in 0u32..3u32 {
        let a: u32 = w0[s as usize];
        let b: u32 = w1[s as usize];
        if (a & 15u32) != NO_PAIR {
            pair_tile = s * 9u32 + (a & 15u32);
        }
        let n_sets: u32 = (a >> 4u32) & 7u32;
        for k in 0u32..n_sets {
            let v: u32 = (a >> (8u32 + 4u32 * k)) & 15u32;
            if v <= 6u32 {
                f.runs += 1u32;
            } else {
                let pos: u32 = v - 7u32;
                let t: u32 = s * 9u32 + pos;
                let mut set_fu: u32 = 4u32;
                if pos == 0u32 || pos == 8u32 {
                    set_fu = 8u32;
                }
                f.triplets += 1u32;
                if !tsumo && slot == SLOT_TRIPLET && slot_tile == t {
                    set_fu = set_fu / 2u32;
                } else {
                    f.concealed_triplets += 1u32;
                }
                fu += set_fu;
            }
        }
        run_masks[s as usize] |= b & 127u32;
        triplet_masks[s as usize] |= (b >> 7u32) & 511u32;
        f.identical_runs += (b >> 16u32) & 3u32;
        if ((b >> 18u32) & 1u32) == 0u32 {
            f.outside = false;
        }
        if ((b >> 19u32) & 1u32) != 0u32 && inp.n_melds == 0u32 {
            f.nine_gates = true;
            let mut rest: [u32; 34] = inp.hand;
            rest[win as usize] -= 1u32;
            let mut exact: bool = true;
            for i in 0u32..9u32 {
                let mut want: u32 = 1u32;
                if i == 0u32 || i == 8u32 {
                    want = 3u32;
                }
                if rest[(s * 9u32 + i) as usize] != want {
                    exact = false;
                }
            }
            f.nine_gates_nine_wait = exact;
        }
    }
    for i in 0u32..7u32 {
        let t: u32 = FIRST_HONOR + i;
        let c: u32 = inp.hand[t as usize];
        if c == 2u32 {
            pair_tile = t;
        } else if c == 3u32 {
            f.triplets += 1u32;
            if !tsumo && slot == SLOT_TRIPLET && slot_tile == t {
                fu += 4u32;
            } else {
                f.concealed_triplets += 1u32;
                fu += 8u32;
            }
        }
    }
    if is_dragon(pair_tile) {
        fu += 2u32;
    }
    let seat_pair: bool = pair_tile == EAST + inp.seat_wind;
    let round_pair: bool = pair_tile == EAST + inp.round_wind;
    if seat_pair && round_pair {
        fu += DOUBLE_WIND_PAIR_FU;
    } else if seat_pair || round_pair {
        fu += 2u32;
    }
    f.pair_is_value = is_dragon(pair_tile) || pair_tile == EAST + inp.seat_wind || pair_tile == EAST + inp.round_wind;
    f.dragon_pair = is_dragon(pair_tile);
    f.wind_pair = is_wind(pair_tile);
    if slot == SLOT_PAIR {
        f.pair_wait = true;
        fu += 2u32;
    } else if slot == SLOT_RUN {
        let start: u32 = slot_tile % 9u32;
        let pos: u32 = win % 9u32;
        if pos == start + 1u32 {
            fu += 2u32;
        } else if (pos == start && start == 6u32) || (pos == start + 2u32 && start == 0u32) {
            fu += 2u32;
        } else {
            f.two_sided_wait = true;
        }
    }
    for s in 0u32..3u32 {
        if (run_masks[s as usize] & 73u32) == 73u32 {
            f.straight = true;
        }
    }
    f.three_colour_runs = (run_masks[0] & run_masks[1] & run_masks[2]) != 0u32;
    f.three_colour_triplets = (triplet_masks[0] & triplet_masks[1] & triplet_masks[2]) != 0u32;
    judge(inp, h, f, fu, 0u32)
}

fn decomp_word(index: u32, k: u32, word: u32) -> u32 {
    table(T_DECOMPS + ((index >> 4u32) + k) * 2u32 + word)
}

// Every standard reading of the hand; returns the best one (or STATUS_NOT_COMPLETE).
fn best_standard(inp: ScoreInput, h: HandInfo, common: Features) -> Judged {
    let mut best: Judged = no_reading();
    let mut honor_pairs: u32 = 0u32;
    for i in 0u32..7u32 {
        let c: u32 = inp.hand[(FIRST_HONOR + i) as usize];
        if c == 1u32 || c == 4u32 {
            return best;
        }
        if c == 2u32 {
            honor_pairs += 1u32;
        }
    }
    let idx0: u32 = table(T_DECOMP_INDEX + suit_code(inp.hand, 0u32));
    let idx1: u32 = table(T_DECOMP_INDEX + suit_code(inp.hand, 1u32));
    let idx2: u32 = table(T_DECOMP_INDEX + suit_code(inp.hand, 2u32));
    let win: u32 = inp.win_tile;
    let win_suit: u32 = win / 9u32;
    let win_pos: u32 = win % 9u32;
    for a in 0u32..(idx0 & 15u32) {
        for b in 0u32..(idx1 & 15u32) {
            for c in 0u32..(idx2 & 15u32) {
                let w0: [u32; 3] = [decomp_word(idx0, a, 0u32), decomp_word(idx1, b, 0u32), decomp_word(idx2, c, 0u32)];
                let w1: [u32; 3] = [decomp_word(idx0, a, 1u32), decomp_word(idx1, b, 1u32), decomp_word(idx2, c, 1u32)];
                let mut pairs: u32 = honor_pairs;
                for s in 0u32..3u32 {
                    if (w0[s as usize] & 15u32) != NO_PAIR {
                        pairs += 1u32;
                    }
                }
                if pairs != 1u32 {
                    continue;
                }
                // The places the winning tile can sit: k = 0 pair, 1 triplet, 2..4 a run starting
                // 0, 1 or 2 tiles below it. One call site keeps GPU compilers from inlining
                // `judge_standard` once per case.
                let a0: u32 = w0[(win_suit % 3u32) as usize];
                let a1: u32 = w1[(win_suit % 3u32) as usize];
                for k in 0u32..5u32 {
                    let mut slot: u32 = SLOT_RUN;
                    let mut slot_tile: u32 = win;
                    let mut fits: bool = false;
                    if is_honor(win) {
                        // Honors are pairs or triplets only, fixed by their count.
                        if k == 0u32 && inp.hand[win as usize] == 2u32 {
                            slot = SLOT_PAIR;
                            fits = true;
                        } else if k == 1u32 && inp.hand[win as usize] == 3u32 {
                            slot = SLOT_TRIPLET;
                            fits = true;
                        }
                    } else if k == 0u32 {
                        slot = SLOT_PAIR;
                        fits = (a0 & 15u32) == win_pos;
                    } else if k == 1u32 {
                        slot = SLOT_TRIPLET;
                        fits = ((a1 >> (7u32 + win_pos)) & 1u32) != 0u32;
                    } else {
                        let d: u32 = k - 2u32;
                        if win_pos >= d && win_pos - d <= 6u32 && ((a1 >> (win_pos - d)) & 1u32) != 0u32 {
                            slot_tile = win - d;
                            fits = true;
                        }
                    }
                    if fits {
                        let j: Judged = judge_standard(inp, h, common, w0, w1, slot, slot_tile);
                        if better(j, best) {
                            best = j;
                        }
                    }
                }
            }
        }
    }
    best
}

fn judge_seven_pairs(inp: ScoreInput, h: HandInfo, common: Features) -> Judged {
    if inp.n_melds != 0u32 {
        return no_reading();
    }
    for t in 0u32..N_TYPES {
        let c: u32 = inp.hand[t as usize];
        if c != 0u32 && c != 2u32 {
            return no_reading();
        }
    }
    let mut f: Features = common;
    f.seven_pairs = true;
    f.pair_wait = true;
    judge(inp, h, f, 25u32, 25u32)
}

fn judge_thirteen_orphans(inp: ScoreInput, h: HandInfo, common: Features) -> Judged {
    if inp.n_melds != 0u32 {
        return no_reading();
    }
    for t in 0u32..N_TYPES {
        let c: u32 = inp.hand[t as usize];
        if is_terminal_or_honor(t) {
            if c == 0u32 || c > 2u32 {
                return no_reading();
            }
        } else if c != 0u32 {
            return no_reading();
        }
    }
    let mut f: Features = common;
    f.thirteen_orphans = true;
    f.thirteen_wait = inp.hand[inp.win_tile as usize] == 2u32;
    judge(inp, h, f, 0u32, 0u32)
}
