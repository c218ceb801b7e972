//! Replaying logged games into training rows: each decision of the chosen seats, with that seat's
//! observation, its legal mask and the action the log took; per game its final scores and ranks.
//! A game is kept whole or not at all: one round that does not replay exactly, or a log that stops
//! before the game ends, skips the game with the reason.

use std::collections::HashMap;

use rinshan_engine::env::{action_names, Table};
use rinshan_engine::observe::Form;
use rinshan_engine::Variant;
use rinshan_logs::file::parse_log;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::replay::{mode_of, replay_visiting, Decision, Visitor};
use rinshan_search::Search;

use crate::inputs::Unit;
use crate::label::label_rows;

/// The rules datasets are made in unless asked otherwise: Tenhou's four-player rules (with red
/// fives or not: the tiles say which are red).
pub const DEFAULT_VARIANT: Variant = Variant::Red;

/// Whose decisions become rows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Seats {
    /// Every seat.
    All,
    /// These absolute seats (0 = East 1's dealer).
    Some([bool; 4]),
    /// The seats of these player names (as the logs spell them).
    Players(Vec<String>),
}

impl Seats {
    /// The selection a caller asked for: these absolute `seats` (each 0..3), or these `players`,
    /// or every seat when neither is given.
    pub fn chosen(seats: Option<&[u8]>, players: Option<&[String]>) -> Result<Seats, String> {
        match (seats, players) {
            (Some(_), Some(_)) => Err("give seats or players, not both".into()),
            (None, Some(names)) => Ok(Seats::Players(names.to_vec())),
            (Some(list), None) => {
                let mut keep = [false; 4];
                for &s in list {
                    if s > 3 {
                        return Err(format!("seat {s}: seats are 0..3"));
                    }
                    keep[s as usize] = true;
                }
                Ok(Seats::Some(keep))
            }
            (None, None) => Ok(Seats::All),
        }
    }

    fn keeps(&self, game: &Game, seat: usize) -> bool {
        match self {
            Seats::All => true,
            Seats::Some(seats) => seats[seat],
            Seats::Players(names) => names.iter().any(|n| *n == game.names[seat]),
        }
    }

    /// How the manifest writes it.
    pub fn describe(&self) -> String {
        match self {
            Seats::All => "all".into(),
            Seats::Some(s) => {
                let list: Vec<String> = (0..4).filter(|&p| s[p]).map(|p| p.to_string()).collect();
                format!("seats {}", list.join(","))
            }
            Seats::Players(names) => format!("players {}", names.join(",")),
        }
    }
}

/// What rows to make.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// The rules the logs are replayed in; a log of other rules is skipped, as one dataset's rows
    /// share one action layout.
    pub variant: Variant,
    /// The observation forms each row holds (not the oracle: a row is what its seat saw).
    pub forms: Vec<Form>,
    /// Whose decisions.
    pub seats: Seats,
    /// Keep decisions with one legal action (a claim prompt's lone pass cannot be one: it comes
    /// with the claim; a forced draw-and-discard has more than one discard). Off by default: such
    /// a row teaches nothing.
    pub forced: bool,
    /// The look-ahead that labels each row (`search:rollouts=N:...` as the agent is written): each
    /// row then also gets its action and its value of each action ([`crate::label`]). `None`: no
    /// labels.
    pub search: Option<String>,
}

impl Options {
    /// The labelling look-ahead, or `Err` with the reason its settings do not parse.
    pub fn look_ahead(&self) -> Result<Option<Search>, String> {
        self.search
            .as_deref()
            .map(|spec| {
                spec.parse::<rinshan_search::Options>()
                    .map(|o| Search::new(self.variant, o))
                    .map_err(|e| format!("--search {spec}: {e}"))
            })
            .transpose()
    }
}

/// The rows of one game, column by column.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GameRows {
    /// The log's name.
    pub name: String,
    /// Per form of [`Options::forms`], each row's record (`Form::bytes` each).
    pub observations: Vec<Vec<u8>>,
    /// Each row's legal actions, one byte (0 or 1) per action id.
    pub mask: Vec<u8>,
    /// The action id the log took.
    pub action: Vec<u8>,
    /// The deciding seat (absolute).
    pub seat: Vec<u8>,
    /// The round (index into the log's rounds).
    pub round: Vec<u8>,
    /// The look-ahead's action (empty unless [`Options::search`]).
    pub search_action: Vec<u8>,
    /// The look-ahead's value of each action id (minus the expected final rank), NaN for one it
    /// did not play out (empty unless [`Options::search`]).
    pub search_value: Vec<f32>,
    /// Each row's round and decision index in it (claim prompts counted), where the look-ahead
    /// finds it.
    pub at: Vec<(usize, usize)>,
    /// Each seat's points at the end of the game.
    pub scores: [i32; 4],
    /// Each seat's final place (0 = first), as uma pays it.
    pub ranks: [u8; 4],
}

impl GameRows {
    /// Rows held.
    pub fn rows(&self) -> usize {
        self.action.len()
    }
}

/// What became of one log.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Its rows.
    Rows(Box<GameRows>),
    /// Why it was skipped.
    Skipped(String),
}

struct Recorder<'a> {
    games: &'a [&'a Game],
    options: &'a Options,
    num_actions: usize,
    rows: Vec<GameRows>,
    over: Vec<bool>,
    /// Per game, the round being replayed and the decisions seen in it so far.
    step: Vec<(usize, usize)>,
    bug: Option<String>,
}

impl Visitor for Recorder<'_> {
    fn decision(&mut self, d: &Decision) {
        let (i, step) = (d.slot, d.step);
        let game = d.game;
        let seat = step.current_player[i] as usize;
        let at = &mut self.step[game];
        if at.0 != d.round {
            *at = (d.round, 0);
        }
        let here = *at;
        at.1 += 1;
        let mask = step.legal_action_mask[i];
        let legal = |a: u32| mask[(a / 32) as usize] >> (a % 32) & 1 == 1;
        let count: u32 = mask.iter().map(|w| w.count_ones()).sum();
        if (count == 1 && !self.options.forced) || !self.options.seats.keeps(self.games[game], seat) {
            return;
        }
        if !legal(d.action) {
            // The replay plays only legal moves: a row breaking its own mask is rinshan's bug.
            self.bug.get_or_insert_with(|| {
                format!(
                    "{}: round {}: action {} is not legal under its own mask {mask:?}",
                    self.games[game].path, d.round, d.action
                )
            });
            return;
        }
        let rows = &mut self.rows[game];
        for (f, &form) in self.options.forms.iter().enumerate() {
            let bytes = form.bytes();
            // The replay's env observes every form of the options each step.
            if let Some(all) = d.env.observation(form) {
                rows.observations[f].extend_from_slice(&all[i * bytes..(i + 1) * bytes]);
            }
        }
        rows.mask
            .extend((0..self.num_actions as u32).map(|a| u8::from(legal(a))));
        rows.action.push(d.action as u8);
        rows.seat.push(seat as u8);
        rows.round.push(d.round.min(255) as u8);
        rows.at.push(here);
    }

    fn game_over(&mut self, game: usize, ranks: [u8; 4], table: &Table) {
        self.over[game] = true;
        self.rows[game].scores = table.scores;
        self.rows[game].ranks = ranks;
    }
}

/// Replays `games` (all of one length: East or half) and returns each one's outcome, in order.
/// `Err` only for a bug of rinshan's (a row against its own mask) or an env that cannot be made.
fn record_group(games: &[&Game], options: &Options) -> Result<Vec<Outcome>, String> {
    let num_actions = action_names(options.variant).len();
    let owned: Vec<Game> = games.iter().map(|&g| g.clone()).collect();
    let mut recorder = Recorder {
        games,
        options,
        num_actions,
        rows: games
            .iter()
            .map(|g| GameRows {
                name: g.path.clone(),
                observations: vec![Vec::new(); options.forms.len()],
                ..GameRows::default()
            })
            .collect(),
        over: vec![false; games.len()],
        step: vec![(usize::MAX, 0); games.len()],
        bug: None,
    };
    let report = replay_visiting(&owned, &options.forms, &mut recorder).map_err(|e| e.to_string())?;
    if let Some(bug) = recorder.bug {
        return Err(format!("rinshan bug, please report: {bug}"));
    }
    let mut first_mismatch: HashMap<&str, String> = HashMap::new();
    for m in &report.mismatches {
        first_mismatch.entry(m.file.as_str()).or_insert_with(|| m.to_string());
    }
    let search = options.look_ahead()?;
    recorder
        .rows
        .into_iter()
        .zip(recorder.over)
        .zip(games)
        .map(
            |((mut rows, over), game)| match first_mismatch.get(rows.name.as_str()) {
                Some(m) => Ok(Outcome::Skipped(format!("does not replay: {m}"))),
                None if !over => Ok(Outcome::Skipped(format!(
                    "{}: the log stops before the game ends",
                    rows.name
                ))),
                None => {
                    if let Some(search) = &search {
                        let keys: Vec<_> = rows
                            .at
                            .iter()
                            .zip(&rows.seat)
                            .zip(&rows.action)
                            .map(|((&(round, step), &seat), &action)| (round, step, seat, action))
                            .collect();
                        (rows.search_action, rows.search_value) = label_rows(search, game, &keys, num_actions)?;
                    }
                    Ok(Outcome::Rows(Box::new(rows)))
                }
            },
        )
        .collect()
}

/// Replays `games` and returns each one's outcome, in order: East games and half games are
/// replayed apart (one replay plays one length).
pub fn record(games: &[Game], options: &Options) -> Result<Vec<Outcome>, String> {
    let mut out: Vec<Option<Outcome>> = vec![None; games.len()];
    let modes: Vec<_> = games.iter().map(|g| mode_of(std::slice::from_ref(g))).collect();
    // A dataset's rows share one action layout: games of other rule sets are left out.
    for (o, g) in out.iter_mut().zip(games) {
        if g.variant != options.variant {
            *o = Some(Outcome::Skipped(format!(
                "{}: played under {}, and this dataset holds games of {}",
                g.path, g.variant, options.variant
            )));
        }
    }
    let mut seen = Vec::new();
    for &mode in &modes {
        if seen.contains(&mode) {
            continue;
        }
        seen.push(mode);
        let index: Vec<usize> = (0..games.len())
            .filter(|&i| modes[i] == mode && out[i].is_none())
            .collect();
        if index.is_empty() {
            continue;
        }
        let group: Vec<&Game> = index.iter().map(|&i| &games[i]).collect();
        for (i, outcome) in index.into_iter().zip(record_group(&group, options)?) {
            out[i] = Some(outcome);
        }
    }
    Ok(out
        .into_iter()
        .map(|o| o.unwrap_or_else(|| Outcome::Skipped("not replayed".into())))
        .collect())
}

/// Reads and parses one log: its game, or the reader's reason it has none.
pub fn parse_unit(unit: &Unit) -> Result<Game, String> {
    unit.bytes()
        .and_then(|b| parse_log(&unit.name, &b).map_err(|e| e.to_string()))
        .map(|(game, _format)| game)
}

/// Replays parsed logs: each one's outcome, in order. A log that could not be read or parsed is
/// skipped with the reader's reason, as one that does not replay is.
pub fn record_parsed(parsed: Vec<Result<Game, String>>, options: &Options) -> Result<Vec<Outcome>, String> {
    let mut games = Vec::new();
    let read: Vec<Result<(), String>> = parsed.into_iter().map(|p| p.map(|game| games.push(game))).collect();
    let mut replayed = record(&games, options)?.into_iter();
    drop(games);
    Ok(read
        .into_iter()
        .map(|r| match r {
            Ok(()) => replayed
                .next()
                .unwrap_or_else(|| Outcome::Skipped("not replayed".into())),
            Err(reason) => Outcome::Skipped(reason),
        })
        .collect())
}

/// Reads, parses and replays `units`: each one's outcome, in order (see [`record_parsed`]).
pub fn record_units(units: &[Unit], options: &Options) -> Result<Vec<Outcome>, String> {
    record_parsed(units.iter().map(parse_unit).collect(), options)
}
