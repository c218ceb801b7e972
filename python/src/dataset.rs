//! Training data from logs: building a dataset folder (`rinshan dataset`), and a log's rows
//! straight into numpy arrays without one.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rinshan_dataset::inputs::{for_each_unit, sources, Source};
use rinshan_dataset::manifest::check_forms;
use rinshan_dataset::record::{record_units, Outcome};
use rinshan_dataset::{build, Build, Options, Seats};
use rinshan_engine::env::action_names;
use rinshan_engine::observe::Form;

use crate::env::{form_of, parse};

fn options(
    variant: &str,
    forms: Vec<String>,
    seats: Option<Vec<u8>>,
    players: Option<Vec<String>>,
    forced: bool,
    search: Option<String>,
) -> PyResult<Options> {
    let forms = forms.iter().map(|f| form_of(f)).collect::<PyResult<Vec<Form>>>()?;
    check_forms(&forms).map_err(PyValueError::new_err)?;
    let seats = Seats::chosen(seats.as_deref(), players.as_deref()).map_err(PyValueError::new_err)?;
    let options = Options {
        variant: parse("variant", variant)?,
        forms,
        seats,
        forced,
        search,
    };
    options.look_ahead().map_err(PyValueError::new_err)?;
    Ok(options)
}

/// Builds (or resumes) a dataset folder; the summary as a dict.
#[pyfunction]
#[pyo3(signature = (inputs, out, forms, seats=None, players=None, forced=false, shard_size=None, threads=None, variant="red", search=None))]
#[allow(clippy::too_many_arguments)]
fn dataset_build<'py>(
    py: Python<'py>,
    inputs: Vec<String>,
    out: String,
    forms: Vec<String>,
    seats: Option<Vec<u8>>,
    players: Option<Vec<String>>,
    forced: bool,
    shard_size: Option<usize>,
    threads: Option<usize>,
    variant: &str,
    search: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let b = Build {
        inputs,
        out: out.into(),
        options: options(variant, forms, seats, players, forced, search)?,
        inputs_per_shard: shard_size.unwrap_or(rinshan_dataset::DEFAULT_INPUTS_PER_SHARD),
        threads: threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
    };
    let s = py.detach(|| build(&b, &mut |_| {})).map_err(PyValueError::new_err)?;
    let d = PyDict::new(py);
    d.set_item("shards_written", s.shards_written)?;
    d.set_item("shards_resumed", s.shards_resumed)?;
    d.set_item("inputs", s.inputs)?;
    d.set_item("games", s.games)?;
    d.set_item("rows", s.rows)?;
    d.set_item("total_rows", s.total_rows)?;
    let skipped: Vec<(String, String)> = s.skipped.into_iter().map(|k| (k.input, k.reason)).collect();
    d.set_item("skipped", skipped)?;
    let duplicates: Vec<(String, String)> = s.duplicates.into_iter().map(|k| (k.input, k.same_as)).collect();
    d.set_item("duplicates", duplicates)?;
    d.set_item("seconds", s.seconds)?;
    Ok(d)
}

/// The logs and archives `inputs` name, in the order a build visits them (folders walked,
/// globs expanded): `(path, is_archive)` each.
#[pyfunction]
fn dataset_sources(py: Python<'_>, inputs: Vec<String>) -> PyResult<Vec<(String, bool)>> {
    let found = py.detach(|| sources(&inputs)).map_err(PyValueError::new_err)?;
    Ok(found
        .into_iter()
        .map(|s| match s {
            Source::File(p) => (p.display().to_string(), false),
            Source::Tar(p) => (p.display().to_string(), true),
        })
        .collect())
}

/// Every log of `inputs` replayed into rows: one dict per log, in order (`name`, and `skipped`
/// with the reason or the arrays).
#[pyfunction]
#[pyo3(signature = (inputs, forms, seats=None, players=None, forced=false, variant="red", search=None))]
#[allow(clippy::too_many_arguments)]
fn dataset_records<'py>(
    py: Python<'py>,
    inputs: Vec<String>,
    forms: Vec<String>,
    seats: Option<Vec<u8>>,
    players: Option<Vec<String>>,
    forced: bool,
    variant: &str,
    search: Option<String>,
) -> PyResult<Bound<'py, PyList>> {
    let options = options(variant, forms, seats, players, forced, search)?;
    let work = || -> Result<(Vec<String>, Vec<Outcome>), String> {
        let mut units = Vec::new();
        for_each_unit(&sources(&inputs)?, &mut |unit| {
            units.push(unit);
            Ok(())
        })?;
        let outcomes = record_units(&units, &options)?;
        Ok((units.into_iter().map(|u| u.name).collect(), outcomes))
    };
    let (names, outcomes) = py.detach(work).map_err(PyValueError::new_err)?;
    let na = action_names(options.variant).len();
    let list = PyList::empty(py);
    for (name, outcome) in names.into_iter().zip(outcomes) {
        let d = PyDict::new(py);
        d.set_item("name", name)?;
        match outcome {
            Outcome::Skipped(reason) => d.set_item("skipped", reason)?,
            Outcome::Rows(rows) => {
                let n = rows.rows();
                let obs = PyDict::new(py);
                for (form, raw) in options.forms.iter().zip(rows.observations) {
                    obs.set_item(form.name(), PyArray1::from_vec(py, raw).reshape([n, form.bytes()])?)?;
                }
                d.set_item("observation", obs)?;
                let mask: Vec<bool> = rows.mask.iter().map(|&b| b != 0).collect();
                d.set_item("legal_action_mask", PyArray1::from_vec(py, mask).reshape([n, na])?)?;
                d.set_item("action", PyArray1::from_vec(py, rows.action))?;
                d.set_item("seat", PyArray1::from_vec(py, rows.seat))?;
                d.set_item("round", PyArray1::from_vec(py, rows.round))?;
                if options.search.is_some() {
                    d.set_item("search_action", PyArray1::from_vec(py, rows.search_action))?;
                    let value = PyArray1::from_vec(py, rows.search_value).reshape([n, na])?;
                    d.set_item("search_value", value)?;
                }
                d.set_item("scores", rows.scores.to_vec())?;
                // As a list of ints (a Vec<u8> would become Python bytes).
                d.set_item("ranks", rows.ranks.map(u32::from).to_vec())?;
            }
        }
        list.append(d)?;
    }
    Ok(list)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(dataset_build, m)?)?;
    m.add_function(wrap_pyfunction!(dataset_records, m)?)?;
    m.add_function(wrap_pyfunction!(dataset_sources, m)?)?;
    Ok(())
}
