//! What the memory of an observed step costs on this machine: one random step with the planes (or
//! the tokens) of each env's current player, beside the same step without them, and loops that move
//! the bytes of a step and of an observed step and compute nothing; at a batch that stays in the
//! core's cache from one step to the next and at batches that do not:
//! `cargo bench -p rinshan-engine --bench memory_floor`. The step plus a form's bytes less the
//! step's is a floor under the observed step that no change of the kernels' code goes below while
//! the records stay the same bytes.

use std::hint::black_box;
use std::mem::size_of;

mod random_play;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use random_play::{random_env, random_step};
use rinshan_engine::generated::kernel as k;
use rinshan_engine::observe::Form;

const BATCHES: [usize; 3] = [64, 1024, 4096];
const LINE: usize = 64;

/// The bytes of one env that an observed step touches, as the CPU backend lays them out: its
/// state, its step view, the part of its table view that every observation in the form reads, and
/// its record.
struct Traffic {
    states: Vec<u8>,
    views: Vec<u8>,
    tables: Vec<u8>,
    records: Vec<u8>,
    record: Vec<u8>,
    table: usize,
}

const STATE: usize = size_of::<k::GameState>();
const VIEW: usize = size_of::<k::StepView>();
// The log's words end where its length begins. Every observation checks the state's log against
// the table view's copy.
const LOG: usize = std::mem::offset_of!(k::GameState, log_len) - std::mem::offset_of!(k::GameState, log);

/// The forms measured, each with the bytes of the table view that every observation in it reads:
/// the four seat blocks the planes copy, the event list the tokens copy (all of it: a late
/// round's), and the log.
const FORMS: [(Form, usize); 2] = [
    (Form::Planes, 4 * k::P_SEAT_ROWS as usize * 34 + LOG),
    (Form::Tokens, k::TOKEN_EVENTS as usize * 4 + LOG),
];

impl Traffic {
    fn new(batch: usize, form: Form, table: usize) -> Traffic {
        Traffic {
            states: vec![1; batch * STATE],
            views: vec![1; batch * VIEW],
            tables: vec![1; batch * table],
            records: vec![1; batch * form.bytes()],
            record: vec![2; form.bytes()],
            table,
        }
    }

    /// The step's share: each state read and written a word a cache line, and its view written.
    fn step_bytes(&mut self) {
        for (state, view) in self
            .states
            .chunks_exact_mut(STATE)
            .zip(self.views.chunks_exact_mut(VIEW))
        {
            for line in state.chunks_exact_mut(LINE) {
                line[0] = line[0].wrapping_add(1);
            }
            view.fill(line_sum(state));
        }
        black_box(&mut *self);
    }

    /// A whole observed step's worth: the step's share, then, env by env, its state and table
    /// view read a word a cache line and its record written.
    fn observed_step_bytes(&mut self) {
        self.step_bytes();
        let mut sum = 0u8;
        let envs = self
            .states
            .chunks_exact(STATE)
            .zip(self.tables.chunks_exact(self.table));
        for ((state, table), record) in envs.zip(self.records.chunks_exact_mut(self.record.len())) {
            sum = sum.wrapping_add(line_sum(state)).wrapping_add(line_sum(table));
            // A byte that depends on what was read: the copy cannot start before the reads end.
            self.record[0] = sum;
            record.copy_from_slice(&self.record);
        }
        black_box(&mut *self);
    }
}

/// A byte of every cache line of `bytes`, summed.
fn line_sum(bytes: &[u8]) -> u8 {
    bytes.iter().step_by(LINE).fold(0u8, |s, &b| s.wrapping_add(b))
}

fn memory_floor(c: &mut Criterion) {
    let mut group = c.benchmark_group("observed step");
    for batch in BATCHES {
        group.throughput(Throughput::Elements(batch as u64));
        let (mut env, mut rng) = random_env(batch, &[]);
        group.bench_function(BenchmarkId::new("step", batch), |b| {
            b.iter(|| random_step(&mut env, &mut rng))
        });
        // The step's share touches the states and views only: any form's buffers will do.
        let (form, table) = FORMS[0];
        let mut traffic = Traffic::new(batch, form, table);
        group.bench_function(BenchmarkId::new("step bytes", batch), |b| {
            b.iter(|| traffic.step_bytes())
        });
        for (form, table) in FORMS {
            let (mut env, mut rng) = random_env(batch, &[form]);
            group.bench_function(BenchmarkId::new(form.name(), batch), |b| {
                b.iter(|| random_step(&mut env, &mut rng))
            });
            let mut traffic = Traffic::new(batch, form, table);
            group.bench_function(BenchmarkId::new(format!("{form} bytes"), batch), |b| {
                b.iter(|| traffic.observed_step_bytes())
            });
        }
    }
    group.finish();
}

criterion_group!(benches, memory_floor);
criterion_main!(benches);
