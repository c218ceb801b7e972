//! Log files in any format, plain or gzipped: the reader tells the format from the text (an
//! mjlog starts with `<mjloggm`; an MJAI log's first line is an event with a `type`; anything
//! else is read as tenhou.net/6), the writer from the file name (`.mjson`, `.jsonl` or
//! `--format`; `.gz` compresses). mjlog is read only.

use std::io::{Read, Write};
use std::path::Path;

use flate2::read::GzDecoder;
use flate2::write::GzEncoder;
use flate2::Compression;

use crate::mjai;
use crate::tenhou::log::{Game, LogError};
use crate::tenhou::write as tenhou_write;

/// A log format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// tenhou.net/6 JSON, one round per line.
    Tenhou,
    /// MJAI, one event per line.
    Mjai,
    /// Tenhou's mjlog XML (read only).
    Mjlog,
}

impl Format {
    /// The format a file name asks for: MJAI for `*.mjson` and `*.jsonl` (gzipped or not).
    pub fn of_path(path: &Path) -> Format {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().to_lowercase())
            .unwrap_or_default();
        let name = name.strip_suffix(".gz").unwrap_or(&name);
        if name.ends_with(".mjson") || name.ends_with(".jsonl") {
            Format::Mjai
        } else {
            Format::Tenhou
        }
    }
}

/// The most text a log may hold, plain or unpacked from gzip (a whole hanchan is under 200 KB in
/// either format; the cap keeps a hostile file from filling memory).
pub const MAX_TEXT: u64 = 64 << 20;

/// A log file's bytes, at most [`MAX_TEXT`] of them: a larger file is refused before it is read
/// whole (a one-line log of gigabytes would otherwise be held, then parsed, in memory).
pub fn read_log_bytes(path: &Path) -> Result<Vec<u8>, LogError> {
    read_capped(path, MAX_TEXT)
}

fn read_capped(path: &Path, cap: u64) -> Result<Vec<u8>, LogError> {
    let err = |message: String| LogError::file(&path.display().to_string(), message);
    let file = std::fs::File::open(path).map_err(|e| err(e.to_string()))?;
    let mut out = Vec::new();
    file.take(cap + 1)
        .read_to_end(&mut out)
        .map_err(|e| err(e.to_string()))?;
    if out.len() as u64 > cap {
        return Err(err(format!(
            "larger than {} MiB: not a log this reader takes",
            cap >> 20
        )));
    }
    Ok(out)
}

/// The text of a log's bytes, unpacked when they are gzipped.
pub fn log_text(name: &str, bytes: &[u8]) -> Result<String, LogError> {
    let file_err = |message: String| LogError {
        file: name.to_string(),
        line: None,
        column: None,
        round: None,
        field: None,
        message,
    };
    let bytes = if bytes.starts_with(&[0x1f, 0x8b]) {
        let mut out = Vec::new();
        GzDecoder::new(bytes)
            .take(MAX_TEXT + 1)
            .read_to_end(&mut out)
            .map_err(|e| file_err(format!("not a readable gzip file: {e}")))?;
        if out.len() as u64 > MAX_TEXT {
            return Err(file_err(format!("unpacks to more than {} MiB", MAX_TEXT >> 20)));
        }
        out
    } else if bytes.len() as u64 > MAX_TEXT {
        return Err(file_err(format!("larger than {} MiB", MAX_TEXT >> 20)));
    } else {
        bytes.to_vec()
    };
    String::from_utf8(bytes).map_err(|e| file_err(format!("not UTF-8 text: {e}")))
}

/// Reads a log of either format from its bytes; `name` only names it in messages.
pub fn parse_log(name: &str, bytes: &[u8]) -> Result<(Game, Format), LogError> {
    let text = log_text(name, bytes)?;
    if crate::mjlog::read::is_mjlog(&text) {
        Ok((crate::mjlog::read::parse_game(name, &text)?, Format::Mjlog))
    } else if mjai::read::is_mjai(&text) {
        Ok((mjai::read::parse_game(name, &text)?, Format::Mjai))
    } else {
        Ok((crate::tenhou::log::parse_game(name, &text)?, Format::Tenhou))
    }
}

/// Reads one log file of either format, plain or gzipped.
pub fn read_log(path: &Path) -> Result<Game, LogError> {
    let bytes = read_log_bytes(path)?;
    parse_log(&path.display().to_string(), &bytes).map(|(game, _)| game)
}

/// A game as the text of a log of `format` (tenhou.net/6 or MJAI: mjlog is read, not written).
pub fn game_text(game: &Game, format: Format) -> Result<String, LogError> {
    match format {
        Format::Tenhou => Ok(tenhou_write::game_text(game)),
        Format::Mjai => mjai::write::game_text(game),
        Format::Mjlog => Err(LogError {
            file: game.path.clone(),
            line: None,
            column: None,
            round: None,
            field: None,
            message: "mjlog is read only: write tenhou.net/6 or MJAI".into(),
        }),
    }
}

/// Writes a game to `path` in `format`, gzipped when the name ends in `.gz`.
pub fn write_log(path: &Path, game: &Game, format: Format) -> Result<(), String> {
    let text = game_text(game, format).map_err(|e| e.to_string())?;
    let io = |e: std::io::Error| format!("{}: {e}", path.display());
    if path.extension().is_some_and(|e| e == "gz") {
        let file = std::fs::File::create(path).map_err(io)?;
        let mut gz = GzEncoder::new(file, Compression::default());
        gz.write_all(text.as_bytes()).map_err(io)?;
        gz.finish().map_err(io)?;
        Ok(())
    } else {
        std::fs::write(path, text).map_err(io)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_log_file_past_the_cap_is_refused_unread() {
        let path = std::env::temp_dir().join(format!("rinshan-big-log-{}.json", std::process::id()));
        // Sparse: a file one byte past the cap costs no disk, and reading it whole would cost 64 MiB.
        std::fs::File::create(&path)
            .and_then(|f| f.set_len(MAX_TEXT + 1))
            .expect("a sparse file");
        let refused = read_log(&path).map(|_| ()).expect_err("refused");
        assert!(refused.message.contains("larger than 64 MiB"), "{refused}");
        let small = read_capped(&path, 1 << 20).expect_err("refused");
        assert!(small.message.contains("larger than 1 MiB"), "{small}");
        std::fs::write(&path, "x".repeat(1 << 20)).expect("written");
        assert_eq!(read_capped(&path, 1 << 20).map(|b| b.len()).ok(), Some(1 << 20));
        let _ = std::fs::remove_file(&path);
        // In memory (the server's upload), plain text past the cap is refused too.
        let big = vec![b' '; MAX_TEXT as usize + 1];
        assert!(log_text("upload", &big).is_err_and(|e| e.message.contains("larger than 64 MiB")));
    }

    #[test]
    fn a_record_too_long_for_a_game_is_refused_before_it_is_parsed() {
        // One line of 5 MiB inside the cap on files: a tenhou.net/6 record, and an MJAI event.
        let long = format!("{{\"log\": [], \"title\": [\"{}\"]}}", "x".repeat(5 << 20));
        let e = parse_log("long.json", long.as_bytes())
            .map(|_| ())
            .expect_err("refused");
        assert!(e.message.contains("at most 4 MiB") && e.line == Some(1), "{e}");
        let mjai = format!(
            "{{\"type\":\"start_game\"}}\n{{\"type\":\"none\",\"x\":\"{}\"}}\n",
            "x".repeat(70_000)
        );
        let e = parse_log("long.mjson", mjai.as_bytes())
            .map(|_| ())
            .expect_err("refused");
        assert!(
            e.message.contains("no MJAI event is longer") && e.line == Some(2),
            "{e}"
        );
    }
}
