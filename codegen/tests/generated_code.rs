//! The generated kernel code stays inside the portable kernel subset, compiles without warnings,
//! and computes exactly what the interpreter says the spec means.

use crate::common::*;
use rinshan_codegen::expr::{eval, Type, Value};
use rinshan_codegen::{generate, Spec};
use syn::visit::Visit;

/// Rejects anything outside the subset the WGSL translator accepts for generated code.
#[derive(Default)]
struct Subset {
    errors: Vec<String>,
}

impl Subset {
    fn reject(&mut self, what: &str, node: &dyn quote::ToTokens) {
        self.errors.push(format!("{what}: {}", node.to_token_stream()));
    }
}

fn scalar_or_u32_array(ty: &syn::Type) -> bool {
    match ty {
        syn::Type::Path(p) => ["u32", "i32", "f32", "bool"].iter().any(|t| p.path.is_ident(t)),
        syn::Type::Array(a) => matches!(&*a.elem, syn::Type::Path(p) if p.path.is_ident("u32")),
        _ => false,
    }
}

impl<'ast> Visit<'ast> for Subset {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        match item {
            syn::Item::Const(c) => {
                if !scalar_or_u32_array(&c.ty) {
                    self.reject("const type", &c.ty);
                }
            }
            syn::Item::Fn(_) => {}
            other => self.reject("item", other),
        }
        syn::visit::visit_item(self, item);
    }

    fn visit_type_array(&mut self, a: &'ast syn::TypeArray) {
        // The length of an array type is a plain integer in both Rust and WGSL.
        self.visit_type(&a.elem);
    }

    fn visit_local(&mut self, local: &'ast syn::Local) {
        if !matches!(local.pat, syn::Pat::Type(_)) {
            self.reject("let without a type", local);
        }
        syn::visit::visit_local(self, local);
    }

    fn visit_expr(&mut self, e: &'ast syn::Expr) {
        use syn::Expr as E;
        match e {
            E::Binary(_)
            | E::Unary(_)
            | E::Paren(_)
            | E::Field(_)
            | E::Cast(_)
            | E::Index(_)
            | E::Array(_)
            | E::If(_)
            | E::Block(_)
            | E::Assign(_) => {}
            E::Lit(l) => match &l.lit {
                syn::Lit::Bool(_) => {}
                syn::Lit::Int(i) if !i.suffix().is_empty() => {}
                syn::Lit::Float(x) if !x.suffix().is_empty() => {}
                _ => self.reject("unsuffixed literal", e),
            },
            E::Path(p) if p.path.get_ident().is_some() => {}
            other => self.reject("expression", other),
        }
        syn::visit::visit_expr(self, e);
    }
}

fn assert_in_subset(spec: &Spec) {
    let g = generate(spec);
    let file = syn::parse_file(&g.kernel_rust).expect("generated kernel code parses");
    let mut v = Subset::default();
    v.visit_file(&file);
    assert!(
        v.errors.is_empty(),
        "{}: outside the kernel subset:\n{}",
        spec.variant.name,
        v.errors.join("\n")
    );
}

#[test]
fn kernel_code_stays_in_the_subset() {
    assert_in_subset(&load_real("red"));
    assert_in_subset(&load_real("no_red"));
}

/// A small deterministic generator (splitmix64) so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// Random feature assignments biased toward "true" and small counts, so that conditions with
/// five conjuncts still hold often enough to be checked both ways.
fn random_cases(spec: &Spec, n: usize) -> Vec<Vec<(String, Value)>> {
    let mut rng = Rng(0x5EED);
    (0..n)
        .map(|_| {
            spec.features
                .iter()
                .map(|f| {
                    let v = match f.ty {
                        Type::Bool => Value::Bool(rng.next() & 3 != 0),
                        Type::Int => Value::Int((rng.next() % 5) as i64),
                    };
                    (f.name.clone(), v)
                })
                .collect()
        })
        .collect()
}

fn expected_masks(spec: &Spec, case: &[(String, Value)]) -> [u32; 2] {
    let lookup = |name: &str| {
        case.iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| *v)
            .or_else(|| spec.option(name).map(Value::Bool))
            .unwrap_or_else(|| panic!("no value for {name}"))
    };
    let mut m = [0u32; 2];
    for y in &spec.yaku {
        if eval(&y.condition, &lookup).as_bool() {
            m[y.index / 32] |= 1 << (y.index % 32);
        }
    }
    m
}

/// Compiles the generated kernel code with rustc (warnings denied), runs `yaku_conditions` on
/// random features and compares every mask with the interpreter.
fn differential(spec: &Spec, tag: &str) {
    let g = generate(spec);
    let cases = random_cases(spec, 3000);
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("codegen-diff-{tag}"));
    std::fs::create_dir_all(&dir).unwrap();
    let (_, _, features) = sources("red");
    std::fs::write(dir.join("features.rs"), features).unwrap();
    std::fs::write(dir.join("kernel.rs"), &g.kernel_rust).unwrap();
    std::fs::write(dir.join("host.rs"), &g.host_rust).unwrap();
    let mut main = String::from(
        "#![deny(warnings)]\n#![allow(dead_code)]\ninclude!(\"features.rs\");\n\
         mod kernel { use super::Features; include!(\"kernel.rs\"); }\n\
         mod host { include!(\"host.rs\"); }\nuse kernel::yaku_conditions;\nfn main() {\n",
    );
    for case in &cases {
        let fields: Vec<String> = case
            .iter()
            .map(|(n, v)| match v {
                Value::Bool(b) => format!("{n}: {b}"),
                Value::Int(i) => format!("{n}: {i}"),
            })
            .collect();
        main.push_str(&format!(
            "    {{ let m = yaku_conditions(Features {{ {} }}); println!(\"{{}} {{}}\", m[0], m[1]); }}\n",
            fields.join(", ")
        ));
    }
    main.push_str("}\n");
    std::fs::write(dir.join("main.rs"), main).unwrap();
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = std::process::Command::new(&rustc)
        .current_dir(&dir)
        .args(["--edition", "2021", "-C", "opt-level=0", "-o", "diff", "main.rs"])
        .output()
        .expect("run rustc");
    assert!(
        out.status.success(),
        "generated code does not compile:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let run = std::process::Command::new(dir.join("diff"))
        .output()
        .expect("run the compiled kernel");
    assert!(run.status.success());
    let stdout = String::from_utf8(run.stdout).unwrap();
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), cases.len());
    let mut seen = vec![[false; 2]; spec.yaku.len()];
    for (case, line) in cases.iter().zip(lines) {
        let want = expected_masks(spec, case);
        assert_eq!(line, format!("{} {}", want[0], want[1]), "features: {case:?}");
        for y in &spec.yaku {
            seen[y.index][usize::from(want[y.index / 32] >> (y.index % 32) & 1 == 1)] = true;
        }
    }
    // Every condition was seen both holding and failing, so the comparison covered it.
    for y in &spec.yaku {
        assert_eq!(
            seen[y.index],
            [true, true],
            "{tag}: `{}` not exercised both ways",
            y.name
        );
    }
}

#[test]
fn compiled_conditions_match_the_interpreter_red() {
    differential(&load_real("red"), "red");
}

#[test]
fn compiled_conditions_match_the_interpreter_modified_no_red() {
    let (v, y, f) = sources("no_red");
    let v = replace_once(&v, "open_tanyao = true", "open_tanyao = false");
    let y = format!(
        "{y}\n[[yaku]]\nname = \"bonus\"\nhan_closed = 2\nhan_open = 1\n\
         when = \"kans + runs - 1 >= 2 && !(tsumo || dealer) && suits != 3\"\ndescription = \"test\"\n"
    );
    let spec = load_texts("no_red", &v, &y, &f).unwrap_or_else(|e| panic!("{}", render(&e)));
    assert_in_subset(&spec);
    differential(&spec, "no_red_modified");
}

/// A new option takes only its line in the variant file: it comes out as a typed constant, in
/// file order, and in the host's option list.
#[test]
fn a_new_option_needs_no_codegen_edit() {
    let (v, y, f) = sources("red");
    let v = replace_once(&v, "pao = true\n", "pao = true\nmy_new_rule = true\n");
    let v = replace_once(&v, "[actions]", "my_limit = 7\n\n[actions]");
    let spec = load_texts("red", &v, &y, &f).unwrap_or_else(|e| panic!("{}", render(&e)));
    let g = generate(&spec);
    assert!(
        g.kernel_rust.contains("pub const MY_NEW_RULE: bool = true;\n"),
        "{}",
        g.kernel_rust
    );
    assert!(
        g.kernel_rust.contains("pub const MY_LIMIT: u32 = 7u32;\n"),
        "{}",
        g.kernel_rust
    );
    assert!(
        g.host_rust.contains("(\"liability\", \"my_new_rule\", \"true\"),"),
        "{}",
        g.host_rust
    );
    assert!(
        g.host_rust.contains("(\"game\", \"my_limit\", \"7\"),"),
        "{}",
        g.host_rust
    );
    // Nothing else changes.
    let (before, after) = (items(&generate(&load_real("red")).kernel_rust), items(&g.kernel_rust));
    let added: Vec<&String> = after.keys().filter(|k| !before.contains_key(*k)).collect();
    assert_eq!(added, ["MY_LIMIT", "MY_NEW_RULE"]);
    assert!(before.iter().all(|(k, item)| after.get(k) == Some(item)));
    assert_in_subset(&spec);
}
