//! `rinshan._core.Env`: a batch of games whose outputs are numpy arrays allocated once and
//! rewritten in place by every reset and step, with the GIL released while Rust works.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rinshan_engine::agents::Agent;
use rinshan_engine::env::{env_seed, Backend, Config, Env, EnvError, Mode, Observer, Step};
use rinshan_engine::observe::Form;
use rinshan_engine::Variant;

use crate::opponents::{warn, BotOptions, Opponents};

pub(crate) fn env_error(e: EnvError) -> PyErr {
    match e {
        EnvError::Gpu(g) => PyRuntimeError::new_err(g.to_string()),
        other => PyValueError::new_err(other.to_string()),
    }
}

pub(crate) fn parse<T: std::str::FromStr>(what: &str, name: &str) -> PyResult<T>
where
    T::Err: std::fmt::Display,
{
    name.parse::<T>()
        .map_err(|e| PyValueError::new_err(format!("{what}: {e}")))
}

/// Bools of each byte value, low bit first: a mask byte expands with one copy.
static BITS: [[bool; 8]; 256] = {
    let mut t = [[false; 8]; 256];
    let mut v = 0;
    while v < 256 {
        let mut b = 0;
        while b < 8 {
            t[v][b] = (v >> b) & 1 == 1;
            b += 1;
        }
        v += 1;
    }
    t
};

/// Writes the first `out.len()` bits of `words` as bools.
pub(crate) fn expand_bits(words: &[u32], out: &mut [bool]) {
    let mut bytes = words.iter().flat_map(|w| w.to_le_bytes());
    // Whole bytes as fixed 8-byte copies (a single move each), then the partial last one.
    let mut whole = out.chunks_exact_mut(8);
    for (chunk, byte) in (&mut whole).zip(&mut bytes) {
        chunk.copy_from_slice(&BITS[usize::from(byte)]);
    }
    let rest = whole.into_remainder();
    if let (false, Some(byte)) = (rest.is_empty(), bytes.next()) {
        rest.copy_from_slice(&BITS[usize::from(byte)][..rest.len()]);
    }
}

/// The arrays every reset and step rewrites (one row per env).
struct Outputs {
    mask: Py<PyArray2<bool>>,
    current_player: Py<PyArray1<i32>>,
    rewards: Py<PyArray2<f32>>,
    terminated: Py<PyArray1<bool>>,
    truncated: Py<PyArray1<bool>>,
    illegal: Py<PyArray1<bool>>,
    hero: Py<PyArray1<bool>>,
    episode_id: Py<PyArray1<i64>>,
    events: Py<PyArray1<u32>>,
    winners: Py<PyArray2<bool>>,
    deal_in: Py<PyArray1<i8>>,
    yaku: Py<PyArray2<bool>>,
    rounds: Py<PyArray1<i32>>,
    final_scores: Py<PyArray2<i32>>,
    final_rank: Py<PyArray2<i8>>,
    /// One raw byte record per env for each observation form written every step.
    observations: Vec<(Form, Py<PyArray2<u8>>)>,
}

/// Mutable views of [`Outputs`]' rows (all rows, or one part's), taken with the GIL held and
/// written without it.
struct Slices<'a> {
    mask: &'a mut [bool],
    current_player: &'a mut [i32],
    rewards: &'a mut [f32],
    terminated: &'a mut [bool],
    truncated: &'a mut [bool],
    illegal: &'a mut [bool],
    hero: &'a mut [bool],
    episode_id: &'a mut [i64],
    events: &'a mut [u32],
    winners: &'a mut [bool],
    deal_in: &'a mut [i8],
    yaku: &'a mut [bool],
    rounds: &'a mut [i32],
    final_scores: &'a mut [i32],
    final_rank: &'a mut [i8],
}

/// Rows per part of a parallel fill: a few parts per thread at the batches people train with,
/// each large enough that handing it to a thread costs little beside writing it.
const FILL_ROWS: usize = 512;

impl<'a> Slices<'a> {
    /// The rows in parts of `rows` envs (`sizes`: the number of actions and of yaku per row).
    fn split(self, rows: usize, sizes: (usize, usize)) -> Vec<Slices<'a>> {
        fn parts<T>(s: &mut [T], width: usize, rows: usize) -> std::slice::ChunksMut<'_, T> {
            s.chunks_mut(width * rows)
        }
        let (na, ny) = sizes;
        let n = self.terminated.len().div_ceil(rows);
        let mut mask = parts(self.mask, na, rows);
        let mut current_player = parts(self.current_player, 1, rows);
        let mut rewards = parts(self.rewards, 4, rows);
        let mut terminated = parts(self.terminated, 1, rows);
        let mut truncated = parts(self.truncated, 1, rows);
        let mut illegal = parts(self.illegal, 1, rows);
        let mut hero = parts(self.hero, 1, rows);
        let mut episode_id = parts(self.episode_id, 1, rows);
        let mut events = parts(self.events, 1, rows);
        let mut winners = parts(self.winners, 4, rows);
        let mut deal_in = parts(self.deal_in, 1, rows);
        let mut yaku = parts(self.yaku, ny, rows);
        let mut rounds = parts(self.rounds, 1, rows);
        let mut final_scores = parts(self.final_scores, 4, rows);
        let mut final_rank = parts(self.final_rank, 4, rows);
        (0..n)
            .map(|_| Slices {
                mask: mask.next().unwrap_or_default(),
                current_player: current_player.next().unwrap_or_default(),
                rewards: rewards.next().unwrap_or_default(),
                terminated: terminated.next().unwrap_or_default(),
                truncated: truncated.next().unwrap_or_default(),
                illegal: illegal.next().unwrap_or_default(),
                hero: hero.next().unwrap_or_default(),
                episode_id: episode_id.next().unwrap_or_default(),
                events: events.next().unwrap_or_default(),
                winners: winners.next().unwrap_or_default(),
                deal_in: deal_in.next().unwrap_or_default(),
                yaku: yaku.next().unwrap_or_default(),
                rounds: rounds.next().unwrap_or_default(),
                final_scores: final_scores.next().unwrap_or_default(),
                final_rank: final_rank.next().unwrap_or_default(),
            })
            .collect()
    }
}

/// Per-env bookkeeping the kernel does not keep: the running score change of each game (its final
/// scores, since the kernel deals the next game in the step that ends one) and episode ids.
struct Games {
    points: Vec<[f64; 4]>,
    episode: Vec<i64>,
    /// The id the next game to start gets: ids count games in the order they start, over the
    /// env's life, so no two games share one.
    next_episode: i64,
    /// A finished game without auto-reset: its final rows stay as they were.
    finished: Vec<bool>,
    /// The final rows hold a finished game's (to clear at the next step).
    shown: Vec<bool>,
    start: f64,
    /// Seats at the table (4, or 3): a seat past them ends every game with no points.
    seats: usize,
}

impl Games {
    /// Each seat's points at the start: none for a seat past the table's (three players).
    fn start_points(&self) -> [f64; 4] {
        std::array::from_fn(|p| if p < self.seats { self.start } else { 0.0 })
    }
}

/// A batch of games (see `rinshan.make`).
#[pyclass(module = "rinshan._core", name = "Env")]
pub struct PyEnv {
    env: Option<Env>,
    outputs: Outputs,
    games: Games,
    actions: Vec<u32>,
    /// Per env: which seats the caller plays (hero mode), a bit per seat.
    caller_seats: Vec<u8>,
    /// MJAI bots or the look-ahead playing the other seats (`opponents="mjai:COMMAND"`,
    /// `"search"`).
    bots: Option<Opponents>,
    num_actions: usize,
    num_yaku: usize,
}

// One array, one writer: the slice's exclusivity comes from the protocol below, not the borrow.
#[allow(clippy::mut_from_ref)]
fn slice<'a, T: numpy::Element, D: numpy::ndarray::Dimension>(
    a: &'a Bound<'_, numpy::PyArray<T, D>>,
) -> PyResult<&'a mut [T]> {
    // SAFETY: the arrays are made by this module, C-contiguous and never resized; Python sees
    // them read-only, so only this fill writes them, and it holds the env's `&mut self`.
    unsafe { a.as_slice_mut() }.map_err(|e| PyRuntimeError::new_err(format!("output array: {e}")))
}

impl PyEnv {
    fn env(&mut self) -> PyResult<&mut Env> {
        self.env
            .as_mut()
            .ok_or_else(|| PyRuntimeError::new_err("this env is closed: make a new one with rinshan.make"))
    }

    /// Runs `job` (a reset or a step of the env) without the GIL, then writes its outcome into
    /// the output arrays.
    fn run<'py>(
        &mut self,
        py: Python<'py>,
        begin: Begin,
        job: impl FnOnce(&mut Env, &[u32]) -> Result<(), EnvError> + Send,
    ) -> PyResult<()> {
        let o = &self.outputs;
        let (mask, current_player, rewards) = (o.mask.bind(py), o.current_player.bind(py), o.rewards.bind(py));
        let (terminated, truncated, illegal) = (o.terminated.bind(py), o.truncated.bind(py), o.illegal.bind(py));
        let (hero, episode_id, events) = (o.hero.bind(py), o.episode_id.bind(py), o.events.bind(py));
        let (winners, deal_in, yaku, rounds) = (
            o.winners.bind(py),
            o.deal_in.bind(py),
            o.yaku.bind(py),
            o.rounds.bind(py),
        );
        let (final_scores, final_rank) = (o.final_scores.bind(py), o.final_rank.bind(py));
        let obs: Vec<(Form, Bound<'py, PyArray2<u8>>)> =
            o.observations.iter().map(|(f, a)| (*f, a.bind(py).clone())).collect();
        let out = Slices {
            mask: slice(mask)?,
            current_player: slice(current_player)?,
            rewards: slice(rewards)?,
            terminated: slice(terminated)?,
            truncated: slice(truncated)?,
            illegal: slice(illegal)?,
            hero: slice(hero)?,
            episode_id: slice(episode_id)?,
            events: slice(events)?,
            winners: slice(winners)?,
            deal_in: slice(deal_in)?,
            yaku: slice(yaku)?,
            rounds: slice(rounds)?,
            final_scores: slice(final_scores)?,
            final_rank: slice(final_rank)?,
        };
        let mut observations: Vec<(Form, &mut [u8])> =
            obs.iter().map(|(f, a)| Ok((*f, slice(a)?))).collect::<PyResult<_>>()?;
        let (na, ny) = (self.num_actions, self.num_yaku);
        let Some(env) = self.env.as_mut() else {
            return Err(PyRuntimeError::new_err(
                "this env is closed: make a new one with rinshan.make",
            ));
        };
        let games = &mut self.games;
        let actions = &self.actions;
        let callers = &self.caller_seats;
        py.detach(move || -> Result<(), EnvError> {
            job(env, actions)?;
            match begin {
                Begin::Step => {}
                Begin::New => games.points.iter_mut().for_each(|p| *p = [0.0; 4]),
                Begin::Restored => {
                    // A restored game's points so far are its score changes (rewards add up
                    // to them, step by step).
                    let start = games.start_points();
                    for (p, t) in games.points.iter_mut().zip(env.tables()?) {
                        *p = std::array::from_fn(|q| (f64::from(t.scores[q]) - start[q]) / 100.0);
                    }
                }
            }
            if !matches!(begin, Begin::Step) {
                games.finished.iter_mut().for_each(|f| *f = false);
                games.shown.iter_mut().for_each(|f| *f = true);
            }
            let auto_reset = env.config().auto_reset;
            let start = games.start_points();
            let step = env.last();
            let parts = out
                .split(FILL_ROWS, (na, ny))
                .into_iter()
                .zip(games.points.chunks_mut(FILL_ROWS))
                .zip(games.finished.chunks_mut(FILL_ROWS))
                .zip(games.shown.chunks_mut(FILL_ROWS))
                .zip(games.episode.chunks(FILL_ROWS))
                .enumerate()
                .map(|(k, ((((out, points), finished), shown), episode))| Part {
                    first: k * FILL_ROWS,
                    out,
                    games: GameRows {
                        points,
                        episode,
                        finished,
                        shown,
                    },
                    callers: callers
                        .get(k * FILL_ROWS..)
                        .map_or(&[][..], |c| &c[..c.len().min(FILL_ROWS)]),
                })
                .collect();
            env.for_each_part(parts, |part| fill(step, part, (na, ny), start, auto_reset));
            if auto_reset {
                // Ids count games in the order they start: numbered here, after the parallel
                // part, so they do not depend on how the rows were split.
                for (e, _) in games.episode.iter_mut().zip(&step.terminated).filter(|(_, &t)| t) {
                    *e = games.next_episode;
                    games.next_episode += 1;
                }
            }
            for (form, raw) in observations.iter_mut() {
                env.observe_into(*form, Observer::Current, raw)?;
            }
            Ok(())
        })
        .map_err(env_error)
    }
}

/// What a run starts from: new games, restored games, or the games as they were.
#[derive(Clone, Copy)]
enum Begin {
    New,
    Restored,
    Step,
}

/// One part of a fill: rows `first..` of the step, of the arrays and of the bookkeeping.
struct Part<'a> {
    first: usize,
    out: Slices<'a>,
    games: GameRows<'a>,
    /// The caller's seats of these rows (empty: the caller plays every seat).
    callers: &'a [u8],
}

/// One part's rows of [`Games`] (the episode ids are read here and numbered after the fill).
struct GameRows<'a> {
    points: &'a mut [[f64; 4]],
    episode: &'a [i64],
    finished: &'a mut [bool],
    shown: &'a mut [bool],
}

/// Writes one part of a step's outcome into the arrays and keeps the per-game bookkeeping
/// (`sizes`: the number of actions and of yaku). Each array is written in its own pass, a
/// streaming loop, rather than one pass over envs touching twenty arrays at once. The parts run
/// on the env's threads: serial, the fill took about a tenth of a one-thread step and a fifth of
/// a two-thread one (measured inside `run`, batch 4096 and 2048).
fn fill(step: &Step, part: Part, sizes: (usize, usize), start: [f64; 4], auto_reset: bool) {
    let (na, ny) = sizes;
    let Part {
        first,
        out,
        games,
        callers,
    } = part;
    let rows = first..first + out.terminated.len();
    for (row, m) in out.mask.chunks_exact_mut(na).zip(&step.legal_action_mask[rows.clone()]) {
        expand_bits(m, row);
    }
    for (o, &c) in out.current_player.iter_mut().zip(&step.current_player[rows.clone()]) {
        *o = c as i32;
    }
    out.rewards.copy_from_slice(step.rewards[rows.clone()].as_flattened());
    out.terminated.copy_from_slice(&step.terminated[rows.clone()]);
    out.truncated.copy_from_slice(&step.truncated[rows.clone()]);
    out.illegal.copy_from_slice(&step.illegal[rows.clone()]);
    out.events.copy_from_slice(&step.events[rows.clone()]);
    for (row, &w) in out.winners.chunks_exact_mut(4).zip(&step.winners[rows.clone()]) {
        row.copy_from_slice(&BITS[(w & 15) as usize][..4]);
    }
    for (o, &d) in out.deal_in.iter_mut().zip(&step.deal_in[rows.clone()]) {
        *o = d as i8 - 1;
    }
    for (row, y) in out.yaku.chunks_exact_mut(ny).zip(&step.yaku[rows.clone()]) {
        expand_bits(y, row);
    }
    for (o, &r) in out.rounds.iter_mut().zip(&step.rounds[rows.clone()]) {
        *o = r as i32;
    }
    if callers.is_empty() {
        out.hero.fill(true);
    } else {
        for ((o, &c), &seat) in out.hero.iter_mut().zip(callers).zip(&step.current_player[rows.clone()]) {
            *o = c >> seat & 1 == 1;
        }
    }
    out.episode_id.copy_from_slice(games.episode);
    for (j, i) in rows.enumerate() {
        if games.finished[j] {
            continue;
        }
        if !step.illegal[i] {
            for p in 0..4 {
                games.points[j][p] += f64::from(step.rewards[i][p]);
            }
        }
        let (scores, ranks) = (
            &mut out.final_scores[j * 4..j * 4 + 4],
            &mut out.final_rank[j * 4..j * 4 + 4],
        );
        if step.terminated[i] {
            for p in 0..4 {
                scores[p] = (start[p] + games.points[j][p] * 100.0).round() as i32;
                // Places are a permutation of 0..3: all zeros means none were reported (a game
                // ended by an illegal action, or a finished game restored by set_state).
                ranks[p] = if step.ranks[i] == [0; 4] {
                    -1
                } else {
                    step.ranks[i][p] as i8
                };
            }
            games.points[j] = [0.0; 4];
            games.finished[j] = !auto_reset;
            games.shown[j] = true;
        } else if games.shown[j] {
            // Only the rows of the game that ended in the last step need clearing.
            scores.fill(0);
            ranks.fill(-1);
            games.shown[j] = false;
        }
    }
}

/// Bytes an env holds besides its observations: the game state, its view and step outputs.
const ENV_BYTES: usize = 1536;
/// The most memory `make` lets a batch take.
const MAX_BYTES: usize = 16 << 30;

pub(crate) fn form_of(name: &str) -> PyResult<Form> {
    name.parse::<Form>().map_err(|e| PyValueError::new_err(e.to_string()))
}

#[pymethods]
impl PyEnv {
    #[new]
    #[pyo3(signature = (variant, mode, num_envs, backend, num_threads, seed, forms, auto_reset, opponents, hero_seats, penalty, mjai_dialect="app", mjai_timeout=5.0, mjai_startup=60.0))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        variant: &str,
        mode: &str,
        num_envs: usize,
        backend: &str,
        num_threads: Option<usize>,
        seed: u64,
        forms: Vec<String>,
        auto_reset: bool,
        opponents: Option<&str>,
        hero_seats: Option<Vec<u32>>,
        penalty: Option<f32>,
        mjai_dialect: &str,
        mjai_timeout: f64,
        mjai_startup: f64,
    ) -> PyResult<PyEnv> {
        let variant: Variant = parse("variant", variant)?;
        let mode: Mode = parse("mode", mode)?;
        let backend: Backend = parse("backend", backend)?;
        let forms = forms.iter().map(|f| form_of(f)).collect::<PyResult<Vec<Form>>>()?;
        let per_env = ENV_BYTES + forms.iter().map(|f| f.bytes()).sum::<usize>();
        if num_envs.saturating_mul(per_env) > MAX_BYTES {
            // Rust aborts the process when an allocation fails: refuse sizes that cannot fit.
            return Err(PyValueError::new_err(format!(
                "num_envs {num_envs} needs about {} GiB ({per_env} bytes per env with these \
                 observations); the limit is {} GiB",
                num_envs.saturating_mul(per_env) >> 30,
                MAX_BYTES >> 30
            )));
        }
        if forms.contains(&Form::Oracle) {
            return Err(PyValueError::new_err(
                "the oracle is not an observation: ask for it with env.oracle()",
            ));
        }
        let (mut bots, mut hero_bits) = (None, Vec::new());
        let agents =
            match (opponents, hero_seats) {
                (None, None) => Vec::new(),
                (None, Some(_)) => return Err(PyValueError::new_err(
                    "hero_seats needs opponents (random, rule, greedy, defensive, search, net:PATH or mjai:COMMAND)",
                )),
                (Some(name), seats) => {
                    let seats = seats.unwrap_or_else(|| vec![0]);
                    if seats.len() != 1 && seats.len() != num_envs {
                        return Err(PyValueError::new_err(format!(
                            "hero_seats has {} entries: give one seat, or one per env ({num_envs})",
                            seats.len()
                        )));
                    }
                    let table = variant.seats();
                    if let Some(s) = seats.iter().find(|&&s| s >= table) {
                        return Err(PyValueError::new_err(format!(
                            "hero seat {s}: seats are 0..{}",
                            table - 1
                        )));
                    }
                    // Opponents the host plays (a net, the look-ahead, MJAI bots): the kernel plays
                    // no seat, and the caller's and the opponents' actions go in by step.
                    bots = if let Some(path) = name.strip_prefix("net:") {
                        Some(Opponents::net(path, &seats, num_envs, (variant, backend))?)
                    } else if name.starts_with("search") {
                        Some(Opponents::search(name, &seats, num_envs, (variant, backend))?)
                    } else if let Some(command) = name.strip_prefix("mjai:") {
                        let options = BotOptions {
                            dialect: mjai_dialect,
                            timeout: mjai_timeout,
                            startup: mjai_startup,
                        };
                        Some(Opponents::new(
                            command,
                            &seats,
                            num_envs,
                            (variant, mode, backend),
                            &options,
                        )?)
                    } else {
                        None
                    };
                    if bots.is_some() {
                        hero_bits = (0..num_envs)
                            .map(|i| 1u8 << seats[if seats.len() == 1 { 0 } else { i }])
                            .collect();
                        Vec::new()
                    } else {
                        let agent: Agent = parse("opponents", name)?;
                        seats
                            .iter()
                            .map(|&h| std::array::from_fn(|p| (p as u32 != h).then_some(agent)))
                            .collect()
                    }
                }
            };
        let caller_seats: Vec<u8> = match agents.is_empty() {
            true => hero_bits,
            false => (0..num_envs)
                .map(|i| {
                    let seats: &[Option<Agent>; 4] = &agents[if agents.len() == 1 { 0 } else { i }];
                    (0..4).filter(|&p| seats[p].is_none()).map(|p| 1u8 << p).sum()
                })
                .collect(),
        };
        let config = Config {
            mode,
            backend,
            seed,
            auto_reset,
            threads: num_threads,
            penalty,
            agents,
            ..Config::new(variant, num_envs)
        };
        let env = py.detach(|| Env::new(config)).map_err(env_error)?;
        let b = num_envs;
        let na = env.num_actions() as usize;
        let ny = rinshan_engine::env::yaku_names(variant).len();
        let outputs = Outputs {
            mask: PyArray2::zeros(py, [b, na], false).unbind(),
            current_player: PyArray1::zeros(py, b, false).unbind(),
            rewards: PyArray2::zeros(py, [b, 4], false).unbind(),
            terminated: PyArray1::zeros(py, b, false).unbind(),
            truncated: PyArray1::zeros(py, b, false).unbind(),
            illegal: PyArray1::zeros(py, b, false).unbind(),
            hero: PyArray1::zeros(py, b, false).unbind(),
            episode_id: PyArray1::zeros(py, b, false).unbind(),
            events: PyArray1::zeros(py, b, false).unbind(),
            winners: PyArray2::zeros(py, [b, 4], false).unbind(),
            deal_in: PyArray1::zeros(py, b, false).unbind(),
            yaku: PyArray2::zeros(py, [b, ny], false).unbind(),
            rounds: PyArray1::zeros(py, b, false).unbind(),
            final_scores: PyArray2::zeros(py, [b, 4], false).unbind(),
            final_rank: PyArray2::zeros(py, [b, 4], false).unbind(),
            observations: forms
                .iter()
                .map(|&f| (f, PyArray2::zeros(py, [b, f.bytes()], false).unbind()))
                .collect(),
        };
        Ok(PyEnv {
            env: Some(env),
            outputs,
            games: Games {
                points: vec![[0.0; 4]; b],
                episode: vec![0; b],
                next_episode: 0,
                finished: vec![false; b],
                shown: vec![true; b],
                start: f64::from(variant.starting_points()),
                seats: variant.seats() as usize,
            },
            actions: vec![0; b],
            caller_seats,
            bots,
            num_actions: na,
            num_yaku: ny,
        })
    }

    /// The output arrays by name (the same objects after every reset and step).
    fn buffers<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let o = &self.outputs;
        d.set_item("legal_action_mask", o.mask.bind(py))?;
        d.set_item("current_player", o.current_player.bind(py))?;
        d.set_item("rewards", o.rewards.bind(py))?;
        d.set_item("terminated", o.terminated.bind(py))?;
        d.set_item("truncated", o.truncated.bind(py))?;
        d.set_item("illegal", o.illegal.bind(py))?;
        d.set_item("hero", o.hero.bind(py))?;
        d.set_item("episode_id", o.episode_id.bind(py))?;
        d.set_item("events", o.events.bind(py))?;
        d.set_item("winners", o.winners.bind(py))?;
        d.set_item("deal_in", o.deal_in.bind(py))?;
        d.set_item("yaku", o.yaku.bind(py))?;
        d.set_item("rounds", o.rounds.bind(py))?;
        d.set_item("final_scores", o.final_scores.bind(py))?;
        d.set_item("final_rank", o.final_rank.bind(py))?;
        for (form, a) in &o.observations {
            d.set_item(format!("raw_{}", form.name()), a.bind(py))?;
        }
        Ok(d)
    }

    /// New games: from `make`'s seed and a count of resets when `seed` is None, else env i from
    /// `env_seed(seed, i, 0)`; `seeds` gives each env's 64-bit seed directly.
    #[pyo3(signature = (seed=None, seeds=None))]
    fn reset(&mut self, py: Python<'_>, seed: Option<u64>, seeds: Option<Vec<u64>>) -> PyResult<()> {
        let b = self.env()?.batch();
        let seeds = match (seed, seeds) {
            (Some(_), Some(_)) => return Err(PyValueError::new_err("give seed or seeds, not both")),
            (Some(s), None) => Some((0..b as u64).map(|i| env_seed(s, i, 0)).collect::<Vec<u64>>()),
            (None, seeds) => seeds,
        };
        let first = self.games.next_episode;
        for (i, e) in self.games.episode.iter_mut().enumerate() {
            *e = first + i as i64;
        }
        self.games.next_episode = first + b as i64;
        self.run(py, Begin::New, move |env, _| match &seeds {
            Some(s) => env.reset_with_seeds(s).map(|_| ()),
            None => env.reset().map(|_| ()),
        })?;
        if let (Some(bots), Some(env)) = (self.bots.as_mut(), self.env.as_ref()) {
            bots.restart(py, env)?;
        }
        Ok(())
    }

    /// One decision per env: `actions[i]` is env i's action id (int64). Out-of-range ids raise;
    /// an illegal id in range ends that game with the penalty.
    fn step(&mut self, py: Python<'_>, actions: PyReadonlyArray1<'_, i64>) -> PyResult<()> {
        let b = self.env()?.batch();
        let a = actions
            .as_slice()
            .map_err(|e| PyValueError::new_err(format!("actions: {e}")))?;
        if a.len() != b {
            return Err(PyValueError::new_err(format!(
                "actions has {} entries for {b} envs: give exactly one per env",
                a.len()
            )));
        }
        let na = self.num_actions as i64;
        if let Some(i) = a.iter().position(|&x| !(0..na).contains(&x)) {
            return Err(PyValueError::new_err(format!(
                "action {} of env {i} is out of range: action ids are 0..{}",
                a[i],
                na - 1
            )));
        }
        for (dst, &src) in self.actions.iter_mut().zip(a) {
            *dst = src as u32;
        }
        let mut faults = match self.bots.as_mut() {
            Some(bots) => bots.act(py, &mut self.actions)?,
            None => Vec::new(),
        };
        self.run(py, Begin::Step, |env, actions| env.step(actions).map(|_| ()))?;
        if let (Some(bots), Some(env)) = (self.bots.as_mut(), self.env.as_ref()) {
            faults.extend(bots.stepped(py, env, &self.actions)?);
        }
        warn(py, &faults)
    }

    /// One `form` record per env for the seats in `seats` (0..3 each; 4 = the current player):
    /// a new (B, bytes) uint8 array.
    fn observe<'py>(&mut self, py: Python<'py>, form: &str, seats: Vec<u32>) -> PyResult<Bound<'py, PyArray2<u8>>> {
        let form = form_of(form)?;
        let env = self.env()?;
        let b = env.batch();
        let out = PyArray2::<u8>::zeros(py, [b, form.bytes()], false);
        let raw = slice(&out)?;
        py.detach(|| env.observe_into(form, Observer::Seats(&seats), raw))
            .map_err(env_error)?;
        Ok(out)
    }

    /// The action the built-in `agent` would choose for each env's current player.
    fn agent_actions<'py>(&mut self, py: Python<'py>, agent: &str) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let agent: Agent = parse("agent", agent)?;
        let env = self.env()?;
        let actions = py.detach(|| env.agent_actions(&[[agent; 4]])).map_err(env_error)?;
        Ok(PyArray1::from_vec(py, actions.into_iter().map(i64::from).collect()))
    }

    /// Env `i`'s win odds per discard for the seat to act, at its own turn, drawing alone from
    /// the tiles it cannot see: JSON text (`rinshan outlook --json`'s fields); `None` at any
    /// other decision.
    #[pyo3(signature = (i, trials, seed))]
    fn outlook(&mut self, py: Python<'_>, i: usize, trials: u32, seed: u64) -> PyResult<Option<String>> {
        let env = self.env()?;
        let b = env.batch();
        if i >= b {
            return Err(PyValueError::new_err(format!("env {i} does not exist: there are {b}")));
        }
        if trials == 0 {
            return Err(PyValueError::new_err("trials must be at least 1"));
        }
        let variant = env.variant();
        let state = env.game_states().map_err(env_error)?.swap_remove(i);
        let own = variant.discard_actions();
        if (0..3).all(|w| state.mask[w] & own[w] == 0) {
            return Ok(None);
        }
        let (odds, draws) = py
            .detach(|| rinshan_search::outlook::at_turn(variant, &state, state.current, trials, seed))
            .map_err(PyValueError::new_err)?;
        Ok(Some(rinshan_search::outlook::to_json(&odds, draws).to_string()))
    }

    /// Env `i`'s table as SVG text (`png`: PNG bytes), `pov` at the bottom (default: the seat to act).
    #[pyo3(signature = (i, tiles, pov, reveal, png))]
    fn render<'py>(
        &mut self,
        py: Python<'py>,
        i: usize,
        tiles: &str,
        pov: Option<u32>,
        reveal: bool,
        png: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        use rinshan_render::{Board, Options, TileMode};
        let tiles: TileMode = parse("tiles", tiles)?;
        let env = self.env()?;
        let b = env.batch();
        if i >= b {
            return Err(PyValueError::new_err(format!("env {i} does not exist: there are {b}")));
        }
        let seats = env.variant().seats();
        if let Some(p) = pov.filter(|&p| p >= seats) {
            return Err(PyValueError::new_err(format!("pov {p}: seats are 0..{}", seats - 1)));
        }
        let states = env.game_states().map_err(env_error)?;
        let board = Board::from_state(&states[i], env.variant());
        let opts = Options {
            tiles,
            pov: pov.unwrap_or(board.current),
            reveal,
            defs: true,
        };
        let svg = rinshan_render::svg(&board, &opts);
        if png {
            let bytes = py
                .detach(|| rinshan_render::png::png(&svg, 1.0))
                .map_err(PyRuntimeError::new_err)?;
            return Ok(pyo3::types::PyBytes::new(py, &bytes).into_any());
        }
        Ok(pyo3::types::PyString::new(py, &svg).into_any())
    }

    /// Every env's game as uint32 words (B, W): the kernel state and a check pair.
    fn get_state<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<u32>>> {
        let env = self.env()?;
        let (b, w) = (env.batch(), env.saved_words());
        let words = py.detach(|| env.save_states()).map_err(env_error)?;
        PyArray1::from_vec(py, words).reshape([b, w])
    }

    /// Restores games from `get_state` (this variant and batch size).
    fn set_state(&mut self, py: Python<'_>, state: PyReadonlyArray2<'_, u32>) -> PyResult<()> {
        if self.bots.is_some() {
            // A bot has followed its game from the start; it cannot be put in the middle of another.
            return Err(PyValueError::new_err(
                "an env with MJAI or look-ahead opponents cannot restore states (they follow their games from the start)",
            ));
        }
        let env = self.env()?;
        let (b, w) = (env.batch(), env.saved_words());
        if state.shape() != [b, w] {
            return Err(PyValueError::new_err(format!(
                "state has shape {:?}; this env's is ({b}, {w})",
                state.shape()
            )));
        }
        let words = state
            .as_slice()
            .map_err(|e| PyValueError::new_err(format!("state: {e}")))?
            .to_vec();
        self.run(py, Begin::Restored, move |env, _| env.load_states(&words).map(|_| ()))
    }

    /// Releases the env (and stops its MJAI opponents); later calls raise.
    fn close(&mut self) {
        self.env = None;
        self.bots = None;
    }

    /// Whether `close` was called.
    #[getter]
    fn closed(&self) -> bool {
        self.env.is_none()
    }

    /// Words of one env in `get_state`.
    #[getter]
    fn state_words(&mut self) -> PyResult<usize> {
        Ok(self.env()?.saved_words())
    }

    /// The GPU adapter's name, or None on the CPU.
    #[getter]
    fn adapter(&mut self) -> PyResult<Option<String>> {
        Ok(self.env()?.adapter())
    }
}
