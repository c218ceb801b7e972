//! The generated WGSL of every variant: validated by naga and pinned by insta snapshots, so a
//! change to the kernels, the specs or the translator shows up as a reviewed diff.

use rinshan::Variant;

/// The module without its first line, which names absolute source paths.
fn body(wgsl: &str) -> &str {
    wgsl.split_once('\n').map_or("", |(_, rest)| rest)
}

fn wgsl(variant: Variant) -> &'static str {
    match variant {
        Variant::Red => rinshan::generated::red::WGSL,
        Variant::NoRed => rinshan::generated::no_red::WGSL,
    }
}

#[test]
fn every_variant_module_validates_with_naga() {
    for &v in Variant::ALL {
        let module = rinshan_shaders_gen::validate(wgsl(v)).unwrap_or_else(|e| panic!("{v}: {e}"));
        let entries: Vec<&str> = module.entry_points.iter().map(|e| e.name.as_str()).collect();
        let expected: Vec<&str> = rinshan::entries::ENTRIES
            .iter()
            .chain(rinshan::entries::UPDATE_ENTRIES.iter())
            .map(|e| e.0)
            .collect();
        assert_eq!(entries, expected, "{v}");
    }
}

#[test]
fn red_wgsl_snapshot() {
    insta::assert_snapshot!("red_wgsl", body(wgsl(Variant::Red)));
}

#[test]
fn no_red_wgsl_snapshot() {
    insta::assert_snapshot!("no_red_wgsl", body(wgsl(Variant::NoRed)));
}
