//! The rule set a `start_game` names. rinshan writes its own (`"variant":"mleague"`, for every
//! rule set but Tenhou's, as its tenhou.net/6 logs do); jansou writes its `"preset"` and its whole
//! configuration as a `"rules"` object. A log is played under the rule set of rinshan's that
//! matches, and refused, naming the rules, where rinshan has none.
//!
//! A `rules` object is held to the rule set by the rules both projects model: each jansou key
//! beside the option of rinshan's specs that says the same. Three keys are left out, where the
//! two read the same real rule set differently (so jansou's own presets would not match
//! rinshan's): the three-player noten pool, who pays a pao ron's honba, and M-League's nagashi.

use rinshan_engine::Variant;
use serde_json::{Map, Value};

/// jansou's presets and the rule sets of rinshan's that play them.
const PRESETS: [(&str, Variant); 5] = [
    ("tenhou", Variant::Red),
    ("mahjong-soul", Variant::Mjsoul),
    ("tenhou-3p", Variant::Sanma),
    ("mahjong-soul-3p", Variant::MjsoulSanma),
    ("m-league", Variant::Mleague),
];

/// jansou's keys beside the spec options that say the same (`negated`: the opposite).
const SAME: [(&str, &str, bool); 19] = [
    ("player_count", "seats", false),
    ("starting_points", "starting_points", false),
    ("aka_dora", "red_fives", false),
    ("kiriage_mangan", "kiriage_mangan", false),
    ("kazoe_yakuman", "kazoe_yakuman", false),
    ("multiple_yakuman", "multiple_yakuman", false),
    ("double_yakuman", "double_yakuman", false),
    ("double_wind_fu", "double_wind_pair_fu", false),
    ("multiple_ron", "double_ron", false),
    ("kokushi_ankan_chankan", "kokushi_robs_closed_kan", false),
    ("kuitan", "open_tanyao", false),
    ("pao_suukantsu", "pao_suukantsu", false),
    ("riichi_without_draw", "riichi_with_no_draw_left", false),
    ("sudden_death_target", "target_points", false),
    ("abort_kyuushu_kyuuhai", "abortive_draws", false),
    ("sudden_death", "west_extension", false),
    ("agari_yame", "dealer_top_stop", false),
    ("rank_ties_shared", "tied_seats_share_uma", false),
    ("allow_negative_scores", "bust_below_zero", true),
];

/// Rules every rule set of rinshan's plays the same way, with their value there.
const FIXED: [(&str, &str); 7] = [
    ("ura_dora", "true"),
    ("kan_dora", "true"),
    ("ippatsu", "true"),
    ("riichi_without_tenpai", "false"),
    ("closed_kan_after_riichi", "true"),
    ("kuikae_ban", "true"),
    ("honba_value", "100"),
];

/// A JSON value as the specs write option values (`true`, `25000`).
fn option_text(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Where `rules` differ from `variant`: (key, the log's value, the rule set's).
fn differences(rules: &Map<String, Value>, variant: Variant) -> Vec<(&'static str, String, String)> {
    let mut out = Vec::new();
    for (key, option, negated) in SAME {
        let (Some(theirs), Some(ours)) = (rules.get(key), variant.option(option)) else {
            continue;
        };
        let theirs = match (theirs, negated) {
            (Value::Bool(b), true) => (!b).to_string(),
            (v, _) => option_text(v),
        };
        if theirs != ours {
            let shown = |v: &str| {
                if negated {
                    v.replace("true", "no").replace("false", "yes")
                } else {
                    v.into()
                }
            };
            out.push((key, shown(&theirs), shown(ours)));
        }
    }
    out
}

/// What a `start_game` names: rinshan's `variant`, jansou's `preset` and its `rules`. `None`
/// when it names none (the log plays Tenhou's rules, at three players or four).
pub(super) fn rule_set(
    variant: Option<&str>,
    preset: Option<&str>,
    rules: Option<&Map<String, Value>>,
) -> Result<Option<Variant>, String> {
    if let Some(rules) = rules {
        let unmodelled: Vec<String> = FIXED
            .iter()
            .filter_map(|(key, ours)| {
                let theirs = option_text(rules.get(*key)?);
                (theirs != *ours).then(|| format!("{key} {theirs} (rinshan plays {ours} in every rule set)"))
            })
            .collect();
        if !unmodelled.is_empty() {
            return Err(format!(
                "start_game's rules: rinshan does not model {}",
                unmodelled.join(", ")
            ));
        }
    }
    let named = match (variant, preset) {
        (Some(name), _) => Some(
            name.parse::<Variant>()
                .map_err(|e| format!("start_game's variant: {e}"))?,
        ),
        (None, Some(preset)) => match PRESETS.iter().find(|(p, _)| *p == preset) {
            Some(&(_, v)) => Some(v),
            // A preset rinshan lacks: its rules (when given) say what differs.
            None if rules.is_some() => None,
            None => {
                let known: Vec<&str> = PRESETS.iter().map(|(p, _)| *p).collect();
                return Err(format!(
                    "start_game's preset {preset:?}: rinshan has no such rule set (it plays jansou's {})",
                    known.join(", ")
                ));
            }
        },
        (None, None) => None,
    };
    let Some(rules) = rules else {
        return Ok(named);
    };
    let candidates: Vec<Variant> = match named {
        Some(v) => vec![v],
        None => Variant::ALL.to_vec(),
    };
    let nearest = candidates
        .iter()
        .map(|&v| (v, differences(rules, v)))
        .min_by_key(|(_, d)| d.len());
    match nearest {
        Some((v, d)) if d.is_empty() => Ok(Some(v)),
        Some((v, d)) => {
            let listed: Vec<String> = d
                .iter()
                .map(|(key, theirs, ours)| format!("{key} {theirs} ({v} plays {ours})"))
                .collect();
            let which = match (named, preset) {
                (Some(_), _) => format!("{v}, the rule set it names,"),
                (None, Some(p)) => format!("no rule set of rinshan's plays jansou's {p:?}; the nearest, {v},"),
                (None, None) => format!("no rule set of rinshan's plays them; the nearest, {v},"),
            };
            Err(format!("start_game's rules: {which} differs in {}", listed.join(", ")))
        }
        None => Ok(named),
    }
}

/// The rule set a log of `variant` names in its `start_game`: none for Tenhou's (the reader's
/// default), as rinshan's tenhou.net/6 logs do.
pub(crate) fn named(variant: Variant) -> Option<String> {
    (variant != Variant::Red).then(|| variant.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// jansou 0.14.0's presets as its `dump_mjai` writes them in `start_game` (tests/data/mjai).
    fn jansou(preset: &str) -> Map<String, Value> {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/mjai/jansou_rules.json");
        let all: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("reads")).expect("JSON");
        all[preset]
            .as_object()
            .cloned()
            .unwrap_or_else(|| panic!("no preset {preset}"))
    }

    #[test]
    fn presets_and_their_rules_name_rinshans_rule_sets() {
        assert_eq!(rule_set(None, None, None), Ok(None));
        assert_eq!(rule_set(Some("mleague"), None, None), Ok(Some(Variant::Mleague)));
        assert_eq!(
            rule_set(Some("mjsoul-sanma"), None, None),
            Ok(Some(Variant::MjsoulSanma))
        );
        for (preset, variant) in PRESETS {
            let rules = jansou(preset);
            assert_eq!(rule_set(None, Some(preset), None), Ok(Some(variant)));
            assert_eq!(
                rule_set(None, Some(preset), Some(&rules)),
                Ok(Some(variant)),
                "{preset}"
            );
            // Its rules alone tell the rule set too.
            assert_eq!(rule_set(None, None, Some(&rules)), Ok(Some(variant)), "{preset}");
        }
        for v in Variant::ALL {
            assert_eq!(
                rule_set(named(*v).as_deref(), None, None),
                Ok((*v != Variant::Red).then_some(*v))
            );
        }
    }

    #[test]
    fn rules_rinshan_does_not_play_are_refused_by_name() {
        let err = |r: Result<Option<Variant>, String>| r.expect_err("refused");
        let message = err(rule_set(None, Some("renmei"), Some(&jansou("renmei"))));
        assert!(message.contains("rinshan does not model ura_dora false"), "{message}");
        assert!(message.contains("ippatsu false"), "{message}");
        let message = err(rule_set(None, Some("kyokai"), None));
        assert!(
            message.contains("preset \"kyokai\": rinshan has no such rule set"),
            "{message}"
        );
        // Kiriage mangan on Tenhou's rules: no rule set of rinshan's plays that.
        let mut custom = jansou("tenhou");
        custom.insert("kiriage_mangan".into(), true.into());
        let message = err(rule_set(None, None, Some(&custom)));
        assert!(
            message.contains("the nearest, red, differs in kiriage_mangan true (red plays false)"),
            "{message}"
        );
        let message = err(rule_set(None, Some("tenhou"), Some(&custom)));
        assert!(
            message.contains("red, the rule set it names, differs in kiriage_mangan"),
            "{message}"
        );
        let message = err(rule_set(Some("tenhou-rules"), None, None));
        assert!(message.contains("start_game's variant"), "{message}");
    }
}
