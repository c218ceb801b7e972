//! One game of a soak: played decision by decision on the variant's native kernel, checked after
//! every step.

use rinshan_engine::generated::kernel::{GameState, ResetInput, OBSERVE_CURRENT};
use rinshan_engine::observe::{resample_hidden, OwnDraws};
use rinshan_engine::random::Rng;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::write::GameRecorder;

use super::{Players, Soak};

/// What one game did.
pub(super) struct Played {
    /// Every action played.
    pub actions: Vec<u32>,
    /// Observations checked against hidden resampling.
    pub leak_checks: u64,
    /// The first failed check: the decisions played before it, and what failed.
    pub failure: Option<(u64, String)>,
    /// The finished game as a Tenhou log, where the variant and length have one.
    pub log: Option<Game>,
}

pub(super) fn play(soak: &Soak, g: u64, seed: u64, starting: i32, logged: bool) -> Played {
    let mut out = Played {
        actions: Vec::new(),
        leak_checks: 0,
        failure: None,
        log: None,
    };
    rinshan_engine::with_variant!(soak.variant, v => {
        let input = ResetInput {
            seed: [seed as u32, (seed >> 32) as u32],
            mode: soak.mode.kernel(),
            dealer: 4,
            use_wall: 0,
            wall: [0; 136],
            uma: v::host::UMA.map(|x| x * 1000),
            penalty: v::host::ILLEGAL_ACTION_PENALTY,
            auto_reset: 0,
        };
        let mut s: GameState = v::game_new(input);
        let seating: Option<[u32; 4]> = match soak.players {
            Players::Agents(a) => Some(std::array::from_fn(|p| a[(p + g as usize) % 4].kernel())),
            Players::Uniform => None,
        };
        let mut policy = Rng::new(seed ^ 0x736f_616b);
        let mut leak_rng = Rng::new(seed ^ 0x6c65_616b);
        let mut recorder = match logged.then(|| GameRecorder::for_variant(&s, soak.variant)).transpose() {
            Ok(r) => r,
            Err(e) => {
                out.failure = Some((0, format!("the recorder refused the game: {e}")));
                return out;
            }
        };
        let mut draws: [OwnDraws; 4] = Default::default();
        for (q, d) in draws.iter_mut().enumerate() {
            d.update(soak.variant, &s, &mut s.clone(), q as u32);
        }
        let mut rewards = [0f64; 4];
        let fail = |out: &mut Played, what: String| {
            let step = out.actions.len() as u64;
            out.failure = Some((step, what));
        };
        loop {
            if let Err(e) = rinshan_engine::invariants::check(&s, soak.variant) {
                fail(&mut out, e);
                return out;
            }
            if s.terminated != 0 {
                break;
            }
            let p = s.current;
            let decided = out.actions.len() as u64;
            if soak.leak_every > 0 && decided.is_multiple_of(soak.leak_every) {
                out.leak_checks += 1;
                let r = resample_hidden(soak.variant, &s, p, &draws[p as usize].positions, &mut leak_rng);
                let same = bytemuck::bytes_of(&v::observe_planes(s, p)) == bytemuck::bytes_of(&v::observe_planes(r, p))
                    && bytemuck::bytes_of(&v::observe_tokens(s, p)) == bytemuck::bytes_of(&v::observe_tokens(r, p))
                    && bytemuck::bytes_of(&v::observe_packed(s, p)) == bytemuck::bytes_of(&v::observe_packed(r, p));
                if !same {
                    fail(&mut out, format!("seat {p}'s observation changed when the tiles it cannot see were resampled"));
                    return out;
                }
            }
            let a = match seating {
                Some(agents) => {
                    let mut planes = v::observe_planes(s, OBSERVE_CURRENT);
                    v::agent_act(agents[p as usize], &mut planes, s.mask, s.seed, s.steps)
                }
                None => policy.pick_legal(&s.mask),
            };
            let before = s;
            v::game_step(&mut s, a);
            out.actions.push(a);
            let view = v::game_view(s);
            if view.illegal != 0 {
                fail(&mut out, format!("seat {p}'s action {a} was refused as illegal, though the mask offered it"));
                return out;
            }
            for (sum, r) in rewards.iter_mut().zip(view.rewards) {
                *sum += f64::from(r);
            }
            for (q, d) in draws.iter_mut().enumerate() {
                d.update(soak.variant, &before, &mut s, q as u32);
            }
            if let Some(rec) = &mut recorder {
                match rec.record(&before, a, &s) {
                    Ok(Some(game)) => out.log = Some(game),
                    Ok(None) => {}
                    Err(e) => {
                        fail(&mut out, format!("the recorder could not follow: {e}"));
                        return out;
                    }
                }
            }
        }
        for (q, (sum, score)) in rewards.iter().zip(s.scores).enumerate().take(soak.variant.seats() as usize) {
            let change = f64::from(score - starting) / 100.0;
            if (sum - change).abs() > 1e-3 {
                fail(&mut out, format!("seat {q}'s rewards add up to {sum}, its score changed by {change}"));
                return out;
            }
        }
        if recorder.is_some() && out.log.is_none() {
            fail(&mut out, "the game ended but its Tenhou log was never finished".into());
        }
        out
    })
}
