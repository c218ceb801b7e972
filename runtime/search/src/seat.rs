//! The look-ahead as an arena player: it follows its game step by step to know which wall places
//! it drew itself (all it needs beyond the state's visible part), and counts its decisions to
//! seed each one's worlds apart.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

use rinshan_engine::arena::{Entrant, Seat};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::observe::OwnDraws;
use rinshan_engine::Variant;

use crate::decide::Search;
use crate::options::Options;

/// The look-ahead agent as an [`Entrant`], with totals over all its games for reports.
#[derive(Debug, Default)]
pub struct SearchEntrant {
    options: Options,
    /// Decisions taken, and those looked ahead at.
    decisions: AtomicU64,
    searched: AtomicU64,
    rollouts: AtomicU64,
    steps: AtomicU64,
    /// Decisions where it played other than its base agent.
    changed: AtomicU64,
    /// Nanoseconds spent deciding.
    nanos: AtomicU64,
    /// Each decision's time in microseconds, for its quantiles.
    micros: Mutex<Vec<u32>>,
}

/// Totals of a [`SearchEntrant`] over its games.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Totals {
    /// Decisions taken.
    pub decisions: u64,
    /// Of them, those looked ahead at (own turns with a choice).
    pub searched: u64,
    /// Play-outs played.
    pub rollouts: u64,
    /// Env steps the play-outs took.
    pub steps: u64,
    /// Decisions where it played other than its base agent.
    pub changed: u64,
    /// Seconds spent deciding (all threads together).
    pub seconds: f64,
    /// The median decision's time, milliseconds.
    pub median_ms: f64,
    /// The 99th percentile of the decisions' time, milliseconds.
    pub p99_ms: f64,
}

impl SearchEntrant {
    /// The look-ahead with `options` in every game it joins.
    pub fn new(options: Options) -> SearchEntrant {
        SearchEntrant {
            options,
            ..SearchEntrant::default()
        }
    }

    /// Its totals so far.
    pub fn totals(&self) -> Totals {
        Totals {
            decisions: self.decisions.load(Ordering::Relaxed),
            searched: self.searched.load(Ordering::Relaxed),
            rollouts: self.rollouts.load(Ordering::Relaxed),
            steps: self.steps.load(Ordering::Relaxed),
            changed: self.changed.load(Ordering::Relaxed),
            seconds: self.nanos.load(Ordering::Relaxed) as f64 * 1e-9,
            median_ms: self.quantile_ms(0.5),
            p99_ms: self.quantile_ms(0.99),
        }
    }

    fn quantile_ms(&self, q: f64) -> f64 {
        let mut t = self.micros.lock().map(|t| t.clone()).unwrap_or_default();
        if t.is_empty() {
            return f64::NAN;
        }
        t.sort_unstable();
        let i = ((t.len() - 1) as f64 * q).round() as usize;
        f64::from(t[i]) * 1e-3
    }
}

struct SearchSeat<'a> {
    entrant: &'a SearchEntrant,
    search: Search,
    variant: Variant,
    seat: u32,
    own_draws: OwnDraws,
    /// Seeds this game's decisions apart from other games'.
    game_key: u64,
    nonce: u64,
}

impl Entrant for SearchEntrant {
    fn join(&self, seat: u32, state: &GameState, variant: Variant) -> Box<dyn Seat + '_> {
        let mut own_draws = OwnDraws::default();
        own_draws.update(variant, state, &mut state.clone(), seat);
        // Games apart by what the seat sees at their start, its own hand (the game's seed would
        // do too, but it is hidden: it deals the wall).
        let mut game_key = u64::from(seat) << 32 | u64::from(state.red >> (seat * 3) & 7);
        for w in 0..5 {
            game_key = game_key.rotate_left(13) ^ u64::from(state.hands[(seat * 5 + w) as usize]);
        }
        Box::new(SearchSeat {
            entrant: self,
            search: Search::new(variant, self.options),
            variant,
            seat,
            own_draws,
            game_key,
            nonce: 0,
        })
    }
}

impl Seat for SearchSeat<'_> {
    fn act(&mut self, state: &GameState) -> Result<u32, String> {
        let start = std::time::Instant::now();
        let nonce = self.game_key ^ self.nonce.wrapping_mul(0x2545_F491_4F6C_DD1D);
        self.nonce += 1;
        let d = self.search.decide(state, self.seat, &self.own_draws.positions, nonce);
        let e = self.entrant;
        e.decisions.fetch_add(1, Ordering::Relaxed);
        e.searched
            .fetch_add(u64::from(!d.candidates.is_empty()), Ordering::Relaxed);
        e.rollouts.fetch_add(u64::from(d.rollouts), Ordering::Relaxed);
        e.steps.fetch_add(d.steps, Ordering::Relaxed);
        e.changed.fetch_add(u64::from(d.action != d.base), Ordering::Relaxed);
        let nanos = start.elapsed().as_nanos() as u64;
        e.nanos.fetch_add(nanos, Ordering::Relaxed);
        if let Ok(mut t) = e.micros.lock() {
            t.push((nanos / 1000).min(u64::from(u32::MAX)) as u32);
        }
        Ok(d.action)
    }

    fn stepped(&mut self, before: &GameState, _action: u32, after: &GameState) -> Result<(), String> {
        self.own_draws
            .update(self.variant, before, &mut after.clone(), self.seat);
        Ok(())
    }
}
