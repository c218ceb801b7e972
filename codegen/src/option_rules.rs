//! Plain options that mean nothing without another one. Each rule is written once, here, as data;
//! the checker reports a broken one at the option that needs the other.
//!
//! A rule belongs here only when the kernel (`rules/kernel/`) ignores the option unless the other
//! is set, so the file would claim a rule the game never plays.

use crate::spec::{OptionValue, VariantOption};

/// `option` set (`true`, or above 0) needs `needs` set too. Both are `section.name`.
#[derive(Clone, Copy, Debug)]
pub struct Needs {
    pub option: &'static str,
    pub needs: &'static str,
    /// Why the option alone means nothing; ends the error message.
    pub why: &'static str,
}

pub const OPTION_RULES: [Needs; 3] = [
    Needs {
        option: "claims.triple_ron_abort",
        needs: "claims.double_ron",
        why: "three rons on one discard can only happen with double ron; with head bump the first \
              in turn order wins alone",
    },
    Needs {
        option: "scoring.double_yakuman",
        needs: "scoring.multiple_yakuman",
        why: "without multiple yakuman every hand is capped at one yakuman, so a double one never \
              counts twice",
    },
    Needs {
        option: "game.west_extension",
        needs: "game.target_points",
        why: "the West round goes on until someone reaches target_points, and with 0 the top \
              player always has",
    },
];

/// `section.name` of a rule, split.
fn parts(path: &str) -> (&str, &str) {
    path.split_once('.').unwrap_or(("", path))
}

fn find<'a>(options: &'a [VariantOption], path: &str) -> Option<(usize, &'a VariantOption)> {
    let (section, name) = parts(path);
    options
        .iter()
        .enumerate()
        .find(|(_, o)| o.section == section && o.name == name)
}

fn set_text(name: &str, value: OptionValue) -> String {
    match value {
        OptionValue::Bool(_) => format!("`{name} = true`"),
        OptionValue::U32(_) => format!("`{name}` above 0"),
    }
}

fn unset_text(name: &str, value: OptionValue) -> String {
    match value {
        OptionValue::Bool(_) => format!("`{name} = false`"),
        OptionValue::U32(_) => format!("`{name} = 0`"),
    }
}

/// Every broken rule: (index in `options` of the option that needs another, message).
pub fn violations(options: &[VariantOption]) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for rule in &OPTION_RULES {
        let Some((at, o)) = find(options, rule.option) else {
            continue;
        };
        if !o.value.is_set() {
            continue;
        }
        let written = format!("`{} = {}`", o.name, o.value);
        let unset = unset_text(&o.name, o.value);
        let why = rule.why;
        let message = match find(options, rule.needs) {
            Some((_, n)) if n.value.is_set() => continue,
            Some((_, n)) => {
                let set = set_text(&n.name, n.value);
                format!("{written} needs {set} ({why}); write {unset} or {set}")
            }
            None => {
                let (section, name) = parts(rule.needs);
                format!(
                    "{written} needs `{name}` in `[{section}]`, which this file lacks ({why}); add it or write {unset}"
                )
            }
        };
        out.push((at, message));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn opt(section: &str, name: &str, value: OptionValue) -> VariantOption {
        VariantOption {
            section: section.into(),
            name: name.into(),
            value,
        }
    }

    #[test]
    fn a_rule_fires_only_when_the_option_is_set_and_the_other_is_not() {
        let west = |on, target| {
            vec![
                opt("game", "target_points", OptionValue::U32(target)),
                opt("game", "west_extension", OptionValue::Bool(on)),
            ]
        };
        assert!(violations(&west(true, 30000)).is_empty());
        assert!(violations(&west(false, 0)).is_empty());
        let v = violations(&west(true, 0));
        assert_eq!(v.len(), 1);
        assert_eq!(v[0].0, 1);
        assert!(v[0]
            .1
            .starts_with("`west_extension = true` needs `target_points` above 0 ("));
        let v = violations(&[opt("claims", "triple_ron_abort", OptionValue::Bool(true))]);
        assert!(v[0]
            .1
            .contains("needs `double_ron` in `[claims]`, which this file lacks"));
    }
}
