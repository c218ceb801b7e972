//! An MJAI bot as a seat of the engine's games ([`rinshan_engine::arena::Entrant`]): one process
//! per game, told the game's events in its seat's view and asked at its seat's decisions.
//!
//! A bot that fails (no reply within the timeout, a malformed or illegal reaction, a crash) makes
//! its seat play an illegal action, so the game ends with the engine's illegal-action penalty
//! (`ILLEGAL_ACTION_PENALTY` of the rules, as the rewards report it); the arena reports the fault
//! with the bot's stderr tail, and the other games go on.

use rinshan_engine::arena::{Entrant, Seat};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;

use super::bot::{Bot, BotSpec, Dialect};
use super::event::Event;
use super::live::{view, Live};
use super::reaction::action_of;

/// Runs `spec`'s bot in each game it joins: games of Tenhou's rules (`red`, or `sanma` with three
/// seats' lists and `kita`), east or half (what MJAI and the log recorder describe; `rinshan
/// arena` and `selfplay` check it with [`super::bot::check_games`] before they start).
#[derive(Debug, Clone)]
pub struct MjaiEntrant {
    /// The bot.
    pub spec: BotSpec,
}

/// The bot in one game.
pub struct MjaiSeat {
    live: Result<Live, String>,
    bot: Result<Bot, String>,
    seat: u8,
    variant: Variant,
    /// Events of `live` already sent.
    sent: usize,
    /// Why the bot can play no more of this game.
    broken: Option<String>,
}

impl MjaiEntrant {
    /// Starts the bot for seat `seat` (the engine's) of the game of `variant` that starts in
    /// `state`.
    pub fn start(&self, seat: u32, state: &GameState, variant: Variant) -> MjaiSeat {
        let live = Live::new(state, ["", "", "", ""].map(String::from), variant);
        let mjai_seat = live.as_ref().map_or(0, |l| l.mjai_seat(seat));
        let mut s = MjaiSeat {
            bot: Bot::spawn(&self.spec, mjai_seat, variant.seats() as usize),
            live,
            seat: mjai_seat,
            variant,
            sent: 0,
            broken: None,
        };
        if self.spec.dialect == Dialect::App {
            // mjai.app asks for a `none` to `start_game` before the first round.
            s.acknowledge(1);
        }
        s
    }
}

impl Entrant for MjaiEntrant {
    fn join(&self, seat: u32, state: &GameState, variant: Variant) -> Box<dyn Seat + '_> {
        Box::new(self.start(seat, state, variant))
    }
}

impl MjaiSeat {
    /// This seat's view of the events after the last sent, up to `end` (exclusive).
    fn unsent(&mut self, end: usize) -> Result<Vec<Event>, String> {
        let live = self.live.as_ref().map_err(String::clone)?;
        let end = end.min(live.events().len());
        let events = live.events()[self.sent.min(end)..end]
            .iter()
            .map(|e| view(e, self.seat))
            .collect();
        self.sent = end;
        Ok(events)
    }

    fn bot(&mut self) -> Result<&mut Bot, String> {
        if let Some(why) = &self.broken {
            return Err(format!("the bot failed earlier in this game: {why}"));
        }
        self.bot.as_mut().map_err(|e| e.clone())
    }

    /// Sends the events up to `end` and has the bot acknowledge them (App) or just reads them
    /// (Stdio); a failure breaks the seat.
    fn acknowledge(&mut self, end: usize) -> Option<String> {
        let result = self
            .unsent(end)
            .and_then(|events| self.bot().and_then(|bot| bot.acknowledge(&events)));
        let err = result.err()?;
        self.broken.get_or_insert(err.clone());
        Some(err)
    }
}

impl Seat for MjaiSeat {
    fn act(&mut self, state: &GameState) -> Result<u32, String> {
        let end = self.live.as_ref().map_or(0, |l| l.events().len());
        let events = self.unsent(end)?;
        let reaction = self.bot()?.ask(&events).inspect_err(|e| {
            self.broken = Some(e.clone());
        })?;
        action_of(&reaction, self.seat, state, self.variant).map_err(|e| {
            let text = serde_json::to_string(&reaction).unwrap_or_default();
            let why = format!("illegal reaction {text}: {e}");
            self.broken = Some(why.clone());
            why
        })
    }

    fn stepped(&mut self, before: &GameState, action: u32, after: &GameState) -> Result<(), String> {
        // A seat that cannot follow its game says why once, at its next decision.
        let (Ok(live), None) = (self.live.as_mut(), &self.broken) else {
            return Ok(());
        };
        if let Err(e) = live.step(before, action, after) {
            self.broken = Some(e.clone());
            return Err(e);
        }
        // Round and game ends are acknowledged as they come (App), or sent at once (Stdio: a
        // bot that is never asked again still hears how its game ended).
        let sent = self.sent.min(live.events().len());
        let ends = live.events()[sent..]
            .iter()
            .rposition(|e| matches!(e, Event::EndKyoku {} | Event::EndGame { .. }))
            .map(|i| sent + i + 1);
        match ends {
            Some(end) => self.acknowledge(end).map_or(Ok(()), Err),
            None => Ok(()),
        }
    }
}
