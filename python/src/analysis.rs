//! The look-ahead's judgements: a player's decisions in a log reviewed (`rinshan review`) and a
//! hand's win odds per discard (`rinshan outlook`), each as the JSON the command prints.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rinshan_search::outlook::{of_notation, to_json};
use rinshan_search::Options;

/// The review of one seat's decisions in the log at `path`, as JSON text (`rinshan review --json`).
#[pyfunction]
#[pyo3(signature = (path, seat, player, round, search))]
fn review(
    py: Python<'_>,
    path: &str,
    seat: Option<u32>,
    player: Option<String>,
    round: Option<usize>,
    search: &str,
) -> PyResult<String> {
    let options: Options = search.parse().map_err(PyValueError::new_err)?;
    let game = rinshan_logs::read_log(std::path::Path::new(path)).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let seat = rinshan_review::seat_for(&game, seat, player.as_deref()).map_err(PyValueError::new_err)?;
    // Play-outs take seconds: other Python threads run meanwhile.
    let reviewed = py
        .detach(|| rinshan_review::review(&game, seat, round, options))
        .map_err(PyValueError::new_err)?;
    serde_json::to_string(&reviewed).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A hand's odds per discard, drawing alone from the unseen tiles, as JSON text (`rinshan outlook
/// --json`).
#[pyfunction]
#[pyo3(signature = (hand, seen, draws, trials, seed))]
fn outlook(py: Python<'_>, hand: &str, seen: &str, draws: usize, trials: u32, seed: u64) -> PyResult<String> {
    let odds = py
        .detach(|| of_notation(hand, seen, draws, trials, seed))
        .map_err(PyValueError::new_err)?;
    Ok(to_json(&odds, draws).to_string())
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(review, m)?)?;
    m.add_function(wrap_pyfunction!(outlook, m)?)
}
