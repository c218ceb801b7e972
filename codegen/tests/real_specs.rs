//! The real spec files: they load, they say what the rules say, and the generated code means what
//! the spec means.

use crate::common::*;
use rinshan_codegen::expr::{eval, Value};
use rinshan_codegen::{generate, Spec};

const ALL_YAKU: [&str; 45] = [
    "riichi",
    "menzen_tsumo",
    "pinfu",
    "tanyao",
    "iipeikou",
    "yakuhai_seat_wind",
    "yakuhai_round_wind",
    "yakuhai_white",
    "yakuhai_green",
    "yakuhai_red",
    "haitei",
    "houtei",
    "rinshan",
    "chankan",
    "double_riichi",
    "ippatsu",
    "chiitoitsu",
    "chanta",
    "ittsu",
    "sanshoku_doujun",
    "sanshoku_doukou",
    "toitoi",
    "sanankou",
    "sankantsu",
    "shousangen",
    "honroutou",
    "ryanpeikou",
    "junchan",
    "honitsu",
    "chinitsu",
    "kokushi",
    "kokushi_13",
    "suuankou",
    "suuankou_tanki",
    "daisangen",
    "shousuushi",
    "daisuushi",
    "tsuuiisou",
    "ryuuiisou",
    "chinroutou",
    "chuuren",
    "junsei_chuuren",
    "suukantsu",
    "tenhou",
    "chiihou",
];

#[test]
fn every_variant_loads() {
    assert_eq!(
        rinshan_codegen::variant_names(&rules_dir()),
        ["mjsoul", "mjsoul_sanma", "mleague", "no_red", "red", "sanma", "wrc"]
    );
    for v in ["red", "no_red", "mjsoul", "mleague", "wrc", "sanma", "mjsoul_sanma"] {
        let spec = load_real(v);
        assert_eq!(spec.variant.name, v);
    }
}

#[test]
fn unknown_variant_lists_the_known_ones() {
    let Err(e) = rinshan_codegen::load(&rules_dir(), "blue") else {
        panic!("loaded")
    };
    assert!(
        e[0].message.contains("no variant `blue`")
            && e[0]
                .message
                .contains("mjsoul, mjsoul_sanma, mleague, no_red, red, sanma, wrc"),
        "{}",
        e[0]
    );
}

#[test]
fn yaku_list_is_complete_with_tenhou_han() {
    let spec = load_real("red");
    let mut names: Vec<&str> = spec.yaku.iter().map(|y| y.name.as_str()).collect();
    names.sort_unstable();
    let mut want = ALL_YAKU.to_vec();
    want.sort_unstable();
    assert_eq!(names, want);
    let han = |n: &str| {
        let y = spec.yaku(n).unwrap();
        (y.han_closed, y.han_open, y.yakuman)
    };
    for (n, closed, open) in [
        ("riichi", 1, 0),
        ("ippatsu", 1, 0),
        ("menzen_tsumo", 1, 0),
        ("pinfu", 1, 0),
        ("iipeikou", 1, 0),
        ("tanyao", 1, 1),
        ("yakuhai_white", 1, 1),
        ("haitei", 1, 1),
        ("houtei", 1, 1),
        ("rinshan", 1, 1),
        ("chankan", 1, 1),
        ("double_riichi", 2, 0),
        ("chiitoitsu", 2, 0),
        ("chanta", 2, 1),
        ("ittsu", 2, 1),
        ("sanshoku_doujun", 2, 1),
        ("sanshoku_doukou", 2, 2),
        ("toitoi", 2, 2),
        ("sanankou", 2, 2),
        ("sankantsu", 2, 2),
        ("shousangen", 2, 2),
        ("honroutou", 2, 2),
        ("ryanpeikou", 3, 0),
        ("junchan", 3, 2),
        ("honitsu", 3, 2),
        ("chinitsu", 6, 5),
    ] {
        assert_eq!(han(n), (closed, open, 0), "{n}");
    }
    for n in ["daisuushi", "kokushi_13", "suuankou_tanki", "junsei_chuuren"] {
        assert_eq!(han(n), (0, 0, 2), "{n}");
    }
    for n in [
        "kokushi",
        "suuankou",
        "daisangen",
        "shousuushi",
        "tsuuiisou",
        "ryuuiisou",
        "chinroutou",
        "chuuren",
        "suukantsu",
        "tenhou",
        "chiihou",
    ] {
        assert_eq!(han(n), (0, 0, 1), "{n}");
    }
    let sup = |a: &str, b: &str| spec.yaku(a).unwrap().supersedes.contains(&spec.yaku(b).unwrap().index);
    for (a, b) in [
        ("double_riichi", "riichi"),
        ("ryanpeikou", "iipeikou"),
        ("junchan", "chanta"),
        ("chinitsu", "honitsu"),
        ("kokushi_13", "kokushi"),
        ("suuankou_tanki", "suuankou"),
        ("junsei_chuuren", "chuuren"),
    ] {
        assert!(sup(a, b), "{a} should supersede {b}");
        assert!(!sup(b, a));
    }
}

/// Action layouts of the reference (MahJax), section 3.
#[test]
fn action_layouts_match_the_reference() {
    let red = load_real("red");
    let no_red = load_real("no_red");
    assert_eq!(red.variant.num_actions, 87);
    assert_eq!(no_red.variant.num_actions, 79);
    let ids = |s: &Spec| -> Vec<(String, u32, u32)> {
        s.variant
            .actions
            .iter()
            .map(|b| (b.kind.clone(), b.first, b.count))
            .collect()
    };
    let expect = |v: &[(&str, u32, u32)]| -> Vec<(String, u32, u32)> {
        v.iter().map(|&(k, a, b)| (k.to_string(), a, b)).collect()
    };
    assert_eq!(
        ids(&red),
        expect(&[
            ("discard", 0, 37),
            ("self_kan", 37, 34),
            ("tsumogiri", 71, 1),
            ("riichi", 72, 1),
            ("tsumo", 73, 1),
            ("ron", 74, 1),
            ("pon", 75, 1),
            ("pon_red", 76, 1),
            ("open_kan", 77, 1),
            ("chi_left", 78, 1),
            ("chi_left_red", 79, 1),
            ("chi_middle", 80, 1),
            ("chi_middle_red", 81, 1),
            ("chi_right", 82, 1),
            ("chi_right_red", 83, 1),
            ("pass", 84, 1),
            ("kyuushu", 85, 1),
            ("dummy", 86, 1),
        ])
    );
    assert_eq!(
        ids(&no_red),
        expect(&[
            ("discard", 0, 34),
            ("self_kan", 34, 34),
            ("tsumogiri", 68, 1),
            ("riichi", 69, 1),
            ("tsumo", 70, 1),
            ("ron", 71, 1),
            ("pon", 72, 1),
            ("open_kan", 73, 1),
            ("chi_left", 74, 1),
            ("chi_middle", 75, 1),
            ("chi_right", 76, 1),
            ("pass", 77, 1),
            ("dummy", 78, 1),
        ])
    );
    let g = generate(&red).kernel_rust;
    assert_eq!(const_text(&g, "ACTION_PASS"), "84u32");
    assert_eq!(const_text(&g, "ACTION_SELF_KAN"), "37u32");
    let g = generate(&no_red).kernel_rust;
    assert_eq!(const_text(&g, "ACTION_KYUUSHU"), "ACTION_ABSENT");
    assert_eq!(const_text(&g, "ACTION_PASS"), "77u32");
}

#[test]
fn variant_options() {
    let red = load_real("red").variant;
    let no_red = load_real("no_red").variant;
    let flag = |v: &rinshan_codegen::spec::Variant, name: &str| {
        v.bool_option(name)
            .unwrap_or_else(|| panic!("{}: no bool option `{name}`", v.name))
    };
    let number = |v: &rinshan_codegen::spec::Variant, name: &str| {
        v.u32_option(name)
            .unwrap_or_else(|| panic!("{}: no integer option `{name}`", v.name))
    };
    assert!(red.red_fives && red.abortive_draws && !no_red.red_fives && !no_red.abortive_draws);
    for name in [
        "red_fives",
        "double_ron",
        "triple_ron_abort",
        "abortive_draws",
        "nagashi_mangan",
        "pao",
    ] {
        assert!(flag(&red, name) && !flag(&no_red, name), "{name}");
    }
    // Tenhou counts the "double" yakuman once; no_red keeps the reference's doubles.
    assert!(!flag(&red, "double_yakuman") && flag(&no_red, "double_yakuman"));
    // Mahjong Soul differs from Tenhou in exactly the four rules its spec's header names.
    let mjsoul = load_real("mjsoul").variant;
    let differ: Vec<&str> = red
        .options
        .iter()
        .zip(&mjsoul.options)
        .filter(|(a, b)| a.name != b.name || a.value != b.value)
        .map(|(a, _)| a.name.as_str())
        .collect();
    assert_eq!(
        differ,
        [
            "double_yakuman",
            "triple_ron_abort",
            "kokushi_robs_closed_kan",
            "pao_share_only"
        ]
    );
    assert!(!flag(&mjsoul, "triple_ron_abort") && flag(&mjsoul, "pao_share_only"));
    assert_eq!(
        (mjsoul.uma, mjsoul.illegal_action_penalty),
        (red.uma, red.illegal_action_penalty)
    );
    // M-League differs from Tenhou in the rules its spec's header names, and nothing else.
    let mleague = load_real("mleague").variant;
    // The options (name, value in `other`) where `other` differs from red.
    let differ_from_red = |other: &rinshan_codegen::spec::Variant| -> Vec<(String, String)> {
        red.options
            .iter()
            .zip(&other.options)
            .filter(|(a, b)| a.name != b.name || a.value != b.value)
            .map(|(a, b)| (a.name.clone(), b.value.to_string()))
            .collect()
    };
    assert_eq!(
        differ_from_red(&mleague),
        [
            ("kiriage_mangan", "true"),
            ("kan_dora_at_once", "true"),
            ("kazoe_yakuman", "false"),
            ("double_wind_pair_fu", "2"),
            ("double_ron", "false"),
            ("triple_ron_abort", "false"),
            ("abortive_draws", "false"),
            ("pao_share_only", "true"),
            ("pao_pays_honba", "true"),
            ("pao_suukantsu", "true"),
            ("riichi_min_points", "0"),
            ("riichi_with_no_draw_left", "true"),
            ("bust_below_zero", "false"),
            ("west_extension", "false"),
            ("dealer_top_stop", "false"),
            ("tied_seats_share_uma", "true"),
        ]
        .map(|(n, v)| (n.to_string(), v.to_string()))
    );
    // Sanma differs from Tenhou's four-player rules in the options its spec's header names: the
    // seats (which bring the tile set, kita, no chi and tsumo loss), its honba, its noten pool, its
    // points and its three-entry uma.
    let sanma = load_real("sanma").variant;
    assert_eq!(
        differ_from_red(&sanma),
        [
            ("honba_ron_points", "200"),
            ("noten_pool_points", "2000"),
            ("seats", "3"),
            ("starting_points", "35000"),
            ("target_points", "40000"),
        ]
        .map(|(n, v)| (n.to_string(), v.to_string()))
    );
    assert_eq!((sanma.seats, sanma.uma), (3, [15, 0, -15, 0]));
    let kinds: Vec<&str> = sanma.actions.iter().map(|a| a.kind.as_str()).collect();
    assert!(
        kinds.contains(&"kita") && !kinds.iter().any(|k| k.starts_with("chi")),
        "{kinds:?}"
    );
    // 25,000 start, 30,000 return, uma +30/+10/-10/-30: measured from the start, first place
    // also takes the 20,000 oka and everyone gives back 5,000.
    let oka_and_return = [20 - 5, -5, -5, -5];
    let book = [30, 10, -10, -30];
    assert_eq!(mleague.uma, std::array::from_fn(|i| book[i] + oka_and_return[i]));
    for v in [&red, &no_red] {
        assert!(!flag(v, "pao_share_only"), "{}", v.name);
    }
    for v in [&red, &no_red] {
        assert!(!flag(v, "kiriage_mangan") && flag(v, "kazoe_yakuman") && flag(v, "multiple_yakuman"));
        assert_eq!(
            ["honba_ron_points", "honba_tsumo_points", "riichi_stick_points"].map(|n| number(v, n)),
            [300, 100, 1000]
        );
        assert_eq!(
            ["starting_points", "riichi_min_points", "target_points"].map(|n| number(v, n)),
            [25000, 1000, 30000]
        );
        // Tenhou: a double-wind pair is 4 fu, and riichi needs a draw left for every seat.
        assert_eq!(number(v, "double_wind_pair_fu"), 4);
        assert!(!flag(v, "riichi_with_no_draw_left"));
        assert!(flag(v, "bust_below_zero") && flag(v, "west_extension") && flag(v, "dealer_top_stop"));
        // Tenhou lets no hand rob a closed kan, thirteen orphans included.
        assert!(!flag(v, "kokushi_robs_closed_kan"));
        assert_eq!(v.uma, [30, 10, -10, -30]);
        assert_eq!(v.illegal_action_penalty, -1.0);
        assert_eq!(v.yaku_rules, [("open_tanyao".to_string(), true)]);
        // File order, section by section; uma and the penalty are not plain options.
        let names: Vec<&str> = v.options.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "red_fives",
                "kiriage_mangan",
                "kan_dora_at_once",
                "kazoe_yakuman",
                "multiple_yakuman",
                "double_yakuman",
                "honba_ron_points",
                "honba_tsumo_points",
                "riichi_stick_points",
                "double_wind_pair_fu",
                "double_ron",
                "triple_ron_abort",
                "kokushi_robs_closed_kan",
                "noten_pool_points",
                "abortive_draws",
                "nagashi_mangan",
                "pao",
                "pao_share_only",
                "pao_pays_honba",
                "pao_suukantsu",
                "seats",
                "starting_points",
                "riichi_min_points",
                "riichi_with_no_draw_left",
                "bust_below_zero",
                "target_points",
                "west_extension",
                "dealer_top_stop",
                "tied_seats_share_uma",
            ]
        );
    }
}

/// (a) Changing one number in the spec changes exactly that entry of the generated table.
#[test]
fn rules_are_data_tanyao_han() {
    let before = load_real("red");
    let from = "name = \"tanyao\"\nhan_closed = 1\nhan_open = 1";
    let after = load_yaku_edit("red", from, "name = \"tanyao\"\nhan_closed = 2\nhan_open = 1")
        .unwrap_or_else(|e| panic!("{}", render(&e)));
    let (g0, g1) = (generate(&before), generate(&after));
    assert_eq!(g0.host_rust, g1.host_rust);
    let (i0, i1) = (items(&g0.kernel_rust), items(&g1.kernel_rust));
    let changed: Vec<&String> = i0.keys().filter(|k| i0[*k] != i1[*k]).collect();
    assert_eq!(changed, ["YAKU_HAN_CLOSED"]);
    let (a0, a1) = (
        u32_array(&g0.kernel_rust, "YAKU_HAN_CLOSED"),
        u32_array(&g1.kernel_rust, "YAKU_HAN_CLOSED"),
    );
    let tanyao = before.yaku("tanyao").unwrap().index;
    let diff: Vec<usize> = (0..a0.len()).filter(|&i| a0[i] != a1[i]).collect();
    assert_eq!(diff, [tanyao]);
    assert_eq!((a0[tanyao], a1[tanyao]), (1, 2));
}

fn features_value<'s>(spec: &'s Spec, set: &[(&str, Value)]) -> impl Fn(&str) -> Value + 's {
    let set: Vec<(String, Value)> = set.iter().map(|(n, v)| (n.to_string(), *v)).collect();
    move |name: &str| {
        if let Some((_, v)) = set.iter().find(|(n, _)| n == name) {
            return *v;
        }
        if let Some(b) = spec.option(name) {
            return Value::Bool(b);
        }
        match spec.feature(name).map(|f| f.ty) {
            Some(rinshan_codegen::expr::Type::Int) => Value::Int(0),
            _ => Value::Bool(false),
        }
    }
}

fn holds(spec: &Spec, yaku: &str, set: &[(&str, Value)]) -> bool {
    let y = spec.yaku(yaku).unwrap();
    eval(&y.condition, &features_value(spec, set)).as_bool()
}

/// (b) A variant option reaches the yaku conditions by name.
#[test]
fn rules_are_data_open_tanyao() {
    let open_hand = [("all_simples", Value::Bool(true)), ("concealed", Value::Bool(false))];
    let closed_hand = [("all_simples", Value::Bool(true)), ("concealed", Value::Bool(true))];
    let kuitan = load_real("red");
    assert!(holds(&kuitan, "tanyao", &open_hand));
    assert!(holds(&kuitan, "tanyao", &closed_hand));
    let no_kuitan = load_variant_edit("red", "open_tanyao = true", "open_tanyao = false")
        .unwrap_or_else(|e| panic!("{}", render(&e)));
    assert!(!holds(&no_kuitan, "tanyao", &open_hand));
    assert!(holds(&no_kuitan, "tanyao", &closed_hand));
    let g = generate(&no_kuitan).kernel_rust;
    assert_eq!(const_text(&g, "OPEN_TANYAO"), "false");
    assert!(
        g.contains("let yaku_tanyao: bool = f.all_simples && (f.concealed || OPEN_TANYAO);"),
        "{g}"
    );
}

const LOCAL_YAKU: &str = r#"
[[yaku]]
name = "tanyao_pinfu_bonus"
han_closed = 1
han_open = 0
when = "all_simples && concealed && standard && runs == 4 && !pair_is_value && two_sided_wait"
description = "Local rule: a closed all-simples pinfu hand scores one more han"
"#;

/// (c) A local yaku added to the file gets an id, a table entry and a condition.
#[test]
fn rules_are_data_local_yaku() {
    let (v, y, f) = sources("red");
    let spec = load_texts("red", &v, &format!("{y}{LOCAL_YAKU}"), &f).unwrap_or_else(|e| panic!("{}", render(&e)));
    let local = spec.yaku("tanyao_pinfu_bonus").unwrap();
    assert_eq!(local.index, 45);
    let g = generate(&spec);
    assert_eq!(const_text(&g.kernel_rust, "YAKU_TANYAO_PINFU_BONUS"), "45u32");
    assert_eq!(const_text(&g.kernel_rust, "YAKU_COUNT"), "46u32");
    assert_eq!(u32_array(&g.kernel_rust, "YAKU_HAN_CLOSED")[45], 1);
    assert_eq!(u32_array(&g.kernel_rust, "YAKU_HAN_OPEN")[45], 0);
    assert_eq!(u32_array(&g.kernel_rust, "YAKU_YAKUMAN").len(), 46);
    assert!(g.kernel_rust.contains("(YAKU_TANYAO_PINFU_BONUS - 32u32)"));
    assert!(g.host_rust.contains("\"tanyao_pinfu_bonus\",\n];"), "{}", g.host_rust);
    let hand = [
        ("all_simples", Value::Bool(true)),
        ("concealed", Value::Bool(true)),
        ("standard", Value::Bool(true)),
        ("runs", Value::Int(4)),
        ("two_sided_wait", Value::Bool(true)),
    ];
    assert!(holds(&spec, "tanyao_pinfu_bonus", &hand));
    assert!(!holds(&spec, "tanyao_pinfu_bonus", &hand[..4]));
}

#[test]
fn generation_is_deterministic() {
    let spec = load_real("red");
    assert_eq!(generate(&spec), generate(&load_real("red")));
}

/// A combination rule naming an option no variant has would never fire.
#[test]
fn option_rules_name_real_options() {
    for variant in ["red", "no_red"] {
        let v = load_real(variant).variant;
        for rule in rinshan_codegen::option_rules::OPTION_RULES {
            for path in [rule.option, rule.needs] {
                let (section, name) = path.split_once('.').expect("section.name");
                assert!(
                    v.options.iter().any(|o| o.section == section && o.name == name),
                    "{variant}: no option `{path}`"
                );
            }
        }
    }
}
