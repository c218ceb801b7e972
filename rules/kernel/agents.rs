// Baseline agents, batched on both backends. Each reads only the planes observation of the seat
// it plays and the legal mask (so the hidden-resampling test covers what they may know), plus a
// random stream for its own choices: deterministic for a seed.
//
// - random: uniform over the legal actions.
// - rule: MahJax's rule-based player with its bugs fixed: win > riichi > yakuhai pon > discard
//   by shanten (normal, seven pairs, thirteen orphans; concealed tiles only), then wait count at
//   tenpai, then a static tile priority; folds onto safe tiles against a riichi at 2+ shanten.
// - greedy: win and riichi when legal; discard by shanten, then ukeire over unseen tiles, then
//   tile value (keeps dora and red fives); pons only yakuhai that do not worsen shanten; no chi;
//   kans that keep shanten.
// - defensive: greedy, but against a riichi or an obvious open threat it folds when far from
//   tenpai, discarding by danger (genbutsu, suji, kabe, visible honors, dora).
//
// The observation is passed by `&mut`, a pointer in the WGSL, though no agent writes it: a by-value
// parameter becomes a local copy there, and the helpers below would copy its 568 words per call.

fn pl(o: &mut ObsPlanes, row: u32, t: u32) -> u32 {
    let i: u32 = row * 34u32 + t;
    (o.planes[(i / 4u32) as usize] >> ((i % 4u32) * 8u32)) & 255u32
}

fn scalar_of(o: &mut ObsPlanes, i: u32) -> i32 {
    let w: u32 = (o.scalars[(i / 2u32) as usize] >> ((i % 2u32) * 16u32)) & 65535u32;
    ((w << 16u32) as i32) >> 16i32
}

fn obs_hand(o: &mut ObsPlanes) -> [u32; 34] {
    let mut h: [u32; 34] = [0u32; 34];
    for t in 0u32..34u32 {
        h[t as usize] = pl(o, P_HAND, t) + pl(o, P_HAND + 1u32, t) + pl(o, P_HAND + 2u32, t) + pl(o, P_HAND + 3u32, t);
    }
    h
}

fn shanten_of(h: [u32; 34]) -> i32 {
    shanten(ShantenInput { hand: h }).shanten
}

// The tile type and redness of a discard action (`drawn`: the drawn tile's type and red bit).
fn discard_tile(a: u32, drawn: u32) -> u32 {
    if a == ACTION_TSUMOGIRI {
        return drawn;
    }
    let v: u32 = a - ACTION_DISCARD;
    value_type(v) | (((v >= 34u32) as u32) << 8u32)
}

fn is_discard(a: u32) -> bool {
    a == ACTION_TSUMOGIRI || (a >= ACTION_DISCARD && a < ACTION_DISCARD + ACTION_DISCARD_COUNT)
}

// Unseen copies of each type from this seat: what may still be drawn (three players draw no
// 2m-8m).
fn unseen_of(o: &mut ObsPlanes) -> [u32; 34] {
    let mut u: [u32; 34] = [0u32; 34];
    for t in 0u32..34u32 {
        if tile_in_play(t) {
            u[t as usize] = 4u32 - pl(o, P_SEEN, t).min(4u32);
        }
    }
    u
}

// Tiles that lower the shanten of `h` (3k+1 tiles), weighted by unseen copies; `waits` counts
// kinds rather than copies. `base` is the shanten of `h`, which every caller already holds.
fn ukeire(h: [u32; 34], base: i32, unseen: [u32; 34], kinds: bool) -> u32 {
    // A type held four times reads SHANTEN_NOT_APPLICABLE: never an improvement.
    let after: [i32; 34] = shanten_after_draws(h);
    let mut n: u32 = 0u32;
    for t in 0u32..34u32 {
        if after[t as usize] < base && (unseen[t as usize] > 0u32 || kinds) {
            if kinds {
                n += 1u32;
            } else {
                n += unseen[t as usize];
            }
        }
    }
    n
}

// How much a tile is worth keeping, beyond shanten: honors less than terminals less than middle
// tiles; yakuhai, dora and red fives more.
fn keep_value(o: &mut ObsPlanes, t: u32, red: u32) -> u32 {
    let mut v: u32 = 4u32;
    if t >= FIRST_HONOR {
        v = 1u32 + 2u32 * pl(o, P_YAKUHAI, t);
    } else if t % 9u32 == 0u32 || t % 9u32 == 8u32 {
        v = 2u32;
    } else if t % 9u32 == 1u32 || t % 9u32 == 7u32 {
        v = 3u32;
    }
    v + 3u32 * pl(o, P_DORA, t) + 3u32 * red
}

// MahJax's static priority: the lower, the sooner discarded (outer winds, other honors,
// terminals, 2/8, the rest).
fn rule_priority(o: &mut ObsPlanes, t: u32) -> u32 {
    if t >= FIRST_HONOR {
        if pl(o, P_YAKUHAI, t) == 0u32 {
            return 0u32;
        }
        return 1u32;
    }
    if t % 9u32 == 0u32 || t % 9u32 == 8u32 {
        return 2u32;
    }
    if t % 9u32 == 1u32 || t % 9u32 == 7u32 {
        return 3u32;
    }
    4u32
}

// Danger of discarding type t against ego seat q (ordinal levels after tenhou-python-bot).
fn danger_against(o: &mut ObsPlanes, q: u32, t: u32) -> u32 {
    let safe_row: u32 = P_SEAT + q * P_SEAT_ROWS + P_SEAT_SAFE;
    if pl(o, safe_row, t) != 0u32 {
        return 0u32;
    }
    let seen: u32 = pl(o, P_SEEN, t);
    if t >= FIRST_HONOR {
        if seen >= 3u32 {
            return 1u32;
        }
        if seen == 2u32 {
            return 3u32;
        }
        return 6u32;
    }
    let r: u32 = t % 9u32;
    let base: u32 = t - r;
    let low_safe: bool = r >= 3u32 && pl(o, safe_row, t - 3u32) != 0u32;
    let high_safe: bool = r <= 5u32 && pl(o, safe_row, t + 3u32) != 0u32;
    let suji: bool = (r < 3u32 && high_safe) || (r > 5u32 && low_safe) || (low_safe && high_safe);
    if suji {
        if r == 0u32 || r == 8u32 {
            return 2u32;
        }
        if r == 1u32 || r == 7u32 {
            return 4u32;
        }
        return 5u32;
    }
    // Kabe: no two-sided wait can take t when a tile it needs has all four copies in sight.
    let below_blocked: bool = r < 2u32 || pl(o, P_SEEN, base + r - 1u32) >= 4u32 || pl(o, P_SEEN, base + r - 2u32) >= 4u32;
    let above_blocked: bool = r > 6u32 || pl(o, P_SEEN, base + r + 1u32) >= 4u32 || pl(o, P_SEEN, base + r + 2u32) >= 4u32;
    if below_blocked && above_blocked {
        return 4u32;
    }
    if r == 0u32 || r == 8u32 {
        return 6u32;
    }
    7u32
}

// Ego seats that threaten: a riichi, or an open hand with 3+ melds or 3+ dora in its melds.
fn threats(o: &mut ObsPlanes) -> u32 {
    let mut th: u32 = 0u32;
    for q in 1u32..4u32 {
        let mut dora_in_melds: u32 = 0u32;
        for t in 0u32..34u32 {
            dora_in_melds += pl(o, P_SEAT + q * P_SEAT_ROWS + P_SEAT_MELD_TILES, t) * pl(o, P_DORA, t);
        }
        if scalar_of(o, S_RIICHI + q) > 0i32 || scalar_of(o, S_MELDS + q) >= 3i32 || dora_in_melds >= 3u32 {
            th |= 1u32 << q;
        }
    }
    th
}

fn folds(o: &mut ObsPlanes, agent: u32) -> bool {
    if agent == AGENT_RULE {
        let mut riichi: bool = false;
        for q in 1u32..4u32 {
            if scalar_of(o, S_RIICHI + q) > 0i32 {
                riichi = true;
            }
        }
        return riichi && scalar_of(o, S_SHANTEN) >= 2i32;
    }
    if agent != AGENT_DEFENSIVE || threats(o) == 0u32 {
        return false;
    }
    let sh: i32 = scalar_of(o, S_SHANTEN);
    sh >= 2i32 || (sh >= 1i32 && scalar_of(o, S_DISCARDS) >= 12i32)
}

fn first_legal(mask: [u32; 3]) -> u32 {
    for a in 0u32..NUM_ACTIONS {
        if mask_has(mask, a) {
            return a;
        }
    }
    ACTION_PASS
}

fn random_legal(mask: [u32; 3], seed: [u32; 2], nonce: u32) -> u32 {
    let n: u32 = mask[0].count_ones() + mask[1].count_ones() + mask[2].count_ones();
    if n == 0u32 {
        return ACTION_PASS;
    }
    let mut rng: Rng = rng_new(seed, RNG_AGENT, nonce, 0u32);
    nth_legal(mask, random_below(&mut rng, n))
}

// The discard a seat picks: folding by danger, else by the agent's own order.
fn choose_discard(o: &mut ObsPlanes, mask: [u32; 3], agent: u32, fold: bool) -> u32 {
    let hand: [u32; 34] = obs_hand(o);
    let unseen: [u32; 34] = unseen_of(o);
    let mut drawn: u32 = 255u32;
    for t in 0u32..34u32 {
        if pl(o, P_DRAWN, t) != 0u32 {
            drawn = t;
        }
    }
    // The drawn tile's redness: a red five held that the hand has no other copy of.
    if drawn != 255u32 && drawn < 27u32 && drawn % 9u32 == 4u32 && pl(o, P_RED, drawn) != 0u32 && hand[drawn as usize] == 1u32 {
        drawn |= 256u32;
    }
    let th: u32 = threats(o);
    // Shanten after each discardable type, and the best of them.
    let after: [i32; 34] = shanten_after_discards(hand);
    let mut best: i32 = 99i32;
    for a in 0u32..NUM_ACTIONS {
        if is_discard(a) && mask_has(mask, a) {
            best = best.min(after[(discard_tile(a, drawn) & 255u32) as usize]);
        }
    }
    let mut choice: u32 = first_legal(mask);
    let mut choice_key: u32 = 0xffffffffu32;
    for a in 0u32..NUM_ACTIONS {
        if is_discard(a) && mask_has(mask, a) {
            let tr: u32 = discard_tile(a, drawn);
            let t: u32 = tr & 255u32;
            let red: u32 = tr >> 8u32;
            let sh: u32 = (after[t as usize] + 1i32) as u32;
            let mut key: u32 = 0u32;
            if fold {
                let mut danger: u32 = 0u32;
                for q in 1u32..4u32 {
                    if ((th >> q) & 1u32) != 0u32 || agent == AGENT_RULE {
                        danger += danger_against(o, q, t);
                    }
                }
                if agent == AGENT_RULE {
                    // MahJax's intended fold: any tile safe against every riichi, else as usual.
                    let mut unsafe_count: u32 = 0u32;
                    for q in 1u32..4u32 {
                        if scalar_of(o, S_RIICHI + q) > 0i32 && pl(o, P_SEAT + q * P_SEAT_ROWS + P_SEAT_SAFE, t) == 0u32 {
                            unsafe_count += 1u32;
                        }
                    }
                    danger = unsafe_count;
                }
                key = danger << 24u32;
            }
            if agent == AGENT_RULE {
                let mut waits: u32 = 0u32;
                if after[t as usize] == 0i32 {
                    let mut h: [u32; 34] = hand;
                    h[t as usize] -= 1u32;
                    waits = ukeire(h, 0i32, unseen, true);
                }
                key += (sh << 16u32) + ((63u32 - waits) << 8u32) + (rule_priority(o, t) << 2u32) + 3u32 * red;
            } else {
                let mut uk: u32 = 0u32;
                if after[t as usize] == best {
                    let mut h: [u32; 34] = hand;
                    h[t as usize] -= 1u32;
                    uk = ukeire(h, best, unseen, false).min(255u32);
                }
                key += (sh.min(15u32) << 20u32) + ((255u32 - uk) << 8u32) + keep_value(o, t, red) * 2u32 + red;
            }
            if key < choice_key {
                choice_key = key;
                choice = a;
            }
        }
    }
    choice
}

// Whether a pon on `t` keeps (or improves) the shanten of the 13-tile hand.
fn pon_keeps_shanten(hand: [u32; 34], t: u32) -> bool {
    if hand[t as usize] < 2u32 {
        return false;
    }
    let mut h: [u32; 34] = hand;
    h[t as usize] -= 2u32;
    let after: [i32; 34] = shanten_after_discards(h);
    let mut best: i32 = 99i32;
    for d in 0u32..34u32 {
        if d != t {
            best = best.min(after[d as usize]);
        }
    }
    best <= shanten_of(hand)
}

// Whether the seat plays a uniformly random legal action, reading no observation: the random
// agent, the caller's seat when an agent is asked for it, and any number that names no agent.
fn plays_at_random(agent: u32) -> bool {
    agent == AGENT_RANDOM || agent == AGENT_CALLER || agent >= AGENT_KINDS
}

// The action of the agent seated at the player to move of `s` (also the host's arena's). Only an
// agent that reads the planes has them built: for a random seat they were four fifths of the
// step's instructions (docs/performance-history.md, a seventh pass).
pub fn seat_act(s: &mut GameState, agent: u32) -> u32 {
    if plays_at_random(agent) {
        return random_legal(s.mask, s.seed, s.steps);
    }
    let mut o: ObsPlanes = planes_of(s, OBSERVE_CURRENT);
    agent_act(agent, &mut o, s.mask, s.seed, s.steps)
}

pub fn agent_act(agent: u32, o: &mut ObsPlanes, mask: [u32; 3], seed: [u32; 2], nonce: u32) -> u32 {
    if plays_at_random(agent) {
        return random_legal(mask, seed, nonce);
    }
    if mask_has(mask, ACTION_TSUMO) {
        return ACTION_TSUMO;
    }
    if mask_has(mask, ACTION_RON) {
        return ACTION_RON;
    }
    let fold: bool = folds(o, agent);
    let decision: u32 = scalar_of(o, S_DECISION) as u32;
    let hand: [u32; 34] = obs_hand(o);
    if decision == DECISION_CLAIM || decision == DECISION_CHANKAN {
        let mut target: u32 = 255u32;
        for t in 0u32..34u32 {
            if pl(o, P_TARGET, t) != 0u32 {
                target = t;
            }
        }
        let can_pon: bool = mask_has(mask, ACTION_PON) || mask_has(mask, ACTION_PON_RED);
        if !fold && can_pon && target < 34u32 && pl(o, P_YAKUHAI, target) > 0u32 {
            let mut take: bool = agent == AGENT_RULE;
            if agent == AGENT_RULE {
                let mut rng: Rng = rng_new(seed, RNG_AGENT, nonce, 0u32);
                take = random_below(&mut rng, 10u32) < 7u32;
            } else if pon_keeps_shanten(hand, target) {
                take = true;
            }
            if take {
                if mask_has(mask, ACTION_PON) {
                    return ACTION_PON;
                }
                return ACTION_PON_RED;
            }
        }
        if mask_has(mask, ACTION_PASS) {
            return ACTION_PASS;
        }
        return first_legal(mask);
    }
    if decision == DECISION_TURN {
        let sh: i32 = scalar_of(o, S_SHANTEN);
        if mask_has(mask, ACTION_KYUUSHU) && (agent == AGENT_RULE || sh >= 3i32) {
            return ACTION_KYUUSHU;
        }
        // Three players: a North set aside is a dora and a fresh tile.
        if mask_has(mask, ACTION_KITA) {
            return ACTION_KITA;
        }
        if !fold && mask_has(mask, ACTION_RIICHI) {
            return ACTION_RIICHI;
        }
        if !fold && agent != AGENT_RULE {
            for t in 0u32..34u32 {
                if mask_has(mask, ACTION_SELF_KAN + t) {
                    // A closed kan takes all four, an added kan the one copy held.
                    let mut h: [u32; 34] = hand;
                    h[t as usize] = 0u32;
                    if shanten_of(h) <= sh {
                        return ACTION_SELF_KAN + t;
                    }
                }
            }
        }
    }
    choose_discard(o, mask, agent, fold)
}

// Hero mode: the caller's action (bits 0-7; ignored when the seat to move is not the caller's)
// then the built-in agents of bits 8.. (4 bits per seat, AGENT_CALLER = the caller's seat) play
// until one of the caller's seats must decide or the game ends. With PLAY_ROUND it is a play-out:
// the caller's action is played whoever is to move, then the agents play to the round's end. The
// step's outputs add up every decision played (rewards summed, events and winners merged). A host
// that drives the GPU makes the same calls as this loop, a pass of game_play_action then the
// step's passes, so that no shader holds both the step and the agents.
pub fn game_play(s: &mut GameState, arg: u32) {
    for i in 0u32..PLAY_LIMIT {
        let a: u32 = play_action(s, arg | (PLAY_FIRST * ((i == 0u32) as u32)));
        if a == PLAY_DONE {
            break;
        }
        game_advance(s, a);
    }
}

// Hero mode's next decision, as game_advance's argument: on the call's first decision (PLAY_FIRST)
// the caller's action if its seat is to move (or the game is over, which stays over, or the call
// is a play-out), else the built-in agent's; on later decisions PLAY_DONE once the game ended, is
// over or waits for the caller (or, in a play-out, the round ended), else the agent's action with
// PLAY_ADD.
fn play_action(s: &mut GameState, arg: u32) -> u32 {
    let first: bool = (arg & PLAY_FIRST) != 0u32;
    let play_out: bool = (arg & PLAY_ROUND) != 0u32;
    let agent: u32 = (arg >> (8u32 + s.current * 4u32)) & 15u32;
    let waits: bool = agent == AGENT_CALLER || s.phase == PHASE_OVER;
    if first && (waits || play_out) {
        return arg & 255u32;
    }
    // The call's first decision cleared the events: any round-ending one since is this round's.
    let round_over: bool = play_out && (s.events & EVENT_ROUND_OVER) != 0u32;
    if !first && (waits || round_over || s.terminated != 0u32) {
        return PLAY_DONE;
    }
    seat_act(s, agent) | (PLAY_ADD * ((!first) as u32))
}

pub fn game_play_action(state: GameState, arg: u32) -> u32 {
    let mut s: GameState = state;
    play_action(&mut s, arg)
}

// The first pass of a step (`game_step` after its outputs are cleared), or of one of hero mode's
// decisions (from game_play_action): PLAY_DONE plays nothing, and with PLAY_ADD the step's outputs
// add up with those already in the state. They do so by not being cleared: hero mode plays a
// decision with PLAY_ADD only in a game that has not ended (play_action), so the flags, ranks and
// illegal seat it finds are zero, and every other output is summed or merged by the step itself
// (a ron's deal-in seat replaces the one before).
pub fn game_decide(s: &mut GameState, arg: u32) {
    if arg == PLAY_DONE {
        s.task = TASK_IDLE;
        return;
    }
    if (arg & PLAY_ADD) == 0u32 {
        clear_step_outputs(s);
    }
    step_decide(s, arg & !PLAY_ADD);
}

// A whole step or hero-mode decision: its first pass, then the step's later ones.
pub fn game_advance(s: &mut GameState, arg: u32) {
    game_decide(s, arg);
    step_passes(s);
}

// The action the built-in agent seated at the player to move would play (`arg`: 4 bits per
// seat, as in game_play), for hosts that step themselves (self-play with per-step statistics).
pub fn game_agent_action(state: GameState, arg: u32) -> u32 {
    let mut s: GameState = state;
    let agent: u32 = (arg >> (s.current * 4u32)) & 15u32;
    seat_act(&mut s, agent)
}
