//! Mapping Rust identifiers to WGSL identifiers.

/// WGSL keywords, reserved words (WGSL spec §15.3 "Reserved Words"), predeclared type
/// names, the builtins the translator emits, and the identifiers the generated entry points
/// use. A Rust identifier in this list gets a `_` suffix everywhere it is used, so
/// renaming stays consistent between declarations and uses.
const RESERVED: &[&str] = &[
    // keywords
    "alias", "break", "case", "const", "const_assert", "continue", "continuing", "default",
    "diagnostic", "discard", "else", "enable", "false", "fn", "for", "if", "let", "loop",
    "override", "requires", "return", "struct", "switch", "true", "var", "while",
    // reserved words
    "NULL", "Self", "abstract", "active", "alignas", "alignof", "as", "asm", "asm_fragment",
    "async", "attribute", "auto", "await", "become", "binding_array", "cast", "catch", "class",
    "co_await", "co_return", "co_yield", "coherent", "column_major", "common", "compile",
    "compile_fragment", "concept", "const_cast", "consteval", "constexpr", "constinit", "crate",
    "debugger", "decltype", "delete", "demote", "demote_to_helper", "do", "dynamic_cast", "enum",
    "explicit", "export", "extends", "extern", "external", "fallthrough", "filter", "final",
    "finally", "friend", "from", "fxgroup", "get", "goto", "groupshared", "highp", "impl",
    "implements", "import", "inline", "instanceof", "interface", "layout", "lowp", "macro",
    "macro_rules", "match", "mediump", "meta", "mod", "module", "move", "mut", "mutable",
    "namespace", "new", "nil", "noexcept", "noinline", "nointerpolation", "non_coherent",
    "noncoherent", "noperspective", "null", "nullptr", "of", "operator", "package", "packoffset",
    "partition", "pass", "patch", "pixelfragment", "precise", "precision", "premerge", "priv",
    "protected", "pub", "public", "readonly", "ref", "regardless", "register",
    "reinterpret_cast", "require", "resource", "restrict", "self", "set", "shared", "sizeof",
    "smooth", "snorm", "static", "static_assert", "static_cast", "std", "subroutine", "super",
    "target", "template", "this", "thread_local", "throw", "trait", "try", "type", "typedef",
    "typeid", "typename", "typeof", "union", "unless", "unorm", "unsafe", "unsized", "use",
    "using", "varying", "virtual", "volatile", "wgsl", "where", "with", "writeonly", "yield",
    // predeclared types and type generators
    "array", "atomic", "bool", "f16", "f32", "i32", "u32", "ptr", "sampler",
    "sampler_comparison", "vec2", "vec3", "vec4", "mat2x2", "mat2x3", "mat2x4", "mat3x2",
    "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2i", "vec3i", "vec4i", "vec2u",
    "vec3u", "vec4u", "vec2f", "vec3f", "vec4f", "vec2h", "vec3h", "vec4h",
    // builtins the translator emits; a user function with one of these names would shadow it
    "abs", "min", "max", "select", "countOneBits", "countLeadingZeros", "countTrailingZeros",
    "arrayLength",
    // the table intrinsic and entry-point plumbing
    "table", "tables", "gid",
];

/// The WGSL spelling of a Rust identifier. Deterministic, so every use of a name
/// (declaration, field access, call) maps the same way.
pub(crate) fn wgsl_ident(rust: &str) -> String {
    // Raw identifiers (`r#match`) mean the plain name in Rust.
    let rust = rust.strip_prefix("r#").unwrap_or(rust);
    // WGSL reserves identifiers starting with `__`, and `_` alone is not an identifier.
    if rust == "_" || rust.starts_with("__") {
        return format!("u{rust}");
    }
    if RESERVED.contains(&rust) {
        format!("{rust}_")
    } else {
        rust.to_string()
    }
}
