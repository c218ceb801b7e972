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

/// Whether the GPU tests of the agents' pipelines (their actions, hero mode) run here: on a hardware
/// adapter and on Mesa's lavapipe from 25.0 on. Older lavapipe takes over 16 minutes of one core to
/// compile the agents' pipeline (25.0: about half a minute, docs/performance.md); there they skip with a
/// note, or fail where `RINSHAN_REQUIRE_GPU=1` says every GPU test must run.
pub fn agent_gpu_tests_run(gpu: &rinshan_engine::gpu::Gpu, test: &str) -> bool {
    let driver = gpu.driver_info();
    if !gpu.is_software() || mesa_major(driver).is_none_or(|major| major >= 25) {
        return true;
    }
    let why = format!(
        "{test}: the software adapter {} ({driver}) takes over 16 minutes to compile the agents' pipeline; \
         Mesa 25 takes half a minute (Debian 12: apt-get install -t bookworm-backports mesa-vulkan-drivers)",
        gpu.adapter()
    );
    if std::env::var("RINSHAN_REQUIRE_GPU").is_ok_and(|v| v == "1") {
        panic!("{why}");
    }
    eprintln!("{why}: skipped");
    false
}

/// The GPU backend for a test of the agents' pipelines: `None` (with a note) where
/// [`gpu_or_skip`] finds no adapter or [`agent_gpu_tests_run`] says they do not run here.
pub fn agent_gpu_or_skip(test: &str) -> Option<rinshan_engine::gpu::Gpu> {
    gpu_or_skip(test).filter(|gpu| agent_gpu_tests_run(gpu, test))
}

/// The major version in a driver line such as `Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)`.
fn mesa_major(driver: &str) -> Option<u32> {
    let rest = &driver[driver.find("Mesa ")? + "Mesa ".len()..];
    rest.split('.').next()?.parse().ok()
}

#[cfg(test)]
mod tests {
    #[test]
    fn mesa_major_reads_the_driver_line() {
        assert_eq!(super::mesa_major("Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"), Some(25));
        assert_eq!(super::mesa_major("Mesa 22.3.6 (LLVM 15.0.6)"), Some(22));
        assert_eq!(super::mesa_major("580.159.04"), None);
        assert_eq!(super::mesa_major(""), None);
    }
}
