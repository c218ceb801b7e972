//! Each test takes the real spec, makes one small edit, and pins the exact `file:line:col` and the
//! key words of the resulting message (what is wrong, and what to write instead).

use crate::common::*;

/// Asserts the location and that every fragment appears in the message.
fn assert_diag(d: &rinshan_codegen::Diagnostic, file: &str, line: usize, column: usize, words: &[&str]) {
    assert_eq!(
        (d.file.as_str(), d.line, d.column),
        (file, line, column),
        "wrong location for: {d}"
    );
    for w in words {
        assert!(d.message.contains(w), "`{w}` missing from: {d}");
    }
    assert!(d.to_string().starts_with(&format!("{file}:{line}:{column}: error: ")));
}

fn yaku_text() -> String {
    sources("red").1
}

#[test]
fn unknown_key_in_yaku_lists_allowed_keys() {
    let y = replace_once(
        &yaku_text(),
        "when = \"concealed && tsumo\"\n",
        "when = \"concealed && tsumo\"\nwhn = 1\n",
    );
    let d = single_error(load_texts("red", &sources("red").0, &y, &sources("red").2));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&y, "whn = 1"),
        1,
        &["unknown field `whn`", "`when`", "`supersedes`"],
    );
}

#[test]
fn unknown_section_in_variant() {
    let d = single_error(load_variant_edit("red", "[liability]", "[liabilty]"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&sources("red").0, "[liability]"),
        2,
        &["unknown field `liabilty`", "`liability`"],
    );
}

#[test]
fn option_no_kernel_code_reads() {
    // Without the kernel sources a stray option is just a new constant.
    assert!(load_variant_edit("red", "pao = true", "pao = true\npoa = false").is_ok());
    let d = single_error(load_variant_edit_with_kernel(
        "red",
        "pao = true",
        "pao = true\npoa = false",
    ));
    let v = replace_once(&sources("red").0, "pao = true", "pao = true\npoa = false");
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "poa = false"),
        1,
        &[
            "option `poa` is read by no kernel code",
            "no `POA`",
            "did you mean `pao`?",
        ],
    );
}

#[test]
fn wrong_type_variant_option() {
    let line = line_of(&sources("no_red").0, "double_ron = false");
    for (to, words) in [
        (
            "double_ron = \"no\"",
            &["`double_ron` is a TOML string", "`true`/`false`", "0 to 4294967295"][..],
        ),
        (
            "double_ron = 0.5",
            &["`double_ron` is a TOML float", "`u32` constant"][..],
        ),
        ("double_ron = [true]", &["`double_ron` is a TOML array"][..]),
        (
            "double_ron = -1",
            &["`double_ron = -1` is out of range", "from 0 to 4294967295"][..],
        ),
        (
            "double_ron = 4294967296",
            &["`double_ron = 4294967296` is out of range"][..],
        ),
    ] {
        let d = single_error(load_variant_edit("no_red", "double_ron = false", to));
        assert_diag(&d, &variant_path("no_red"), line, 14, words);
    }
}

#[test]
fn option_in_two_sections() {
    let to = "pao = true\ndouble_ron = true";
    let v = replace_once(&sources("red").0, "pao = true", to);
    let d = single_error(load_variant_edit("red", "pao = true", to));
    let second = v
        .lines()
        .enumerate()
        .filter(|(_, l)| l.starts_with("double_ron"))
        .nth(1)
        .unwrap()
        .0
        + 1;
    assert_diag(
        &d,
        &variant_path("red"),
        second,
        1,
        &[
            "option `double_ron` is also in `[claims]`",
            &format!("line {}", line_of(&v, "double_ron = true")),
            "`DOUBLE_RON`",
            "rename one",
        ],
    );
}

#[test]
fn option_named_like_a_generated_constant() {
    let to = "pao = true\nnum_actions = 3";
    let v = replace_once(&sources("red").0, "pao = true", to);
    let d = single_error(load_variant_edit("red", "pao = true", to));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "num_actions = 3"),
        1,
        &["`NUM_ACTIONS`", "rename it"],
    );
}

#[test]
fn red_fives_must_be_a_bool() {
    let d = single_error(load_variant_edit("no_red", "red_fives = false", "red_fives = 0"));
    assert_diag(
        &d,
        &variant_path("no_red"),
        line_of(&sources("no_red").0, "red_fives = false"),
        13,
        &["`red_fives` must be `true` or `false`", "discard ids"],
    );
}

#[test]
fn red_fives_is_required() {
    let d = single_error(load_variant_edit("no_red", "red_fives = false\n", ""));
    assert_diag(
        &d,
        &variant_path("no_red"),
        line_of(&sources("no_red").0, "[tiles]"),
        1,
        &[
            "`[tiles]` lacks `red_fives`",
            "add `red_fives = true` or `red_fives = false`",
        ],
    );
}

#[test]
fn triple_ron_abort_needs_double_ron() {
    let v = sources("red").0;
    let d = single_error(load_variant_edit("red", "double_ron = true", "double_ron = false"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "triple_ron_abort = true"),
        20,
        &[
            "`triple_ron_abort = true` needs `double_ron = true`",
            "three rons on one discard can only happen with double ron",
            "write `triple_ron_abort = false` or `double_ron = true`",
        ],
    );
}

#[test]
fn double_yakuman_needs_multiple_yakuman() {
    let v = sources("no_red").0;
    let d = single_error(load_variant_edit(
        "no_red",
        "multiple_yakuman = true",
        "multiple_yakuman = false",
    ));
    assert_diag(
        &d,
        &variant_path("no_red"),
        line_of(&v, "double_yakuman = true"),
        18,
        &[
            "`double_yakuman = true` needs `multiple_yakuman = true`",
            "capped at one yakuman",
            "write `double_yakuman = false` or `multiple_yakuman = true`",
        ],
    );
}

#[test]
fn west_extension_needs_a_target() {
    let v = sources("red").0;
    let d = single_error(load_variant_edit("red", "target_points = 30000", "target_points = 0"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "west_extension = true"),
        18,
        &[
            "`west_extension = true` needs `target_points` above 0",
            "with 0 the top player always has",
            "write `west_extension = false` or `target_points` above 0",
        ],
    );
}

#[test]
fn starting_points_must_be_positive() {
    let d = single_error(load_variant_edit(
        "red",
        "starting_points = 25000",
        "starting_points = 0",
    ));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&sources("red").0, "starting_points = 25000"),
        19,
        &["starting_points must be positive"],
    );
}

#[test]
fn toml_syntax_error_has_a_location() {
    let d = single_error(load_variant_edit(
        "red",
        "starting_points = 25000",
        "starting_points = = 25000",
    ));
    let line = line_of(&sources("red").0, "starting_points = 25000");
    assert_eq!((d.file.as_str(), d.line), (variant_path("red").as_str(), line), "{d}");
}

#[test]
fn han_out_of_range() {
    let from = "name = \"tanyao\"\nhan_closed = 1";
    let d = single_error(load_yaku_edit("red", from, "name = \"tanyao\"\nhan_closed = 14"));
    let line = line_of(&yaku_text(), "name = \"tanyao\"") + 1;
    assert_diag(
        &d,
        YAKU_PATH,
        line,
        14,
        &["han_closed = 14", "`tanyao`", "out of range", "1 to 13"],
    );
}

#[test]
fn han_open_above_closed() {
    let from = "name = \"chanta\"\nhan_closed = 2\nhan_open = 1";
    let d = single_error(load_yaku_edit(
        "red",
        from,
        "name = \"chanta\"\nhan_closed = 2\nhan_open = 3",
    ));
    let line = line_of(&yaku_text(), "name = \"chanta\"") + 2;
    assert_diag(
        &d,
        YAKU_PATH,
        line,
        12,
        &["han_open = 3", "greater than han_closed = 2", "han_open <= 2"],
    );
}

#[test]
fn yakuman_weight_must_be_one_or_two() {
    let from = "name = \"daisangen\"\nyakuman = 1";
    let d = single_error(load_yaku_edit("red", from, "name = \"daisangen\"\nyakuman = 3"));
    let line = line_of(&yaku_text(), "name = \"daisangen\"") + 1;
    assert_diag(&d, YAKU_PATH, line, 11, &["weight 3", "`yakuman = 1`", "`yakuman = 2`"]);
}

#[test]
fn both_han_and_yakuman() {
    let from = "name = \"kokushi\"\nyakuman = 1";
    let d = single_error(load_yaku_edit(
        "red",
        from,
        "name = \"kokushi\"\nhan_closed = 13\nyakuman = 1",
    ));
    let line = line_of(&yaku_text(), "name = \"kokushi\"") + 1;
    assert_diag(
        &d,
        YAKU_PATH,
        line,
        14,
        &["`kokushi` has both `yakuman` and han", "remove"],
    );
}

#[test]
fn neither_han_nor_yakuman() {
    let from = "name = \"suukantsu\"\nyakuman = 1\n";
    let d = single_error(load_yaku_edit("red", from, "name = \"suukantsu\"\n"));
    let line = line_of(&yaku_text(), "name = \"suukantsu\"");
    assert_diag(&d, YAKU_PATH, line, 8, &["neither han nor yakuman", "`yakuman = 1`"]);
}

#[test]
fn unknown_feature_with_suggestion() {
    let d = single_error(load_yaku_edit("red", "when = \"straight\"", "when = \"straigth\""));
    // Column 9: the first character inside the quotes of `when = "..."`.
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"straight\""),
        9,
        &[
            "`ittsu`",
            "unknown name `straigth`",
            "did you mean `straight`?",
            "struct Features",
        ],
    );
}

#[test]
fn unknown_feature_after_an_escape_maps_to_the_raw_column() {
    // `\u0072` is one character (`r`) in the value but six in the file.
    let d = single_error(load_yaku_edit(
        "red",
        "when = \"riichi\"",
        "when = \"\\u0072iichi && tsumoo\"",
    ));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"riichi\""),
        24,
        &["unknown name `tsumoo`", "`tsumo`"],
    );
    // Literal strings have no escapes.
    let d = single_error(load_yaku_edit("red", "when = \"riichi\"", "when = 'riichi && tsumoo'"));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"riichi\""),
        19,
        &["unknown name `tsumoo`"],
    );
}

#[test]
fn type_error_int_used_as_bool() {
    let d = single_error(load_yaku_edit(
        "red",
        "when = \"kans == 3\"",
        "when = \"tsumo && kans\"",
    ));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"kans == 3\""),
        18,
        &[
            "`sankantsu`",
            "`&&` needs bool operands",
            "`kans` is an integer",
            "`kans > 0`",
        ],
    );
}

#[test]
fn type_error_bool_compared_with_int() {
    let d = single_error(load_yaku_edit("red", "when = \"riichi\"", "when = \"riichi == 2\""));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"riichi\""),
        16,
        &["`==` compares a bool (`riichi`) with an integer (`2`)", "`!riichi`"],
    );
}

#[test]
fn syntax_error_column_inside_the_condition() {
    let d = single_error(load_yaku_edit("red", "when = \"kans == 3\"", "when = \"kans = 3\""));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "when = \"kans == 3\""),
        14,
        &["unexpected `=`", "write `==`"],
    );
    let from = "when = \"concealed && identical_runs == 2\"";
    let d = single_error(load_yaku_edit(
        "red",
        from,
        "when = \"concealed && (identical_runs == 2\"",
    ));
    // The missing `)` is reported at the end of the condition text.
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), from),
        9 + 33,
        &["expected `)`", "the end of the condition"],
    );
}

#[test]
fn duplicate_yaku_points_at_the_second() {
    let y = yaku_text();
    let d = single_error(load_yaku_edit("red", "name = \"chiihou\"", "name = \"tenhou\""));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&y, "name = \"chiihou\""),
        8,
        &[
            "duplicate yaku `tenhou`",
            &format!("line {}", line_of(&y, "name = \"tenhou\"")),
        ],
    );
}

#[test]
fn supersedes_cycle_is_printed() {
    let from = "name = \"riichi\"\nhan_closed = 1\nhan_open = 0\nwhen = \"riichi\"\n";
    let to = format!("{from}supersedes = [\"double_riichi\"]\n");
    let d = single_error(load_yaku_edit("red", from, &to));
    // Reported at the edge that closes the cycle: double_riichi's entry naming riichi.
    let edited = replace_once(&yaku_text(), from, &to);
    let line = line_of(&edited, "supersedes = [\"riichi\"]");
    assert_diag(
        &d,
        YAKU_PATH,
        line,
        15,
        &["supersedes cycle: riichi -> double_riichi -> riichi", "remove one"],
    );
}

#[test]
fn supersedes_unknown_yaku() {
    let d = single_error(load_yaku_edit(
        "red",
        "supersedes = [\"honitsu\"]",
        "supersedes = [\"honitsuu\"]",
    ));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "supersedes = [\"honitsu\"]"),
        15,
        &[
            "`chinitsu` supersedes unknown yaku `honitsuu`",
            "did you mean `honitsu`?",
        ],
    );
}

#[test]
fn too_many_yaku() {
    let (v, y, f) = sources("red");
    let mut extra = String::new();
    for i in 0..20 {
        extra.push_str(&format!(
            "\n[[yaku]]\nname = \"extra_{i}\"\nhan_closed = 1\nhan_open = 1\nwhen = \"riichi\"\ndescription = \"x\"\n"
        ));
    }
    let y = format!("{y}{extra}");
    let d = single_error(load_texts("red", &v, &y, &f));
    let n = y.matches("[[yaku]]\n").count();
    let sixty_fifth = format!("name = \"extra_{}\"", 64 - (n - 20));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&y, &sixty_fifth),
        8,
        &[&format!("{n} yaku"), "at most 64"],
    );
}

#[test]
fn unknown_action_kind() {
    let from = "{ kind = \"pon_red\" }";
    let d = single_error(load_variant_edit("red", from, "{ kind = \"pon_rde\" }"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&sources("red").0, from),
        14,
        &["unknown action kind `pon_rde`", "did you mean `pon_red`?"],
    );
}

#[test]
fn discard_block_must_match_red_fives() {
    let from = "{ kind = \"discard\", count = 37 }";
    let d = single_error(load_variant_edit("red", from, "{ kind = \"discard\", count = 34 }"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&sources("red").0, from),
        33,
        &["`discard` has 34 ids, but it needs 37", "3 red fives", "`count = 37`"],
    );
}

#[test]
fn red_action_without_red_fives() {
    let (v, ..) = sources("no_red");
    let from = "{ kind = \"pon\" },";
    let d = single_error(load_variant_edit(
        "no_red",
        from,
        "{ kind = \"pon\" }, { kind = \"pon_red\" },",
    ));
    // The red block itself is the error; the shifted total is not reported on top of it.
    assert_diag(
        &d,
        &variant_path("no_red"),
        line_of(&v, from),
        32,
        &["`pon_red`", "red_fives = false", "remove it"],
    );
}

#[test]
fn kyuushu_needs_abortive_draws() {
    let (v, ..) = sources("red");
    let d = single_error(load_variant_edit(
        "red",
        "abortive_draws = true\n",
        "abortive_draws = false\n",
    ));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "{ kind = \"kyuushu\" }"),
        14,
        &["`kyuushu`", "abortive_draws = false"],
    );
}

#[test]
fn missing_action_kind_and_wrong_total() {
    let (v, ..) = sources("no_red");
    let r = load_variant_edit("no_red", "    { kind = \"pass\" },                 # 77\n", "");
    let Err(errors) = r else { panic!("accepted") };
    assert_eq!(errors.len(), 2, "{}", render(&errors));
    assert_diag(
        &errors[0],
        &variant_path("no_red"),
        line_of(&v, "layout = ["),
        10,
        &["lacks `pass`", "{ kind = \"pass\" }"],
    );
    assert_diag(
        &errors[1],
        &variant_path("no_red"),
        line_of(&v, "num_actions = 79"),
        15,
        &["78 action ids", "num_actions = 79", "write `num_actions = 78`"],
    );
}

#[test]
fn uma_must_have_four_entries_summing_to_zero() {
    let line = line_of(&sources("red").0, "uma = [");
    let d = single_error(load_variant_edit(
        "red",
        "uma = [30, 10, -10, -30]",
        "uma = [30, 10, -10]",
    ));
    assert_diag(&d, &variant_path("red"), line, 7, &["3 entries", "thousands"]);
    let d = single_error(load_variant_edit(
        "red",
        "uma = [30, 10, -10, -30]",
        "uma = [30, 10, -10, -20]",
    ));
    assert_diag(&d, &variant_path("red"), line, 7, &["sums to 10", "not 0"]);
}

#[test]
fn penalty_must_be_finite() {
    let line = line_of(&sources("red").0, "illegal_action_penalty");
    let d = single_error(load_variant_edit(
        "red",
        "illegal_action_penalty = -1.0",
        "illegal_action_penalty = nan",
    ));
    assert_diag(&d, &variant_path("red"), line, 26, &["finite"]);
}

#[test]
fn mistyped_option_is_caught_on_both_sides() {
    // The option name in the variant no longer matches what tanyao reads.
    let d = single_error(load_variant_edit("red", "open_tanyao = true", "open_tanyoa = true"));
    assert_diag(
        &d,
        YAKU_PATH,
        line_of(&yaku_text(), "open_tanyao"),
        38,
        &["unknown name `open_tanyao`", "did you mean `open_tanyoa`?"],
    );
    // An option nobody reads is an error in the variant file.
    let d = single_error(load_variant_edit(
        "red",
        "open_tanyao = true",
        "open_tanyao = true\nkuitan = true",
    ));
    let v = replace_once(
        &sources("red").0,
        "open_tanyao = true",
        "open_tanyao = true\nkuitan = true",
    );
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "kuitan = true"),
        1,
        &["option `kuitan` is not used"],
    );
}

#[test]
fn variant_name_must_match_file() {
    let d = single_error(load_variant_edit("red", "name = \"red\"", "name = \"tenhou\""));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&sources("red").0, "name = \"red\""),
        8,
        &["`tenhou`", "write `name = \"red\"`"],
    );
}

#[test]
fn feature_of_unsupported_type() {
    let (v, y, f) = sources("red");
    let f = replace_once(&f, "pub suits: u32,", "pub suits: u8,");
    let d = single_error(load_texts("red", &v, &y, &f));
    assert_diag(
        &d,
        FEATURES_PATH,
        line_of(&f, "pub suits: u8,"),
        16,
        &["`suits`", "`u8`", "`bool` or `u32`"],
    );
}

#[test]
fn option_names_must_not_clash_with_generated_consts() {
    let from = "open_tanyao = true";
    let to = "open_tanyao = true\nyaku_riichi = true";
    let v = replace_once(&sources("red").0, from, to);
    let Err(errors) = load_variant_edit("red", from, to) else {
        panic!("accepted")
    };
    // Also unused by any condition; the clash is what matters here.
    assert_diag(
        &errors[0],
        &variant_path("red"),
        line_of(&v, "yaku_riichi"),
        1,
        &["`YAKU_RIICHI`", "rename"],
    );
}

#[test]
fn yaku_rule_named_like_a_plain_option() {
    let from = "open_tanyao = true";
    let to = "open_tanyao = true\ndouble_ron = true";
    let v = replace_once(&sources("red").0, from, to);
    let Err(errors) = load_variant_edit("red", from, to) else {
        panic!("accepted")
    };
    // Also unused by any condition; the clash is what matters here.
    assert_diag(
        &errors[0],
        &variant_path("red"),
        line_of(&v, "double_ron = true"),
        1,
        &[
            "option `double_ron`",
            "`[claims] double_ron`",
            "`DOUBLE_RON`",
            "rename it",
        ],
    );
}

#[test]
fn seats_are_four_or_three() {
    let (v, ..) = sources("red");
    let d = single_error(load_variant_edit("red", "seats = 4\n", "seats = 5\n"));
    assert_diag(
        &d,
        &variant_path("red"),
        line_of(&v, "seats = 4"),
        9,
        &["seats must be 4, or 3", "three-player"],
    );
}

#[test]
fn uma_has_one_entry_per_seat() {
    let (v, ..) = sources("sanma");
    let d = single_error(load_variant_edit(
        "sanma",
        "uma = [15, 0, -15]",
        "uma = [15, 5, -5, -15]",
    ));
    assert_diag(
        &d,
        &variant_path("sanma"),
        line_of(&v, "uma = [15, 0, -15]"),
        7,
        &["uma has 4 entries", "3 seats"],
    );
}

#[test]
fn three_seats_have_no_chi_and_four_no_kita() {
    let (v, ..) = sources("sanma");
    let d = single_error(load_variant_edit(
        "sanma",
        "    { kind = \"pass\" },",
        "    { kind = \"chi_left\" },\n    { kind = \"pass\" },",
    ));
    assert!(
        d.message.contains("`chi_left` is a chi") && d.message.contains("seats = 3"),
        "{}",
        d.message
    );
    assert_eq!(d.line, line_of(&v, "{ kind = \"pass\" }"));
    let (v, ..) = sources("red");
    let d = single_error(load_variant_edit(
        "red",
        "    { kind = \"pass\" },",
        "    { kind = \"kita\" },\n    { kind = \"pass\" },",
    ));
    assert!(d.message.contains("`kita` sets North aside"), "{}", d.message);
    assert_eq!(d.line, line_of(&v, "{ kind = \"pass\" }"));
    // A three-player layout without kita is reported at the layout.
    let r = load_variant_edit(
        "sanma",
        "    { kind = \"kita\" },                 # 78: set a North aside for a replacement tile\n",
        "",
    );
    let Err(diags) = r else { panic!("loaded") };
    assert!(
        diags
            .iter()
            .any(|d| d.message.contains("lacks `kita` (seats = 3 needs it)")),
        "{diags:?}"
    );
}
