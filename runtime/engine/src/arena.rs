//! Rating agents by duplicate play: every set of walls is played once per seat (four times, three
//! for three players) with the players rotated through the seats, so each player meets the same
//! tiles from every seat and luck cancels out. Reports per player the average rank with a 95% confidence interval (over sets,
//! the unit of the duplicate design), the rank histogram, the average final score, and per round
//! the win, deal-in, call and riichi rates and the points per win.

use rayon::prelude::*;

use crate::agents::Agent;
use crate::env::{env_seed, Mode};
use crate::generated::kernel::{self, GameState};
use crate::Variant;

/// A policy of the caller's, for [`run`]: one action per decision, from the deciding seat's planes
/// observation ([`crate::observe::Form::Planes`] bytes) and its legal mask.
pub trait Policy: Sync {
    /// The action id to play (an illegal one ends the game with the penalty, and is counted).
    fn act(&self, planes: &[u8], mask: &[u32; 3]) -> u32;
}

/// A player that follows every step of its games and keeps its own state, such as an external
/// program speaking a protocol (rinshan-logs' MJAI bots).
pub trait Entrant: Sync {
    /// Starts a game of `variant` in which the player takes seat `seat`; `state` is the game's
    /// first.
    fn join(&self, seat: u32, state: &GameState, variant: Variant) -> Box<dyn Seat + '_>;
}

/// An [`Entrant`] in one game.
pub trait Seat: Send {
    /// The action for `state`, where this seat is to act. `Err` (why it has none) plays an
    /// illegal action: the game ends with the penalty and the reason is reported as a [`Fault`].
    fn act(&mut self, state: &GameState) -> Result<u32, String>;
    /// Told after every step of the game, anyone's; an `Err` is reported as a [`Fault`] (and the
    /// seat's next `act` should fail).
    fn stepped(&mut self, before: &GameState, action: u32, after: &GameState) -> Result<(), String>;
}

/// An action id no state allows: what a seat plays when its player has no action to give.
pub fn refused_action(mask: &[u32; 3]) -> u32 {
    (0..96)
        .find(|&a| mask[a as usize / 32] >> (a % 32) & 1 == 0)
        .unwrap_or(95)
}

/// Who plays a seat in the arena.
#[derive(Clone, Copy)]
pub enum Player<'a> {
    /// A built-in agent.
    Builtin(Agent),
    /// A caller's policy, reported under `name`.
    Policy {
        /// The name in the report.
        name: &'a str,
        /// The policy.
        policy: &'a dyn Policy,
    },
    /// A player that follows the whole game, reported under `name`.
    Entrant {
        /// The name in the report.
        name: &'a str,
        /// The player.
        entrant: &'a dyn Entrant,
    },
}

impl Player<'_> {
    /// The name the report uses.
    pub fn name(&self) -> String {
        match self {
            Player::Builtin(a) => a.name().to_string(),
            Player::Policy { name, .. } | Player::Entrant { name, .. } => name.to_string(),
        }
    }
}

/// What to play.
#[derive(Clone)]
pub struct Arena<'a> {
    /// The rules.
    pub variant: Variant,
    /// Game length.
    pub mode: Mode,
    /// The players of seats 0..3 in the first game of each set; the set's other games rotate them.
    /// A three-player game seats the first three (the fourth plays nothing and is not reported).
    pub players: [Player<'a>; 4],
    /// Sets of walls; each set is one game per seat (one per rotation).
    pub sets: usize,
    /// Seeds the walls (set `i` uses `env_seed(seed, i, 0)`).
    pub seed: u64,
}

/// One player's results.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Standing {
    /// The player's name (players with the same name are pooled).
    pub name: String,
    /// Games played (seat-games: a name in two seats counts twice per game).
    pub games: u64,
    /// Average final rank, 1 = first.
    pub mean_rank: f64,
    /// Half-width of the 95% confidence interval of `mean_rank` (Student's t over the wall sets);
    /// NaN for a single set, which has no spread to estimate.
    pub rank_ci95: f64,
    /// Finishes in 1st..4th place (three players: 1st..3rd).
    pub ranks: [u64; 4],
    /// Average final score in points (before uma; the arena pays none).
    pub mean_score: f64,
    /// Rounds played.
    pub rounds: u64,
    /// Rounds won (ron or tsumo) / rounds.
    pub win_rate: f64,
    /// Rounds in which the player's discard was ronned / rounds.
    pub deal_in_rate: f64,
    /// Rounds in which the player called chi, pon or an open kan / rounds.
    pub call_rate: f64,
    /// Rounds in which the player declared riichi / rounds.
    pub riichi_rate: f64,
    /// Average score change of a winning round for the winner (hand, honba and sticks).
    pub points_per_win: f64,
    /// Illegal actions played (a built-in agent never plays one). Each ended its game at once,
    /// with its player placed last and the others in their order at that moment.
    pub illegal: u64,
}

/// The whole result.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Report {
    /// Games played (one per seat per set).
    pub games: u64,
    /// Decisions played.
    pub decisions: u64,
    /// One standing per distinct player name, best average rank first.
    pub standings: Vec<Standing>,
    /// What went wrong with [`Player::Entrant`]s, in game order.
    pub faults: Vec<Fault>,
}

/// A game an [`Entrant`] failed in (it gave no action, or could not follow a step).
#[derive(Debug, Clone, PartialEq)]
pub struct Fault {
    /// The player's name.
    pub player: String,
    /// The game: set `game / seats`, rotation `game % seats`.
    pub game: u64,
    /// The seat it played.
    pub seat: u32,
    /// The decision (0 = the game's first) at or after which it failed.
    pub decision: u64,
    /// Why.
    pub message: String,
}

/// One wall set's results: per name (rank sum, seat-games), then every seat-game's tally and
/// player name, and the decisions played.
struct SetResult {
    by_name: Vec<(f64, u64)>,
    tallies: Vec<Tally>,
    who: Vec<String>,
    decisions: u64,
    faults: Vec<Fault>,
}

/// Per seat-game tallies.
#[derive(Clone, Copy, Default)]
struct Tally {
    rank: u32,
    score: i64,
    rounds: u64,
    wins: u64,
    deal_ins: u64,
    calls: u64,
    riichis: u64,
    win_points: i64,
    illegal: u64,
}

/// Plays game `game` with `seating[p]` in seat p; returns the tallies per seat and the decisions,
/// and adds its entrants' faults to `faults`.
fn play(arena: &Arena, seed: u64, seating: &[Player; 4], game: u64, faults: &mut Vec<Fault>) -> ([Tally; 4], u64) {
    with_variant!(arena.variant, v => {
        let mut s: GameState = arena.variant.new_game(seed, arena.mode);
        let mut t = [Tally::default(); 4];
        let (mut called, mut riichi) = ([false; 4], [false; 4]);
        let mut decisions = 0u64;
        let mut seats: [Option<Box<dyn Seat>>; 4] = std::array::from_fn(|p| match seating[p] {
            Player::Entrant { entrant, .. } if p < v::SEATS as usize => Some(entrant.join(p as u32, &s, arena.variant)),
            _ => None,
        });
        let mut fault = |p: usize, decision: u64, message: String| {
            faults.push(Fault {
                player: seating[p].name(),
                game,
                seat: p as u32,
                decision,
                message,
            })
        };
        let round_end = kernel::EVENT_RON | kernel::EVENT_TSUMO | kernel::EVENT_EXHAUSTIVE_DRAW | kernel::EVENT_ABORTIVE_DRAW;
        while s.terminated == 0 {
            let p = s.current as usize;
            let a = match seating[p] {
                // Built only where read: a random seat and an MJAI entrant read no planes.
                Player::Builtin(agent) => v::seat_act(&mut { s }, agent.kernel()),
                Player::Policy { policy, .. } => {
                    let planes = v::observe_planes(s, kernel::OBSERVE_CURRENT);
                    policy.act(bytemuck::bytes_of(&planes), &s.mask)
                }
                Player::Entrant { .. } => match seats[p].as_mut().map(|seat| seat.act(&s)) {
                    Some(Ok(a)) => a,
                    Some(Err(message)) => {
                        fault(p, decisions, message);
                        refused_action(&s.mask)
                    }
                    None => refused_action(&s.mask),
                },
            };
            riichi[p] |= a == v::ACTION_RIICHI;
            let melds_before = s.meld_counts;
            let before = s;
            v::game_step(&mut s, a);
            for (q, seat) in seats.iter_mut().enumerate() {
                if let Some(Err(message)) = seat.as_mut().map(|seat| seat.stepped(&before, a, &s)) {
                    fault(q, decisions, message);
                }
            }
            // A call counts once it is made (a chi or pon chosen at a prompt can lose to a pon or
            // a ron): a new meld that is not a closed kan.
            if s.meld_counts != melds_before {
                for (q, c) in called.iter_mut().enumerate() {
                    let n = kernel::meld_count(&mut s, q as u32);
                    if n > kernel::byte_of(melds_before, q as u32) {
                        let kind = kernel::meld_kind(s.melds[q * 4 + n as usize - 1]);
                        *c |= kind != kernel::MELD_CLOSED_KAN;
                    }
                }
            }
            decisions += 1;
            if s.illegal != 0 {
                t[(s.illegal - 1) as usize].illegal += 1;
            }
            if s.events & round_end != 0 {
                for (q, tq) in t.iter_mut().enumerate() {
                    tq.rounds += 1;
                    tq.calls += u64::from(called[q]);
                    tq.riichis += u64::from(riichi[q]);
                    if s.winners >> q & 1 == 1 {
                        tq.wins += 1;
                        tq.win_points += i64::from(s.rewards[q]) * 100;
                    }
                }
                if s.deal_in != 0 {
                    t[(s.deal_in - 1) as usize].deal_ins += 1;
                }
                called = [false; 4];
                riichi = [false; 4];
            }
        }
        let ranks: [u32; 4] = v::seat_ranks(&mut s);
        for (q, tq) in t.iter_mut().enumerate() {
            tq.rank = match s.illegal.checked_sub(1) {
                // A game lost to an illegal action places its player last and the others in
                // their order of the moment.
                Some(o) if o as usize == q => v::SEATS - 1,
                Some(o) => ranks[q] - u32::from(ranks[o as usize] < ranks[q]),
                None => ranks[q],
            };
            tq.score = i64::from(s.scores[q]);
        }
        (t, decisions)
    })
}

/// Plays the arena (sets in parallel on rayon's pool), calling `progress(games_done)` as games finish.
pub fn run(arena: &Arena, progress: &(dyn Fn(u64) + Sync)) -> Report {
    let seats = arena.variant.seats() as usize;
    let names: Vec<String> = {
        let mut n: Vec<String> = arena.players[..seats].iter().map(Player::name).collect();
        n.sort();
        n.dedup();
        n
    };
    let done = std::sync::atomic::AtomicU64::new(0);
    // Per set: for each name, the (rank sum, count) of its seat-games, and the tallies.
    let sets: Vec<SetResult> = (0..arena.sets)
        .into_par_iter()
        .map(|set| {
            let seed = env_seed(arena.seed, set as u64, 0);
            let mut by_name = vec![(0.0, 0u64); names.len()];
            let mut tallies = Vec::new();
            let mut who = Vec::new();
            let mut decisions = 0;
            let mut faults = Vec::new();
            for rotation in 0..seats {
                let seating: [Player; 4] = std::array::from_fn(|p| match p < seats {
                    true => arena.players[(p + rotation) % seats],
                    false => arena.players[p],
                });
                let game = (set * seats + rotation) as u64;
                let (t, d) = play(arena, seed, &seating, game, &mut faults);
                decisions += d;
                for p in 0..seats {
                    let name = seating[p].name();
                    let i = names.iter().position(|n| *n == name).unwrap_or(0);
                    by_name[i].0 += f64::from(t[p].rank + 1);
                    by_name[i].1 += 1;
                    tallies.push(t[p]);
                    who.push(name);
                }
                progress(done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1);
            }
            SetResult {
                by_name,
                tallies,
                who,
                decisions,
                faults,
            }
        })
        .collect();
    let mut report = Report {
        games: (seats * arena.sets) as u64,
        decisions: sets.iter().map(|s| s.decisions).sum(),
        standings: Vec::new(),
        faults: sets.iter().flat_map(|s| s.faults.iter().cloned()).collect(),
    };
    for (i, name) in names.iter().enumerate() {
        let unit_means: Vec<f64> = sets.iter().map(|s| s.by_name[i].0 / s.by_name[i].1 as f64).collect();
        let n = unit_means.len() as f64;
        let mean = unit_means.iter().sum::<f64>() / n;
        let var = if n > 1.0 {
            unit_means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (n - 1.0)
        } else {
            0.0
        };
        // One wall set has no spread to estimate: no interval, rather than a "± 0" that reads as
        // certainty.
        let ci95 = if n > 1.0 {
            t975(n as u64 - 1) * (var / n).sqrt()
        } else {
            f64::NAN
        };
        let mut st = Standing {
            name: name.clone(),
            mean_rank: mean,
            rank_ci95: ci95,
            ..Standing::default()
        };
        let (mut score, mut wins, mut deal_ins, mut calls, mut riichis, mut win_points) =
            (0i64, 0u64, 0u64, 0u64, 0u64, 0i64);
        for s in &sets {
            for (t, who) in s.tallies.iter().zip(&s.who) {
                if who == name {
                    st.games += 1;
                    st.ranks[t.rank as usize] += 1;
                    score += t.score;
                    st.rounds += t.rounds;
                    wins += t.wins;
                    deal_ins += t.deal_ins;
                    calls += t.calls;
                    riichis += t.riichis;
                    win_points += t.win_points;
                    st.illegal += t.illegal;
                }
            }
        }
        let per_round = |x: u64| {
            if st.rounds == 0 {
                0.0
            } else {
                x as f64 / st.rounds as f64
            }
        };
        st.mean_score = score as f64 / st.games.max(1) as f64;
        st.win_rate = per_round(wins);
        st.deal_in_rate = per_round(deal_ins);
        st.call_rate = per_round(calls);
        st.riichi_rate = per_round(riichis);
        st.points_per_win = if wins == 0 {
            0.0
        } else {
            win_points as f64 / wins as f64
        };
        report.standings.push(st);
    }
    report.standings.sort_by(|a, b| a.mean_rank.total_cmp(&b.mean_rank));
    report
}

/// Student's t 0.975 quantiles for 1..30 degrees of freedom (any statistics table).
const T975: [f64; 30] = [
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
    2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042,
];

/// The 0.975 quantile of Student's t with `df` (at least 1) degrees of freedom, a 95% interval's
/// multiplier: the table to 30, then the Cornish-Fisher expansion about the normal's 1.96 (within
/// 1e-4 of the exact value there). Python's `rinshan.evaluate` uses the same.
pub fn t975(df: u64) -> f64 {
    match df {
        0 => f64::NAN,
        1..=30 => T975[df as usize - 1],
        _ => {
            let z = 1.959_963_984_540_054_f64;
            let d = df as f64;
            z + (z.powi(3) + z) / (4.0 * d) + (5.0 * z.powi(5) + 16.0 * z.powi(3) + 3.0 * z) / (96.0 * d * d)
        }
    }
}

#[cfg(test)]
mod t_tests {
    use super::t975;

    #[test]
    fn t_quantiles_meet_the_normal_and_the_table() {
        // Exact values from a statistics table at 40, 60 and 120 degrees of freedom.
        for (df, exact) in [(40, 2.021), (60, 2.000), (120, 1.980)] {
            assert!((t975(df) - exact).abs() < 1e-3, "{df}: {}", t975(df));
        }
        assert!((t975(1_000_000) - 1.96).abs() < 1e-3);
        assert_eq!(t975(1), 12.706);
        assert!(t975(0).is_nan());
        assert!((1..200).all(|d| t975(d) > t975(d + 1)));
    }
}
