//! Helpers for rinshan's test suite: where the test data lives, and a GPU that
//! skips politely on machines without one (unless `RINSHAN_REQUIRE_GPU=1`, as in CI).

use std::path::PathBuf;

pub mod policy;
pub mod scenario;

/// The WGSL entry points, from the file `runtime/build.rs` and the GPU backend read (the library
/// keeps it private).
pub mod entries {
    include!(concat!(env!("CARGO_MANIFEST_DIR"), "/../runtime/src/entries.rs"));
}

/// The test data the project carries (`tests/data`: Tenhou logs, shanten cases, scenarios).
pub fn test_data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data")
}

/// The GPU backend, or `None` (with a note on stderr) where no adapter exists and none is required.
pub fn gpu_or_skip(test: &str) -> Option<rinshan::gpu::Gpu> {
    match rinshan::gpu::Gpu::new() {
        Ok(g) => Some(g),
        Err(e) if std::env::var("RINSHAN_REQUIRE_GPU").is_ok_and(|v| v == "1") => {
            panic!("{test}: RINSHAN_REQUIRE_GPU=1 but {e}")
        }
        Err(e) => {
            eprintln!("{test}: skipped: {e}");
            None
        }
    }
}
