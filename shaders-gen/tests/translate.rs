//! The sample kernel translates to WGSL that naga validates (and lowers to SPIR-V), and the
//! same file compiles and runs as native Rust.

use rinshan_shaders_gen::{
    translate, translate_entry_points, validate_with_info, Entry, EntryPoint, Guard, ReadEntry, Source, UpdateEntry,
};

const FIXTURE: &str = include_str!("fixtures/sample_kernel.rs");

fn fixture_source() -> Source {
    Source {
        path: "tests/fixtures/sample_kernel.rs".into(),
        text: FIXTURE.into(),
    }
}

fn score_entry() -> Entry {
    Entry {
        name: "score_main".into(),
        function: "score".into(),
        input: "Input".into(),
        output: "Output".into(),
    }
}

fn translate_one(text: &str, entries: &[Entry]) -> String {
    let src = Source {
        path: "k.rs".into(),
        text: text.into(),
    };
    translate(&[src], entries).unwrap_or_else(|e| panic!("{e}"))
}

/// Kernels reach Vulkan drivers through naga's SPIR-V backend; make sure it accepts them.
fn assert_spirv(wgsl: &str) {
    let (module, info) = validate_with_info(wgsl).unwrap_or_else(|e| panic!("{e}"));
    naga::back::spv::write_vec(&module, &info, &naga::back::spv::Options::default(), None)
        .unwrap_or_else(|e| panic!("SPIR-V backend: {e}"));
}

#[test]
fn sample_kernel_snapshot() {
    let wgsl = translate(&[fixture_source()], &[score_entry()]).unwrap_or_else(|e| panic!("{e}"));
    assert_spirv(&wgsl);
    insta::assert_snapshot!("sample_kernel", wgsl);
}

#[test]
fn output_is_deterministic() {
    let a = translate(&[fixture_source()], &[score_entry()]).unwrap_or_else(|e| panic!("{e}"));
    let b = translate(&[fixture_source()], &[score_entry()]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(a, b);
}

#[allow(dead_code, clippy::all)]
mod native {
    /// The runtime's table intrinsic, natively.
    pub fn table(i: u32) -> u32 {
        i * 3 + 1
    }

    include!("fixtures/sample_kernel.rs");
}

#[test]
fn sample_kernel_runs_natively() {
    let mut tiles = [0u32; 34];
    tiles[0] = 2;
    tiles[5] = 3;
    tiles[30] = 1;
    let out = native::score(native::Input {
        tiles,
        seat: 1,
        flags: 6,
        delta: -4,
    });
    assert_eq!(out.sum, 6);
    assert_eq!(out.max, 3);
    assert_eq!(out.pairs, 2 * 100 + 6);
    // seat 1: tables 1..=4 -> 4, 7, 10, 13
    assert_eq!(out.table_sum, 34);
    assert_eq!(out.bits & 1, 0);
    assert_eq!((out.bits >> 1) & 1, 1, "honors");
}

#[test]
fn keywords_are_renamed_consistently() {
    let wgsl = translate_one(
        "struct Meta {\n    ptr: u32,\n    var: u32,\n}\n\nfn select(meta: Meta, target: u32) -> u32 {\n    let active = meta.ptr + target;\n    active + meta.var\n}\n",
        &[],
    );
    assert!(
        wgsl.contains("struct Meta {\n    ptr_: u32,\n    var_: u32,\n}"),
        "{wgsl}"
    );
    assert!(
        wgsl.contains("fn select_(meta_: Meta, target_: u32) -> u32 {"),
        "{wgsl}"
    );
    assert!(wgsl.contains("let active_: u32 = meta_.ptr_ + target_;"), "{wgsl}");
}

#[test]
fn shadowing_and_pointer_params() {
    let wgsl = translate_one(
        "fn inc(x: &mut u32) {\n    *x += 1;\n}\n\nfn twice(x: &mut u32) {\n    inc(x);\n    inc(x);\n}\n\nfn f(a: u32) -> u32 {\n    let a = a + 1;\n    let mut b = a;\n    twice(&mut b);\n    let a = b * 2;\n    a\n}\n",
        &[],
    );
    assert!(wgsl.contains("let a_1: u32 = a + 1u;"), "{wgsl}");
    assert!(wgsl.contains("twice(&b);"), "{wgsl}");
    assert!(wgsl.contains("    inc(x);\n"), "{wgsl}");
    assert!(wgsl.contains("let a_2: u32 = b * 2u;"), "{wgsl}");
}

#[test]
fn break_inside_match_leaves_the_loop() {
    let wgsl = translate_one(
        "fn f(n: u32) -> u32 {\n    let mut i = 0u32;\n    loop {\n        match i {\n            5 => break,\n            _ => i += 1,\n        }\n    }\n    i + n\n}\n",
        &[],
    );
    assert!(wgsl.contains("exit_loop = true;\n"), "{wgsl}");
    assert!(wgsl.contains("if exit_loop {\n            break;\n        }"), "{wgsl}");
}

#[test]
fn entries_get_distinct_bindings() {
    let src = "#[derive(Clone, Copy)]\npub struct A {\n    x: u32,\n}\n\npub fn one(a: A) -> A {\n    A { x: a.x + table(0) }\n}\n\npub fn two(a: A) -> A {\n    A { x: a.x * 2 }\n}\n";
    let entry = |name: &str, function: &str| Entry {
        name: name.into(),
        function: function.into(),
        input: "A".into(),
        output: "A".into(),
    };
    let wgsl = translate_one(src, &[entry("first", "one"), entry("second", "two")]);
    for needle in [
        "@group(0) @binding(0) var<storage, read> tables: array<u32>;",
        "@group(0) @binding(1) var<storage, read> first_in: array<A>;",
        "@group(0) @binding(2) var<storage, read_write> first_out: array<A>;",
        "@group(0) @binding(3) var<storage, read> second_in: array<A>;",
        "@group(0) @binding(4) var<storage, read_write> second_out: array<A>;",
    ] {
        assert!(wgsl.contains(needle), "missing {needle}:\n{wgsl}");
    }
    assert_spirv(&wgsl);
}

#[test]
fn entry_structs_must_be_host_shareable() {
    let src = Source {
        path: "k.rs".into(),
        text: "pub struct A {\n    ok: bool,\n}\n\npub fn one(a: A) -> A {\n    a\n}\n".into(),
    };
    let e = translate(
        &[src],
        &[Entry {
            name: "e".into(),
            function: "one".into(),
            input: "A".into(),
            output: "A".into(),
        }],
    )
    .unwrap_err();
    assert_eq!((e.line, e.column), (5, 8), "{e}");
    assert!(e.message.contains("use a u32"), "{e}");
}

#[test]
fn several_sources_form_one_module() {
    let a = Source {
        path: "a.rs".into(),
        text: "const N: usize = 4;\npub struct P {\n    v: [i32; N],\n}\n".into(),
    };
    let b = Source {
        path: "b.rs".into(),
        text: "pub fn neg_sum(p: P) -> P {\n    let mut out = P { v: [0; N] };\n    for i in 0..4 {\n        out.v[i as usize] = -p.v[i as usize] + i32::MIN.max(-5);\n    }\n    out\n}\n".into(),
    };
    let wgsl = translate(
        &[a, b],
        &[Entry {
            name: "k".into(),
            function: "neg_sum".into(),
            input: "P".into(),
            output: "P".into(),
        }],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(wgsl.contains("var out: P = P(array<i32, 4>());"), "{wgsl}");
    assert_spirv(&wgsl);
}

#[allow(dead_code, clippy::all)]
mod native_constructs {
    include!("fixtures/constructs.rs");
}

#[test]
fn constructs_snapshot_and_native() {
    let src = Source {
        path: "tests/fixtures/constructs.rs".into(),
        text: include_str!("fixtures/constructs.rs").into(),
    };
    let wgsl = translate(&[src], &[]).unwrap_or_else(|e| panic!("{e}"));
    assert_spirv(&wgsl);
    insta::assert_snapshot!("constructs", wgsl);

    assert_eq!(native_constructs::pick(-1), 1);
    assert_eq!(native_constructs::pick(2), 4);
    let s = native_constructs::S { a: [1, 2, 3], f: 0.5 };
    assert!(native_constructs::misc(s, 4).is_finite());
}

fn update_source() -> Source {
    Source {
        path: "tests/fixtures/update_kernel.rs".into(),
        text: include_str!("fixtures/update_kernel.rs").into(),
    }
}

fn update_entry(name: &str, function: &str, arg: &str) -> EntryPoint {
    EntryPoint::Update(UpdateEntry {
        name: name.into(),
        function: function.into(),
        state: "GameState".into(),
        arg: arg.into(),
        guard: None,
    })
}

#[allow(dead_code, clippy::all)]
mod native_update {
    include!("fixtures/update_kernel.rs");
}

#[test]
fn update_kernel_snapshot() {
    let wgsl = translate_entry_points(
        &[update_source()],
        &[
            update_entry("step_main", "step", "StepArg"),
            update_entry("pay_main", "pay_dealer", "u32"),
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    for needle in [
        "@group(0) @binding(1) var<storage, read_write> step_main_state: array<GameState>;",
        "@group(0) @binding(2) var<storage, read> step_main_arg: array<StepArg>;",
        "@group(0) @binding(3) var<storage, read_write> pay_main_state: array<GameState>;",
        "@group(0) @binding(4) var<storage, read> pay_main_arg: array<u32>;",
        "    var state = step_main_state[i];\n    step(&state, step_main_arg[i]);\n    step_main_state[i] = state;\n",
    ] {
        assert!(wgsl.contains(needle), "missing {needle}:\n{wgsl}");
    }
    assert_spirv(&wgsl);
    insta::assert_snapshot!("update_kernel", wgsl);
}

#[test]
fn update_state_is_game_sized() {
    // The engine's game state is about 190 words; the fixture mirrors its shape.
    assert_eq!(std::mem::size_of::<native_update::GameState>(), 188 * 4);
}

#[test]
fn update_kernel_runs_natively() {
    let mut s = native_update::GameState {
        seed: [1, 2],
        round: 0,
        dealer: 2,
        scores: [250; 4],
        wall: [4; 34],
        next_draw: 0,
        hands: [0; 20],
        melds: [0; 16],
        rivers: [0; 24],
        river_lens: 0,
        discarded: [0; 8],
        seat_flags: [0; 4],
        rewards: [0.0; 4],
        current: 0,
        drawn: 0,
        steps: 0,
        terminated: 0,
        history: [0; 64],
    };
    native_update::step(&mut s, native_update::StepArg { action: 40, bonus: 9 });
    assert_eq!(s.scores, [259, 247, 247, 247]);
    assert_eq!(s.rewards, [2.25, -0.75, -0.75, -0.75]);
    assert_eq!(s.melds[2], 7);
    assert_eq!((s.current, s.steps, s.next_draw), (1, 1, 1));
    assert_eq!(s.wall.iter().sum::<u32>(), 4 * 34 - 1);
    native_update::pay_dealer(&mut s, 30);
    assert_eq!(s.scores[2], 277);
}

#[test]
fn map_entries_keep_their_layout_through_translate_entry_points() {
    let via_points = translate_entry_points(&[fixture_source()], &[EntryPoint::Map(score_entry())])
        .unwrap_or_else(|e| panic!("{e}"));
    let via_translate = translate(&[fixture_source()], &[score_entry()]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(via_points, via_translate);
}

#[test]
fn mixed_entry_kinds_share_the_binding_sequence() {
    let src = "#[derive(Clone, Copy)]\npub struct A {\n    x: u32,\n}\n\npub fn double(a: A) -> A {\n    A { x: a.x * 2 }\n}\n\npub fn bump(a: &mut A, by: u32) {\n    a.x += by;\n}\n";
    let wgsl = translate_entry_points(
        &[Source {
            path: "k.rs".into(),
            text: src.into(),
        }],
        &[
            EntryPoint::Map(Entry {
                name: "map".into(),
                function: "double".into(),
                input: "A".into(),
                output: "A".into(),
            }),
            EntryPoint::Update(UpdateEntry {
                name: "upd".into(),
                function: "bump".into(),
                state: "A".into(),
                arg: "u32".into(),
                guard: None,
            }),
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    for needle in [
        "@group(0) @binding(1) var<storage, read> map_in: array<A>;",
        "@group(0) @binding(2) var<storage, read_write> map_out: array<A>;",
        "@group(0) @binding(3) var<storage, read_write> upd_state: array<A>;",
        "@group(0) @binding(4) var<storage, read> upd_arg: array<u32>;",
    ] {
        assert!(wgsl.contains(needle), "missing {needle}:\n{wgsl}");
    }
    assert_spirv(&wgsl);
}

/// A guarded update entry tests its guard on the stored record before copying it, and the WGSL
/// still validates; the guard's function keeps its name, and the wrapper's locals move aside.
#[test]
fn a_guarded_update_entry_skips_records_before_copying_them() {
    let src = "#[derive(Clone, Copy)]\npub struct A {\n    x: u32,\n    task: u32,\n}\n\npub fn i(task: u32) -> bool {\n    task == 3u32\n}\n\npub fn bump(a: &mut A, by: u32) {\n    if a.task == 3u32 {\n        a.x += by;\n    }\n}\n";
    let wgsl = translate_entry_points(
        &[Source {
            path: "k.rs".into(),
            text: src.into(),
        }],
        &[EntryPoint::Update(UpdateEntry {
            name: "upd".into(),
            function: "bump".into(),
            state: "A".into(),
            arg: "u32".into(),
            guard: Some(Guard {
                field: "task".into(),
                function: "i".into(),
            }),
        })],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let wrapper = "    let i_1 = gid.x;\n    if (i_1 >= arrayLength(&upd_state)) { return; }\n    if (!i(upd_state[i_1].task)) { return; }\n    var state = upd_state[i_1];\n";
    assert!(wgsl.contains(wrapper), "missing {wrapper}:\n{wgsl}");
    assert_spirv(&wgsl);
}

#[test]
fn a_read_entry_takes_two_slots_and_the_next_entry_follows_them() {
    let src = "#[derive(Clone, Copy)]\npub struct A {\n    x: u32,\n}\n\npub fn peek(a: A, seat: u32) -> u32 {\n    a.x + seat\n}\n\npub fn bump(a: &mut A, by: u32) {\n    a.x += by;\n}\n";
    let wgsl = translate_entry_points(
        &[Source {
            path: "k.rs".into(),
            text: src.into(),
        }],
        &[
            EntryPoint::Read(ReadEntry {
                name: "look".into(),
                function: "peek".into(),
                state: "A".into(),
                arg: "u32".into(),
                output: "u32".into(),
            }),
            EntryPoint::Update(UpdateEntry {
                name: "upd".into(),
                function: "bump".into(),
                state: "A".into(),
                arg: "u32".into(),
                guard: None,
            }),
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    for needle in [
        "@group(0) @binding(1) var<storage, read> look_state: array<A>;",
        "@group(0) @binding(2) var<storage, read> look_arg: array<u32>;",
        "@group(0) @binding(3) var<storage, read_write> look_out: array<u32>;",
        "look_out[i] = peek(look_state[i], look_arg[i]);",
        "@group(0) @binding(5) var<storage, read_write> upd_state: array<A>;",
        "@group(0) @binding(6) var<storage, read> upd_arg: array<u32>;",
    ] {
        assert!(wgsl.contains(needle), "missing {needle}:\n{wgsl}");
    }
    assert_spirv(&wgsl);
}

#[test]
fn a_read_entry_with_the_wrong_signature_is_rejected_at_its_function() {
    let src = "pub struct A {\n    x: u32,\n}\n\npub fn peek(a: A) -> u32 {\n    a.x\n}\n";
    let e = translate_entry_points(
        &[Source {
            path: "k.rs".into(),
            text: src.into(),
        }],
        &[EntryPoint::Read(ReadEntry {
            name: "look".into(),
            function: "peek".into(),
            state: "A".into(),
            arg: "u32".into(),
            output: "u32".into(),
        })],
    )
    .expect_err("one parameter, not two");
    assert_eq!((e.file.as_str(), e.line), ("k.rs", 5));
    assert!(
        e.message.contains("needs `fn peek(state: A, arg: u32) -> u32`"),
        "{}",
        e.message
    );
}

#[test]
fn update_wrapper_locals_do_not_hide_the_function() {
    let src = "pub struct S {\n    x: u32,\n}\n\npub fn state(s: &mut S, a: u32) {\n    s.x += a;\n}\n\npub fn i(s: &mut S, a: u32) {\n    s.x *= a;\n}\n";
    let entry = |name: &str, function: &str| {
        EntryPoint::Update(UpdateEntry {
            name: name.into(),
            function: function.into(),
            state: "S".into(),
            arg: "u32".into(),
            guard: None,
        })
    };
    let wgsl = translate_entry_points(
        &[Source {
            path: "k.rs".into(),
            text: src.into(),
        }],
        &[entry("a", "state"), entry("b", "i")],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(wgsl.contains("state(&state_1, a_arg[i]);"), "{wgsl}");
    assert!(wgsl.contains("i(&state, b_arg[i_1]);"), "{wgsl}");
    assert_spirv(&wgsl);
}
