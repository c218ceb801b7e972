//! One shard on disk: a folder of `.npy` arrays, one row per decision (and `scores`/`ranks`, one
//! row per game). `.npy` because numpy maps it without a copy (`np.load(mmap_mode="r")`) and
//! PyTorch takes the result as it is; every array is a plain little-endian one, so any reader of
//! the format works. Written into a hidden folder and renamed into place: a shard folder that
//! exists is whole.

use std::io::{BufWriter, Write};
use std::path::Path;

use npyz::WriterBuilder;
use rinshan_engine::observe::Form;

use crate::record::GameRows;

/// The per-row arrays besides the observations, with numpy's dtype, in the order written.
pub const ROW_ARRAYS: [(&str, &str); 5] = [
    ("legal_action_mask", "bool"),
    ("action", "uint8"),
    ("seat", "uint8"),
    ("round", "uint8"),
    ("game", "uint32"),
];

/// The per-row arrays of a dataset labelled by the look-ahead: its action, and its value of each
/// action id (float32 `[rows, actions]`, NaN where it played the action out in no world).
pub const SEARCH_ARRAYS: [(&str, &str); 2] = [("search_action", "uint8"), ("search_value", "float32")];

/// The per-game arrays: `scores` (points at the end, int32 `[games, 4]`) and `ranks` (final place,
/// uint8 `[games, 4]`).
pub const GAME_ARRAYS: [(&str, &str); 2] = [("scores", "int32"), ("ranks", "uint8")];

/// Writes `name.npy` in `dir`: npyz writes the header (`descr`: numpy's type string, e.g. `|u1`,
/// `<u4`), the data goes out as the little-endian bytes `parts` hold, one slice at a time (a row
/// array is the games' columns one after another, never joined in memory).
fn write_npy<'a>(
    dir: &Path,
    name: &str,
    descr: &str,
    shape: &[u64],
    parts: impl IntoIterator<Item = &'a [u8]>,
) -> Result<(), String> {
    let path = dir.join(format!("{name}.npy"));
    let io = |e: std::io::Error| format!("{}: {e}", path.display());
    let dtype = descr
        .parse::<npyz::TypeStr>()
        .map(npyz::DType::Plain)
        .map_err(|e| format!("{descr}: {e}"))?;
    let file = std::fs::File::create(&path).map_err(io)?;
    let mut writer = npyz::WriteOptions::new_header_only()
        .dtype(dtype)
        .shape(shape)
        .writer(BufWriter::new(file))
        .write_header_only()
        .map_err(io)?;
    for part in parts {
        writer.write_all(part).map_err(io)?;
    }
    writer.flush().map_err(io)
}

/// Writes `games`' rows as shard `name` of `out` (replacing a folder of that name a run left
/// unfinished); returns the rows written.
pub fn write_shard(
    out: &Path,
    name: &str,
    games: &[GameRows],
    forms: &[Form],
    num_actions: usize,
    labelled: bool,
) -> Result<u64, String> {
    let partial = out.join(format!(".{name}.partial"));
    let done = out.join(name);
    let io = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    if partial.exists() {
        std::fs::remove_dir_all(&partial).map_err(|e| io(&partial, e))?;
    }
    std::fs::create_dir_all(&partial).map_err(|e| io(&partial, e))?;
    let rows: usize = games.iter().map(GameRows::rows).sum();
    let n = rows as u64;
    for (f, form) in forms.iter().enumerate() {
        let parts = games.iter().map(|g| g.observations[f].as_slice());
        write_npy(&partial, form.name(), "|u1", &[n, form.bytes() as u64], parts)?;
    }
    // The mask's bytes are 0 or 1: numpy's bool as it is.
    let mask = games.iter().map(|g| g.mask.as_slice());
    write_npy(&partial, "legal_action_mask", "|b1", &[n, num_actions as u64], mask)?;
    write_npy(
        &partial,
        "action",
        "|u1",
        &[n],
        games.iter().map(|g| g.action.as_slice()),
    )?;
    write_npy(&partial, "seat", "|u1", &[n], games.iter().map(|g| g.seat.as_slice()))?;
    write_npy(&partial, "round", "|u1", &[n], games.iter().map(|g| g.round.as_slice()))?;
    if labelled {
        let chosen = games.iter().map(|g| g.search_action.as_slice());
        write_npy(&partial, "search_action", "|u1", &[n], chosen)?;
        let value: Vec<u8> = games
            .iter()
            .flat_map(|g| &g.search_value)
            .flat_map(|v| v.to_le_bytes())
            .collect();
        write_npy(
            &partial,
            "search_value",
            "<f4",
            &[n, num_actions as u64],
            [value.as_slice()],
        )?;
    }
    let game: Vec<u8> = games
        .iter()
        .enumerate()
        .flat_map(|(i, g)| std::iter::repeat_n(i as u32, g.rows()))
        .flat_map(u32::to_le_bytes)
        .collect();
    write_npy(&partial, "game", "<u4", &[n], [game.as_slice()])?;
    let g = games.len() as u64;
    let scores: Vec<u8> = games.iter().flat_map(|g| g.scores).flat_map(i32::to_le_bytes).collect();
    write_npy(&partial, "scores", "<i4", &[g, 4], [scores.as_slice()])?;
    let ranks: Vec<u8> = games.iter().flat_map(|g| g.ranks).collect();
    write_npy(&partial, "ranks", "|u1", &[g, 4], [ranks.as_slice()])?;
    if done.exists() {
        std::fs::remove_dir_all(&done).map_err(|e| io(&done, e))?;
    }
    std::fs::rename(&partial, &done).map_err(|e| io(&done, e))?;
    Ok(n)
}
