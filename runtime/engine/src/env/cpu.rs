//! The CPU backend: every env's `GameState` as raw kernel words, stepped with rayon.

use std::cell::RefCell;
use std::sync::Arc;

use rayon::prelude::*;

use crate::generated::kernel;
use crate::observe::{observe_cpu, Form, TableView};
use crate::Variant;

/// The CPU backend: every env's `GameState` as raw kernel words, stepped with rayon.
pub(super) struct CpuEnv {
    pub(super) states: Vec<u32>,
    pub(super) views: Vec<u32>,
    /// What each game's table shows, for the planes, packed planes and tokens (made on their
    /// first use).
    pub(super) tables: Vec<TableView>,
    pub(super) pool: Option<Arc<rayon::ThreadPool>>,
    pub(super) serial: bool,
}

thread_local! {
    /// The pool this thread works in as one of its threads (rayon's `use_current_thread`), made
    /// by the first env on the thread and kept for the thread's life.
    static JOINED: RefCell<Option<Arc<rayon::ThreadPool>>> = const { RefCell::new(None) };
}

/// The pool a CPU env made on this thread steps with: `threads` in all (`None`: as many as
/// rayon's current pool has), or none for one thread. The calling thread is one of them: the
/// thread's own pool, which it joins as a worker, so it takes a share of each step instead of
/// waiting for helpers it woke. (Waiting, on a machine with as many threads as cores, the woken
/// helpers could share one core while the caller's stood idle: Python's `env.step` after a busy
/// policy ran at about 0.65x.) A pool a thread joins can never be left, so it is made once per
/// thread and shared by the envs made there with the same thread count; an env that asks for
/// another count, or one made on a thread that already works in a pool (a rayon task), gets a
/// pool of its own that the caller waits for, as before.
pub(super) fn pool_for(threads: Option<usize>) -> Result<Option<Arc<rayon::ThreadPool>>, String> {
    let n = threads.unwrap_or_else(rayon::current_num_threads);
    if n <= 1 {
        return Ok(None);
    }
    JOINED.with(|joined| {
        let mut joined = joined.borrow_mut();
        if let Some(pool) = joined.as_ref().filter(|p| p.current_num_threads() == n) {
            return Ok(Some(Arc::clone(pool)));
        }
        if joined.is_none() {
            let own = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .use_current_thread()
                .build();
            if let Ok(pool) = own {
                let pool = Arc::new(pool);
                *joined = Some(Arc::clone(&pool));
                return Ok(Some(pool));
            }
        }
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map(|pool| Some(Arc::new(pool)))
            .map_err(|e| e.to_string())
    })
}

/// Below this many envs a step runs on the calling thread (rayon's hand-off costs more).
pub(super) const PARALLEL_MIN: usize = 32;
/// Envs per rayon task.
const CHUNK: usize = 8;

impl CpuEnv {
    /// Runs `job` on the env's thread pool when it has one (and is not serial).
    pub(super) fn install<R: Send>(&self, job: impl FnOnce() -> R + Send) -> R {
        match &self.pool {
            Some(pool) if !self.serial => pool.install(job),
            _ => job(),
        }
    }

    /// Writes `form` observations of every game for the seats in `args` into `out`.
    pub(super) fn observe(&mut self, variant: Variant, form: Form, args: &[u32], out: &mut [u32]) {
        let mut tables = std::mem::take(&mut self.tables);
        self.install(|| observe_cpu(variant, form, &self.states, args, out, &mut tables, self.serial));
        self.tables = tables;
    }

    pub(super) fn reset(&mut self, variant: Variant, inputs: &[u32]) {
        let serial = self.serial;
        let states = &mut self.states;
        let views = &mut self.views;
        let mut job = move || {
            with_variant!(variant, v => {
                let ins: &[kernel::ResetInput] = bytemuck::cast_slice(inputs);
                let sts: &mut [kernel::GameState] = bytemuck::cast_slice_mut(states);
                let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(views);
                let one = |((s, w), i): ((&mut kernel::GameState, &mut kernel::StepView), &kernel::ResetInput)| {
                    *s = v::game_new(*i);
                    *w = v::game_view(*s);
                };
                if serial {
                    sts.iter_mut().zip(vws.iter_mut()).zip(ins).for_each(one);
                } else {
                    sts.par_iter_mut().zip(vws.par_iter_mut()).zip(ins.par_iter()).with_min_len(CHUNK).for_each(one);
                }
            })
        };
        match &self.pool {
            Some(pool) if !serial => pool.install(job),
            _ => job(),
        }
    }

    pub(super) fn step(&mut self, variant: Variant, actions: &[u32], play: bool) {
        let serial = self.serial;
        let states = &mut self.states;
        let views = &mut self.views;
        let mut job = move || {
            with_variant!(variant, v => {
                let sts: &mut [kernel::GameState] = bytemuck::cast_slice_mut(states);
                let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(views);
                let one = |((s, w), a): ((&mut kernel::GameState, &mut kernel::StepView), &u32)| {
                    if play {
                        v::game_play(s, *a);
                    } else {
                        v::game_step(s, *a);
                    }
                    *w = v::game_view(*s);
                };
                if serial {
                    sts.iter_mut().zip(vws.iter_mut()).zip(actions).for_each(one);
                } else {
                    sts.par_iter_mut().zip(vws.par_iter_mut()).zip(actions.par_iter()).with_min_len(CHUNK).for_each(one);
                }
            })
        };
        match &self.pool {
            Some(pool) if !serial => pool.install(job),
            _ => job(),
        }
    }
}
