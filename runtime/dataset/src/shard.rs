//! One shard on disk: a folder of `.npy` arrays, one row per decision (and `scores`/`ranks`, one
//! row per game). `.npy` because numpy maps it without a copy (`np.load(mmap_mode="r")`) and
//! PyTorch takes the result as it is; every array is a plain little-endian one, so any reader of
//! the format works. Written into a hidden folder and renamed into place: a shard folder that
//! exists is whole.

use std::io::BufWriter;
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

/// The per-game arrays: `scores` (points at the end, int32 `[games, 4]`) and `ranks` (final place,
/// uint8 `[games, 4]`).
pub const GAME_ARRAYS: [(&str, &str); 2] = [("scores", "int32"), ("ranks", "uint8")];

fn write_npy<T: npyz::AutoSerialize + Copy>(
    dir: &Path,
    name: &str,
    shape: &[u64],
    values: impl IntoIterator<Item = T>,
) -> Result<(), String> {
    let path = dir.join(format!("{name}.npy"));
    let io = |e: std::io::Error| format!("{}: {e}", path.display());
    let file = std::fs::File::create(&path).map_err(io)?;
    let mut writer = npyz::WriteOptions::new()
        .default_dtype()
        .shape(shape)
        .writer(BufWriter::new(file))
        .begin_nd()
        .map_err(io)?;
    writer.extend(values).map_err(io)?;
    writer.finish().map_err(io)
}

/// Writes `games`' rows as shard `name` of `out` (replacing a folder of that name a run left
/// unfinished); returns the rows written.
pub fn write_shard(
    out: &Path,
    name: &str,
    games: &[GameRows],
    forms: &[Form],
    num_actions: usize,
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
        let bytes = games.iter().flat_map(|g| g.observations[f].iter().copied());
        write_npy(&partial, form.name(), &[n, form.bytes() as u64], bytes)?;
    }
    let mask = games.iter().flat_map(|g| g.mask.iter().map(|&b| b != 0));
    write_npy(&partial, "legal_action_mask", &[n, num_actions as u64], mask)?;
    write_npy(
        &partial,
        "action",
        &[n],
        games.iter().flat_map(|g| g.action.iter().copied()),
    )?;
    write_npy(
        &partial,
        "seat",
        &[n],
        games.iter().flat_map(|g| g.seat.iter().copied()),
    )?;
    write_npy(
        &partial,
        "round",
        &[n],
        games.iter().flat_map(|g| g.round.iter().copied()),
    )?;
    let game = games
        .iter()
        .enumerate()
        .flat_map(|(i, g)| std::iter::repeat_n(i as u32, g.rows()));
    write_npy(&partial, "game", &[n], game)?;
    let g = games.len() as u64;
    write_npy(&partial, "scores", &[g, 4], games.iter().flat_map(|g| g.scores))?;
    write_npy(&partial, "ranks", &[g, 4], games.iter().flat_map(|g| g.ranks))?;
    if done.exists() {
        std::fs::remove_dir_all(&done).map_err(|e| io(&done, e))?;
    }
    std::fs::rename(&partial, &done).map_err(|e| io(&done, e))?;
    Ok(n)
}
