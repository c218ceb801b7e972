//! One game on the web page: an env of one game, who plays each seat, the counter that makes a
//! repeated click stale, and the picture of a round's end held until the player moves on. Pure
//! and synchronous: the HTTP layer locks it, the driver task calls [`Session::agent_move`] for the
//! built-in agents and hands the MJAI bots their work ([`Session::bot_work`], done off the lock,
//! and [`Session::bot_done`]).

use std::time::{Duration, Instant};

use bytemuck::Zeroable as _;
use serde::Serialize;

use rinshan_engine::agents::Agent;
use rinshan_engine::arena::refused_action;
use rinshan_engine::env::{events as ev, Backend, Config, Env, Mode};
use rinshan_engine::generated::kernel::{self, GameState};
use rinshan_engine::observe::OwnDraws;
use rinshan_engine::{with_variant, Tile, Variant};
use rinshan_logs::mjai::bot::check_games;
use rinshan_logs::tenhou::write::Recorder;
use rinshan_render::{Board, Options, RoundEndInput, TileMode};

use super::bots::{Ask, Bots, Done, NamedBot, Stepped, Work};

/// Who plays a seat that is not the person's.
#[derive(Debug, Clone)]
pub enum Opponent {
    /// A built-in agent, played at once.
    Agent(Agent),
    /// One of the server's MJAI bots.
    Bot(NamedBot),
    /// The look-ahead: its own turns thought out on a blocking thread (see
    /// [`Session::search_work`]), its claims its base agent's.
    Search(rinshan_search::Options),
    /// One of the server's trained nets, played at once (a forward pass is a fraction of a
    /// millisecond).
    Net(rinshan_net::NetAgent),
}

impl std::fmt::Display for Opponent {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Opponent::Agent(a) => write!(f, "{a}"),
            Opponent::Bot(b) => f.write_str(&b.name),
            Opponent::Search(o) => f.write_str(&o.name()),
            Opponent::Net(n) => f.write_str(&n.name()),
        }
    }
}

/// What a new game is: who sits where, and how fast the agents move.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The rules.
    pub variant: Variant,
    /// The game's length.
    pub mode: Mode,
    /// Who plays each seat; `None` = the person (at most one seat; none = spectating).
    pub seats: [Option<Opponent>; 4],
    /// Seeds the walls.
    pub seed: u64,
    /// Pause before each agent's turn (its calls are decided at once: who may call is hidden);
    /// a spectated game moves past a round's end after four times this and half a second.
    pub delay: Duration,
}

impl Setup {
    /// Its MJAI bot seats: each runs a process of its own.
    pub fn bot_seats(&self) -> usize {
        self.seats
            .iter()
            .filter(|s| matches!(s, Some(Opponent::Bot(_))))
            .count()
    }
}

/// Where a game stands, as the page shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Phase {
    /// The person decides.
    Human,
    /// An agent decides (it moves after the delay).
    Agent,
    /// A round has ended: its result is shown until `next`.
    Result,
    /// The game has ended.
    Over,
}

/// Why a request cannot change a game.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Refusal {
    /// The game moved on since the page last saw it, or it is not the person's turn (409).
    Stale(String),
    /// The action is not legal here (422).
    Illegal(String),
}

/// A legal action as a button or a clickable tile.
#[derive(Debug, Clone, Serialize)]
pub struct Choice {
    /// The action id.
    pub id: u32,
    /// Its name in the variant's layout (`discard_5m`, `riichi`, `pass`).
    pub name: String,
    /// What a button says.
    pub label: String,
    /// For a discard: the tile (`5m`, `0m` for a red five), matching the board's `data-tile`.
    pub tile: Option<String>,
}

/// One game in play.
pub struct Session {
    setup: Setup,
    env: Env,
    names: [String; 4],
    /// Decisions played so far: a move must name the current count.
    pub step: u64,
    /// The board of the round that just ended, shown until the next round starts.
    ended: Option<Board>,
    recorder: Option<Recorder>,
    log: Option<String>,
    events: Vec<String>,
    /// Entries of the round's public log already in `events`.
    told: u32,
    /// The pass action's id (claim prompts offer it).
    pass: u32,
    /// While a bot considers a call, the board the page shows instead of the table as it stands,
    /// and how many events it shows (see [`Session::hold_view`]).
    held_view: Option<(Board, usize)>,
    /// When a client's request last touched the game (the agents' moves do not count).
    pub touched: Instant,
    /// The game's MJAI bots, while they are here (not at work, and the game has some).
    bots: Option<Bots>,
    /// Steps the bots have not heard yet.
    untold: Vec<Stepped>,
    /// The wall places each seat drew this round: what a look-ahead seat knows beyond the table.
    own_draws: [OwnDraws; 4],
    /// The person's odds per discard (`GET .../outlook`) at the decision they were worked out for.
    pub odds: Option<(u64, serde_json::Value)>,
}

/// A look-ahead seat's decision, taken out of the session to be thought out on a blocking thread
/// ([`Session::search_work`]), its answer handed back with [`Session::search_done`].
pub struct Thinking {
    search: rinshan_search::Search,
    state: GameState,
    seat: u32,
    own_draws: Vec<u32>,
    /// The decision it answers (the session's step count then).
    step: u64,
}

impl Thinking {
    /// The action, and the decision it is for.
    pub fn run(self) -> (u64, u32) {
        // Each decision's worlds seeded apart by the step (the game's seed is hidden from it).
        let d = self.search.decide(&self.state, self.seat, &self.own_draws, self.step);
        (self.step, d.action)
    }
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The env of one game, dealt from `seed`.
fn dealt(variant: Variant, mode: Mode, seed: u64) -> Result<Env, String> {
    let mut env = Env::new(Config {
        mode,
        seed,
        threads: Some(1),
        ..Config::new(variant, 1)
    })
    .map_err(err)?;
    env.reset().map_err(err)?;
    Ok(env)
}

/// The seat that deals East 1 of the game `seed` deals: the seed draws it, so a person who asks
/// for a wind (East = deal first) is seated from it before the game is made.
pub fn first_dealer(variant: Variant, mode: Mode, seed: u64) -> Result<u32, String> {
    let env = dealt(variant, mode, seed)?;
    let mut states = env.game_states().map_err(err)?;
    states
        .pop()
        .map(|s| s.dealer)
        .ok_or_else(|| "the env holds no game".to_string())
}

impl Session {
    /// A new game, dealt.
    pub fn new(setup: Setup) -> Result<Session, String> {
        if setup.seats.iter().filter(|s| s.is_none()).count() > 1 {
            return Err("at most one seat can be played by a person".into());
        }
        let env = dealt(setup.variant, setup.mode, setup.seed)?;
        let bot_seats = setup.seats.clone().map(|s| match s {
            Some(Opponent::Bot(b)) => Some(b),
            _ => None,
        });
        if bot_seats.iter().any(Option::is_some) && check_games(setup.variant, setup.mode, Backend::Cpu).is_err() {
            return Err("MJAI bots play Tenhou's rules (red, or sanma for three) in east or half games".into());
        }
        let bots = match bot_seats.iter().any(Option::is_some) {
            true => Some(Bots::new(
                std::array::from_fn(|p| bot_seats[p].as_ref()),
                env.game_states().map_err(err)?.pop().ok_or("the env holds no game")?,
                setup.variant,
            )),
            false => None,
        };
        // Tenhou logs hold east and half games (of any rule set, which the log names).
        let logged = setup.mode != Mode::Single;
        let recorder = logged.then(|| Recorder::new(&env)).transpose().map_err(err)?;
        let at_table = setup.variant.seats() as usize;
        let names: [String; 4] = std::array::from_fn(|p| match p < at_table {
            true => setup.seats[p]
                .as_ref()
                .map_or_else(|| "You".to_string(), |a| format!("{a} {p}")),
            false => String::new(),
        });
        let pass = rinshan_engine::env::action_names(setup.variant)
            .iter()
            .position(|n| n == "pass")
            .ok_or("the variant has no pass action")? as u32;
        let mut s = Session {
            setup,
            env,
            names,
            step: 0,
            ended: None,
            recorder,
            log: None,
            events: Vec::new(),
            told: 0,
            pass,
            held_view: None,
            touched: Instant::now(),
            bots,
            untold: Vec::new(),
            own_draws: Default::default(),
            odds: None,
        };
        let state = s.state()?;
        for q in 0..s.setup.variant.seats() {
            s.own_draws[q as usize].update(s.setup.variant, &state, &mut state.clone(), q);
        }
        // The log numbers seats from East 1's dealer, the page by the engine's seats.
        let first = s.state()?.dealer;
        if let Some(r) = &mut s.recorder {
            let seats = s.setup.variant.seats();
            r.set_names(std::array::from_fn(|i| match i as u32 {
                i if i < seats => s.names[((first + i) % seats) as usize].clone(),
                _ => String::new(),
            }));
        }
        s.events.push(format!(
            "{} begins",
            rinshan_render::round_name(0, s.setup.variant.seats())
        ));
        Ok(s)
    }

    /// The game's setup.
    pub fn setup(&self) -> &Setup {
        &self.setup
    }

    /// The seat the person plays.
    pub fn human(&self) -> Option<u32> {
        self.setup.seats.iter().position(Option::is_none).map(|p| p as u32)
    }

    fn current(&self) -> u32 {
        self.env.last().current_player[0]
    }

    /// Where the game stands.
    pub fn phase(&self) -> Phase {
        if self.ended.as_ref().is_some_and(|b| !b.over) {
            Phase::Result
        } else if self.env.last().terminated[0] || self.ended.is_some() {
            Phase::Over
        } else if Some(self.current()) == self.human() {
            Phase::Human
        } else {
            Phase::Agent
        }
    }

    fn state(&self) -> Result<GameState, String> {
        let mut states = self.env.game_states().map_err(err)?;
        states.pop().ok_or_else(|| "the env holds no game".to_string())
    }

    /// The board as the person may see it (a spectator sees every hand).
    pub fn board(&self) -> Result<Board, String> {
        let mut board = match (&self.ended, &self.held_view) {
            (Some(b), _) => b.clone(),
            (None, Some((b, _))) if self.claim_pending() => b.clone(),
            (None, _) => {
                let state = self.state()?;
                let mut board = Board::from_state(&state, self.setup.variant);
                if self.claim_pending() {
                    // No view held (the last discard of a round): the seat that plays on if
                    // nobody calls, not who may take the tile.
                    board.current = match state.claim_kan {
                        0 => (state.claim_from + 1) % self.setup.variant.seats(),
                        _ => state.claim_from,
                    };
                    board.claim = None;
                }
                board
            }
        };
        board.names = self.names.clone();
        Ok(board)
    }

    /// The board before a step, to hold if the step leaves a bot considering a call.
    fn view_before(&self) -> Option<(Board, usize)> {
        // Only a bot leaves a call to consider: without one, no board is drawn for nothing.
        self.bots.as_ref()?;
        match (&self.held_view, self.claim_pending()) {
            (Some(held), true) => Some(held.clone()),
            _ => self.board().ok().map(|b| (b, self.events.len())),
        }
    }

    /// What the page shows while a bot considers a call: what it shows when the built-in agents
    /// decide theirs (at once, out of sight). After another seat's move: the table as it was
    /// before it, as during any agent's pause. After the person's own move (their discard, or
    /// their pass on a discard), which the page shows at once: the table as it will be if everyone
    /// passes, the next seat having drawn (a face-down tile); a call, when made, is public
    /// anyway. When that next seat is the person, their draw is not shown early: the table as it
    /// was before their move, without its buttons (the one case in which the pause shows).
    fn hold_view(&mut self, before: Option<(Board, usize)>, person_moved: bool) {
        self.held_view = None;
        if !self.claim_pending() {
            return;
        }
        let Ok(state) = self.state() else { return };
        if person_moved && state.claim_kan == 0 {
            let passed = self.all_pass(&state).filter(|b| Some(b.current) != self.human());
            if let Some(mut passed) = passed {
                passed.names = self.names.clone();
                self.held_view = Some((passed, self.events.len()));
                return;
            }
        }
        self.held_view = before;
    }

    /// The board of `state` after every seat passes its claim prompt; `None` if the round would
    /// end there (its last discard), where there is no draw to show.
    fn all_pass(&self, state: &GameState) -> Option<Board> {
        let mut s = *state;
        let (rounds, pass) = (s.rounds, self.pass);
        with_variant!(self.setup.variant, v => {
            for _ in 0..4 {
                if s.phase != kernel::PHASE_CLAIM {
                    break;
                }
                v::game_step(&mut s, pass);
            }
        });
        let drew = s.rounds == rounds && s.terminated == 0 && s.phase != kernel::PHASE_CLAIM;
        drew.then(|| Board::from_state(&s, self.setup.variant))
    }

    /// `board` (this game's [`Session::board`]) drawn for the page (faces from the page's sprite).
    pub fn svg(&self, board: &Board, tiles: TileMode) -> String {
        let opts = Options {
            tiles,
            pov: self.human().unwrap_or(0),
            reveal: self.human().is_none() || self.phase() == Phase::Over,
            defs: false,
        };
        rinshan_render::svg(board, &opts)
    }

    /// The person's legal actions (none when it is not their turn).
    pub fn choices(&self) -> Vec<Choice> {
        if self.phase() != Phase::Human {
            return Vec::new();
        }
        let names = rinshan_engine::env::action_names(self.setup.variant);
        let claim = self.board().ok().and_then(|b| b.claim);
        self.env
            .last()
            .legal_actions(0)
            .map(|id| {
                let name = names
                    .get(id as usize)
                    .cloned()
                    .unwrap_or_else(|| format!("action {id}"));
                let tile = name.strip_prefix("discard_").map(str::to_string);
                Choice {
                    id,
                    label: label(&name, claim),
                    name,
                    tile,
                }
            })
            .collect()
    }

    /// The last lines of the game's story.
    pub fn events(&self) -> &[String] {
        let n = match (&self.held_view, self.claim_pending()) {
            (Some((_, shown)), true) => (*shown).min(self.events.len()),
            _ => self.events.len(),
        };
        &self.events[n.saturating_sub(12)..n]
    }

    /// Names by seat.
    pub fn names(&self) -> &[String; 4] {
        &self.names
    }

    /// The game's Tenhou log, once it is over (east and half games).
    pub fn log(&self) -> Result<&str, String> {
        if self.recorder.is_none() {
            return Err("Tenhou logs are written for east and half games only".into());
        }
        match (&self.log, self.phase()) {
            (Some(log), _) => Ok(log),
            (None, Phase::Over) if self.env.last().illegal[0] => {
                Err("the game ended by an illegal action: its log is not written".into())
            }
            (None, Phase::Over) => Err("the game stopped before its end: it has no log".into()),
            (None, _) => Err("the log is ready when the game is over".into()),
        }
    }

    /// The person plays `action`, named at decision `step` of the game.
    pub fn play(&mut self, action: u32, step: u64) -> Result<(), Refusal> {
        if step != self.step {
            return Err(Refusal::Stale(format!(
                "the move was made at decision {step}, the game is at decision {}",
                self.step
            )));
        }
        if self.phase() != Phase::Human {
            return Err(Refusal::Stale(
                format!("it is not your turn ({:?})", self.phase()).to_lowercase(),
            ));
        }
        if !self.env.last().legal_actions(0).any(|a| a == action) {
            let names = rinshan_engine::env::action_names(self.setup.variant);
            let what = names.get(action as usize).map_or_else(
                || format!("action {action} does not exist"),
                |n| format!("{n} ({action}) is not legal now"),
            );
            let legal: Vec<String> = self.choices().iter().map(|c| c.name.clone()).collect();
            return Err(Refusal::Illegal(format!("{what}; legal: {}", legal.join(", "))));
        }
        self.apply(action).map_err(Refusal::Illegal)
    }

    /// The built-in agent to move plays, if one is to move; `true` if it did (a bot's move is
    /// the driver's: see [`Session::bot_work`]).
    pub fn agent_move(&mut self) -> Result<bool, String> {
        if self.phase() != Phase::Agent || self.bot_to_move() || self.search_to_move() {
            return Ok(false);
        }
        let action = self.agent_action()?;
        self.apply(action)?;
        Ok(true)
    }

    fn agent_action(&mut self) -> Result<u32, String> {
        let current = self.current() as usize;
        let agent = match &self.setup.seats[current] {
            Some(Opponent::Net(net)) => return net.act(&self.state()?).map_err(|e| e.to_string()),
            Some(Opponent::Agent(a)) => *a,
            // The look-ahead leaves claims to its base agent.
            Some(Opponent::Search(o)) => o.base,
            _ => return Err("no built-in agent sits there".into()),
        };
        // Every seat gets the deciding seat's agent; only the current player's entry is read.
        let action = self.env.agent_actions(&[[agent; 4]]).map_err(err)?;
        Ok(action[0])
    }

    /// The current decision is a claim prompt (whether to call a discard or an added kan).
    fn claim_prompt(&self) -> bool {
        self.env.last().legal_actions(0).any(|a| a == self.pass)
    }

    /// The state and the person's seat at the person's own turn (a tile to discard, not a claim
    /// prompt): what the page's odds are worked out from. `None` at any other time.
    pub fn own_turn(&self) -> Option<(GameState, u32, Variant)> {
        if self.ended.is_some() || self.phase() != Phase::Human || self.claim_prompt() {
            return None;
        }
        Some((self.state().ok()?, self.human()?, self.setup.variant))
    }

    /// An agent or bot decides whether to call: the page must not learn who may.
    pub fn claim_pending(&self) -> bool {
        self.ended.is_none() && self.phase() == Phase::Agent && self.claim_prompt()
    }

    /// A look-ahead seat is to move on its own turn (its claims are answered at once).
    fn search_to_move(&self) -> bool {
        self.phase() == Phase::Agent
            && !self.claim_prompt()
            && matches!(self.setup.seats[self.current() as usize], Some(Opponent::Search(_)))
    }

    /// The look-ahead's decision to think out, when a look-ahead seat is to move.
    pub fn search_work(&self) -> Option<Thinking> {
        if !self.search_to_move() {
            return None;
        }
        let seat = self.current();
        let Some(Opponent::Search(options)) = &self.setup.seats[seat as usize] else {
            return None;
        };
        Some(Thinking {
            search: rinshan_search::Search::new(self.setup.variant, *options),
            state: self.state().ok()?,
            seat,
            own_draws: self.own_draws[seat as usize].positions.clone(),
            step: self.step,
        })
    }

    /// Plays the look-ahead's answer to decision `step`; `false` if the game has moved on since.
    pub fn search_done(&mut self, (step, action): (u64, u32)) -> Result<bool, String> {
        if step != self.step || !self.search_to_move() {
            return Ok(false);
        }
        self.apply(action)?;
        Ok(true)
    }

    /// A bot is to move.
    fn bot_to_move(&self) -> bool {
        self.phase() == Phase::Agent && matches!(self.setup.seats[self.current() as usize], Some(Opponent::Bot(_)))
    }

    /// The bots have work: to start, to hear steps, or to move.
    pub fn bot_due(&self) -> bool {
        self.bots
            .as_ref()
            .is_some_and(|b| b.waiting() || !self.untold.is_empty() || self.bot_to_move())
    }

    /// The bots' work, taken out of the session until [`Session::bot_done`] hands it back;
    /// `None` when they have none or are already at work.
    pub fn bot_work(&mut self) -> Option<Work> {
        if !self.bot_due() {
            return None;
        }
        let ask = match self.bot_to_move() {
            true => Some(Ask {
                seat: self.current() as usize,
                state: self.state().ok()?,
                step: self.step,
            }),
            false => None,
        };
        let bots = self.bots.take()?;
        Some(bots.work(std::mem::take(&mut self.untold), ask))
    }

    /// Takes the bots back from their work and plays the answer, if the game still waits for
    /// it; `true` if a move was made. A bot that failed is told on the page, and its failure at
    /// a decision plays an illegal action: the game ends with the rules' penalty.
    pub fn bot_done(&mut self, done: Done) -> Result<bool, String> {
        self.bots = Some(done.bots);
        for (p, why) in done.faults {
            self.bot_failed(p, &why);
        }
        let Some((ask, answer)) = done.answer else {
            return Ok(false);
        };
        if ask.step != self.step || !self.bot_to_move() || self.current() as usize != ask.seat {
            return Ok(false);
        }
        let action = answer.unwrap_or_else(|why| {
            self.bot_failed(ask.seat, &why);
            refused_action(&ask.state.mask)
        });
        if self.claim_prompt() {
            let before = self.view_before();
            self.step_once(action)?;
            self.answer_claims()?;
            self.hold_view(before, false);
        } else {
            self.apply(action)?;
        }
        Ok(true)
    }

    fn bot_failed(&mut self, seat: usize, why: &str) {
        // The page lists events in a narrow column: the bot's stderr tail stays in the message's
        // first few hundred characters.
        let short: String = why.chars().take(300).collect();
        self.events.push(format!("{} failed: {short}", self.names[seat]));
    }

    /// The seed the game deals from, where the page may see it: always for a spectated game, and
    /// once it is over for a game with a person (for a replay; while it runs it would show every
    /// hand and draw to whoever searched the seed's games).
    pub fn shown_seed(&self) -> Option<u64> {
        (self.human().is_none() || self.phase() == Phase::Over).then_some(self.setup.seed)
    }

    /// Tells the page something about the game that is not a move.
    pub fn note(&mut self, what: &str) {
        self.events.push(what.to_string());
    }

    /// Ends the game where it stands (the engine failed), telling the page why.
    pub fn stop(&mut self, why: &str) {
        self.events.push(format!("the game stopped: {why}"));
        let mut board = self
            .board()
            .unwrap_or_else(|_| Board::from_state(&GameState::zeroed(), self.setup.variant));
        board.over = true;
        self.ended = Some(board);
    }

    /// Leaves a round's result for the next round.
    pub fn next_round(&mut self) -> Result<(), Refusal> {
        if self.phase() != Phase::Result {
            return Err(Refusal::Stale("no round result is waiting".into()));
        }
        self.ended = None;
        self.step += 1;
        let b = self.board().map_err(Refusal::Illegal)?;
        self.events.push(format!("{} begins", b.round_name()));
        Ok(())
    }

    /// Plays `action`, then every agent's claim prompt that follows at once: who may call a
    /// discard is hidden information, so the page never sees an agent considering a call (no
    /// delay, no `current`, no decision counted); it sees the call, if one is made, on the table.
    fn apply(&mut self, action: u32) -> Result<(), String> {
        let (before, person_moved) = (self.view_before(), self.phase() == Phase::Human);
        self.step_once(action)?;
        self.step += 1;
        self.answer_claims()?;
        self.hold_view(before, person_moved);
        Ok(())
    }

    /// The built-in agents' claim prompts that follow, answered at once; a bot's waits for it.
    fn answer_claims(&mut self) -> Result<(), String> {
        while self.phase() == Phase::Agent && self.claim_prompt() && !self.bot_to_move() {
            let a = self.agent_action()?;
            self.step_once(a)?;
        }
        Ok(())
    }

    fn step_once(&mut self, action: u32) -> Result<(), String> {
        let before = self.state()?;
        let step = self.env.step(&[action]).map_err(err)?.clone();
        if self.setup.seats.iter().any(|s| matches!(s, Some(Opponent::Bot(_)))) {
            self.untold.push(Stepped {
                before,
                action,
                after: self.state()?,
            });
        }
        if self.setup.seats.iter().any(|s| matches!(s, Some(Opponent::Search(_)))) {
            let after = self.state()?;
            for q in 0..self.setup.variant.seats() {
                self.own_draws[q as usize].update(self.setup.variant, &before, &mut after.clone(), q);
            }
        }
        if let Some(r) = &mut self.recorder {
            r.observe(&self.env, &[action]).map_err(err)?;
            if let Some(done) = r.take_finished().pop() {
                self.log = Some(rinshan_logs::tenhou::write::game_text(&done.game));
            }
        }
        let e = step.events[0];
        if e & ev::ROUND_OVER == 0 {
            self.tell(&self.state()?);
        }
        if e & ev::ROUND_OVER != 0 {
            let table = self.env.tables().map_err(err)?.remove(0);
            let end = RoundEndInput {
                action,
                step: &step,
                env: 0,
                table: &table,
                variant: self.setup.variant,
                uma: self.env.uma(),
            };
            let mut board = Board::round_end(&before, &end).ok_or("a round ended without a result")?;
            board.names = self.names.clone();
            let deltas: Vec<String> = board
                .result
                .iter()
                .flat_map(|r| {
                    r.deltas
                        .iter()
                        .enumerate()
                        .map(|(p, d)| format!("{} {d:+}", self.names[p]))
                })
                .collect();
            self.events
                .push(format!("{} ends: {}", board.round_name(), deltas.join(", ")));
            self.ended = Some(board);
            // The next round's record starts afresh.
            self.told = 0;
        }
        if step.terminated[0] && self.ended.is_none() {
            self.ended = Some(Board::from_state(&self.state()?, self.setup.variant));
        }
        Ok(())
    }

    /// Adds the table's new public events (discards, calls, kans, riichi) to the story: what every
    /// seat saw, never a decision that changed nothing on the table.
    fn tell(&mut self, state: &GameState) {
        let mut s = *state;
        let n = kernel::log_count(&mut s);
        for i in self.told.min(n)..n {
            let e = kernel::log_entry(&mut s, i);
            let tile = u8::try_from(kernel::log_tile(e))
                .ok()
                .and_then(Tile::from_value)
                .map_or_else(String::new, |t| spoken(&t.name()));
            let what = match kernel::log_kind(e) {
                kernel::EV_DISCARD if kernel::log_flags(e) & kernel::LOG_TSUMOGIRI != 0 => {
                    format!("discards {tile} (just drawn)")
                }
                kernel::EV_DISCARD => format!("discards {tile}"),
                kernel::EV_CHI => format!("chi {tile}"),
                kernel::EV_PON => format!("pon {tile}"),
                kernel::EV_OPEN_KAN => format!("kan {tile}"),
                kernel::EV_CLOSED_KAN => format!("closed kan {tile}"),
                kernel::EV_ADDED_KAN => format!("added kan {tile}"),
                kernel::EV_RIICHI => "riichi".to_string(),
                _ => continue,
            };
            let who = &self.names[kernel::log_actor(e) as usize];
            self.events.push(format!("{who}: {what}"));
        }
        self.told = n;
    }
}

/// A button's words for an action named `name` (chi says which run it makes with `claim`).
pub fn label(name: &str, claim: Option<Tile>) -> String {
    if let Some(t) = name.strip_prefix("discard_") {
        return format!("Discard {}", spoken(t));
    }
    if let Some(t) = name.strip_prefix("self_kan_") {
        return format!("Kan {}", spoken(t));
    }
    let run = |offsets: [i8; 3]| -> String {
        let Some(t) = claim else { return String::new() };
        let k = t.kind();
        let (Some(n), Some(suit)) = (k.number(), k.name().chars().last()) else {
            return String::new();
        };
        let digits: String = offsets.iter().map(|o| char::from(b'0' + (n as i8 + o) as u8)).collect();
        format!(" {digits}{suit}")
    };
    let red = if name.ends_with("_red") { " (red 5)" } else { "" };
    let base = name.trim_end_matches("_red");
    match base {
        "chi_left" => format!("Chi{}{red}", run([0, 1, 2])),
        "chi_middle" => format!("Chi{}{red}", run([-1, 0, 1])),
        "chi_right" => format!("Chi{}{red}", run([-2, -1, 0])),
        "pon" => format!("Pon{}{red}", on(claim)),
        "open_kan" => format!("Kan{}", on(claim)),
        "tsumogiri" => "Discard drawn tile".into(),
        "riichi" => "Riichi".into(),
        "tsumo" => "Tsumo".into(),
        "ron" => format!("Ron{}", on(claim)),
        "pass" => "Pass".into(),
        "kyuushu" => "Nine terminals (draw)".into(),
        "dummy" => "Continue".into(),
        other => other.replace('_', " "),
    }
}

/// ` 7s`: the claimed tile, after a call's name.
fn on(claim: Option<Tile>) -> String {
    claim.map_or_else(String::new, |t| format!(" {}", spoken(&t.name())))
}

/// A tile name as the board's labels read: `E`, `Rd`, `red 5m`.
fn spoken(name: &str) -> String {
    match rinshan_engine::notation::parse_tile(name) {
        Ok(t) if t.is_red() => format!("red {}", rinshan_render::tile_label(t)),
        Ok(t) => rinshan_render::tile_label(t),
        Err(_) => name.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup(seats: [Option<Agent>; 4]) -> Setup {
        Setup {
            variant: Variant::Red,
            mode: Mode::East,
            seats: seats.map(|s| s.map(Opponent::Agent)),
            seed: 5,
            delay: Duration::ZERO,
        }
    }

    #[test]
    fn a_stopped_game_is_over_and_says_why() {
        let mut s =
            Session::new(setup([None, Some(Agent::Rule), Some(Agent::Rule), Some(Agent::Rule)])).expect("a game");
        s.stop("the device was lost");
        assert_eq!(s.phase(), Phase::Over);
        assert!(s.events().last().is_some_and(|e| e.contains("the device was lost")));
        assert!(s.choices().is_empty());
    }

    #[test]
    fn two_people_cannot_share_a_game() {
        let e = Session::new(setup([None, None, Some(Agent::Rule), Some(Agent::Rule)])).err();
        assert_eq!(e.as_deref(), Some("at most one seat can be played by a person"));
    }

    #[test]
    fn buttons_name_the_tiles() {
        let t = rinshan_engine::notation::parse_tile("4p").ok();
        assert_eq!(label("chi_left", t), "Chi 456p");
        assert_eq!(label("chi_middle_red", t), "Chi 345p (red 5)");
        assert_eq!(label("chi_right", t), "Chi 234p");
        assert_eq!(label("pon", rinshan_engine::notation::parse_tile("7z").ok()), "Pon Rd");
        assert_eq!(label("discard_0s", None), "Discard red 5s");
        assert_eq!(label("self_kan_1z", None), "Kan E");
    }

    /// What the person sees of a board: their own hand, the others' hand sizes and whether they
    /// hold a drawn tile, and everything on the table.
    fn seen(s: &Session) -> String {
        let mut b = s.board().expect("a board");
        let sizes: Vec<(usize, bool)> = (0..4).map(|p| (b.hands[p].len(), b.drawn[p].is_some())).collect();
        for p in 1..4 {
            b.hands[p].clear();
            b.drawn[p] = None;
        }
        format!("{b:?} {sizes:?} {:?} {}", s.events(), s.choices().len())
    }

    #[test]
    fn bots_decide_their_calls_out_of_sight() {
        // The stdlib test bot pons every pair it can; with a person at seat 0 and bots at 1 and
        // 3, the page shows, while a bot considers a call, what it shows when the built-in
        // agents decide theirs at once: the view before another seat's discard, or after the
        // person's own move the view that follows if nobody calls. Views are read from the
        // session's state alone, so a bot's thinking time cannot change them; every state the
        // page could read while a bot thinks is checked here, before its work is taken.
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/bots/simple_bot.py");
        let bot = |name: &str| NamedBot {
            name: name.into(),
            spec: rinshan_logs::mjai::bot::BotSpec {
                command: format!("python3 {script} --dialect app"),
                dialect: rinshan_logs::mjai::bot::Dialect::App,
                timeout: Duration::from_secs(5),
                startup: Duration::from_secs(20),
            },
        };
        let seats = [
            None,
            Some(Opponent::Bot(bot("a"))),
            Some(Opponent::Agent(Agent::Rule)),
            Some(Opponent::Bot(bot("b"))),
        ];
        let mut s = Session::new(Setup {
            seats,
            ..setup([None; 4])
        })
        .expect("a game");
        let (mut frozen, mut forecast, mut forecast_kept, mut moves) = (0, 0, 0, 0);
        // The last view with no call pending, and a pending view that was not it.
        let mut free = seen(&s);
        let mut ahead: Option<(String, usize)> = None;
        while s.phase() != Phase::Over {
            let view = seen(&s);
            if s.claim_pending() {
                let b = s.board().expect("a board");
                let cur = b.current as usize;
                // The seat shown to move holds a whole hand: never 13 tiles and no draw.
                assert_eq!(
                    (b.hands[cur].len() + usize::from(b.drawn[cur].is_some())) % 3,
                    2,
                    "{view}"
                );
                assert_eq!(b.claim, None);
                if view == free {
                    frozen += 1;
                } else {
                    assert_ne!(b.current, 0, "the person's own draw shown early");
                    let melds: usize = b.melds.iter().map(Vec::len).sum();
                    ahead = Some((view.clone(), melds));
                }
            } else {
                if let Some((forecast_view, melds)) = ahead.take() {
                    forecast += 1;
                    let b = s.board().expect("a board");
                    let called = b.melds.iter().map(Vec::len).sum::<usize>() > melds;
                    if !called && s.ended.is_none() {
                        // Nobody called: the view shown while the bot thought is what followed.
                        assert_eq!(view, forecast_view);
                        forecast_kept += 1;
                    }
                }
                free = view;
            }
            if let Some(work) = s.bot_work() {
                s.bot_done(work.run()).expect("the bots' move");
                continue;
            }
            match s.phase() {
                Phase::Agent => assert!(s.agent_move().expect("a move")),
                Phase::Human => s.play(s.choices()[0].id, s.step).expect("a legal move"),
                Phase::Result => s.next_round().expect("the next round"),
                Phase::Over => {}
            }
            moves += 1;
            assert!(moves < 20_000);
        }
        assert!(
            frozen > 0 && forecast_kept > 0,
            "frozen {frozen}, forecast {forecast} ({forecast_kept} kept)"
        );
        assert!(!s.events.iter().any(|e| e.contains("failed")), "{:?}", s.events);
    }

    #[test]
    fn agents_decide_their_calls_out_of_sight() {
        // Four agents, played to the end: the page never finds an agent at a claim prompt.
        let mut s = Session::new(setup([Some(Agent::Rule); 4])).expect("a game");
        let mut moves = 0;
        while s.phase() != Phase::Over {
            match s.phase() {
                Phase::Agent => {
                    assert!(!s.claim_prompt(), "an agent's claim prompt was left open");
                    s.agent_move().expect("a move");
                    moves += 1;
                }
                Phase::Result => s.next_round().expect("the next round"),
                _ => unreachable!(),
            }
            assert!(moves < 20_000);
        }
        assert!(moves > 100 && u64::try_from(moves).is_ok_and(|m| s.step >= m));
    }
}
