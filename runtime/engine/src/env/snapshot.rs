//! Saving and restoring every env's game (search, checkpoints, bug reports). A saved env is its
//! `GameState` words followed by a check pair: the kernels index tables with the state's bytes, so
//! a state edited by hand, cut short, made by another variant or laid out by another build is
//! refused, not stepped.

use super::config::EnvError;
use super::games::{Backing, Env};
use super::seed::mix64;
use super::step::Step;
use crate::generated::kernel;

/// Words after each env's state in [`Env::save_states`]: the check pair.
pub const CHECK_WORDS: usize = 2;

/// Mixed with the variant into every check pair.
const CHECK_SALT: u64 = 0x7269_6e73_6861_6e00;

/// The fields of the variant's `GameState` as its WGSL declares them: names, types and order.
fn state_layout(variant: crate::Variant) -> Option<&'static str> {
    let wgsl = with_variant!(variant, v => v::WGSL);
    let (_, rest) = wgsl.split_once("struct GameState {")?;
    rest.split_once("\n}").map(|(fields, _)| fields)
}

/// What the check pair starts from: the variant and the layout of its `GameState`, so that the
/// words of a build whose state is laid out otherwise fail the check instead of being read into
/// the wrong fields.
fn check_seed(variant: crate::Variant) -> u64 {
    let mut h = mix64(CHECK_SALT ^ variant as u64);
    for b in state_layout(variant).unwrap_or_default().bytes() {
        h = mix64(h ^ u64::from(b));
    }
    h
}

/// The check pair of one env's state words, from [`check_seed`].
fn check(seed: u64, words: &[u32]) -> [u32; 2] {
    let mut h = seed;
    for &w in words {
        h = mix64(h ^ u64::from(w));
    }
    [h as u32, (h >> 32) as u32]
}

impl Env {
    /// Words of one env in [`Env::save_states`]: its state and the check pair.
    pub fn saved_words(&self) -> usize {
        self.state_words() + CHECK_WORDS
    }

    /// Every env's game, [`Env::saved_words`] words per env, for [`Env::load_states`] (here or in
    /// another env of the same variant and batch).
    pub fn save_states(&self) -> Result<Vec<u32>, EnvError> {
        let seed = check_seed(self.variant());
        let states = self.states_words()?;
        let mut out = Vec::with_capacity(self.batch() * self.saved_words());
        for s in states.chunks(self.state_words()) {
            out.extend_from_slice(s);
            out.extend_from_slice(&check(seed, s));
        }
        Ok(out)
    }

    /// Restores games saved by [`Env::save_states`] and returns their view as of the save (the
    /// rewards and events of the step that led there). The env is unchanged if any saved env
    /// fails its check.
    pub fn load_states(&mut self, saved: &[u32]) -> Result<&Step, EnvError> {
        let n = self.saved_words();
        if saved.len() != self.batch() * n {
            return Err(EnvError::WrongLength {
                what: "saved state words",
                expected: self.batch() * n,
                got: saved.len(),
            });
        }
        let variant = self.variant();
        let seed = check_seed(variant);
        let w = self.state_words();
        let mut states = Vec::with_capacity(self.batch() * w);
        for (env, one) in saved.chunks(n).enumerate() {
            let (s, c) = one.split_at(w);
            if check(seed, s) != c {
                return Err(EnvError::BadState {
                    env,
                    reason: format!(
                        "its check words do not match: it was edited, or saved by an env of another variant than {variant} or by a rinshan whose game state is laid out otherwise"
                    ),
                });
            }
            states.extend_from_slice(s);
        }
        self.install(&states)
    }

    /// Replaces every env's game by `states` (one per env), as [`Env::load_states`] does without
    /// the check pair: for Rust callers holding states made by this build's kernels (the
    /// look-ahead's worlds), whose layout the type already guarantees. Only the variant is the
    /// caller's to get right.
    pub fn load_game_states(&mut self, states: &[kernel::GameState]) -> Result<&Step, EnvError> {
        self.check_len("game states", states.len())?;
        let words: Vec<u32> = bytemuck::cast_slice(states).to_vec();
        self.install(&words)
    }

    fn install(&mut self, states: &[u32]) -> Result<&Step, EnvError> {
        let variant = self.variant();
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                cpu.states.copy_from_slice(states);
                with_variant!(variant, v => {
                    let sts: &[kernel::GameState] = bytemuck::cast_slice(&cpu.states);
                    let vws: &mut [kernel::StepView] = bytemuck::cast_slice_mut(&mut cpu.views);
                    for (view, s) in vws.iter_mut().zip(sts) {
                        *view = v::game_view(*s);
                    }
                });
                self.step.fill(&cpu.views);
            }
            Backing::Gpu(gpu) => {
                let views = gpu.load(states)?;
                self.step.fill(views);
            }
        }
        self.write_observations()?;
        Ok(&self.step)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::env::Config;

    /// The check covers the state's layout: the declaration it reads holds every field, and a
    /// state saved by the builds before it (their check seeded by the variant alone, whatever
    /// the layout) is refused.
    #[test]
    fn states_saved_with_another_layout_are_refused() {
        for &variant in crate::Variant::ALL {
            let fields = state_layout(variant).expect("the GameState declaration");
            for field in ["seed:", "task:", "task_seat:", "log_len:"] {
                assert!(fields.contains(field), "{variant}: {field} not in the layout");
            }
            let mut env = Env::new(Config::new(variant, 2)).expect("env");
            env.reset().expect("reset");
            let mut saved = env.save_states().expect("save");
            env.load_states(&saved).expect("this build's states load");
            let old_seed = mix64(CHECK_SALT ^ variant as u64);
            let n = env.saved_words();
            for one in saved.chunks_mut(n) {
                let (s, c) = one.split_at_mut(n - CHECK_WORDS);
                c.copy_from_slice(&check(old_seed, s));
            }
            let e = env.load_states(&saved).expect_err("an older build's states");
            assert!(e.to_string().contains("laid out otherwise"), "{variant}: {e}");
        }
    }
}
