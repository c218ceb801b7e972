//! Shared helpers: the real spec sources, and loading them after a small textual edit.
#![allow(dead_code)] // each test binary uses a different subset

use rinshan_codegen::{Diagnostic, Spec};
use std::path::{Path, PathBuf};

pub const YAKU_PATH: &str = "rules/yaku.toml";
pub const FEATURES_PATH: &str = "rules/kernel/features.rs";

pub fn rules_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../rules")
}

pub fn variant_path(variant: &str) -> String {
    format!("rules/variants/{variant}.toml")
}

fn read(rel: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The real sources of a variant: (variant text, yaku text, features text).
pub fn sources(variant: &str) -> (String, String, String) {
    (read(&variant_path(variant)), read(YAKU_PATH), read(FEATURES_PATH))
}

/// Replaces exactly one occurrence of `from` (so an edit can never silently miss).
pub fn replace_once(text: &str, from: &str, to: &str) -> String {
    let n = text.matches(from).count();
    assert_eq!(n, 1, "`{from}` occurs {n} times");
    text.replacen(from, to, 1)
}

pub fn load_texts(variant: &str, v: &str, y: &str, f: &str) -> Result<Spec, Vec<Diagnostic>> {
    rinshan_codegen::load_sources((&variant_path(variant), v), (YAKU_PATH, y), (FEATURES_PATH, f))
}

/// The kernel sources as (path, text), for the check that the kernel reads every option.
pub fn kernel_sources() -> Vec<(String, String)> {
    rinshan_codegen::kernel_paths(&rules_dir())
        .into_iter()
        .map(|p| {
            let name = format!("rules/kernel/{}", p.file_name().unwrap().to_string_lossy());
            let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            (name, text)
        })
        .collect()
}

/// Loads `variant` after editing its variant file, checking it against the kernel sources.
pub fn load_variant_edit_with_kernel(variant: &str, from: &str, to: &str) -> Result<Spec, Vec<Diagnostic>> {
    let (v, y, f) = sources(variant);
    let kernel = kernel_sources();
    let kernel: Vec<(&str, &str)> = kernel.iter().map(|(p, t)| (p.as_str(), t.as_str())).collect();
    rinshan_codegen::load_sources_with_kernel(
        (&variant_path(variant), &replace_once(&v, from, to)),
        (YAKU_PATH, &y),
        (FEATURES_PATH, &f),
        &kernel,
    )
}

/// Loads `variant` after editing the yaku file.
pub fn load_yaku_edit(variant: &str, from: &str, to: &str) -> Result<Spec, Vec<Diagnostic>> {
    let (v, y, f) = sources(variant);
    load_texts(variant, &v, &replace_once(&y, from, to), &f)
}

/// Loads `variant` after editing its variant file.
pub fn load_variant_edit(variant: &str, from: &str, to: &str) -> Result<Spec, Vec<Diagnostic>> {
    let (v, y, f) = sources(variant);
    load_texts(variant, &replace_once(&v, from, to), &y, &f)
}

pub fn load_real(variant: &str) -> Spec {
    match rinshan_codegen::load(&rules_dir(), variant) {
        Ok(s) => s,
        Err(errors) => panic!("{}", render(&errors)),
    }
}

pub use rinshan_codegen::render;

/// The single error of a failed load.
pub fn single_error(result: Result<Spec, Vec<Diagnostic>>) -> Diagnostic {
    match result {
        Ok(_) => panic!("the edited spec was accepted"),
        Err(errors) => {
            assert_eq!(errors.len(), 1, "expected one error, got:\n{}", render(&errors));
            errors.into_iter().next().unwrap()
        }
    }
}

/// Line (1-based) of the first line of `text` containing `needle`.
pub fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("`{needle}` not found"))
        + 1
}

/// Generated items by name (consts and fns), as normalized token text, so tests can compare two
/// generated files item by item.
pub fn items(src: &str) -> std::collections::BTreeMap<String, String> {
    let file = syn::parse_file(src).unwrap_or_else(|e| panic!("generated code does not parse: {e}"));
    file.items
        .iter()
        .map(|item| {
            let name = match item {
                syn::Item::Const(c) => c.ident.to_string(),
                syn::Item::Fn(f) => f.sig.ident.to_string(),
                other => panic!("unexpected item {}", quote::quote!(#other)),
            };
            (name, quote::quote!(#item).to_string())
        })
        .collect()
}

/// The value of a `const NAME: [u32; N] = [..]` in generated code.
pub fn u32_array(src: &str, name: &str) -> Vec<u32> {
    let file = syn::parse_file(src).unwrap_or_else(|e| panic!("generated code does not parse: {e}"));
    for item in &file.items {
        if let syn::Item::Const(c) = item {
            if c.ident == name {
                let syn::Expr::Array(a) = &*c.expr else {
                    panic!("{name} is not an array")
                };
                return a
                    .elems
                    .iter()
                    .map(|e| match e {
                        syn::Expr::Lit(syn::ExprLit {
                            lit: syn::Lit::Int(i), ..
                        }) => i.base10_parse::<u32>().unwrap(),
                        other => panic!("{name}: non-literal {}", quote::quote!(#other)),
                    })
                    .collect();
            }
        }
    }
    panic!("no const {name}")
}

/// The value of a scalar `const NAME: u32 = ..;` in generated code, as written.
pub fn const_text(src: &str, name: &str) -> String {
    let file = syn::parse_file(src).unwrap_or_else(|e| panic!("generated code does not parse: {e}"));
    for item in &file.items {
        if let syn::Item::Const(c) = item {
            if c.ident == name {
                let e = &c.expr;
                return quote::quote!(#e).to_string();
            }
        }
    }
    panic!("no const {name}")
}
