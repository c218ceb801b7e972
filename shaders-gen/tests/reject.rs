//! Constructs outside the kernel subset are rejected at the right place, with a message
//! that says what to write instead.

use rinshan_shaders_gen::{translate, translate_entry_points, EntryPoint, Error, Guard, Source, UpdateEntry};

fn reject(text: &str) -> Error {
    let src = Source {
        path: "kernels/k.rs".into(),
        text: text.into(),
    };
    match translate(&[src], &[]) {
        Ok(wgsl) => panic!("expected a rejection, got WGSL:\n{wgsl}"),
        Err(e) => e,
    }
}

#[track_caller]
fn check(text: &str, line: usize, column: usize, advice: &str) {
    let e = reject(text);
    assert_eq!(
        (e.file.as_str(), e.line, e.column),
        ("kernels/k.rs", line, column),
        "{e}"
    );
    assert!(e.message.contains(advice), "message should mention `{advice}`: {e}");
}

#[test]
fn display_is_file_line_column_message() {
    let e = reject("fn f() -> u64 {\n    0\n}\n");
    assert_eq!(e.to_string(), format!("kernels/k.rs:1:11: {}", e.message));
}

#[test]
fn heap_types() {
    check(
        "fn f(v: Vec<u32>) -> u32 {\n    0\n}\n",
        1,
        9,
        "fixed-size array `[T; N]`",
    );
    check("struct S {\n    a: Box<u32>,\n}\n", 2, 8, "fixed-size array");
}

#[test]
fn option_and_result() {
    check("fn f(x: u32) -> Option<u32> {\n    x\n}\n", 1, 17, "status field");
    check(
        "fn f(x: u32) -> u32 {\n    let y = Some(x);\n    x\n}\n",
        2,
        13,
        "status field",
    );
}

#[test]
fn wide_and_narrow_integers() {
    check(
        "fn f(x: u32) -> u32 {\n    let y: u64 = 1;\n    x\n}\n",
        2,
        12,
        "use `u32`",
    );
    check("fn f(x: f64) -> u32 {\n    1\n}\n", 1, 9, "use `f32`");
    check(
        "fn f(x: u32) -> u32 {\n    let y = 1u8;\n    x\n}\n",
        2,
        13,
        "`u32` or `i32` literal",
    );
}

#[test]
fn usize_outside_index() {
    check(
        "fn f(x: u32) -> u32 {\n    let n = x as usize;\n    x\n}\n",
        2,
        18,
        "only allowed directly inside an index (`a[i as usize]`)",
    );
}

#[test]
fn iterators_and_unknown_methods() {
    check(
        "fn f(a: [u32; 4]) -> u32 {\n    let mut s = 0u32;\n    for x in a.iter() {\n        s += *x;\n    }\n    s\n}\n",
        3,
        14,
        "for i in a..b",
    );
    check(
        "fn f(x: f32) -> f32 {\n    x.sqrt()\n}\n",
        2,
        7,
        "write a free function",
    );
}

#[test]
fn macros() {
    check(
        "fn f(x: u32) -> u32 {\n    assert!(x < 4);\n    x\n}\n",
        2,
        5,
        "return a status value",
    );
    check(
        "fn f(x: u32) -> u32 {\n    if x > 3 {\n        panic!(\"no\");\n    }\n    x\n}\n",
        3,
        9,
        "cannot panic",
    );
}

#[test]
fn recursion_direct_and_indirect() {
    check(
        "fn f(x: u32) -> u32 {\n    if x == 0 {\n        return 0;\n    }\n    f(x - 1)\n}\n",
        5,
        5,
        "rewrite it as a loop",
    );
    let e = reject(
        "fn a(x: u32) -> u32 {\n    b(x)\n}\n\nfn b(x: u32) -> u32 {\n    if x > 0 { a(x - 1) } else { 0 }\n}\n",
    );
    assert_eq!((e.line, e.column), (6, 16), "{e}");
    assert!(e.message.contains("a -> b -> a"), "{e}");
}

#[test]
fn traits_impls_generics_closures() {
    check(
        "struct S {\n    a: u32,\n}\n\nimpl S {\n    fn get(&self) -> u32 {\n        self.a\n    }\n}\n",
        5,
        1,
        "free functions",
    );
    check("trait T {}\n", 1, 1, "free functions");
    check("fn id<T>(x: T) -> T {\n    x\n}\n", 1, 6, "concrete types");
    check(
        "fn f(x: u32) -> u32 {\n    let g = |y: u32| y + 1;\n    g(x)\n}\n",
        2,
        13,
        "separate `fn`",
    );
}

#[test]
fn references() {
    check("fn f(x: &u32) -> u32 {\n    *x\n}\n", 1, 9, "pass the value itself");
    check(
        "struct S {\n    a: u32,\n}\n\nfn inc(x: &mut u32) {\n    *x += 1;\n}\n\nfn f(s: S) -> u32 {\n    let mut t = s;\n    inc(&mut t.a);\n    t.a\n}\n",
        11,
        9,
        "copy the value into a local (`let mut tmp = x.f;`), pass `&mut tmp`, then copy it back",
    );
}

#[test]
fn items_use_mod() {
    check("use core::cmp::max;\n", 1, 1, "plain name");
    check("mod inner {}\n", 1, 1, "separate `Source`");
}

#[test]
fn loop_labels_and_tuples() {
    check(
        "fn f() -> u32 {\n    'outer: loop {\n        break 'outer;\n    }\n    0\n}\n",
        2,
        5,
        "`bool` flag",
    );
    check(
        "fn f(x: u32) -> u32 {\n    let (a, b) = (x, x);\n    a + b\n}\n",
        2,
        9,
        "struct with named fields",
    );
    check(
        "fn f(x: [u32; 4]) -> u32 {\n    let s = &x[1..3];\n    0\n}\n",
        2,
        13,
        "pass values otherwise",
    );
    check(
        "fn f(x: &[u32]) -> u32 {\n    x[0]\n}\n",
        1,
        9,
        "fixed-size array `[T; N]`",
    );
}

#[test]
fn literals_and_inference() {
    check("fn f() -> u32 {\n    4294967296\n}\n", 2, 5, "32-bit");
    check("fn f() -> i32 {\n    2147483648i32\n}\n", 2, 5, "out of range");
    check(
        "fn f() -> u32 {\n    let mut x = 0;\n    x += 1u32;\n    x\n}\n",
        2,
        17,
        "`0u32`",
    );
}

#[test]
fn if_as_value_needs_simple_branches() {
    check(
        "fn g(x: &mut u32) -> u32 {\n    *x += 1;\n    *x\n}\n\nfn f(c: bool) -> u32 {\n    let mut n = 0u32;\n    let v = if c { g(&mut n) } else { 1 };\n    v\n}\n",
        8,
        13,
        "`let mut x: T = ...;`",
    );
}

#[test]
fn unknown_functions_and_reserved_intrinsic() {
    check(
        "fn f(x: u32) -> u32 {\n    helper(x)\n}\n",
        2,
        5,
        "not defined in the kernel sources",
    );
    check("fn table(i: u32) -> u32 {\n    i\n}\n", 1, 4, "table intrinsic");
}

#[test]
fn syntax_errors_are_located() {
    let e = reject("fn f( -> u32 {\n    0\n}\n");
    assert_eq!(e.line, 1, "{e}");
    assert!(e.message.starts_with("syntax error"), "{e}");
}

fn reject_update(text: &str, function: &str, state: &str, arg: &str) -> Error {
    reject_update_entry(
        text,
        UpdateEntry {
            name: "upd".into(),
            function: function.into(),
            state: state.into(),
            arg: arg.into(),
            guard: None,
        },
    )
}

fn reject_update_entry(text: &str, entry: UpdateEntry) -> Error {
    let src = Source {
        path: "kernels/k.rs".into(),
        text: text.into(),
    };
    let entry = EntryPoint::Update(entry);
    match translate_entry_points(&[src], &[entry]) {
        Ok(wgsl) => panic!("expected a rejection, got WGSL:\n{wgsl}"),
        Err(e) => e,
    }
}

const UPDATE_SRC: &str = "pub struct S {\n    x: u32,\n}\n\npub struct Flag {\n    on: bool,\n}\n\npub struct Outer {\n    inner: [Flag; 2],\n}\n\npub fn by_value(s: S, a: u32) -> S {\n    S { x: s.x + a }\n}\n\npub fn returns(s: &mut S, a: u32) -> u32 {\n    s.x += a;\n    s.x\n}\n\npub fn ok(s: &mut S, a: u32) {\n    s.x += a;\n}\n\npub fn one_param(s: &mut S) {\n    s.x += 1;\n}\n\npub fn flag(f: &mut Outer, a: u32) {\n    f.inner[a as usize].on = true;\n}\n\npub fn bool_arg(s: &mut S, a: bool) {\n    s.x += a as u32;\n}\n";

#[test]
fn update_entry_signature_mismatch() {
    let cases = [
        ("by_value", "S", "u32", 13, 8),
        ("returns", "S", "u32", 17, 8),
        ("one_param", "S", "u32", 26, 8),
        // The argument type does not match the entry's.
        ("ok", "S", "i32", 22, 8),
        ("ok", "Flag", "u32", 22, 8),
    ];
    for (function, state, arg, line, column) in cases {
        let e = reject_update(UPDATE_SRC, function, state, arg);
        assert_eq!(
            (e.file.as_str(), e.line, e.column),
            ("kernels/k.rs", line, column),
            "{function}: {e}"
        );
        let want = format!("entry `upd` needs `fn {function}(state: &mut {state}, arg: {arg})` with no return value");
        assert!(e.message.contains(&want), "{function}: {e}");
        assert!(
            e.to_string().starts_with(&format!("kernels/k.rs:{line}:{column}: ")),
            "{e}"
        );
    }
}

#[test]
fn update_entry_types_must_be_host_shareable() {
    // bool nested inside an array of structs in the state.
    let e = reject_update(UPDATE_SRC, "flag", "Outer", "u32");
    assert_eq!((e.line, e.column), (30, 8), "{e}");
    assert!(e.message.contains("`Outer` cannot live in a storage buffer"), "{e}");
    assert!(e.message.contains("use a u32"), "{e}");
    // bool as the scalar argument.
    let e = reject_update(UPDATE_SRC, "bool_arg", "S", "bool");
    assert_eq!((e.line, e.column), (34, 8), "{e}");
    assert!(e.message.contains("`bool` cannot live in a storage buffer"), "{e}");
}

#[test]
fn update_entry_unknown_function_and_name_clash() {
    let e = reject_update(UPDATE_SRC, "missing", "S", "u32");
    assert_eq!((e.line, e.column), (1, 1), "{e}");
    assert!(e.message.contains("function `missing` is not defined"), "{e}");
    let src = format!("{UPDATE_SRC}\nconst upd_state: u32 = 1;\n");
    let e = reject_update(&src, "ok", "S", "u32");
    assert!(e.message.contains("needs the name `upd_state`"), "{e}");
}

#[test]
fn a_guard_must_read_a_u32_field_with_a_u32_predicate() {
    let src = format!("{UPDATE_SRC}\npub fn is_one(x: u32) -> bool {{\n    x == 1u32\n}}\n\npub fn widen(x: u32) -> u32 {{\n    x\n}}\n");
    let guarded = |field: &str, function: &str| UpdateEntry {
        name: "upd".into(),
        function: "ok".into(),
        state: "S".into(),
        arg: "u32".into(),
        guard: Some(Guard {
            field: field.into(),
            function: function.into(),
        }),
    };
    let e = reject_update_entry(&src, guarded("y", "is_one"));
    assert_eq!((e.line, e.column), (22, 8), "{e}");
    assert!(
        e.message
            .contains("the guard reads `S.y`, which is not a `u32` field of `S`"),
        "{e}"
    );
    for function in ["widen", "missing"] {
        let e = reject_update_entry(&src, guarded("x", function));
        assert!(
            e.message
                .contains(&format!("the guard needs `fn {function}(x: u32) -> bool`")),
            "{e}"
        );
    }
}
