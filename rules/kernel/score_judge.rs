// Judging one reading against the spec's yaku table: han, fu, limits and base points.

// The judged value of one reading, before payments.
#[derive(Clone, Copy)]
struct Judged {
    status: u32,
    han: u32,
    fu: u32,
    yakuman: u32,
    yaku_lo: u32,
    yaku_hi: u32,
    dora: u32,
    aka: u32,
    ura: u32,
    base: u32,
}

// `pub`: the Tenhou log writer names a hand's limit from it.
pub fn base_points(han: u32, fu: u32, yakuman: u32) -> u32 {
    if yakuman > 0u32 {
        return 8000u32 * yakuman;
    }
    if han >= 13u32 {
        if KAZOE_YAKUMAN {
            return 8000u32;
        }
        return 6000u32;
    }
    if han >= 11u32 {
        return 6000u32;
    }
    if han >= 8u32 {
        return 4000u32;
    }
    if han >= 6u32 {
        return 3000u32;
    }
    if han >= 5u32 {
        return MANGAN;
    }
    let raw: u32 = fu << (han + 2u32);
    if raw >= MANGAN {
        return MANGAN;
    }
    if KIRIAGE_MANGAN && raw == 1920u32 {
        return MANGAN;
    }
    raw
}

fn has_yaku(lo: u32, hi: u32, i: u32) -> bool {
    if i < 32u32 {
        return ((lo >> i) & 1u32) != 0u32;
    }
    ((hi >> (i - 32u32)) & 1u32) != 0u32
}

// The dora is the tile after its indicator, wrapping within its own group; three players have
// no 2m-8m, so 1m shows 9m (and 9m 1m).
fn dora_of(indicator: u32) -> u32 {
    let mut next: u32 = indicator + 1u32;
    if SEATS == 3u32 && indicator == 0u32 {
        next = 8u32;
    }
    if indicator < FIRST_HONOR {
        if indicator % 9u32 == 8u32 {
            next = indicator - 8u32;
        }
    } else if indicator < FIRST_DRAGON {
        if indicator == 30u32 {
            next = EAST;
        }
    } else if indicator == 33u32 {
        next = FIRST_DRAGON;
    }
    next
}

// Dora in the hand for `n` indicators; the North tiles set aside count as held Norths.
fn dora_count(h: HandInfo, indicators: [u32; 5], n: u32, kita: u32) -> u32 {
    let mut count: u32 = 0u32;
    for i in 0u32..n {
        let d: u32 = dora_of(indicators[i as usize]);
        count += h.full[d as usize];
        if d == NORTH {
            count += kita;
        }
    }
    count
}

// Apply the spec's yaku table to one reading. `fu` is the reading's fu before the tsumo bonus and
// rounding; `fixed_fu` (non-zero) overrides the fu rules for shapes with a flat value.
fn judge(inp: ScoreInput, h: HandInfo, f: Features, fu: u32, fixed_fu: u32) -> Judged {
    let held: [u32; 2] = yaku_conditions(f);
    let mut lo: u32 = 0u32;
    let mut hi: u32 = 0u32;
    let mut yakuman: u32 = 0u32;
    for i in 0u32..YAKU_COUNT {
        if has_yaku(held[0], held[1], i) && (f.concealed || YAKU_HAN_OPEN[i as usize] > 0u32 || YAKU_YAKUMAN[i as usize] > 0u32) {
            if i < 32u32 {
                lo |= 1u32 << i;
            } else {
                hi |= 1u32 << (i - 32u32);
            }
        }
    }
    let mut keep_lo: u32 = lo;
    let mut keep_hi: u32 = hi;
    for i in 0u32..YAKU_COUNT {
        if has_yaku(lo, hi, i) {
            keep_lo &= !YAKU_SUPERSEDES_LO[i as usize];
            keep_hi &= !YAKU_SUPERSEDES_HI[i as usize];
        }
    }
    for i in 0u32..YAKU_COUNT {
        if has_yaku(keep_lo, keep_hi, i) && YAKU_YAKUMAN[i as usize] > 0u32 {
            let mut weight: u32 = YAKU_YAKUMAN[i as usize];
            if !DOUBLE_YAKUMAN {
                weight = 1u32;
            }
            yakuman += weight;
        }
    }
    if yakuman > 0u32 {
        if !MULTIPLE_YAKUMAN && yakuman > 1u32 {
            yakuman = 1u32;
        }
        // A yakuman leaves no room for ordinary yaku.
        for i in 0u32..YAKU_COUNT {
            if YAKU_YAKUMAN[i as usize] == 0u32 {
                if i < 32u32 {
                    keep_lo &= !(1u32 << i);
                } else {
                    keep_hi &= !(1u32 << (i - 32u32));
                }
            }
        }
    }
    let mut han: u32 = 0u32;
    if yakuman == 0u32 {
        for i in 0u32..YAKU_COUNT {
            if has_yaku(keep_lo, keep_hi, i) {
                if f.concealed {
                    han += YAKU_HAN_CLOSED[i as usize];
                } else {
                    han += YAKU_HAN_OPEN[i as usize];
                }
            }
        }
    }
    let mut j: Judged = no_reading();
    j.status = STATUS_NO_YAKU;
    if yakuman == 0u32 && han == 0u32 {
        return j;
    }
    j.status = STATUS_WIN;
    j.yaku_lo = keep_lo;
    j.yaku_hi = keep_hi;
    j.yakuman = yakuman;
    if yakuman > 0u32 {
        j.base = base_points(0u32, 0u32, yakuman);
        return j;
    }
    // Each North set aside is a dora of its own as well (nukidora).
    j.dora = dora_count(h, inp.dora, inp.n_dora, inp.kita) + inp.kita;
    if f.riichi {
        j.ura = dora_count(h, inp.ura, inp.n_ura, inp.kita);
    }
    if RED_FIVES {
        j.aka = inp.aka;
    }
    j.han = han + j.dora + j.ura + j.aka;
    let mut total_fu: u32 = fixed_fu;
    if fixed_fu == 0u32 {
        total_fu = fu;
        if f.tsumo && !has_yaku(keep_lo, keep_hi, YAKU_PINFU) {
            total_fu += 2u32;
        }
        if !f.concealed && total_fu == 20u32 {
            total_fu = 30u32;
        }
        total_fu = (total_fu + 9u32) / 10u32 * 10u32;
    }
    j.fu = total_fu;
    j.base = base_points(j.han, j.fu, 0u32);
    j
}

// A win beats a complete hand without yaku, which beats no reading at all.
fn status_rank(status: u32) -> u32 {
    if status == STATUS_WIN {
        return 2u32;
    }
    if status == STATUS_NO_YAKU {
        return 1u32;
    }
    0u32
}

fn better(a: Judged, b: Judged) -> bool {
    if a.status != b.status {
        return status_rank(a.status) > status_rank(b.status);
    }
    if a.base != b.base {
        return a.base > b.base;
    }
    if a.han != b.han {
        return a.han > b.han;
    }
    a.fu > b.fu
}

fn no_reading() -> Judged {
    Judged {
        status: STATUS_NOT_COMPLETE,
        han: 0u32,
        fu: 0u32,
        yakuman: 0u32,
        yaku_lo: 0u32,
        yaku_hi: 0u32,
        dora: 0u32,
        aka: 0u32,
        ura: 0u32,
        base: 0u32,
    }
}
