//! The generated WGSL of every variant: validated by naga and pinned by insta snapshots, so a
//! change to the kernels, the specs or the translator shows up as a reviewed diff.

use rinshan_engine::Variant;

/// The module without its first line, which names absolute source paths.
fn body(wgsl: &str) -> &str {
    wgsl.split_once('\n').map_or("", |(_, rest)| rest)
}

fn wgsl(variant: Variant) -> &'static str {
    rinshan_engine::with_variant!(variant, v => v::WGSL)
}

#[test]
fn every_variant_module_validates_with_naga() {
    for &v in Variant::ALL {
        let module = rinshan_shaders_gen::validate(wgsl(v)).unwrap_or_else(|e| panic!("{v}: {e}"));
        let entries: Vec<&str> = module.entry_points.iter().map(|e| e.name.as_str()).collect();
        let expected: Vec<&str> = rinshan_tests::entries::ENTRIES
            .iter()
            .map(|e| e.0)
            .chain(rinshan_tests::entries::UPDATE_ENTRIES.iter().map(|e| e.0))
            .chain(rinshan_tests::entries::READ_ENTRIES.iter().map(|e| e.0))
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

#[test]
fn mjsoul_wgsl_snapshot() {
    insta::assert_snapshot!("mjsoul_wgsl", body(wgsl(Variant::Mjsoul)));
}

#[test]
fn mleague_wgsl_snapshot() {
    insta::assert_snapshot!("mleague_wgsl", body(wgsl(Variant::Mleague)));
}

#[test]
fn wrc_wgsl_snapshot() {
    insta::assert_snapshot!("wrc_wgsl", body(wgsl(Variant::Wrc)));
}

#[test]
fn sanma_wgsl_snapshot() {
    insta::assert_snapshot!("sanma_wgsl", body(wgsl(Variant::Sanma)));
}

#[test]
fn mjsoul_sanma_wgsl_snapshot() {
    insta::assert_snapshot!("mjsoul_sanma_wgsl", body(wgsl(Variant::MjsoulSanma)));
}

/// Size and member offsets of struct `name` in a WGSL module, as naga lays it out.
fn wgsl_layout(module: &naga::Module, name: &str) -> (u32, Vec<(String, u32)>) {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).expect("the module lays out");
    let inner = module
        .types
        .iter()
        .find(|(_, ty)| ty.name.as_deref() == Some(name))
        .map(|(_, ty)| &ty.inner)
        .unwrap_or_else(|| panic!("no struct {name}"));
    let naga::TypeInner::Struct { members, span } = inner else {
        panic!("{name} is not a struct");
    };
    let offsets = members
        .iter()
        .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
        .collect();
    (*span, offsets)
}

/// The host fills GPU buffers with the one Rust definition of each record (`generated::kernel`),
/// so every variant's WGSL must lay each record out the same way, at the Rust size.
#[test]
fn every_variant_lays_out_the_shared_records_alike_and_at_the_rust_size() {
    use rinshan_engine::generated::kernel as k;
    use std::mem::size_of;
    let rust_size = |name: &str| match name {
        "ShantenInput" => size_of::<k::ShantenInput>(),
        "ShantenOutput" => size_of::<k::ShantenOutput>(),
        "ScoreInput" => size_of::<k::ScoreInput>(),
        "ScoreOutput" => size_of::<k::ScoreOutput>(),
        "ResetInput" => size_of::<k::ResetInput>(),
        "GameState" => size_of::<k::GameState>(),
        "StepView" => size_of::<k::StepView>(),
        "DealInput" => size_of::<k::DealInput>(),
        other => panic!("a record this test does not know: {other}"),
    };
    let modules: Vec<naga::Module> = Variant::ALL
        .iter()
        .map(|&v| rinshan_shaders_gen::validate(wgsl(v)).unwrap_or_else(|e| panic!("{v}: {e}")))
        .collect();
    let mut records: Vec<&str> = rinshan_tests::entries::ENTRIES
        .iter()
        .flat_map(|e| [e.2, e.3])
        .chain(rinshan_tests::entries::UPDATE_ENTRIES.iter().flat_map(|e| [e.2, e.3]))
        .filter(|ty| !matches!(*ty, "u32" | "i32" | "f32"))
        .collect();
    records.sort_unstable();
    records.dedup();
    assert!(records.len() >= 8, "{records:?}");
    for name in records {
        let first = wgsl_layout(&modules[0], name);
        assert_eq!(first.0 as usize, rust_size(name), "{name}: WGSL size vs Rust size");
        for (module, v) in modules.iter().zip(Variant::ALL).skip(1) {
            assert_eq!(wgsl_layout(module, name), first, "{name}: {v} vs {}", Variant::ALL[0]);
        }
    }
}
