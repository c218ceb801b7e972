//! A game being played, as the MJAI events the engines send live: followed step by step on the
//! kernel's states, and cut into each seat's view (others' draws and starting hands as `?`).
//!
//! The events of a round in play are the log writer's ([`super::write`]) for the entries played so
//! far, so a live stream is the game's MJAI log up to now; each step checks that what was already
//! sent is still a prefix of the round's events (a riichi discard's `reach_accepted` waits for the
//! claims on it, a declared riichi's `reach` comes before its discard).

use rinshan_engine::env::events::ROUND_OVER;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::Variant;

use super::event::Event;
use super::tile::Pai;
use super::write::{round_events, round_so_far, start_game};
use crate::tenhou::log::Game;
use crate::tenhou::write::GameRecorder;

/// One game's events so far, for every seat.
#[derive(Debug, Clone)]
pub struct Live {
    recorder: GameRecorder,
    events: Vec<Event>,
    /// Where the round in play starts in `events`.
    round_start: usize,
    first: u32,
    /// Players at the table.
    seats: u32,
    game: Option<Game>,
    over: bool,
}

impl Live {
    /// Follows the game of `variant` in `state`, which has just dealt its first round (a reset or
    /// a deal).
    pub fn new(state: &GameState, names: [String; 4], variant: Variant) -> Result<Live, String> {
        let mut recorder = GameRecorder::for_variant(state, variant)?;
        recorder.names = names;
        let first = recorder.in_play().map_or(0, |p| p.first);
        let mut live = Live {
            events: vec![start_game(
                &recorder.names,
                recorder.rule(),
                variant.red_fives(),
                variant,
            )],
            round_start: 1,
            recorder,
            first,
            seats: variant.seats(),
            game: None,
            over: false,
        };
        live.sync()?;
        Ok(live)
    }

    /// Every event so far, unmasked.
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// The MJAI seat (East 1's dealer is 0) of the engine's seat `p`.
    pub fn mjai_seat(&self, p: u32) -> u8 {
        ((p + self.seats - self.first) % self.seats) as u8
    }

    /// The game ended (by the rules, with `end_game` sent, or by an illegal action).
    pub fn is_over(&self) -> bool {
        self.over
    }

    /// The whole game's record, once it ended by the rules.
    pub fn game(&self) -> Option<&Game> {
        self.game.as_ref()
    }

    /// Follows the step that took the game from `before` to `after` with `action`.
    pub fn step(&mut self, before: &GameState, action: u32, after: &GameState) -> Result<(), String> {
        if self.over {
            return Ok(());
        }
        let game = self.recorder.record(before, action, after)?;
        if after.illegal != 0 {
            // No rule ends the round: the stream just stops.
            self.over = true;
            return Ok(());
        }
        if let Some(game) = game {
            let last = game.rounds.last().ok_or("the game ended with no round")?;
            self.finish_round(last)?;
            self.events.push(Event::EndGame { scores: None });
            self.game = Some(game);
            self.over = true;
            return Ok(());
        }
        if after.events & ROUND_OVER != 0 {
            let last = self
                .recorder
                .rounds()
                .last()
                .ok_or("a round ended but none was filed")?;
            let last = last.clone();
            self.finish_round(&last)?;
        }
        self.sync()
    }

    /// Sends the finished round's remaining events (its result and `end_kyoku`).
    fn finish_round(&mut self, round: &crate::tenhou::log::Round) -> Result<(), String> {
        let mut all = Vec::new();
        round_events(round, &mut all)?;
        self.extend(all)?;
        self.round_start = self.events.len();
        Ok(())
    }

    /// Sends the round in play's events not sent yet.
    fn sync(&mut self) -> Result<(), String> {
        let Some(in_play) = self.recorder.in_play() else {
            return Ok(());
        };
        let mut now = Vec::new();
        round_so_far(&in_play.round, in_play.order, in_play.declared, &mut now)?;
        self.extend(now)
    }

    fn extend(&mut self, round: Vec<Event>) -> Result<(), String> {
        let sent = &self.events[self.round_start..];
        if let Some(i) = sent.iter().zip(&round).position(|(a, b)| a != b) {
            return Err(format!(
                "the round's events changed after they were sent: event {} was {}, now {}",
                i + 1,
                serde_json::to_string(&sent[i]).unwrap_or_default(),
                serde_json::to_string(&round[i]).unwrap_or_default()
            ));
        }
        if round.len() < sent.len() {
            return Err(format!(
                "the round's events shrank after they were sent: {} sent, now {}",
                sent.len(),
                round.len()
            ));
        }
        let n = sent.len();
        self.events.extend(round.into_iter().skip(n));
        Ok(())
    }
}

/// `event` as MJAI seat `seat` sees it: others' starting hands and draws hidden, its own seat
/// named in `start_game`.
pub fn view(event: &Event, seat: u8) -> Event {
    let mut seen = event.clone();
    match &mut seen {
        Event::StartGame { id, .. } => *id = Some(seat),
        Event::StartKyoku { tehais, .. } => {
            for (_, hand) in tehais.iter_mut().enumerate().filter(|(s, _)| *s != usize::from(seat)) {
                *hand = vec![Pai::HIDDEN; hand.len()];
            }
        }
        Event::Tsumo { actor, pai } if *actor != seat => *pai = Pai::HIDDEN,
        _ => {}
    }
    seen
}
