//! `rinshan replay <files or folders>`: replays tenhou.net/6, MJAI or mjlog logs, each under its
//! rule set (red for Tenhou's and MJAI's; a log rinshan wrote names its own), and reports how far rinshan agrees with them (see `rinshan_logs::tenhou::replay`).

use std::path::PathBuf;

use rinshan_logs::read_log;
use rinshan_logs::tenhou::log::collect_files;
use rinshan_logs::tenhou::replay::{replay, Report};

use rinshan_engine::Variant;

use crate::args::BackendArg;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Log files (tenhou.net/6 JSON, MJAI or mjlog XML, plain or gzipped) or folders of them
    /// (*.json, *.mjson, *.jsonl, *.xml, *.mjlog, each also .gz)
    #[arg(required = true)]
    paths: Vec<PathBuf>,
    #[command(flatten)]
    backend: BackendArg,
    /// Play every log under this rule set instead of the one it names (red unless rinshan wrote
    /// it), e.g. Mahjong Soul games converted to tenhou.net/6: --variant mjsoul
    #[arg(long)]
    variant: Option<Variant>,
    /// Print the report as JSON
    #[arg(long)]
    json: bool,
}

fn print_report(r: &Report, unreadable: &[String]) {
    let line = |name: &str, got: usize, of: usize| println!("  {name:<34} {got:>6} / {of}");
    println!("replayed {} games", r.games);
    line("games ending where the log ends", r.games_ended_right, r.games);
    line("rounds replayed to their logged end", r.rounds_replayed, r.rounds);
    line("logged actions accepted", r.actions_accepted, r.actions);
    line("rounds with matching score changes", r.score_changes_matching, r.rounds);
    line("next rounds (round, honba, sticks)", r.tables_matching, r.tables);
    line("wins with matching han, fu, yaku", r.wins_matching, r.wins);
    if r.wins_yaku_not_logged > 0 {
        line("wins whose yaku are not in the log", r.wins_yaku_not_logged, r.wins);
    }
    line("draws of the same kind", r.draws_matching, r.draws);
    if !r.mismatches.is_empty() {
        println!("{} mismatches:", r.mismatches.len());
        for m in &r.mismatches {
            println!("  {m}");
        }
    }
    for e in unreadable {
        println!("unreadable: {e}");
    }
    if r.all_agree() && unreadable.is_empty() {
        println!("every round and every win agrees with the logs");
    }
}

pub fn run(args: Args) -> Result<(), CliError> {
    let backend = args.backend.backend;
    let files = collect_files(&args.paths).map_err(CliError::input)?;
    if files.is_empty() {
        return Err(CliError::input(
            "no log files found (folders are searched for *.json, *.mjson, *.jsonl, *.xml, *.mjlog, each also .gz)",
        ));
    }
    let mut games = Vec::new();
    let mut unreadable = Vec::new();
    for f in &files {
        match read_log(f) {
            Ok(mut g) => match args.variant.map_or(Ok(()), |v| g.play_under(v)) {
                Ok(()) => games.push(g),
                Err(e) => unreadable.push(e),
            },
            Err(e) => unreadable.push(e.to_string()),
        }
    }
    let report = replay(&games, backend).map_err(CliError::failure)?;
    if args.json {
        let value = serde_json::json!({ "report": report, "unreadable": unreadable, "all_agree": report.all_agree() });
        println!("{value:#}");
    } else {
        print_report(&report, &unreadable);
    }
    if !unreadable.is_empty() {
        return Err(CliError::input(format!(
            "{} log files could not be read",
            unreadable.len()
        )));
    }
    if !report.all_agree() {
        return Err(CliError::failure(format!(
            "{} disagreements with the logs",
            report.mismatches.len()
        )));
    }
    Ok(())
}
