//! `rinshan observe <log> --round R --step K`: what a seat's observation holds at a position of a
//! real game (how a user checks what the network sees); `--fields` prints the field reference.

use std::path::PathBuf;

use rinshan_engine::observe::{describe, field_values, fields_markdown, Form};
use rinshan_logs::read_log;
use rinshan_logs::tenhou::position::round_positions;
use serde_json::json;

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// A log of one game, tenhou.net/6 or MJAI, plain or gzipped
    #[arg(required_unless_present = "fields")]
    log: Option<PathBuf>,
    /// Round: 0-based index into the log's rounds
    #[arg(long, default_value_t = 0)]
    round: usize,
    /// Decision within the round, 0-based (claim prompts count; the list is printed when K is too large)
    #[arg(long, default_value_t = 0)]
    step: usize,
    /// The observing seat (absolute, 0..3); default: the seat deciding
    #[arg(long)]
    seat: Option<u32>,
    /// planes, tokens, analysis or oracle (what the seat cannot see)
    #[arg(long, default_value = "tokens")]
    form: Form,
    /// Print the fields as JSON arrays
    #[arg(long)]
    json: bool,
    /// Print the reference of every observation field (markdown) and exit
    #[arg(long)]
    fields: bool,
}

pub fn run(args: Args) -> Result<(), CliError> {
    if args.fields {
        print!("{}", fields_markdown());
        return Ok(());
    }
    let Some(path) = &args.log else {
        return Err(CliError::input("give a log file, or --fields"));
    };
    let game = read_log(path).map_err(CliError::input)?;
    let positions = round_positions(&game, args.round).map_err(CliError::input)?;
    let Some(pos) = positions.get(args.step) else {
        let list: Vec<String> = positions
            .iter()
            .map(|p| format!("{}: seat {} {}", p.step, p.seat, p.what))
            .collect();
        return Err(CliError::input(format!(
            "round {} has {} decisions (0..{}); --step {} is past them:\n{}",
            args.round,
            positions.len(),
            positions.len().saturating_sub(1),
            args.step,
            list.join("\n")
        )));
    };
    let seat = match args.seat {
        Some(s) if s > 3 => return Err(CliError::input(format!("--seat {s}: seats are 0..3"))),
        Some(s) => s,
        None => pos.seat,
    };
    let record = rinshan_engine::observe::record(game.variant, args.form, &pos.state, seat);
    let round = &game.rounds[args.round];
    if args.json {
        let fields: serde_json::Map<String, serde_json::Value> = args
            .form
            .fields()
            .iter()
            .map(|f| (f.name.to_string(), json!({"dtype": f.dtype.name(), "shape": f.shape, "values": field_values(args.form, &record, f.name)})))
            .collect();
        let out = json!({
            "log": path.display().to_string(), "line": round.line, "round": round.to_string(), "step": pos.step,
            "deciding_seat": pos.seat, "observer": seat, "log_plays": pos.what, "form": args.form.name(), "fields": fields,
        });
        println!("{out:#}");
        return Ok(());
    }
    println!(
        "{} line {} ({}), step {}: seat {} decides, the log plays: {}; seen by seat {seat} ({})",
        path.display(),
        round.line,
        round,
        pos.step,
        pos.seat,
        pos.what,
        args.form
    );
    print!("{}", describe(args.form, &record));
    Ok(())
}
