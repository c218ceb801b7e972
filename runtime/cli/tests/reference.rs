//! docs/cli.md is `rinshan reference`'s output (every subcommand and flag, from the clap
//! definitions), and `rinshan reference --man` is a man page: a renamed flag shows up in the guide.

use std::process::Command;

fn reference(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rinshan"))
        .arg("reference")
        .args(args)
        .output()
        .expect("run rinshan reference");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("UTF-8")
}

#[test]
fn the_guide_holds_the_generated_reference() {
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/cli.md")).expect("docs/cli.md");
    assert!(
        page == reference(&[]),
        "docs/cli.md differs from `rinshan reference`: regenerate it with\n  cargo run -- reference > docs/cli.md"
    );
}

#[test]
fn every_subcommand_and_a_man_page() {
    let page = reference(&[]);
    for sub in [
        "selfplay",
        "arena",
        "replay",
        "convert",
        "dataset",
        "mjai-bot",
        "serve",
        "bench env",
    ] {
        assert!(page.contains(&format!("## `rinshan {sub}`")), "{sub} missing");
    }
    assert!(page.contains("--max-fault-rate"), "a flag's help");
    let man = reference(&["--man"]);
    assert!(
        man.starts_with(".ie") || man.contains(".TH rinshan"),
        "{}",
        &man[..200.min(man.len())]
    );
    assert!(man.contains("selfplay"));
}
