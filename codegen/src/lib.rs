//! rinshan-codegen: `rules/` -> spec model -> checker -> emitters, plus the suit tables.
//!
//! Stages, each in its own module (the way naga splits front end, IR, validator and back ends):
//! * `diag`     — errors with file:line:col
//! * `model`    — the spec files as written (serde, with spans)
//! * `expr`     — the yaku condition language: parser, type checker, interpreter
//! * `check`    — semantic checks over the model (unknown features, duplicates, supersedes cycles,
//!   ranges, action layout, plain options typed by their values), producing the checked `spec`
//! * `option_rules` — options that mean nothing without another, as data
//! * `kernel_names` — the names the kernel code mentions, so an option it never reads is an error
//! * `spec`     — the checked spec the emitters read
//! * `emit_rust`— kernel-subset Rust (variant consts, yaku table, yaku conditions) and host-only metadata
//! * `tables`   — per-suit base-5 tables (shanten costs, decompositions) built from first principles
pub mod check;
pub mod diag;
pub mod emit_rust;
pub mod expr;
pub mod kernel_names;
pub mod model;
pub mod option_rules;
pub mod spec;
pub mod tables;

pub use diag::{render, Diagnostic};
pub use emit_rust::{generate, Generated};
pub use spec::Spec;

use std::path::{Path, PathBuf};

fn read(path: &Path) -> Result<String, Diagnostic> {
    std::fs::read_to_string(path).map_err(|e| Diagnostic {
        file: path.display().to_string(),
        line: 1,
        column: 1,
        message: format!("cannot read the file: {e}"),
    })
}

/// The spec files [`load`] reads for `variant`: the variant file, the yaku file and the features
/// file (a build script prints them as `cargo:rerun-if-changed`, with [`kernel_paths`]).
pub fn source_paths(rules_dir: &Path, variant: &str) -> [PathBuf; 3] {
    [
        rules_dir.join("variants").join(format!("{variant}.toml")),
        rules_dir.join("yaku.toml"),
        rules_dir.join("kernel").join("features.rs"),
    ]
}

/// `rules_dir/kernel/*.rs`, sorted: [`load`] reads them for the option constants the kernel names.
pub fn kernel_paths(rules_dir: &Path) -> Vec<PathBuf> {
    files_in(&rules_dir.join("kernel"), "rs")
}

/// The files of `dir` named `*.ext`, sorted; empty if the folder cannot be read.
fn files_in(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == ext))
        .collect();
    paths.sort();
    paths
}

/// Load, parse and check `rules/variants/<variant>.toml` + `rules/yaku.toml` +
/// `rules/kernel/features.rs` under `rules_dir`; every plain option must be named by some
/// `rules/kernel/*.rs`.
pub fn load(rules_dir: &Path, variant: &str) -> Result<Spec, Vec<Diagnostic>> {
    let paths = source_paths(rules_dir, variant);
    let mut texts = Vec::new();
    let mut errors = Vec::new();
    for p in &paths {
        match read(p) {
            Ok(t) => texts.push(t),
            Err(e) => errors.push(e),
        }
    }
    if !errors.is_empty() {
        if paths[0].exists() {
            return Err(errors);
        }
        let known = variant_names(rules_dir);
        errors[0].message = format!(
            "no variant `{variant}` (no file {}); the variants are: {}",
            paths[0].display(),
            known.join(", ")
        );
        return Err(errors);
    }
    let mut kernel = Vec::new();
    for p in kernel_paths(rules_dir) {
        kernel.push((p.display().to_string(), read(&p).map_err(|e| vec![e])?));
    }
    let kernel: Vec<(&str, &str)> = kernel.iter().map(|(p, t)| (p.as_str(), t.as_str())).collect();
    let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    load_sources_with_kernel(
        (&names[0], &texts[0]),
        (&names[1], &texts[1]),
        (&names[2], &texts[2]),
        &kernel,
    )
}

/// Same as [`load`] from in-memory sources, as (path used in diagnostics, text) pairs, but without
/// the kernel code: an option no kernel code names is not caught here. The variant name in the
/// file must equal the variant path's file stem.
pub fn load_sources(
    variant: (&str, &str),
    yaku: (&str, &str),
    features: (&str, &str),
) -> Result<Spec, Vec<Diagnostic>> {
    let features = check::parse_features(features.0, features.1)?;
    check::check(variant, yaku, features, None)
}

/// [`load_sources`] plus the kernel sources (path, text): every plain option's constant must be
/// named in them.
pub fn load_sources_with_kernel(
    variant: (&str, &str),
    yaku: (&str, &str),
    features: (&str, &str),
    kernel: &[(&str, &str)],
) -> Result<Spec, Vec<Diagnostic>> {
    let kernel_names = kernel_names::collect(kernel)?;
    let features = check::parse_features(features.0, features.1)?;
    check::check(variant, yaku, features, Some(&kernel_names))
}

/// File stems of `rules_dir/variants/*.toml`, sorted; empty if the folder cannot be read.
pub fn variant_names(rules_dir: &Path) -> Vec<String> {
    files_in(&rules_dir.join("variants"), "toml")
        .iter()
        .filter_map(|p| p.file_stem().and_then(|s| s.to_str()).map(String::from))
        .collect()
}
