//! `_core.MjaiPlayer`: rinshan's MJAI player (rinshan-logs' `mjai::player`) for a Python policy,
//! which `rinshan.mjai.Bot` wraps.

use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rinshan_engine::observe::Form;
use rinshan_engine::Variant;
use rinshan_logs::mjai::bot::Dialect;
use rinshan_logs::mjai::player::Player;

use crate::env::{expand_bits, form_of};

/// One seat's MJAI game: lines from the host in, reaction lines out, a Python callable deciding.
#[pyclass(name = "MjaiPlayer", module = "rinshan._core")]
pub(crate) struct PyMjaiPlayer {
    player: Player,
    forms: Vec<Form>,
}

#[pymethods]
impl PyMjaiPlayer {
    #[new]
    #[pyo3(signature = (seat, forms))]
    fn new(seat: Option<u8>, forms: Vec<String>) -> PyResult<PyMjaiPlayer> {
        if seat.is_some_and(|s| s > 3) {
            return Err(PyValueError::new_err("the seat is 0, 1, 2 or 3"));
        }
        let forms = forms.iter().map(|f| form_of(f)).collect::<PyResult<Vec<Form>>>()?;
        if forms.contains(&Form::Oracle) {
            return Err(PyValueError::new_err(
                "a bot sees what its seat sees: the oracle is not one of its forms",
            ));
        }
        Ok(PyMjaiPlayer {
            player: Player::new(seat),
            forms,
        })
    }

    /// The seat, once known.
    #[getter]
    fn seat(&self) -> Option<u8> {
        self.player.seat()
    }

    /// Answers `line` in `dialect` ("app" or "stdio"): `(reply or None, messages)`. At a decision
    /// `decide(observation, legal_mask)` is called with the raw record of each form and the mask
    /// as a bool array; its action id is turned into the reaction. A failing `decide` is one of
    /// the messages, and the bot answers with a legal fallback.
    fn respond(
        &mut self,
        py: Python<'_>,
        line: &str,
        dialect: &str,
        decide: Bound<'_, PyAny>,
    ) -> PyResult<(Option<String>, Vec<String>)> {
        let dialect: Dialect = dialect.parse().map_err(PyValueError::new_err)?;
        let na = rinshan_engine::env::action_names(Variant::Red).len();
        let forms = self.forms.clone();
        let mut decide_state = |s: &rinshan_engine::generated::kernel::GameState| -> Result<u32, String> {
            let obs = PyDict::new(py);
            for &form in &forms {
                let raw = rinshan_engine::observe::record(Variant::Red, form, s, 4);
                obs.set_item(form.name(), PyArray1::from_vec(py, raw))
                    .map_err(|e| e.to_string())?;
            }
            let mut mask = vec![false; na];
            expand_bits(&s.mask, &mut mask);
            let action = decide
                .call1((obs, PyArray1::from_vec(py, mask)))
                .and_then(|a| a.extract::<u32>())
                .map_err(|e| format!("the policy failed: {e}"))?;
            Ok(action)
        };
        let mut messages = Vec::new();
        let reply = self
            .player
            .respond(line, dialect, &mut decide_state, &mut |m| messages.push(m));
        Ok((reply, messages))
    }
}
