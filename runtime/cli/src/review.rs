//! `rinshan review LOG --player NAME`: a player's decisions judged by the look-ahead, as text, JSON
//! or an offline HTML report.

use std::io::IsTerminal as _;
use std::path::PathBuf;

use indicatif::{ProgressBar, ProgressStyle};
use rinshan_logs::read_log;
use rinshan_review::{review_html, review_spots, seat_for, spots};
use rinshan_search::Options;

use crate::args::on_threads;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// A log of one game: tenhou.net/6, MJAI or mjlog, plain or gzipped
    log: PathBuf,
    /// The player to review, by the name the log gives
    #[arg(long, conflicts_with = "seat", required_unless_present = "seat")]
    player: Option<String>,
    /// The seat to review (0 = East 1's dealer)
    #[arg(long)]
    seat: Option<u32>,
    /// Review one round only: 0-based index into the log's rounds
    #[arg(long)]
    round: Option<usize>,
    /// The look-ahead judging each decision: play-outs per decision, seed, base agent, margin
    /// (standard errors a loss needs to count as a mistake), e.g. `search:rollouts=4096:seed=2`.
    /// 1,024 play-outs give a duel of 256 worlds, a standard error of about 0.05 places
    #[arg(long, default_value = "search:rollouts=1024")]
    search: String,
    /// Write the HTML report here (one file, viewable offline)
    #[arg(long, short = 'o', value_name = "FILE")]
    html: Option<PathBuf>,
    /// Print the review as JSON instead of text
    #[arg(long)]
    json: bool,
    /// How many mistakes the text lists
    #[arg(long, default_value_t = 10)]
    top: usize,
    /// CPU threads (default: all cores)
    #[arg(long)]
    threads: Option<usize>,
}

pub fn run(args: Args) -> Result<(), CliError> {
    let options: Options = args.search.parse().map_err(CliError::input)?;
    let game = read_log(&args.log).map_err(CliError::input)?;
    let seat = seat_for(&game, args.seat, args.player.as_deref()).map_err(CliError::input)?;
    let spots = spots(&game, seat, args.round).map_err(CliError::input)?;
    let bar = match std::io::stderr().is_terminal() && !args.json {
        true => {
            let bar = ProgressBar::new(spots.len() as u64);
            bar.set_style(
                ProgressStyle::with_template("{bar:40} {pos}/{len} decisions eta {eta}")
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            bar
        }
        false => ProgressBar::hidden(),
    };
    let review = on_threads(args.threads, || {
        review_spots(&game, seat, &spots, options, &|| bar.inc(1))
    })?;
    bar.finish_and_clear();
    if let Some(path) = &args.html {
        let page = review_html(&game, &review).map_err(CliError::failure)?;
        std::fs::write(path, page).map_err(|e| CliError::failure(format!("{}: {e}", path.display())))?;
    }
    if args.json {
        let text = serde_json::to_string_pretty(&review).map_err(|e| CliError::failure(e.to_string()))?;
        println!("{text}");
        return Ok(());
    }
    let g = &review.game;
    let who = match review.player.as_str() {
        "" => format!("seat {seat}"),
        name => format!("{name} (seat {seat})"),
    };
    println!(
        "{who}: {} decisions with a choice, {} mistakes (agreement {:.1}%) losing {:.3} expected places; edge over the best other action {:+.3} ± {:.3}; judged by {}, {} play-outs",
        g.decisions,
        g.mistakes,
        100.0 * g.agreement,
        g.loss,
        g.edge,
        1.96 * g.edge_stderr,
        review.search,
        review.rollouts
    );
    println!("\nround                decisions  mistakes    loss    edge  ± 95%");
    for r in &review.rounds {
        let s = &r.summary;
        println!(
            "{:<20} {:>9} {:>9} {:>7.3} {:>+7.3} {:>6.3}",
            r.name,
            s.decisions,
            s.mistakes,
            s.loss,
            s.edge,
            1.96 * s.edge_stderr
        );
    }
    let mut mistakes: Vec<_> = review.decisions.iter().filter(|d| d.mistake).collect();
    mistakes.sort_by(|a, b| b.loss.total_cmp(&a.loss));
    if !mistakes.is_empty() {
        println!("\nlargest mistakes (loss in expected places, ± 95%):");
        for d in mistakes.iter().take(args.top) {
            println!(
                "  {:.3} ± {:.3}  {}, step {}: played {}, better {}",
                d.loss,
                1.96 * d.loss_stderr.unwrap_or(f64::NAN),
                d.round_name,
                d.step,
                d.played,
                d.best
            );
        }
    }
    if let Some(path) = &args.html {
        println!("\nreport: {}", path.display());
    }
    Ok(())
}
