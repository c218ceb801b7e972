//! Win odds with the other seats playing. Drawing alone ([`super::solo()`]) ignores that the round
//! ends when someone else wins, that a discard may deal in, and what a win is worth. Here each
//! discard is played, then the round to its end, in worlds dealt from what the seat can see
//! ([`crate::world::deal`]: the others' hands built as their discards suggest, riichi seats
//! tenpai), with a built-in agent in every seat after the discard (the seat itself included). The
//! same worlds serve every discard (paired). What is counted is the round's end: whether the seat
//! won, whether it dealt in, and its points' change (wins, payments, riichi sticks, noten
//! payments).

use rinshan_engine::agents::Agent;
use rinshan_engine::env::action_names;
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

use crate::positions::defensive_game;
use crate::rollout::play_round;
use crate::world::deal;

/// One discard's outcomes over its worlds.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlay {
    /// The action id (a `discard_` or `tsumogiri`).
    pub action: u32,
    /// Its name.
    pub name: String,
    /// The share of worlds the seat won the round in.
    pub win: f64,
    /// The share it dealt in.
    pub deal_in: f64,
    /// Its mean change of points over the round.
    pub points: f64,
    /// Its mean gain in the worlds it won (`None` where it won none): the value of its wins.
    pub win_points: Option<f64>,
    /// Worlds played.
    pub worlds: u32,
}

impl InPlay {
    /// The half width of the 95% interval of a share (`win`, `deal_in`) this discard reports.
    pub fn interval(&self, p: f64) -> f64 {
        1.96 * (p * (1.0 - p) / f64::from(self.worlds.max(1))).sqrt()
    }
}

/// Every legal discard of `seat` at `s` (its own turn) played in `worlds` worlds seeded by `seed`,
/// `base` playing every seat after it; `own_draws` are the wall places the seat drew this round
/// ([`rinshan_engine::observe::OwnDraws`]). Best chance of winning first. Empty where the seat has
/// no discard to make.
pub fn in_play(
    variant: Variant,
    s: &GameState,
    seat: u32,
    own_draws: &[u32],
    worlds: u32,
    base: Agent,
    seed: u64,
) -> Vec<InPlay> {
    let names = action_names(variant);
    let own = variant.discard_actions();
    let discards: Vec<u32> = (0..names.len() as u32)
        .filter(|&a| (s.mask[a as usize / 32] & own[a as usize / 32]) >> (a % 32) & 1 == 1)
        .collect();
    if s.current != seat || discards.is_empty() {
        return Vec::new();
    }
    let dealt: Vec<GameState> = (0..u64::from(worlds))
        .map(|k| {
            deal(
                variant,
                s,
                seat,
                own_draws,
                &mut Rng::new(seed ^ k.wrapping_mul(0x9E37_79B9_7F4A_7C15)),
            )
        })
        .collect();
    let before = f64::from(s.scores[seat as usize]);
    let mut out: Vec<InPlay> = discards
        .iter()
        .map(|&action| {
            let (mut wins, mut deal_ins, mut points, mut won_points) = (0u32, 0u32, 0.0, 0.0);
            for world in &dealt {
                let (end, _) = play_round(variant, *world, action, base);
                let change = f64::from(end.scores[seat as usize]) - before;
                points += change;
                if end.winners >> seat & 1 == 1 {
                    wins += 1;
                    won_points += change;
                }
                deal_ins += u32::from(end.deal_in == seat + 1);
            }
            let n = f64::from(worlds.max(1));
            InPlay {
                action,
                name: names[action as usize].clone(),
                win: f64::from(wins) / n,
                deal_in: f64::from(deal_ins) / n,
                points: points / n,
                win_points: (wins > 0).then(|| won_points / f64::from(wins)),
                worlds,
            }
        })
        .collect();
    out.sort_by(|a, b| b.win.total_cmp(&a.win).then(b.points.total_cmp(&a.points)));
    out
}

/// How well [`in_play`] predicts what happens: at every `every`-th decision of the seat to act in
/// `defensive` self-play half games from `seeds` (own turns with a discard), the outlook of the
/// action `defensive` took (`worlds` worlds) against the game itself played on from there with
/// the real hidden tiles. Returns the predicted wins and deal-ins (sums of the chances), the
/// counted ones, and the positions.
pub fn calibration(
    variant: Variant,
    seeds: std::ops::Range<u64>,
    every: usize,
    worlds: u32,
) -> ((f64, f64), (u32, u32), usize) {
    let (mut predicted, mut counted, mut n) = ((0.0, 0.0), (0u32, 0u32), 0);
    for seed in seeds {
        let mut k = 0;
        defensive_game(variant, seed, &mut |p| {
            k += 1;
            if k % every != 0 {
                return true;
            }
            let played = Agent::Defensive.act(variant, &p.state);
            let odds = in_play(
                variant,
                &p.state,
                p.seat,
                &p.own_draws,
                worlds,
                Agent::Defensive,
                seed << 20 | k as u64,
            );
            if let Some(o) = odds.iter().find(|o| o.action == played) {
                let (end, _) = play_round(variant, p.state, played, Agent::Defensive);
                predicted.0 += o.win;
                predicted.1 += o.deal_in;
                counted.0 += end.winners >> p.seat & 1;
                counted.1 += u32::from(end.deal_in == p.seat + 1);
                n += 1;
            }
            true
        });
    }
    (predicted, counted, n)
}
