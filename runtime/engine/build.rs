//! Runs the rules compiler: `rules/` -> tables, kernel-subset Rust and WGSL in OUT_DIR.
//! A malformed spec or kernel fails the build with file:line:col, as cargo's own `error:` lines.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::exit;

use rinshan_shaders_gen::Source;

include!("src/entries.rs");

/// Fails the build with each line of `message` as a `cargo::error`, so cargo shows the located
/// message first and plainly (a script that exits non-zero would bury it under cargo's "failed to
/// run custom build command" and the script's whole output). Cargo fails the build on its own
/// after a script that printed an error.
fn fail(message: impl std::fmt::Display) -> ! {
    for line in message.to_string().lines() {
        println!("cargo::error={line}");
    }
    exit(0);
}

/// `file:line:col: message`, the file relative to the workspace root (`rules/yaku.toml`), as
/// the user who edits it knows it.
fn located(root: &Path, file: &str, line: usize, column: usize, message: &str) -> String {
    let file = Path::new(file);
    let file = file.strip_prefix(root).unwrap_or(file);
    format!("{}:{line}:{column}: {message}", file.display())
}

fn write(path: &Path, text: impl AsRef<[u8]>) {
    if let Err(e) = std::fs::write(path, text) {
        fail(format!("cannot write {}: {e}", path.display()));
    }
}

fn kernel_sources(rules: &Path) -> Vec<Source> {
    let paths = rinshan_codegen::kernel_paths(rules);
    if paths.is_empty() {
        fail(format!("no kernel sources in {}", rules.join("kernel").display()));
    }
    paths
        .into_iter()
        .map(|p| match std::fs::read_to_string(&p) {
            Ok(text) => Source {
                path: p.display().to_string(),
                text,
            },
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
    // The workspace root: this crate lives in runtime/engine.
    let root = manifest.join("../..");
    let rules = root.join("rules");
    println!("cargo:rerun-if-changed={}", rules.display());
    for sub in ["variants", "kernel"] {
        println!("cargo:rerun-if-changed={}", rules.join(sub).display());
    }
    println!("cargo:rerun-if-changed={}", rules.join("yaku.toml").display());

    let tables = rinshan_codegen::tables::build();
    write(&out.join("tables.bin"), tables.to_le_bytes());
    let table_consts = tables.kernel_consts();
    write(&out.join("table_consts.rs"), &table_consts);

    let kernel = kernel_sources(&rules);
    for src in &kernel {
        println!("cargo:rerun-if-changed={}", src.path);
    }
    let variants = rinshan_codegen::variant_names(&rules);
    if variants.is_empty() {
        fail(format!("no variant specs in {}", rules.join("variants").display()));
    }

    let mut generated = Vec::new();
    for variant in &variants {
        let spec = match rinshan_codegen::load(&rules, variant) {
            Ok(spec) => spec,
            Err(diags) => {
                let lines: Vec<String> = diags
                    .iter()
                    .map(|d| located(&root, &d.file, d.line, d.column, &d.message))
                    .collect();
                fail(lines.join("\n"));
            }
        };
        let code = rinshan_codegen::generate(&spec);
        let consts_file = out.join(format!("{variant}_consts.rs"));
        write(&consts_file, &code.kernel_rust);
        write(&out.join(format!("{variant}_host.rs")), &code.host_rust);
        generated.push(Source {
            path: consts_file.display().to_string(),
            text: code.kernel_rust,
        });
    }
    let shared = match rinshan_shaders_gen::shared_files(&kernel, &generated) {
        Ok(s) => s,
        Err(e) => fail(located(&root, &e.file, e.line, e.column, &e.message)),
    };

    // One `kernel` module holds what every variant shares (the state and I/O structs, their
    // constants, the code that names no variant constant); each variant's module inside it adds
    // its constants and the rest of the kernel. Host code names shared things `kernel::X`, so no
    // host code reaches into one variant's module to mean any variant.
    let include = |module: &mut String, path: &Path| {
        let _ = writeln!(module, "    include!({:?});", path.display().to_string());
    };
    let mut modules = String::from("pub mod kernel {\n");
    modules.push_str("    #![allow(dead_code, clippy::all, unused_parens, unused_variables)]\n");
    modules.push_str("    use crate::tables::table;\n");
    include(&mut modules, &out.join("table_consts.rs"));
    for (src, &is_shared) in kernel.iter().zip(&shared) {
        if is_shared {
            include(&mut modules, Path::new(&src.path));
        }
    }
    let mut io_types: Vec<&str> = ENTRIES
        .iter()
        .flat_map(|(_, _, input, output)| [*input, *output])
        .chain(UPDATE_ENTRIES.iter().flat_map(|(_, _, state, arg, _)| [*state, *arg]))
        .chain(
            READ_ENTRIES
                .iter()
                .flat_map(|(_, _, state, arg, out)| [*state, *arg, *out]),
        )
        .filter(|ty| !matches!(*ty, "u32" | "i32" | "f32"))
        .collect();
    io_types.sort_unstable();
    io_types.dedup();
    for ty in io_types {
        let _ = writeln!(modules, "    unsafe impl bytemuck::Zeroable for {ty} {{}}");
        let _ = writeln!(modules, "    unsafe impl bytemuck::Pod for {ty} {{}}");
    }

    for (variant, consts) in variants.iter().zip(&generated) {
        let mut sources = vec![
            consts.clone(),
            Source {
                path: out.join("table_consts.rs").display().to_string(),
                text: table_consts.clone(),
            },
        ];
        sources.extend(kernel.iter().cloned());
        let entries = rinshan_shaders_gen::entry_points(&ENTRIES, &UPDATE_ENTRIES, &READ_ENTRIES);
        let wgsl = match rinshan_shaders_gen::translate_entry_points(&sources, &entries) {
            Ok(w) => w,
            Err(e) => fail(located(&root, &e.file, e.line, e.column, &e.message)),
        };
        write(&out.join(format!("{variant}.wgsl")), &wgsl);

        let _ = writeln!(modules, "    pub mod {variant} {{");
        let _ = writeln!(
            modules,
            "    #![allow(dead_code, clippy::all, unused_parens, unused_variables)]"
        );
        let _ = writeln!(modules, "    use super::*;");
        include(&mut modules, Path::new(&consts.path));
        for (src, &is_shared) in kernel.iter().zip(&shared) {
            if !is_shared {
                include(&mut modules, Path::new(&src.path));
            }
        }
        let _ = writeln!(
            modules,
            "    pub mod host {{ include!(concat!(env!(\"OUT_DIR\"), \"/{variant}_host.rs\")); }}"
        );
        let _ = writeln!(
            modules,
            "    pub const WGSL: &str = include_str!(concat!(env!(\"OUT_DIR\"), \"/{variant}.wgsl\"));"
        );
        let _ = writeln!(modules, "    }}");
    }
    modules.push_str("}\n");
    let _ = writeln!(modules, "pub use kernel::{{{}}};", variants.join(", "));

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
    let mut dispatch = String::from("/// Runs `$body` with `$m` bound to the generated module of variant `$v` (exported: the\n/// crates that play the kernels directly, as the soak, dispatch on the variant the same way).\n#[macro_export]\nmacro_rules! with_variant {\n    ($v:expr, $m:ident => $body:expr) => {\n        match $v {\n");
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
