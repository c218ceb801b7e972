//! Building a dataset folder: inputs in their fixed order, cut into shards of so many inputs;
//! shards made in parallel a wave at a time (one per thread), each written whole and then listed
//! in the manifest. A run that stops leaves every listed shard whole; run again with the same
//! inputs and options, it checks the listed shards cover the same inputs and goes on after them.
//! The same inputs and options give the same bytes, whatever the thread count.
//!
//! A game that comes in two inputs (two formats, two copies) is kept from the first in input order
//! and the later ones are listed as duplicates: each wave's logs are parsed in parallel, checked
//! against the games seen in order, then replayed in parallel. A resumed run parses the finished
//! shards' logs again (no replay) to know their games.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rayon::prelude::*;
use rinshan_engine::env::action_names;
use rinshan_logs::tenhou::log::Game;

use crate::inputs::{count, for_each_unit, sources, Unit};
use crate::manifest::{check_forms, Duplicate, Manifest, ShardRecord, Skip};
use crate::record::{parse_unit, record_parsed, GameRows, Options, Outcome};
use crate::same::{game_key, GameKey};
use crate::shard::write_shard;

/// Logs per shard unless told: a shard of hanchan with the planes form is about 200 MB while it is
/// made (about 600 rows of 2.4 KB per game), and one is made per thread.
pub const DEFAULT_INPUTS_PER_SHARD: usize = 128;

/// How often the manifest is rewritten while shards are made: it lists every input, so rewriting
/// it after each wave would cost time quadratic in a large run's length. A shard made but not yet
/// listed when a run stops is made again by the next one.
const SAVE_EVERY: Duration = Duration::from_secs(10);

/// A dataset to build.
#[derive(Debug, Clone)]
pub struct Build {
    /// Files, folders, glob patterns and tar archives of logs (any format, plain or gzipped).
    pub inputs: Vec<String>,
    /// The dataset folder (made if missing; an existing one is resumed).
    pub out: PathBuf,
    /// What rows to make.
    pub options: Options,
    /// Inputs per shard.
    pub inputs_per_shard: usize,
    /// Shards made at once (threads).
    pub threads: usize,
}

/// Where a build stands, for a progress bar.
#[derive(Debug, Clone, Copy, Default)]
pub struct Progress {
    /// Inputs done (resumed ones included).
    pub inputs: u64,
    /// All inputs, when known before reading them (no archives).
    pub total: Option<u64>,
    /// Rows written by this run.
    pub rows: u64,
}

/// What a build did.
#[derive(Debug, Clone, Default)]
pub struct Summary {
    /// Shards written by this run.
    pub shards_written: usize,
    /// Shards a previous run had finished.
    pub shards_resumed: usize,
    /// Inputs covered by this run.
    pub inputs: u64,
    /// Games kept by this run.
    pub games: u64,
    /// Rows written by this run.
    pub rows: u64,
    /// Inputs this run left out, with reasons (duplicates apart).
    pub skipped: Vec<Skip>,
    /// Inputs this run left out as the same game as an earlier input (of this run or a resumed
    /// one's), each with that input.
    pub duplicates: Vec<Duplicate>,
    /// Rows in the whole dataset.
    pub total_rows: u64,
    /// Seconds this run took.
    pub seconds: f64,
}

fn shard_name(index: usize) -> String {
    format!("shard-{index:06}")
}

/// One shard's logs, parsed, before it is replayed: `None` for a duplicate (in `duplicates`).
struct Parsed<'a> {
    index: usize,
    units: &'a [Unit],
    games: Vec<Option<Result<Game, String>>>,
    duplicates: Vec<Duplicate>,
}

/// Replays and writes one shard.
fn make_shard(out: &Path, shard: Parsed<'_>, options: &Options) -> Result<ShardRecord, String> {
    let Parsed {
        index,
        units,
        games,
        duplicates,
    } = shard;
    let mut kept: Vec<GameRows> = Vec::new();
    let mut skipped = Vec::new();
    let (replayed, parsed): (Vec<&Unit>, Vec<Result<Game, String>>) =
        units.iter().zip(games).filter_map(|(u, g)| Some((u, g?))).unzip();
    for (unit, outcome) in replayed.into_iter().zip(record_parsed(parsed, options)?) {
        match outcome {
            Outcome::Rows(rows) => kept.push(*rows),
            Outcome::Skipped(reason) => skipped.push(Skip {
                input: unit.name.clone(),
                reason,
            }),
        }
    }
    let name = shard_name(index);
    let num_actions = action_names(options.variant).len();
    let rows = write_shard(out, &name, &kept, &options.forms, num_actions, options.search.is_some())?;
    Ok(ShardRecord {
        name,
        rows,
        inputs: units.iter().map(|u| u.name.clone()).collect(),
        games: kept.into_iter().map(|g| g.name).collect(),
        skipped,
        duplicates,
    })
}

/// The name of the input at `at` (shard, position): a listed shard's, or one of `wave`'s.
fn input_name(manifest: &Manifest, wave: &[(usize, Vec<Unit>)], at: (usize, usize)) -> String {
    let (shard, pos) = at;
    let listed = manifest.shards.get(shard).and_then(|s| s.inputs.get(pos).cloned());
    let waiting = || {
        wave.iter()
            .find(|(i, _)| *i == shard)
            .and_then(|(_, units)| units.get(pos))
            .map(|u| u.name.clone())
    };
    listed
        .or_else(waiting)
        .unwrap_or_else(|| format!("input {pos} of shard {shard}"))
}

struct State<'a> {
    build: &'a Build,
    manifest: Manifest,
    /// Shards finished before this run.
    resumed: usize,
    /// Index of the next shard.
    next: usize,
    chunk: Vec<Unit>,
    wave: Vec<(usize, Vec<Unit>)>,
    summary: Summary,
    progress: Progress,
    pool: rayon::ThreadPool,
    /// When the manifest was last written.
    saved: Instant,
    /// Each game read so far, at its first input (shard, position).
    seen: HashMap<GameKey, (usize, usize)>,
}

impl State<'_> {
    /// Takes a full (or the last) chunk: checks it against a finished shard, or queues it.
    fn cut(&mut self, on_progress: &mut dyn FnMut(Progress)) -> Result<(), String> {
        let units = std::mem::take(&mut self.chunk);
        if units.is_empty() {
            return Ok(());
        }
        let index = self.next;
        self.next += 1;
        if let Some(done) = self.manifest.shards.get(index) {
            let names: Vec<&str> = units.iter().map(|u| u.name.as_str()).collect();
            if done.inputs != names {
                return Err(format!(
                    "{}: {} was made from other inputs ({} first held {:?}, now {:?}): build into a new folder",
                    self.build.out.display(),
                    done.name,
                    done.name,
                    done.inputs.first(),
                    names.first()
                ));
            }
            // Its games are seen as the run that made it saw them, so later copies stay out.
            let keys: Vec<Option<GameKey>> = self.pool.install(|| {
                units
                    .par_iter()
                    .map(|u| parse_unit(u).ok().map(|g| game_key(&g)))
                    .collect()
            });
            for (pos, key) in keys.into_iter().enumerate() {
                if let Some(key) = key {
                    self.seen.entry(key).or_insert((index, pos));
                }
            }
            self.progress.inputs += units.len() as u64;
            on_progress(self.progress);
            return Ok(());
        }
        self.wave.push((index, units));
        if self.wave.len() >= self.build.threads.max(1) {
            self.flush(false, on_progress)?;
        }
        Ok(())
    }

    /// Makes the queued shards in parallel and lists them in the manifest, in order; writes the
    /// manifest when `last` or when [`SAVE_EVERY`] has passed.
    fn flush(&mut self, last: bool, on_progress: &mut dyn FnMut(Progress)) -> Result<(), String> {
        let wave = std::mem::take(&mut self.wave);
        let (out, options) = (&self.build.out, &self.build.options);
        let games: Vec<Vec<Result<Game, String>>> = self.pool.install(|| {
            wave.par_iter()
                .map(|(_, units)| units.iter().map(parse_unit).collect())
                .collect()
        });
        // In input order whatever the threads: the first input of a game keeps it.
        let mut shards = Vec::with_capacity(wave.len());
        for ((index, units), games) in wave.iter().zip(games) {
            let mut duplicates = Vec::new();
            let mut kept = Vec::with_capacity(games.len());
            for (pos, (unit, game)) in units.iter().zip(games).enumerate() {
                let first = match &game {
                    Ok(g) => *self.seen.entry(game_key(g)).or_insert((*index, pos)),
                    Err(_) => (*index, pos),
                };
                if first == (*index, pos) {
                    kept.push(Some(game));
                } else {
                    duplicates.push(Duplicate {
                        input: unit.name.clone(),
                        same_as: input_name(&self.manifest, &wave, first),
                    });
                    kept.push(None);
                }
            }
            shards.push(Parsed {
                index: *index,
                units,
                games: kept,
                duplicates,
            });
        }
        let made: Vec<Result<ShardRecord, String>> = self.pool.install(|| {
            shards
                .into_par_iter()
                .map(|shard| make_shard(out, shard, options))
                .collect()
        });
        for record in made {
            let record = record?;
            self.summary.shards_written += 1;
            self.summary.inputs += record.inputs.len() as u64;
            self.summary.games += record.games.len() as u64;
            self.summary.rows += record.rows;
            self.summary.skipped.extend(record.skipped.iter().cloned());
            self.summary.duplicates.extend(record.duplicates.iter().cloned());
            self.progress.inputs += record.inputs.len() as u64;
            self.progress.rows += record.rows;
            self.manifest.shards.push(record);
        }
        if last || self.saved.elapsed() >= SAVE_EVERY {
            self.manifest.save(out)?;
            self.saved = Instant::now();
        }
        on_progress(self.progress);
        Ok(())
    }
}

/// Builds (or resumes) the dataset `b` describes; `on_progress` hears after each wave.
pub fn build(b: &Build, on_progress: &mut dyn FnMut(Progress)) -> Result<Summary, String> {
    let start = Instant::now();
    check_forms(&b.options.forms)?;
    b.options.look_ahead()?;
    if b.inputs_per_shard == 0 {
        return Err("a shard needs at least one input".into());
    }
    let sources = sources(&b.inputs)?;
    let out = &b.out;
    let io = |e: std::io::Error| format!("{}: {e}", out.display());
    std::fs::create_dir_all(out).map_err(io)?;
    let fresh = Manifest::new(&b.options, b.inputs_per_shard);
    let manifest = match Manifest::load(out)? {
        Some(m) if m.same_layout(&fresh) => m,
        Some(_) => {
            return Err(format!(
                "{}: holds a dataset made with other options or by another version: build into a new folder",
                out.display()
            ))
        }
        None => {
            if std::fs::read_dir(out).map_err(io)?.next().is_some() {
                return Err(format!(
                    "{}: the folder is not empty and holds no dataset manifest: build into a new or empty folder",
                    out.display()
                ));
            }
            fresh.save(out)?;
            fresh
        }
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(b.threads.max(1))
        .build()
        .map_err(|e| e.to_string())?;
    let resumed = manifest.shards.len();
    let mut state = State {
        build: b,
        manifest,
        resumed,
        next: 0,
        chunk: Vec::new(),
        wave: Vec::new(),
        summary: Summary::default(),
        progress: Progress {
            total: count(&sources),
            ..Progress::default()
        },
        pool,
        saved: Instant::now(),
        seen: HashMap::new(),
    };
    for_each_unit(&sources, &mut |unit| {
        state.chunk.push(unit);
        if state.chunk.len() == b.inputs_per_shard {
            state.cut(on_progress)?;
        }
        Ok(())
    })?;
    state.cut(on_progress)?;
    state.flush(true, on_progress)?;
    if state.next < state.manifest.shards.len() {
        return Err(format!(
            "{}: lists {} shards but the inputs fill only {}: build into a new folder",
            out.display(),
            state.manifest.shards.len(),
            state.next
        ));
    }
    let mut summary = state.summary;
    summary.shards_resumed = state.resumed;
    summary.total_rows = state.manifest.shards.iter().map(|s| s.rows).sum();
    summary.seconds = start.elapsed().as_secs_f64();
    Ok(summary)
}
