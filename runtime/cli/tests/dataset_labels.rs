//! `rinshan dataset --search`: the look-ahead labels the rows of self-play games. In games of
//! `defensive` (the look-ahead's base agent) its label is the move played wherever it looked at
//! nothing, and a move it valued wherever it did.

mod common;

use std::path::Path;

use common::{json, rinshan};

fn read<T: npyz::Deserialize>(path: &Path) -> (Vec<u64>, Vec<T>) {
    let bytes = std::fs::read(path).expect("the array");
    let npy = npyz::NpyFile::new(&bytes[..]).expect("a .npy file");
    let shape = npy.shape().to_vec();
    (shape, npy.into_vec().expect("its data"))
}

#[test]
fn the_look_ahead_labels_a_self_play_export() {
    let dir = std::env::temp_dir().join(format!("rinshan-dataset-labels-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (logs, out) = (dir.join("logs"), dir.join("ds"));
    let path = |p: &Path| p.to_str().expect("a UTF-8 path").to_string();
    let played = rinshan(&[
        "selfplay",
        "--agents",
        "defensive,defensive,defensive,defensive",
        "--mode",
        "east",
        "--games",
        "2",
        "--batch",
        "2",
        "--export",
        &path(&logs),
        "--json",
    ]);
    json(&played);
    let spec = "search:rollouts=16:focus=all";
    let v = json(&rinshan(&[
        "dataset",
        &path(&logs),
        "-o",
        &path(&out),
        "--search",
        spec,
        "--observe",
        "none",
        "--json",
    ]));
    assert_eq!(v["games"].as_u64(), Some(2), "{v:#}");
    let manifest: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("manifest.json")).expect("a manifest")).expect("JSON");
    assert_eq!(manifest["options"]["search"].as_str(), Some(spec));
    let shard = out.join(manifest["shards"][0]["name"].as_str().expect("a shard"));
    let (_, action) = read::<u8>(&shard.join("action.npy"));
    let (_, label) = read::<u8>(&shard.join("search_action.npy"));
    let (shape, value) = read::<f32>(&shard.join("search_value.npy"));
    let na = shape[1] as usize;
    assert_eq!((shape[0] as usize, label.len()), (action.len(), action.len()));
    let (mut valued, mut changed) = (0, 0);
    for (row, (&a, &l)) in action.iter().zip(&label).enumerate() {
        let values = &value[row * na..(row + 1) * na];
        if values.iter().all(|x| x.is_nan()) {
            assert_eq!(a, l, "row {row}: left to defensive, which played it");
        } else {
            valued += 1;
            changed += usize::from(a != l);
            assert!(!values[l as usize].is_nan(), "row {row}");
        }
    }
    assert!(valued > 20, "{valued} rows valued of {}", action.len());
    assert!(changed < valued, "{changed} of {valued}");
    let bad = rinshan(&[
        "dataset",
        &path(&logs),
        "-o",
        &path(&dir.join("bad")),
        "--search",
        "search:margin=x",
    ]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--search search:margin=x"));
    let _ = std::fs::remove_dir_all(&dir);
}
