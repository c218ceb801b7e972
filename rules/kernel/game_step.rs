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
    s.rounds = 0u32;
    s.phase = PHASE_TURN;
    s.terminated = 0u32;
    start_round(s, wall);
}

// Runs what follows an action until the step settles. Every continuation is called from this one
// loop rather than from each other, so each heavy function (scoring, dealing, masks) is inlined
// once by GPU compilers instead of once per path.
fn run_tasks(s: &mut GameState, first: u32) {
    let mut task: u32 = first;
    loop {
        if task == TASK_DONE {
            break;
        }
        if task == TASK_OPEN_CLAIMS {
            task = open_claims(s);
        } else if task == TASK_RESOLVE {
            task = resolve_claims(s);
        } else if task == TASK_AFTER_DISCARD {
            task = after_discard(s);
        } else if task == TASK_REPLACEMENT {
            let seat: u32 = s.task_seat;
            draw_replacement(s, seat);
            task = TASK_DONE;
        } else if task == TASK_ABORTIVE {
            s.events |= EVENT_ABORTIVE_DRAW;
            s.task_flags = END_DEALER_CONTINUES | END_DRAWN | END_ABORTIVE;
            task = TASK_END_ROUND;
        } else if task == TASK_TSUMO {
            let winner: u32 = s.task_seat;
            settle_tsumo(s, winner);
            s.task_flags = 0u32;
            if winner == s.dealer {
                s.task_flags = END_DEALER_CONTINUES;
            }
            task = TASK_END_ROUND;
        } else if task == TASK_END_ROUND {
            let flags: u32 = s.task_flags;
            end_round(s, flags);
            task = TASK_DONE;
        } else {
            task = TASK_DONE;
        }
    }
}

fn first_dealer(seed: [u32; 2], games: u32, requested: u32) -> u32 {
    if requested < 4u32 {
        return requested;
    }
    let mut rng: Rng = rng_new(seed, RNG_DEALER, games, 0u32);
    random_below(&mut rng, 4u32)
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

pub fn game_step(s: &mut GameState, action: u32) {
    clear_step_outputs(s);
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
    if action >= NUM_ACTIONS || !mask_has(s.mask, action) {
        s.illegal = actor + 1u32;
        s.phase = PHASE_OVER;
        s.terminated = 1u32;
        s.events |= EVENT_GAME_OVER;
    } else {
        let mut next: u32 = TASK_DONE;
        if s.phase == PHASE_CLAIM {
            next = do_claim_decision(s, action);
        } else if s.phase != PHASE_OVER {
            next = do_turn_action(s, action);
        }
        run_tasks(s, next);
    }
    if s.terminated != 0u32 && s.auto_reset != 0u32 {
        // Pgx-style auto-reset: the next game starts in this step; the view still reports the end.
        s.games += 1u32;
        let dealer: u32 = first_dealer(s.seed, s.games, 4u32);
        let wall: [u32; 136] = shuffled_wall(s.seed, s.games, 0u32);
        let finished_rounds: u32 = s.rounds;
        begin_game(s, dealer, wall);
        s.terminated = 1u32;
        s.rounds = finished_rounds;
    }
    s.mask = compute_mask(s);
}

// Replaces the round a game is about to play with the given table and wall (log replay: each
// logged round is dealt from its own wall). A finished game, or `deal == 0`, is left alone.
pub fn game_deal(s: &mut GameState, inp: DealInput) {
    if inp.deal == 0u32 || s.phase == PHASE_OVER {
        return;
    }
    s.round = inp.round;
    s.dealer = inp.dealer % 4u32;
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
        truncated: s.truncated,
        illegal: (s.illegal != 0u32) as u32,
        events: s.events,
        winners: s.winners,
        deal_in: s.deal_in,
        yaku: s.yaku,
        rounds: s.rounds,
        ranks: s.ranks,
    }
}
