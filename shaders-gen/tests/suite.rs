//! The translator's tests in one binary (one link of wgpu for the crate instead of one per file).

mod gpu;
mod reject;
mod translate;
