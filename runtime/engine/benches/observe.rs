//! Observations per second on one thread, each form alone, over a fixed batch of mid-game
//! positions (random self-play, so the batch holds every phase of a round), beside the game step
//! measured on the same positions: `cargo bench -p rinshan-engine --bench observe`.

mod random_play;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use random_play::{random_env, random_step};
use rinshan_engine::env::Observer;
use rinshan_engine::observe::Form;

const BATCH: usize = 1024;

fn observe(c: &mut Criterion) {
    let (mut env, mut rng) = random_env(BATCH, &[]);
    let mut group = c.benchmark_group("observe");
    group.throughput(Throughput::Elements(BATCH as u64));
    for form in Form::ALL {
        let mut out = vec![0u8; BATCH * form.bytes()];
        group.bench_function(form.name(), |b| {
            b.iter(|| env.observe_into(form, Observer::Current, &mut out).expect("observe"))
        });
    }
    // The baseline: one random step of the same batch (with its mask), same run.
    group.bench_function("step", |b| b.iter(|| random_step(&mut env, &mut rng)));
    group.finish();
}

criterion_group!(benches, observe);
criterion_main!(benches);
