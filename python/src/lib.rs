//! `rinshan._core`: the Rust side of the `rinshan` Python package (python/rinshan wraps it).

use pyo3::prelude::*;

mod analysis;
mod dataset;
mod env;
mod mjai;
mod net;
mod opponents;
mod tools;

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // The workspace's version, the one `rinshan --version` prints: declared once in Cargo.toml.
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<env::PyEnv>()?;
    m.add_class::<mjai::PyMjaiPlayer>()?;
    tools::register(m)?;
    analysis::register(m)?;
    net::register(m)?;
    dataset::register(m)
}
