// Hand scoring: every reading of a complete hand is judged against the yaku spec and the one that
// pays most wins (then more han, then more fu: Tenhou's choice). A reading is a decomposition of the
// concealed tiles (from the suit tables, every one of them) plus the set that the winning tile
// completed, or the seven-pairs / thirteen-orphans shape.

// Meld word: kind in bits 0-3, tile type in bits 4-9 (for a chi: the lowest tile of the run).
const MELD_CHI: u32 = 0;
const MELD_PON: u32 = 1;
const MELD_OPEN_KAN: u32 = 2;
const MELD_CLOSED_KAN: u32 = 3;
const MELD_ADDED_KAN: u32 = 4;

// Situation flags of a win.
const FLAG_TSUMO: u32 = 1;
const FLAG_RIICHI: u32 = 2;
const FLAG_DOUBLE_RIICHI: u32 = 4;
const FLAG_IPPATSU: u32 = 8;
const FLAG_HAITEI: u32 = 16;
const FLAG_HOUTEI: u32 = 32;
const FLAG_RINSHAN: u32 = 64;
const FLAG_CHANKAN: u32 = 128;
const FLAG_TENHOU: u32 = 256;
const FLAG_CHIIHOU: u32 = 512;
const FLAG_DEALER: u32 = 1024;

const STATUS_WIN: u32 = 0;
const STATUS_NOT_COMPLETE: u32 = 1;
const STATUS_NO_YAKU: u32 = 2;
const STATUS_BAD_INPUT: u32 = 3;

// Which set of the reading the winning tile completed.
const SLOT_PAIR: u32 = 0;
const SLOT_TRIPLET: u32 = 1;
const SLOT_RUN: u32 = 2;

const NO_PAIR: u32 = 15;
const NO_TILE: u32 = 99;
const MANGAN: u32 = 2000;

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ScoreInput {
    // Concealed tiles, the winning tile included.
    pub hand: [u32; 34],
    pub win_tile: u32,
    pub melds: [u32; 4],
    pub n_melds: u32,
    pub flags: u32,
    // 0..3 = E S W N
    pub round_wind: u32,
    pub seat_wind: u32,
    pub dora: [u32; 5],
    pub n_dora: u32,
    pub ura: [u32; 5],
    pub n_ura: u32,
    // Red fives among all of the winner's tiles, melds included.
    pub aka: u32,
    pub honba: u32,
    pub sticks: u32,
}

#[derive(Clone, Copy)]
#[repr(C)]
pub struct ScoreOutput {
    pub status: u32,
    pub han: u32,
    pub fu: u32,
    pub yakuman: u32,
    pub yaku_lo: u32,
    pub yaku_hi: u32,
    pub dora: u32,
    pub aka: u32,
    pub ura: u32,
    pub base: u32,
    // Ron: what the discarder pays, honba included.
    pub ron: u32,
    // Tsumo: what the dealer pays (non-dealer win) and what each other payer pays.
    pub dealer_pays: u32,
    pub others_pay: u32,
    // The winner's whole gain, riichi sticks included.
    pub gain: u32,
    // 1 when no meld was called (closed kans allowed): selects the closed han of each yaku.
    pub concealed: u32,
}

// What does not depend on the reading.
#[derive(Clone, Copy)]
struct HandInfo {
    full: [u32; 34],
    concealed: bool,
    meld_runs: [u32; 3],
    meld_triplets: [u32; 3],
    n_meld_runs: u32,
    n_meld_triplets: u32,
    kans: u32,
    closed_kans: u32,
    meld_fu: u32,
    melds_outside: bool,
    // bit i = a triplet or quad of honor 27 + i, concealed or called
    honor_sets: u32,
}

fn flag(inp: ScoreInput, f: u32) -> bool {
    (inp.flags & f) != 0u32
}

fn meld_kind(m: u32) -> u32 {
    m & 15u32
}

fn meld_tile(m: u32) -> u32 {
    (m >> 4u32) & 63u32
}

fn empty_output(status: u32) -> ScoreOutput {
    ScoreOutput {
        status: status,
        han: 0u32,
        fu: 0u32,
        yakuman: 0u32,
        yaku_lo: 0u32,
        yaku_hi: 0u32,
        dora: 0u32,
        aka: 0u32,
        ura: 0u32,
        base: 0u32,
        ron: 0u32,
        dealer_pays: 0u32,
        others_pay: 0u32,
        gain: 0u32,
        concealed: 0u32,
    }
}

fn input_is_valid(inp: ScoreInput) -> bool {
    if inp.n_melds > 4u32 || inp.win_tile >= N_TYPES || inp.round_wind > 3u32 || inp.seat_wind > 3u32 {
        return false;
    }
    if inp.n_dora > 5u32 || inp.n_ura > 5u32 || inp.aka > 4u32 {
        return false;
    }
    let mut all: [u32; 34] = inp.hand;
    let mut concealed_tiles: u32 = 0u32;
    for t in 0u32..N_TYPES {
        concealed_tiles += inp.hand[t as usize];
    }
    for i in 0u32..inp.n_melds {
        let m: u32 = inp.melds[i as usize];
        let kind: u32 = meld_kind(m);
        let t: u32 = meld_tile(m);
        if kind > MELD_ADDED_KAN || t >= N_TYPES {
            return false;
        }
        if kind == MELD_CHI {
            if is_honor(t) || t % 9u32 > 6u32 {
                return false;
            }
            all[t as usize] += 1u32;
            all[(t + 1u32) as usize] += 1u32;
            all[(t + 2u32) as usize] += 1u32;
        } else if kind == MELD_PON {
            all[t as usize] += 3u32;
        } else {
            all[t as usize] += 4u32;
        }
    }
    for t in 0u32..N_TYPES {
        if all[t as usize] > 4u32 {
            return false;
        }
    }
    for i in 0u32..inp.n_dora {
        if inp.dora[i as usize] >= N_TYPES {
            return false;
        }
    }
    for i in 0u32..inp.n_ura {
        if inp.ura[i as usize] >= N_TYPES {
            return false;
        }
    }
    concealed_tiles + 3u32 * inp.n_melds == 14u32 && inp.hand[inp.win_tile as usize] >= 1u32
}

fn hand_info(inp: ScoreInput) -> HandInfo {
    let mut h: HandInfo = HandInfo {
        full: inp.hand,
        concealed: true,
        meld_runs: [0u32; 3],
        meld_triplets: [0u32; 3],
        n_meld_runs: 0u32,
        n_meld_triplets: 0u32,
        kans: 0u32,
        closed_kans: 0u32,
        meld_fu: 0u32,
        melds_outside: true,
        honor_sets: 0u32,
    };
    for i in 0u32..inp.n_melds {
        let m: u32 = inp.melds[i as usize];
        let kind: u32 = meld_kind(m);
        let t: u32 = meld_tile(m);
        if kind != MELD_CLOSED_KAN {
            h.concealed = false;
        }
        if kind == MELD_CHI {
            h.full[t as usize] += 1u32;
            h.full[(t + 1u32) as usize] += 1u32;
            h.full[(t + 2u32) as usize] += 1u32;
            h.meld_runs[(t / 9u32) as usize] |= 1u32 << (t % 9u32);
            h.n_meld_runs += 1u32;
            if t % 9u32 != 0u32 && t % 9u32 != 6u32 {
                h.melds_outside = false;
            }
        } else {
            let mut fu: u32 = 2u32;
            if kind == MELD_PON {
                h.full[t as usize] += 3u32;
            } else {
                h.full[t as usize] += 4u32;
                h.kans += 1u32;
                fu = 8u32;
                if kind == MELD_CLOSED_KAN {
                    h.closed_kans += 1u32;
                    fu = 16u32;
                }
            }
            if is_terminal_or_honor(t) {
                fu = fu * 2u32;
            } else {
                h.melds_outside = false;
            }
            h.meld_fu += fu;
            h.n_meld_triplets += 1u32;
            if is_honor(t) {
                h.honor_sets |= 1u32 << (t - FIRST_HONOR);
            } else {
                h.meld_triplets[(t / 9u32) as usize] |= 1u32 << (t % 9u32);
            }
        }
    }
    for i in 0u32..7u32 {
        if inp.hand[(FIRST_HONOR + i) as usize] >= 3u32 {
            h.honor_sets |= 1u32 << i;
        }
    }
    h
}

fn no_features() -> Features {
    Features {
        concealed: false,
        tsumo: false,
        riichi: false,
        double_riichi: false,
        ippatsu: false,
        haitei: false,
        houtei: false,
        rinshan: false,
        chankan: false,
        tenhou: false,
        chiihou: false,
        dealer: false,
        standard: false,
        seven_pairs: false,
        thirteen_orphans: false,
        thirteen_wait: false,
        all_simples: false,
        no_simples: false,
        honors_only: false,
        green_only: false,
        has_honors: false,
        suits: 0u32,
        outside: false,
        runs: 0u32,
        triplets: 0u32,
        concealed_triplets: 0u32,
        kans: 0u32,
        identical_runs: 0u32,
        two_sided_wait: false,
        pair_wait: false,
        pair_is_value: false,
        seat_wind_set: false,
        round_wind_set: false,
        white_set: false,
        green_set: false,
        red_set: false,
        dragon_sets: 0u32,
        wind_sets: 0u32,
        dragon_pair: false,
        wind_pair: false,
        straight: false,
        three_colour_runs: false,
        three_colour_triplets: false,
        nine_gates: false,
        nine_gates_nine_wait: false,
    }
}

// Features that hold for every reading of this hand.
fn common_features(inp: ScoreInput, h: HandInfo) -> Features {
    let mut f: Features = no_features();
    f.concealed = h.concealed;
    f.tsumo = flag(inp, FLAG_TSUMO);
    f.riichi = flag(inp, FLAG_RIICHI) || flag(inp, FLAG_DOUBLE_RIICHI);
    f.double_riichi = flag(inp, FLAG_DOUBLE_RIICHI);
    f.ippatsu = flag(inp, FLAG_IPPATSU);
    f.haitei = flag(inp, FLAG_HAITEI);
    f.houtei = flag(inp, FLAG_HOUTEI);
    f.rinshan = flag(inp, FLAG_RINSHAN);
    f.chankan = flag(inp, FLAG_CHANKAN);
    f.tenhou = flag(inp, FLAG_TENHOU);
    f.chiihou = flag(inp, FLAG_CHIIHOU);
    f.dealer = flag(inp, FLAG_DEALER);
    let mut simples: u32 = 0u32;
    let mut honors: u32 = 0u32;
    let mut greens: u32 = 0u32;
    let mut total: u32 = 0u32;
    let mut suit_mask: u32 = 0u32;
    for t in 0u32..N_TYPES {
        let c: u32 = h.full[t as usize];
        total += c;
        if c > 0u32 {
            if is_honor(t) {
                honors += c;
            } else {
                suit_mask |= 1u32 << (t / 9u32);
                if !is_terminal_or_honor(t) {
                    simples += c;
                }
            }
            if is_green(t) {
                greens += c;
            }
        }
    }
    f.all_simples = simples == total;
    f.no_simples = simples == 0u32;
    f.honors_only = honors == total;
    f.green_only = greens == total;
    f.has_honors = honors > 0u32;
    f.suits = suit_mask.count_ones();
    f.kans = h.kans;
    f.seat_wind_set = ((h.honor_sets >> inp.seat_wind) & 1u32) != 0u32;
    f.round_wind_set = ((h.honor_sets >> inp.round_wind) & 1u32) != 0u32;
    f.white_set = ((h.honor_sets >> 4u32) & 1u32) != 0u32;
    f.green_set = ((h.honor_sets >> 5u32) & 1u32) != 0u32;
    f.red_set = ((h.honor_sets >> 6u32) & 1u32) != 0u32;
    f.dragon_sets = ((h.honor_sets >> 4u32) & 7u32).count_ones();
    f.wind_sets = (h.honor_sets & 15u32).count_ones();
    f
}

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

fn base_points(han: u32, fu: u32, yakuman: u32) -> u32 {
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

fn dora_count(h: HandInfo, indicators: [u32; 5], n: u32) -> u32 {
    let mut count: u32 = 0u32;
    for i in 0u32..n {
        count += h.full[dora_of(indicators[i as usize]) as usize];
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
    j.dora = dora_count(h, inp.dora, inp.n_dora);
    if f.riichi {
        j.ura = dora_count(h, inp.ura, inp.n_ura);
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
    if pair_tile == EAST + inp.seat_wind {
        fu += 2u32;
    }
    if pair_tile == EAST + inp.round_wind {
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
                if is_honor(win) {
                    let mut slot: u32 = SLOT_TRIPLET;
                    if inp.hand[win as usize] == 2u32 {
                        slot = SLOT_PAIR;
                    }
                    let j: Judged = judge_standard(inp, h, common, w0, w1, slot, win);
                    if better(j, best) {
                        best = j;
                    }
                    continue;
                }
                let a0: u32 = w0[win_suit as usize];
                let a1: u32 = w1[win_suit as usize];
                if (a0 & 15u32) == win_pos {
                    let j: Judged = judge_standard(inp, h, common, w0, w1, SLOT_PAIR, win);
                    if better(j, best) {
                        best = j;
                    }
                }
                if ((a1 >> (7u32 + win_pos)) & 1u32) != 0u32 {
                    let j: Judged = judge_standard(inp, h, common, w0, w1, SLOT_TRIPLET, win);
                    if better(j, best) {
                        best = j;
                    }
                }
                for d in 0u32..3u32 {
                    if win_pos >= d && win_pos - d <= 6u32 && ((a1 >> (win_pos - d)) & 1u32) != 0u32 {
                        let j: Judged = judge_standard(inp, h, common, w0, w1, SLOT_RUN, win - d);
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

fn round_up_100(x: u32) -> u32 {
    (x + 99u32) / 100u32 * 100u32
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
    if flag(inp, FLAG_TSUMO) {
        let honba: u32 = inp.honba * HONBA_TSUMO_POINTS;
        if dealer {
            out.others_pay = round_up_100(best.base * 2u32) + honba;
            out.gain = out.others_pay * 3u32 + sticks;
        } else {
            out.dealer_pays = round_up_100(best.base * 2u32) + honba;
            out.others_pay = round_up_100(best.base) + honba;
            out.gain = out.dealer_pays + out.others_pay * 2u32 + sticks;
        }
    } else {
        let mut mult: u32 = 4u32;
        if dealer {
            mult = 6u32;
        }
        out.ron = round_up_100(best.base * mult) + inp.honba * HONBA_RON_POINTS;
        out.gain = out.ron + sticks;
    }
    out
}
