//! "The rules are data", end to end: a spec edited at run time goes through the codegen library
//! and the WGSL translator and runs on the GPU backend, without rebuilding rinshan.

use std::path::{Path, PathBuf};

use rinshan_engine::generated::kernel::ScoreOutput;
use rinshan_engine::gpu::Kernel;
use rinshan_engine::hand::{self, Win};
use rinshan_engine::notation::{parse_meld, parse_tiles};
use rinshan_shaders_gen::Source;
use rinshan_tests::gpu_or_skip;

fn rules() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../rules")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// (file name, text) of every kernel source, in name order.
fn kernel_files() -> Vec<(String, String)> {
    rinshan_codegen::kernel_paths(&rules())
        .iter()
        .map(|p| {
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or_default();
            (name.to_string(), read(p))
        })
        .collect()
}

/// Compiles `variant` with the given spec texts into a WGSL module with the runtime's entry points.
fn compile(variant: &str, variant_text: &str, yaku_text: &str) -> String {
    compile_with_kernel(variant, variant_text, yaku_text, |_, text| text)
}

/// As [`compile`], with each kernel file's text passed through `edit(file name, text)`.
fn compile_with_kernel(
    variant: &str,
    variant_text: &str,
    yaku_text: &str,
    edit: impl Fn(&str, String) -> String,
) -> String {
    let kernel: Vec<(String, String)> = kernel_files()
        .into_iter()
        .map(|(name, text)| {
            let text = edit(&name, text);
            (format!("rules/kernel/{name}"), text)
        })
        .collect();
    let features = read(&rules().join("kernel/features.rs"));
    let kernel_refs: Vec<(&str, &str)> = kernel.iter().map(|(p, t)| (p.as_str(), t.as_str())).collect();
    let spec = rinshan_codegen::load_sources_with_kernel(
        (&format!("rules/variants/{variant}.toml"), variant_text),
        ("rules/yaku.toml", yaku_text),
        ("rules/kernel/features.rs", &features),
        &kernel_refs,
    )
    .unwrap_or_else(|d| panic!("{}", rinshan_codegen::render(&d)));
    let generated = rinshan_codegen::generate(&spec);
    let tables = rinshan_codegen::tables::build();
    let mut sources = vec![
        Source {
            path: "generated.rs".into(),
            text: generated.kernel_rust,
        },
        Source {
            path: "table_consts.rs".into(),
            text: tables.kernel_consts(),
        },
    ];
    sources.extend(kernel.into_iter().map(|(path, text)| Source { path, text }));
    // The same entry points as build.rs: the map entries, then the in-place update entries.
    let entries = rinshan_shaders_gen::entry_points(
        &rinshan_tests::entries::ENTRIES,
        &rinshan_tests::entries::UPDATE_ENTRIES,
        &rinshan_tests::entries::READ_ENTRIES,
    );
    rinshan_shaders_gen::translate_entry_points(&sources, &entries).unwrap_or_else(|e| panic!("{e}"))
}

fn win(hand: &str, win: &str, melds: &[&str], tsumo: bool) -> Win {
    let tiles = parse_tiles(hand).expect("hand");
    let w = parse_tiles(win).expect("win").tiles[0].kind();
    let mut c = hand::WinContext {
        tsumo,
        seat_wind: 1,
        ..Default::default()
    };
    c.dealer = false;
    Win {
        hand: tiles.counts(),
        win: w,
        melds: melds.iter().map(|m| parse_meld(m).expect("meld")).collect(),
        aka: 0,
        context: c,
    }
}

/// (status, han, yakuman) of each hand under a WGSL module.
fn judge(gpu: &mut rinshan_engine::gpu::Gpu, wgsl: &str, wins: &[Win]) -> Vec<(u32, u32, u32)> {
    let inputs: Vec<u32> = wins
        .iter()
        .flat_map(|w| hand::score_input(w).expect("consistent"))
        .collect();
    let out = gpu.run_wgsl(wgsl, Kernel::Score, &inputs).expect("gpu run");
    outputs(&out).iter().map(|o| (o.status, o.han, o.yakuman)).collect()
}

fn outputs(words: &[u32]) -> Vec<ScoreOutput> {
    bytemuck::cast_slice(words).to_vec()
}

#[test]
fn edited_specs_change_results_on_the_gpu() {
    let Some(mut gpu) = gpu_or_skip("rules as data") else {
        return;
    };
    let variant_text = read(&rules().join("variants/red.toml"));
    let yaku_text = read(&rules().join("yaku.toml"));
    let hands = [
        // closed pinfu + tanyao ron: 2 han
        win("234567m234p456s66s", "6s", &[], false),
        // open tanyao: 1 han, or no yaku when open tanyao is off
        win("567m234p456s66s", "6s", &["chi:234m"], false),
        // 22334455667788p read as 345 345 678 678 + 22: pinfu, ryanpeikou, tanyao, chinitsu (11 han)
        // beats the seven-pairs reading
        win("22334455667788p", "8p", &[], false),
    ];

    let stock = compile("red", &variant_text, &yaku_text);
    // The first line names the source paths, which differ between build.rs and this test.
    let body = |w: &str| w.split_once('\n').map(|(_, rest)| rest.to_string()).unwrap_or_default();
    assert!(
        body(&stock) == body(rinshan_engine::generated::red::WGSL),
        "run-time compilation reproduces the built module"
    );
    let stock_results = judge(&mut gpu, rinshan_engine::generated::red::WGSL, &hands);
    assert_eq!(stock_results, vec![(0, 2, 0), (0, 1, 0), (0, 1 + 3 + 1 + 6, 0)]);

    // A han value (tanyao worth 3 closed / 2 open) and a local yaku (daisharin-style seven simple
    // pairs of one suit as a double yakuman), compiled together: each GPU pipeline build costs seconds on
    // a software driver.
    let tanyao = "name = \"tanyao\"\nhan_closed = 1\nhan_open = 1";
    assert!(yaku_text.contains(tanyao), "yaku.toml layout changed; update this test");
    let edited = yaku_text.replace(tanyao, "name = \"tanyao\"\nhan_closed = 3\nhan_open = 2")
        + "\n[[yaku]]\nname = \"daisharin\"\ndescription = \"seven pairs of 2-8 in one suit\"\nyakuman = 2\nwhen = \"seven_pairs && all_simples && suits == 1\"\n";
    // Tenhou (the red spec) counts no yakuman double; the edited variant does.
    assert!(variant_text.contains("double_yakuman = false"));
    let doubles = variant_text.replace("double_yakuman = false", "double_yakuman = true");
    let results = judge(&mut gpu, &compile("red", &doubles, &edited), &hands);
    assert_eq!(results[0], (0, 4, 0), "closed tanyao now 3 han");
    assert_eq!(results[1], (0, 2, 0), "open tanyao now 2 han");
    // The standard reading now has 13 han (kazoe yakuman, base 8000); the double yakuman pays more.
    assert_eq!(results[2], (0, 0, 2), "the seven-pairs reading is now a double yakuman");

    // A variant option: no open tanyao.
    assert!(variant_text.contains("open_tanyao = true"));
    let closed_only = variant_text.replace("open_tanyao = true", "open_tanyao = false");
    let results = judge(&mut gpu, &compile("red", &closed_only, &yaku_text), &hands);
    assert_eq!(results[1].0, 2, "open all-simples hand has no yaku without open tanyao");
    assert_eq!((results[0], results[2]), (stock_results[0], stock_results[2]));
}

/// Adding a variant option takes its TOML line and the kernel code that reads it, nothing else:
/// here a new `[scoring] sticks_to_winner` (whether the winner collects the riichi sticks on the
/// table), declared in a copy of the spec and read in a copy of the scoring kernel.
#[test]
fn a_new_option_is_its_toml_line_and_the_kernel_code_that_reads_it() {
    let Some(mut gpu) = gpu_or_skip("a new option") else {
        return;
    };
    let variant_text = read(&rules().join("variants/red.toml"));
    let yaku_text = read(&rules().join("yaku.toml"));
    let stick_line = "riichi_stick_points = 1000\n";
    assert!(
        variant_text.contains(stick_line),
        "red.toml layout changed; update this test"
    );
    let with_option = |on: bool| variant_text.replace(stick_line, &format!("{stick_line}sticks_to_winner = {on}\n"));
    let read_option = |name: &str, text: String| {
        let sticks = "let sticks: u32 = inp.sticks * RIICHI_STICK_POINTS;";
        if name != "score.rs" {
            return text;
        }
        assert!(text.contains(sticks), "score.rs changed; update this test");
        text.replace(
            sticks,
            "let mut sticks: u32 = inp.sticks * RIICHI_STICK_POINTS;\n    if !STICKS_TO_WINNER {\n        sticks = 0u32;\n    }",
        )
    };
    let mut with_sticks = win("234567m234p456s66s", "6s", &[], false);
    with_sticks.context.sticks = 2;
    let inputs: Vec<u32> = hand::score_input(&with_sticks).expect("consistent").to_vec();
    let gain = |gpu: &mut rinshan_engine::gpu::Gpu, wgsl: &str| {
        outputs(&gpu.run_wgsl(wgsl, Kernel::Score, &inputs).expect("gpu run"))[0].gain
    };
    // tanyao pinfu ron, 2 han 30 fu: 2000, plus 2000 in sticks when the winner takes them.
    assert_eq!(
        gain(
            &mut gpu,
            &compile_with_kernel("red", &with_option(true), &yaku_text, read_option)
        ),
        4000
    );
    assert_eq!(
        gain(
            &mut gpu,
            &compile_with_kernel("red", &with_option(false), &yaku_text, read_option)
        ),
        2000
    );
    // Declared but read by no kernel code (the stock kernel): the spec is rejected, a typo guard.
    let stock = kernel_files();
    let stock: Vec<(&str, &str)> = stock.iter().map(|(p, t)| (p.as_str(), t.as_str())).collect();
    let unread = rinshan_codegen::load_sources_with_kernel(
        ("rules/variants/red.toml", &with_option(true)),
        ("rules/yaku.toml", &yaku_text),
        ("rules/kernel/features.rs", &read(&rules().join("kernel/features.rs"))),
        &stock,
    )
    .expect_err("an option no kernel reads");
    assert_eq!(unread.len(), 1, "{}", rinshan_codegen::render(&unread));
    assert!(unread[0].message.contains("sticks_to_winner"), "{}", unread[0].message);
    assert_eq!(
        unread[0].line,
        variant_text[..variant_text.find(stick_line).expect("line")]
            .lines()
            .count()
            + 2
    );
}
