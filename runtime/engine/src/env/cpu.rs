//! The CPU backend: every env's `GameState` as raw kernel words, stepped with rayon.

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
    pub(super) pool: Option<rayon::ThreadPool>,
    pub(super) serial: bool,
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
