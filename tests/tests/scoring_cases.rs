//! Hand-scoring cases whose expected values were worked out from the rules (tests/data/scoring_cases.toml).

use std::collections::BTreeMap;

use rinshan_engine::hand::{score, Payment, Win, WinContext};
use rinshan_engine::notation::{parse_meld, parse_tile, parse_tiles, parse_wind};
use rinshan_engine::{TileType, Variant};
use rinshan_tests::test_data;
use serde::Deserialize;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    pub name: String,
    pub hand: String,
    pub win: String,
    #[serde(default)]
    pub tsumo: bool,
    #[serde(default)]
    pub riichi: bool,
    #[serde(default)]
    pub double_riichi: bool,
    #[serde(default)]
    pub ippatsu: bool,
    #[serde(default)]
    pub haitei: bool,
    #[serde(default)]
    pub houtei: bool,
    #[serde(default)]
    pub rinshan: bool,
    #[serde(default)]
    pub chankan: bool,
    #[serde(default)]
    pub tenhou: bool,
    #[serde(default)]
    pub chiihou: bool,
    #[serde(default)]
    pub dealer: bool,
    pub round_wind: Option<String>,
    pub seat_wind: Option<String>,
    #[serde(default)]
    pub melds: Vec<String>,
    #[serde(default)]
    pub dora: Vec<String>,
    #[serde(default)]
    pub ura: Vec<String>,
    #[serde(default)]
    pub honba: u32,
    #[serde(default)]
    pub sticks: u32,
    pub variant: Option<String>,
    pub han: u32,
    pub fu: u32,
    pub yakuman: u32,
    pub yaku: BTreeMap<String, u32>,
    pub ron: Option<u32>,
    pub dealer_pays: Option<u32>,
    pub others_pay: Option<u32>,
}

#[derive(Deserialize)]
struct File {
    case: Vec<Case>,
}

pub fn load_cases() -> Vec<Case> {
    let path = test_data().join("scoring_cases.toml");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let file: File = toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    file.case
}

pub fn to_win(c: &Case) -> (Variant, Win) {
    let variant = Variant::from_name(c.variant.as_deref().unwrap_or("red")).expect("variant");
    let tiles = parse_tiles(&c.hand).unwrap_or_else(|e| panic!("{}: {e}", c.name));
    let win = parse_tile(&c.win).unwrap_or_else(|e| panic!("{}: {e}", c.name)).kind();
    let melds: Vec<_> = c
        .melds
        .iter()
        .map(|m| parse_meld(m).unwrap_or_else(|e| panic!("{}: {e}", c.name)))
        .collect();
    let aka = tiles.red() + melds.iter().map(|m| m.red).sum::<u8>();
    let wind = |w: &Option<String>, default: u8| w.as_deref().map_or(default, |s| parse_wind(s).expect("wind"));
    let indicators = |v: &Vec<String>| -> Vec<TileType> {
        v.iter()
            .flat_map(|s| parse_tiles(s).expect("indicator").tiles.into_iter().map(|t| t.kind()))
            .collect()
    };
    let seat_wind = wind(&c.seat_wind, if c.dealer { 0 } else { 1 });
    let context = WinContext {
        tsumo: c.tsumo,
        riichi: c.riichi || c.double_riichi,
        double_riichi: c.double_riichi,
        ippatsu: c.ippatsu,
        haitei: c.haitei,
        houtei: c.houtei,
        rinshan: c.rinshan,
        chankan: c.chankan,
        tenhou: c.tenhou,
        chiihou: c.chiihou,
        dealer: c.dealer,
        round_wind: wind(&c.round_wind, 0),
        seat_wind,
        dora: indicators(&c.dora),
        ura: indicators(&c.ura),
        honba: c.honba,
        sticks: c.sticks,
    };
    (
        variant,
        Win {
            hand: tiles.counts(),
            win,
            melds,
            aka,
            context,
        },
    )
}

#[test]
fn every_case_scores_as_the_rules_say() {
    let cases = load_cases();
    assert!(cases.len() >= 60, "at least 60 cases, found {}", cases.len());
    let mut failures = Vec::new();
    for c in &cases {
        let (variant, win) = to_win(c);
        let s = match score(variant, &win) {
            Ok(s) => s,
            Err(e) => {
                failures.push(format!("{}: {e}", c.name));
                continue;
            }
        };
        let yaku: BTreeMap<String, u32> = s.yaku.iter().map(|y| (y.name.to_string(), y.han.number())).collect();
        let (ron, dealer_pays, others_pay) = match s.payment {
            Payment::Ron { discarder } => (Some(discarder), None, None),
            Payment::Tsumo { dealer, others } => (None, dealer, Some(others)),
        };
        let expected_dealer_pays = if c.dealer { None } else { c.dealer_pays };
        let got = (s.han, s.fu, s.yakuman, &yaku, ron, dealer_pays, others_pay);
        let want = (
            c.han,
            c.fu,
            c.yakuman,
            &c.yaku,
            c.ron,
            expected_dealer_pays,
            c.others_pay,
        );
        if got != want {
            failures.push(format!("{}:\n    expected {want:?}\n    got      {got:?}", c.name));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases differ:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

#[test]
fn cases_cover_every_yaku_of_the_spec() {
    let cases = load_cases();
    let covered: std::collections::BTreeSet<&str> =
        cases.iter().flat_map(|c| c.yaku.keys().map(String::as_str)).collect();
    let names = rinshan_engine::generated::red::host::YAKU_NAMES;
    let missing: Vec<&&str> = names.iter().filter(|n| !covered.contains(**n)).collect();
    assert!(missing.is_empty(), "yaku without a scoring case: {missing:?}");
}

#[test]
fn every_case_is_identical_on_the_gpu() {
    let Some(mut gpu) = rinshan_tests::gpu_or_skip("scoring cases on the gpu") else {
        return;
    };
    let cases = load_cases();
    for &variant in Variant::ALL {
        let chosen: Vec<_> = cases
            .iter()
            .map(to_win)
            .filter(|(v, _)| *v == variant)
            .map(|(_, w)| w)
            .collect();
        if chosen.is_empty() {
            continue;
        }
        let inputs: Vec<u32> = chosen
            .iter()
            .flat_map(|w| rinshan_engine::hand::score_input(w).expect("consistent"))
            .collect();
        let mut cpu = vec![0u32; chosen.len() * rinshan_engine::hand::SCORE_OUT_WORDS];
        rinshan_engine::hand::score_batch(variant, &inputs, &mut cpu);
        let out = gpu
            .run(variant, rinshan_engine::gpu::Kernel::Score, &inputs)
            .expect("gpu run");
        assert_eq!(out, cpu, "{variant}");
    }
}
