//! Helpers for rinshan's test suite: where the test data lives, and a GPU that
//! skips politely on machines without one (unless `RINSHAN_REQUIRE_GPU=1`, as in CI).

use std::path::PathBuf;

pub mod policy;
pub mod scenario;

/// The WGSL entry points, from the file `runtime/engine/build.rs` and the GPU backend read (the library
/// keeps it private).
pub mod entries {
    include!(concat!(env!("CARGO_MANIFEST_DIR"), "/../runtime/engine/src/entries.rs"));
}

/// The test data the project carries (`tests/data`: Tenhou logs, shanten cases, scenarios).
pub fn test_data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data")
}

/// The GPU backend, or `None` (with a note on stderr) where no adapter exists and none is required.
pub fn gpu_or_skip(test: &str) -> Option<rinshan_engine::gpu::Gpu> {
    match rinshan_engine::gpu::Gpu::new() {
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

/// Whether GPU tests whose pipelines take a software adapter very long to compile run here: always
/// on a hardware adapter; on a software one (Mesa's lavapipe: the agents' pipelines take it more
/// than ten minutes on 2 cores) only with `RINSHAN_SLOW_GPU_TESTS=1`. Says so on stderr when not.
pub fn slow_gpu_tests_run(gpu: &rinshan_engine::gpu::Gpu, test: &str) -> bool {
    if !gpu.is_software() || std::env::var("RINSHAN_SLOW_GPU_TESTS").is_ok_and(|v| v == "1") {
        return true;
    }
    eprintln!(
        "{test}: skipped on the software adapter {} (set RINSHAN_SLOW_GPU_TESTS=1 to run it)",
        gpu.adapter()
    );
    false
}
