//! Where one game's replay stands: its round, that round's plan and the decisions taken so far.

use super::report::{outcome_name, Mismatch, Report};
use crate::tenhou::log::{round_name, Game, Round};
use crate::tenhou::plan::{plan, MoveIds, Plan};
use rinshan_engine::env::{Deal, Step};
use rinshan_engine::{with_variant, Variant};

/// Where one game's replay stands.
pub(super) struct Run<'g> {
    pub(super) game: &'g Game,
    /// The round being played (index into `game.rounds`).
    pub(super) round: usize,
    pub(super) plan: Option<Plan>,
    pub(super) next: usize,
    pub(super) steps: usize,
    /// Engine score change of this round so far, in points.
    pub(super) change: [i64; 4],
    pub(super) finished: bool,
    /// The rules the game is replayed under.
    pub(super) variant: Variant,
    /// The plan's moves (red's action ids and kita) in the variant's ids.
    from_red: MoveIds,
    /// The variant's pass.
    pass: u32,
}

impl<'g> Run<'g> {
    pub(super) fn new(game: &'g Game, variant: Variant) -> Run<'g> {
        Run {
            game,
            round: 0,
            plan: None,
            next: 0,
            steps: 0,
            change: [0; 4],
            finished: false,
            variant,
            from_red: MoveIds::new(variant),
            pass: with_variant!(variant, v => v::ACTION_PASS),
        }
    }

    pub(super) fn round_log(&self) -> &'g Round {
        &self.game.rounds[self.round]
    }

    pub(super) fn mismatch(&self, what: &str, log: impl Into<String>, rinshan: impl Into<String>) -> Mismatch {
        let r = self.round_log();
        Mismatch {
            file: self.game.path.clone(),
            line: r.line,
            round: round_name(r.kyoku, r.honba),
            step: self.steps,
            what: what.into(),
            log: log.into(),
            rinshan: rinshan.into(),
        }
    }

    /// Plans the current round (and the ones after it that cannot be planned are reported and
    /// skipped); the deal to start it, or `None` when the log has no round left.
    pub(super) fn start_round(&mut self, report: &mut Report) -> Option<Deal> {
        while self.round < self.game.rounds.len() {
            let r = self.round_log();
            report.rounds += 1;
            self.next = 0;
            self.steps = 0;
            self.change = [0; 4];
            match plan(r).and_then(|p| Ok((p.deal(r, self.variant)?, p))) {
                Ok((deal, p)) => {
                    report.actions += p.moves.len();
                    self.plan = Some(p);
                    return Some(deal);
                }
                Err(e) => {
                    let m = self.mismatch("the log cannot be placed in turn order", e, "round not replayed");
                    report.mismatches.push(m);
                    self.round += 1;
                }
            }
        }
        self.finished = true;
        None
    }

    /// The action for the engine's prompt, without consuming the move.
    pub(super) fn decide(&self, step: &Step, i: usize) -> Result<u32, Box<Mismatch>> {
        let seat = step.current_player[i] as usize;
        let mask = step.legal_action_mask[i];
        let legal = |a: u32| mask[(a / 32) as usize] >> (a % 32) & 1 == 1;
        let claim = legal(self.pass);
        let moves = self.plan.as_ref().map_or(&[][..], |p| p.moves.as_slice());
        let Some(m) = moves.get(self.next) else {
            if claim {
                return Ok(self.pass);
            }
            return Err(Box::new(self.mismatch(
                "round end",
                format!("the round ends here ({})", outcome_name(&self.round_log().outcome)),
                format!("seat {seat} is still to act"),
            )));
        };
        if claim && !(m.claim && m.seat == seat) {
            return Ok(self.pass);
        }
        if m.seat != seat || m.claim != claim {
            let asked = if claim { "a claim" } else { "its turn" };
            return Err(Box::new(self.mismatch(
                "turn order",
                format!("seat {}: {}", m.seat, m.what),
                format!("seat {seat} is asked for {asked}"),
            )));
        }
        let Some(action) = self.from_red.get(m.action) else {
            return Err(Box::new(self.mismatch(
                "illegal logged action",
                format!("seat {}: {}", m.seat, m.what),
                format!("{} has no such action", self.variant),
            )));
        };
        if !legal(action) {
            return Err(Box::new(self.mismatch(
                "illegal logged action",
                format!("seat {}: {}", m.seat, m.what),
                format!(
                    "not legal; legal actions {:?}",
                    step.legal_actions(i).collect::<Vec<_>>()
                ),
            )));
        }
        Ok(action)
    }

    /// Moves past the logged decision `action` of `seat` just played; `false` for a pass the log
    /// does not list.
    pub(super) fn consume(&mut self, seat: usize, action: u32) -> bool {
        let moves = self.plan.as_ref().map_or(&[][..], |p| p.moves.as_slice());
        let taken = moves
            .get(self.next)
            .is_some_and(|m| m.seat == seat && self.from_red.get(m.action) == Some(action));
        if taken {
            self.next += 1;
        }
        taken
    }
}
