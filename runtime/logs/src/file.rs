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

/// The most text a gzipped log may unpack to (a whole hanchan is under 200 KB in either format;
/// the cap keeps a hostile file from filling memory).
const MAX_TEXT: u64 = 64 << 20;

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
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| LogError {
        file: name.clone(),
        line: None,
        column: None,
        round: None,
        field: None,
        message: e.to_string(),
    })?;
    parse_log(&name, &bytes).map(|(game, _)| game)
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
