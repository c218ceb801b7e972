//! `rinshan dataset` tells the games it left out as copies of earlier logs: tests/data/mjlog holds
//! each Tenhou game as mjlog XML and as tenhou.net/6 JSON, and a dataset of the folder holds each
//! game's rows once.

mod common;

use common::rinshan;

#[test]
fn the_summary_lists_each_game_left_out_as_a_duplicate() {
    let logs = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjlog");
    let out_dir = std::env::temp_dir().join(format!("rinshan-dataset-dups-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out_dir);
    let out_text = out_dir.join("text");
    let out_json = out_dir.join("json");
    let path = |p: &std::path::Path| p.to_str().expect("a UTF-8 path").to_string();

    let out = rinshan(&["dataset", logs, "-o", &path(&out_json), "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert_eq!(
        (v["inputs"].as_u64(), v["games"].as_u64()),
        (Some(13), Some(6)),
        "{v:#}"
    );
    let dups = v["duplicates"].as_array().expect("duplicates");
    assert_eq!(dups.len(), 6, "{v:#}");
    for d in dups {
        let (input, same) = (d["input"].as_str().unwrap_or(""), d["same_as"].as_str().unwrap_or(""));
        assert_eq!(input.strip_suffix(".xml"), same.strip_suffix(".json"), "{d}");
    }
    // Duplicates are not among the logs skipped for a reason of their own.
    assert_eq!(v["skipped"].as_array().map(Vec::len), Some(1), "{v:#}");

    let out = rinshan(&["dataset", logs, "-o", &path(&out_text), "--quiet"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("6 logs left out as the same game"), "{text}");
    let _ = std::fs::remove_dir_all(&out_dir);
}
