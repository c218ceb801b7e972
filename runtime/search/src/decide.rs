//! The budget spent over the candidates.
//!
//! Every candidate is played in the same worlds (world k is dealt from the same seed whatever the
//! candidate), so two candidates are compared world by world: the luck of the deal, the largest
//! part of a round's spread, cancels out of their difference. The budget goes in rounds of
//! successive halving: each round plays every surviving candidate in the same new worlds, then the
//! worse half is dropped, so the last worlds go to the few actions that are close. The base
//! agent's own choice always survives, and the look-ahead plays another action only when its
//! paired gain over the base agent's is `margin` standard errors above zero: a noisy estimate
//! then falls back on a sound player instead of on chance.

use std::time::Instant;

use rinshan_engine::agents::Agent;
use rinshan_engine::env::Backend;
use rinshan_engine::generated::kernel::{GameState, SEAT_RIICHI};
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Variant};

use crate::options::{Focus, Options};
use crate::rollout::play_rounds;
use crate::value::placement_value;
use crate::world::deal;

/// One candidate's estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// The action id.
    pub action: u32,
    /// Its mean value over its play-outs (minus the expected final rank, 0 = first; see
    /// [`crate::value`]).
    pub mean: f64,
    /// The standard error of `mean` (infinite under two play-outs: no spread to estimate).
    pub stderr: f64,
    /// Play-outs it got (the halving drops the worse candidates early).
    pub rollouts: u32,
}

/// What the look-ahead decided, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct Decision {
    /// The action to play.
    pub action: u32,
    /// The base agent's action at the same decision.
    pub base: u32,
    /// Every candidate's estimate, best mean first (empty where the look-ahead played none).
    pub candidates: Vec<Candidate>,
    /// Play-outs played, over all candidates.
    pub rollouts: u32,
    /// Env steps they took.
    pub steps: u64,
}

/// Every legal action's estimate at one decision, and the best other action against a kept one.
#[derive(Debug, Clone, PartialEq)]
pub struct Appraisal {
    /// Every candidate's estimate, best mean first (over the worlds each played: the halving's and,
    /// for the two duellists, the duel's).
    pub candidates: Vec<Candidate>,
    /// The best action other than the kept one after the halving.
    pub challenger: Option<u32>,
    /// The challenger's paired mean gain over the kept action in fresh worlds, and its standard
    /// error (`None` where there was no duel: one legal action, the kept action illegal, or out of
    /// time).
    pub duel: Option<(f64, f64)>,
    /// Play-outs played, over all candidates.
    pub rollouts: u32,
    /// Env steps they took.
    pub steps: u64,
}

/// The look-ahead agent of one rule set.
#[derive(Debug, Clone)]
pub struct Search {
    variant: Variant,
    options: Options,
    /// The actions of a seat's own turn (discards): a decision that offers one is looked ahead at.
    own_turn: [u32; 3],
    /// The riichi declaration's action id.
    riichi: u32,
}

fn legal(mask: &[u32; 3]) -> Vec<u32> {
    (0..96)
        .filter(|&a| mask[a as usize / 32] >> (a % 32) & 1 == 1)
        .collect()
}

/// splitmix64's finaliser over two words: world seeds that differ in every bit.
fn mix(a: u64, b: u64) -> u64 {
    let mut z = a ^ b.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

fn mean_and_stderr(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    if xs.len() < 2 {
        return (mean, f64::INFINITY);
    }
    let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

impl Search {
    /// The look-ahead for games of `variant`.
    pub fn new(variant: Variant, options: Options) -> Search {
        Search {
            variant,
            options,
            own_turn: variant.discard_actions(),
            riichi: with_variant!(variant, v => v::ACTION_RIICHI),
        }
    }

    /// Its settings.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Whether the look-ahead plays out the decision at `s`: two or more legal actions on the
    /// seat's own turn, and with [`Focus::Threats`] another seat in riichi or riichi legal. Claim
    /// prompts are left to the base agent.
    pub fn looks_ahead(&self, s: &GameState) -> bool {
        let own = (0..3).any(|w| s.mask[w] & self.own_turn[w] != 0);
        if !own || s.mask.iter().map(|w| w.count_ones()).sum::<u32>() < 2 {
            return false;
        }
        match self.options.focus {
            Focus::All => true,
            Focus::Threats => {
                let riichi_legal = s.mask[self.riichi as usize / 32] >> (self.riichi % 32) & 1 == 1;
                let threat =
                    (0..self.variant.seats()).any(|q| q != s.current && s.seat_flags[q as usize] & SEAT_RIICHI != 0);
                riichi_legal || threat
            }
        }
    }

    /// The action for `observer`, the seat to act at `s`, from what it can see: `own_draws` are
    /// the wall places it drew from this round ([`rinshan_engine::observe::OwnDraws`]), and
    /// `nonce` tells its decisions apart (the worlds are seeded by the options' seed and it). The
    /// hidden part of `s` is read only as a multiset, in a fixed order: the decision is the same
    /// for every state that looks the same from `observer`'s seat.
    pub fn decide(&self, s: &GameState, observer: u32, own_draws: &[u32], nonce: u64) -> Decision {
        let base = self.options.base.act(self.variant, s);
        let mut decision = Decision {
            action: base,
            base,
            candidates: Vec::new(),
            rollouts: 0,
            steps: 0,
        };
        if s.current != observer || !self.looks_ahead(s) {
            return decision;
        }
        let a = self.appraise(s, observer, own_draws, nonce, &[base]);
        let margin = self.options.margin;
        let base_legal = s.mask[base as usize / 32] >> (base % 32) & 1 == 1;
        decision.action = match (a.challenger, a.duel) {
            (Some(c), Some((gain, se))) if gain > 0.0 && (gain > margin * se || margin <= 0.0) => c,
            // The base agent's action is always legal; a state whose mask lacks it is not a game's.
            (Some(c), None) if !base_legal => c,
            _ => base,
        };
        decision.candidates = a.candidates;
        decision.rollouts = a.rollouts;
        decision.steps = a.steps;
        decision
    }

    /// Every legal action at `s` valued for `observer` (the seat to act, at any decision: its own
    /// turn or a claim prompt) in common worlds, with successive halving that always keeps the
    /// actions of `kept`, then the best survivor other than `kept[0]` against `kept[0]` in fresh
    /// worlds: the look-ahead decides by it (`kept` = the base agent's action) and the reviewer
    /// judges by it (`kept` = the action played, then the base agent's, a sound challenger that
    /// the halving's first noisy rounds could otherwise drop). Seeded like [`Search::decide`];
    /// capped by the options' `ms` as well.
    pub fn appraise(&self, s: &GameState, observer: u32, own_draws: &[u32], nonce: u64, kept: &[u32]) -> Appraisal {
        let start = Instant::now();
        let out_of_time = || self.options.ms > 0 && start.elapsed().as_millis() >= u128::from(self.options.ms);
        let mut appraisal = Appraisal {
            candidates: Vec::new(),
            challenger: None,
            duel: None,
            rollouts: 0,
            steps: 0,
        };
        let actions = legal(&s.mask);
        if actions.is_empty() {
            return appraisal;
        }
        let kept_index = kept.first().and_then(|k| actions.iter().position(|a| a == k));
        let pinned: Vec<usize> = kept
            .iter()
            .filter_map(|k| actions.iter().position(|a| a == k))
            .collect();
        let seed = mix(self.options.seed, nonce);
        let mut worlds: Vec<GameState> = Vec::new();
        let mut values: Vec<Vec<f64>> = vec![Vec::new(); actions.len()];
        let mut alive: Vec<usize> = (0..actions.len()).collect();
        let halvings = (usize::BITS - (actions.len() - 1).leading_zeros()).max(1);
        // Half the budget chooses a challenger; the rest pits it against the kept action in fresh
        // worlds. The halving's best is the luckiest of many noisy estimates (the winner's
        // curse): only worlds that played no part in choosing it judge it fairly.
        let selection = self.options.rollouts as usize / 2;
        let per_halving = selection / halvings as usize;
        // On the CPU, a candidate's worlds (a duel's world) at a time, so that a time cap stops
        // between them; on the GPU, all of a halving's (the duel's) at once.
        let gpu = self.options.backend == Backend::Gpu;
        let play = |plays: &[(GameState, u32)], appraisal: &mut Appraisal| -> Vec<f64> {
            let ends = play_rounds(self.variant, plays, self.options.base, self.options.backend);
            appraisal.rollouts += ends.len() as u32;
            ends.iter()
                .map(|(end, steps)| {
                    appraisal.steps += u64::from(*steps);
                    placement_value(end, observer, self.variant)
                })
                .collect()
        };
        let deal_more = |worlds: &mut Vec<GameState>, n: usize| {
            let from = worlds.len();
            for k in from..from + n {
                let mut rng = Rng::new(mix(seed, k as u64));
                worlds.push(deal(self.variant, s, observer, own_draws, &mut rng));
            }
            from
        };
        let mut timed_out = false;
        for halving in 1..=halvings {
            let from = deal_more(&mut worlds, (per_halving / alive.len()).max(1));
            let fresh = &worlds[from..];
            let groups: Vec<&[usize]> = match gpu {
                true => vec![&alive[..]],
                false => alive.chunks(1).collect(),
            };
            for group in groups {
                let plays: Vec<(GameState, u32)> = group
                    .iter()
                    .flat_map(|&c| fresh.iter().map(move |w| (*w, c)))
                    .map(|(w, c)| (w, actions[c]))
                    .collect();
                let v = play(&plays, &mut appraisal);
                for (&c, vs) in group.iter().zip(v.chunks(fresh.len())) {
                    values[c].extend_from_slice(vs);
                }
                if out_of_time() {
                    timed_out = true;
                    break;
                }
            }
            if timed_out {
                // The candidates played in fewer worlds than the others are not compared.
                let n = worlds.len();
                alive.retain(|&c| values[c].len() == n);
                break;
            }
            if alive.len() > 1 && halving < halvings {
                let mut ranked = alive.clone();
                ranked.sort_by(|&a, &b| mean_and_stderr(&values[b]).0.total_cmp(&mean_and_stderr(&values[a]).0));
                ranked.truncate(alive.len().div_ceil(2));
                for &b in &pinned {
                    if !ranked.contains(&b) {
                        ranked.push(b);
                    }
                }
                ranked.sort_unstable();
                alive = ranked;
            }
        }
        let challenger = alive
            .iter()
            .copied()
            .filter(|&c| Some(c) != kept_index)
            .max_by(|&a, &b| mean_and_stderr(&values[a]).0.total_cmp(&mean_and_stderr(&values[b]).0));
        appraisal.challenger = challenger.map(|c| actions[c]);
        if let (Some(c), Some(b)) = (challenger, kept_index) {
            if !timed_out && alive.contains(&b) {
                let duel = (self.options.rollouts as usize - selection) / 2;
                let from = deal_more(&mut worlds, duel.max(2));
                let fresh = &worlds[from..];
                let mut gains = Vec::new();
                for ws in fresh.chunks(if gpu { fresh.len() } else { 1 }) {
                    let plays: Vec<(GameState, u32)> =
                        ws.iter().flat_map(|w| [(*w, actions[c]), (*w, actions[b])]).collect();
                    for pair in play(&plays, &mut appraisal).chunks(2) {
                        values[c].push(pair[0]);
                        values[b].push(pair[1]);
                        gains.push(pair[0] - pair[1]);
                    }
                    if out_of_time() {
                        break;
                    }
                }
                appraisal.duel = Some(mean_and_stderr(&gains));
            }
        }
        for (c, v) in values.iter().enumerate().filter(|(_, v)| !v.is_empty()) {
            let (mean, stderr) = mean_and_stderr(v);
            appraisal.candidates.push(Candidate {
                action: actions[c],
                mean,
                stderr,
                rollouts: v.len() as u32,
            });
        }
        appraisal.candidates.sort_by(|a, b| b.mean.total_cmp(&a.mean));
        appraisal
    }

    /// The base agent's action at `s` (for the decisions the look-ahead leaves alone).
    pub fn base_action(&self, s: &GameState) -> u32 {
        Agent::act(self.options.base, self.variant, s)
    }
}
