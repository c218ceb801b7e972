//! The module's functions: the hand calculator, Tenhou logs (records for supervised learning,
//! replay through the engine) and the tables that describe actions, yaku and observations.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rinshan_engine::env::Backend;
use rinshan_engine::observe::Form;
use rinshan_engine::win_input::{score_json, WinInput};
use rinshan_engine::Variant;
use rinshan_logs::tenhou;
use rinshan_search::{Options, Search};

use crate::env::{env_error, expand_bits, form_of, parse};

/// `{"shanten", "normal", "chiitoitsu", "kokushi"}` of a concealed hand in notation.
#[pyfunction]
fn shanten<'py>(py: Python<'py>, hand: &str) -> PyResult<Bound<'py, PyDict>> {
    let s = rinshan_engine::hand::shanten_of_notation(hand).map_err(PyValueError::new_err)?;
    let d = PyDict::new(py);
    d.set_item("shanten", s.shanten)?;
    d.set_item("normal", s.normal)?;
    d.set_item("chiitoitsu", s.chiitoitsu)?;
    d.set_item("kokushi", s.kokushi)?;
    Ok(d)
}

/// The score of a winning hand as JSON text (the fields of `rinshan score --json`).
#[pyfunction]
#[pyo3(signature = (variant, hand, win, flags, round_wind, seat_wind, dora, ura, melds, honba, sticks))]
#[allow(clippy::too_many_arguments)]
fn score(
    variant: &str,
    hand: String,
    win: String,
    flags: Vec<String>,
    round_wind: String,
    seat_wind: Option<String>,
    dora: Option<String>,
    ura: Option<String>,
    melds: Vec<String>,
    honba: u32,
    sticks: u32,
) -> PyResult<String> {
    let variant: Variant = parse("variant", variant)?;
    let mut input = WinInput {
        hand,
        win,
        round_wind,
        seat_wind,
        dora,
        ura,
        melds,
        honba,
        sticks,
        ..WinInput::default()
    };
    for flag in &flags {
        let f = match flag.as_str() {
            "tsumo" => &mut input.tsumo,
            "riichi" => &mut input.riichi,
            "double_riichi" => &mut input.double_riichi,
            "ippatsu" => &mut input.ippatsu,
            "haitei" => &mut input.haitei,
            "houtei" => &mut input.houtei,
            "rinshan" => &mut input.rinshan,
            "chankan" => &mut input.chankan,
            "tenhou" => &mut input.tenhou,
            "chiihou" => &mut input.chiihou,
            "dealer" => &mut input.dealer,
            other => return Err(PyValueError::new_err(format!("unknown flag `{other}`"))),
        };
        *f = true;
    }
    let win = input.win().map_err(|e| PyValueError::new_err(e.0))?;
    let s = rinshan_engine::hand::score(variant, &win).map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(score_json(&s).to_string())
}

fn read_game(path: &str) -> PyResult<tenhou::log::Game> {
    rinshan_logs::read_log(std::path::Path::new(path)).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A log's rounds as decision records: per round the deciding seat, the action id, what the log
/// says, the legal mask and each asked observation form's raw record of the deciding seat; with
/// `search` (`"search:rollouts=N:..."`), the look-ahead's action at each decision too.
#[pyfunction]
#[pyo3(signature = (path, forms, search=None))]
fn tenhou_read<'py>(
    py: Python<'py>,
    path: &str,
    forms: Vec<String>,
    search: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let game = read_game(path)?;
    let forms = forms.iter().map(|f| form_of(f)).collect::<PyResult<Vec<Form>>>()?;
    let search = search
        .map(|spec| spec.parse::<Options>().map(|o| Search::new(game.variant, o)))
        .transpose()
        .map_err(PyValueError::new_err)?;
    if forms.contains(&Form::Oracle) {
        return Err(PyValueError::new_err(
            "a log record holds what the deciding seat sees: the oracle is not one of its forms",
        ));
    }
    let variant = game.variant;
    let na = rinshan_engine::env::action_names(variant).len();
    let rounds = PyList::empty(py);
    for (r, round) in game.rounds.iter().enumerate() {
        let d = PyDict::new(py);
        d.set_item("kyoku", round.kyoku)?;
        d.set_item("honba", round.honba)?;
        d.set_item("sticks", round.sticks)?;
        d.set_item("scores", round.scores.to_vec())?;
        match tenhou::position::round_positions(&game, r) {
            Err(e) => d.set_item("error", e)?,
            Ok(positions) => {
                let n = positions.len();
                let seat: Vec<i8> = positions.iter().map(|p| p.seat as i8).collect();
                let action: Vec<i64> = positions.iter().map(|p| i64::from(p.action)).collect();
                let what: Vec<&str> = positions.iter().map(|p| p.what.as_str()).collect();
                let mut mask = vec![false; n * na];
                for (p, row) in positions.iter().zip(mask.chunks_mut(na)) {
                    expand_bits(&p.state.mask, row);
                }
                d.set_item("seat", PyArray1::from_vec(py, seat))?;
                d.set_item("action", PyArray1::from_vec(py, action))?;
                d.set_item("what", what)?;
                d.set_item("legal_action_mask", PyArray1::from_vec(py, mask).reshape([n, na])?)?;
                if let Some(search) = &search {
                    let chosen: Vec<i64> = py.detach(|| {
                        rinshan_dataset::label::look_ahead(search, variant, &positions, r)
                            .iter()
                            .map(|d| i64::from(d.action))
                            .collect()
                    });
                    d.set_item("search_action", PyArray1::from_vec(py, chosen))?;
                }
                let obs = PyDict::new(py);
                for &form in &forms {
                    let mut raw = Vec::with_capacity(n * form.bytes());
                    for p in &positions {
                        raw.extend(rinshan_engine::observe::record(variant, form, &p.state, p.seat));
                    }
                    obs.set_item(form.name(), PyArray1::from_vec(py, raw).reshape([n, form.bytes()])?)?;
                }
                d.set_item("observation", obs)?;
            }
        }
        rounds.append(d)?;
    }
    let out = PyDict::new(py);
    out.set_item("path", &game.path)?;
    out.set_item("rule", &game.rule)?;
    out.set_item("red_fives", game.red_fives)?;
    out.set_item("variant", game.variant.to_string())?;
    out.set_item("names", game.names.to_vec())?;
    out.set_item("rounds", rounds)?;
    Ok(out)
}

/// Replays logs (files or folders) through the engine: the agreement counts and mismatches.
#[pyfunction]
#[pyo3(signature = (paths, backend="cpu", variant=None))]
fn replay<'py>(
    py: Python<'py>,
    paths: Vec<String>,
    backend: &str,
    variant: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let backend: Backend = parse("backend", backend)?;
    let variant: Option<Variant> = variant.map(|v| parse("variant", v)).transpose()?;
    let paths: Vec<std::path::PathBuf> = paths.iter().map(std::path::PathBuf::from).collect();
    let files = tenhou::log::collect_files(&paths).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let read = |f: &std::path::PathBuf| -> Result<tenhou::log::Game, String> {
        let mut game = rinshan_logs::read_log(f).map_err(|e| e.to_string())?;
        if let Some(v) = variant {
            game.play_under(v)?;
        }
        Ok(game)
    };
    let games = files
        .iter()
        .map(|f| read(f).map_err(PyValueError::new_err))
        .collect::<PyResult<Vec<_>>>()?;
    let r = py
        .detach(|| tenhou::replay::replay(&games, backend))
        .map_err(env_error)?;
    let d = PyDict::new(py);
    let counts = [
        ("games", r.games),
        ("games_ended_right", r.games_ended_right),
        ("rounds", r.rounds),
        ("rounds_replayed", r.rounds_replayed),
        ("actions", r.actions),
        ("actions_accepted", r.actions_accepted),
        ("score_changes_matching", r.score_changes_matching),
        ("tables", r.tables),
        ("tables_matching", r.tables_matching),
        ("wins", r.wins),
        ("wins_matching", r.wins_matching),
        ("wins_yaku_not_logged", r.wins_yaku_not_logged),
        ("draws", r.draws),
        ("draws_matching", r.draws_matching),
    ];
    for (name, n) in counts {
        d.set_item(name, n)?;
    }
    d.set_item("all_agree", r.all_agree())?;
    d.set_item(
        "mismatches",
        r.mismatches.iter().map(ToString::to_string).collect::<Vec<_>>(),
    )?;
    Ok(d)
}

/// One field as Python sees it: name, byte offset, dtype name, shape, doc.
type FieldRow = (String, usize, String, Vec<usize>, String);

/// The record size and the fields of an observation form.
#[pyfunction]
fn fields(form: &str) -> PyResult<(usize, Vec<FieldRow>)> {
    let form = form_of(form)?;
    let fields = form
        .fields()
        .iter()
        .map(|f| {
            (
                f.name.to_string(),
                f.offset,
                f.dtype.name().to_string(),
                f.shape.to_vec(),
                f.doc.to_string(),
            )
        })
        .collect();
    Ok((form.bytes(), fields))
}

/// Where each planes row (0..64, in order) is in the packed form: ("bits", i) or ("counts", i).
#[pyfunction]
fn packed_rows() -> Vec<(&'static str, u32)> {
    (0..rinshan_engine::generated::kernel::PLANE_ROWS)
        .map(|row| match rinshan_engine::observe::packed_row(row) {
            rinshan_engine::observe::PackedRow::Bits(i) => ("bits", i),
            rinshan_engine::observe::PackedRow::Counts(i) => ("counts", i),
        })
        .collect()
}

/// A log of either format as the text of `to` (`tenhou` or `mjai`): the conversion `rinshan
/// convert` makes, for one game.
#[pyfunction]
fn convert_log(path: &str, to: &str) -> PyResult<String> {
    let format = match to {
        "tenhou" => rinshan_logs::Format::Tenhou,
        "mjai" => rinshan_logs::Format::Mjai,
        _ => return Err(PyValueError::new_err(format!("to={to:?}: give 'tenhou' or 'mjai'"))),
    };
    let game = read_game(path)?;
    rinshan_logs::file::game_text(&game, format).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The variant's action names by id, yaku names by id, starting points and seats (4, or 3).
#[pyfunction]
fn variant_info(variant: &str) -> PyResult<(Vec<String>, Vec<String>, u32, u32)> {
    let v: Variant = parse("variant", variant)?;
    Ok((
        rinshan_engine::env::action_names(v),
        rinshan_engine::env::yaku_names(v)
            .iter()
            .map(|s| s.to_string())
            .collect(),
        v.starting_points(),
        v.seats(),
    ))
}

/// Observation forms, agents, variants and modes by name.
#[pyfunction]
fn names() -> (Vec<&'static str>, Vec<&'static str>, Vec<String>, Vec<&'static str>) {
    (
        Form::ALL.map(Form::name).to_vec(),
        rinshan_engine::agents::Agent::ALL.map(|a| a.name()).to_vec(),
        Variant::ALL.iter().map(|v| v.to_string()).collect(),
        rinshan_engine::env::Mode::ALL.map(|m| m.name()).to_vec(),
    )
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(shanten, m)?)?;
    m.add_function(wrap_pyfunction!(score, m)?)?;
    m.add_function(wrap_pyfunction!(tenhou_read, m)?)?;
    m.add_function(wrap_pyfunction!(replay, m)?)?;
    m.add_function(wrap_pyfunction!(convert_log, m)?)?;
    m.add_function(wrap_pyfunction!(fields, m)?)?;
    m.add_function(wrap_pyfunction!(packed_rows, m)?)?;
    m.add_function(wrap_pyfunction!(variant_info, m)?)?;
    m.add_function(wrap_pyfunction!(names, m)?)?;
    m.add("STATE_CHECK_WORDS", rinshan_engine::env::CHECK_WORDS)?;
    Ok(())
}
