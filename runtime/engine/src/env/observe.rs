//! Observations of the games of an [`Env`]: any seat of each game, in either form, on request or
//! written every step for the current player ([`Config::observe`](crate::env::Config::observe)(super::Config::observe)).

use super::config::EnvError;
use super::games::{Backing, Env};
use crate::batch::each;
use crate::generated::kernel;
use crate::observe::Form;

/// Whose observation to write, per env.
#[derive(Debug, Clone, Copy)]
pub enum Observer<'a> {
    /// Each env's current player (the seat that decides next).
    Current,
    /// The same seat (0..3, 0..2 with three players, or 4 for each env's current player) in
    /// every env.
    Seat(u32),
    /// One seat per env (0..3, 0..2 with three players, or 4 for that env's current player).
    Seats(&'a [u32]),
}

impl Env {
    fn observer_args(&self, observer: Observer) -> Result<Vec<u32>, EnvError> {
        let b = self.batch();
        // A seat of the table (three in sanma), or OBSERVE_CURRENT.
        let seats = self.variant().seats();
        let bad = |s: u32| s >= seats && s != kernel::OBSERVE_CURRENT;
        match observer {
            Observer::Current => Ok(vec![kernel::OBSERVE_CURRENT; b]),
            Observer::Seat(s) if !bad(s) => Ok(vec![s; b]),
            Observer::Seat(s) => Err(EnvError::BadSeat { env: 0, seat: s, seats }),
            Observer::Seats(seats) => {
                self.check_len("seats", seats.len())?;
                if let Some(env) = seats.iter().position(|&s| bad(s)) {
                    return Err(EnvError::BadSeat {
                        env,
                        seat: seats[env],
                        seats: self.variant().seats(),
                    });
                }
                Ok(seats.to_vec())
            }
        }
    }

    /// Writes one `form` observation per env into `out` (`batch * form.bytes()` bytes, env-major),
    /// for the seats `observer` names. Seats that are not deciding see everything public and their
    /// own hand, and no decision. On the GPU, only this call (and [`Config::observe`](crate::env::Config::observe)) reads
    /// observations back.
    pub fn observe_into(&mut self, form: Form, observer: Observer, out: &mut [u8]) -> Result<(), EnvError> {
        let want = self.batch() * form.bytes();
        if out.len() != want {
            return Err(EnvError::WrongLength {
                what: "observation bytes",
                expected: want,
                got: out.len(),
            });
        }
        let args = self.observer_args(observer)?;
        let variant = self.variant();
        match &mut self.backing {
            Backing::Cpu(cpu) => match bytemuck::try_cast_slice_mut::<u8, u32>(out) {
                // A word-aligned buffer (numpy's are) is written in place.
                Ok(words) => cpu.observe(variant, form, &args, words),
                Err(_) => {
                    let mut words = vec![0u32; self.config.batch * form.words()];
                    cpu.observe(variant, form, &args, &mut words);
                    out.copy_from_slice(bytemuck::cast_slice(&words));
                }
            },
            Backing::Gpu(gpu) => {
                let words = gpu.observe(form, &args)?;
                out.copy_from_slice(bytemuck::cast_slice(words));
            }
        }
        Ok(())
    }

    /// As [`Env::observe_into`], into a buffer the env keeps (overwritten by the next call).
    pub fn observe(&mut self, form: Form, observer: Observer) -> Result<&[u8], EnvError> {
        let mut buf = std::mem::take(&mut self.observed);
        buf.resize(self.batch() * form.bytes(), 0);
        let r = self.observe_into(form, observer, &mut buf);
        self.observed = buf;
        r.map(|()| self.observed.as_slice())
    }

    /// Every seat's observation of every env in `form` (centralised critics): `batch * seats`
    /// records (four seats, three in sanma), env-major (env 0 seats 0..3, then env 1 ...), each in
    /// its seat's own ego frame.
    pub fn observe_all(&mut self, form: Form) -> Result<Vec<u8>, EnvError> {
        let n = form.bytes();
        let seats = self.variant().seats() as usize;
        let mut all = vec![0u8; self.batch() * seats * n];
        let mut one = vec![0u8; self.batch() * n];
        for seat in 0..seats {
            self.observe_into(form, Observer::Seat(seat as u32), &mut one)?;
            for (env, record) in one.chunks(n).enumerate() {
                let at = (env * seats + seat) * n;
                all[at..at + n].copy_from_slice(record);
            }
        }
        Ok(all)
    }

    /// The current player's observation of each env in `form`, written by the last reset or step
    /// when [`Config::observe`](crate::env::Config::observe) asks for that form (`batch * form.bytes()` bytes).
    pub fn observation(&self, form: Form) -> Option<&[u8]> {
        let i = self.config.observe.iter().position(|&f| f == form)?;
        Some(bytemuck::cast_slice(&self.observations[i]))
    }

    /// Fills the per-step observations of [`Config::observe`](crate::env::Config::observe) (current players).
    pub(super) fn write_observations(&mut self) -> Result<(), EnvError> {
        if self.config.observe.is_empty() {
            return Ok(());
        }
        let variant = self.variant();
        let args = vec![kernel::OBSERVE_CURRENT; self.batch()];
        for (i, &form) in self.config.observe.iter().enumerate() {
            match &mut self.backing {
                Backing::Cpu(cpu) => cpu.observe(variant, form, &args, &mut self.observations[i]),
                Backing::Gpu(gpu) => {
                    let words = gpu.observe(form, &args)?;
                    self.observations[i].copy_from_slice(words);
                }
            }
        }
        Ok(())
    }
}

impl Env {
    /// The action each env's current player would play if the built-in agent seated there
    /// (`seatings`: one per env, or one for all) decided: for callers that step themselves and
    /// keep per-step statistics (self-play with agents). Computed in the kernel on either backend.
    pub fn agent_actions(&mut self, seatings: &[[crate::agents::Agent; 4]]) -> Result<Vec<u32>, EnvError> {
        let b = self.batch();
        let args = self.seats_words(seatings)?;
        let variant = self.variant();
        match &mut self.backing {
            Backing::Cpu(cpu) => {
                let mut out = vec![0u32; b];
                let sts: &[kernel::GameState] = bytemuck::cast_slice(&cpu.states);
                with_variant!(variant, v => cpu.install(|| each(&mut out, sts, &args, cpu.serial, v::game_agent_action)));
                Ok(out)
            }
            Backing::Gpu(gpu) => Ok(gpu.agent_actions(&args)?.to_vec()),
        }
    }
}
