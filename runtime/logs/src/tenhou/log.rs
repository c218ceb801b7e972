//! tenhou.net/6 JSON logs.
//!
//! A file holds one record per line (blank lines are skipped), or one record written over many
//! lines: `{"title":..,"name":[..],"rule":{"disp":"鳳南喰赤","aka":1},"log":[ROUND]}`. `log` usually holds one round;
//! when it holds several, each becomes a [`Round`] with the same line. Tenhou's logs play Tenhou's
//! rules (rinshan's `red`); a game rinshan played under another rule set names it in the rule,
//! `"rule":{"disp":"鳳南喰","aka":0,"variant":"mleague"}` ([`Game::variant`]).
//!
//! A round is a 17-element array:
//!
//! * `[0]` `[kyoku, honba, sticks]` (kyoku 0 = East 1, 4 = South 1, 8 = West 1), `[1]` the scores
//!   at the start, `[2]` dora indicators, `[3]` ura indicators;
//! * for seat 0..3 (absolute, seat 0 deals East 1): `[4+3s]` the 13-tile starting hand, `[5+3s]`
//!   draws (tiles and calls), `[6+3s]` discards (tiles and kans); a three-player game (sanma,
//!   its rule named `三鳳南喰赤` or `"variant":"sanma"`) leaves seat 3's lists empty and its
//!   score 0, and numbers its rounds as Tenhou does: East 1-3 are kyoku 0-2, South 1 is 4;
//! * `[16]` the result (see [`Outcome`]).
//!
//! Tiles are two-digit codes (see [`Tile::from_tenhou_code`]). Calls and kans are strings of tile codes with one
//! letter. In open calls the letter stands before the called tile, at the place the meld is
//! drawn with that tile turned, so its position says who the tile came from (see [`Rel`]):
//!
//! | string      | meaning                   | letter position: from left, across, right |
//! |-------------|---------------------------|-------------------------------------------|
//! | `c131415`   | chi (draws)               | 0 (chi only takes from the left)          |
//! | `p434343`   | pon (draws)               | 0, 2, 4                                   |
//! | `m39393939` | open kan (draws)          | 0, 2, 6                                   |
//! | `k23232323` | added kan (discards)      | 0, 2, 4, as in its pon                    |
//! | `424242a42` | closed kan (discards)     | 6 (any is read), no direction             |
//! | `r24`       | riichi with that discard  | 0; `r60` with the drawn tile              |
//! | `f44`       | kita (discards, sanma)    | a North set aside; a replacement draw follows |
//!
//! In an added kan the added tile follows the letter, then the pon's called tile.
//!
//! Discards are also `60` (the drawn tile) and `0` (the empty discard after an open kan). Each
//! draw is followed by one discard except a last draw that ends the round, so a seat has as many
//! discards as draws or one fewer.

use std::fmt;
use std::path::{Path, PathBuf};

use serde_json::Value;

mod moves;
mod result;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_mjsoul;
mod value;

pub(crate) use moves::KITA;
pub use moves::{Discard, Draw, Rel};
pub(crate) use result::{
    check_yaku, our_yaku, points_total, tenhou_yaku, yaku_name as tenhou_yaku_name, MOST_YAKU_HAN,
};
pub use result::{Limit, LoggedDraw, LoggedWin, Outcome};

use moves::{parse_discard, parse_draw, tile};
use rinshan_engine::env::check_table;
use rinshan_engine::tile::Tile;
use rinshan_engine::Variant;
use value::{numbers, show};

/// One round (kyoku) of a log.
#[derive(Debug, Clone, PartialEq)]
pub struct Round {
    /// 1-based line of the record in the file.
    pub line: usize,
    /// Players at the table: 4, or 3 (seat 3 takes no part: its lists are empty, its score 0).
    pub seats: usize,
    /// 0 = East 1, 4 = South 1, 8 = West 1 (three players too: their East 3 is 2, South 1 is 4).
    pub kyoku: u32,
    /// Repeat counters at the start.
    pub honba: u32,
    /// Riichi sticks on the table at the start.
    pub sticks: u32,
    /// Scores at the start, by absolute seat.
    pub scores: [i32; 4],
    /// Dora indicators, one more after each kan.
    pub dora: Vec<Tile>,
    /// Ura indicators (often empty).
    pub ura: Vec<Tile>,
    /// Starting hands, 13 tiles each.
    pub hands: [Vec<Tile>; 4],
    /// Each seat's draws and calls, in order.
    pub draws: [Vec<Draw>; 4],
    /// Each seat's discards, kans and riichi declarations, in order.
    pub discards: [Vec<Discard>; 4],
    /// How the round ended.
    pub outcome: Outcome,
}

impl Round {
    /// The dealer's seat.
    pub fn dealer(&self) -> usize {
        (self.kyoku % 4) as usize
    }

    /// The engine's number of the round (`GameState::round`): `SEATS` rounds per wind.
    pub fn table_round(&self) -> u32 {
        table_round(self.kyoku, self.seats)
    }
}

/// The engine's round number of Tenhou's `kyoku` at a table of `seats`.
pub(crate) fn table_round(kyoku: u32, seats: usize) -> u32 {
    kyoku / 4 * seats as u32 + kyoku % 4
}

/// Tenhou's `kyoku` of the engine's round number at a table of `seats`.
pub(crate) fn tenhou_kyoku(round: u32, seats: usize) -> u32 {
    round / seats as u32 * 4 + round % seats as u32
}

impl fmt::Display for Round {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&round_name(self.kyoku, self.honba))
    }
}

/// `"East 1, 0 honba"`, `"South 3, 2 honba"`, `"West 1, 0 honba"`.
pub(crate) fn round_name(kyoku: u32, honba: u32) -> String {
    match ["East", "South", "West", "North"].get((kyoku / 4) as usize) {
        Some(wind) => format!("{wind} {}, {honba} honba", kyoku % 4 + 1),
        None => format!("kyoku {kyoku}, {honba} honba"),
    }
}

/// A whole game: the rounds of every record of one file.
#[derive(Debug, Clone, PartialEq)]
pub struct Game {
    /// The path as given, for messages.
    pub path: String,
    /// The rule's display name, e.g. `鳳南喰赤`.
    pub rule: String,
    /// Whether the rule plays with red fives (`aka`).
    pub red_fives: bool,
    /// The rules the game was played under: red (Tenhou's) unless the rule names another of
    /// rinshan's rule sets (`"variant":"mleague"`, which rinshan writes for games of those).
    pub variant: Variant,
    /// The players' names by seat, empty when the log has none.
    pub names: [String; 4],
    /// Every round, in file order.
    pub rounds: Vec<Round>,
}

impl Game {
    /// Plays the game under `variant` instead of the rule set it names (logs that cannot name
    /// theirs, such as Mahjong Soul games converted to tenhou.net/6); a game with red fives
    /// cannot be played under a rule set without them. Wins rinshan scored as it read the log
    /// ([`LoggedWin::computed`]) keep the yaku of the rule set they were read under: a replay
    /// does not compare them.
    pub fn play_under(&mut self, variant: Variant) -> Result<(), String> {
        if variant.seats() != self.variant.seats() {
            return Err(format!(
                "{}: a {}-player log cannot be played under {variant}, a {}-player game",
                self.path,
                self.variant.seats(),
                variant.seats()
            ));
        }
        if self.red_fives && !variant.red_fives() {
            return Err(format!("{}: the log plays red fives, {variant} has none", self.path));
        }
        self.variant = variant;
        Ok(())
    }
}

/// Why a log could not be read. Lines count from 1; seats (absolute) and list entries from 0.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LogError {
    /// The file as named to the reader.
    pub file: String,
    /// The line of the record.
    pub line: Option<usize>,
    /// Column inside the line, for a line that is not JSON. (u32 keeps the error small enough to
    /// pass around by value.)
    pub column: Option<u32>,
    /// The round, e.g. `East 2, 1 honba`, once its first element could be read.
    pub round: Option<String>,
    /// The part of the record, e.g. `result`, `hand of seat 1`, `discards of seat 3, entry 7`.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl LogError {
    pub(crate) fn file(file: &str, message: impl Into<String>) -> LogError {
        LogError {
            file: file.to_string(),
            line: None,
            column: None,
            round: None,
            field: None,
            message: message.into(),
        }
    }
}

impl fmt::Display for LogError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.file)?;
        if let Some(line) = self.line {
            write!(f, ": line {line}")?;
        }
        if let Some(column) = self.column {
            write!(f, ", column {column}")?;
        }
        if let Some(round) = &self.round {
            write!(f, " ({round})")?;
        }
        f.write_str(": ")?;
        if let Some(field) = &self.field {
            write!(f, "{field}: ")?;
        }
        f.write_str(&self.message)
    }
}

impl std::error::Error for LogError {}

/// Reads one log file (see [`parse_game`]).
pub fn read_game(path: &Path) -> Result<Game, LogError> {
    let name = path.display().to_string();
    let bytes = crate::file::read_log_bytes(path)?;
    let text = String::from_utf8(bytes).map_err(|e| LogError::file(&name, format!("not UTF-8 text: {e}")))?;
    parse_game(&name, &text)
}

/// The file names a folder's logs go by: tenhou.net/6 (`.json`), MJAI (`.mjson`, `.jsonl`) and
/// mjlog (`.xml`, `.mjlog`), each also gzipped (`.gz`).
pub const LOG_EXTENSIONS: [&str; 10] = [
    ".json",
    ".mjson",
    ".jsonl",
    ".xml",
    ".mjlog",
    ".json.gz",
    ".mjson.gz",
    ".jsonl.gz",
    ".xml.gz",
    ".mjlog.gz",
];

/// The files to read: files as given, folders replaced by their log files (see
/// [`LOG_EXTENSIONS`]) sorted by name.
pub fn collect_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, LogError> {
    let mut files = Vec::new();
    for path in paths {
        let name = path.display().to_string();
        let io = |e: std::io::Error| LogError::file(&name, e.to_string());
        if !path.is_dir() {
            // Fail here rather than halfway through a batch of files.
            std::fs::metadata(path).map_err(io)?;
            files.push(path.clone());
            continue;
        }
        let mut found = Vec::new();
        for entry in std::fs::read_dir(path).map_err(io)? {
            let entry = entry.map_err(io)?;
            let file = entry.path();
            let name = file
                .file_name()
                .map(|n| n.to_string_lossy().to_lowercase())
                .unwrap_or_default();
            if LOG_EXTENSIONS.iter().any(|e| name.ends_with(e)) && file.is_file() {
                found.push(file);
            }
        }
        if found.is_empty() {
            return Err(LogError::file(
                &name,
                format!("the folder has no log files ({})", LOG_EXTENSIONS.join(", ")),
            ));
        }
        found.sort();
        files.extend(found);
    }
    Ok(files)
}

/// The longest record (one line, or a pretty-printed file) read.
const MAX_RECORD: usize = 4 << 20;

/// Parses the text of one log file; `path` only names it in messages.
pub fn parse_game(path: &str, text: &str) -> Result<Game, LogError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut records = Vec::new();
    for (index, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        // A record is read whole into a JSON tree, which takes many times its text: past this
        // size it is refused first (a whole hanchan's record is under 200 KB).
        if line.len() > MAX_RECORD {
            return Err(LogError {
                line: Some(index + 1),
                message: format!(
                    "a record of {:.1} MiB: a game's record is well under 1 MiB (at most {} MiB is read)",
                    line.len() as f64 / (1 << 20) as f64,
                    MAX_RECORD >> 20
                ),
                ..LogError::file(path, "")
            });
        }
        match serde_json::from_str::<Value>(line) {
            Ok(value) => records.push((index + 1, value)),
            Err(e) => {
                // A single record spread over many lines (pretty-printed) fails on its first line.
                if records.is_empty() && text.len() <= MAX_RECORD {
                    if let Ok(value @ Value::Object(_)) = serde_json::from_str::<Value>(text) {
                        records.push((index + 1, value));
                        break;
                    }
                }
                let position = format!(" at line {} column {}", e.line(), e.column());
                let full = e.to_string();
                let message = full.strip_suffix(&position).unwrap_or(&full);
                return Err(LogError {
                    line: Some(index + 1),
                    column: u32::try_from(e.column()).ok(),
                    message: format!("not JSON: {message}"),
                    ..LogError::file(path, "")
                });
            }
        }
    }
    let mut game = Game {
        path: path.to_string(),
        rule: String::new(),
        red_fives: false,
        variant: Variant::Red,
        names: Default::default(),
        rounds: Vec::new(),
    };
    let mut first_line = None;
    for (line, record) in &records {
        let mut ctx = Ctx {
            file: path,
            line: *line,
            round: None,
        };
        if !record.is_object() {
            return Err(ctx.err("record", format!("{} is not an object with a \"log\"", show(record))));
        }
        let (rule, red_fives, variant) = parse_rule(record).map_err(|m| ctx.err("rule", m))?;
        match first_line {
            None => {
                first_line = Some(*line);
                game.rule = rule;
                game.red_fives = red_fives;
                game.variant = variant;
                game.names = parse_names(record, variant.seats() as usize);
            }
            Some(first) if (&rule, red_fives, variant) != (&game.rule, game.red_fives, game.variant) => {
                let message = format!(
                    "{rule:?} (red fives {red_fives}, variant {variant}) differs from line {first}'s {:?} (red fives {}, variant {}): one file is one game",
                    game.rule, game.red_fives, game.variant
                );
                return Err(ctx.err("rule", message));
            }
            Some(_) => {}
        }
        let rounds = match record.get("log") {
            Some(Value::Array(rounds)) if !rounds.is_empty() => rounds,
            Some(other) => return Err(ctx.err("log", format!("{} is not a non-empty list of rounds", show(other)))),
            None => return Err(ctx.err("log", "missing")),
        };
        for (index, round) in rounds.iter().enumerate() {
            let index = (rounds.len() > 1).then_some(index);
            let round = parse_round(&mut ctx, index, round, variant.seats() as usize)?;
            if !red_fives {
                check_no_red(&ctx, &round)?;
            }
            game.rounds.push(round);
        }
    }
    if game.rounds.is_empty() {
        return Err(LogError::file(path, "no rounds: the file has no records"));
    }
    Ok(game)
}

/// Reads one round's 17-element array as found at `line` of `file` (how a reader of another
/// format holds its rounds to this format's rules: what reads here is a round).
pub(crate) fn parse_round_value(
    file: &str,
    line: usize,
    v: &Value,
    red_fives: bool,
    seats: usize,
) -> Result<Round, LogError> {
    let mut ctx = Ctx {
        file,
        line,
        round: None,
    };
    let round = parse_round(&mut ctx, None, v, seats)?;
    if !red_fives {
        check_no_red(&ctx, &round)?;
    }
    Ok(round)
}

/// Where in a file parsing is, to name it in errors.
struct Ctx<'a> {
    file: &'a str,
    line: usize,
    round: Option<String>,
}

impl Ctx<'_> {
    fn err(&self, field: impl Into<String>, message: impl Into<String>) -> LogError {
        LogError {
            line: Some(self.line),
            round: self.round.clone(),
            field: Some(field.into()),
            ..LogError::file(self.file, message)
        }
    }
}

fn parse_rule(record: &Value) -> Result<(String, bool, Variant), String> {
    let rule = record.get("rule").ok_or("missing")?;
    let disp = rule.get("disp").and_then(Value::as_str);
    let disp = disp.ok_or_else(|| format!("{} has no \"disp\" string", show(rule)))?;
    let red = match rule.get("aka") {
        Some(aka) => {
            aka.as_u64()
                .ok_or_else(|| format!("\"aka\" {} is not a count", show(aka)))?
                != 0
        }
        // Tenhou writes 赤 in the rule's name when red fives are on.
        None => disp.contains('赤'),
    };
    let variant = match rule.get("variant") {
        // Tenhou names its three-player rules 三.. (`三鳳南喰赤`).
        None if disp.starts_with('三') => Variant::Sanma,
        None => Variant::Red,
        Some(v) => {
            let name = v
                .as_str()
                .ok_or_else(|| format!("\"variant\" {} is not a name", show(v)))?;
            name.parse::<Variant>().map_err(|e| format!("\"variant\": {e}"))?
        }
    };
    if red && !variant.red_fives() {
        return Err(format!("\"aka\" says red fives, but {variant} plays without them"));
    }
    Ok((disp.to_string(), red, variant))
}

/// Names are only for display, so a missing or odd `name` is no error; a name past the table's
/// `seats` (three players' fourth place) is left out, as every format leaves that place empty.
fn parse_names(record: &Value, seats: usize) -> [String; 4] {
    let mut names: [String; 4] = Default::default();
    if let Some(Value::Array(list)) = record.get("name") {
        for (name, value) in names.iter_mut().zip(list).take(seats) {
            *name = value.as_str().unwrap_or_default().to_string();
        }
    }
    names
}

/// A list of tiles; `counts` is the allowed length.
fn tiles(v: &Value, counts: std::ops::RangeInclusive<usize>) -> Result<Vec<Tile>, String> {
    let items = v
        .as_array()
        .ok_or_else(|| format!("{} is not a list of tiles", show(v)))?;
    if !counts.contains(&items.len()) {
        let expected = match (counts.start(), counts.end()) {
            (a, b) if a == b => format!("{a}"),
            (a, b) => format!("{a} to {b}"),
        };
        return Err(format!("has {} tiles, expected {expected}", items.len()));
    }
    let parsed: Result<Vec<Tile>, String> = items.iter().map(tile).collect();
    parsed.map_err(|m| format!("{m} in {}", show(v)))
}

fn parse_round(ctx: &mut Ctx, index: Option<usize>, v: &Value, seats: usize) -> Result<Round, LogError> {
    const LEN: usize = 17;
    ctx.round = index.map(|i| format!("log[{i}]"));
    let items = match v.as_array() {
        Some(items) if !items.is_empty() => items,
        _ => return Err(ctx.err("round", format!("{} is not a list of {LEN} elements", show(v)))),
    };
    // The round's name goes into every later message, so read it before anything else.
    let [kyoku, honba, sticks] = items
        .first()
        .ok_or_else(|| "missing".to_string())
        .and_then(numbers::<3>)
        .and_then(
            |[k, h, s]| match (u32::try_from(k), u32::try_from(h), u32::try_from(s)) {
                (Ok(k @ 0..16), Ok(h), Ok(s)) if (k % 4) < seats as u32 => Ok([k, h, s]),
                _ if seats == 3 => Err(format!(
                    "[{k}, {h}, {s}] is not [kyoku, honba, sticks] of three players (kyoku 0-2, 4-6, 8-10, 12-14)"
                )),
                _ => Err(format!("[{k}, {h}, {s}] is not [kyoku 0-15, honba, sticks]")),
            },
        )
        .map_err(|m| ctx.err("[kyoku, honba, sticks]", m))?;
    let name = round_name(kyoku, honba);
    ctx.round = Some(match index {
        Some(i) => format!("log[{i}], {name}"),
        None => name,
    });
    if items.len() != LEN {
        return Err(ctx.err("round", format!("has {} elements, expected {LEN}", items.len())));
    }
    let item = |i: usize| items.get(i).unwrap_or(&Value::Null);
    let scores = numbers::<4>(item(1)).map_err(|m| ctx.err("scores", m))?;
    if seats == 3 && scores[3] != 0 {
        return Err(ctx.err("scores", format!("{scores:?}: three players leave the fourth score 0")));
    }
    // What the replay deals from: a table no round could be dealt from is refused here, by name.
    check_table(kyoku, honba, sticks, &scores).map_err(|m| ctx.err("[kyoku, honba, sticks] and scores", m))?;
    let dora = tiles(item(2), 1..=5).map_err(|m| ctx.err("dora", m))?;
    let ura = tiles(item(3), 0..=5).map_err(|m| ctx.err("ura", m))?;
    let mut hands: [Vec<Tile>; 4] = Default::default();
    let mut draws: [Vec<Draw>; 4] = Default::default();
    let mut discards: [Vec<Discard>; 4] = Default::default();
    for seat in 0..4 {
        let base = 4 + 3 * seat;
        if seat >= seats {
            let empty = (0..3).all(|i| item(base + i).as_array().is_some_and(Vec::is_empty));
            if !empty {
                return Err(ctx.err(
                    format!("seat {seat}"),
                    "three players leave seat 3's hand, draws and discards empty",
                ));
            }
            continue;
        }
        hands[seat] = tiles(item(base), 13..=13).map_err(|m| ctx.err(format!("hand of seat {seat}"), m))?;
        draws[seat] = entries(ctx, item(base + 1), &format!("draws of seat {seat}"), parse_draw)?;
        discards[seat] = entries(ctx, item(base + 2), &format!("discards of seat {seat}"), parse_discard)?;
        check_seats(ctx, seat, seats, &draws[seat], &discards[seat])?;
        let (n_draws, n_discards) = (draws[seat].len(), discards[seat].len());
        if n_discards != n_draws && n_discards + 1 != n_draws {
            let message = format!(
                "{n_discards} discards for {n_draws} draws: each draw is followed by a discard, except a last \
                 draw that ends the round"
            );
            return Err(ctx.err(format!("discards of seat {seat}"), message));
        }
    }
    // Each kan reveals one more indicator: a list longer than that names tiles no kan showed.
    let kans = (0..4)
        .map(|s| {
            let open = draws[s].iter().filter(|d| matches!(d, Draw::OpenKan { .. })).count();
            // A kita reveals no indicator.
            let own = discards[s]
                .iter()
                .filter(|d| matches!(d, Discard::AddedKan { .. } | Discard::ClosedKan { .. }));
            open + own.count()
        })
        .sum::<usize>();
    if dora.len() > 1 + kans {
        let message = format!(
            "{} indicators, but the round has {kans} kans (one indicator each, after the first)",
            dora.len()
        );
        return Err(ctx.err("dora", message));
    }
    let outcome = result::parse_result(item(16), seats).map_err(|m| ctx.err("result", m))?;
    if seats == 3 {
        let fourth = match &outcome {
            Outcome::Wins(wins) => wins
                .iter()
                .any(|w| w.deltas[3] != 0 || w.winner == 3 || w.from == 3 || w.pao == 3),
            Outcome::Draw { deltas, .. } => deltas.is_some_and(|d| d[3] != 0),
        };
        if fourth {
            let message = "a win or a payment of the fourth place, which three players leave empty";
            return Err(ctx.err("result", message));
        }
    }
    Ok(Round {
        line: ctx.line,
        seats,
        kyoku,
        honba,
        sticks,
        scores,
        dora,
        ura,
        hands,
        draws,
        discards,
        outcome,
    })
}

/// What only one table size has: chi at four seats, kita at three; and at three, no call from
/// the empty fourth place.
fn check_seats(ctx: &Ctx, seat: usize, seats: usize, draws: &[Draw], discards: &[Discard]) -> Result<(), LogError> {
    let empty = |from: &Rel| from.seat_of(seat) >= seats;
    for (i, d) in draws.iter().enumerate() {
        let message = match d {
            Draw::Chi { .. } if seats == 3 => "a chi: three players have none",
            Draw::Pon { from, .. } | Draw::OpenKan { from, .. } if empty(from) => {
                "a call from the fourth place, which three players leave empty"
            }
            _ => continue,
        };
        return Err(ctx.err(format!("draws of seat {seat}, entry {i}"), message));
    }
    for (i, d) in discards.iter().enumerate() {
        let message = match d {
            Discard::Kita if seats == 4 => "a kita (f44): four players keep North",
            Discard::AddedKan { from, .. } if empty(from) => {
                "an added kan on a pon from the fourth place, which three players leave empty"
            }
            _ => continue,
        };
        return Err(ctx.err(format!("discards of seat {seat}, entry {i}"), message));
    }
    Ok(())
}

/// A list of draws or discards, each entry read by `parse`.
fn entries<T>(ctx: &Ctx, v: &Value, field: &str, parse: fn(&Value) -> Result<T, String>) -> Result<Vec<T>, LogError> {
    let items = v
        .as_array()
        .ok_or_else(|| ctx.err(field, format!("{} is not a list", show(v))))?;
    let parsed = items
        .iter()
        .enumerate()
        .map(|(i, item)| parse(item).map_err(|m| ctx.err(format!("{field}, entry {i}"), m)));
    parsed.collect()
}

fn check_no_red(ctx: &Ctx, round: &Round) -> Result<(), LogError> {
    let red = |tiles: &[Tile]| tiles.iter().any(|t| t.is_red());
    let mut places = vec![
        ("dora".to_string(), red(&round.dora)),
        ("ura".to_string(), red(&round.ura)),
    ];
    for seat in 0..4 {
        let drawn: Vec<Tile> = round.draws[seat].iter().flat_map(Draw::tiles).collect();
        let discarded: Vec<Tile> = round.discards[seat].iter().flat_map(Discard::tiles).collect();
        places.push((format!("hand of seat {seat}"), red(&round.hands[seat])));
        places.push((format!("draws of seat {seat}"), red(&drawn)));
        places.push((format!("discards of seat {seat}"), red(&discarded)));
    }
    match places.into_iter().find(|(_, has_red)| *has_red) {
        Some((field, _)) => Err(ctx.err(field, "a red five, but the rule has no red fives (aka 0)")),
        None => Ok(()),
    }
}
