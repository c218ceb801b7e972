//! The plain options of a variant: every key of `[tiles]`, `[scoring]`, `[claims]`, `[draws]`,
//! `[liability]` and `[game]`, typed by its TOML value. Nothing here names an option, so adding one
//! takes only its line in the variant files and the kernel code that reads its constant.

use super::{generated_name, is_snake_ident, Checker};
use crate::diag::did_you_mean;
use crate::model::{OptionTable, VariantFile};
use crate::option_rules;
use crate::spec::{OptionValue, VariantOption};
use serde_spanned::Spanned;
use std::collections::BTreeSet;

/// Keys of the option sections that are not plain options: the checker reads them itself
/// (`uma` is an array, `illegal_action_penalty` a float).
pub(super) const SPECIAL: [(&str, &str); 2] = [("game", "uma"), ("game", "illegal_action_penalty")];

/// A checked option and where its key and value were written.
pub(super) struct Located {
    pub option: VariantOption,
    pub key_at: usize,
    pub value_at: usize,
}

/// Reads every plain option in file order, then checks the combination rules and, given the
/// kernel's identifiers, that the kernel names each option's constant.
pub(super) fn read(c: &mut Checker<'_>, vf: &VariantFile, kernel_names: Option<&BTreeSet<String>>) -> Vec<Located> {
    let mut entries = Vec::new();
    for (section, table) in vf.option_sections() {
        for (key, value) in table.get_ref() {
            if !SPECIAL.contains(&(section, key.get_ref().as_str())) {
                entries.push((section, key, value));
            }
        }
    }
    entries.sort_by_key(|(_, key, _)| key.span().start);

    let mut out: Vec<Located> = Vec::new();
    for (section, key, value) in entries {
        let name = key.get_ref();
        let key_at = key.span().start;
        let upper = name.to_ascii_uppercase();
        if !is_snake_ident(name) {
            c.variant_err(
                key_at,
                format!("option `{name}` is not a snake_case name (it names a constant); write e.g. `double_ron`"),
            );
            continue;
        }
        if let Some(first) = out.iter().find(|o| o.option.name == *name) {
            let (line, _) = c.variant_src.line_col(first.key_at);
            c.variant_err(
                key_at,
                format!(
                    "option `{name}` is also in `[{}]` (line {line}); both would be the constant `{upper}`, rename one",
                    first.option.section
                ),
            );
            continue;
        }
        if generated_name(name) {
            c.variant_err(
                key_at,
                format!("option `{name}` would clash with a generated constant (`{upper}`); rename it"),
            );
            continue;
        }
        if let Some(kernel) = kernel_names.filter(|k| !k.contains(&upper)) {
            let constants = kernel
                .iter()
                .filter(|n| {
                    n.chars()
                        .all(|ch| ch.is_ascii_uppercase() || ch.is_ascii_digit() || ch == '_')
                })
                .map(|n| n.to_ascii_lowercase())
                .collect::<Vec<_>>();
            c.variant_err(
                key_at,
                format!(
                    "option `{name}` is read by no kernel code (no `{upper}` in rules/kernel/){}; remove it, or read `{upper}` in the kernel",
                    did_you_mean(name, constants.iter().map(String::as_str))
                ),
            );
            continue;
        }
        let Some(typed) = typed(c, name, value) else {
            continue;
        };
        out.push(Located {
            option: VariantOption {
                section: section.to_string(),
                name: name.clone(),
                value: typed,
            },
            key_at,
            value_at: value.span().start,
        });
    }

    let options: Vec<VariantOption> = out.iter().map(|o| o.option.clone()).collect();
    for (i, message) in option_rules::violations(&options) {
        c.variant_err(out[i].value_at, message);
    }
    out
}

fn typed(c: &mut Checker<'_>, name: &str, value: &Spanned<toml::Value>) -> Option<OptionValue> {
    let at = value.span().start;
    match value.get_ref() {
        toml::Value::Boolean(b) => Some(OptionValue::Bool(*b)),
        toml::Value::Integer(n) => match u32::try_from(*n) {
            Ok(n) => Some(OptionValue::U32(n)),
            Err(_) => {
                c.variant_err(
                    at,
                    format!(
                        "`{name} = {n}` is out of range: an integer option is a `u32` constant; write a value from 0 to {}",
                        u32::MAX
                    ),
                );
                None
            }
        },
        other => {
            c.variant_err(
                at,
                format!(
                    "`{name}` is a TOML {}; an option is `true`/`false` (a `bool` constant) or a whole number from 0 to {} (a `u32` constant)",
                    other.type_str(),
                    u32::MAX
                ),
            );
            None
        }
    }
}

/// A bool option that codegen itself reads (`why` says what for); false after an error.
pub(super) fn required_bool(
    c: &mut Checker<'_>,
    options: &[Located],
    (section, table): (&str, &OptionTable),
    name: &str,
    why: &str,
) -> bool {
    let found = options
        .iter()
        .find(|o| o.option.section == section && o.option.name == name);
    match found.map(|o| (o.option.value, o.value_at)) {
        Some((OptionValue::Bool(b), _)) => b,
        Some((OptionValue::U32(_), at)) => {
            c.variant_err(at, format!("`{name}` must be `true` or `false` ({why})"));
            false
        }
        // A key that is present but was rejected has its error already.
        None if table.get_ref().keys().any(|k| k.get_ref() == name) => false,
        None => {
            c.variant_err(
                table.span().start,
                format!("`[{section}]` lacks `{name}`; add `{name} = true` or `{name} = false` ({why})"),
            );
            false
        }
    }
}

/// A special value of `[game]`; reports its absence.
pub(super) fn special<'a>(
    c: &mut Checker<'_>,
    game: &'a OptionTable,
    name: &str,
    example: &str,
) -> Option<&'a Spanned<toml::Value>> {
    let found = game.get_ref().iter().find(|(k, _)| k.get_ref() == name).map(|(_, v)| v);
    if found.is_none() {
        c.variant_err(
            game.span().start,
            format!("`[game]` lacks `{name}`; add e.g. `{example}`"),
        );
    }
    found
}
