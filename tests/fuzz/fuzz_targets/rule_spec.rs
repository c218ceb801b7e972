//! A rule spec as a user edits it: a variant file, the yaku file or a kernel file, through the
//! rules compiler (checker, Rust emitter) and the WGSL translator. A located error, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rinshan_shaders_gen::Source;

const RED: &str = include_str!("../../../rules/variants/red.toml");
const YAKU: &str = include_str!("../../../rules/yaku.toml");
const FEATURES: &str = include_str!("../../../rules/kernel/features.rs");
const GAME_RNG: &str = include_str!("../../../rules/kernel/game_rng.rs");
const TILES: &str = include_str!("../../../rules/kernel/tiles.rs");

fuzz_target!(|data: &[u8]| {
    let Some((&which, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else { return };
    match which % 3 {
        // The variant file.
        0 => {
            if let Ok(spec) = rinshan_codegen::load_sources(
                ("rules/variants/red.toml", text),
                ("rules/yaku.toml", YAKU),
                ("rules/kernel/features.rs", FEATURES),
            ) {
                let _ = rinshan_codegen::generate(&spec);
            }
        }
        // The yaku file.
        1 => {
            if let Ok(spec) = rinshan_codegen::load_sources(
                ("rules/variants/red.toml", RED),
                ("rules/yaku.toml", text),
                ("rules/kernel/features.rs", FEATURES),
            ) {
                let _ = rinshan_codegen::generate(&spec);
            }
        }
        // A kernel file beside two real ones, through the translator (and naga's validation).
        _ => {
            let sources = [
                Source {
                    path: "rules/kernel/tiles.rs".into(),
                    text: TILES.into(),
                },
                Source {
                    path: "rules/kernel/game_rng.rs".into(),
                    text: GAME_RNG.into(),
                },
                Source {
                    path: "rules/kernel/fuzz.rs".into(),
                    text: text.into(),
                },
            ];
            let _ = rinshan_shaders_gen::translate(&sources, &[]);
        }
    }
});
