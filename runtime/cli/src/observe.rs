//! `rinshan observe <log> --round R --step K`: what a seat's observation holds at a position of a
//! real game (how a user checks what the network sees); `--fields` prints the field reference;
//! `--outlook` adds the deciding seat's win odds per discard.

use std::path::PathBuf;

use rinshan_engine::agents::Agent;
use rinshan_engine::observe::{describe, field_values, fields_markdown, Form};
use rinshan_logs::read_log;
use rinshan_logs::tenhou::log::Game;
use rinshan_logs::tenhou::position::{own_draws, round_positions, Position};
use rinshan_search::outlook::{at_turn, in_play, to_json, InPlay, Odds};
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
    /// Add the deciding seat's win odds per discard at its own turn: drawing alone, and with
    /// every seat played by `defensive` in worlds dealt from its view
    #[arg(long)]
    outlook: bool,
    /// Worlds per discard for the odds with the others playing
    #[arg(long, default_value_t = 128, requires = "outlook")]
    worlds: u32,
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
    let odds = match args.outlook {
        true => Some(outlook(&game, &positions, args.step, seat, args.worlds)?),
        false => None,
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
        let mut out = json!({
            "log": path.display().to_string(), "line": round.line, "round": round.to_string(), "step": pos.step,
            "deciding_seat": pos.seat, "observer": seat, "log_plays": pos.what, "form": args.form.name(), "fields": fields,
        });
        if let Some(o) = &odds {
            out["outlook"] = o.json();
        }
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
    if let Some(o) = &odds {
        o.print();
    }
    Ok(())
}

/// The deciding seat's odds at position `step` of a round's `positions`.
struct Outlook {
    alone: Vec<Odds>,
    draws: usize,
    in_play: Vec<InPlay>,
}

fn outlook(game: &Game, positions: &[Position], step: usize, seat: u32, worlds: u32) -> Result<Outlook, CliError> {
    let pos = &positions[step];
    if seat != pos.seat {
        return Err(CliError::input(format!(
            "--outlook: the odds are the deciding seat's (seat {}), not seat {seat}'s",
            pos.seat
        )));
    }
    let own = own_draws(game.variant, &positions[..=step], seat)
        .pop()
        .unwrap_or_default();
    let (alone, draws) = at_turn(game.variant, &pos.state, seat, 10_000, 1)
        .map_err(|e| CliError::input(format!("--outlook at step {step}: {e}")))?;
    let in_play = in_play(game.variant, &pos.state, seat, &own, worlds, Agent::Defensive, 1);
    Ok(Outlook { alone, draws, in_play })
}

impl Outlook {
    fn json(&self) -> serde_json::Value {
        let in_play: Vec<serde_json::Value> = self
            .in_play
            .iter()
            .map(|o| {
                json!({"action": o.name, "win": o.win, "deal_in": o.deal_in, "points": o.points,
                       "win_points": o.win_points, "worlds": o.worlds})
            })
            .collect();
        json!({"alone": to_json(&self.alone, self.draws), "in_play": in_play})
    }

    fn print(&self) {
        println!("outlook, drawing alone ({} draws left):", self.draws);
        crate::outlook::print_table(&self.alone, self.draws, "  ");
        if let Some(first) = self.in_play.first() {
            println!(
                "outlook with every seat played by defensive ({} worlds, 95%):",
                first.worlds
            );
            println!("  action          win           deal-in        points  points per win");
            for o in &self.in_play {
                println!(
                    "  {:<12} {:>5.1}% +- {:<4.1} {:>5.1}% +- {:<4.1} {:>+8.0}  {}",
                    o.name,
                    100.0 * o.win,
                    100.0 * o.interval(o.win),
                    100.0 * o.deal_in,
                    100.0 * o.interval(o.deal_in),
                    o.points,
                    o.win_points.map_or("-".into(), |p| format!("{p:+.0}"))
                );
            }
        }
    }
}
