//! Observations per second on one thread, each form alone, over a fixed batch of mid-game
//! positions (random self-play, so the batch holds every phase of a round), beside the game step
//! measured on the same positions: `cargo bench -p rinshan-engine --bench observe`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rinshan_engine::env::{Config, Env, Observer};
use rinshan_engine::observe::Form;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

const BATCH: usize = 1024;

/// Random self-play on one thread: long enough that the games are spread over rounds and turns.
fn positions() -> (Env, Rng) {
    let mut config = Config::new(Variant::Red, BATCH);
    config.threads = Some(1);
    config.auto_reset = true;
    let mut env = Env::new(config).expect("an env of the default rules");
    env.reset().expect("reset");
    let mut rng = Rng::new(7);
    for _ in 0..600 {
        let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
        env.step(&actions).expect("legal random actions");
    }
    (env, rng)
}

fn observe(c: &mut Criterion) {
    let (mut env, mut rng) = positions();
    let mut group = c.benchmark_group("observe");
    group.throughput(Throughput::Elements(BATCH as u64));
    for form in Form::ALL {
        let mut out = vec![0u8; BATCH * form.bytes()];
        group.bench_function(form.name(), |b| {
            b.iter(|| env.observe_into(form, Observer::Current, &mut out).expect("observe"))
        });
    }
    // The baseline: one random step of the same batch (with its mask), same run.
    group.bench_function("step", |b| {
        b.iter(|| {
            let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
            env.step(&actions).expect("legal random actions");
        })
    });
    group.finish();
}

criterion_group!(benches, observe);
criterion_main!(benches);
