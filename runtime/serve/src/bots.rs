//! MJAI bots at the page's table: programs the operator names at `rinshan serve --mjai-bot
//! NAME=COMMAND` (a client picks a bot by its name, never a command). A bot is told every step of
//! its game and asked at its seat's decisions; it may take seconds to answer, so that work is taken
//! out of the game's session ([`Work`]) and done on a blocking thread while the page goes on
//! reading the game as it stands, then handed back ([`Done`]).

use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::BotSpec;
use rinshan_logs::mjai::seat::{MjaiEntrant, MjaiSeat};

use rinshan_engine::arena::Seat as _;

/// A bot the server offers.
#[derive(Debug, Clone)]
pub struct NamedBot {
    /// What the page calls it (`mjai:NAME` in a new game's agents).
    pub name: String,
    /// How to run it.
    pub spec: BotSpec,
}

/// A bot seat: started at the first work of its game (starting one may wait for its reply to
/// `start_game`), then playing.
enum Slot {
    Waiting(MjaiEntrant),
    Playing(Box<MjaiSeat>),
}

/// The bots of one game, by seat.
pub struct Bots {
    slots: [Option<Slot>; 4],
    /// The game's first state (a bot joins from it).
    start: GameState,
    /// The game's rules.
    variant: Variant,
}

/// A step of the game, as every bot is told it.
pub struct Stepped {
    pub(crate) before: GameState,
    pub(crate) action: u32,
    pub(crate) after: GameState,
}

/// What the bots are to do away from the session: hear the steps played since they last heard,
/// and, when a bot is to move, answer for its seat.
pub struct Work {
    bots: Bots,
    told: Vec<Stepped>,
    ask: Option<Ask>,
}

/// A question to a bot: its seat, the state it decides in, and the session's decision count then
/// (the answer is played only if the game is still there).
#[derive(Clone, Copy)]
pub struct Ask {
    pub(crate) seat: usize,
    pub(crate) state: GameState,
    pub(crate) step: u64,
}

/// The work done: the bots to put back, what went wrong (seat, why), and the answer asked for.
pub struct Done {
    pub(crate) bots: Bots,
    pub(crate) faults: Vec<(usize, String)>,
    pub(crate) answer: Option<(Ask, Result<u32, String>)>,
}

impl Bots {
    /// The bots of a game of `variant` that starts in `start`, at the seats given.
    pub fn new(seats: [Option<&NamedBot>; 4], start: GameState, variant: Variant) -> Bots {
        Bots {
            slots: seats.map(|b| b.map(|b| Slot::Waiting(MjaiEntrant { spec: b.spec.clone() }))),
            start,
            variant,
        }
    }

    /// A bot that has not started yet.
    pub fn waiting(&self) -> bool {
        self.slots.iter().any(|s| matches!(s, Some(Slot::Waiting(_))))
    }

    /// The work of telling `told` and answering `ask`.
    pub fn work(self, told: Vec<Stepped>, ask: Option<Ask>) -> Work {
        Work { bots: self, told, ask }
    }
}

impl Work {
    /// Does the work: blocks for as long as the bots take (each read at most their timeout).
    pub fn run(mut self) -> Done {
        let mut faults = Vec::new();
        let (start, variant) = (self.bots.start, self.bots.variant);
        for (p, slot) in self.bots.slots.iter_mut().enumerate() {
            if let Some(Slot::Waiting(entrant)) = slot {
                *slot = Some(Slot::Playing(Box::new(entrant.start(p as u32, &start, variant))));
            }
        }
        for (p, slot) in self.bots.slots.iter_mut().enumerate() {
            let Some(Slot::Playing(seat)) = slot else { continue };
            for s in &self.told {
                if let Err(e) = seat.stepped(&s.before, s.action, &s.after) {
                    faults.push((p, e));
                }
            }
        }
        let answer = self.ask.map(|ask| {
            let action = match &mut self.bots.slots[ask.seat] {
                Some(Slot::Playing(seat)) => seat.act(&ask.state),
                _ => Err("no bot sits there".to_string()),
            };
            (ask, action)
        });
        Done {
            bots: self.bots,
            faults,
            answer,
        }
    }
}
