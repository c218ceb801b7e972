//! Random self-play for the benches: one thread, auto-reset, the default rules.

use rinshan_engine::env::{Config, Env};
use rinshan_engine::observe::Form;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// An env of `batch` games writing the `observe` forms every step, played long enough that its
/// games are spread over rounds and turns, and the policy's generator.
pub fn random_env(batch: usize, observe: &[Form]) -> (Env, Rng) {
    let mut config = Config::new(Variant::Red, batch);
    config.threads = Some(1);
    config.auto_reset = true;
    config.observe = observe.to_vec();
    let mut env = Env::new(config).expect("an env of the default rules");
    env.reset().expect("reset");
    let mut rng = Rng::new(7);
    for _ in 0..600 {
        random_step(&mut env, &mut rng);
    }
    (env, rng)
}

/// One step with a random legal action in every game.
pub fn random_step(env: &mut Env, rng: &mut Rng) {
    let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
    env.step(&actions).expect("legal random actions");
}
