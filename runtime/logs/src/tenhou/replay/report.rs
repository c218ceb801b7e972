//! What a replay found: its totals and every disagreement between a log and rinshan.

use serde::Serialize;

use crate::tenhou::log::Outcome;

/// One disagreement between a log and rinshan.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Mismatch {
    /// The log file.
    pub file: String,
    /// 1-based line of the round in the file.
    pub line: usize,
    /// `East 1, 0 honba`.
    pub round: String,
    /// Engine steps into the round when it was found.
    pub step: usize,
    /// What was compared, e.g. `score changes`.
    pub what: String,
    /// What the log says.
    pub log: String,
    /// What rinshan did.
    pub rinshan: String,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{} ({}), step {}: {}: log says {}; rinshan says {}",
            self.file, self.line, self.round, self.step, self.what, self.log, self.rinshan
        )
    }
}

/// Totals of a replay.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Report {
    /// Games replayed.
    pub games: usize,
    /// Games that ended exactly where their log ends.
    pub games_ended_right: usize,
    /// Logged rounds.
    pub rounds: usize,
    /// Rounds whose every logged decision was legal and taken, ending where the log ends.
    pub rounds_replayed: usize,
    /// Logged decisions of the rounds that could be planned.
    pub actions: usize,
    /// Logged decisions the engine took.
    pub actions_accepted: usize,
    /// Rounds whose score change of every seat matches the log.
    pub score_changes_matching: usize,
    /// Rounds whose next table (round, dealer, honba, sticks, scores) matches the next logged round.
    pub tables_matching: usize,
    /// Rounds followed by another logged round.
    pub tables: usize,
    /// Logged wins.
    pub wins: usize,
    /// Wins whose winner, han, fu and yaku (with their han) match.
    pub wins_matching: usize,
    /// Wins with the right winner whose yaku are not in the log (libriichi's `hora` gives none:
    /// [`crate::tenhou::log::LoggedWin::computed`]), so only their score changes and the next
    /// round are compared.
    pub wins_yaku_not_logged: usize,
    /// Logged rounds without a win.
    pub draws: usize,
    /// Drawn rounds that rinshan drew the same way.
    pub draws_matching: usize,
    /// Every disagreement, in the order found.
    pub mismatches: Vec<Mismatch>,
}

impl Report {
    /// Every count agrees: nothing was found wrong.
    pub fn all_agree(&self) -> bool {
        self.mismatches.is_empty()
            && self.games_ended_right == self.games
            && self.rounds_replayed == self.rounds
            && self.actions_accepted == self.actions
            && self.score_changes_matching == self.rounds
            && self.tables_matching == self.tables
            && self.wins_matching + self.wins_yaku_not_logged == self.wins
            && self.draws_matching == self.draws
    }
}

/// How a logged outcome is named in a disagreement.
pub(super) fn outcome_name(o: &Outcome) -> String {
    match o {
        Outcome::Wins(ws) => ws
            .iter()
            .map(|w| {
                if w.tsumo {
                    format!("tsumo by seat {}", w.winner)
                } else {
                    format!("ron by seat {} from seat {}", w.winner, w.from)
                }
            })
            .collect::<Vec<_>>()
            .join(", "),
        Outcome::Draw { kind, .. } => format!("draw: {kind:?}"),
    }
}
