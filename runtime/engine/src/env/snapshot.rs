//! Saving and restoring every env's game (search, checkpoints, bug reports). A saved env is its
//! `GameState` words followed by a check pair: the kernels index tables with the state's bytes, so
//! a state edited by hand, cut short or made by another variant is refused, not stepped.

use super::config::EnvError;
use super::games::{Backing, Env};
use super::seed::mix64;
use super::step::Step;
use crate::generated::kernel;

/// Words after each env's state in [`Env::save_states`]: the check pair.
pub const CHECK_WORDS: usize = 2;

/// The check pair of one env's state words for `variant`.
fn check(variant: crate::Variant, words: &[u32]) -> [u32; 2] {
    let mut h = mix64(0x7269_6e73_6861_6e00 ^ variant as u64);
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
        let variant = self.variant();
        let states = self.states_words()?;
        let mut out = Vec::with_capacity(self.batch() * self.saved_words());
        for s in states.chunks(self.state_words()) {
            out.extend_from_slice(s);
            out.extend_from_slice(&check(variant, s));
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
        let w = self.state_words();
        let mut states = Vec::with_capacity(self.batch() * w);
        for (env, one) in saved.chunks(n).enumerate() {
            let (s, c) = one.split_at(w);
            if check(variant, s) != c {
                return Err(EnvError::BadState {
                    env,
                    reason: format!(
                        "its check words do not match: it was edited, or saved by an env of another variant than {variant}"
                    ),
                });
            }
            states.extend_from_slice(s);
        }
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                cpu.states.copy_from_slice(&states);
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
                let views = gpu.load(&states)?;
                self.step.fill(views);
            }
        }
        self.write_observations()?;
        Ok(&self.step)
    }
}
