//! MJAI logs (one event per line, a whole game from `start_game` to `end_game`) read into the
//! same [`Game`] the tenhou.net/6 reader gives, so that replaying, converting and rendering work
//! on any format. [`GameBuilder`] takes the events of a game in order (from this reader or the
//! mjlog reader) and checks each round, when it ends, by the tenhou.net/6 reader's rules, so a
//! game read in any format converts to the others; the events of a round are read in
//! `mjai::round`, the yaku of a win in `mjai::yaku`.

use rinshan_engine::tile::Tile;

use super::event::{Event, PER_SEAT};
use super::round::{actor_of, known, Open};
use super::rules::rule_set;
use super::unlogged::fill_in;
use crate::tenhou::log::{parse_round_value, round_name, Game, LogError, Outcome, Round};
use crate::tenhou::replay::mode_of_rule;
use crate::tenhou::write::round_value;

/// Whether a text looks like an MJAI log: its first non-blank line is an object with a `type`.
pub fn is_mjai(text: &str) -> bool {
    let first = text.lines().map(str::trim).find(|l| !l.is_empty());
    // A line too long for an event is no MJAI log (and is not read into a tree to find out).
    first.is_some_and(|l| {
        l.len() <= MAX_EVENT
            && serde_json::from_str::<serde_json::Map<String, serde_json::Value>>(l)
                .is_ok_and(|m| m.contains_key("type"))
    })
}

/// What an absent fourth seat holds in the per-seat list `key` ([`PER_SEAT`]).
fn absent_seat(key: &str) -> serde_json::Value {
    match key {
        "names" => "".into(),
        "tehais" => serde_json::Value::Array(Vec::new()),
        "tenpais" => false.into(),
        _ => 0.into(),
    }
}

/// How many seats an event's per-seat lists hold (`None` for an event without them).
pub(super) fn listed_seats(event: &serde_json::Value) -> Option<usize> {
    PER_SEAT
        .iter()
        .find_map(|k| event.get(k).and_then(serde_json::Value::as_array).map(Vec::len))
}

/// A three-player event in the four-seat form [`Event`] reads: each per-seat list gets the
/// absent fourth seat's entry.
fn with_fourth_seat(event: &mut serde_json::Value) {
    for key in PER_SEAT {
        if let Some(serde_json::Value::Array(list)) = event.get_mut(key) {
            if list.len() == 3 {
                list.push(absent_seat(key));
            }
        }
    }
}

/// The longest event line read.
const MAX_EVENT: usize = 64 << 10;

/// Reads the text of an MJAI log; `path` only names it in messages.
pub fn parse_game(path: &str, text: &str) -> Result<Game, LogError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut builder = GameBuilder::new(path);
    // Three players' events list three seats (`start_game`'s names, `start_kyoku`'s scores):
    // the first such list says how many sit at the table.
    let mut seats = None;
    for (index, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let not_json = |e: serde_json::Error| {
            let position = format!(" at line {} column {}", e.line(), e.column());
            let full = e.to_string();
            let message = full.strip_suffix(&position).unwrap_or(&full).to_string();
            LogError {
                line: Some(index + 1),
                column: u32::try_from(e.column()).ok(),
                ..file_error(path, format!("not an MJAI event: {message}"))
            }
        };
        // An event is a few hundred bytes; a longer line is refused before it is read into a tree.
        if line.len() > MAX_EVENT {
            return Err(LogError {
                line: Some(index + 1),
                ..file_error(
                    path,
                    format!(
                        "a line of {} bytes: no MJAI event is longer than {MAX_EVENT}",
                        line.len()
                    ),
                )
            });
        }
        let mut value: serde_json::Value = serde_json::from_str(line).map_err(not_json)?;
        if seats.is_none() {
            seats = listed_seats(&value).filter(|&n| n == 3 || n == 4);
            if seats == Some(3) {
                builder.three_players();
            }
        }
        if seats == Some(3) {
            with_fourth_seat(&mut value);
        }
        let event: Event = serde_json::from_value(value).map_err(|e| LogError {
            line: Some(index + 1),
            ..file_error(path, format!("not an MJAI event: {e}"))
        })?;
        builder.event(event, index + 1)?;
    }
    builder.finish()
}

fn file_error(path: &str, message: String) -> LogError {
    LogError {
        file: path.to_string(),
        line: None,
        column: None,
        round: None,
        field: None,
        message,
    }
}

/// A game put together from MJAI events in the order of play, by any front end that can say
/// its format's moves as MJAI events (the MJAI text reader, the mjlog reader).
pub struct GameBuilder {
    reader: Reader,
}

impl GameBuilder {
    /// An empty game; `path` names the source in messages.
    pub fn new(path: &str) -> GameBuilder {
        GameBuilder {
            reader: Reader {
                game: Game {
                    path: path.to_string(),
                    rule: String::new(),
                    red_fives: true,
                    variant: rinshan_engine::Variant::Red,
                    names: Default::default(),
                    rounds: Vec::new(),
                },
                round: None,
                finished: None,
                started: false,
                ended: false,
                seats: 4,
            },
        }
    }

    /// The game has three players (rinshan's `sanma`): its events list the fourth seat empty.
    pub fn three_players(&mut self) {
        let game = &mut self.reader.game;
        // A three-player rule set the start_game named stays.
        if game.variant.seats() != 3 {
            game.variant = rinshan_engine::Variant::Sanma;
        }
        // A `start_game` without names was read as four players' (Tenhou names theirs 三..).
        if self.reader.started && !game.rule.starts_with('三') {
            game.rule.insert(0, '三');
        }
        game.names[3].clear();
        self.reader.seats = 3;
    }

    /// The next event, found at `line` of the source (1-based; a single-line format gives the
    /// position it has).
    pub fn event(&mut self, event: Event, line: usize) -> Result<(), LogError> {
        // Only the round's numbers are kept before the event (it may end the round); the names
        // of an error are put together only when there is one.
        let at = self.reader.round.as_ref().map(|r| (r.round.kyoku, r.round.honba));
        if let Err(message) = self.reader.event(event, line) {
            return Err(self.error(line, message, at.map(|(kyoku, honba)| round_name(kyoku, honba))));
        }
        if let Some((mut done, unstated)) = self.reader.finished.take() {
            let game = &self.reader.game;
            let mode = mode_of_rule(&game.rule);
            if let Err(e) = fill_in(&game.path, &mut done, unstated, game.variant, mode) {
                let message = format!("what the log leaves out, rinshan finds by playing the round: {e}");
                return Err(self.error(line, message, Some(done.to_string())));
            }
            // A round holds to the rules of a tenhou.net/6 round (a draw before each discard,
            // calls of real melds, a han count the yaku add up to), checked by that reader.
            let mut back = parse_round_value(&game.path, done.line, &round_value(&done), game.red_fives, done.seats)?;
            // What no format writes: which wins rinshan scored.
            if let (Outcome::Wins(back), Outcome::Wins(wins)) = (&mut back.outcome, &done.outcome) {
                for (b, w) in back.iter_mut().zip(wins) {
                    b.computed = w.computed;
                }
            }
            if back != done {
                let message = "the round's events do not read back as one round".into();
                return Err(self.error(line, message, Some(done.to_string())));
            }
            self.reader.game.rounds.push(done);
        }
        Ok(())
    }

    fn error(&self, line: usize, message: String, round: Option<String>) -> LogError {
        LogError {
            line: Some(line),
            round,
            ..file_error(&self.reader.game.path, message)
        }
    }

    /// The game, once every event is in.
    pub fn finish(self) -> Result<Game, LogError> {
        let reader = self.reader;
        let path = &reader.game.path;
        if reader.round.is_some() {
            return Err(file_error(path, "the log stops inside a round (no end_kyoku)".into()));
        }
        if !reader.started {
            return Err(file_error(
                path,
                "no start_game event: not an MJAI log of a game".into(),
            ));
        }
        if reader.game.rounds.is_empty() {
            return Err(file_error(path, "the log holds no round (no start_kyoku)".into()));
        }
        Ok(reader.game)
    }
}

struct Reader {
    game: Game,
    round: Option<Open>,
    /// The round an `end_kyoku` just closed, to check before it joins the game, and whether its
    /// `ryukyoku` left its kind unstated ([`Open::unstated`]).
    finished: Option<(Round, bool)>,
    started: bool,
    ended: bool,
    /// Players at the table.
    seats: usize,
}

impl Reader {
    fn event(&mut self, event: Event, line: usize) -> Result<(), String> {
        if self.ended {
            return Err(format!("{} after end_game: one file is one game", event.kind()));
        }
        match event {
            Event::None {} => Ok(()),
            Event::StartGame {
                names,
                kyoku_first,
                aka_flag,
                rule,
                variant,
                preset,
                rules,
                ..
            } => {
                if self.started {
                    return Err("a second start_game: one file is one game".into());
                }
                self.started = true;
                if let Some(named) = rule_set(variant.as_deref(), preset.as_deref(), rules.as_ref())? {
                    self.game.variant = named;
                }
                self.game.names = names;
                // Names are only for display: a name for three players' empty fourth place (an
                // mjlog's `n3`) is left out, as no format can write it back.
                for name in &mut self.game.names[self.seats..] {
                    name.clear();
                }
                self.game.red_fives = aka_flag.unwrap_or(self.game.variant.red_fives());
                if self.game.red_fives && !self.game.variant.red_fives() {
                    return Err(format!(
                        "aka_flag says red fives, but {} plays without them",
                        self.game.variant
                    ));
                }
                let length = if kyoku_first == Some(4) { "東" } else { "南" };
                let red = if self.game.red_fives { "喰赤" } else { "喰" };
                let three = if self.game.variant.seats() == 3 { "三" } else { "" };
                self.game.rule = rule.unwrap_or_else(|| format!("{three}{length}{red}"));
                Ok(())
            }
            Event::StartKyoku {
                bakaze,
                dora_marker,
                kyoku,
                honba,
                kyotaku,
                oya,
                scores,
                tehais,
            } => {
                if !self.started {
                    return Err("start_kyoku before start_game".into());
                }
                if self.game.variant.seats() as usize != self.seats {
                    return Err(format!(
                        "{} players sit at the table, but start_game names {}, a game of {}",
                        self.seats,
                        self.game.variant,
                        self.game.variant.seats()
                    ));
                }
                if self.round.is_some() {
                    return Err("start_kyoku inside a round (no end_kyoku before it)".into());
                }
                let wind = known(bakaze, "bakaze")?.kind().index();
                if !(27..31).contains(&wind) {
                    return Err(format!("bakaze {bakaze} is not a wind (E, S, W, N)"));
                }
                if !(1..=4).contains(&kyoku) {
                    return Err(format!("kyoku {kyoku} is not 1-4"));
                }
                let k = (wind as u32 - 27) * 4 + u32::from(kyoku) - 1;
                if k % 4 >= self.seats as u32 {
                    return Err(format!("kyoku {kyoku}: three players play kyoku 1-3 of a wind"));
                }
                if actor_of(oya)? != (k % 4) as usize {
                    return Err(format!("oya {oya} is not the dealer of kyoku {kyoku} (seat {})", k % 4));
                }
                let mut hands: [Vec<Tile>; 4] = Default::default();
                for (s, tehai) in tehais.into_iter().enumerate().take(self.seats) {
                    if tehai.len() != 13 {
                        return Err(format!("tehais of seat {s} has {} tiles, not 13", tehai.len()));
                    }
                    hands[s] = tehai
                        .into_iter()
                        .map(|p| known(p, &format!("a tile of seat {s}'s tehai")))
                        .collect::<Result<_, _>>()?;
                }
                self.round = Some(Open::new(
                    Round {
                        line,
                        seats: self.seats,
                        kyoku: k,
                        honba,
                        sticks: kyotaku,
                        scores,
                        dora: vec![known(dora_marker, "dora_marker")?],
                        ura: Vec::new(),
                        hands,
                        draws: Default::default(),
                        discards: Default::default(),
                        outcome: Outcome::Wins(Vec::new()),
                    },
                    self.game.variant,
                ));
                Ok(())
            }
            Event::EndGame { .. } => {
                if self.round.is_some() {
                    return Err("end_game inside a round (no end_kyoku before it)".into());
                }
                self.ended = true;
                Ok(())
            }
            Event::EndKyoku {} => {
                let open = self.round.take().ok_or("end_kyoku outside a round")?;
                let mut round = open.round;
                round.outcome = match (open.wins.is_empty(), open.draw) {
                    (false, None) => Outcome::Wins(open.wins),
                    (true, Some((kind, deltas))) => Outcome::Draw { kind, deltas },
                    (true, None) => return Err("the round ends with neither hora nor ryukyoku".into()),
                    (false, Some(_)) => return Err("the round has both hora and ryukyoku".into()),
                };
                self.finished = Some((round, open.unstated));
                Ok(())
            }
            other => {
                let open = self
                    .round
                    .as_mut()
                    .ok_or_else(|| format!("{} outside a round (before start_kyoku)", other.kind()))?;
                if !open.wins.is_empty() && !matches!(other, Event::Hora { .. }) {
                    return Err(format!(
                        "{} after hora: only another hora or end_kyoku may follow",
                        other.kind()
                    ));
                }
                if open.draw.is_some() {
                    return Err(format!("{} after ryukyoku: only end_kyoku may follow", other.kind()));
                }
                open.play(other)
            }
        }
    }
}
