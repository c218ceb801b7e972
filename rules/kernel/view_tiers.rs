// The two opt-in outputs beside the observation. Analysis: what the observer's own hand can do
// (computed from its hand and the tiles it has seen, so it leaks nothing the observation does
// not). Oracle: what the observer cannot see (other hands, the wall in draw order, the hidden
// dead wall), for oracle guiding and centralised critics; never part of an observation.

fn put_word_byte(out: &mut [u32; 34], i: u32, v: u32) {
    out[(i / 4u32) as usize] |= (v & 255u32) << ((i % 4u32) * 8u32);
}

fn put_oracle_byte(out: &mut [u32; 78], i: u32, v: u32) {
    out[(i / 4u32) as usize] |= (v & 255u32) << ((i % 4u32) * 8u32);
}

// Unseen copies per type from what the observer has seen; ukeire of a 3k+1 hand (of shanten
// `base`) over them.
fn improving_tiles(h: [u32; 34], base: i32, unseen: [u32; 34]) -> [u32; 34] {
    let after: [i32; 34] = shanten_after_draws(h);
    let mut out: [u32; 34] = [0u32; 34];
    for t in 0u32..34u32 {
        out[t as usize] = unseen[t as usize] * ((after[t as usize] < base) as u32);
    }
    out
}

pub fn observe_analysis(state: GameState, arg: u32) -> ObsAnalysis {
    let mut s: GameState = state;
    analysis_of(&mut s, arg)
}

fn analysis_of(s: &mut GameState, arg: u32) -> ObsAnalysis {
    let seat: u32 = observer(s, arg);
    let v: Seen = gather(s, seat);
    let hand: [u32; 34] = hand_counts(s, seat);
    let mut out: [u32; 34] = [0u32; 34];
    let mut unseen: [u32; 34] = [0u32; 34];
    let mut tiles: u32 = 0u32;
    for t in 0u32..34u32 {
        unseen[t as usize] = 4u32 - cell_of(v.seen_cells, t);
        tiles += hand[t as usize];
    }
    let w: [u32; 2] = own_waits(s, seat);
    for t in 0u32..34u32 {
        put_word_byte(&mut out, A_WAITS + t, set_has(w, t) as u32);
    }
    if tiles % 3u32 == 2u32 {
        for t in 0u32..34u32 {
            let mut sh: u32 = NO_TILE_BYTE;
            let mut uk: u32 = 0u32;
            if hand[t as usize] > 0u32 {
                let mut h: [u32; 34] = hand;
                h[t as usize] -= 1u32;
                let base: i32 = shanten(ShantenInput { hand: h }).shanten;
                sh = base as u32;
                let imp: [u32; 34] = improving_tiles(h, base, unseen);
                for u in 0u32..34u32 {
                    uk += imp[u as usize];
                }
            }
            put_word_byte(&mut out, A_DISCARD_SHANTEN + t, sh);
            put_word_byte(&mut out, A_DISCARD_UKEIRE + t, uk);
        }
    } else {
        for t in 0u32..34u32 {
            put_word_byte(&mut out, A_DISCARD_SHANTEN + t, NO_TILE_BYTE);
        }
        let base: i32 = shanten(ShantenInput { hand: hand }).shanten;
        let imp: [u32; 34] = improving_tiles(hand, base, unseen);
        for t in 0u32..34u32 {
            put_word_byte(&mut out, A_IMPROVING + t, imp[t as usize]);
        }
    }
    ObsAnalysis { words: out }
}

pub fn observe_oracle(state: GameState, arg: u32) -> ObsOracle {
    let mut s: GameState = state;
    oracle_of(&mut s, arg)
}

fn oracle_of(s: &mut GameState, arg: u32) -> ObsOracle {
    let seat: u32 = observer(s, arg);
    let mut out: [u32; 78] = [0u32; 78];
    for j in 1u32..SEATS {
        let q: u32 = (seat + j) % SEATS;
        let i: u32 = j - 1u32;
        let c: [u32; 34] = hand_counts(s, q);
        for t in 0u32..34u32 {
            put_oracle_byte(&mut out, O_HANDS + i * 34u32 + t, c[t as usize]);
        }
        for suit in 0u32..3u32 {
            put_oracle_byte(&mut out, O_RED + i * 3u32 + suit, holds_red(s, q, suit) as u32);
        }
        put_oracle_byte(&mut out, O_SHANTEN + i, shanten(ShantenInput { hand: c }).shanten as u32);
        put_oracle_byte(&mut out, O_FURITEN + i, furiten(s, q) as u32);
        for t in 0u32..34u32 {
            put_oracle_byte(&mut out, O_WAITS + i * 34u32 + t, waits_include(s, q, t) as u32);
        }
    }
    for k in 0u32..WALL_LIVE_END - WALL_LIVE_START {
        let pos: u32 = WALL_LIVE_START + k;
        let mut v: u32 = NO_TILE_BYTE;
        if pos >= s.next_draw && pos < s.live_end {
            v = wall_tile(s, pos);
        }
        put_oracle_byte(&mut out, O_WALL + k, v);
    }
    // The dead wall's replacement tiles not drawn yet (each draw moved the live wall's end down).
    for k in 0u32..4u32 {
        let mut v: u32 = NO_TILE_BYTE;
        if k >= replacements_drawn(s) {
            v = wall_tile(s, WALL_RINSHAN + k);
        }
        put_oracle_byte(&mut out, O_RINSHAN + k, v);
        }
    for k in 0u32..5u32 {
        put_oracle_byte(&mut out, O_DORA + k, wall_tile(s, WALL_DORA + k));
        put_oracle_byte(&mut out, O_URA + k, wall_tile(s, WALL_URA + k));
    }
    ObsOracle { words: out }
}
