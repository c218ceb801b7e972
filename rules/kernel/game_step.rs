// The environment's three pure functions (Pgx style): a new game, one decision of the current
// player, and the view of the outcome that the host reads back.

fn compute_mask(s: &mut GameState) -> [u32; 3] {
    if s.phase == PHASE_CLAIM {
        return claim_mask(s);
    }
    if s.phase == PHASE_OVER {
        return [0u32; 3];
    }
    turn_mask(s)
}

fn begin_game(s: &mut GameState, dealer: u32, wall: [u32; 136]) {
    s.round = 0u32;
    s.dealer = dealer;
    s.honba = 0u32;
    s.sticks = 0u32;
    s.scores = [STARTING_POINTS as i32; 4];
    // A seat past the table's (three players) holds nothing.
    for p in SEATS..4u32 {
        s.scores[p as usize] = 0i32;
    }
    s.rounds = 0u32;
    s.phase = PHASE_TURN;
    s.terminated = 0u32;
    start_round(s, wall);
}

// A step runs as passes over the state, each pass the continuations (`GameState.task`) of one
// stage: the decision, the claims on a discard, what follows them (the next draw, a replacement
// tile, a tsumo, an abortive draw), the end of the round, then the new mask. A task only ever
// leads to one numbered after it (TASK_*) or ends the step's play (TASK_DONE), so each runs at
// most once, in that order, and the passes play a whole step in straight lines. The CPU calls
// them in a row (`game_step`); the GPU dispatches each as a pipeline of its own: one shader
// holding the whole step took Mesa's lavapipe 2.5 minutes to compile, its parts 0.63x of that in
// all (docs/performance.md, "How long each pipeline takes to compile").

// Whether a pass has work: the GPU skips the envs whose task its guard (entries.rs) rules out,
// without copying their state. Each pass leaves every other state as it is.
pub fn claims_pending(task: u32) -> bool {
    task == TASK_OPEN_CLAIMS || task == TASK_RESOLVE
}

pub fn flow_pending(task: u32) -> bool {
    task >= TASK_AFTER_DISCARD && task <= TASK_TSUMO
}

pub fn settle_pending(task: u32) -> bool {
    task == TASK_END_ROUND || task == TASK_NEW_GAME
}

// The claims stage: a discard's claim window opened, and the claims resolved once every
// claimant decided.
pub fn game_claims(s: &mut GameState, _arg: u32) {
    if s.task == TASK_OPEN_CLAIMS {
        s.task = open_claims(s);
    }
    if s.task == TASK_RESOLVE {
        s.task = resolve_claims(s);
    }
}

// What follows the claims: the next draw (or an exhaustive or abortive draw), a kan's replacement
// tile, a tsumo's payments.
pub fn game_flow(s: &mut GameState, _arg: u32) {
    if s.task == TASK_AFTER_DISCARD {
        s.task = after_discard(s);
    }
    if s.task == TASK_REPLACEMENT {
        let seat: u32 = s.task_seat;
        let kita: bool = s.task_flags == REPLACE_KITA;
        draw_replacement(s, seat, kita);
        s.task = TASK_DONE;
    }
    if s.task == TASK_ABORTIVE {
        s.events |= EVENT_ABORTIVE_DRAW;
        s.task_flags = END_DEALER_CONTINUES | END_DRAWN | END_ABORTIVE;
        s.task = TASK_END_ROUND;
    }
    if s.task == TASK_TSUMO {
        let winner: u32 = s.task_seat;
        settle_tsumo(s, winner);
        s.task_flags = 0u32;
        if winner == s.dealer {
            s.task_flags = END_DEALER_CONTINUES;
        }
        s.task = TASK_END_ROUND;
    }
}

// The end of the round (the next deal, or the game's end), and with auto-reset the next game.
pub fn game_settle(s: &mut GameState, _arg: u32) {
    if s.task == TASK_END_ROUND {
        let flags: u32 = s.task_flags;
        end_round(s, flags);
        s.task = TASK_DONE;
        if s.terminated != 0u32 {
            s.task = TASK_NEW_GAME;
        }
    }
    if s.task == TASK_NEW_GAME {
        if s.auto_reset != 0u32 {
            // Pgx-style auto-reset: the next game starts in this step; the view still reports the end.
            s.games += 1u32;
            let dealer: u32 = first_dealer(s.seed, s.games, SEATS);
            let wall: [u32; 136] = shuffled_wall(s.seed, s.games, 0u32);
            let finished_rounds: u32 = s.rounds;
            begin_game(s, dealer, wall);
            s.terminated = 1u32;
            s.rounds = finished_rounds;
        }
        s.task = TASK_DONE;
    }
}

// The legal actions of the step's outcome; the step is settled.
pub fn game_mask(s: &mut GameState, _arg: u32) {
    if s.task != TASK_IDLE {
        s.mask = compute_mask(s);
    }
    s.task = TASK_DONE;
}

// `requested` below SEATS is that seat; anything else draws one from the seed.
fn first_dealer(seed: [u32; 2], games: u32, requested: u32) -> u32 {
    if requested < SEATS {
        return requested;
    }
    let mut rng: Rng = rng_new(seed, RNG_DEALER, games, 0u32);
    random_below(&mut rng, SEATS)
}

pub fn game_new(inp: ResetInput) -> GameState {
    let mut s: GameState = empty_state();
    s.seed = inp.seed;
    s.mode = inp.mode;
    s.uma = inp.uma;
    s.penalty = inp.penalty;
    s.auto_reset = inp.auto_reset;
    let dealer: u32 = first_dealer(inp.seed, 0u32, inp.dealer);
    let mut wall: [u32; 136] = inp.wall;
    if inp.use_wall == 0u32 {
        wall = shuffled_wall(inp.seed, 0u32, 0u32);
    }
    begin_game(&mut s, dealer, wall);
    s.mask = compute_mask(&mut s);
    s
}

// A step's outputs start empty: rewards and events report this step only.
fn clear_step_outputs(s: &mut GameState) {
    s.rewards = [0i32; 4];
    s.events = 0u32;
    s.winners = 0u32;
    s.deal_in = 0u32;
    s.yaku = [0u32; 2];
    s.illegal = 0u32;
    s.ranks = 0u32;
}

// The decision: the action played, or the game ended by an illegal one. Leaves the task that
// follows in `s.task` (TASK_IDLE: the step changes nothing more, not even the mask).
fn step_decide(s: &mut GameState, action: u32) {
    s.task = TASK_IDLE;
    if s.terminated != 0u32 {
        if s.auto_reset == 0u32 {
            // A finished game without auto-reset stays finished; its view repeats with no reward.
            return;
        }
        // The flag reported the end of the previous game; the state already holds the next one.
        s.terminated = 0u32;
    }
    s.steps += 1u32;
    let actor: u32 = s.current;
    s.task = TASK_DONE;
    if action >= NUM_ACTIONS || !mask_has(s.mask, action) {
        s.illegal = actor + 1u32;
        s.phase = PHASE_OVER;
        s.terminated = 1u32;
        s.events |= EVENT_GAME_OVER;
        s.task = TASK_NEW_GAME;
    } else if s.phase == PHASE_CLAIM {
        s.task = do_claim_decision(s, action);
    } else if s.phase != PHASE_OVER {
        s.task = do_turn_action(s, action);
    }
}

// The passes after the decision, in their order.
fn step_passes(s: &mut GameState) {
    game_claims(s, 0u32);
    game_flow(s, 0u32);
    game_settle(s, 0u32);
    game_mask(s, 0u32);
}

pub fn game_step(s: &mut GameState, action: u32) {
    clear_step_outputs(s);
    step_decide(s, action);
    step_passes(s);
}

// Replaces the round a game is about to play with the given table and wall (log replay: each
// logged round is dealt from its own wall). A finished game, or `deal == 0`, is left alone.
pub fn game_deal(s: &mut GameState, inp: DealInput) {
    if inp.deal == 0u32 || s.phase == PHASE_OVER {
        return;
    }
    s.round = inp.round;
    s.dealer = inp.dealer % SEATS;
    s.honba = inp.honba;
    s.sticks = inp.sticks;
    s.scores = inp.scores;
    clear_step_outputs(s);
    s.terminated = 0u32;
    start_round(s, inp.wall);
    s.mask = compute_mask(s);
}

pub fn game_view(s: GameState) -> StepView {
    let mut rewards: [f32; 4] = [0.0f32; 4];
    for p in 0u32..4u32 {
        rewards[p as usize] = s.rewards[p as usize] as f32;
    }
    if s.illegal != 0u32 {
        rewards = [0.0f32; 4];
        rewards[(s.illegal - 1u32) as usize] = s.penalty;
    }
    StepView {
        current_player: s.current,
        mask: s.mask,
        rewards: rewards,
        terminated: s.terminated,
        truncated: 0u32,
        illegal: (s.illegal != 0u32) as u32,
        events: s.events,
        winners: s.winners,
        deal_in: s.deal_in,
        yaku: s.yaku,
        rounds: s.rounds,
        ranks: s.ranks,
    }
}
