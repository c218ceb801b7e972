//! Runs the rules compiler: `rules/` -> tables, kernel-subset Rust and WGSL in OUT_DIR.
//! A malformed spec or kernel fails the build with file:line:col.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::exit;

use rinshan_shaders_gen::Source;

include!("src/entries.rs");

fn fail(message: impl std::fmt::Display) -> ! {
    eprintln!("error: {message}");
    exit(1);
}

fn write(path: &Path, text: impl AsRef<[u8]>) {
    if let Err(e) = std::fs::write(path, text) {
        fail(format!("cannot write {}: {e}", path.display()));
    }
}

fn kernel_sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut paths: Vec<PathBuf> = match std::fs::read_dir(dir) {
        Ok(entries) => entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "rs"))
            .collect(),
        Err(e) => fail(format!("cannot read {}: {e}", dir.display())),
    };
    paths.sort();
    paths
        .into_iter()
        .map(|p| match std::fs::read_to_string(&p) {
            Ok(text) => (p, text),
            Err(e) => fail(format!("cannot read {}: {e}", p.display())),
        })
        .collect()
}

fn camel(name: &str) -> String {
    name.split(['_', '-'])
        .map(|w| {
            let mut c = w.chars();
            c.next()
                .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
                .unwrap_or_default()
        })
        .collect()
}

fn main() {
    let manifest =
        PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| fail("CARGO_MANIFEST_DIR unset")));
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_else(|_| fail("OUT_DIR unset")));
    let rules = manifest.join("..").join("rules");
    println!("cargo:rerun-if-changed={}", rules.display());
    for sub in ["variants", "kernel"] {
        println!("cargo:rerun-if-changed={}", rules.join(sub).display());
    }
    println!("cargo:rerun-if-changed={}", rules.join("yaku.toml").display());

    let tables = rinshan_codegen::tables::build();
    write(&out.join("tables.bin"), tables.to_le_bytes());
    let table_consts = tables.kernel_consts();
    write(&out.join("table_consts.rs"), &table_consts);

    let kernel = kernel_sources(&rules.join("kernel"));
    for (path, _) in &kernel {
        println!("cargo:rerun-if-changed={}", path.display());
    }
    let variants = rinshan_codegen::variant_names(&rules);
    if variants.is_empty() {
        fail(format!("no variant specs in {}", rules.join("variants").display()));
    }

    let mut modules = String::new();
    for variant in &variants {
        let spec = match rinshan_codegen::load(&rules, variant) {
            Ok(spec) => spec,
            Err(diags) => {
                for d in &diags {
                    eprintln!("{d}");
                }
                fail(format!("the spec of variant `{variant}` has {} error(s)", diags.len()));
            }
        };
        let generated = rinshan_codegen::generate(&spec);
        let consts_file = out.join(format!("{variant}_consts.rs"));
        write(&consts_file, &generated.kernel_rust);
        write(&out.join(format!("{variant}_host.rs")), &generated.host_rust);

        let mut sources = vec![
            Source {
                path: consts_file.display().to_string(),
                text: generated.kernel_rust.clone(),
            },
            Source {
                path: out.join("table_consts.rs").display().to_string(),
                text: table_consts.clone(),
            },
        ];
        sources.extend(kernel.iter().map(|(p, t)| Source {
            path: p.display().to_string(),
            text: t.clone(),
        }));
        let entries = rinshan_shaders_gen::entry_points(&ENTRIES, &UPDATE_ENTRIES);
        let wgsl = match rinshan_shaders_gen::translate_entry_points(&sources, &entries) {
            Ok(w) => w,
            Err(e) => fail(e),
        };
        write(&out.join(format!("{variant}.wgsl")), &wgsl);

        let mut module = String::new();
        let _ = writeln!(module, "pub mod {variant} {{");
        let _ = writeln!(
            module,
            "    #![allow(dead_code, clippy::all, unused_parens, unused_variables)]"
        );
        let _ = writeln!(module, "    use crate::tables::table;");
        let _ = writeln!(
            module,
            "    include!(concat!(env!(\"OUT_DIR\"), \"/{variant}_consts.rs\"));"
        );
        let _ = writeln!(
            module,
            "    include!(concat!(env!(\"OUT_DIR\"), \"/table_consts.rs\"));"
        );
        for (path, _) in &kernel {
            let _ = writeln!(module, "    include!({:?});", path.display().to_string());
        }
        let mut io_types: Vec<&str> = ENTRIES
            .iter()
            .chain(UPDATE_ENTRIES.iter())
            .flat_map(|(_, _, input, output)| [*input, *output])
            .filter(|ty| !matches!(*ty, "u32" | "i32" | "f32"))
            .collect();
        io_types.sort_unstable();
        io_types.dedup();
        for ty in io_types {
            let _ = writeln!(module, "    unsafe impl bytemuck::Zeroable for {ty} {{}}");
            let _ = writeln!(module, "    unsafe impl bytemuck::Pod for {ty} {{}}");
        }
        let _ = writeln!(
            module,
            "    pub mod host {{ include!(concat!(env!(\"OUT_DIR\"), \"/{variant}_host.rs\")); }}"
        );
        let _ = writeln!(
            module,
            "    pub const WGSL: &str = include_str!(concat!(env!(\"OUT_DIR\"), \"/{variant}.wgsl\"));"
        );
        let _ = writeln!(module, "}}");
        modules.push_str(&module);
    }

    // The variant enum and a dispatch macro, so the host code is written once for every variant.
    let mut enum_src = String::from("#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]\npub enum Variant {\n");
    for v in &variants {
        let _ = writeln!(enum_src, "    {},", camel(v));
    }
    enum_src.push_str("}\nimpl Variant {\n    pub const ALL: &'static [Variant] = &[");
    for v in &variants {
        let _ = write!(enum_src, "Variant::{}, ", camel(v));
    }
    enum_src.push_str("];\n    /// The spec file stem, e.g. `no_red`.\n    pub fn name(self) -> &'static str {\n        match self {\n");
    for v in &variants {
        let _ = writeln!(enum_src, "            Variant::{} => {:?},", camel(v), v);
    }
    enum_src.push_str("        }\n    }\n}\n");
    modules.push_str(&enum_src);
    write(&out.join("generated.rs"), modules);

    // Included at the crate root before the modules that use it (textual macro scope).
    let mut dispatch = String::from("/// Runs `$body` with `$m` bound to the generated module of variant `$v`.\nmacro_rules! with_variant {\n    ($v:expr, $m:ident => $body:expr) => {\n        match $v {\n");
    for v in &variants {
        let _ = writeln!(
            dispatch,
            "            $crate::Variant::{} => {{ use $crate::generated::{v} as $m; $body }}",
            camel(v)
        );
    }
    dispatch.push_str("        }\n    };\n}\n");
    write(&out.join("dispatch.rs"), dispatch);
}
