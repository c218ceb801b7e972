// The hand features that yaku conditions in rules/yaku.toml are written over.

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
