//! A trained net's file (`examples/train/export.py`) run by the Rust side, as the `net:PATH`
//! agents run it: for checking it against PyTorch on the same inputs, and for playing it from
//! Python without PyTorch.

use numpy::{PyArray2, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use rinshan_net::inputs::Inputs;
use rinshan_net::Net;

/// A trained net's file (examples/train/export.py), run as `net:PATH` runs it: `Net(path)` reads
/// and checks it (ValueError with the reason if it cannot be played); `logits(rows, scalars,
/// mask)` gives its masked logits over `actions`.
#[pyclass(name = "Net", module = "rinshan._core", frozen)]
pub(crate) struct PyNet {
    net: Net,
}

fn values<'a, T: numpy::Element, D: numpy::ndarray::Dimension>(
    name: &str,
    a: &'a numpy::PyReadonlyArray<'_, T, D>,
) -> PyResult<&'a [T]> {
    a.as_slice()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e} (pass a C-contiguous array)")))
}

#[pymethods]
impl PyNet {
    #[new]
    fn new(path: &str) -> PyResult<PyNet> {
        Net::load(path)
            .map(|net| PyNet { net })
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The action names the logits are indexed by.
    #[getter]
    fn actions(&self) -> Vec<String> {
        self.net.actions.clone()
    }

    /// The analysis fields the net reads as rows under the planes.
    #[getter]
    fn analysis(&self) -> Vec<&'static str> {
        self.net.analysis.clone()
    }

    /// Masked logits (B, actions) float32 of `rows` (B, rows, 34) uint8 (the planes, then the
    /// analysis rows), `scalars` (B, scalars) int16 and `mask` (B, actions) bool.
    fn logits<'py>(
        &self,
        py: Python<'py>,
        rows: PyReadonlyArray3<'py, u8>,
        scalars: PyReadonlyArray2<'py, i16>,
        mask: PyReadonlyArray2<'py, bool>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let n = rows.shape()[0];
        let actions = self.net.actions.len();
        if scalars.shape()[0] != n || mask.shape() != [n, actions] {
            return Err(PyValueError::new_err(format!(
                "rows has {n} decisions, scalars {} and mask {:?}: give one row of each per decision, and {actions} mask columns",
                scalars.shape()[0],
                mask.shape()
            )));
        }
        let (r, s, m) = (
            values("rows", &rows)?,
            values("scalars", &scalars)?,
            values("mask", &mask)?,
        );
        let mut inputs = Inputs::new(self.net.analysis.len(), actions);
        let per_rows = r.len().checked_div(n).unwrap_or(0);
        let per_scalars = s.len().checked_div(n).unwrap_or(0);
        for i in 0..n {
            let row: Vec<f32> = r[i * per_rows..(i + 1) * per_rows]
                .iter()
                .map(|&v| f32::from(v))
                .collect();
            let sc: Vec<f32> = s[i * per_scalars..(i + 1) * per_scalars]
                .iter()
                .map(|&v| f32::from(v))
                .collect();
            let legal = &m[i * actions..(i + 1) * actions];
            inputs
                .push(&row, &sc, |a| legal[a])
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
        }
        let out = py
            .detach(|| self.net.logits(&inputs))
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        PyArray2::from_vec2(py, &out.chunks(actions.max(1)).map(<[f32]>::to_vec).collect::<Vec<_>>())
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyNet>()
}
