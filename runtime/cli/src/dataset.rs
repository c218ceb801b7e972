//! `rinshan dataset <inputs> -o DIR`: logs (files, folders, glob patterns, tar archives; any
//! format, plain or gzipped) replayed into training shards (see `rinshan_dataset`). Resumes a
//! folder a run left unfinished; a log that cannot be read or replayed is reported and skipped,
//! and a game that comes in two logs (two formats, two copies) is kept once and reported.

use std::path::PathBuf;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_dataset::{build, Build, Options, Progress, Seats, DEFAULT_INPUTS_PER_SHARD, DEFAULT_VARIANT};
use rinshan_engine::observe::Form;
use rinshan_engine::Variant;

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Log files, folders (searched recursively), glob patterns (quoted) or tar archives
    /// (.tar, .tar.gz, .tgz) of tenhou.net/6 JSON, MJAI or mjlog XML logs
    #[arg(required = true)]
    inputs: Vec<String>,
    /// The dataset folder: made if missing, resumed if a run left it unfinished
    #[arg(short, long)]
    output: PathBuf,
    /// The rules the logs are replayed in (sanma for three-player logs); logs of other rules are
    /// skipped, as a dataset's rows share one action layout
    #[arg(long, default_value_t = DEFAULT_VARIANT)]
    variant: Variant,
    /// Observation forms of each row, comma-separated (planes, tokens, analysis; none for no
    /// observation)
    #[arg(long, default_value = "planes")]
    observe: String,
    /// Only these absolute seats' decisions (0 = the first dealer), e.g. `0,2`
    #[arg(long, value_delimiter = ',', conflicts_with = "players")]
    seats: Vec<u8>,
    /// Only the decisions of these players (names as the logs spell them), comma-separated
    #[arg(long, value_delimiter = ',')]
    players: Vec<String>,
    /// Keep decisions with a single legal action
    #[arg(long)]
    forced: bool,
    /// Label every row with the look-ahead's action and its value of each action, from the
    /// deciding seat's view (e.g. `search:rollouts=1024`, the agent's settings): the arrays
    /// `search_action` and `search_value` (NaN for actions it did not play out)
    #[arg(long)]
    search: Option<String>,
    /// Logs per shard
    #[arg(long, default_value_t = DEFAULT_INPUTS_PER_SHARD)]
    shard_size: usize,
    /// Threads (default: all cores)
    #[arg(long)]
    threads: Option<usize>,
    /// No progress bar
    #[arg(long)]
    quiet: bool,
    /// Print the summary as JSON
    #[arg(long)]
    json: bool,
}

/// Skipped logs listed in the summary; a large archive may skip thousands (three-player games in
/// a Phoenix year of four-player rows), and the manifest keeps every one.
const SKIPS_SHOWN: usize = 20;

fn forms(text: &str) -> Result<Vec<Form>, CliError> {
    if text == "none" {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    for name in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let form: Form = name.parse().map_err(CliError::input)?;
        if !out.contains(&form) {
            out.push(form);
        }
    }
    Ok(out)
}

fn seats(args: &Args) -> Result<Seats, CliError> {
    // clap refuses both at once, so an error here is about a seat number.
    let seats = (!args.seats.is_empty()).then_some(args.seats.as_slice());
    let players = (!args.players.is_empty()).then_some(args.players.as_slice());
    Seats::chosen(seats, players).map_err(|e| CliError::input(format!("--seats: {e}")))
}

pub fn run(args: Args) -> Result<(), CliError> {
    let b = Build {
        inputs: args.inputs.clone(),
        out: args.output.clone(),
        options: Options {
            variant: args.variant,
            forms: forms(&args.observe)?,
            seats: seats(&args)?,
            forced: args.forced,
            search: args.search.clone(),
        },
        inputs_per_shard: args.shard_size,
        threads: args.threads.unwrap_or_else(rayon::current_num_threads),
    };
    let bar = if args.quiet || args.json {
        ProgressBar::hidden()
    } else {
        let bar = ProgressBar::new_spinner();
        bar.set_style(
            ProgressStyle::with_template("{spinner} {pos} logs  {per_sec}  {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
        );
        bar
    };
    let mut on_progress = |p: Progress| {
        if let Some(total) = p.total {
            if bar.length() != Some(total) {
                bar.set_length(total);
                bar.set_style(
                    ProgressStyle::with_template("{bar:40} {pos}/{len} logs  {per_sec}  eta {eta}  {msg}")
                        .unwrap_or_else(|_| ProgressStyle::default_bar()),
                );
            }
        }
        bar.set_position(p.inputs);
        bar.set_message(format!("{} rows", p.rows));
    };
    let summary = build(&b, &mut on_progress);
    bar.finish_and_clear();
    let summary = summary.map_err(CliError::input)?;
    let per_sec = |n: u64| n as f64 / summary.seconds.max(1e-9);
    if args.json {
        let skipped: Vec<_> = summary
            .skipped
            .iter()
            .map(|s| serde_json::json!({"input": s.input, "reason": s.reason}))
            .collect();
        let duplicates: Vec<_> = summary
            .duplicates
            .iter()
            .map(|d| serde_json::json!({"input": d.input, "same_as": d.same_as}))
            .collect();
        let value = serde_json::json!({
            "output": args.output.display().to_string(),
            "shards_written": summary.shards_written,
            "shards_resumed": summary.shards_resumed,
            "inputs": summary.inputs,
            "games": summary.games,
            "rows": summary.rows,
            "total_rows": summary.total_rows,
            "skipped": skipped,
            "duplicates": duplicates,
            "seconds": summary.seconds,
            "games_per_second": per_sec(summary.games),
            "rows_per_second": per_sec(summary.rows),
        });
        println!("{value:#}");
        return Ok(());
    }
    println!("dataset {}", args.output.display());
    if summary.shards_resumed > 0 {
        println!("  {} shards were already finished", summary.shards_resumed);
    }
    println!(
        "  {} shards written: {} logs, {} games kept, {} rows ({} rows in all)",
        summary.shards_written, summary.inputs, summary.games, summary.rows, summary.total_rows
    );
    println!(
        "  {:.1} s: {:.0} games/s, {:.0} rows/s",
        summary.seconds,
        per_sec(summary.games),
        per_sec(summary.rows)
    );
    if !summary.duplicates.is_empty() {
        println!(
            "  {} logs left out as the same game (deals and moves) as an earlier log, whose rows hold it:",
            summary.duplicates.len()
        );
        for d in summary.duplicates.iter().take(SKIPS_SHOWN) {
            println!("    {} = {}", d.input, d.same_as);
        }
        if summary.duplicates.len() > SKIPS_SHOWN {
            println!(
                "    ... and {} more (each in {})",
                summary.duplicates.len() - SKIPS_SHOWN,
                args.output.join("manifest.json").display()
            );
        }
    }
    if !summary.skipped.is_empty() {
        println!("  {} logs skipped:", summary.skipped.len());
        for s in summary.skipped.iter().take(SKIPS_SHOWN) {
            println!("    {}", s.reason);
        }
        if summary.skipped.len() > SKIPS_SHOWN {
            println!(
                "    ... and {} more (each with its reason in {})",
                summary.skipped.len() - SKIPS_SHOWN,
                args.output.join("manifest.json").display()
            );
        }
    }
    Ok(())
}
