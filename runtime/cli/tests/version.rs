//! `rinshan --version` prints the workspace's version, the one Python's `rinshan.__version__` gives
//! (python/tests/test_api.py): declared once, in the workspace's Cargo.toml.

#[test]
fn version_is_the_workspace_version() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .arg("--version")
        .output()
        .expect("run rinshan --version");
    assert!(out.status.success());
    let cargo = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../Cargo.toml")).expect("Cargo.toml");
    let section = cargo.split("[workspace.package]").nth(1).expect("[workspace.package]");
    let version = section
        .lines()
        .find_map(|l| l.strip_prefix("version = \""))
        .and_then(|v| v.strip_suffix('"'))
        .expect("the workspace's version");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).trim(),
        format!("rinshan {version}")
    );
}
