// Rounds: dealing, drawing, kan dora, and what happens when a round ends (dealer repeat, honba,
// the next round or the end of the game with uma).

// The wall, in dealing order: 13 tiles to each seat, the live wall, then the dead wall's 14 tiles:
// five dora indicators, five ura indicators, four replacement tiles. Three players play without
// 2m-8m (108 tiles); their replacement tiles past the fourth are the live wall's last ones, each
// kan or kita having moved the live wall's end down by one (Tenhou keeps 14 tiles in the dead
// wall). `pub`: log replay builds walls in this layout.
pub const WALL_TILES: u32 = 136u32 - 28u32 * (4u32 - SEATS);
pub const WALL_LIVE_START: u32 = 13u32 * SEATS;
pub const WALL_LIVE_END: u32 = WALL_TILES - 14u32;
pub const WALL_DORA: u32 = WALL_LIVE_END;
pub const WALL_URA: u32 = WALL_DORA + 5u32;
pub const WALL_RINSHAN: u32 = WALL_URA + 5u32;

// Whether tile type t is in the set: three players have no 2m-8m.
pub fn tile_in_play(t: u32) -> bool {
    SEATS == 4u32 || t == 0u32 || t >= 8u32
}

// The wall index of the k-th replacement tile of the round (kans and kita together).
pub fn replacement_index(k: u32) -> u32 {
    if k < 4u32 {
        return WALL_RINSHAN + k;
    }
    WALL_LIVE_END + 3u32 - k
}

fn empty_state() -> GameState {
    GameState {
        seed: [0u32; 2],
        games: 0u32,
        mode: MODE_HALF,
        uma: [0i32; 4],
        penalty: 0.0f32,
        auto_reset: 0u32,
        round: 0u32,
        dealer: 0u32,
        honba: 0u32,
        sticks: 0u32,
        scores: [0i32; 4],
        wall: [0u32; 34],
        next_draw: WALL_LIVE_START,
        live_end: WALL_LIVE_END,
        kans: 0u32,
        dora_revealed: 1u32,
        dora_pending: 0u32,
        hands: [0u32; 20],
        red: 0u32,
        melds: [0u32; 16],
        meld_counts: 0u32,
        rivers: [0u32; 24],
        river_lens: 0u32,
        discarded: [0u32; 8],
        waits: [0u32; 8],
        seat_flags: [0u32; 4],
        pao: 0u32,
        phase: PHASE_TURN,
        current: 0u32,
        drawn: NO_TILE_VALUE,
        rinshan: 0u32,
        uninterrupted: 1u32,
        kuikae: 0xffffu32,
        claim_tile: NO_TILE_VALUE,
        claim_from: 0u32,
        claim_kan: 0u32,
        claim_options: [0u32; 4],
        claim_choices: [NO_CHOICE; 4],
        task: TASK_DONE,
        task_seat: 0u32,
        task_flags: 0u32,
        mask: [0u32; 3],
        rewards: [0i32; 4],
        terminated: 0u32,
        illegal: 0u32,
        events: 0u32,
        winners: 0u32,
        deal_in: 0u32,
        yaku: [0u32; 2],
        rounds: 0u32,
        ranks: 0u32,
        steps: 0u32,
        win_yaku: [0u32; 8],
        win_score: [0u32; 8],
        draw_kind: 0u32,
        log: [0u32; 60],
        log_len: 0u32,
    }
}

// The WALL_TILES tiles in a uniformly random order (Fisher-Yates over the wall stream of the
// game's round); the rest of the array is 0.
pub fn shuffled_wall(seed: [u32; 2], game: u32, round: u32) -> [u32; 136] {
    let mut w: [u32; 136] = [0u32; 136];
    let mut n: u32 = 0u32;
    for i in 0u32..136u32 {
        let t: u32 = i / 4u32;
        let mut v: u32 = t;
        if RED_FIVES && i % 4u32 == 0u32 && t < 27u32 && t % 9u32 == 4u32 {
            v = 34u32 + t / 9u32;
        }
        if tile_in_play(t) {
            w[n as usize] = v;
            n += 1u32;
        }
    }
    let mut rng: Rng = rng_new(seed, RNG_WALL, game, round);
    let mut i: u32 = WALL_TILES - 1u32;
    while i > 0u32 {
        let j: u32 = random_below(&mut rng, i + 1u32);
        let x: u32 = w[i as usize];
        w[i as usize] = w[j as usize];
        w[j as usize] = x;
        i -= 1u32;
    }
    w
}

fn start_round(s: &mut GameState, wall: [u32; 136]) {
    for i in 0u32..34u32 {
        s.wall[i as usize] = wall[(i * 4u32) as usize]
            | (wall[(i * 4u32 + 1u32) as usize] << 8u32)
            | (wall[(i * 4u32 + 2u32) as usize] << 16u32)
            | (wall[(i * 4u32 + 3u32) as usize] << 24u32);
    }
    s.next_draw = WALL_LIVE_START;
    s.live_end = WALL_LIVE_END;
    s.kans = 0u32;
    s.dora_revealed = 1u32;
    s.dora_pending = 0u32;
    s.hands = [0u32; 20];
    s.red = 0u32;
    s.melds = [0u32; 16];
    s.meld_counts = 0u32;
    s.rivers = [0u32; 24];
    s.river_lens = 0u32;
    s.discarded = [0u32; 8];
    s.seat_flags = [SEAT_CONCEALED | SEAT_NAGASHI; 4];
    s.pao = 0u32;
    s.uninterrupted = 1u32;
    s.kuikae = 0xffffu32;
    s.claim_tile = NO_TILE_VALUE;
    s.claim_kan = 0u32;
    s.claim_options = [0u32; 4];
    s.claim_choices = [NO_CHOICE; 4];
    log_clear(s);
    for j in 0u32..SEATS {
        let seat: u32 = (s.dealer + j) % SEATS;
        for k in 0u32..13u32 {
            let v: u32 = wall_tile(s, j * 13u32 + k);
            give_tile(s, seat, v);
        }
    }
    for seat in 0u32..SEATS {
        update_waits(s, seat);
    }
    draw(s, s.dealer);
}

fn draw(s: &mut GameState, seat: u32) {
    let v: u32 = wall_tile(s, s.next_draw);
    s.next_draw += 1u32;
    receive_draw(s, seat, v, 0u32);
}

// North tiles the seat has set aside this round.
pub fn kita_count(s: &mut GameState, seat: u32) -> u32 {
    (s.seat_flags[seat as usize] >> SEAT_KITA_SHIFT) & 7u32
}

// Replacement tiles drawn this round (after kans and kita): each moved the live wall's end down
// by one. `pub`: hosts find the drawn ones' places with `replacement_index`.
pub fn replacements_drawn(s: &mut GameState) -> u32 {
    WALL_LIVE_END - s.live_end
}

// The replacement draw after a kan or a kita: the dead wall gives one tile and the live wall
// shrinks by one.
fn draw_replacement(s: &mut GameState, seat: u32, kita: bool) {
    if KAN_DORA_AT_ONCE {
        // An open kan's dora, or an added kan's once no one robbed it, shows before the
        // replacement tile is drawn, so a rinshan win already counts it.
        reveal_pending_dora(s);
    }
    let k: u32 = replacements_drawn(s);
    let v: u32 = wall_tile(s, replacement_index(k));
    if !kita {
        s.kans += 1u32;
    }
    s.live_end -= 1u32;
    receive_draw(s, seat, v, 1u32);
}

fn receive_draw(s: &mut GameState, seat: u32, v: u32, rinshan: u32) {
    give_tile(s, seat, v);
    s.drawn = v;
    s.rinshan = rinshan;
    s.current = seat;
    s.phase = PHASE_TURN;
    s.kuikae = 0xffffu32;
    // Temporary furiten lasts until the seat's own next discard (see `do_discard`); nothing
    // between a draw and that discard can be ronned by the seat, so the draw lifts it already and
    // the turn's view shows the seat as it will discard.
    s.seat_flags[seat as usize] &= !SEAT_FURITEN_TEMP;
    log_draw(s);
}

// Reveals `n` more dora indicators, logging each.
fn reveal_dora(s: &mut GameState, n: u32) {
    for i in 0u32..n {
        let v: u32 = wall_tile(s, WALL_DORA + s.dora_revealed);
        s.dora_revealed += 1u32;
        log_push(s, EV_DORA, s.current, v, 0u32);
    }
}

fn reveal_pending_dora(s: &mut GameState) {
    let n: u32 = s.dora_pending;
    s.dora_pending = 0u32;
    reveal_dora(s, n);
}

// Rounds count up by one per dealer: East 1 is 0, South 1 is SEATS.
fn last_round(s: &mut GameState) -> u32 {
    if s.mode == MODE_EAST {
        return SEATS - 1u32;
    }
    2u32 * SEATS - 1u32
}

// The round's wind, 0..3 = E S W N.
pub fn round_wind_of(round: u32) -> u32 {
    (round / SEATS) % 4u32
}

// East 1's dealer: the seat `round` dealer changes before the current dealer.
fn first_dealer_seat(s: &mut GameState) -> u32 {
    (s.dealer + 16u32 * SEATS - s.round % (16u32 * SEATS)) % SEATS
}

fn top_seat(s: &mut GameState) -> u32 {
    // Ties go to the seat nearer the first dealer of the game (East 1's dealer is round 0's).
    let first: u32 = first_dealer_seat(s);
    let mut best: u32 = first;
    for j in 1u32..SEATS {
        let p: u32 = (first + j) % SEATS;
        if s.scores[p as usize] > s.scores[best as usize] {
            best = p;
        }
    }
    best
}

// `flags`: the END_* arguments of the round's end.
fn game_is_over(s: &mut GameState, flags: u32) -> bool {
    if s.mode == MODE_SINGLE {
        return true;
    }
    if BUST_BELOW_ZERO {
        for p in 0u32..SEATS {
            if s.scores[p as usize] < 0i32 {
                return true;
            }
        }
    }
    let last: u32 = last_round(s);
    let top: u32 = top_seat(s);
    let reached: bool = s.scores[top as usize] >= TARGET_POINTS as i32;
    if s.round < last {
        return false;
    }
    let mut limit: u32 = last;
    if WEST_EXTENSION {
        limit = last + SEATS;
    }
    if (flags & END_DEALER_CONTINUES) != 0u32 {
        // All-last: a dealer who is top (and has reached the target) stops the game after a win or
        // a tenpai at the exhaustive draw (agari-yame, tenpai-yame). An abortive draw is neither:
        // the round is played again with one more honba, as Tenhou and RiichiEnv do (otherwise a
        // leading dealer could end the game by declaring nine terminals).
        let stop_allowed: bool = (flags & END_ABORTIVE) == 0u32;
        //
        // The dealer's continuation comes before the target, in the extension rounds too: a dealer
        // who wins or is tenpai plays the next honba even when another seat has passed the target
        // (a double ron, a tenpai payment). Tenhou: "親以外が30000点以上になっても1本場が始まる"
        // (hagurin-tenhou.com, on the West round), "連荘を優先する" (a summary of Tenhou's manual);
        // Mahjong Soul ends the game at the target "なおかつ親が連荘しない"; RiichiEnv plays on.
        return DEALER_TOP_STOP && stop_allowed && top == s.dealer && (reached || !WEST_EXTENSION);
    }
    if s.round > last && reached {
        // Otherwise extension rounds end as soon as someone reaches the target.
        return true;
    }
    if s.round == limit {
        return true;
    }
    !WEST_EXTENSION || reached
}

// The uma each seat is paid for its place `ranks[p]` under `scores` (the points before uma). With
// TIED_SEATS_SHARE_UMA, seats tied on points share the uma of the places they hold equally in
// whole hundreds; the hundreds that do not divide go one each to the tied seats first in rank
// order, so the uma still sums to zero and every share is a whole reward unit.
pub fn uma_shares(scores: [i32; 4], ranks: [u32; 4], uma: [i32; 4]) -> [i32; 4] {
    let mut out: [i32; 4] = [0i32; 4];
    for p in 0u32..SEATS {
        out[p as usize] = uma[ranks[p as usize] as usize];
        if TIED_SEATS_SHARE_UMA {
            let mut total: i32 = 0;
            let mut n: i32 = 0;
            let mut ahead: i32 = 0;
            for q in 0u32..SEATS {
                if scores[q as usize] == scores[p as usize] {
                    total += uma[ranks[q as usize] as usize] / 100i32;
                    n += 1i32;
                    if ranks[q as usize] < ranks[p as usize] {
                        ahead += 1i32;
                    }
                }
            }
            // Division truncates toward zero (Rust and WGSL alike): step the share down for a
            // negative remainder so that the leftover is 0..n.
            let mut share: i32 = total / n;
            if share * n > total {
                share -= 1i32;
            }
            if ahead < total - share * n {
                share += 1i32;
            }
            out[p as usize] = share * 100i32;
        }
    }
    out
}

// Each seat's place by score, 0 = first; ties go to the seat nearer the first dealer of the game
// (East 1's dealer is round 0's). One comparison per pair of seats; a seat past the table's (three
// players) gets 0. Uma, observations and the arena all rank by it.
pub fn seat_ranks(s: &mut GameState) -> [u32; 4] {
    let first: u32 = first_dealer_seat(s);
    let mut ranks: [u32; 4] = [0u32; 4];
    for p in 0u32..SEATS {
        for q in p + 1u32..SEATS {
            let a: i32 = s.scores[p as usize];
            let b: i32 = s.scores[q as usize];
            let p_sits_first: bool = (p + SEATS - first) % SEATS < (q + SEATS - first) % SEATS;
            let q_above: u32 = (b > a || (b == a && !p_sits_first)) as u32;
            ranks[p as usize] += q_above;
            ranks[q as usize] += 1u32 - q_above;
        }
    }
    ranks
}

// Uma by rank and the leftover sticks to the top seat, paid in the game's final step.
fn finish_game(s: &mut GameState) {
    let top: u32 = top_seat(s);
    collect_sticks(s, top);
    let ranks: [u32; 4] = seat_ranks(s);
    for p in 0u32..SEATS {
        s.ranks |= ranks[p as usize] << (p * RANK_SHIFT);
    }
    // A seat past the table's (three players) holds the place no one does.
    for p in SEATS..4u32 {
        s.ranks |= 3u32 << (p * RANK_SHIFT);
    }
    let uma: [i32; 4] = uma_shares(s.scores, ranks, s.uma);
    for p in 0u32..SEATS {
        let u: i32 = uma[p as usize];
        s.scores[p as usize] += u;
        s.rewards[p as usize] += u / 100i32;
    }
    s.phase = PHASE_OVER;
    s.terminated = 1u32;
    s.events |= EVENT_GAME_OVER;
}

// Ends the round. `flags` (END_*): the dealer continues after a dealer win, a dealer tenpai at a
// draw or an abortive draw; the round is drawn when nobody won.
fn end_round(s: &mut GameState, flags: u32) {
    let dealer_continues: bool = (flags & END_DEALER_CONTINUES) != 0u32;
    let drawn_round: bool = (flags & END_DRAWN) != 0u32;
    s.rounds += 1u32;
    if game_is_over(s, flags) {
        finish_game(s);
        return;
    }
    if dealer_continues || drawn_round {
        s.honba += 1u32;
    } else {
        s.honba = 0u32;
    }
    if !dealer_continues {
        s.round += 1u32;
        s.dealer = (s.dealer + 1u32) % SEATS;
    }
    let wall: [u32; 136] = shuffled_wall(s.seed, s.games, s.rounds);
    start_round(s, wall);
}
