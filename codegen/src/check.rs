//! Semantic checks: raw model (`model`) -> checked spec (`spec`), or every error found.
//!
//! The checker keeps going after an error so one run reports as much as it can; each message says
//! what to write instead.

use crate::diag::{did_you_mean, Diagnostic, Source};
use crate::expr::{self, Scope, Type};
use crate::model::{ActionsSection, VariantFile, YakuFile, YakuRaw};
use crate::spec::{discard_count, ActionBlock, Feature, Need, OptionValue, Spec, Variant, Yaku, ACTION_KINDS};
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;

mod options;

/// The yaku mask is two u32 words in the kernel.
pub const MAX_YAKU: usize = 64;

/// Whether `name` in SCREAMING_CASE is a constant the emitter makes from something other than an
/// option (the action layout and the yaku table), so no option may take it.
fn generated_name(name: &str) -> bool {
    name == "num_actions" || name.starts_with("yaku_") || name.starts_with("action_")
}

fn is_snake_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('a'..='z')) && chars.all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

/// Reads `struct Features` from the kernel source: its field names and types (bool or u32).
pub fn parse_features(path: &str, text: &str) -> Result<Vec<Feature>, Vec<Diagnostic>> {
    let at = |span: proc_macro2::Span, message: String| {
        let start = span.start();
        Diagnostic {
            file: path.to_string(),
            line: start.line.max(1),
            column: start.column + 1,
            message,
        }
    };
    let file = syn::parse_file(text).map_err(|e| vec![at(e.span(), format!("cannot parse the features file: {e}"))])?;
    let Some(item) = file.items.iter().find_map(|item| match item {
        syn::Item::Struct(s) if s.ident == "Features" => Some(s),
        _ => None,
    }) else {
        return Err(vec![Diagnostic {
            file: path.to_string(),
            line: 1,
            column: 1,
            message: "no `struct Features` found; the yaku conditions read its fields".into(),
        }]);
    };
    let syn::Fields::Named(fields) = &item.fields else {
        return Err(vec![at(
            item.ident.span(),
            "`Features` must have named fields (`pub name: bool` or `pub name: u32`)".into(),
        )]);
    };
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for field in &fields.named {
        let Some(ident) = &field.ident else { continue };
        let ty = match &field.ty {
            syn::Type::Path(p) if p.qself.is_none() && p.path.is_ident("bool") => Some(Type::Bool),
            syn::Type::Path(p) if p.qself.is_none() && p.path.is_ident("u32") => Some(Type::Int),
            _ => None,
        };
        match ty {
            Some(ty) => out.push(Feature {
                name: ident.to_string(),
                ty,
            }),
            None => {
                let ty = &field.ty;
                let written = quote::quote!(#ty).to_string();
                errors.push(at(
                    syn::spanned::Spanned::span(&field.ty),
                    format!(
                        "feature `{ident}` has type `{written}`; features must be `bool` or `u32` \
                         (pack smaller values into a u32)"
                    ),
                ));
            }
        }
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// Byte offset in the file of byte `offset` of a string value whose raw text (quotes included,
/// as toml reports it) spans `span`. Escapes and multi-line delimiters are walked so that a
/// column inside a condition lands on the right character.
fn string_offset(src: &Source<'_>, span: &Range<usize>, offset: usize) -> usize {
    let Some(raw) = src.text.get(span.clone()) else {
        return span.start;
    };
    let (delim, basic) = if raw.starts_with("'''") {
        (3, false)
    } else if raw.starts_with("\"\"\"") {
        (3, true)
    } else if raw.starts_with('\'') {
        (1, false)
    } else if raw.starts_with('"') {
        (1, true)
    } else {
        return span.start + offset;
    };
    let mut body = &raw[delim..];
    let mut base = span.start + delim;
    if delim == 3 {
        // A newline right after the opening delimiter is not part of the value.
        for nl in ["\r\n", "\n"] {
            if let Some(rest) = body.strip_prefix(nl) {
                base += nl.len();
                body = rest;
                break;
            }
        }
    }
    if !basic {
        return base + offset;
    }
    let mut decoded = 0;
    let mut it = body.char_indices().peekable();
    while let Some((i, c)) = it.next() {
        if decoded >= offset {
            return base + i;
        }
        if c != '\\' {
            decoded += c.len_utf8();
            continue;
        }
        let Some(&(_, e)) = it.peek() else { break };
        match e {
            'u' | 'U' | 'x' => {
                let digits = match e {
                    'u' => 4,
                    'U' => 8,
                    _ => 2,
                };
                it.next();
                let hex: String = (0..digits).filter_map(|_| it.next().map(|(_, h)| h)).collect();
                let ch = u32::from_str_radix(&hex, 16)
                    .ok()
                    .and_then(char::from_u32)
                    .unwrap_or('?');
                decoded += ch.len_utf8();
            }
            ' ' | '\t' | '\r' | '\n' => {
                // Line-ending backslash (multi-line strings): the whitespace up to the next
                // non-blank character is dropped.
                while matches!(it.peek(), Some(&(_, ' ' | '\t' | '\r' | '\n'))) {
                    it.next();
                }
            }
            _ => {
                it.next();
                decoded += 1;
            }
        }
    }
    base + body.len().min(offset)
}

struct Checker<'a> {
    variant_src: Source<'a>,
    yaku_src: Source<'a>,
    errors: Vec<Diagnostic>,
}

impl Checker<'_> {
    fn variant_err(&mut self, offset: usize, message: impl Into<String>) {
        let d = self.variant_src.error_at(offset, message);
        self.errors.push(d);
    }

    fn yaku_err(&mut self, offset: usize, message: impl Into<String>) {
        let d = self.yaku_src.error_at(offset, message);
        self.errors.push(d);
    }
}

/// Checks a parsed variant, yaku file and feature list; with `kernel_names` (every identifier in
/// the kernel code), also that the kernel names every plain option's constant.
pub fn check(
    (variant_path, variant_text): (&str, &str),
    (yaku_path, yaku_text): (&str, &str),
    features: Vec<Feature>,
    kernel_names: Option<&BTreeSet<String>>,
) -> Result<Spec, Vec<Diagnostic>> {
    let variant_src = Source::new(variant_path, variant_text);
    let yaku_src = Source::new(yaku_path, yaku_text);
    let vf: Result<VariantFile, _> = toml::from_str(variant_text);
    let yf: Result<YakuFile, _> = toml::from_str(yaku_text);
    let mut errors = Vec::new();
    if let Err(e) = &vf {
        errors.push(variant_src.toml_error(e));
    }
    if let Err(e) = &yf {
        errors.push(yaku_src.toml_error(e));
    }
    let (Ok(vf), Ok(yf)) = (vf, yf) else {
        return Err(errors);
    };
    let mut c = Checker {
        variant_src,
        yaku_src,
        errors,
    };
    let variant = check_variant(&mut c, &vf, &features, kernel_names);
    let yaku = check_yaku(&mut c, &yf, &vf, &features);
    if c.errors.is_empty() {
        Ok(Spec {
            variant,
            yaku,
            features,
        })
    } else {
        Err(c.errors)
    }
}

fn check_variant(
    c: &mut Checker<'_>,
    vf: &VariantFile,
    features: &[Feature],
    kernel_names: Option<&BTreeSet<String>>,
) -> Variant {
    let name = vf.variant.name.get_ref().clone();
    let stem = std::path::Path::new(c.variant_src.path)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or(&name)
        .to_string();
    if name != stem {
        c.variant_err(
            vf.variant.name.span().start,
            format!("variant name `{name}` differs from its file name; write `name = \"{stem}\"`"),
        );
    }

    let options = options::read(c, vf, kernel_names);

    for key in vf.yaku_rules.keys() {
        let k = key.get_ref();
        let at = key.span().start;
        if !is_snake_ident(k) {
            c.variant_err(
                at,
                format!("option `{k}` is not a snake_case name; write e.g. `open_tanyao`"),
            );
        } else if features.iter().any(|f| f.name == *k) {
            c.variant_err(
                at,
                format!(
                    "option `{k}` has the name of a feature; conditions could not tell them apart, rename the option"
                ),
            );
        } else if let Some(o) = options.iter().find(|o| o.option.name == *k) {
            c.variant_err(
                at,
                format!(
                    "option `{k}` would clash with the constant of `[{}] {k}` (`{}`); rename it",
                    o.option.section,
                    k.to_ascii_uppercase()
                ),
            );
        } else if generated_name(k) {
            c.variant_err(
                at,
                format!(
                    "option `{k}` would clash with a generated constant (`{}`); rename it",
                    k.to_ascii_uppercase()
                ),
            );
        }
    }

    let seats = check_seats(c, &options, vf);
    let uma = check_uma(c, vf, seats);
    let illegal_action_penalty = check_penalty(c, vf);
    if let Some(o) = options.iter().find(|o| o.option.name == "starting_points") {
        if !matches!(o.option.value, OptionValue::U32(1..)) {
            c.variant_err(o.value_at, "starting_points must be positive, e.g. `25000`");
        }
    }

    let red_fives = options::required_bool(
        c,
        &options,
        ("tiles", &vf.tiles),
        "red_fives",
        "the discard ids and the `*_red` actions follow it",
    );
    let abortive_draws = options::required_bool(
        c,
        &options,
        ("draws", &vf.draws),
        "abortive_draws",
        "the `kyuushu` action follows it",
    );
    let (actions, num_actions) = check_actions(c, &vf.actions, red_fives, abortive_draws, seats);

    Variant {
        name,
        description: vf.variant.description.clone(),
        red_fives,
        abortive_draws,
        seats,
        yaku_rules: vf
            .yaku_rules
            .iter()
            .map(|(k, v)| (k.get_ref().clone(), *v.get_ref()))
            .collect(),
        options: options.into_iter().map(|o| o.option).collect(),
        uma,
        illegal_action_penalty,
        num_actions,
        actions,
    }
}

/// `[game] seats`: 4, or 3 for the three-player game. Reported where it is wrong; 4 then, so that
/// the checks that follow it do not pile up.
fn check_seats(c: &mut Checker<'_>, options: &[options::Located], vf: &VariantFile) -> u32 {
    let found = options
        .iter()
        .find(|o| o.option.section == "game" && o.option.name == "seats");
    match found.map(|o| (o.option.value, o.value_at)) {
        Some((OptionValue::U32(n @ 3..=4), _)) => n,
        Some((_, at)) => {
            c.variant_err(at, "seats must be 4, or 3 for the three-player game (sanma)");
            4
        }
        None if vf.game.get_ref().keys().any(|k| k.get_ref() == "seats") => 4,
        None => {
            c.variant_err(
                vf.game.span().start,
                "`[game]` lacks `seats`; add `seats = 4` (or 3 for the three-player game)",
            );
            4
        }
    }
}

/// `[game] uma`: one integer per seat (thousands of points) summing to 0.
fn check_uma(c: &mut Checker<'_>, vf: &VariantFile, seats: u32) -> [i32; 4] {
    let mut uma = [0i32; 4];
    let Some(value) = options::special(c, &vf.game, "uma", "uma = [30, 10, -10, -30]") else {
        return uma;
    };
    let at = value.span().start;
    let Ok(uma_vec) = value.get_ref().clone().try_into::<Vec<i32>>() else {
        c.variant_err(
            at,
            "uma must be a list of integers, one per place in thousands of points, e.g. `uma = [30, 10, -10, -30]`",
        );
        return uma;
    };
    if uma_vec.len() != seats as usize {
        c.variant_err(
            at,
            format!(
                "uma has {} entries, but the game has {seats} seats; write one per place, in thousands of points, e.g. `uma = [30, 10, -10, -30]`",
                uma_vec.len()
            ),
        );
    } else {
        uma[..uma_vec.len()].copy_from_slice(&uma_vec);
        let sum: i64 = uma.iter().map(|&u| i64::from(u)).sum();
        if sum != 0 {
            c.variant_err(
                at,
                format!("uma sums to {sum}, not 0; uma only moves points between players"),
            );
        }
    }
    uma
}

/// `[game] illegal_action_penalty`: a finite f32 reward.
fn check_penalty(c: &mut Checker<'_>, vf: &VariantFile) -> f32 {
    let Some(value) = options::special(c, &vf.game, "illegal_action_penalty", "illegal_action_penalty = -1.0") else {
        return 0.0;
    };
    let penalty = match value.get_ref() {
        toml::Value::Float(x) => *x as f32,
        toml::Value::Integer(n) => *n as f32,
        _ => f32::NAN,
    };
    if !penalty.is_finite() {
        c.variant_err(
            value.span().start,
            "illegal_action_penalty must be a finite number (an f32 reward), e.g. `-1.0`",
        );
    }
    penalty
}

fn check_actions(
    c: &mut Checker<'_>,
    a: &ActionsSection,
    red_fives: bool,
    abortive_draws: bool,
    seats: u32,
) -> (Vec<ActionBlock>, u32) {
    let mut blocks: Vec<ActionBlock> = Vec::new();
    let mut next = 0u32;
    let errors_before = c.errors.len();
    for block in a.layout.get_ref() {
        let block = block.get_ref();
        let kind = block.kind.get_ref();
        let at = block.kind.span().start;
        let Some(info) = ACTION_KINDS.iter().find(|k| k.name == kind) else {
            c.variant_err(
                at,
                format!(
                    "unknown action kind `{kind}`{}; the kinds are: {}",
                    did_you_mean(kind, ACTION_KINDS.iter().map(|k| k.name)),
                    ACTION_KINDS.map(|k| k.name).join(", ")
                ),
            );
            continue;
        };
        if blocks.iter().any(|b| b.kind == *kind) {
            c.variant_err(
                at,
                format!("action kind `{kind}` appears twice in the layout; remove one"),
            );
            continue;
        }
        match info.need {
            Need::RedFives if !red_fives => c.variant_err(
                at,
                format!(
                    "`{kind}` uses a red five, but `[tiles] red_fives = false`; remove it from the layout"
                ),
            ),
            Need::AbortiveDraws if !abortive_draws => c.variant_err(
                at,
                format!(
                    "`{kind}` declares an abortive draw, but `[draws] abortive_draws = false`; remove it from the layout"
                ),
            ),
            Need::FourSeats | Need::FourSeatsRedFives if seats != 4 => c.variant_err(
                at,
                format!("`{kind}` is a chi, but `[game] seats = {seats}` has no chi; remove it from the layout"),
            ),
            Need::FourSeatsRedFives if !red_fives => c.variant_err(
                at,
                format!(
                    "`{kind}` uses a red five, but `[tiles] red_fives = false`; remove it from the layout"
                ),
            ),
            Need::ThreeSeats if seats != 3 => c.variant_err(
                at,
                format!("`{kind}` sets North aside, which only the three-player game does; remove it from the layout"),
            ),
            _ => {}
        }
        let expected = if info.name == "discard" {
            discard_count(red_fives)
        } else {
            info.count
        };
        let count = match &block.count {
            Some(n) => {
                if *n.get_ref() != expected {
                    let why = match info.name {
                        "discard" if red_fives => " (34 tile types + 3 red fives, since red_fives = true)",
                        "discard" => " (34 tile types, since red_fives = false)",
                        "self_kan" => " (one per tile type)",
                        _ => "",
                    };
                    c.variant_err(
                        n.span().start,
                        format!(
                            "`{kind}` has {} ids, but it needs {expected}{why}; write `count = {expected}`",
                            n.get_ref()
                        ),
                    );
                }
                *n.get_ref()
            }
            None if expected == 1 => 1,
            None => {
                c.variant_err(
                    at,
                    format!("`{kind}` is a block of {expected} ids; add `count = {expected}`"),
                );
                expected
            }
        };
        blocks.push(ActionBlock {
            kind: kind.clone(),
            first: next,
            count,
        });
        next = next.saturating_add(count);
    }
    // A bad block already explains why kinds or ids are missing; don't pile consequences on it.
    if c.errors.len() > errors_before {
        return (blocks, next);
    }
    for info in &ACTION_KINDS {
        let needed = match info.need {
            Need::Always => true,
            Need::RedFives => red_fives,
            Need::AbortiveDraws => abortive_draws,
            Need::FourSeats => seats == 4,
            Need::FourSeatsRedFives => seats == 4 && red_fives,
            Need::ThreeSeats => seats == 3,
        };
        if needed && !blocks.iter().any(|b| b.kind == info.name) {
            let why = match info.need {
                Need::Always => "every variant needs it",
                Need::RedFives => "red_fives = true needs it",
                Need::AbortiveDraws => "abortive_draws = true needs it",
                Need::FourSeats => "seats = 4 needs it",
                Need::FourSeatsRedFives => "seats = 4 with red_fives = true needs it",
                Need::ThreeSeats => "seats = 3 needs it",
            };
            c.variant_err(
                a.layout.span().start,
                format!(
                    "the action layout lacks `{}` ({why}); add `{{ kind = \"{}\" }}`",
                    info.name, info.name
                ),
            );
        }
    }
    let declared = *a.num_actions.get_ref();
    if declared != next {
        c.variant_err(
            a.num_actions.span().start,
            format!("the layout has {next} action ids, but num_actions = {declared}; write `num_actions = {next}`"),
        );
    }
    (blocks, next)
}

fn check_yaku(c: &mut Checker<'_>, yf: &YakuFile, vf: &VariantFile, features: &[Feature]) -> Vec<Yaku> {
    let mut scope = Scope::default();
    for f in features {
        scope.names.insert(f.name.clone(), f.ty);
    }
    for k in vf.yaku_rules.keys() {
        scope.names.entry(k.get_ref().clone()).or_insert(Type::Bool);
    }

    if yf.yaku.len() > MAX_YAKU {
        let at = yf.yaku[MAX_YAKU].get_ref().name.span().start;
        c.yaku_err(
            at,
            format!(
                "{} yaku, but the yaku mask holds at most {MAX_YAKU}; remove or merge some",
                yf.yaku.len()
            ),
        );
    }

    let mut first_at: BTreeMap<&str, usize> = BTreeMap::new();
    let mut used_names: BTreeSet<String> = BTreeSet::new();
    let mut condition_failed = false;
    let mut out = Vec::new();
    for (index, entry) in yf.yaku.iter().enumerate() {
        let y: &YakuRaw = entry.get_ref();
        let name = y.name.get_ref();
        let name_at = y.name.span().start;
        if !is_snake_ident(name) {
            c.yaku_err(
                name_at,
                format!("yaku name `{name}` is not snake_case romaji; write e.g. `menzen_tsumo`"),
            );
        }
        if let Some(&first) = first_at.get(name.as_str()) {
            let (line, _) = c.yaku_src.line_col(first);
            c.yaku_err(
                name_at,
                format!("duplicate yaku `{name}` (first defined on line {line}); rename or remove one"),
            );
        } else {
            first_at.insert(name, name_at);
        }

        let (han_closed, han_open, yakuman) = check_han(c, y);

        let src = y.when.get_ref();
        let condition = match expr::parse(src).and_then(|e| {
            expr::check(&e, src, &scope)?;
            Ok(e)
        }) {
            Ok(e) => {
                used_names.extend(e.idents().into_iter().map(String::from));
                e
            }
            Err(e) => {
                condition_failed = true;
                let at = string_offset(&c.yaku_src, &y.when.span(), e.offset);
                c.yaku_err(at, format!("in the condition of `{name}`: {}", e.message));
                expr::Expr::Int { value: 0, span: 0..0 }
            }
        };
        out.push(Yaku {
            index,
            name: name.clone(),
            han_closed,
            han_open,
            yakuman,
            when: src.clone(),
            condition,
            supersedes: Vec::new(),
            description: y.description.clone(),
        });
    }

    // A typo in an option name would otherwise leave the intended option silently unset.
    for k in vf.yaku_rules.keys() {
        if !condition_failed && !used_names.contains(k.get_ref()) {
            c.variant_err(
                k.span().start,
                format!(
                    "option `{}` is not used by any yaku condition in {}; remove it or use it in a `when`",
                    k.get_ref(),
                    c.yaku_src.path
                ),
            );
        }
    }

    check_supersedes(c, yf, &mut out);
    out
}

/// Returns (han_closed, han_open, yakuman weight), reporting every inconsistency.
fn check_han(c: &mut Checker<'_>, y: &YakuRaw) -> (u32, u32, u32) {
    let name = y.name.get_ref();
    let name_at = y.name.span().start;
    match (&y.han_closed, &y.han_open, &y.yakuman) {
        (hc, ho, Some(ym)) => {
            if let Some(h) = hc.as_ref().or(ho.as_ref()) {
                c.yaku_err(
                    h.span().start,
                    format!("`{name}` has both `yakuman` and han; a yakuman has no han: remove `han_closed`/`han_open` or remove `yakuman`"),
                );
            }
            let w = *ym.get_ref();
            if w != 1 && w != 2 {
                c.yaku_err(
                    ym.span().start,
                    format!("yakuman weight {w} of `{name}`: write `yakuman = 1` (single) or `yakuman = 2` (double)"),
                );
            }
            (0, 0, w.clamp(0, 2) as u32)
        }
        (None, None, None) => {
            c.yaku_err(
                name_at,
                format!("`{name}` has neither han nor yakuman; write `han_closed = N` and `han_open = M` (0 = closed only), or `yakuman = 1`"),
            );
            (0, 0, 0)
        }
        (Some(_), None, None) | (None, Some(_), None) => {
            c.yaku_err(
                name_at,
                format!("`{name}` needs both `han_closed` and `han_open`; write `han_open = 0` for a closed-only yaku"),
            );
            (0, 0, 0)
        }
        (Some(hc), Some(ho), None) => {
            let (closed, open) = (*hc.get_ref(), *ho.get_ref());
            if !(1..=13).contains(&closed) {
                c.yaku_err(
                    hc.span().start,
                    format!("han_closed = {closed} of `{name}` is out of range; write a value from 1 to 13"),
                );
            }
            if !(0..=13).contains(&open) {
                c.yaku_err(
                    ho.span().start,
                    format!("han_open = {open} of `{name}` is out of range; write a value from 0 (closed only) to han_closed"),
                );
            } else if open > closed && (1..=13).contains(&closed) {
                c.yaku_err(
                    ho.span().start,
                    format!("han_open = {open} of `{name}` is greater than han_closed = {closed}; an open hand never scores more, write han_open <= {closed}"),
                );
            }
            (closed.clamp(0, 13) as u32, open.clamp(0, 13) as u32, 0)
        }
    }
}

fn check_supersedes(c: &mut Checker<'_>, yf: &YakuFile, out: &mut [Yaku]) {
    let index_of: BTreeMap<&str, usize> = out
        .iter()
        .rev() // first definition wins if a name is duplicated (already reported)
        .map(|y| (y.name.as_str(), y.index))
        .collect();
    // Direct edges with the span of the entry that names the target.
    let mut edges: Vec<Vec<(usize, usize)>> = vec![Vec::new(); out.len()];
    for (i, entry) in yf.yaku.iter().enumerate() {
        for target in &entry.get_ref().supersedes {
            let t = target.get_ref();
            match index_of.get(t.as_str()) {
                Some(&j) => edges[i].push((j, target.span().start)),
                None => c.yaku_err(
                    target.span().start,
                    format!(
                        "`{}` supersedes unknown yaku `{t}`{}; name a yaku defined in this file",
                        out[i].name,
                        did_you_mean(t, out.iter().map(|y| y.name.as_str()))
                    ),
                ),
            }
        }
    }

    // Cycle search: iterative DFS with colours; each back edge closes one cycle.
    let n = out.len();
    let mut colour = vec![0u8; n]; // 0 new, 1 on stack, 2 done
    let mut cyclic = false;
    for root in 0..n {
        if colour[root] != 0 {
            continue;
        }
        let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
        colour[root] = 1;
        while let Some(&mut (u, ref mut k)) = stack.last_mut() {
            if *k == edges[u].len() {
                colour[u] = 2;
                stack.pop();
                continue;
            }
            let (v, at) = edges[u][*k];
            *k += 1;
            match colour[v] {
                0 => {
                    colour[v] = 1;
                    stack.push((v, 0));
                }
                1 => {
                    cyclic = true;
                    let from = stack.iter().position(|&(w, _)| w == v).unwrap_or(0);
                    let mut path: Vec<&str> = stack[from..].iter().map(|&(w, _)| out[w].name.as_str()).collect();
                    path.push(out[v].name.as_str());
                    c.yaku_err(
                        at,
                        format!(
                            "supersedes cycle: {}; remove one of these `supersedes` entries",
                            path.join(" -> ")
                        ),
                    );
                }
                _ => {}
            }
        }
    }
    if cyclic {
        return;
    }
    for i in 0..n {
        let mut seen = vec![false; n];
        let mut todo: Vec<usize> = edges[i].iter().map(|&(j, _)| j).collect();
        while let Some(j) = todo.pop() {
            if !seen[j] {
                seen[j] = true;
                todo.extend(edges[j].iter().map(|&(k, _)| k));
            }
        }
        out[i].supersedes = (0..n).filter(|&j| seen[j]).collect();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn string_offsets_skip_quotes_and_escapes() {
        let text = "a = \"x\\ty\"\nb = 'pq'\nc = \"\"\"\nuv\"\"\"\n";
        let s = Source::new("f", text);
        // "x\ty": decoded offset 2 is `y`, raw offset 4 + 1 (quote) + 3.
        assert_eq!(string_offset(&s, &(4..10), 2), 8);
        assert_eq!(string_offset(&s, &(15..19), 1), 17);
        let start = text.find("\"\"\"").unwrap();
        assert_eq!(string_offset(&s, &(start..start + 9), 1), start + 5);
    }
}
