//! `rinshan convert <files or folders> [-o OUT] [--to tenhou|mjai] [--gzip]`: logs from one format
//! to another (tenhou.net/6 JSON and MJAI both ways, Tenhou's mjlog XML to either; the input's
//! format is read off its text). One file
//! goes to `-o FILE` or to standard output; several, or a folder, go into the folder `-o DIR`,
//! each under its own name with the new format's extension. A file that cannot be read or
//! converted is reported and skipped; the others are written.

use std::io::Write;
use std::path::{Path, PathBuf};

use rinshan_logs::file::{game_text, parse_log, read_log_bytes, write_log, Format};
use rinshan_logs::tenhou::log::{collect_files, LOG_EXTENSIONS};

use crate::args::FormatArg;
use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// Log files (tenhou.net/6 JSON, MJAI or mjlog XML, plain or gzipped) or folders of them
    #[arg(required = true)]
    paths: Vec<PathBuf>,
    /// Where to write: a file for one input (standard output when left out), a folder for several
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// The format to write (default: from -o's extension, .mjson/.jsonl for MJAI; else the
    /// other format than each input's, tenhou.net/6 for mjlog)
    #[arg(long, value_enum)]
    to: Option<FormatArg>,
    /// Gzip what is written into a folder (a file given by -o is gzipped when it ends in .gz)
    #[arg(long)]
    gzip: bool,
}

/// The format a log converts to by default.
fn other(from: Format) -> Format {
    match from {
        Format::Tenhou => Format::Mjai,
        Format::Mjai | Format::Mjlog => Format::Tenhou,
    }
}

fn extension(format: Format) -> &'static str {
    match format {
        Format::Tenhou => FormatArg::Tenhou.extension(),
        Format::Mjai => FormatArg::Mjai.extension(),
        Format::Mjlog => "xml",
    }
}

/// The input's name without its log extension: `game.json.gz` -> `game`.
fn stem(path: &Path) -> String {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let lower = name.to_lowercase();
    let cut = LOG_EXTENSIONS
        .iter()
        .filter(|e| lower.ends_with(*e))
        .map(|e| name.len() - e.len())
        .min();
    name[..cut.unwrap_or(name.len())].to_string()
}

pub fn run(args: Args) -> Result<(), CliError> {
    let files = collect_files(&args.paths).map_err(CliError::input)?;
    let into_folder =
        files.len() > 1 || args.paths.iter().any(|p| p.is_dir()) || args.output.as_ref().is_some_and(|o| o.is_dir());
    let read = |f: &Path| -> Result<(rinshan_logs::tenhou::log::Game, Format), String> {
        let name = f.display().to_string();
        let bytes = read_log_bytes(f).map_err(|e| e.to_string())?;
        parse_log(&name, &bytes).map_err(|e| e.to_string())
    };
    if !into_folder {
        let f = &files[0];
        let (game, from) = read(f).map_err(CliError::input)?;
        let to = match (args.to, &args.output) {
            (Some(to), _) => to.format(),
            (None, Some(out)) if Format::of_path(out) == Format::Mjai => Format::Mjai,
            (None, _) => other(from),
        };
        return match &args.output {
            Some(out) => write_log(out, &game, to).map_err(CliError::failure),
            None => {
                let text = game_text(&game, to).map_err(CliError::input)?;
                std::io::stdout()
                    .write_all(text.as_bytes())
                    .map_err(|e| CliError::failure(format!("standard output: {e}")))
            }
        };
    }
    let Some(dir) = &args.output else {
        return Err(CliError::input("several logs convert into a folder: give -o DIR"));
    };
    std::fs::create_dir_all(dir).map_err(|e| CliError::input(format!("-o {}: {e}", dir.display())))?;
    let mut failed = Vec::new();
    let mut written = 0;
    for f in &files {
        let done = read(f).and_then(|(game, from)| {
            let to = args.to.map_or(other(from), FormatArg::format);
            let gz = if args.gzip { ".gz" } else { "" };
            let out = dir.join(format!("{}.{}{gz}", stem(f), extension(to)));
            write_log(&out, &game, to)
        });
        match done {
            Ok(()) => written += 1,
            Err(e) => failed.push(e),
        }
    }
    println!("converted {written} of {} logs into {}", files.len(), dir.display());
    for e in &failed {
        println!("not converted: {e}");
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(CliError::input(format!("{} logs could not be converted", failed.len())))
    }
}
