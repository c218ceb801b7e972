// Hand scoring: every reading of a complete hand is judged against the yaku spec and the one that
// pays most wins (then more han, then more fu: Tenhou's choice). A reading is a decomposition of the
// concealed tiles (from the suit tables, every one of them) plus the set that the winning tile
// completed, or the seven-pairs / thirteen-orphans shape.

fn round_up_100(x: u32) -> u32 {
    (x + 99u32) / 100u32 * 100u32
}

// What a hand of `base` points costs, before honba: [a ron, the dealer's share of a non-dealer's
// tsumo (0 when the dealer won), each other payer's share of a tsumo]. `pub`: the Tenhou log
// writer prints these amounts.
pub fn hand_payments(base: u32, dealer: bool) -> [u32; 3] {
    if dealer {
        return [round_up_100(base * 6u32), 0u32, round_up_100(base * 2u32)];
    }
    [round_up_100(base * 4u32), round_up_100(base * 2u32), round_up_100(base)]
}

pub fn score_hand(inp: ScoreInput) -> ScoreOutput {
    if !input_is_valid(inp) {
        return empty_output(STATUS_BAD_INPUT);
    }
    let h: HandInfo = hand_info(inp);
    let common: Features = common_features(inp, h);
    let mut best: Judged = best_standard(inp, h, common);
    let seven: Judged = judge_seven_pairs(inp, h, common);
    if better(seven, best) {
        best = seven;
    }
    let orphans: Judged = judge_thirteen_orphans(inp, h, common);
    if better(orphans, best) {
        best = orphans;
    }
    let mut out: ScoreOutput = empty_output(best.status);
    if best.status != STATUS_WIN {
        return out;
    }
    out.han = best.han;
    out.fu = best.fu;
    out.yakuman = best.yakuman;
    out.yaku_lo = best.yaku_lo;
    out.yaku_hi = best.yaku_hi;
    out.dora = best.dora;
    out.aka = best.aka;
    out.ura = best.ura;
    out.base = best.base;
    out.concealed = h.concealed as u32;
    let dealer: bool = flag(inp, FLAG_DEALER);
    let sticks: u32 = inp.sticks * RIICHI_STICK_POINTS;
    let pays: [u32; 3] = hand_payments(best.base, dealer);
    if flag(inp, FLAG_TSUMO) {
        let honba: u32 = inp.honba * HONBA_TSUMO_POINTS;
        // Every other seat pays: three players lose the absent seat's share (tsumo loss).
        if dealer {
            out.others_pay = pays[2] + honba;
            out.gain = out.others_pay * (SEATS - 1u32) + sticks;
        } else {
            out.dealer_pays = pays[1] + honba;
            out.others_pay = pays[2] + honba;
            out.gain = out.dealer_pays + out.others_pay * (SEATS - 2u32) + sticks;
        }
    } else {
        out.ron = pays[0] + inp.honba * HONBA_RON_POINTS;
        out.gain = out.ron + sticks;
    }
    out
}
